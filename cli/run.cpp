// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// The run of the measured_parameterization program (run.h): the only file that calls the
// library. The atlas (the default mode): the polygon soup as read goes to
// compute_atlas_of_polygon_soup(), which repairs it, makes its charts and packs them; its
// UVs per polygon corner and chart ids come back in the input's numbering.
// A single chart (--single-chart): the mesh is a CGAL::Surface_mesh; a mesh that is not a
// disk is cut along seams (a CGAL::Seam_mesh over it) and parameterized with
// Conformal_parameterizer_3, for the solver traits of --solver and the border policy of
// --border (Automatic_border, Conformal_border, Conformal_length_border, Measured_border or Circular_border, chosen at
// run time among the instantiated policies); the helpers mesh_input.h and seam_selection.h
// read and check the mesh and the seams.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Seam_mesh.h>

#include <CGAL/Surface_mesh_parameterization/Atlas_report.h>
#include <CGAL/Surface_mesh_parameterization/Conformal_length_border.h>
#include <CGAL/Surface_mesh_parameterization/Conformal_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Default_sparse_cholesky_traits.h>
#include <CGAL/Surface_mesh_parameterization/Disk_seams_report.h>
#include <CGAL/Surface_mesh_parameterization/Fixed_center.h>
#include <CGAL/Surface_mesh_parameterization/Geodesic_border_distance.h>
#include <CGAL/Surface_mesh_parameterization/Geodesic_center_locator.h>
#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_report.h>
#include <CGAL/Surface_mesh_parameterization/Poisson_border_distance.h>
#include <CGAL/Surface_mesh_parameterization/Poisson_center_locator.h>
#include <CGAL/Surface_mesh_parameterization/Straightest_geodesic_border_distance.h>
#include <CGAL/Surface_mesh_parameterization/compute_atlas.h>
#include <CGAL/Surface_mesh_parameterization/compute_disk_seams.h>
#include <CGAL/Surface_mesh_parameterization/main_border.h>
#include <CGAL/Surface_mesh_parameterization/measure_quality.h>
#ifdef MBP_WITH_CHOLMOD
#include <CGAL/Surface_mesh_parameterization/Cholmod_supernodal_cholesky_traits.h>
#endif

#include "mesh_input.h"
#include "run.h"
#include "seam_selection.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <set>
#include <string>
#include <utility>
#include <vector>

typedef CGAL::Simple_cartesian<double>                                Kernel;
typedef Kernel::Point_2                                               Point_2;
typedef Kernel::Point_3                                               Point_3;
typedef CGAL::Surface_mesh<Point_3>                                   Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor                  vertex_descriptor;
typedef boost::graph_traits<Mesh>::halfedge_descriptor                halfedge_descriptor;
typedef boost::graph_traits<Mesh>::edge_descriptor                    edge_descriptor;
typedef boost::graph_traits<Mesh>::face_descriptor                    face_descriptor;

// The mesh cut along seams. Its vertices are halfedges of `Mesh` (one per side of a seam);
// its faces are those of `Mesh`.
typedef Mesh::Property_map<edge_descriptor, bool>                     Seam_edge_map;
typedef Mesh::Property_map<vertex_descriptor, bool>                   Seam_vertex_map;
typedef CGAL::Seam_mesh<Mesh, Seam_edge_map, Seam_vertex_map>         Seam_mesh;

namespace SMP = CGAL::Surface_mesh_parameterization;
typedef SMP::Heat_method_geodesics<CGAL::Heat_method_3::Direct>             Heat;
typedef SMP::Heat_method_geodesics<CGAL::Heat_method_3::Intrinsic_Delaunay> Heat_idt;

namespace {

using mbp_cli::Failure;

// The library's test of a degenerate face, 2A <= threshold * (longest edge)^2, as documented
// for ERROR_DEGENERATE_FACE (the library has no public constant for it): for the message that
// names the face.
const double degenerate_face_threshold = 1e-12;

double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The input vertex (0-based, file order) of a vertex of the parameterized mesh.
std::size_t input_index(const Mesh&, vertex_descriptor v) { return std::size_t(v); }
std::size_t input_index(const Seam_mesh& seam_mesh, boost::graph_traits<Seam_mesh>::vertex_descriptor v)
{
  return std::size_t(target(halfedge_descriptor(v), seam_mesh.mesh()));
}

// The input vertex of the vertex at `position` in the range `vertices(tm)` (how the library's
// reports name vertices).
template <class TriangleMesh>
std::size_t input_index_at(const TriangleMesh& tm, std::size_t position)
{
  return input_index(tm, *std::next(vertices(tm).begin(), static_cast<std::ptrdiff_t>(position)));
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

  template <class Disk>
  SMP::Error_code locate_center(Disk& disk, std::size_t& center) const
  {
    if(m_name == "vertex")
      return m_fixed.locate_center(disk, center);
    if(m_name == "geodesic:fast-marching")
      return SMP::Geodesic_center_locator<SMP::Fast_marching_geodesics>().locate_center(disk, center);
    if(m_name == "geodesic:dijkstra")
      return SMP::Geodesic_center_locator<SMP::Dijkstra_geodesics>().locate_center(disk, center);
    if(m_name == "geodesic:heat")
      return SMP::Geodesic_center_locator<Heat>().locate_center(disk, center);
    if(m_name == "geodesic:heat-idt")
      return SMP::Geodesic_center_locator<Heat_idt>().locate_center(disk, center);
    if(m_name == "geodesic:exact")
      return SMP::Geodesic_center_locator<SMP::Exact_geodesics>().locate_center(disk, center);
    return SMP::Poisson_center_locator().locate_center(disk, center);
  }

private:
  SMP::Fixed_center<TriangleMesh> m_fixed;
  std::string m_name;
};

// The border distance of the command line (a model of `MeasuredBorderDistance`), chosen at
// run time: Poisson, a geodesic method, or straightest geodesics.
class Command_line_border_distance
{
public:
  explicit Command_line_border_distance(const std::string& name = "poisson") : m_name(name) { }

