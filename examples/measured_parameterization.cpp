// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// The command-line program of the package: flattens a disk-like triangle mesh with the
// measured boundary parameterization of "Measured boundary parameterization based on
// Poisson's equation" (Measured_conformal_parameterizer_3) and writes the UV layout.
//
//   measured_parameterization [INPUT] [OUTPUT.obj] [--seams=FILE.selection.txt]
//                             [--center=poisson|geodesic[:METHOD]|vertex:N]
//                             [--distance=poisson|METHOD|straightest] [--border=auto|conformal|measured|circle]
//                             [--solver=cholmod|cholmod-nd|ldlt] [--svg=FILE] [--json] [--no-repair] [--help]
//
// Reads OFF, OBJ, PLY or STL (default: a real mesh of the project's data, or a generated
// curved disk when that file is missing), maps the longest border, and writes an OBJ with
// one UV per vertex (default: <input file stem>_uv.obj), optionally an SVG picture, and a
// one-line summary or a JSON object with the times, the solver work and the distortion.
// With --seams, the mesh (closed, or open with handles) is first cut along the seam edges
// of a CGAL selection file: the program parameterizes the CGAL::Seam_mesh, and the OBJ gets
// one UV per vertex of the seam mesh (one per side of a seam). Without --seams, a mesh that is
// not a disk (closed, with holes or handles) is cut along automatic seams (compute_disk_seams);
// --write-seams=FILE writes the seams used as a CGAL selection file.
// On any failure it says why on stderr, exits with a non-zero status and leaves no output
// file. The library does no IO; this program is the IO layer (helpers in cli/).

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Seam_mesh.h>

#include <CGAL/Surface_mesh_parameterization/Fixed_center.h>
#include <CGAL/Surface_mesh_parameterization/Geodesic_border_distance.h>
#include <CGAL/Surface_mesh_parameterization/Geodesic_center_locator.h>
#include <CGAL/Surface_mesh_parameterization/Measured_conformal_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/Poisson_border_distance.h>
#include <CGAL/Surface_mesh_parameterization/Poisson_center_locator.h>
#include <CGAL/Surface_mesh_parameterization/Straightest_geodesic_border_distance.h>
#include <CGAL/Surface_mesh_parameterization/compute_disk_seams.h>
#include <CGAL/Surface_mesh_parameterization/measure_quality.h>
#ifdef MBP_WITH_CHOLMOD
#include <CGAL/Surface_mesh_parameterization/Cholmod_supernodal_cholesky_traits.h>
#endif

#include "cli/file_output.h"
#include "cli/mesh_input.h"
#include "cli/options.h"
#include "cli/seam_selection.h"
#include "cli/svg_layout.h"
#include "cli/text_output.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <csignal>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <limits>
#include <set>
#include <string>
#include <utility>
#include <vector>

#ifndef MBP_DEFAULT_MESH
#define MBP_DEFAULT_MESH ""
#endif

typedef CGAL::Simple_cartesian<double>                                Kernel;
typedef Kernel::Point_2                                               Point_2;
typedef Kernel::Point_3                                               Point_3;
typedef CGAL::Surface_mesh<Point_3>                                   Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor                  vertex_descriptor;
typedef boost::graph_traits<Mesh>::halfedge_descriptor                halfedge_descriptor;
typedef boost::graph_traits<Mesh>::edge_descriptor                    edge_descriptor;
typedef boost::graph_traits<Mesh>::face_descriptor                    face_descriptor;

// The mesh cut along the seams of --seams. Its vertices are halfedges of `Mesh` (one per side
// of a seam); its faces are those of `Mesh`.
typedef Mesh::Property_map<edge_descriptor, bool>                     Seam_edge_map;
typedef Mesh::Property_map<vertex_descriptor, bool>                   Seam_vertex_map;
typedef CGAL::Seam_mesh<Mesh, Seam_edge_map, Seam_vertex_map>         Seam_mesh;

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace fs = std::filesystem;
typedef SMP::Heat_method_geodesics<CGAL::Heat_method_3::Direct>             Heat;
typedef SMP::Heat_method_geodesics<CGAL::Heat_method_3::Intrinsic_Delaunay> Heat_idt;

namespace {

const int exit_failure = 1;  // the input cannot be parameterized, or a file cannot be written
const int exit_usage = 2;    // command-line error

// The input vertex (0-based, file order) of a vertex of the parameterized mesh.
std::size_t input_index(const Mesh&, vertex_descriptor v) { return std::size_t(v); }
std::size_t input_index(const Seam_mesh& seam_mesh, boost::graph_traits<Seam_mesh>::vertex_descriptor v)
{
  return std::size_t(target(halfedge_descriptor(v), seam_mesh.mesh()));
}

// The vertex of the parameterized mesh of input vertex `v`, which is not on a seam.
vertex_descriptor mesh_vertex(const Mesh&, vertex_descriptor v) { return v; }
boost::graph_traits<Seam_mesh>::vertex_descriptor mesh_vertex(const Seam_mesh& seam_mesh, vertex_descriptor v)
{
  // a seam mesh vertex is represented by a halfedge of the mesh; off the seams, by halfedge(v)
  return boost::graph_traits<Seam_mesh>::halfedge_descriptor(halfedge(v, seam_mesh.mesh()));
}

// The center locator of the command line (a model of `MeasuredCenterLocator`), chosen at run
// time among the user's vertex (`--center=vertex:N`, through `Fixed_center`), the Poisson
// center and the geodesic centers, so that the method is instantiated once per solver and
// mesh type rather than once per solver, mesh type, locator and distance.
template <class TriangleMesh>
class Command_line_center_locator
{
public:
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;

  explicit Command_line_center_locator(const std::string& name = "poisson") : m_name(name) { }
  explicit Command_line_center_locator(vertex_descriptor v) : m_fixed(v), m_name("vertex") { }

