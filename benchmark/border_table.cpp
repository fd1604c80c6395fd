// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// The border table of issue 11: on every disk mesh of a directory, the borders of
// Measured_conformal_parameterizer_3 (conformal, automatic, the paper's measured borders,
// CGAL's circle) beside CGAL's LSCM and Boundary First Flattening's command line: angle
// distortion, L2 stretch, flips, one-to-one, time, factorizations, the member the automatic
// border kept, and the single-factorization floor.
//
//   border_table [options] [MESH_DIR]   (default MESH_DIR: ../shared/data/meshes, as configured)
//
//   --runs N            timed runs per method and mesh (default 3); the median is reported
//   --mesh NAME         only this file of MESH_DIR (repeatable)
//   --bff PATH          Boundary First Flattening's command line (default, as configured:
//                       ../shared/peers/bff-command-line); --bff none: no BFF column
//   --cross-check NAME  a mesh on which our circle is compared with CGAL's own DCP
//                       (repeatable; default: snail.obj maxFace.obj lion-head.off mask.off)
//   --method NAME       only this method (a name of the tables, e.g. "conformal L"; repeatable)
//   --scale L           also bimba_i.obj refined L times by 1-to-4 midpoint subdivision
//                       (levels 1..L; default 1; 0: none), timed like the other meshes but
//                       kept out of the medians (no real disk reaches 45k vertices)
//
// Methods (each run builds a new parameterizer; its parameterize(mesh, bhd, uv, vimap, vpmap)
// call is timed, the maps are prepared outside the timing, so SMP::parameterize()'s wrapper is
// not counted):
//   conformal    Conformal_parameterizer_3<Mesh, Conformal_border> (Eigen LDLT)
//   conformal L  Conformal_parameterizer_3<Mesh, Conformal_length_border> (Eigen LDLT; issue 23:
//                the conformal border with conformal lengths where it overlaps itself)
//   auto         Conformal_parameterizer_3<Mesh, Automatic_border<Poisson_center_locator,
//                Geodesic_border_distance<Fast_marching_geodesics>>>: the command line's
//                default (one factorization)
//   auto P       Conformal_parameterizer_3<Mesh> (Automatic_border<>: the paper's default
//                policies, Poisson distances, for its measured member; two factorizations)
//   MBPPP        Measured_conformal_parameterizer_3<Mesh> (default repair)
//   MBPGP        the same with the fast marching geodesic distance (default repair)
//   circle       Conformal_parameterizer_3<Mesh, Circular_border>
//   LSCM         CGAL's LSCM_parameterizer_3<Mesh>, defaults (free border, two fixed
//                vertices: the algorithm of libigl's LSCM)
//   BFF          bff-command-line IN.obj OUT.obj (no option: the conformal map with boundary
//                scale factors 0). IN.obj is this program's mesh written at full precision
//                (so that vertex i of the output is vertex i of the mesh); the whole process
//                is timed (start, reading, solving, writing the OBJ, exit). Its output's
//                (v, vt) corners give a mesh with the input's 3D points and the output's UVs,
//                measured like ours. The output has 6 decimals per UV.
//   floor        SolverTraits::factor() of L_II (analyze + factorize, Eigen LDLT), L_II
//                assembled as the package assembles it (benchmark_support.h); "floor+asm"
//                also counts that assembly (this benchmark's, with Eigen triplets: the
//                package's own is internal and not timed separately any more).
//   with CHOLMOD (MBP_WITH_CHOLMOD): conformal and auto with
//                Cholmod_supernodal_cholesky_traits, and their floor.
//   CGAL DCP     (cross-check meshes only) CGAL's Discrete_conformal_map_parameterizer_3<Mesh>
//                with Circular_border_arc_length_parameterizer_3, defaults (BiCGSTAB).
// The runs are interleaved (run 1 of every method, then run 2, ...). "load": the 1-minute
// load average (/proc/loadavg) at the end of the row.
//
// Distortion: SMP::measure_quality() (angle distortion: the paper's conformal distortion;
// L2: Sander's stretch, 1 = optimal; flipped faces) and SMP::is_one_to_one_uv_map().
//
// Markdown tables on stdout, progress on stderr; the summary ends with the targets of
// issue 11 evaluated on the numbers of this run.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/Circular_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_conformal_map_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>

#include <CGAL/Surface_mesh_parameterization/Automatic_border.h>
#include <CGAL/Surface_mesh_parameterization/Circular_border.h>
#include <CGAL/Surface_mesh_parameterization/Conformal_border.h>
#include <CGAL/Surface_mesh_parameterization/Conformal_length_border.h>
#include <CGAL/Surface_mesh_parameterization/Conformal_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Default_sparse_cholesky_traits.h>
#include <CGAL/Surface_mesh_parameterization/Geodesic_border_distance.h>
#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_report.h>
#include <CGAL/Surface_mesh_parameterization/Poisson_center_locator.h>
#include <CGAL/Surface_mesh_parameterization/geodesic_method_tags.h>
#include <CGAL/Surface_mesh_parameterization/measure_quality.h>
#ifdef MBP_WITH_CHOLMOD
#include <CGAL/Surface_mesh_parameterization/Cholmod_supernodal_cholesky_traits.h>
#endif

#include <Eigen/Core>
#include <Eigen/Sparse>

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include "benchmark_support.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#ifndef MBP_BFF_PROGRAM
#define MBP_BFF_PROGRAM ""
#endif

namespace SMP = CGAL::Surface_mesh_parameterization;
typedef CGAL::Simple_cartesian<double>                          K;
typedef CGAL::Surface_mesh<K::Point_3>                          Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor            vertex_descriptor;
typedef boost::graph_traits<Mesh>::halfedge_descriptor          halfedge_descriptor;
typedef boost::graph_traits<Mesh>::face_descriptor              face_descriptor;
typedef Mesh::Property_map<vertex_descriptor, K::Point_2>       UV_map;
typedef Mesh::Property_map<vertex_descriptor, bool>             Parameterized_map;
typedef std::chrono::steady_clock                               Clock;

typedef SMP::Geodesic_border_distance<SMP::Fast_marching_geodesics>       Fast_marching_distance;
typedef SMP::Automatic_border<SMP::Poisson_center_locator, Fast_marching_distance> Automatic;
typedef SMP::Default_sparse_cholesky_traits                               Ldlt_traits;
typedef SMP::Conformal_parameterizer_3<Mesh, SMP::Conformal_border>       Ours_conformal;
typedef SMP::Conformal_parameterizer_3<Mesh, SMP::Conformal_length_border> Ours_conformal_lengths;
typedef SMP::Conformal_parameterizer_3<Mesh, Automatic>                   Ours_auto;
typedef SMP::Conformal_parameterizer_3<Mesh>                              Ours_auto_poisson;  // Automatic_border<>
typedef SMP::Measured_conformal_parameterizer_3<Mesh>                     Ours_mbppp;
typedef SMP::Measured_conformal_parameterizer_3<Mesh, SMP::Poisson_center_locator,
                                                Fast_marching_distance>    Ours_mbpgp;
typedef SMP::Conformal_parameterizer_3<Mesh, SMP::Circular_border>        Ours_circle;
#ifdef MBP_WITH_CHOLMOD
typedef SMP::Cholmod_supernodal_cholesky_traits                           Cholmod_traits;
typedef SMP::Conformal_parameterizer_3<Mesh, SMP::Conformal_border, Cholmod_traits> Ours_conformal_cholmod;
typedef SMP::Conformal_parameterizer_3<Mesh, Automatic, Cholmod_traits>   Ours_auto_cholmod;
#endif
typedef SMP::LSCM_parameterizer_3<Mesh>                                   Cgal_lscm;
typedef SMP::Discrete_conformal_map_parameterizer_3<Mesh>                 Cgal_dcp;