  template <class Disk>
  SMP::Error_code prepare(Disk& disk) const
  {
    return dispatch([&disk](const auto& policy) { return policy.prepare(disk); });
  }

  template <class Disk>
  SMP::Error_code compute_border_distances(Disk& disk, std::size_t center, std::vector<double>& distances) const
  {
    return dispatch([&](const auto& policy) { return policy.compute_border_distances(disk, center, distances); });
  }

private:
  template <class F>
  SMP::Error_code dispatch(const F& f) const
  {
    if(m_name == "fast-marching")
      return f(SMP::Geodesic_border_distance<SMP::Fast_marching_geodesics>());
    if(m_name == "dijkstra")
      return f(SMP::Geodesic_border_distance<SMP::Dijkstra_geodesics>());
    if(m_name == "heat")
      return f(SMP::Geodesic_border_distance<Heat>());
    if(m_name == "heat-idt")
      return f(SMP::Geodesic_border_distance<Heat_idt>());
    if(m_name == "exact")
      return f(SMP::Geodesic_border_distance<SMP::Exact_geodesics>());
    if(m_name == "straightest")
      return f(SMP::Straightest_geodesic_border_distance());
    return f(SMP::Poisson_border_distance());
  }

  std::string m_name;
};

// What one parameterization of `TriangleMesh` (the mesh, or the seam mesh over it) works
// with: the mesh, its border, the policies of the command line and the output maps.
template <class TriangleMesh>
struct Context
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor   tm_vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor tm_halfedge_descriptor;
  typedef decltype(get(CGAL::dynamic_vertex_property_t<Point_2>(), std::declval<const TriangleMesh&>())) Uv_map;
  typedef decltype(get(CGAL::dynamic_vertex_property_t<bool>(), std::declval<const TriangleMesh&>())) Flag_map;

  // `seam_mesh` is `&tm` for a seam mesh and null otherwise; `mesh` is the input mesh
  Context(const TriangleMesh& tm, const Mesh& mesh, const Seam_mesh* seam_mesh, tm_halfedge_descriptor bhd,
          const mbp_cli::Options& options)
    : tm(tm), mesh(mesh), seam_mesh(seam_mesh), bhd(bhd), options(options),
      locator(options.center), distance(options.distance),
      uvmap(get(CGAL::dynamic_vertex_property_t<Point_2>(), tm)),
      parameterized(get(CGAL::dynamic_vertex_property_t<bool>(), tm))
  {
    for(tm_vertex_descriptor v : vertices(tm))
      put(parameterized, v, false);
    for(tm_halfedge_descriptor h : CGAL::halfedges_around_face(bhd, tm))
      border.push_back(source(h, tm));
  }

  const TriangleMesh& tm;
  const Mesh& mesh;
  const Seam_mesh* seam_mesh;
  tm_halfedge_descriptor bhd;
  const mbp_cli::Options& options;
  std::vector<tm_vertex_descriptor> border;  // the longest border loop, from source(bhd)
  Command_line_center_locator<TriangleMesh> locator;
  Command_line_border_distance distance;
  Uv_map uvmap;
  Flag_map parameterized;
};

// The call of the parameterizer of one border policy (the policy of --border, so that each
// border is instantiated with the command line's center locator and border distance once per
// solver and mesh type). Returns the library's report of the call (its status included).
template <class ConcurrencyTag, class TriangleMesh, class BorderPolicy, class SolverTraits>
SMP::Parameterization_report parameterize_with_tag(Context<TriangleMesh>& c, const BorderPolicy& border,
                                                   const SolverTraits& traits)
{
  const SMP::Conformal_parameterizer_3<TriangleMesh, BorderPolicy, SolverTraits, ConcurrencyTag> parameterizer(
    border, traits, c.options.repair ? SMP::BLEND_TOWARD_CIRCLE : SMP::NO_REPAIR);
  SMP::Parameterization_report report;
  // the vertex index map is not used by the parameterizer (it indexes the component itself)
  parameterizer.parameterize(c.tm, c.bhd, c.uvmap, get(CGAL::dynamic_vertex_property_t<int>(), c.tm),
                             c.parameterized, &report);
  return report;
}