  template <class Patch>
  SMP::Error_code locate_center(Patch& patch, std::size_t& center) const
  {
    if(m_name == "vertex")
      return m_fixed.locate_center(patch, center);
    if(m_name == "geodesic:fast-marching")
      return SMP::Geodesic_center_locator<TriangleMesh, SMP::Fast_marching_geodesics>().locate_center(patch, center);
    if(m_name == "geodesic:dijkstra")
      return SMP::Geodesic_center_locator<TriangleMesh, SMP::Dijkstra_geodesics>().locate_center(patch, center);
    if(m_name == "geodesic:heat")
      return SMP::Geodesic_center_locator<TriangleMesh, Heat>().locate_center(patch, center);
    if(m_name == "geodesic:heat-idt")
      return SMP::Geodesic_center_locator<TriangleMesh, Heat_idt>().locate_center(patch, center);
    if(m_name == "geodesic:exact")
      return SMP::Geodesic_center_locator<TriangleMesh, SMP::Exact_geodesics>().locate_center(patch, center);
    return SMP::Poisson_center_locator<TriangleMesh>().locate_center(patch, center);
  }

private:
  SMP::Fixed_center<TriangleMesh> m_fixed;
  std::string m_name;
};

// The border distance of the command line (a model of `MeasuredBorderDistance`), chosen at
// run time: Poisson, a geodesic method, or straightest geodesics.
template <class TriangleMesh>
class Command_line_border_distance
{
public:
  typedef typename SMP::Straightest_geodesic_border_distance<TriangleMesh>::Failure Straightest_failure;

  explicit Command_line_border_distance(const std::string& name = "poisson") : m_name(name) { }

  template <class Patch>
  SMP::Error_code prepare(Patch& patch) const
  {
    return dispatch([&patch](const auto& policy) { return policy.prepare(patch); });
  }

  template <class Patch>
  SMP::Error_code compute_border_distances(Patch& patch, std::size_t center, std::vector<double>& distances) const
  {
    return dispatch([&](const auto& policy) { return policy.compute_border_distances(patch, center, distances); });
  }

  // whether the distances are fast marching geodesics (then --border=auto takes the Poisson
  // distance map for its second measured border)
  bool measures_fast_marching_geodesics() const { return m_name == "fast-marching"; }

  // the border vertices straightest geodesics could not reach in the last call
  const Straightest_failure& straightest_failure() const { return m_straightest.last_failure(); }

private:
  template <class F>
  SMP::Error_code dispatch(const F& f) const
  {
    if(m_name == "fast-marching")
      return f(SMP::Geodesic_border_distance<TriangleMesh, SMP::Fast_marching_geodesics>());
    if(m_name == "dijkstra")
      return f(SMP::Geodesic_border_distance<TriangleMesh, SMP::Dijkstra_geodesics>());
    if(m_name == "heat")
      return f(SMP::Geodesic_border_distance<TriangleMesh, Heat>());
    if(m_name == "heat-idt")
      return f(SMP::Geodesic_border_distance<TriangleMesh, Heat_idt>());
    if(m_name == "exact")
      return f(SMP::Geodesic_border_distance<TriangleMesh, SMP::Exact_geodesics>());
    if(m_name == "straightest")
      return f(m_straightest);
    return f(SMP::Poisson_border_distance<TriangleMesh>());
  }