namespace {

// ---------------------------------------------------------------------------------------
// Methods

enum Method { CONFORMAL, CONFORMAL_LENGTHS, AUTO, AUTO_POISSON, MBPPP, MBPGP, CIRCLE, LSCM, BFF, FLOOR,
              CONFORMAL_CHOLMOD, AUTO_CHOLMOD, FLOOR_CHOLMOD, CGAL_DCP, NUMBER_OF_METHODS };

const char* method_name(int m)
{
  static const char* names[NUMBER_OF_METHODS] = {"conformal", "conformal L", "auto", "auto P", "MBPPP", "MBPGP", "circle",
                                                 "LSCM", "BFF", "floor", "conformal CHOLMOD", "auto CHOLMOD",
                                                 "floor CHOLMOD", "CGAL DCP"};
  return names[m];
}

bool is_ours(int m)
{
  return m <= CIRCLE || m == CONFORMAL_CHOLMOD || m == AUTO_CHOLMOD;
}

bool has_uv(int m)  // a map is measured
{
  return m <= BFF || m == CGAL_DCP;
}

// What our parameterizer's report says (the fields this table uses).
struct Ours_info
{
  int factorizations = 0, back_substitutions = 0;
  double factorization_seconds = 0., back_substitution_seconds = 0.;
  int kept = -1;  // Border_family: 0 circle, 1 measured, 2 conformal, 3 conformal lengths
  double blend = 0.;
  double own_blend = 0.;       // the report's conformal_blend (conformal members)
  double length_seconds = 0.;  // the report's conformal_length_seconds
  bool mean_value = false, repaired = false;
  std::size_t flips_before = 0;
  std::size_t tried = 0;
  // stage times
  double preparation = 0., center = 0., distance = 0., border_map = 0., conformal_border = 0., interior = 0.,
         repair = 0., output = 0., total = 0.;
};

struct Sample
{
  SMP::Error_code status = SMP::ERROR_WRONG_PARAMETER;
  double seconds = 0.;
  double seconds_with_assembly = 0.;  // floor only
  Ours_info info;
  std::string message;  // BFF failures
};

struct Maps
{
  UV_map uv;
  Parameterized_map vp;
};

void reset(Mesh& mesh, Maps& maps)
{
  for(vertex_descriptor v : vertices(mesh))
  {
    put(maps.vp, v, false);
    put(maps.uv, v, K::Point_2(0., 0.));
  }
}

double since(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

template <class Ours>
Sample run_ours(Mesh& mesh, halfedge_descriptor bhd, Maps& maps)
{
  reset(mesh, maps);
  const Ours ours;
  SMP::Parameterization_report r;
  Sample s;
  const Clock::time_point start = Clock::now();
  s.status = ours.parameterize(mesh, bhd, maps.uv, get(CGAL::vertex_index, mesh), maps.vp, &r);
  s.seconds = since(start);
  Ours_info& i = s.info;
  i.factorizations = r.statistics.factorizations;
  i.back_substitutions = r.statistics.back_substitutions;
  i.factorization_seconds = r.statistics.factorization_seconds;
  i.back_substitution_seconds = r.statistics.back_substitution_seconds;
  i.kept = (r.chosen_candidate >= 0) ? static_cast<int>(r.kept_border) : -1;
  i.blend = r.blend;
  i.own_blend = r.conformal_blend;
  i.length_seconds = r.conformal_length_seconds;
  i.mean_value = r.mean_value_interior;
  i.repaired = r.repaired;
  i.flips_before = r.flipped_faces_before_repair;
  i.tried = r.border_candidates.size();
  i.preparation = r.preparation_seconds;
  i.center = r.center_seconds;
  i.distance = r.distance_seconds;
  i.border_map = r.border_map_seconds;
  i.conformal_border = r.conformal_border_seconds;
  i.interior = r.interior_seconds;
  i.repair = r.repair_seconds;
  i.output = r.output_seconds;
  i.total = r.total_seconds;
  return s;
}

template <class Parameterizer>
Sample run_cgal(Mesh& mesh, halfedge_descriptor bhd, Maps& maps)
{
  reset(mesh, maps);
  Parameterizer p;
  Sample s;
  const Clock::time_point start = Clock::now();
  s.status = p.parameterize(mesh, bhd, maps.uv, get(CGAL::vertex_index, mesh), maps.vp);
  s.seconds = since(start);
  return s;
}

// One analyze + factorize of L_II by the solver traits, as the package factorizes it
// (SolverTraits::factor()); "with assembly" also counts this benchmark's assembly of L_II
// (benchmark_support.h: Eigen triplets, not the package's own assembly, which is internal).
template <class Traits>
Sample run_floor(const Mesh& mesh, halfedge_descriptor bhd)
{
  Sample s;
  const Clock::time_point start = Clock::now();
  Eigen::SparseMatrix<double> A;
  if(!mbp_benchmark::interior_cotangent_laplacian(mesh, bhd, A))
    return s;
  const typename Traits::Matrix M(A);
  Traits traits;
  double D = 1.;
  const Clock::time_point factor_start = Clock::now();
  const bool factorized = traits.factor(M, D);
  s.seconds = since(factor_start);
  s.seconds_with_assembly = since(start);
  s.status = factorized ? SMP::OK : SMP::ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
  s.info.factorizations = 1;
  return s;
}

// ---------------------------------------------------------------------------------------
// Boundary First Flattening's command line, in a child process

// Runs `bff in out` (stdout and stderr to `log`); the whole process is timed.
Sample run_bff(const std::string& bff, const std::string& in, const std::string& out, const std::string& log)
{
  Sample s;
  std::error_code ec;
  std::filesystem::remove(out, ec);
  std::fflush(stdout);
  std::fflush(stderr);
  const Clock::time_point start = Clock::now();
  const pid_t pid = ::fork();
  if(pid < 0)
  {
    s.message = "fork failed";
    return s;
  }
  if(pid == 0)
  {
    const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if(fd >= 0)
    {
      ::dup2(fd, 1);
      ::dup2(fd, 2);
      ::close(fd);
    }
    ::execl(bff.c_str(), bff.c_str(), in.c_str(), out.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  int wstatus = 0;
  while(::waitpid(pid, &wstatus, 0) < 0 && errno == EINTR) { }
  s.seconds = since(start);
  if(WIFEXITED(wstatus) && WEXITSTATUS(wstatus) == 0 && std::filesystem::exists(out))
    s.status = SMP::OK;
  else
  {
    s.status = SMP::ERROR_WRONG_PARAMETER;
    s.message = WIFEXITED(wstatus) ? "exit code " + std::to_string(WEXITSTATUS(wstatus))
                                   : "killed by signal " + std::to_string(WTERMSIG(wstatus));
  }
  return s;
}

// Writes the mesh as OBJ, vertex i of the file being the vertex of index i, full precision.
bool write_obj(const Mesh& mesh, const std::string& path)
{
  std::FILE* f = std::fopen(path.c_str(), "w");
  if(!f)
    return false;
  for(vertex_descriptor v : vertices(mesh))
  {
    const K::Point_3& p = mesh.point(v);
    std::fprintf(f, "v %.17g %.17g %.17g\n", p.x(), p.y(), p.z());
  }
  for(face_descriptor fd : faces(mesh))
  {
    std::fputc('f', f);
    for(vertex_descriptor v : vertices_around_face(halfedge(fd, mesh), mesh))
      std::fprintf(f, " %u", static_cast<unsigned>(v.idx()) + 1u);
    std::fputc('\n', f);
  }
  return std::fclose(f) == 0;
}

// The map BFF wrote: a mesh of its (v, vt) corners with the 3D points of `mesh` (vertex v of
// the output is vertex v of the input we wrote) and the output's UVs.
struct Bff_map
{
  Mesh mesh;
  UV_map uv;
  std::string problem;  // empty when the output could be read
};

// Reads one "a", "a/b" or "a/b/c" corner; 0-based indices (OBJ's negative indices resolved).
bool parse_corner(const std::string& token, long nv, long nvt, long& v, long& vt)
{
  const std::size_t slash = token.find('/');
  v = std::atol(token.substr(0, slash).c_str());
  vt = 0;
  if(slash != std::string::npos)
  {
    const std::size_t end = token.find('/', slash + 1);
    vt = std::atol(token.substr(slash + 1, end == std::string::npos ? std::string::npos : end - slash - 1).c_str());
  }
  v = (v < 0) ? nv + v : v - 1;
  vt = (vt < 0) ? nvt + vt : vt - 1;
  return v >= 0 && v < nv && vt >= 0 && vt < nvt;
}

void read_bff_output(const Mesh& input, const std::string& path, Bff_map& out)
{
  out.uv = out.mesh.add_property_map<vertex_descriptor, K::Point_2>("v:bff_uv").first;
  std::ifstream in(path);
  if(!in)
  {
    out.problem = "no output file";
    return;
  }
  std::vector<K::Point_2> vts;
  std::vector<std::array<std::pair<long, long>, 3> > tris;
  long nv = 0;
  std::string line;
  while(std::getline(in, line))
  {
    std::istringstream ls(line);
    std::string key;
    ls >> key;
    if(key == "v")
      ++nv;
    else if(key == "vt")
    {
      double u = 0., w = 0.;
      ls >> u >> w;
      vts.emplace_back(u, w);
    }
    else if(key == "f")
    {
      std::vector<std::pair<long, long> > corners;
      std::string token;
      while(ls >> token)
      {
        long v = 0, vt = 0;
        if(!parse_corner(token, nv, static_cast<long>(vts.size()), v, vt))
        {
          out.problem = "a face corner without a valid v/vt pair";
          return;
        }
        corners.emplace_back(v, vt);
      }
      if(corners.size() != 3)
      {
        out.problem = "a face that is not a triangle";
        return;
      }
      tris.push_back({corners[0], corners[1], corners[2]});
    }
  }
  if(nv != static_cast<long>(num_vertices(input)))
  {
    out.problem = std::to_string(nv) + " vertices in the output, " + std::to_string(num_vertices(input)) + " in";
    return;
  }
  std::map<std::pair<long, long>, vertex_descriptor> corner_vertex;
  for(const auto& t : tris)
  {
    std::array<vertex_descriptor, 3> vs;
    for(std::size_t k = 0; k < 3; ++k)
    {
      auto it = corner_vertex.find(t[k]);
      if(it == corner_vertex.end())
      {
        const vertex_descriptor nvd = out.mesh.add_vertex(input.point(vertex_descriptor(static_cast<Mesh::size_type>(t[k].first))));
        put(out.uv, nvd, vts[static_cast<std::size_t>(t[k].second)]);
        it = corner_vertex.emplace(t[k], nvd).first;
      }
      vs[k] = it->second;
    }
    if(out.mesh.add_face(vs[0], vs[1], vs[2]) == Mesh::null_face())
    {
      out.problem = "the output's faces do not form a manifold mesh";
      return;
    }
  }
  if(num_vertices(out.mesh) != num_vertices(input) || num_faces(out.mesh) != num_faces(input))
    out.problem = "the output has " + std::to_string(num_vertices(out.mesh)) + " corners and " +
                  std::to_string(num_faces(out.mesh)) + " faces (input: " + std::to_string(num_vertices(input)) +
                  " and " + std::to_string(num_faces(input)) + ")";
}

// ---------------------------------------------------------------------------------------
// Meshes

// 1-to-4 midpoint subdivision (the surface does not move).
Mesh refine(const Mesh& mesh)
{
  Mesh out;
  for(vertex_descriptor v : vertices(mesh))
    out.add_vertex(mesh.point(v));
  std::unordered_map<std::size_t, vertex_descriptor> midpoint;
  auto mid = [&](halfedge_descriptor h) {
    const std::size_t e = edge(h, mesh).idx();
    auto it = midpoint.find(e);
    if(it != midpoint.end())
      return it->second;
    const vertex_descriptor v = out.add_vertex(CGAL::midpoint(mesh.point(source(h, mesh)), mesh.point(target(h, mesh))));
    midpoint.emplace(e, v);
    return v;
  };
  for(face_descriptor f : faces(mesh))
  {
    const halfedge_descriptor h0 = halfedge(f, mesh), h1 = next(h0, mesh), h2 = next(h1, mesh);
    const vertex_descriptor a = source(h0, mesh), b = source(h1, mesh), c = source(h2, mesh);
    const vertex_descriptor ab = mid(h0), bc = mid(h1), ca = mid(h2);
    out.add_face(a, ab, ca);
    out.add_face(ab, b, bc);
    out.add_face(ca, bc, c);
    out.add_face(ab, bc, ca);
  }
  return out;
}

double load_average()
{
  std::ifstream in("/proc/loadavg");
  double l = std::numeric_limits<double>::quiet_NaN();
  in >> l;
  return l;
}

double median(std::vector<double> v)
{
  v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return !std::isfinite(x); }), v.end());
  if(v.empty())
    return std::numeric_limits<double>::quiet_NaN();
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return (n % 2) ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// ---------------------------------------------------------------------------------------
// One mesh

struct Result  // one method on one mesh
{
  bool ran = false;
  SMP::Error_code status = SMP::ERROR_WRONG_PARAMETER;
  std::string message;
  std::vector<Sample> samples;
  double seconds = std::numeric_limits<double>::quiet_NaN();  // median
  double seconds_with_assembly = std::numeric_limits<double>::quiet_NaN();
  Ours_info info;     // last run; stage times: medians
  bool has_quality = false;
  SMP::Parameterization_quality quality;
  bool one_to_one = false;
  std::vector<K::Point_2> uvs;  // the circle and CGAL's DCP only (cross-check)
};

struct Row
{
  std::string name;
  std::size_t vertices = 0, faces = 0;
  bool scaled = false;  // a refined mesh (not in the medians)
  std::array<Result, NUMBER_OF_METHODS> r;
  double load = 0.;
};

struct Options
{
  int runs = 3;
  std::vector<std::string> only;
  std::vector<std::string> methods;  // --method: empty for all
  std::string bff;
  std::vector<std::string> cross_check = {"snail.obj", "maxFace.obj", "lion-head.off", "mask.off"};
  int scale = 1;
};

bool method_available(int m)
{
#ifdef MBP_WITH_CHOLMOD
  (void)m;
  return true;
#else
  return m != CONFORMAL_CHOLMOD && m != AUTO_CHOLMOD && m != FLOOR_CHOLMOD;
#endif
}

Sample run_method(int m, Mesh& mesh, halfedge_descriptor bhd, Maps& maps, const Options& options,
                  const std::string& obj_in, const std::string& obj_out, const std::string& log)
{
  switch(m)
  {
  case CONFORMAL:    return run_ours<Ours_conformal>(mesh, bhd, maps);
  case CONFORMAL_LENGTHS: return run_ours<Ours_conformal_lengths>(mesh, bhd, maps);
  case AUTO:         return run_ours<Ours_auto>(mesh, bhd, maps);
  case AUTO_POISSON: return run_ours<Ours_auto_poisson>(mesh, bhd, maps);
  case MBPPP:        return run_ours<Ours_mbppp>(mesh, bhd, maps);
  case MBPGP:        return run_ours<Ours_mbpgp>(mesh, bhd, maps);
  case CIRCLE:       return run_ours<Ours_circle>(mesh, bhd, maps);
  case LSCM:         return run_cgal<Cgal_lscm>(mesh, bhd, maps);
  case BFF:          return run_bff(options.bff, obj_in, obj_out, log);
  case FLOOR:        return run_floor<Ldlt_traits>(mesh, bhd);
#ifdef MBP_WITH_CHOLMOD
  case CONFORMAL_CHOLMOD: return run_ours<Ours_conformal_cholmod>(mesh, bhd, maps);
  case AUTO_CHOLMOD:      return run_ours<Ours_auto_cholmod>(mesh, bhd, maps);
  case FLOOR_CHOLMOD:     return run_floor<Cholmod_traits>(mesh, bhd);
#endif
  case CGAL_DCP:     return run_cgal<Cgal_dcp>(mesh, bhd, maps);
  default: break;
  }
  return Sample();
}

// Medians of the times and of our stage times over the samples.
void summarize(Result& res)
{
  std::vector<double> t, ta;
  std::array<std::vector<double>, 9> stages;
  for(const Sample& s : res.samples)
  {
    t.push_back(s.seconds);
    ta.push_back(s.seconds_with_assembly);
    const double v[9] = {s.info.preparation, s.info.center, s.info.distance, s.info.border_map,
                         s.info.conformal_border, s.info.interior, s.info.repair, s.info.output, s.info.total};
    for(std::size_t k = 0; k < 9; ++k)
      stages[k].push_back(v[k]);
  }
  res.seconds = median(t);
  res.seconds_with_assembly = median(ta);
  if(res.samples.empty())
    return;
  res.info = res.samples.back().info;
  double* fields[9] = {&res.info.preparation, &res.info.center, &res.info.distance, &res.info.border_map,
                       &res.info.conformal_border, &res.info.interior, &res.info.repair, &res.info.output,
                       &res.info.total};
  for(std::size_t k = 0; k < 9; ++k)
    *fields[k] = median(stages[k]);
  std::vector<double> fs;
  for(const Sample& s : res.samples)
    fs.push_back(s.info.factorization_seconds);
  res.info.factorization_seconds = median(fs);
}

void measure(Mesh& mesh, const Maps& maps, Result& res, bool keep_uvs)
{
  res.quality = SMP::measure_quality(mesh, faces(mesh), maps.uv);
  res.one_to_one = SMP::is_one_to_one_uv_map(mesh, faces(mesh), maps.uv);
  res.has_quality = true;
  if(keep_uvs)
    for(vertex_descriptor v : vertices(mesh))
      res.uvs.push_back(get(maps.uv, v));
}

bool run_mesh(Mesh& mesh, Row& row, const Options& options, const std::string& tmp, bool cross_check)
{
  const halfedge_descriptor bhd = CGAL::Polygon_mesh_processing::longest_border(mesh).first;
  Maps maps;
  maps.uv = mesh.add_property_map<vertex_descriptor, K::Point_2>("v:border_table_uv").first;
  maps.vp = mesh.add_property_map<vertex_descriptor, bool>("v:border_table_vp", false).first;
  row.vertices = num_vertices(mesh);
  row.faces = num_faces(mesh);

  const std::string obj_in = tmp + "/in.obj", obj_out = tmp + "/out.obj", log = tmp + "/bff.log";
  const bool with_bff = !options.bff.empty() && write_obj(mesh, obj_in);
  std::vector<int> methods;
  for(int m = 0; m < NUMBER_OF_METHODS; ++m)
    if(method_available(m) && (m != BFF || with_bff) && (m != CGAL_DCP || cross_check) &&
       (options.methods.empty() ||
        std::find(options.methods.begin(), options.methods.end(), method_name(m)) != options.methods.end()))
      methods.push_back(m);

  for(int run = 0; run < options.runs; ++run)
    for(int m : methods)
    {
      Result& res = row.r[static_cast<std::size_t>(m)];
      std::fprintf(stderr, "  %s run %d: %s\n", row.name.c_str(), run + 1, method_name(m));
      const Sample s = run_method(m, mesh, bhd, maps, options, obj_in, obj_out, log);
      res.ran = true;
      res.samples.push_back(s);
      res.status = s.status;
      res.message = s.message;
      if(run + 1 != options.runs || s.status != SMP::OK || !has_uv(m))
        continue;
      if(m == BFF)
      {
        Bff_map map;
        read_bff_output(mesh, obj_out, map);
        if(!map.problem.empty())
        {
          res.status = SMP::ERROR_WRONG_PARAMETER;
          res.message = map.problem;
          continue;
        }
        res.quality = SMP::measure_quality(map.mesh, faces(map.mesh), map.uv);
        res.one_to_one = SMP::is_one_to_one_uv_map(map.mesh, faces(map.mesh), map.uv);
        res.has_quality = true;
      }
      else
        measure(mesh, maps, res, m == CIRCLE || m == CGAL_DCP);
    }
  for(Result& res : row.r)
    if(res.ran)
      summarize(res);
  row.load = load_average();
  mesh.remove_property_map(maps.uv);
  mesh.remove_property_map(maps.vp);
  return true;
}

// ---------------------------------------------------------------------------------------
// Printing

std::string fixed(double x, int digits = 4)
{
  if(!std::isfinite(x))
    return "-";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, x);
  return buf;
}

std::string seconds(double x)
{
  if(!std::isfinite(x))
    return "-";
  char buf[64];
  std::snprintf(buf, sizeof buf, x < 0.1 ? "%.4f" : "%.3f", x);
  return buf;
}

// Distortion below this counts as this in ratios (exact maps of flat meshes).
const double tiny_distortion = 1e-6;

double ratio(double a, double b)
{
  if(!std::isfinite(a) || !std::isfinite(b))
    return std::numeric_limits<double>::quiet_NaN();
  return (std::max)(a, tiny_distortion) / (std::max)(b, tiny_distortion);
}

double time_ratio(double a, double b)
{
  return (std::isfinite(a) && std::isfinite(b) && b > 0.) ? a / b : std::numeric_limits<double>::quiet_NaN();
}

bool ok(const Result& r) { return r.ran && r.status == SMP::OK && r.has_quality; }

double angle(const Result& r) { return ok(r) ? r.quality.angle_distortion : std::numeric_limits<double>::quiet_NaN(); }

// A distortion figure: 4 decimals, or 3 significant digits below 0.001.
std::string figure(double x)
{
  if(!std::isfinite(x) || x == 0. || x >= 1e-3)
    return fixed(x);
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.2e", x);
  return buf;
}

// "0.0123", with "(nF)" for n flipped faces, "(overlap)" when one-to-one fails without flips,
// "*" for a repaired result of ours.
std::string cell(const Result& r, double value)
{
  if(!r.ran)
    return "-";
  if(!ok(r))
    return "failed";
  std::string s = figure(value);
  if(r.quality.flipped_faces > 0)
    s += " (" + std::to_string(r.quality.flipped_faces) + "F)";
  else if(!r.one_to_one)
    s += " (overlap)";
  if(r.info.repaired)
    s += "*";
  return s;
}

const char* family_name(int f)
{
  switch(f)
  {
  case 0: return "circle";
  case 1: return "measured";
  case 2: return "conformal";
  case 3: return "conformal-lengths";
  default: return "none";
  }
}

std::string kept(const Result& r)
{
  if(!r.ran || r.status != SMP::OK)
    return "-";
  std::string s = family_name(r.info.kept);
  if(r.info.kept != 0)
    s += " t=" + fixed(r.info.blend, 3);
  if(r.info.mean_value)
    s += ", mean value interior";
  return s;
}

const int distortion_columns[] = {CIRCLE, CONFORMAL, CONFORMAL_LENGTHS, AUTO, AUTO_POISSON, MBPPP, MBPGP, LSCM, BFF};

void print_distortion_table(const std::vector<Row>& rows, bool l2)
{
  std::printf("| mesh | V |");
  for(int m : distortion_columns)
    std::printf(" %s |", method_name(m));
  if(!l2)
    std::printf(" conformal / circle | auto / circle | BFF / circle | LSCM / circle | auto / BFF | auto / LSCM |");
  std::printf("\n|---|---|");
  for(std::size_t k = 0; k < std::size(distortion_columns); ++k)
    std::printf("---|");
  if(!l2)
    std::printf("---|---|---|---|---|---|");
  std::printf("\n");
  for(const Row& row : rows)
  {
    std::printf("| %s | %zu |", row.name.c_str(), row.vertices);
    for(int m : distortion_columns)
    {
      const Result& r = row.r[static_cast<std::size_t>(m)];
      std::printf(" %s |", cell(r, l2 ? r.quality.l2_stretch : r.quality.angle_distortion).c_str());
    }
    if(!l2)
    {
      const double circle = angle(row.r[CIRCLE]);
      std::printf(" %s | %s | %s | %s | %s | %s |", fixed(ratio(angle(row.r[CONFORMAL]), circle), 3).c_str(),
                  fixed(ratio(angle(row.r[AUTO]), circle), 3).c_str(), fixed(ratio(angle(row.r[BFF]), circle), 3).c_str(),
                  fixed(ratio(angle(row.r[LSCM]), circle), 3).c_str(),
                  fixed(ratio(angle(row.r[AUTO]), angle(row.r[BFF])), 3).c_str(),
                  fixed(ratio(angle(row.r[AUTO]), angle(row.r[LSCM])), 3).c_str());
    }
    std::printf("\n");
  }
  std::printf("\n");
}

std::string flips_cell(const Result& r, bool fixed_border)
{
  if(!r.ran)
    return "-";
  if(!ok(r))
    return "failed";
  std::string s = std::to_string(r.quality.flipped_faces);
  s += r.one_to_one ? " / yes" : " / no";
  if(fixed_border && r.info.flips_before > 0)
    s += " (" + std::to_string(r.info.flips_before) + " before repair)";
  return s;
}

void print_flips_table(const std::vector<Row>& rows)
{
  std::printf("| mesh | V | F |");
  for(int m : distortion_columns)
    std::printf(" %s |", method_name(m));
  std::printf("\n|---|---|---|");
  for(std::size_t k = 0; k < std::size(distortion_columns); ++k)
    std::printf("---|");
  std::printf("\n");
  for(const Row& row : rows)
  {
    std::printf("| %s | %zu | %zu |", row.name.c_str(), row.vertices, row.faces);
    for(int m : distortion_columns)
      std::printf(" %s |", flips_cell(row.r[static_cast<std::size_t>(m)], is_ours(m) && m != AUTO && m != AUTO_POISSON).c_str());
    std::printf("\n");
  }
  std::printf("\n");
}

// One member's cells: kept blend, angle distortion, L2 stretch, area distortion (mean, max), flips.
std::string member_cells(const Result& r)
{
  if(!ok(r))
    return std::string(r.ran ? "failed" : "-") + " | - | - | - | - | -";
  return fixed(r.info.blend, 3) + " | " + cell(r, r.quality.angle_distortion) + " | " + fixed(r.quality.l2_stretch, 3) +
         " | " + fixed(r.quality.area_distortion_mean, 3) + " | " + fixed(r.quality.area_distortion_max, 2) + " | " +
         flips_cell(r, true);
}

// Issue 23: the conformal member (its smallest valid blend, lengths kept) against the
// conformal-length member (its own blend: the smallest at which its polygon is simple), with the
// time of that member's data (the extra factorization, one solve, its bisection) against that of
// the factorization of L_II, and the factorization time of the member's whole call (both).
void print_conformal_lengths_table(const std::vector<Row>& rows)
{
  std::printf("| mesh | V | conformal: t | angle | L2 | area mean | area max | flips / 1-1 | conformal L: own t | t |"
              " angle | L2 | area mean | area max | flips / 1-1 | angle L / conformal | L member s | factor. s: L_II, both |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  std::vector<double> angle_ratio, time_ratio_of, angle_c, angle_l, l2_c, l2_l;
  for(const Row& row : rows)
  {
    const Result &c = row.r[CONFORMAL], &l = row.r[CONFORMAL_LENGTHS];
    if(!l.ran)
      continue;
    const double q = ratio(angle(l), angle(c)), t = time_ratio(l.info.length_seconds, c.info.factorization_seconds);
    std::printf("| %s | %zu | %s | %s | %s | %s | %s | %s |\n", row.name.c_str(), row.vertices, member_cells(c).c_str(),
                fixed(l.info.own_blend, 3).c_str(), member_cells(l).c_str(), fixed(q, 3).c_str(),
                seconds(l.info.length_seconds).c_str(),
                (seconds(c.info.factorization_seconds) + ", " + seconds(l.info.factorization_seconds)).c_str());
    angle_ratio.push_back(q);
    time_ratio_of.push_back(t);
    angle_c.push_back(angle(c));
    angle_l.push_back(angle(l));
    l2_c.push_back(ok(c) ? c.quality.l2_stretch : std::numeric_limits<double>::quiet_NaN());
    l2_l.push_back(ok(l) ? l.quality.l2_stretch : std::numeric_limits<double>::quiet_NaN());
  }
  std::printf("\nMedians over the disks: angle distortion conformal %s, conformal L %s (ratio %s); L2 stretch"
              " conformal %s, conformal L %s; time of the conformal-length member / factorization of L_II %s\n\n",
              figure(median(angle_c)).c_str(), figure(median(angle_l)).c_str(), fixed(median(angle_ratio), 3).c_str(),
              fixed(median(l2_c), 3).c_str(), fixed(median(l2_l), 3).c_str(), fixed(median(time_ratio_of), 2).c_str());
}

void print_choice_table(const std::vector<Row>& rows)
{
  std::printf("| mesh | V | auto: kept | layouts tried | fewest flips of a member's own layout | auto P: kept | layouts tried |"
              " conformal border: blend toward the circle | conformal: repaired |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  for(const Row& row : rows)
  {
    const Result& a = row.r[AUTO];
    const Result& p = row.r[AUTO_POISSON];
    const Result& c = row.r[CONFORMAL];
    std::printf("| %s | %zu | %s | %zu | %zu | %s | %zu | %s | %s |\n", row.name.c_str(), row.vertices, kept(a).c_str(),
                a.info.tried, a.info.flips_before, kept(p).c_str(), p.info.tried,
                c.status == SMP::OK ? fixed(c.info.blend, 3).c_str() : "-",
                c.status != SMP::OK ? "-" : c.info.repaired ? (c.info.mean_value ? "yes (mean value)" : "yes") : "no");
  }
  std::printf("\n");
}

const int time_columns[] = {FLOOR, CONFORMAL, AUTO, AUTO_POISSON, MBPPP, MBPGP, CIRCLE, LSCM, BFF};

void print_time_table(const std::vector<Row>& rows)
{
  std::printf("| mesh | V | floor | floor + assembly |");
  for(int m : time_columns)
    if(m != FLOOR)
      std::printf(" %s |", m == BFF ? "BFF (process)" : method_name(m));
  std::printf(" conformal / floor | auto / conformal | auto P / conformal | auto / circle |"
              " factorizations: conformal, auto, auto P, MBPPP, MBPGP, circle | load |\n|---|---|---|---|");
  for(std::size_t k = 1; k < std::size(time_columns); ++k)
    std::printf("---|");
  std::printf("---|---|---|---|---|---|\n");
  for(const Row& row : rows)
  {
    std::printf("| %s | %zu | %s | %s |", row.name.c_str(), row.vertices, seconds(row.r[FLOOR].seconds).c_str(),
                seconds(row.r[FLOOR].seconds_with_assembly).c_str());
    for(int m : time_columns)
      if(m != FLOOR)
      {
        const Result& r = row.r[static_cast<std::size_t>(m)];
        std::printf(" %s |", r.ran && r.status == SMP::OK ? seconds(r.seconds).c_str() : r.ran ? "failed" : "-");
      }
    std::printf(" %s | %s | %s | %s | %d, %d, %d, %d, %d, %d | %.2f |\n",
                fixed(time_ratio(row.r[CONFORMAL].seconds, row.r[FLOOR].seconds), 2).c_str(),
                fixed(time_ratio(row.r[AUTO].seconds, row.r[CONFORMAL].seconds), 2).c_str(),
                fixed(time_ratio(row.r[AUTO_POISSON].seconds, row.r[CONFORMAL].seconds), 2).c_str(),
                fixed(time_ratio(row.r[AUTO].seconds, row.r[CIRCLE].seconds), 2).c_str(),
                row.r[CONFORMAL].info.factorizations, row.r[AUTO].info.factorizations,
                row.r[AUTO_POISSON].info.factorizations, row.r[MBPPP].info.factorizations,
                row.r[MBPGP].info.factorizations, row.r[CIRCLE].info.factorizations, row.load);
  }
  std::printf("\n");
}

void print_cholmod_table(const std::vector<Row>& rows)
{
  std::printf("| mesh | V | floor CHOLMOD | conformal CHOLMOD | conformal / floor | auto CHOLMOD | auto / conformal | load |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  for(const Row& row : rows)
    std::printf("| %s | %zu | %s | %s | %s | %s | %s | %.2f |\n", row.name.c_str(), row.vertices,
                seconds(row.r[FLOOR_CHOLMOD].seconds).c_str(), seconds(row.r[CONFORMAL_CHOLMOD].seconds).c_str(),
                fixed(time_ratio(row.r[CONFORMAL_CHOLMOD].seconds, row.r[FLOOR_CHOLMOD].seconds), 2).c_str(),
                seconds(row.r[AUTO_CHOLMOD].seconds).c_str(),
                fixed(time_ratio(row.r[AUTO_CHOLMOD].seconds, row.r[CONFORMAL_CHOLMOD].seconds), 2).c_str(), row.load);
  std::printf("\n");
}

void print_stage_table(const std::vector<Row>& rows, std::size_t min_vertices)
{
  std::printf("| mesh | V | method | preparation | center (with L_II fact.) | distance | border map | conformal border |"
              " interior / search | repair | output | total (report) | call (timed) | factorizations (s) |"
              " back-substitutions (n, s) |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for(const Row& row : rows)
  {
    if(row.vertices < min_vertices)
      continue;
    for(int m : {CONFORMAL, AUTO, AUTO_POISSON, CIRCLE})
    {
      const Result& r = row.r[static_cast<std::size_t>(m)];
      if(!r.ran || r.status != SMP::OK)
        continue;
      const Ours_info& i = r.info;
      std::printf("| %s | %zu | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %d: %s | %d, %s |\n",
                  row.name.c_str(), row.vertices, method_name(m), seconds(i.preparation).c_str(),
                  seconds(i.center).c_str(), seconds(i.distance).c_str(), seconds(i.border_map).c_str(),
                  seconds(i.conformal_border).c_str(), seconds(i.interior).c_str(), seconds(i.repair).c_str(),
                  seconds(i.output).c_str(), seconds(i.total).c_str(), seconds(r.seconds).c_str(), i.factorizations,
                  seconds(i.factorization_seconds).c_str(), i.back_substitutions,
                  seconds(i.back_substitution_seconds).c_str());
    }
  }
  std::printf("\n");
}

void print_cross_check(const std::vector<Row>& rows)
{
  std::printf("| mesh | V | circle (ours): angle dist. | CGAL DCP: angle dist. | relative difference |"
              " max UV distance | circle (ours) s | CGAL DCP s | load |\n|---|---|---|---|---|---|---|---|---|\n");
  for(const Row& row : rows)
  {
    const Result& c = row.r[CIRCLE];
    const Result& d = row.r[CGAL_DCP];
    if(!d.ran)
      continue;
    double max_distance = std::numeric_limits<double>::quiet_NaN();
    if(ok(c) && ok(d) && c.uvs.size() == d.uvs.size())
    {
      max_distance = 0.;
      for(std::size_t k = 0; k < c.uvs.size(); ++k)
        max_distance = (std::max)(max_distance, std::sqrt(CGAL::squared_distance(c.uvs[k], d.uvs[k])));
    }
    char diff[64] = "-", dist[64] = "-";
    if(ok(c) && ok(d))
      std::snprintf(diff, sizeof diff, "%.1e", std::abs(angle(c) - angle(d)) / (std::max)(angle(c), tiny_distortion));
    if(std::isfinite(max_distance))
      std::snprintf(dist, sizeof dist, "%.1e", max_distance);
    std::printf("| %s | %zu | %s | %s | %s | %s | %s | %s | %.2f |\n", row.name.c_str(), row.vertices,
                cell(c, angle(c)).c_str(), cell(d, angle(d)).c_str(), diff, dist, seconds(c.seconds).c_str(),
                seconds(d.seconds).c_str(), row.load);
  }
  std::printf("\n");
}

void print_failures(const std::vector<Row>& rows)
{
  bool any = false;
  for(const Row& row : rows)
    for(int m = 0; m < NUMBER_OF_METHODS; ++m)
    {
      const Result& r = row.r[static_cast<std::size_t>(m)];
      if(r.ran && r.status != SMP::OK)
      {
        if(!any)
          std::printf("Failures:\n\n");
        any = true;
        std::printf("- %s, %s: %s\n", row.name.c_str(), method_name(m),
                    r.message.empty() ? SMP::get_measured_error_message(r.status) : r.message.c_str());
      }
    }
  if(any)
    std::printf("\n");
}

// ---------------------------------------------------------------------------------------
// Summary and targets

struct Stat
{
  double median = std::numeric_limits<double>::quiet_NaN(), worst = std::numeric_limits<double>::quiet_NaN();
  std::string worst_mesh;
  std::size_t count = 0;
};

template <class F>
Stat stat_over(const std::vector<Row>& rows, F value)
{
  Stat s;
  std::vector<double> v;
  for(const Row& row : rows)
  {
    const double x = value(row);
    if(!std::isfinite(x))
      continue;
    v.push_back(x);
    if(!(x <= s.worst))
    {
      s.worst = x;
      s.worst_mesh = row.name;
    }
  }
  s.count = v.size();
  s.median = median(v);
  return s;
}

void print_stat(const char* what, const Stat& s, int digits = 3)
{
  std::printf("- %s: median **%s**, worst %s (%s), over %zu meshes\n", what, fixed(s.median, digits).c_str(),
              fixed(s.worst, digits).c_str(), s.worst_mesh.c_str(), s.count);
}

void print_summary(const std::vector<Row>& all)
{
  std::vector<Row> rows;  // the real meshes
  for(const Row& r : all)
    if(!r.scaled)
      rows.push_back(r);

  std::printf("Angle distortion against the circle (per mesh X / circle, median over the %zu real disks;"
              " distortions below %.0e count as %.0e):\n\n", rows.size(), tiny_distortion, tiny_distortion);
  for(int m : {CONFORMAL, AUTO, AUTO_POISSON, MBPPP, MBPGP, BFF, LSCM})
  {
    const std::string what = std::string(method_name(m)) + " / circle";
    print_stat(what.c_str(), stat_over(rows, [m](const Row& r) {
      return ratio(angle(r.r[static_cast<std::size_t>(m)]), angle(r.r[CIRCLE]));
    }));
  }
  std::printf("\nMedian angle distortion over the disks (not a ratio):");
  for(int m : {CIRCLE, CONFORMAL, AUTO, AUTO_POISSON, MBPPP, MBPGP, BFF, LSCM})
    std::printf(" %s %s;", method_name(m),
                fixed(stat_over(rows, [m](const Row& r) { return angle(r.r[static_cast<std::size_t>(m)]); }).median).c_str());
  std::printf("\n\n");

  for(int m : {AUTO, AUTO_POISSON})
  {
    int wins[4] = {0, 0, 0, 0}, blended = 0, mean_value = 0;
    for(const Row& row : rows)
    {
      const Result& r = row.r[static_cast<std::size_t>(m)];
      if(r.status != SMP::OK || r.info.kept < 0)
        continue;
      ++wins[r.info.kept];
      if(r.info.kept != 0 && r.info.blend > 0.)
        ++blended;
      if(r.info.mean_value)
        ++mean_value;
    }
    std::printf("Members kept by %s: circle %d, measured %d, conformal %d, conformal lengths %d (of which %d at a blend"
                " t > 0, %d with the mean value interior)  \n",
                method_name(m), wins[0], wins[1], wins[2], wins[3], blended, mean_value);
  }
  std::printf("\n");

  auto time_stat = [&](int a, int b, std::size_t min_vertices) {
    return stat_over(rows, [=](const Row& r) {
      return r.vertices >= min_vertices
               ? time_ratio(r.r[static_cast<std::size_t>(a)].seconds, r.r[static_cast<std::size_t>(b)].seconds)
               : std::numeric_limits<double>::quiet_NaN();
    });
  };
  print_stat("time conformal / floor", time_stat(CONFORMAL, FLOOR, 0), 2);
  print_stat("time conformal / floor, meshes of >= 20k vertices", time_stat(CONFORMAL, FLOOR, 20000), 2);
  print_stat("time auto / conformal", time_stat(AUTO, CONFORMAL, 0), 2);
  print_stat("time auto / conformal, meshes of >= 5k vertices", time_stat(AUTO, CONFORMAL, 5000), 2);
  print_stat("time auto P / conformal", time_stat(AUTO_POISSON, CONFORMAL, 0), 2);
  print_stat("time auto / circle", time_stat(AUTO, CIRCLE, 0), 2);
  print_stat("time BFF (whole process) / conformal", time_stat(BFF, CONFORMAL, 0), 2);
  print_stat("time LSCM / conformal", time_stat(LSCM, CONFORMAL, 0), 2);
#ifdef MBP_WITH_CHOLMOD
  print_stat("time conformal CHOLMOD / floor CHOLMOD", time_stat(CONFORMAL_CHOLMOD, FLOOR_CHOLMOD, 0), 2);
  print_stat("time auto CHOLMOD / conformal CHOLMOD", time_stat(AUTO_CHOLMOD, CONFORMAL_CHOLMOD, 0), 2);
#endif
  std::printf("\n");

  // Targets of issue 11.
  std::printf("Targets (issue 11):\n\n| target | verdict | measured |\n|---|---|---|\n");
  {
    const Stat b = stat_over(rows, [](const Row& r) { return ratio(angle(r.r[AUTO]), angle(r.r[BFF])); });
    const Stat l = stat_over(rows, [](const Row& r) { return ratio(angle(r.r[AUTO]), angle(r.r[LSCM])); });
    int within_b = 0, within_l = 0;
    for(const Row& r : rows)
    {
      within_b += ratio(angle(r.r[AUTO]), angle(r.r[BFF])) <= 1.05;
      within_l += ratio(angle(r.r[AUTO]), angle(r.r[LSCM])) <= 1.05;
    }
    const Stat ac = stat_over(rows, [](const Row& r) { return ratio(angle(r.r[AUTO]), angle(r.r[CIRCLE])); });
    const Stat bc = stat_over(rows, [](const Row& r) { return ratio(angle(r.r[BFF]), angle(r.r[CIRCLE])); });
    const Stat lc = stat_over(rows, [](const Row& r) { return ratio(angle(r.r[LSCM]), angle(r.r[CIRCLE])); });
    const Stat am = stat_over(rows, [](const Row& r) { return angle(r.r[AUTO]); });
    const Stat bm = stat_over(rows, [](const Row& r) { return angle(r.r[BFF]); });
    const Stat lm = stat_over(rows, [](const Row& r) { return angle(r.r[LSCM]); });
    std::printf("| auto's angle distortion within 5%% of BFF's on the median disk | %s | median of auto / BFF over the"
                " disks %s (at most 1.05 on %d of %zu); medians against the circle: auto %s, BFF %s;"
                " median distortions: auto %s, BFF %s |\n",
                b.median <= 1.05 ? "**met**" : "**not met**", fixed(b.median, 3).c_str(), within_b, b.count,
                fixed(ac.median, 4).c_str(), fixed(bc.median, 4).c_str(), figure(am.median).c_str(),
                figure(bm.median).c_str());
    std::printf("| auto's angle distortion within 5%% of LSCM's on the median disk | %s | median of auto / LSCM %s"
                " (at most 1.05 on %d of %zu); medians against the circle: auto %s, LSCM %s;"
                " median distortions: auto %s, LSCM %s |\n",
                l.median <= 1.05 ? "**met**" : "**not met**", fixed(l.median, 3).c_str(), within_l, l.count,
                fixed(ac.median, 4).c_str(), fixed(lc.median, 4).c_str(), figure(am.median).c_str(),
                figure(lm.median).c_str());
  }
  {
    std::string folded;
    int n = 0;
    for(const Row& r : all)
      if(!ok(r.r[AUTO]) || r.r[AUTO].quality.flipped_faces > 0 || !r.r[AUTO].one_to_one)
      {
        folded += (n++ ? ", " : "") + r.name;
      }
    std::string peers;
    for(int m : {CONFORMAL, BFF, LSCM})
    {
      int flipped = 0, not_one_to_one = 0;
      for(const Row& r : rows)
      {
        const Result& x = r.r[static_cast<std::size_t>(m)];
        flipped += ok(x) && x.quality.flipped_faces > 0;
        not_one_to_one += !ok(x) || !x.one_to_one;
      }
      peers += std::string(peers.empty() ? "" : "; ") + method_name(m) + ": flips on " + std::to_string(flipped) +
               ", not one-to-one on " + std::to_string(not_one_to_one) + " of " + std::to_string(rows.size());
    }
    std::printf("| 0 flipped faces (auto) on every disk | %s | auto: %s; %s |\n", n == 0 ? "**met**" : "**not met**",
                n == 0 ? "0 flips and one-to-one on every mesh" : ("folds or fails on " + folded).c_str(), peers.c_str());
  }
  {
    const Stat t = time_stat(AUTO, CONFORMAL, 0);
    const Stat t5 = time_stat(AUTO, CONFORMAL, 5000);
    int over = 0;
    for(const Row& r : rows)
      over += time_ratio(r.r[AUTO].seconds, r.r[CONFORMAL].seconds) > 1.3;
    std::printf("| time auto <= 1.3x conformal | %s | median %s, worst %s (%s); above 1.3 on %d of %zu meshes;"
                " >= 5k vertices: median %s, worst %s (%s) |\n",
                t.worst <= 1.3 ? "**met**" : t.median <= 1.3 ? "**met on the median, not on every mesh**" : "**not met**",
                fixed(t.median, 2).c_str(), fixed(t.worst, 2).c_str(), t.worst_mesh.c_str(), over, t.count,
                fixed(t5.median, 2).c_str(), fixed(t5.worst, 2).c_str(), t5.worst_mesh.c_str());
  }
  {
    // No real disk reaches 45k vertices: the refined meshes decide, the two real disks of
    // 40k to 45k vertices are shown beside them.
    std::string cells;
    bool all_met = true, any = false, near_met = true;
    for(const Row& r : all)
      if(r.vertices >= 40000)
      {
        const double q = time_ratio(r.r[CONFORMAL].seconds, r.r[FLOOR].seconds);
        cells += (cells.empty() ? "" : ", ") + r.name + " (" + std::to_string(r.vertices) + " V) " + fixed(q, 2);
        bool& flag = (r.vertices >= 45000) ? all_met : near_met;
        flag = flag && q <= 1.2;
        any = any || r.vertices >= 45000;
      }
    std::string verdict = !any ? "no mesh of >= 45k vertices" : all_met ? "**met**" : "**not met**";
    if(any && all_met && !near_met)
      verdict += " (not at 40k to 45k)";
    std::printf("| time conformal <= 1.2x the floor at >= 45k vertices | %s | %s |\n", verdict.c_str(), cells.c_str());
  }
  std::printf("\n");
}

} // namespace

int main(int argc, char** argv)
{
  Options options;
  std::string dir = MBP_MESH_DIR;
  options.bff = MBP_BFF_PROGRAM;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if(a == "--runs" && i + 1 < argc)
      options.runs = (std::max)(1, std::atoi(argv[++i]));
    else if(a == "--mesh" && i + 1 < argc)
      options.only.push_back(argv[++i]);
    else if(a == "--bff" && i + 1 < argc)
    {
      options.bff = argv[++i];
      if(options.bff == "none")
        options.bff.clear();
    }
    else if(a == "--cross-check" && i + 1 < argc)
    {
      static bool first = true;
      if(first)
        options.cross_check.clear();
      first = false;
      options.cross_check.push_back(argv[++i]);
    }
    else if(a == "--method" && i + 1 < argc)
      options.methods.push_back(argv[++i]);
    else if(a == "--scale" && i + 1 < argc)
      options.scale = (std::max)(0, std::atoi(argv[++i]));
    else if(!a.empty() && a[0] != '-')
      dir = a;
    else
    {
      std::fprintf(stderr, "usage: %s [--runs N] [--mesh NAME]... [--bff PATH|none] [--cross-check NAME]..."
                           " [--method NAME]... [--scale L] [MESH_DIR]\n", argv[0]);
      return 1;
    }
  }
  if(dir.empty())
  {
    std::fprintf(stderr, "no mesh directory (configure found none): give MESH_DIR\n");
    return 1;
  }
  if(!options.bff.empty() && ::access(options.bff.c_str(), X_OK) != 0)
  {
    std::fprintf(stderr, "BFF not found at %s: no BFF column (--bff PATH to give it)\n", options.bff.c_str());
    options.bff.clear();
  }

  char tmpl[] = "/tmp/border_table.XXXXXX";
  const char* tmp = ::mkdtemp(tmpl);
  if(!tmp)
  {
    std::fprintf(stderr, "cannot create a temporary directory\n");
    return 1;
  }

  std::vector<std::filesystem::path> files;
  for(const auto& e : std::filesystem::directory_iterator(dir))
  {
    const std::string ext = e.path().extension().string();
    if(ext != ".off" && ext != ".obj")
      continue;
    if(!options.only.empty() &&
       std::find(options.only.begin(), options.only.end(), e.path().filename().string()) == options.only.end())
      continue;
    files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());

  std::printf("# Border table (issue 11): %s, %d runs, BFF: %s, CHOLMOD: %s\n\n", dir.c_str(), options.runs,
              options.bff.empty() ? "none" : options.bff.c_str(),
#ifdef MBP_WITH_CHOLMOD
              "yes"
#else
              "no"
#endif
  );
  std::vector<Row> rows;
  std::vector<std::string> skipped;
  for(const std::filesystem::path& file : files)
  {
    Mesh mesh;
    const std::string name = file.filename().string();
    if(!CGAL::IO::read_polygon_mesh(file.string(), mesh) || is_empty(mesh) || !CGAL::is_triangle_mesh(mesh))
    {
      skipped.push_back(name + " (cannot be read as a triangle mesh)");
      continue;
    }
    const std::string why = mbp_benchmark::not_a_disk(mesh);
    if(!why.empty())
    {
      skipped.push_back(name + " (" + why + ")");
      continue;
    }
    std::fprintf(stderr, "%s: %zu vertices\n", name.c_str(), static_cast<std::size_t>(num_vertices(mesh)));
    Row row;
    row.name = name;
    const bool cross = std::find(options.cross_check.begin(), options.cross_check.end(), name) != options.cross_check.end();
    run_mesh(mesh, row, options, tmp, cross);
    rows.push_back(std::move(row));

    if(name == "bimba_i.obj")
      for(int level = 1; level <= options.scale; ++level)
      {
        mesh = refine(mesh);
        std::fprintf(stderr, "%s x%d: %zu vertices\n", name.c_str(), level, static_cast<std::size_t>(num_vertices(mesh)));
        Row scaled;
        scaled.name = name + " x" + std::to_string(level);
        scaled.scaled = true;
        run_mesh(mesh, scaled, options, tmp, false);
        rows.push_back(std::move(scaled));
      }
  }
  std::error_code ec;
  std::filesystem::remove_all(tmp, ec);

  std::vector<Row> real, scaled;
  for(const Row& r : rows)
    (r.scaled ? scaled : real).push_back(r);

  std::printf("## Angle distortion (`(nF)`: n flipped faces; `(overlap)`: no flip but not one-to-one;"
              " `*`: repaired)\n\n");
  print_distortion_table(real, false);
  std::printf("## L2 stretch\n\n");
  print_distortion_table(real, true);
  std::printf("## Flipped faces / one-to-one\n\n");
  print_flips_table(real);
  std::printf("## What the automatic border kept\n\n");
  print_choice_table(real);
  std::printf("## Conformal lengths (issue 23): the conformal border's blend (lengths kept) against the"
              " conformal-length member (its own blend)\n\n");
  print_conformal_lengths_table(real);
  std::printf("## Time (seconds, median of %d interleaved runs; BFF: the whole process)\n\n", options.runs);
  print_time_table(real);
#ifdef MBP_WITH_CHOLMOD
  std::printf("## Time with CHOLMOD (seconds, median of %d)\n\n", options.runs);
  print_cholmod_table(real);
#endif
  std::printf("## Where the time goes (report's stage times, medians; meshes of >= 20k vertices)\n\n");
  print_stage_table(real, 20000);
  if(!scaled.empty())
  {
    std::printf("## Refined meshes (not in the medians)\n\n");
    print_distortion_table(scaled, false);
    print_flips_table(scaled);
    print_choice_table(scaled);
    print_time_table(scaled);
#ifdef MBP_WITH_CHOLMOD
    print_cholmod_table(scaled);
#endif
    print_stage_table(scaled, 0);
  }
  std::printf("## Cross-check: our circle against CGAL's DCP (Circular_border_arc_length_parameterizer_3,"
              " BiCGSTAB)\n\n");
  print_cross_check(real);
  print_failures(rows);
  if(!skipped.empty())
  {
    std::printf("Skipped (not a disk):");
    for(const std::string& s : skipped)
      std::printf(" %s;", s.c_str());
    std::printf("\n\n");
  }
  std::printf("## Summary\n\n");
  print_summary(rows);
  return 0;
}