// The same with the package's threads of --threads: CGAL::Parallel_tag from 2 on.
template <class TriangleMesh, class BorderPolicy, class SolverTraits>
SMP::Parameterization_report parameterize_with(Context<TriangleMesh>& c, const BorderPolicy& border,
                                               const SolverTraits& traits)
{
  if(c.options.threads >= 2)
    return parameterize_with_tag<CGAL::Parallel_tag>(c, border, traits);
  return parameterize_with_tag<CGAL::Sequential_tag>(c, border, traits);
}

// The parameterization with the solver traits `traits`, for the border policy of --border.
template <class TriangleMesh, class SolverTraits>
SMP::Parameterization_report parameterize_with_solver(Context<TriangleMesh>& c, const SolverTraits& traits)
{
  typedef SMP::Measured_border<Command_line_center_locator<TriangleMesh>, Command_line_border_distance> Measured;
  typedef SMP::Automatic_border<Command_line_center_locator<TriangleMesh>, Command_line_border_distance> Automatic;
  const Measured measured(c.locator, c.distance);
  switch(c.options.border)
  {
  case mbp_cli::Border::conformal:
    return parameterize_with(c, SMP::Conformal_border(), traits);
  case mbp_cli::Border::conformal_lengths:
    return parameterize_with(c, SMP::Conformal_length_border(), traits);
  case mbp_cli::Border::circle:
    return parameterize_with(c, SMP::Circular_border(), traits);
  case mbp_cli::Border::measured:
    return parameterize_with(c, measured, traits);
  case mbp_cli::Border::automatic:
    break;
  }
  return parameterize_with(c, Automatic(measured, SMP::Distortion_bound{c.options.bounds.max_angle_distortion,
                                                                         c.options.bounds.max_area_spread}),
                           traits);
}

// The parameterization with the solver of --solver.
template <class TriangleMesh>
SMP::Parameterization_report parameterize_with_library(Context<TriangleMesh>& c)
{
#ifdef MBP_WITH_CHOLMOD
  typedef SMP::Cholmod_supernodal_cholesky_traits Cholmod;
  // the BLAS threads of --threads (0: the BLAS is left alone)
  const int blas_threads = static_cast<int>(c.options.threads);
  if(c.options.solver == mbp_cli::Solver::cholmod)
    return parameterize_with_solver(c, Cholmod(Cholmod::AMD, blas_threads));
  if(c.options.solver == mbp_cli::Solver::cholmod_nd)
    return parameterize_with_solver(c, Cholmod(Cholmod::NESTED_DISSECTION, blas_threads));
#endif
  return parameterize_with_solver(c, SMP::Default_sparse_cholesky_traits());
}

// The input vertex of the center the library located (0 when it located none, as in the
// messages of the failures).
template <class TriangleMesh>
std::size_t center_input_vertex(const Context<TriangleMesh>& c, const SMP::Parameterization_report& r)
{
  return r.has_center ? input_index_at(c.tm, r.center) : 0;
}

// Why the mesh (or the mesh cut along seams) is not a topological disk.
std::string explain_not_a_disk(const Mesh& mesh, const Seam_mesh* seam_mesh)
{
  const mbp_cli::Mesh_topology input = mbp_cli::mesh_topology(mesh);
  if(seam_mesh != nullptr)
    return mbp_cli::explain_cut(input, mbp_cli::mesh_topology(*seam_mesh));
  if(input.genus > 0)
    return "the surface has genus " + std::to_string(input.genus) +
           " (handles); cut every handle with seams: --seams=FILE.selection.txt";
  return "the longest border touches itself, or a vertex is non-manifold";
}

// Which border vertices straightest geodesics did not reach (those at distance 0 in the
// report): the first of them, and how many.
template <class TriangleMesh>
std::string explain_unreachable(const Context<TriangleMesh>& c, const SMP::Parameterization_report& r)
{
  std::size_t k = 0;
  while(k + 1 < r.border_distances.size() && r.border_distances[k] > 0.)
    ++k;
  return "the straightest geodesic from the center (vertex " + std::to_string(center_input_vertex(c, r)) +
         ") does not reach border vertex " + std::to_string(input_index(c.tm, c.border[k])) + " (" +
         std::to_string(r.unreachable_border_vertices) + " of " + std::to_string(c.border.size()) +
         " border vertices are not reached)";
}