  std::string m_name;
  SMP::Straightest_geodesic_border_distance<TriangleMesh> m_straightest;  // its failure record is shared by copies
};

double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// What a parameterization produced, copied from the parameterizer's report and record (whose
// types depend on the mesh and the solver). Vertices are input vertex indices.
struct Parameterization_result
{
  SMP::Error_code status = SMP::ERROR_WRONG_PARAMETER;
  bool has_center = false;              // --border=conformal and circle locate no center
  std::size_t center = 0;               // input vertex
  std::size_t border_vertices = 0;      // of the longest border loop
  bool border_convex = false;
  double preparation = 0., center_time = 0., distances = 0., border_map = 0., interior = 0., output = 0., total = 0.;
  int factorizations = 0, back_substitutions = 0;
  double factorization_seconds = 0., back_substitution_seconds = 0.;
  double degenerate_face_threshold = 0.;
  std::size_t unreachable = 0;          // border vertices straightest geodesics did not reach
  std::size_t first_unreachable = 0;    // the first of them (input vertex)
  std::size_t flipped_before_repair = 0;
  bool repaired = false, mean_value_interior = false;
  double blend = 0., repair_seconds = 0.;
  int repair_candidates = 0;
  // the layouts tried, in order (the repair's included), and the kept one
  struct Candidate
  {
    std::string kind;  // circle, conformal, or measured:<distance>, blended toward a convex border
    double blend = 0.;
    bool mean_value = false;  // mean value interior (a repair)
    bool valid = false;
    double angle_distortion = 0.;
  };
  std::vector<Candidate> border_candidates;
  int chosen_candidate = -1;
  double conformal_border_seconds = 0.;
};

// A parameterized mesh in the numbering of the output files, the same for a mesh and for a
// mesh cut along seams, so that the OBJ, the SVG and the report are written once. The 'v'
// lines are the input vertices that are in a face; the 'vt' lines the UVs: one per vertex,
// or, for a seam mesh, one per seam mesh vertex (a vertex on a seam has one per side).
struct Uv_layout
{
  std::vector<std::size_t> vertices;                   // per 'v': its input vertex, increasing
  std::vector<std::size_t> uv_vertex;                  // per 'vt': its 'v' (0-based)
  std::vector<std::array<double, 2> > uv;              // per 'vt'
  std::vector<std::array<std::size_t, 3> > faces;      // per face, in input order: 'vt' indices (0-based)
  std::vector<SMP::Face_quality> face_quality;         // per face
  SMP::Parameterization_quality quality;
  std::vector<std::size_t> border;                     // the longest border loop, from source(bhd): 'vt' indices
  std::size_t center = 0;                              // 'vt' index of the center
  double quality_seconds = 0.;                         // time of the distortion measures
};

template <class SolverTraits, class TriangleMesh, class UVMap, class FlagMap>
Parameterization_result run_parameterization(const TriangleMesh& tm,
                                             typename boost::graph_traits<TriangleMesh>::halfedge_descriptor bhd,
                                             const Command_line_center_locator<TriangleMesh>& locator,
                                             const Command_line_border_distance<TriangleMesh>& distance,
                                             const mbp_cli::Options& options, UVMap uvmap, FlagMap parameterized,
                                             std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>& border)
{
  typedef SMP::Measured_conformal_parameterizer_3<TriangleMesh, Command_line_center_locator<TriangleMesh>,
                                                  Command_line_border_distance<TriangleMesh>,
                                                  SolverTraits>                   Parameterizer;
  Parameterizer parameterizer(locator, distance);
  if(!options.repair)
    parameterizer.set_repair(Parameterizer::NO_REPAIR);
  parameterizer.set_border_choice(options.border == "auto"        ? Parameterizer::AUTOMATIC_BORDER
                                  : options.border == "conformal" ? Parameterizer::CONFORMAL_BORDER
                                  : options.border == "circle"    ? Parameterizer::CIRCULAR_BORDER
                                                                  : Parameterizer::MEASURED_BORDER);
  Parameterization_result r;
  // the vertex index map is not used by the parameterizer (it indexes the component itself)
  r.status = parameterizer.parameterize(tm, bhd, uvmap, get(CGAL::dynamic_vertex_property_t<int>(), tm),
                                        parameterized);
  const auto& straightest = distance.straightest_failure();
  r.unreachable = straightest.unreachable;
  if(r.unreachable > 0)
    r.first_unreachable = input_index(tm, straightest.vertex);

  const typename Parameterizer::Report& report = parameterizer.last_report();
  r.has_center = parameterizer.center() != boost::graph_traits<TriangleMesh>::null_vertex();
  if(r.has_center)
    r.center = input_index(tm, parameterizer.center());
  border.clear();
  if(bhd != boost::graph_traits<TriangleMesh>::null_halfedge() && is_border(bhd, tm))
    for(auto h : CGAL::halfedges_around_face(bhd, tm))
      border.push_back(source(h, tm));
  r.border_vertices = border.size();
  r.preparation = report.preparation_seconds;
  r.center_time = report.center_seconds;
  r.distances = report.distance_seconds;
  r.border_map = report.border_map_seconds;
  r.interior = report.interior_seconds;
  r.conformal_border_seconds = report.conformal_border_seconds;
  r.output = report.output_seconds;
  r.total = report.total_seconds;
  r.factorizations = report.statistics.factorizations;
  r.back_substitutions = report.statistics.back_substitutions;
  r.factorization_seconds = report.statistics.factorization_seconds;
  r.back_substitution_seconds = report.statistics.back_substitution_seconds;
  r.degenerate_face_threshold = Parameterizer::Patch::degenerate_face_threshold();
  r.flipped_before_repair = report.flipped_faces_before_repair;
  r.repaired = report.repaired;
  r.mean_value_interior = report.mean_value_interior;
  r.blend = report.blend;
  r.repair_seconds = report.repair_seconds;
  r.repair_candidates = report.repair_candidates;
  for(const typename Parameterizer::Border_candidate& c : report.border_candidates)
  {
    Parameterization_result::Candidate k;
    k.kind = (c.family == Parameterizer::CIRCLE)      ? std::string("circle")
             : (c.family == Parameterizer::CONFORMAL) ? std::string("conformal")
                                                      : "measured:" + options.distance;
    k.blend = c.blend;
    k.mean_value = c.mean_value_interior;
    k.valid = c.valid;
    k.angle_distortion = c.objective;
    r.border_candidates.push_back(k);
  }
  r.chosen_candidate = report.chosen_candidate;
  // the kept border polygon: convex?
  if(r.chosen_candidate >= 0 && r.status == SMP::OK)
  {
    std::vector<Eigen::Vector2d> polygon;
    for(auto v : border)
      polygon.emplace_back(get(uvmap, v).x(), get(uvmap, v).y());
    r.border_convex = SMP::internal::is_strictly_convex_clockwise(polygon);
  }
  return r;
}

// The vertex of `tm` that `--center=vertex:N` names, or a failure (N out of range, in no
// face, on a seam, on the longest border).
template <class TriangleMesh>
mbp_cli::Failure center_vertex(const TriangleMesh& tm, const Mesh& mesh, const Seam_mesh* seam_mesh,
                               typename boost::graph_traits<TriangleMesh>::halfedge_descriptor bhd, std::size_t n,
                               typename boost::graph_traits<TriangleMesh>::vertex_descriptor& center)
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor tm_halfedge_descriptor;
  const std::string option = "--center=vertex:" + std::to_string(n);
  mbp_cli::Failure f;  // a check of the program: no library code
  // Surface_mesh numbers the vertices in the order they were added: the file order.
  if(n >= num_vertices(mesh))
  {
    f.detail = option + ": vertex index out of range (the mesh has " + std::to_string(num_vertices(mesh)) +
               " vertices, numbered from 0)";
    return f;
  }
  const vertex_descriptor v(static_cast<Mesh::size_type>(n));
  if(mesh.is_isolated(v))
  {
    f.detail = option + ": the vertex is in no face";
    return f;
  }
  if(seam_mesh != nullptr && seam_mesh->has_on_seam(v))
  {
    f.detail = option + ": the vertex lies on a seam, which is on the border of the cut mesh; the center must be"
                        " an interior vertex";
    return f;
  }
  center = mesh_vertex(tm, v);
  for(tm_halfedge_descriptor h : CGAL::halfedges_around_face(bhd, tm))
    if(target(h, tm) == center)
      f.detail = option + ": the vertex lies on the border; the center must be an interior vertex";
  return f;
}

// Parameterizes `tm` (the mesh, or the seam mesh over it) from its border halfedge `bhd` and
// fills `layout`, or returns why it failed. `mesh` is the input mesh; `seam_mesh` is `&tm`
// for a seam mesh and null otherwise.
template <class TriangleMesh>
mbp_cli::Failure parameterize_mesh(const TriangleMesh& tm, const Mesh& mesh, const Seam_mesh* seam_mesh,
                                   typename boost::graph_traits<TriangleMesh>::halfedge_descriptor bhd,
                                   const mbp_cli::Options& options,
                                   Parameterization_result& result, Uv_layout& layout)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor   tm_vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor tm_halfedge_descriptor;

  Command_line_center_locator<TriangleMesh> locator(options.center);
  const Command_line_border_distance<TriangleMesh> distance(options.distance);
  if(options.fixed_center)
  {
    tm_vertex_descriptor v;
    const mbp_cli::Failure f = center_vertex(tm, mesh, seam_mesh, bhd, options.center_vertex, v);
    if(f.failed())
      return f;
    locator = Command_line_center_locator<TriangleMesh>(v);
  }

  auto uvmap = get(CGAL::dynamic_vertex_property_t<Point_2>(), tm);
  auto parameterized = get(CGAL::dynamic_vertex_property_t<bool>(), tm);
  for(tm_vertex_descriptor v : vertices(tm))
    put(parameterized, v, false);
  std::vector<tm_vertex_descriptor> border;
#ifdef MBP_WITH_CHOLMOD
  if(options.solver == mbp_cli::Solver::cholmod)
    result = run_parameterization<SMP::Cholmod_supernodal_cholesky_traits>(tm, bhd, locator, distance, options,
                                                                           uvmap, parameterized, border);
  else if(options.solver == mbp_cli::Solver::cholmod_nd)
    result = run_parameterization<SMP::Cholmod_nested_dissection_cholesky_traits>(tm, bhd, locator, distance,
                                                                                  options, uvmap, parameterized,
                                                                                  border);
  else
#endif
    result = run_parameterization<CGAL::Default>(tm, bhd, locator, distance, options, uvmap, parameterized,
                                                 border);

  if(result.status != SMP::OK)
  {
    mbp_cli::Failure f;
    f.code = result.status;
    if(result.status == SMP::ERROR_DEGENERATE_FACE)
      f.detail = mbp_cli::find_degenerate_face(mesh, result.degenerate_face_threshold);
    else if(result.status == SMP::ERROR_NON_FINITE_COORDINATES)
      f.detail = mbp_cli::find_non_finite_vertex(mesh);
    else if(result.status == SMP::ERROR_NO_TOPOLOGICAL_DISC)
    {
      const mbp_cli::Mesh_topology input = mbp_cli::mesh_topology(mesh);
      if(seam_mesh != nullptr)
        f.detail = mbp_cli::explain_cut(input, mbp_cli::mesh_topology(*seam_mesh));
      else if(input.genus > 0)
        f.detail = "the surface has genus " + std::to_string(input.genus) +
                   " (handles); cut every handle with seams: --seams=FILE.selection.txt";
      else
        f.detail = "the longest border touches itself, or a vertex is non-manifold";
    }
    else if(result.status == SMP::ERROR_NO_1_TO_1_MAPPING)
      f.detail = std::to_string(result.flipped_before_repair) +
                 " faces are flipped by the measured border" +
                 (options.repair ? std::string(" and no blend toward a circle repairs them")
                                 : std::string(" (repair is off: --no-repair)"));
    else if(result.status == SMP::ERROR_DEGENERATE_BORDER_MAP)
      f.detail = "seen from the center (vertex " + std::to_string(result.center) +
                 "), two consecutive border vertices lie in the same direction, or a border distance is not"
                 " positive; try another center (--center=geodesic or --center=vertex:N)";
    else if(result.status == SMP::ERROR_DISTANCE_COMPUTATION_FAILED && options.distance == "straightest" &&
            result.unreachable > 0)
      f.detail = "the straightest geodesic from the center (vertex " + std::to_string(result.center) +
                 ") does not reach border vertex " + std::to_string(result.first_unreachable) + " (" +
                 std::to_string(result.unreachable) + " of " + std::to_string(result.border_vertices) +
                 " border vertices are not reached)";
    return f;
  }

  // The numbering of the output: 'v' lines are the input vertices that are in a face, in
  // input order (the checks before leave one connected component, all of which is
  // parameterized); 'vt' lines the parameterized vertices of `tm`, grouped by input vertex.
  std::vector<std::pair<std::size_t, tm_vertex_descriptor> > uv_order;
  for(tm_vertex_descriptor v : vertices(tm))
    if(get(parameterized, v))
      uv_order.emplace_back(input_index(tm, v), v);
  std::stable_sort(uv_order.begin(), uv_order.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  auto uv_index = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
  for(const auto& u : uv_order)
  {
    const Point_2& q = get(uvmap, u.second);
    if(!std::isfinite(q.x()) || !std::isfinite(q.y()))
    {
      mbp_cli::Failure f;
      f.code = SMP::ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
      f.detail = "the solver gave a non-finite UV at vertex " + std::to_string(u.first);
      return f;
    }
    if(layout.vertices.empty() || layout.vertices.back() != u.first)
      layout.vertices.push_back(u.first);
    put(uv_index, u.second, layout.uv.size());
    layout.uv_vertex.push_back(layout.vertices.size() - 1);
    layout.uv.push_back({q.x(), q.y()});
  }
  for(face_descriptor fd : faces(tm))  // the faces of a seam mesh are those of the mesh
  {
    std::array<std::size_t, 3> t;
    std::size_t k = 0;
    for(tm_halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(fd, tm), tm))
      t[k++] = get(uv_index, target(h, tm));
    layout.faces.push_back(t);
  }
  for(tm_vertex_descriptor v : border)
    layout.border.push_back(get(uv_index, v));
  for(const auto& u : uv_order)
    if(u.first == result.center)  // the center is interior: one UV
      layout.center = get(uv_index, u.second);

  // the distortion, per face
  const std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  auto face_quality = get(CGAL::dynamic_face_property_t<SMP::Face_quality>(), tm);
  layout.quality = SMP::measure_quality_per_face(tm, faces(tm), uvmap, face_quality);
  for(face_descriptor fd : faces(tm))
    layout.face_quality.push_back(get(face_quality, fd));
  layout.quality_seconds = seconds_since(start);
  return mbp_cli::Failure();
}