// Why the parameterization failed, with details the library's code does not give.
template <class TriangleMesh>
Failure explain_failure(const Context<TriangleMesh>& c, const SMP::Parameterization_report& r)
{
  Failure f;
  f.code = r.status;
  if(r.status == SMP::ERROR_DEGENERATE_FACE)
    f.detail = mbp_cli::find_degenerate_face(c.mesh, degenerate_face_threshold);
  else if(r.status == SMP::ERROR_NON_FINITE_COORDINATES)
    f.detail = mbp_cli::find_non_finite_vertex(c.mesh);
  else if(r.status == SMP::ERROR_NO_TOPOLOGICAL_DISC)
    f.detail = explain_not_a_disk(c.mesh, c.seam_mesh);
  else if(r.status == SMP::ERROR_NO_1_TO_1_MAPPING)
    f.detail = std::to_string(r.flipped_faces_before_repair) + " faces are flipped by the measured border" +
               (c.options.repair ? std::string(" and no blend toward a circle repairs them")
                                 : std::string(" (repair is off: --no-repair)"));
  else if(r.status == SMP::ERROR_DEGENERATE_BORDER_MAP)
    f.detail = "seen from the center (vertex " + std::to_string(center_input_vertex(c, r)) +
               "), two consecutive border vertices lie in the same direction, or a border distance is not"
               " positive; try another center (--center=geodesic or --center=vertex:N)";
  else if(r.status == SMP::ERROR_DISTANCE_COMPUTATION_FAILED && c.options.distance == "straightest" &&
          r.unreachable_border_vertices > 0)
    f.detail = explain_unreachable(c, r);
  return f;
}

// The vertex of the parameterized mesh that `--center=vertex:N` names, or a failure (N out
// of range, in no face, on a seam, on the longest border).
template <class TriangleMesh>
Failure center_vertex(const Context<TriangleMesh>& c, std::size_t n,
                      typename Context<TriangleMesh>::tm_vertex_descriptor& center)
{
  const std::string option = "--center=vertex:" + std::to_string(n);
  Failure f;  // a check of the program: no library code
  // Surface_mesh numbers the vertices in the order they were added: the file order.
  if(n >= num_vertices(c.mesh))
  {
    f.detail = option + ": vertex index out of range (the mesh has " + std::to_string(num_vertices(c.mesh)) +
               " vertices, numbered from 0)";
    return f;
  }
  const vertex_descriptor v(static_cast<Mesh::size_type>(n));
  if(c.mesh.is_isolated(v))
  {
    f.detail = option + ": the vertex is in no face";
    return f;
  }
  if(c.seam_mesh != nullptr && c.seam_mesh->has_on_seam(v))
  {
    f.detail = option + ": the vertex lies on a seam, which is on the border of the cut mesh; the center must be"
                        " an interior vertex";
    return f;
  }
  center = mesh_vertex(c.tm, v);
  for(auto h : CGAL::halfedges_around_face(c.bhd, c.tm))
    if(target(h, c.tm) == center)
      f.detail = option + ": the vertex lies on the border; the center must be an interior vertex";
  return f;
}