// The border kept, for the summary: "conformal (3 layouts tried)", "measured:poisson t 0.38,
// mean value interior (9 layouts tried)".
std::string border_summary(const Parameterization_result& result)
{
  const std::size_t n = result.border_candidates.size();
  const std::string tried = " (" + std::to_string(n) + (n == 1 ? " layout" : " layouts") + " tried)";
  if(result.chosen_candidate < 0)
    return "none valid" + tried;
  const Parameterization_result::Candidate& c =
    result.border_candidates[static_cast<std::size_t>(result.chosen_candidate)];
  return c.kind + (c.kind == "circle" || c.blend == 0. ? std::string() : " t " + mbp_cli::rounded(c.blend, 3)) +
         (c.mean_value ? ", mean value interior" : "") + tried;
}

// Whether the layout was repaired, for the summary and the SVG: "repaired 12 flipped faces:
// blend 0.25, mean value interior", "no repair needed" or "repair off".
std::string repair_summary(const Parameterization_result& result, bool repair_enabled)
{
  if(result.repaired)
    return "repaired " + std::to_string(result.flipped_before_repair) + " flipped faces: blend " +
           mbp_cli::rounded(result.blend, 3) + (result.mean_value_interior ? ", mean value interior" : "");
  return repair_enabled ? "no repair needed" : "repair off";
}

// The end of a failed run: the message on stderr ("error: MESSAGE" and, for a command-line
// error, the hint to --help) and, with --json, the same on stdout as one JSON object,
// {"error": MESSAGE, "code": STATUS, "error_code": N}: STATUS is the exit status returned
// (1: the input cannot be parameterized or an output cannot be written; 2: a command-line
// error), N the library's Error_code when the failure is one (null otherwise).
int fail_with(const std::string& message, int status, bool json, SMP::Error_code code = SMP::OK)
{
  std::cerr << "error: " << message << "\n";
  if(status == exit_usage)
    std::cerr << "(run with --help for the usage)\n";
  if(json)
  {
    mbp_cli::Json_writer j;
    j.begin_object().member("error", message).member("code", status);
    if(code == SMP::OK)
      j.null_member("error_code");
    else
      j.member("error_code", static_cast<int>(code));
    j.end_object();
    std::cout << j.text();
  }
  return status;
}

// Automatic seams (compute_disk_seams()) of a mesh that is not a disk: its seam edges into
// `seams`, or why there are none.
mbp_cli::Failure automatic_seams_of(Mesh& mesh, std::vector<edge_descriptor>& seams,
                                    SMP::Disk_seams_report<Mesh>& report)
{
  Seam_edge_map edge_flags = mesh.add_property_map<edge_descriptor, bool>("e:automatic_seam", false).first;
  Seam_vertex_map vertex_flags = mesh.add_property_map<vertex_descriptor, bool>("v:automatic_seam", false).first;
  mbp_cli::Failure f;
  f.code = SMP::compute_disk_seams(mesh, edge_flags, vertex_flags, report);
  if(f.code != SMP::OK)
  {
    f.detail = std::string("automatic seams: ") + SMP::disk_seams_problem_message(report.problem);
    if(report.problem_vertex != Mesh::null_vertex())
      f.detail += " (vertex " + std::to_string(std::size_t(report.problem_vertex)) + ")";
    if(report.problem_face != Mesh::null_face())
      f.detail += " (face " + std::to_string(std::size_t(report.problem_face)) + ")";
  }
  else
    for(edge_descriptor e : edges(mesh))
      if(get(edge_flags, e))
        seams.push_back(e);
  mesh.remove_property_map(edge_flags);
  mesh.remove_property_map(vertex_flags);
  return f;
}

// A line of text for a comment of the OBJ file: no line breaks or other control characters.
std::string one_line(std::string s)
{
  for(char& c : s)
    if(static_cast<unsigned char>(c) < 0x20)
      c = '?';
  return s;
}

} // namespace