// The UVs of the parameterized vertices, in the numbering of the output: 'v' lines are the
// input vertices that are in a face, in input order (the checks before leave one connected
// component, all of which is parameterized); 'vt' lines the parameterized vertices of the
// mesh, grouped by input vertex. Sets `uv_index` to the 'vt' index of every vertex.
template <class TriangleMesh, class IndexMap>
Failure number_uvs(const Context<TriangleMesh>& c, IndexMap uv_index, mbp_cli::Uv_layout& layout)
{
  typedef typename Context<TriangleMesh>::tm_vertex_descriptor tm_vertex_descriptor;
  std::vector<std::pair<std::size_t, tm_vertex_descriptor> > uv_order;
  for(tm_vertex_descriptor v : vertices(c.tm))
    if(get(c.parameterized, v))
      uv_order.emplace_back(input_index(c.tm, v), v);
  std::stable_sort(uv_order.begin(), uv_order.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  for(const auto& u : uv_order)
  {
    const Point_2& q = get(c.uvmap, u.second);
    if(!std::isfinite(q.x()) || !std::isfinite(q.y()))
    {
      Failure f;
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
  return Failure();
}

// The layout of a successful parameterization: UVs, faces, border and center.
template <class TriangleMesh>
Failure make_layout(const Context<TriangleMesh>& c, const SMP::Parameterization_report& r,
                    mbp_cli::Uv_layout& layout)
{
  auto uv_index = get(CGAL::dynamic_vertex_property_t<std::size_t>(), c.tm);
  const Failure f = number_uvs(c, uv_index, layout);
  if(f.failed())
    return f;
  for(face_descriptor fd : faces(c.tm))  // the faces of a seam mesh are those of the mesh
  {
    std::array<std::size_t, 3> t;
    std::size_t k = 0;
    for(auto h : CGAL::halfedges_around_face(halfedge(fd, c.tm), c.tm))
      t[k++] = get(uv_index, target(h, c.tm));
    layout.faces.push_back(t);
  }
  for(auto v : c.border)
    layout.border.push_back(get(uv_index, v));
  layout.has_center = r.has_center;
  layout.center_vertex = center_input_vertex(c, r);
  if(r.has_center)  // the center is interior: one UV
    for(auto v : vertices(c.tm))
      if(get(c.parameterized, v) && input_index(c.tm, v) == layout.center_vertex)
        layout.center = get(uv_index, v);
  return Failure();
}

// The distortion of the layout, per face and in all.
template <class TriangleMesh>
void measure_distortion(const Context<TriangleMesh>& c, mbp_cli::Run_result& result)
{
  const std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  auto face_quality = get(CGAL::dynamic_face_property_t<SMP::Face_quality>(), c.tm);
  const SMP::Parameterization_quality q = SMP::measure_quality_per_face(c.tm, faces(c.tm), c.uvmap, face_quality);
  for(face_descriptor fd : faces(c.tm))
  {
    const SMP::Face_quality& fq = get(face_quality, fd);
    result.layout.face_angle_distortion.push_back(fq.angle_distortion);
    result.layout.face_flipped.push_back(!(fq.uv_area > 0.));
  }
  mbp_cli::Quality& r = result.quality;
  r.angle_distortion = q.angle_distortion;
  r.angle_distortion_per_corner = q.angle_distortion_per_corner;
  r.l2_stretch = q.l2_stretch;
  r.linf_stretch = q.linf_stretch;
  r.quasi_conformal_mean = q.quasi_conformal_mean;
  r.quasi_conformal_max = q.quasi_conformal_max;
  r.area_distortion_mean = q.area_distortion_mean;
  r.area_distortion_max = q.area_distortion_max;
  r.flipped_faces = q.flipped_faces;
  r.number_of_faces = q.number_of_faces;
  result.quality_seconds = seconds_since(start);
}

// Parameterizes the mesh or the seam mesh of `c` and fills `result`, or returns why it failed.
template <class TriangleMesh>
Failure parameterize_mesh(Context<TriangleMesh>& c, mbp_cli::Run_result& result)
{
  if(c.options.fixed_center)
  {
    typename Context<TriangleMesh>::tm_vertex_descriptor v;
    const Failure f = center_vertex(c, c.options.center_vertex, v);
    if(f.failed())
      return f;
    c.locator = Command_line_center_locator<TriangleMesh>(v);
  }
  result.report = parameterize_with_library(c);
  result.border_vertices = c.border.size();
  if(result.report.status != SMP::OK)
    return explain_failure(c, result.report);
  const Failure f = make_layout(c, result.report, result.layout);
  if(f.failed())
    return f;
  measure_distortion(c, result);
  return Failure();
}

// Automatic seams (compute_disk_seams()) of a mesh that is not a disk: its seam edges into
// `seams`, or why there are none.
Failure automatic_seams_of(Mesh& mesh, std::vector<edge_descriptor>& seams, SMP::Disk_seams_report& report)
{
  Seam_edge_map edge_flags = mesh.add_property_map<edge_descriptor, bool>("e:automatic_seam", false).first;
  Seam_vertex_map vertex_flags = mesh.add_property_map<vertex_descriptor, bool>("v:automatic_seam", false).first;
  Failure f;
  f.code = SMP::compute_disk_seams(mesh, edge_flags, vertex_flags, SMP::Disk_seams_options(), &report);
  if(f.code != SMP::OK)
  {
    f.detail = std::string("automatic seams: ") + SMP::disk_seams_problem_message(report.problem);
    // positions in vertices(mesh) and faces(mesh): the input numbering (nothing is removed)
    if(report.problem_vertex != SMP::Disk_seams_report::no_element)
      f.detail += " (vertex " + std::to_string(report.problem_vertex) + ")";
    if(report.problem_face != SMP::Disk_seams_report::no_element)
      f.detail += " (face " + std::to_string(report.problem_face) + ")";
  }
  else
    for(edge_descriptor e : edges(mesh))
      if(get(edge_flags, e))
        seams.push_back(e);
  mesh.remove_property_map(edge_flags);
  mesh.remove_property_map(vertex_flags);
  return f;
}

// Both sides of each seam edge, for the SVG: the edge of each of its two faces, as 'vt' pairs.
std::vector<std::array<std::size_t, 2> > seam_sides(const Mesh& mesh, const std::vector<edge_descriptor>& seams,
                                                    const mbp_cli::Uv_layout& layout)
{
  std::vector<std::array<std::size_t, 2> > sides;
  const std::set<edge_descriptor> on_seam(seams.begin(), seams.end());
  std::size_t i = 0;
  for(face_descriptor fd : faces(mesh))
  {
    const std::array<std::size_t, 3>& t = layout.faces[i++];
    std::size_t k = 0;  // the k-th halfedge of the face ends at UV t[k]
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(fd, mesh), mesh))
    {
      if(on_seam.count(edge(h, mesh)) > 0)
        sides.push_back({t[(k + 2) % 3], t[k]});
      ++k;
    }
  }
  return sides;
}

// The input point of vertex `i`.
std::array<double, 3> point_of(const Mesh& mesh, std::size_t i)
{
  const Point_3& p = mesh.point(vertex_descriptor(static_cast<Mesh::size_type>(i)));
  return {p.x(), p.y(), p.z()};
}

// ---------------------------------------------------------------------------- the atlas

// The soup of a mesh (the generated curved disk): its points in order, its faces.
void soup_of(const Mesh& mesh, mbp_cli::Polygon_soup& soup)
{
  for(vertex_descriptor v : vertices(mesh))
  {
    const Point_3& p = mesh.point(v);
    soup.points.push_back({p.x(), p.y(), p.z()});
  }
  for(face_descriptor fd : faces(mesh))
  {
    for(vertex_descriptor v : CGAL::vertices_around_face(halfedge(fd, mesh), mesh))
      soup.corners.push_back(static_cast<std::uint32_t>(std::size_t(v)));
    soup.face_end.push_back(static_cast<std::uint32_t>(soup.corners.size()));
  }
}

// The power of two that brings coordinates so large (or small) that squared lengths would
// overflow (above 2^60, about 1e18) or underflow (below 2^-60) near 1 (exact in floating
// point: the atlas does not depend on the scale); 0 when they need none.
int scale_exponent_of(const std::vector<std::array<double, 3> >& points)
{
  double largest = 0.;
  for(const std::array<double, 3>& p : points)
    largest = (std::max)({largest, std::abs(p[0]), std::abs(p[1]), std::abs(p[2])});
  if(!std::isfinite(largest) || !(largest > std::ldexp(1., 60) || (largest > 0. && largest < std::ldexp(1., -60))))
    return 0;
  return -std::ilogb(largest);
}

// The area of polygon `i` of the soup in 3D (the norm of its vector area) and in UV (the
// absolute value of its shoelace area), its points multiplied by 2^exponent; both from its
// first corner, so that a polygon far from the origin loses no precision.
std::array<double, 2> polygon_areas(const mbp_cli::Polygon_soup& soup, const std::vector<std::array<double, 2> >& uv,
                                    std::size_t i, int exponent)
{
  const std::size_t begin = soup.face_begin(i), n = soup.face_size(i);
  if(n < 3)
    return {0., 0.};
  const std::array<double, 3>& o = soup.points[soup.corners[begin]];
  auto from_first = [&](std::size_t k) {
    const std::array<double, 3>& p = soup.points[soup.corners[begin + k]];
    return std::array<double, 3>{std::ldexp(p[0] - o[0], exponent), std::ldexp(p[1] - o[1], exponent),
                                 std::ldexp(p[2] - o[2], exponent)};
  };
  std::array<double, 3> vector_area = {0., 0., 0.};
  double uv_area = 0.;
  for(std::size_t k = 1; k + 1 < n; ++k)
  {
    const std::array<double, 3> p = from_first(k), q = from_first(k + 1);
    vector_area[0] += p[1] * q[2] - p[2] * q[1];
    vector_area[1] += p[2] * q[0] - p[0] * q[2];
    vector_area[2] += p[0] * q[1] - p[1] * q[0];
    const std::array<double, 2>& a = uv[begin], &b = uv[begin + k], &c = uv[begin + k + 1];
    uv_area += (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
  }
  return {0.5 * std::sqrt(vector_area[0] * vector_area[0] + vector_area[1] * vector_area[1] +
                          vector_area[2] * vector_area[2]),
          0.5 * std::abs(uv_area)};
}

// Why the library made no atlas, with the details its code does not give.
Failure explain_atlas_failure(SMP::Error_code code, const mbp_cli::Polygon_soup& soup, std::size_t polygons,
                              const mbp_cli::Options& options)
{
  Failure f;
  f.code = code;
  if(code == SMP::ERROR_EMPTY_MESH)
  {
    // all the points of the polygons at one point, or no polygon with an area
    bool one_point = true;
    for(std::uint32_t c : soup.corners)
      one_point = one_point && soup.points[c] == soup.points[soup.corners[0]];
    const std::array<double, 3>& p = soup.points[soup.corners[0]];
    std::vector<bool> used(soup.points.size(), false);
    std::size_t count = 0;
    for(std::uint32_t c : soup.corners)
      if(!used[c])
      {
        used[c] = true;
        ++count;
      }
    f.detail = one_point ? "all " + std::to_string(count) + " vertices of its faces coincide (at " +
                             mbp_cli::exact(p[0]) + " " + mbp_cli::exact(p[1]) + " " + mbp_cli::exact(p[2]) +
                             "): the mesh has no extent"
                         : "no polygon has three distinct points and a nonzero area (" +
                             std::to_string(polygons) + (polygons == 1 ? " polygon)" : " polygons)");
  }
  else if(code == SMP::ERROR_WRONG_PARAMETER)
    f.detail = "the charts do not fit into a texture of " + std::to_string(options.resolution) + " x " +
               std::to_string(options.resolution) + " texels with a gutter of " + std::to_string(options.gutter) +
               " texels (raise --resolution or lower --gutter)";
  return f;
}

// The polygons of the soup that have corners (the library takes polygons of 1 corner or more).
std::vector<std::vector<std::size_t> > polygons_with_corners(const mbp_cli::Polygon_soup& soup)
{
  std::vector<std::vector<std::size_t> > polygons;
  polygons.reserve(soup.number_of_faces());
  for(std::size_t i = 0; i < soup.number_of_faces(); ++i)
    if(soup.face_size(i) > 0)
      polygons.emplace_back(soup.corners.begin() + std::ptrdiff_t(soup.face_begin(i)),
                            soup.corners.begin() + std::ptrdiff_t(soup.face_end[i]));
  return polygons;
}

// The library's UVs and charts of the polygons with corners, given to the input's polygons:
// one UV per corner of the soup, the chart of every polygon (none for those without corners).
Failure take_atlas(const std::vector<std::vector<Point_2> >& corner_uvs, const std::vector<std::size_t>& charts,
                   mbp_cli::Atlas_result& a)
{
  const mbp_cli::Polygon_soup& soup = a.soup;
  a.uv.reserve(soup.corners.size());
  a.polygon_chart.assign(soup.number_of_faces(), mbp_cli::Atlas_result::no_chart);
  for(std::size_t i = 0, p = 0; i < soup.number_of_faces(); ++i)
  {
    if(soup.face_size(i) == 0)
      continue;
    for(const Point_2& q : corner_uvs[p])
    {
      if(!std::isfinite(q.x()) || !std::isfinite(q.y()))
        return Failure{SMP::OK, "the library gave a non-finite UV to a corner of polygon " + std::to_string(i)};
      a.uv.push_back({q.x(), q.y()});
    }
    a.polygon_chart[i] = charts[p++];
  }
  return Failure();
}

// The input's lengths and areas in the report: the points were multiplied by 2^exponent.
void unscale_report(SMP::Atlas_report& report, int exponent)
{
  if(exponent == 0)
    return;
  report.texel_density = std::ldexp(report.texel_density, exponent);
  for(SMP::Atlas_chart_report& c : report.charts)
    c.area_3d = std::ldexp(c.area_3d, -2 * exponent);
}

} // namespace

namespace mbp_cli {

struct Run::Impl
{
  Mesh mesh;
  std::string where;  // names the failures: the input, and the seams it was cut along
  Run_result result;
  std::vector<edge_descriptor> seams;
  SMP::Disk_seams_report automatic;

  Run_error fail(const Failure& f) const { return Run_error{where + ": " + f.message(), int(f.code)}; }

  Run_error make_atlas(const Options& options);
  Run_error cut(const Options& options);
  Failure parameterize_cut(const Options& options);
  Failure parameterize_disk(const Options& options);
  void finish(const Options& options, int scale_exponent);
};

// The atlas of the soup: the library's compute_atlas_of_polygon_soup() on its polygons with
// corners (its points scaled by a power of two when their magnitude needs it), then the UVs
// and charts in the input's numbering and the distortion of every polygon.
Run_error Run::Impl::make_atlas(const Options& options)
{
  Atlas_result& a = result.atlas;
  Polygon_soup& soup = a.soup;
  if(soup.points.empty() && num_vertices(mesh) > 0)  // the generated curved disk
    soup_of(mesh, soup);
  const int exponent = scale_exponent_of(soup.points);
  std::vector<std::array<double, 3> > scaled;
  if(exponent != 0)
    for(const std::array<double, 3>& p : soup.points)
      scaled.push_back({std::ldexp(p[0], exponent), std::ldexp(p[1], exponent), std::ldexp(p[2], exponent)});
  std::vector<std::vector<std::size_t> > polygons = polygons_with_corners(soup);
  a.empty_polygons = soup.number_of_faces() - polygons.size();
  if(polygons.empty())
    return fail(Failure{SMP::ERROR_EMPTY_MESH, "it has no faces (" + std::to_string(soup.points.size()) + " vertices)"});
  SMP::Atlas_options atlas_options = options.bounds;
  atlas_options.resolution = options.resolution;
  atlas_options.gutter = options.gutter;
  std::vector<std::vector<Point_2> > corner_uvs;
  std::vector<std::size_t> charts;
  const SMP::Error_code status = SMP::compute_atlas_of_polygon_soup(exponent != 0 ? scaled : soup.points, polygons,
                                                                    corner_uvs, charts, atlas_options, &a.report);
  if(status != SMP::OK)
    return fail(explain_atlas_failure(status, soup, polygons.size(), options));
  std::vector<std::vector<std::size_t> >().swap(polygons);
  const Failure f = take_atlas(corner_uvs, charts, a);
  if(f.failed())
    return fail(f);
  // the area distortion of every polygon after the one scale of the atlas
  const double uv_per_3d_area = a.report.texel_density * a.report.texel_density;
  a.polygon_area_distortion.assign(soup.number_of_faces(), 0.);
  for(std::size_t i = 0; i < soup.number_of_faces(); ++i)
  {
    const std::array<double, 2> area = polygon_areas(soup, a.uv, i, exponent);
    if(area[0] > 0. && area[1] > 0. && uv_per_3d_area > 0.)
      a.polygon_area_distortion[i] = std::abs(std::log(area[1] / (area[0] * uv_per_3d_area)));
  }
  unscale_report(a.report, exponent);
  return Run_error();
}

// The seams of a mesh that is not a disk: automatic ones, or those of --seams.
Run_error Run::Impl::cut(const Options& options)
{
  if(result.seams.automatic)
  {
    const Failure f = automatic_seams_of(mesh, seams, automatic);
    return f.failed() ? fail(f) : Run_error();
  }
  std::string error = check_regular_input(options.seams);
  if(error.empty())
    error = read_seam_selection(options.seams, mesh, seams);
  if(!error.empty())
    return Run_error{options.seams + ": " + error, 0};
  return Run_error();
}

// The parameterization of the mesh cut along `seams`: a Seam_mesh over the mesh.
Failure Run::Impl::parameterize_cut(const Options& options)
{
  Seam_edge_map seam_edges = mesh.add_property_map<edge_descriptor, bool>("e:seam", false).first;
  Seam_vertex_map seam_vertices = mesh.add_property_map<vertex_descriptor, bool>("v:seam", false).first;
  Seam_mesh seam_mesh(mesh, seam_edges, seam_vertices);
  for(edge_descriptor e : seams)
    seam_mesh.add_seam(source(e, mesh), target(e, mesh));
  where += " cut along " + (result.seams.automatic ? std::string("automatic seams") : options.seams);

  // one piece and no new border loop (handles left uncut are found by the parameterizer)
  Failure f;
  f.detail = check_cut(mesh_topology(mesh), mesh_topology(seam_mesh));
  if(f.failed())
  {
    f.code = SMP::ERROR_NO_TOPOLOGICAL_DISC;
    return f;
  }
  boost::graph_traits<Seam_mesh>::halfedge_descriptor bhd;
  f = find_longest_border(seam_mesh, bhd, result.border_length);
  if(f.failed())
    return f;
  Context<Seam_mesh> c(seam_mesh, mesh, &seam_mesh, bhd, options);
  f = parameterize_mesh(c, result);
  if(!f.failed())
    result.layout.seam_sides = seam_sides(mesh, seams, result.layout);
  return f;
}

// The parameterization of a mesh that is a disk.
Failure Run::Impl::parameterize_disk(const Options& options)
{
  halfedge_descriptor bhd;
  const Failure f = find_longest_border(mesh, bhd, result.border_length);
  if(f.failed())
    return f;
  Context<Mesh> c(mesh, mesh, nullptr, bhd, options);
  return parameterize_mesh(c, result);
}

// What the writers need of the input mesh (its coordinates restored) and of the seams.
void Run::Impl::finish(const Options& options, int scale_exponent)
{
  Uv_layout& layout = result.layout;
  for(std::size_t i : layout.vertices)
    layout.points.push_back(point_of(mesh, i));
  if(layout.has_center)
    layout.center_point = point_of(mesh, layout.center_vertex);
  result.input_vertices = num_vertices(mesh);
  Seams& s = result.seams;
  s.edges = seams.size();
  s.cones = automatic.cones;  // positions in vertices(mesh): the input numbering
  s.length = std::ldexp(automatic.seam_length, -scale_exponent);
  s.genus = automatic.genus;
  s.border_loops = automatic.number_of_border_loops;
  s.loops = automatic.number_of_loops;
  s.seconds = automatic.seconds;
  if(!options.write_seams.empty())
    s.selection = seam_selection_text(mesh, seams, automatic.cones);
}

Run::Run() : m(new Impl) { }
Run::~Run() = default;

std::array<std::size_t, 2> Run::generate_curved_disk()
{
  make_curved_disk(m->mesh);
  m->where = "generated curved disk";
  return {num_vertices(m->mesh), num_faces(m->mesh)};
}

Run_error Run::read(const std::string& path, Mode mode)
{
  m->where = path;
  const Failure f = mode == Mode::atlas ? read_soup_file(path, m->result.atlas.soup) : read_mesh(path, m->mesh);
  return f.failed() ? m->fail(f) : Run_error();
}

Run_error Run::parameterize(const Options& options)
{
  if(options.mode == Mode::atlas)
    return m->make_atlas(options);
  Failure f = check_mesh(m->mesh);
  if(f.failed())
    return m->fail(f);
  // coordinates so large (or small) that squared lengths overflow are scaled by a power of
  // two while the library runs (exact; the output has the input's coordinates)
  Scaled_coordinates<Mesh> scaled(m->mesh);
  // a mesh that is not a disk is cut along seams: those of --seams, or automatic seams
  const Mesh_topology topology = mesh_topology(m->mesh);
  Seams& seams = m->result.seams;
  seams.automatic = options.seams.empty() && !(topology.border_loops == 1 && topology.genus == 0);
  seams.cut = !options.seams.empty() || seams.automatic;
  if(seams.cut)
  {
    const Run_error e = m->cut(options);
    if(e.failed())
      return e;
    f = m->parameterize_cut(options);
  }
  else
    f = m->parameterize_disk(options);
  if(f.failed())
    return m->fail(f);
  scaled.restore();
  m->finish(options, scaled.exponent());
  return Run_error();
}

const Run_result& Run::result() const { return m->result; }

} // namespace mbp_cli