int main(int argc, char** argv)
{
  typedef std::chrono::steady_clock Clock;
  const std::string default_mesh = MBP_DEFAULT_MESH;

  // ------------------------------------------------------------------ command line
  mbp_cli::Options options;
  const std::string usage_error = mbp_cli::parse_options(argc, argv, options);
  if(!usage_error.empty())
  {
    // the parsing stopped at the error: --json may come after it
    bool json = false;
    for(int i = 1; i < argc; ++i)
      json = json || std::string(argv[i]) == "--json";
    return fail_with(usage_error, exit_usage, json);
  }
  if(options.help)
  {
    std::cout << mbp_cli::usage(default_mesh);
    return EXIT_SUCCESS;
  }

  // ------------------------------------------------------------------ input
  Mesh mesh;
  bool generated = false;
  Clock::time_point start = Clock::now();
  if(options.input.empty())
  {
    std::error_code ec;
    if(!default_mesh.empty() && fs::exists(default_mesh, ec))
      options.input = default_mesh;
    else
    {
      mbp_cli::make_curved_disk(mesh);
      generated = true;
      std::cerr << "note: "
                << (default_mesh.empty() ? std::string("no default mesh was configured")
                                         : "the default mesh '" + default_mesh + "' does not exist")
                << "; using a generated curved disk (" << num_vertices(mesh) << " vertices, "
                << num_faces(mesh) << " faces)\n";
    }
  }
  std::string where = generated ? std::string("generated curved disk") : options.input;  // names the failures
  auto fail = [&where, &options](const mbp_cli::Failure& f) {
    return fail_with(where + ": " + f.message(), exit_failure, options.json, f.code);
  };

  // Output names, checked before anything is read or computed: no output may be an input or
  // another output, an existing output must be a regular file (file_output.h).
  if(options.output.empty())
    options.output = (generated ? std::string("curved_disk") : fs::path(options.input).stem().string()) + "_uv.obj";
  mbp_cli::Output_files files;
  {
    if(!generated)
      files.add_input(options.input, "the input");
    if(!options.seams.empty())
      files.add_input(options.seams, "the seam file");
    bool usage = false;
    std::string error = files.add_target(options.output, "OUTPUT", usage);
    if(error.empty() && !options.svg.empty())
      error = files.add_target(options.svg, "--svg", usage);
    if(error.empty() && !options.write_seams.empty())
      error = files.add_target(options.write_seams, "--write-seams", usage);
    if(!error.empty())
      return fail_with(error, usage ? exit_usage : exit_failure, options.json);
  }

  if(!generated)
  {
    const mbp_cli::Failure f = mbp_cli::read_mesh(options.input, mesh);
    if(f.failed())
      return fail(f);
  }
  const double read_seconds = seconds_since(start);

  // ------------------------------------------------------------------ checks
  {
    const mbp_cli::Failure f = mbp_cli::check_mesh(mesh);
    if(f.failed())
      return fail(f);
  }

  // coordinates so large (or small) that squared lengths overflow are scaled by a power of
  // two while the library runs (exact; the output has the input's coordinates)
  mbp_cli::Scaled_coordinates<Mesh> scaled(mesh);

  // ------------------------------------------------------------------ parameterization
  // With seams, of the mesh cut along them: a Seam_mesh over `mesh`. Both give a `Uv_layout`.
  // Without --seams, a mesh that is not a disk is cut along automatic seams.
  const mbp_cli::Mesh_topology topology = mbp_cli::mesh_topology(mesh);
  const bool automatic_seams = options.seams.empty() && !(topology.border_loops == 1 && topology.genus == 0);
  const bool with_seams = !options.seams.empty() || automatic_seams;
  SMP::Disk_seams_report<Mesh> automatic;
  std::vector<edge_descriptor> seams;
  double border_length = 0.;
  Parameterization_result result;
  Uv_layout layout;
  if(with_seams)
  {
    if(automatic_seams)
    {
      const mbp_cli::Failure f = automatic_seams_of(mesh, seams, automatic);
      if(f.failed())
        return fail(f);
    }
    else
    {
      std::string error = mbp_cli::check_regular_input(options.seams);
      if(error.empty())
        error = mbp_cli::read_seam_selection(options.seams, mesh, seams);
      if(!error.empty())
        return fail_with(options.seams + ": " + error, exit_failure, options.json);
    }
    Seam_edge_map seam_edges = mesh.add_property_map<edge_descriptor, bool>("e:seam", false).first;
    Seam_vertex_map seam_vertices = mesh.add_property_map<vertex_descriptor, bool>("v:seam", false).first;
    Seam_mesh seam_mesh(mesh, seam_edges, seam_vertices);
    for(edge_descriptor e : seams)
      seam_mesh.add_seam(source(e, mesh), target(e, mesh));
    where += " cut along " + (automatic_seams ? std::string("automatic seams") : options.seams);

    // one piece and no new border loop (handles left uncut are found by the parameterizer)
    mbp_cli::Failure f;
    f.detail = mbp_cli::check_cut(mbp_cli::mesh_topology(mesh), mbp_cli::mesh_topology(seam_mesh));
    if(f.failed())
    {
      f.code = SMP::ERROR_NO_TOPOLOGICAL_DISC;
      return fail(f);
    }
    boost::graph_traits<Seam_mesh>::halfedge_descriptor bhd;
    f = mbp_cli::find_longest_border(seam_mesh, bhd, border_length);
    if(!f.failed())
      f = parameterize_mesh(seam_mesh, mesh, &seam_mesh, bhd, options, result, layout);
    if(f.failed())
      return fail(f);
  }
  else
  {
    halfedge_descriptor bhd;
    mbp_cli::Failure f = mbp_cli::find_longest_border(mesh, bhd, border_length);
    if(!f.failed())
      f = parameterize_mesh(mesh, mesh, nullptr, bhd, options, result, layout);
    if(f.failed())
      return fail(f);
  }
  scaled.restore();
  const std::size_t isolated = num_vertices(mesh) - layout.vertices.size();
  const SMP::Parameterization_quality& quality = layout.quality;

  // ------------------------------------------------------------------ output files
  start = Clock::now();
  const std::string mesh_name = generated ? std::string("curved disk (generated)")
                                          : fs::path(options.input).filename().string();
  const std::size_t center_index = result.center;
  // the OBJ, written straight into its temporary file
  mbp_cli::Buffered_writer* obj = files.begin(0);
  if(obj == nullptr)
    return fail_with(files.error(), exit_failure, options.json);
  *obj << "# UV layout by measured_parameterization: measured boundary parameterization (center: "
       << options.center_name() << ", border distances: " << options.distance << "), discrete conformal interior\n";
  *obj << "# border: --border=" << options.border << ", kept " << border_summary(result) << "\n";
  *obj << "# input: " << one_line(generated ? mesh_name : options.input) << "\n";
  if(with_seams)
    *obj << "# cut along " << seams.size() << " seam edges ("
         << (automatic_seams ? "automatic, " + std::to_string(automatic.cones.size()) + " cones"
                             : one_line(options.seams))
         << "): one 'vt' per side of a seam, faces 'f v/vt'\n";
  *obj << "# " << layout.vertices.size() << " vertices, " << layout.faces.size() << " faces"
       << (result.has_center ? ", center: input vertex " + std::to_string(center_index) + " (0-based)" : std::string())
       << "\n";
  for(std::size_t i : layout.vertices)
  {
    const Point_3& p = mesh.point(vertex_descriptor(static_cast<Mesh::size_type>(i)));
    *obj << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  }
  for(const std::array<double, 2>& q : layout.uv)
    *obj << "vt " << q[0] << ' ' << q[1] << '\n';
  for(const std::array<std::size_t, 3>& t : layout.faces)
  {
    *obj << 'f';
    for(std::size_t u : t)
      *obj << ' ' << layout.uv_vertex[u] + 1 << '/' << u + 1;
    *obj << '\n';
  }
  if(!files.end(0))
    return fail_with(files.error(), exit_failure, options.json);

  std::string svg;
  if(!options.svg.empty())
  {
    mbp_cli::Svg_layout picture;
    picture.uv = layout.uv;
    picture.faces = layout.faces;
    for(const SMP::Face_quality& fq : layout.face_quality)
    {
      picture.face_angle_distortion.push_back(fq.angle_distortion);
      picture.face_flipped.push_back(!(fq.uv_area > 0.));
    }
    picture.border = layout.border;
    if(with_seams)  // both sides of each seam edge: the edge of each of its two faces
    {
      const std::set<edge_descriptor> on_seam(seams.begin(), seams.end());
      std::size_t i = 0;
      for(face_descriptor fd : faces(mesh))
      {
        const std::array<std::size_t, 3>& t = layout.faces[i++];
        std::size_t k = 0;  // the k-th halfedge of the face ends at UV t[k]
        for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(fd, mesh), mesh))
        {
          if(on_seam.count(edge(h, mesh)) > 0)
            picture.seams.push_back({t[(k + 2) % 3], t[k]});
          ++k;
        }
      }
      picture.seam_edges = seams.size();
    }
    picture.center = result.has_center ? layout.center : std::numeric_limits<std::size_t>::max();
    picture.center_label = "center (vertex " + std::to_string(center_index) + ")";
    picture.title = mesh_name;
    picture.caption.push_back(std::to_string(layout.vertices.size()) + " vertices, " +
                              std::to_string(layout.faces.size()) + " faces, " +
                              (with_seams ? std::to_string(seams.size()) +
                                              (automatic_seams ? " automatic seam edges (" +
                                                                   std::to_string(automatic.cones.size()) + " cones, "
                                                               : std::string(" seam edges (")) +
                                              std::to_string(layout.uv.size()) + " UVs), "
                                          : std::string()) +
                              "border of " + std::to_string(result.border_vertices) + " vertices, center: " +
                              options.center_name() + " center, " + options.distance + " distances");
    picture.caption.push_back("angle distortion " + mbp_cli::rounded(quality.angle_distortion) + ",  L2 stretch " +
                              mbp_cli::rounded(quality.l2_stretch) + ",  quasi-conformal mean " +
                              mbp_cli::rounded(quality.quasi_conformal_mean) + ",  flipped faces " +
                              std::to_string(quality.flipped_faces));
    picture.caption.push_back("border " + options.border + ": kept " + border_summary(result) + ",  " +
                              repair_summary(result, options.repair));
    svg = mbp_cli::svg_document(picture);
  }

  {
    bool written = true;
    if(!options.svg.empty())
    {
      mbp_cli::Buffered_writer* out = files.begin(1);
      written = out != nullptr;
      if(written)
      {
        *out << svg;
        written = files.end(1);
      }
    }
    if(written && !options.write_seams.empty())
    {
      const std::size_t k = options.svg.empty() ? 1 : 2;  // the targets' order of add_target()
      mbp_cli::Buffered_writer* out = files.begin(k);
      written = out != nullptr;
      if(written)
      {
        *out << mbp_cli::seam_selection_text(mesh, seams, automatic.cones);
        written = files.end(k);
      }
    }
    // for the tests of interrupted and failed runs (test_cli): stop with every output written
    // to its temporary file, before any is published
    if(written && std::getenv("MBP_CLI_TEST_STOP_BEFORE_PUBLISH") != nullptr)
      std::raise(SIGSTOP);
    if(!written || !files.publish())
      return fail_with(files.error(), exit_failure, options.json);
  }
  const double write_seconds = seconds_since(start);

  // ------------------------------------------------------------------ report
  if(isolated > 0)
    std::cerr << "note: " << isolated << " vertices in no face were left out of " << options.output << "\n";
  if(!options.write_seams.empty() && !with_seams)
    std::cerr << "note: the mesh is a disk, it needs no seams: " << options.write_seams << " lists none\n";
  if(quality.flipped_faces > 0)
    std::cerr << "warning: " << quality.flipped_faces << " of " << quality.number_of_faces
              << " faces are flipped in the UV layout: the map is not one-to-one"
              << (result.border_convex ? "" : " (the measured border is not convex)") << "\n";

  const Point_3& c = mesh.point(vertex_descriptor(static_cast<Mesh::size_type>(center_index)));
  const std::array<double, 2>& cuv = layout.uv[result.has_center ? layout.center : 0];
  if(options.json)
  {
    mbp_cli::Json_writer j;
    j.begin_object();
    if(generated)
      j.null_member("input");
    else
      j.member("input", options.input);
    j.member("generated_mesh", generated);
    j.member("mesh", mesh_name);
    j.member("output", options.output);
    if(options.svg.empty())
      j.null_member("svg");
    else
      j.member("svg", options.svg);
    j.member("solver", mbp_cli::solver_name(options.solver));
    j.member("center_locator", options.fixed_center ? std::string("vertex") : options.center);
    j.member("border_distance", options.distance);
    j.begin_object("border_choice").member("mode", options.border);
    if(result.chosen_candidate >= 0)
    {
      const Parameterization_result::Candidate& c =
        result.border_candidates[static_cast<std::size_t>(result.chosen_candidate)];
      j.begin_object("chosen")
         .member("index", result.chosen_candidate)
         .member("kind", c.kind)
         .member("blend", c.blend)
         .member("mean_value_interior", c.mean_value)
         .member("angle_distortion", c.angle_distortion)
         .end_object();
    }
    else
      j.null_member("chosen");
    j.begin_array("candidates", false);
    for(const Parameterization_result::Candidate& c : result.border_candidates)
      j.begin_object()
         .member("kind", c.kind)
         .member("blend", c.blend)
         .member("mean_value_interior", c.mean_value)
         .member("valid", c.valid)
         .member("angle_distortion", c.angle_distortion)  // null when not valid
         .end_object();
    j.end_array();
    j.end_object();
    j.member("vertices", layout.vertices.size());
    j.member("faces", layout.faces.size());
    j.member("isolated_vertices", isolated);
    if(with_seams && !automatic_seams)
      j.member("seams", options.seams);
    else
      j.null_member("seams");
    j.member("seam_edges", seams.size());
    if(automatic_seams)
    {
      j.begin_object("automatic_seams")
         .member("seam_edges", seams.size())
         .member("cones", automatic.cones.size());
      j.begin_array("cone_vertices");
      for(vertex_descriptor v : automatic.cones)
        j.element(double(std::size_t(v)));
      j.end_array();
      j.member("length", std::ldexp(automatic.seam_length, -scaled.exponent()))
         .member("genus", automatic.genus)
         .member("border_loops", automatic.number_of_border_loops)
         .member("loops", automatic.number_of_loops)
         .member("seconds", automatic.seconds)
         .end_object();
    }
    else
      j.null_member("automatic_seams");
    j.member("uvs", layout.uv.size());
    j.begin_object("border")
       .member("vertices", result.border_vertices)
       .member("length", border_length)
       .member("convex", result.border_convex)
       .end_object();
    if(result.has_center)
    {
      j.begin_object("center").member("index", center_index);
      j.begin_array("point").element(c.x()).element(c.y()).element(c.z()).end_array();
      j.begin_array("uv").element(cuv[0]).element(cuv[1]).end_array();
      j.end_object();
    }
    else
      j.null_member("center");
    j.begin_object("times")
       .member("preparation", result.preparation)
       .member("center", result.center_time)
       .member("distances", result.distances)
       .member("border_map", result.border_map)
       .member("conformal_border", result.conformal_border_seconds)
       .member("interior", result.interior)  // every layout tried before repair
       .member("output", result.output)
       .member("total", result.total)
       .end_object();
    j.begin_object("io_times")
       .member("read", read_seconds)
       .member("quality", layout.quality_seconds)
       .member("write", write_seconds)
       .end_object();
    j.begin_object("repair")
       .member("enabled", options.repair)
       .member("flipped_faces_before", result.flipped_before_repair)
       .member("repaired", result.repaired)
       .member("blend", result.blend)
       .member("interior", result.mean_value_interior ? "mean value coordinates" : "discrete conformal")
       .member("candidates", result.repair_candidates)
       .member("seconds", result.repair_seconds)
       .end_object();
    j.begin_object("statistics")
       .member("factorizations", result.factorizations)
       .member("back_substitutions", result.back_substitutions)
       .member("factorization_seconds", result.factorization_seconds)
       .member("back_substitution_seconds", result.back_substitution_seconds)
       .end_object();
    j.begin_object("quality")
       .member("angle_distortion", quality.angle_distortion)
       .member("angle_distortion_per_corner", quality.angle_distortion_per_corner)
       .member("l2_stretch", quality.l2_stretch)
       .member("linf_stretch", quality.linf_stretch)
       .member("quasi_conformal_mean", quality.quasi_conformal_mean)
       .member("quasi_conformal_max", quality.quasi_conformal_max)
       .member("area_distortion_mean", quality.area_distortion_mean)
       .member("area_distortion_max", quality.area_distortion_max)
       .member("flipped_faces", quality.flipped_faces)
       .end_object();
    j.end_object();
    std::cout << j.text();
  }
  else
  {
    using mbp_cli::rounded;
    std::cout << mesh_name << ": V " << layout.vertices.size() << ", F " << layout.faces.size()
              << (with_seams ? std::string(automatic_seams ? " | automatic seams " : " | seams ") +
                                 std::to_string(seams.size()) + " edges, " +
                                 (automatic_seams ? std::to_string(automatic.cones.size()) + " cones, " : std::string()) +
                                 std::to_string(layout.uv.size()) + " UVs"
                             : std::string())
              << " | border " << result.border_vertices << " vertices, length " << rounded(border_length)
              << (result.has_center ? " | center " + std::to_string(center_index) + " (" + options.center_name() + ")" +
                                        " | distances " + options.distance
                                    : std::string())
              << " | border " << options.border << ": " << border_summary(result)
              << " | seconds: preparation " << rounded(result.preparation, 3) << ", center "
              << rounded(result.center_time, 3) << ", distances " << rounded(result.distances, 3)
              << ", border map " << rounded(result.border_map, 3)
              << ", conformal border " << rounded(result.conformal_border_seconds, 3)
              << ", layouts " << rounded(result.interior, 3)
              << ", total " << rounded(result.total, 3)
              << " | " << mbp_cli::solver_name(options.solver) << ": " << result.factorizations
              << " factorizations, " << result.back_substitutions << " back-substitutions"
              << " | angle distortion " << rounded(quality.angle_distortion) << ", L2 stretch "
              << rounded(quality.l2_stretch) << ", quasi-conformal mean " << rounded(quality.quasi_conformal_mean)
              << ", flipped faces " << quality.flipped_faces
              << " | " << repair_summary(result, options.repair)
              << " | wrote " << options.output << (options.svg.empty() ? std::string() : ", " + options.svg)
              << "\n";
  }
  return EXIT_SUCCESS;
}
