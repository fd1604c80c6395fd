// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// The paper's Tables 1 and 2 (distortion of the measured boundary methods against DCP, and
// the four center / distance combinations) on every disk mesh of a directory, with times and
// the repair report; and (--auto) the automatic border against its members and the circle.
//
//   paper_tables [options] [MESH_DIR]   (default MESH_DIR: ../shared/data/meshes, as configured)
//
//   --runs N               timed runs per method and mesh (default 3); the median is reported.
//                          A method whose first run takes more than 2 s runs once.
//   --mesh NAME            only this file of MESH_DIR (repeatable)
//   --exact-max-vertices K exact geodesics (CGAL's Surface_mesh_shortest_path) only on meshes
//                          of at most K vertices (default 10000: 2 s at 3k vertices); "-" above
//   --auto                 the automatic border table (issue 6) instead of Tables 1 and 2
//
// Tables 1 and 2 (default mode). Every measured method is this package's
// Measured_conformal_parameterizer_3 (Eigen LDLT) constructed with the repair NO_REPAIR, so
// that the paper's method itself is measured. When its result is not one-to-one (status
// ERROR_NO_1_TO_1_MAPPING) nothing is written; the distortion of that unrepaired map is then
// measured on CGAL's Discrete_conformal_map_parameterizer_3 with the same
// Measured_border_parameterizer_3 (same policies) and a direct solver (Eigen's SparseLU): the
// same map (the package's tests check 1e-14), and the cell shows its flipped faces.
//   DCP             CGAL's DCP with Circular_border_arc_length_parameterizer_3, SparseLU
//   MBPPP           Poisson_center_locator + Poisson_border_distance (the package's default)
//   MBPGP <solver>  Poisson_center_locator + Geodesic_border_distance<solver>, solver =
//                   Fast_marching_geodesics (the paper's), Dijkstra_geodesics,
//                   Heat_method_geodesics<Direct>, Exact_geodesics
//   MBPSGP          Poisson_center_locator + Straightest_geodesic_border_distance ("-" when a
//                   border vertex is not reached; the failure is listed)
//   Table 2         {BPDM = Poisson_center_locator, BGDM = Geodesic_center_locator<
//                   Fast_marching_geodesics>} x {PDM = Poisson_border_distance, GDM =
//                   Geodesic_border_distance<Fast_marching_geodesics>}
//   repair          MBPPP and MBPGP (fast marching) once more with the default repair
//                   (BLEND_TOWARD_CIRCLE): for every mesh where it was needed, the distortion
//                   before and after, the blend, the interior kept, the time of the check and
//                   repair and of the whole call.
// Distortion: SMP::measure_quality() (user manual: Measuring a parameterization): angle_distortion (the paper's
// conformal distortion), l2_stretch (Sander's L2, 1 = optimal), flipped_faces.
// Time: wall-clock seconds of SMP::parameterize(), median of N interleaved runs (run 1 of every
// method, then run 2, ...); load from other processes is reported per row (1-minute load
// average of the machine, which has 2 cores).
//
// --auto (issue 6). Angle distortion of: circle (CGAL DCP with the arc-length circle,
// SparseLU), Poisson border (MBPPP, unrepaired), geodesic border (MBPGP fast marching,
// unrepaired), auto (Conformal_parameterizer_3 with the border policy Automatic_border<>,
// the default), CGAL's LSCM (free border, defaults); auto / circle;
// also auto with the geodesic policy (Geodesic_border_distance with fast marching; its second
// border is then the Poisson one);
// the time of auto against the plain geodesic method (MBPGP fast marching, NO_REPAIR: its
// own cost without any repair), both measured in the same interleaved runs; the member
// chosen (family and blend t), the number of borders tried and the search time.
//
// Meshes that are not a single disk are skipped with the reason.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/Eigen_sparse_matrix.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/Circular_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_conformal_map_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <CGAL/Surface_mesh_parameterization/Automatic_border.h>
#include <CGAL/Surface_mesh_parameterization/Conformal_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Geodesic_border_distance.h>
#include <CGAL/Surface_mesh_parameterization/Geodesic_center_locator.h>
#include <CGAL/Surface_mesh_parameterization/Measured_border.h>
#include <CGAL/Surface_mesh_parameterization/Measured_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_report.h>
#include <CGAL/Surface_mesh_parameterization/Poisson_border_distance.h>
#include <CGAL/Surface_mesh_parameterization/Poisson_center_locator.h>
#include <CGAL/Surface_mesh_parameterization/Straightest_geodesic_border_distance.h>
#include <CGAL/Surface_mesh_parameterization/geodesic_method_tags.h>
#include <CGAL/Surface_mesh_parameterization/measure_quality.h>

#include <Eigen/SparseLU>

#include "benchmark_support.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

namespace SMP = CGAL::Surface_mesh_parameterization;
typedef CGAL::Simple_cartesian<double>                          K;
typedef CGAL::Surface_mesh<K::Point_3>                          Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor            vertex_descriptor;
typedef boost::graph_traits<Mesh>::halfedge_descriptor          halfedge_descriptor;
typedef Mesh::Property_map<vertex_descriptor, K::Point_2>       UV_map;
typedef std::chrono::steady_clock                               Clock;
typedef CGAL::Eigen_solver_traits<Eigen::SparseLU<CGAL::Eigen_sparse_matrix<double>::EigenType> > LU;

typedef SMP::Poisson_center_locator                                             BPDM;
typedef SMP::Geodesic_center_locator<SMP::Fast_marching_geodesics>              BGDM;
typedef SMP::Poisson_border_distance                                            PDM;
typedef SMP::Geodesic_border_distance<SMP::Fast_marching_geodesics>             GDM_fm;
typedef SMP::Geodesic_border_distance<SMP::Dijkstra_geodesics>                  GDM_dijkstra;
typedef SMP::Geodesic_border_distance<SMP::Heat_method_geodesics<> >            GDM_heat;
typedef SMP::Geodesic_border_distance<SMP::Exact_geodesics>                     GDM_exact;
typedef SMP::Straightest_geodesic_border_distance                               SGDM;

namespace {

enum Mode { NO_REPAIR, DEFAULT_REPAIR, AUTOMATIC };

// One call of a method and what its report says.
struct Run
{
  SMP::Error_code status = SMP::OK;
  double seconds = 0.;
  std::string failure;  // why it failed, when known
  // our parameterizer's report
  bool is_ours = false;
  bool valid_before_repair = true;
  std::size_t flips_before = 0;
  bool repaired = false, mean_value_interior = false;
  double blend = 0., repair_seconds = 0., total_seconds = 0.;
  int candidates = 0, chosen = -1, chosen_family = -1;
  double chosen_blend = 0., search_seconds = 0.;
};

double since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// Our parameterizer with the border policy `Border` and the repair `repair`.
template <class Border>
Run run_ours(Mesh& mesh, halfedge_descriptor bhd, UV_map uv, SMP::Repair repair)
{
  typedef SMP::Conformal_parameterizer_3<Mesh, Border> Parameterizer;
  const Parameterizer p(Border(), typename Parameterizer::Solver_traits(), repair);
  SMP::Parameterization_report report;
  Run r;
  const Clock::time_point start = Clock::now();
  r.status = SMP::parameterize(mesh, p, bhd, uv, &report);
  r.seconds = since(start);
  r.is_ours = true;
  r.valid_before_repair = report.valid_before_repair;
  r.flips_before = report.flipped_faces_before_repair;
  r.repaired = report.repaired;
  r.mean_value_interior = report.mean_value_interior;
  r.blend = report.blend;
  r.repair_seconds = report.repair_seconds;
  r.total_seconds = report.total_seconds;
  r.candidates = static_cast<int>(report.border_candidates.size());
  r.chosen = report.chosen_candidate;
  if(r.chosen >= 0)
  {
    r.chosen_family = static_cast<int>(report.border_candidates[static_cast<std::size_t>(r.chosen)].family);
    r.chosen_blend = report.border_candidates[static_cast<std::size_t>(r.chosen)].blend;
  }
  r.search_seconds = report.interior_seconds + report.conformal_border_seconds;
  if(report.unreachable_border_vertices > 0)  // the distances of the vertices not reached are 0
  {
    const std::size_t first = static_cast<std::size_t>(
      std::find(report.border_distances.begin(), report.border_distances.end(), 0.) - report.border_distances.begin());
    r.failure = std::to_string(report.unreachable_border_vertices) + " of " +
                std::to_string(report.border_distances.size()) + " border vertices not reached (first: border index " +
                std::to_string(first) + ")";
  }
  if(r.status != SMP::OK && r.failure.empty())
    r.failure = SMP::get_measured_error_message(r.status);
  return r;
}

template <class Parameterizer>
Run run_cgal(Mesh& mesh, halfedge_descriptor bhd, UV_map uv, Parameterizer p)
{
  Run r;
  const Clock::time_point start = Clock::now();
  r.status = SMP::parameterize(mesh, p, bhd, uv);
  r.seconds = since(start);
  if(r.status != SMP::OK)
    r.failure = SMP::get_measured_error_message(r.status);
  return r;
}

// The unrepaired measured map with the given policies: CGAL's DCP with the measured border and
// a direct solver, i.e. the map our parameterizer rejects under NO_REPAIR.
template <class Center, class Distance>
bool unrepaired_map(Mesh& mesh, halfedge_descriptor bhd, UV_map uv)
{
  typedef SMP::Measured_border_parameterizer_3<Mesh, Center, Distance> Border;
  SMP::Discrete_conformal_map_parameterizer_3<Mesh, Border, LU> dcp;
  return SMP::parameterize(mesh, dcp, bhd, uv) == SMP::OK;
}

typedef std::function<Run(Mesh&, halfedge_descriptor, UV_map)> Runner;
typedef std::function<bool(Mesh&, halfedge_descriptor, UV_map)> Fallback;

struct Method
{
  std::string name;
  Runner run;
  Fallback unrepaired;           // for ours under NO_REPAIR: the map it rejected
  std::size_t max_vertices = 0;  // 0: no cap
};

template <class Center, class Distance>
Method ours(const std::string& name, Mode mode, std::size_t max_vertices = 0)
{
  Method m;
  m.name = name;
  m.run = [mode](Mesh& mesh, halfedge_descriptor bhd, UV_map uv) {
    if(mode == AUTOMATIC)
      return run_ours<SMP::Automatic_border<Center, Distance> >(mesh, bhd, uv, SMP::BLEND_TOWARD_CIRCLE);
    return run_ours<SMP::Measured_border<Center, Distance> >(mesh, bhd, uv,
                                                            mode == NO_REPAIR ? SMP::NO_REPAIR : SMP::BLEND_TOWARD_CIRCLE);
  };
  if(mode == NO_REPAIR)
    m.unrepaired = [](Mesh& mesh, halfedge_descriptor bhd, UV_map uv) { return unrepaired_map<Center, Distance>(mesh, bhd, uv); };
  m.max_vertices = max_vertices;
  return m;
}

Method dcp_circle()
{
  Method m;
  m.name = "DCP";
  m.run = [](Mesh& mesh, halfedge_descriptor bhd, UV_map uv) {
    typedef SMP::Circular_border_arc_length_parameterizer_3<Mesh> Circle;
    return run_cgal(mesh, bhd, uv, SMP::Discrete_conformal_map_parameterizer_3<Mesh, Circle, LU>());
  };
  return m;
}

Method lscm()
{
  Method m;
  m.name = "LSCM";
  m.run = [](Mesh& mesh, halfedge_descriptor bhd, UV_map uv) { return run_cgal(mesh, bhd, uv, SMP::LSCM_parameterizer_3<Mesh>()); };
  return m;
}

// What a method gave on one mesh.
struct Result
{
  bool skipped = false;       // above its vertex cap
  Run first;                  // the first run (status, report)
  double seconds = 0.;        // median
  bool has_quality = false;
  bool unrepaired = false;    // the quality is that of the map our parameterizer rejected
  SMP::Parameterization_quality quality;
};

double median(std::vector<double> v)
{
  if(v.empty())
    return std::numeric_limits<double>::quiet_NaN();
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return (n % 2) ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double load_average()
{
  std::ifstream in("/proc/loadavg");
  double l = -1.;
  in >> l;
  return l;
}

std::vector<Result> run_methods(Mesh& mesh, const std::vector<Method>& methods, int runs, const std::string& label)
{
  const halfedge_descriptor bhd = CGAL::Polygon_mesh_processing::longest_border(mesh).first;
  UV_map uv = mesh.add_property_map<vertex_descriptor, K::Point_2>("v:bench_uv").first;
  std::vector<Result> results(methods.size());
  std::vector<std::vector<double> > times(methods.size());
  std::vector<bool> repeat(methods.size(), true);
  for(int run = 0; run < runs; ++run)
    for(std::size_t m = 0; m < methods.size(); ++m)
    {
      Result& res = results[m];
      if(methods[m].max_vertices > 0 && num_vertices(mesh) > methods[m].max_vertices)
      {
        res.skipped = true;
        continue;
      }
      if(!repeat[m])
        continue;
      if(run == 0)
        std::cerr << label << ": " << methods[m].name << "..." << std::flush;
      Run r = methods[m].run(mesh, bhd, uv);
      times[m].push_back(r.seconds);
      if(run == 0)
      {
        std::cerr << " " << r.seconds << " s" << (r.status == SMP::OK ? "" : " (" + r.failure + ")") << "\n";
        res.first = r;
        if(r.seconds > 2.)
          repeat[m] = false;
        if(r.status == SMP::OK)
        {
          res.quality = SMP::measure_quality(mesh, faces(mesh), uv);
          res.has_quality = true;
        }
        else if(r.status == SMP::ERROR_NO_1_TO_1_MAPPING && methods[m].unrepaired &&
                methods[m].unrepaired(mesh, bhd, uv))
        {
          res.quality = SMP::measure_quality(mesh, faces(mesh), uv);
          res.has_quality = true;
          res.unrepaired = true;
        }
      }
    }
  for(std::size_t m = 0; m < methods.size(); ++m)
    results[m].seconds = median(times[m]);
  mesh.remove_property_map(uv);
  return results;
}

using mbp_benchmark::not_a_disk;

std::string fmt(const char* f, double x)
{
  char buf[64];
  std::snprintf(buf, sizeof buf, f, x);
  return buf;
}

// A distortion cell: the value, with the flips of an unrepaired folded map; "-" on failure.
std::string cell(const Result& r, double SMP::Parameterization_quality::*field)
{
  if(r.skipped)
    return "- (cap)";
  if(!r.has_quality)
    return "-";
  std::string s = fmt("%.4f", r.quality.*field);
  if(r.unrepaired || r.quality.flipped_faces > 0)
    s += " (" + std::to_string(r.quality.flipped_faces) + "F)";
  return s;
}

std::string time_cell(const Result& r)
{
  if(r.skipped)
    return "-";
  return fmt(r.seconds < 0.1 ? "%.4f" : "%.3f", r.seconds);
}

double angle(const Result& r)
{
  return r.has_quality ? r.quality.angle_distortion : std::numeric_limits<double>::quiet_NaN();
}

struct Mesh_entry
{
  std::string name;
  Mesh mesh;
};

// Counts "a < b" over the meshes where both are defined; ties within a relative 1e-9 apart.
struct Claim
{
  std::string text;
  int holds = 0, fails = 0, ties = 0, undefined = 0;
  std::vector<std::string> exceptions;

  explicit Claim(const std::string& t) : text(t) { }

  void add(const std::string& mesh, double a, double b)
  {
    if(!(std::isfinite(a) && std::isfinite(b)))
    {
      ++undefined;
      return;
    }
    if(std::abs(a - b) <= 1e-9 * std::max(std::abs(a), std::abs(b)))
      ++ties;
    else if(a < b)
      ++holds;
    else
    {
      ++fails;
      exceptions.push_back(mesh + " (" + fmt("%.4f", a) + " vs " + fmt("%.4f", b) + ")");
    }
  }

  void add_bool(const std::string& mesh, bool ok, const std::string& why)
  {
    if(ok)
      ++holds;
    else
    {
      ++fails;
      exceptions.push_back(mesh + " (" + why + ")");
    }
  }

  void print() const
  {
    std::printf("| %s | %d | %d | %d | %d | ", text.c_str(), holds, fails, ties, undefined);
    for(std::size_t i = 0; i < exceptions.size(); ++i)
      std::printf("%s%s", i ? ", " : "", exceptions[i].c_str());
    std::printf(" |\n");
  }
};

// ---------------------------------------------------------------------------------------

void paper_tables(std::vector<Mesh_entry>& meshes, int runs, std::size_t exact_cap)
{
  enum { DCP, MBPPP, GP_FM, GP_DIJKSTRA, GP_HEAT, GP_EXACT, SGP, BGDM_PDM, BGDM_GDM, MBPPP_REPAIR, GP_FM_REPAIR, COUNT };
  std::vector<Method> methods(COUNT);
  methods[DCP] = dcp_circle();
  methods[MBPPP] = ours<BPDM, PDM>("MBPPP", NO_REPAIR);
  methods[GP_FM] = ours<BPDM, GDM_fm>("MBPGP fast marching", NO_REPAIR);
  methods[GP_DIJKSTRA] = ours<BPDM, GDM_dijkstra>("MBPGP Dijkstra", NO_REPAIR);
  methods[GP_HEAT] = ours<BPDM, GDM_heat>("MBPGP heat", NO_REPAIR);
  methods[GP_EXACT] = ours<BPDM, GDM_exact>("MBPGP exact", NO_REPAIR, exact_cap);
  methods[SGP] = ours<BPDM, SGDM>("MBPSGP", NO_REPAIR);
  methods[BGDM_PDM] = ours<BGDM, PDM>("BGDM+PDM", NO_REPAIR);
  methods[BGDM_GDM] = ours<BGDM, GDM_fm>("BGDM+GDM", NO_REPAIR);
  methods[MBPPP_REPAIR] = ours<BPDM, PDM>("MBPPP (default repair)", DEFAULT_REPAIR);
  methods[GP_FM_REPAIR] = ours<BPDM, GDM_fm>("MBPGP fast marching (default repair)", DEFAULT_REPAIR);

  std::vector<std::vector<Result> > all;
  std::vector<double> loads;
  for(Mesh_entry& e : meshes)
  {
    all.push_back(run_methods(e.mesh, methods, runs, e.name));
    loads.push_back(load_average());
  }

  auto header = [](const char* title, const std::vector<int>& cols, const std::vector<Method>& ms, bool with_v,
                   bool with_load = false) {
    std::printf("\n#### %s\n\n| mesh |%s", title, with_v ? " V |" : "");
    for(int c : cols)
      std::printf(" %s |", ms[static_cast<std::size_t>(c)].name.c_str());
    std::printf("%s\n|---|%s", with_load ? " load |" : "", with_v ? "---|" : "");
    for(std::size_t i = 0; i < cols.size() + (with_load ? 1 : 0); ++i)
      std::printf("---|");
    std::printf("\n");
  };

  const std::vector<int> table1 = {DCP, MBPPP, GP_FM, GP_DIJKSTRA, GP_HEAT, GP_EXACT, SGP};
  for(int q = 0; q < 2; ++q)
  {
    header(q == 0 ? "Table 1a: angle distortion (paper's conformal distortion)" : "Table 1b: L2 stretch", table1, methods, true);
    for(std::size_t i = 0; i < meshes.size(); ++i)
    {
      std::printf("| %s | %zu |", meshes[i].name.c_str(), std::size_t(num_vertices(meshes[i].mesh)));
      for(int c : table1)
        std::printf(" %s |", cell(all[i][static_cast<std::size_t>(c)], q == 0 ? &SMP::Parameterization_quality::angle_distortion
                                                                            : &SMP::Parameterization_quality::l2_stretch).c_str());
      std::printf("\n");
    }
  }

  const std::vector<int> table2 = {BGDM_GDM, GP_FM, BGDM_PDM, MBPPP};
  std::printf("\n#### Table 2: angle distortion by center (BPDM / BGDM) and distance (GDM = fast marching / PDM)\n\n"
              "| mesh | BGDM+GDM | BPDM+GDM (MBPGP) | BGDM+PDM | BPDM+PDM (MBPPP) |\n|---|---|---|---|---|\n");
  for(std::size_t i = 0; i < meshes.size(); ++i)
  {
    std::printf("| %s |", meshes[i].name.c_str());
    for(int c : table2)
      std::printf(" %s |", cell(all[i][static_cast<std::size_t>(c)], &SMP::Parameterization_quality::angle_distortion).c_str());
    std::printf("\n");
  }

  const std::vector<int> timed = {DCP, MBPPP, GP_FM, GP_DIJKSTRA, GP_HEAT, GP_EXACT, SGP, BGDM_PDM, BGDM_GDM};
  header("Time (seconds, median; NO_REPAIR for ours, failed calls timed to their failure; load = 1-minute load"
         " average after the row)", timed, methods, true, true);
  for(std::size_t i = 0; i < meshes.size(); ++i)
  {
    std::printf("| %s | %zu |", meshes[i].name.c_str(), std::size_t(num_vertices(meshes[i].mesh)));
    for(int c : timed)
      std::printf(" %s |", time_cell(all[i][static_cast<std::size_t>(c)]).c_str());
    std::printf(" %.2f |\n", loads[i]);
  }

  std::printf("\n#### Failures (status of the measured method under NO_REPAIR, other than OK)\n\n");
  for(std::size_t i = 0; i < meshes.size(); ++i)
    for(int c = 0; c < COUNT; ++c)
    {
      const Result& r = all[i][static_cast<std::size_t>(c)];
      if(!r.skipped && r.first.status != SMP::OK)
        std::printf("- %s, %s: %s%s\n", meshes[i].name.c_str(), methods[static_cast<std::size_t>(c)].name.c_str(),
                    r.first.failure.c_str(),
                    r.first.status == SMP::ERROR_NO_1_TO_1_MAPPING
                      ? (" (" + std::to_string(r.first.flips_before) + " flipped faces)").c_str() : "");
    }

  std::printf("\n#### Repair (default BLEND_TOWARD_CIRCLE), meshes where the measured result was not one-to-one\n\n");
  std::printf("| mesh | V | method | flips before | angle dist. before | angle dist. after | L2 before | L2 after |"
              " flips after | blend t | interior | check + repair (s) | call (s) | repair share |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for(std::size_t i = 0; i < meshes.size(); ++i)
    for(const auto& pair : {std::make_pair(MBPPP, MBPPP_REPAIR), std::make_pair(GP_FM, GP_FM_REPAIR)})
    {
      const Result& before = all[i][static_cast<std::size_t>(pair.first)];
      const Result& after = all[i][static_cast<std::size_t>(pair.second)];
      if(after.first.valid_before_repair || !after.has_quality)
        continue;
      std::printf("| %s | %zu | %s | %zu | %s | %.4f | %s | %.4f | %zu | %.3f | %s | %.4f | %.4f | %.0f%% |\n",
                  meshes[i].name.c_str(), std::size_t(num_vertices(meshes[i].mesh)),
                  methods[static_cast<std::size_t>(pair.first)].name.c_str(), after.first.flips_before,
                  before.has_quality ? fmt("%.4f", before.quality.angle_distortion).c_str() : "-",
                  after.quality.angle_distortion,
                  before.has_quality ? fmt("%.4f", before.quality.l2_stretch).c_str() : "-",
                  after.quality.l2_stretch, after.quality.flipped_faces, after.first.blend,
                  after.first.mean_value_interior ? "MVC" : "DCP", after.first.repair_seconds, after.seconds,
                  100. * after.first.repair_seconds / after.first.total_seconds);
    }

  std::printf("\n#### Paper claims, counted (angle distortion unless stated; a < b)\n\n"
              "| claim | holds | fails | ties | undefined | where it fails |\n|---|---|---|---|---|---|\n");
  Claim c1{"MBPGP (fast marching) < MBPPP"}, c1l{"MBPGP (fast marching) < MBPPP, L2"}, c2{"MBPPP < DCP"},
    c2l{"MBPPP < DCP, L2"}, c3{"MBPGP (fast marching) < DCP"}, c3l{"MBPGP (fast marching) < DCP, L2"},
    c4{"BPDM+GDM < BGDM+GDM"}, c5{"BPDM+PDM < BGDM+PDM"}, c6{"MBPPP one-to-one (no flip)"},
    c7{"MBPGP (fast marching) one-to-one"};
  auto l2 = [](const Result& r) { return r.has_quality ? r.quality.l2_stretch : std::numeric_limits<double>::quiet_NaN(); };
  for(std::size_t i = 0; i < meshes.size(); ++i)
  {
    const std::vector<Result>& r = all[i];
    const std::string& n = meshes[i].name;
    c1.add(n, angle(r[GP_FM]), angle(r[MBPPP]));
    c1l.add(n, l2(r[GP_FM]), l2(r[MBPPP]));
    c2.add(n, angle(r[MBPPP]), angle(r[DCP]));
    c2l.add(n, l2(r[MBPPP]), l2(r[DCP]));
    c3.add(n, angle(r[GP_FM]), angle(r[DCP]));
    c3l.add(n, l2(r[GP_FM]), l2(r[DCP]));
    c4.add(n, angle(r[GP_FM]), angle(r[BGDM_GDM]));
    c5.add(n, angle(r[MBPPP]), angle(r[BGDM_PDM]));
    c6.add_bool(n, r[MBPPP].first.status == SMP::OK, std::to_string(r[MBPPP].first.flips_before) + "F");
    c7.add_bool(n, r[GP_FM].first.status == SMP::OK, std::to_string(r[GP_FM].first.flips_before) + "F");
  }
  for(const Claim* c : {&c1, &c1l, &c2, &c2l, &c3, &c3l, &c4, &c5, &c6, &c7})
    c->print();
}

// ---------------------------------------------------------------------------------------

void auto_table(std::vector<Mesh_entry>& meshes, int runs)
{
  enum { CIRCLE, POISSON, GEODESIC, AUTO, AUTO_GEODESIC, LSCM, COUNT };
  std::vector<Method> methods(COUNT);
  methods[CIRCLE] = dcp_circle();
  methods[CIRCLE].name = "circle (DCP)";
  methods[POISSON] = ours<BPDM, PDM>("Poisson border", NO_REPAIR);
  methods[GEODESIC] = ours<BPDM, GDM_fm>("geodesic border", NO_REPAIR);
  methods[AUTO] = ours<BPDM, PDM>("auto", AUTOMATIC);
  methods[AUTO_GEODESIC] = ours<BPDM, GDM_fm>("auto, geodesic policy", AUTOMATIC);
  methods[LSCM] = lscm();

  std::printf("\n#### Automatic border: angle distortion, choice and time\n\n"
              "| mesh | V | circle (DCP) | Poisson border | geodesic border | auto | CGAL LSCM | auto / circle |"
              " chosen | borders tried | auto (s) | geodesic (s) | auto / geodesic | search (s) |"
              " auto, geodesic policy | its time / geodesic | load |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  std::vector<double> ratios, time_ratios, geo_ratios, geo_time_ratios;
  std::string worst_mesh, worst_time_mesh;
  int above = 0;
  for(Mesh_entry& e : meshes)
  {
    const std::vector<Result> r = run_methods(e.mesh, methods, runs, e.name);
    const Result& a = r[AUTO];
    std::string chosen = "-";
    if(a.first.status == SMP::OK)
    {
      if(a.first.chosen < 0)
        chosen = "none valid: repaired";
      else if(a.first.chosen_family == 0)
        chosen = "circle";
      else
        chosen = std::string(a.first.chosen_family == 1   ? "measured"
                             : a.first.chosen_family == 2 ? "conformal"
                                                          : "conformal-lengths") +
                 " t=" + fmt("%.3f", a.first.chosen_blend);
    }
    const double ratio = angle(a) / angle(r[CIRCLE]);
    const double time_ratio = a.seconds / r[GEODESIC].seconds;
    if(std::isfinite(ratio))
    {
      if(ratios.empty() || ratio > *std::max_element(ratios.begin(), ratios.end()))
        worst_mesh = e.name;
      ratios.push_back(ratio);
      if(angle(a) > angle(r[CIRCLE]) * (1. + 1e-9))
        ++above;
    }
    if(std::isfinite(time_ratio))
    {
      if(time_ratios.empty() || time_ratio > *std::max_element(time_ratios.begin(), time_ratios.end()))
        worst_time_mesh = e.name;
      time_ratios.push_back(time_ratio);
    }
    const Result& g = r[AUTO_GEODESIC];
    if(std::isfinite(angle(g) / angle(r[CIRCLE])))
      geo_ratios.push_back(angle(g) / angle(r[CIRCLE]));
    if(std::isfinite(g.seconds / r[GEODESIC].seconds))
      geo_time_ratios.push_back(g.seconds / r[GEODESIC].seconds);
    std::printf("| %s | %zu | %s | %s | %s | %s | %s | %.3f | %s | %d | %s | %s | %.2f | %.4f | %s | %.2f | %.2f |\n", e.name.c_str(),
                std::size_t(num_vertices(e.mesh)), cell(r[CIRCLE], &SMP::Parameterization_quality::angle_distortion).c_str(),
                cell(r[POISSON], &SMP::Parameterization_quality::angle_distortion).c_str(),
                cell(r[GEODESIC], &SMP::Parameterization_quality::angle_distortion).c_str(),
                cell(a, &SMP::Parameterization_quality::angle_distortion).c_str(),
                cell(r[LSCM], &SMP::Parameterization_quality::angle_distortion).c_str(), ratio, chosen.c_str(),
                a.first.candidates, time_cell(a).c_str(), time_cell(r[GEODESIC]).c_str(), time_ratio, a.first.search_seconds,
                cell(g, &SMP::Parameterization_quality::angle_distortion).c_str(), g.seconds / r[GEODESIC].seconds,
                load_average());
    std::fflush(stdout);
  }
  std::printf("\nauto / circle over %zu meshes: median %.3f, worst %.3f (%s); auto above circle on %d meshes\n",
              ratios.size(), median(ratios), ratios.empty() ? 0. : *std::max_element(ratios.begin(), ratios.end()),
              worst_mesh.c_str(), above);
  std::printf("auto time / plain geodesic time: median %.2f, worst %.2f (%s)\n", median(time_ratios),
              time_ratios.empty() ? 0. : *std::max_element(time_ratios.begin(), time_ratios.end()), worst_time_mesh.c_str());
  std::printf("auto with the geodesic policy: auto / circle median %.3f, worst %.3f; time / plain geodesic median %.2f,"
              " worst %.2f\n", median(geo_ratios), geo_ratios.empty() ? 0. : *std::max_element(geo_ratios.begin(), geo_ratios.end()),
              median(geo_time_ratios),
              geo_time_ratios.empty() ? 0. : *std::max_element(geo_time_ratios.begin(), geo_time_ratios.end()));
}

int usage(const char* argv0)
{
  std::cerr << "usage: " << argv0 << " [--runs N] [--mesh NAME]... [--exact-max-vertices K] [--auto] [MESH_DIR]\n";
  return 2;
}

} // namespace

int main(int argc, char** argv)
{
  std::string dir = MBP_MESH_DIR;
  std::vector<std::string> only;
  int runs = 3;
  std::size_t exact_cap = 10000;
  bool automatic = false;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    const bool has_value = i + 1 < argc;
    if(a == "--runs" && has_value)                     runs = std::atoi(argv[++i]);
    else if(a == "--mesh" && has_value)                only.push_back(argv[++i]);
    else if(a == "--exact-max-vertices" && has_value)  exact_cap = std::strtoul(argv[++i], nullptr, 10);
    else if(a == "--auto")                             automatic = true;
    else if(!a.empty() && a[0] == '-')                 return usage(argv[0]);
    else                                               dir = a;
  }
  if(runs < 1)
    return usage(argv[0]);

  const std::vector<std::filesystem::path> files = mbp_benchmark::mesh_files_in(dir, only);
  if(files.empty())
  {
    std::cerr << "error: no mesh in '" << dir << "'\n";
    return 1;
  }

  std::vector<Mesh_entry> meshes;
  std::vector<std::string> skipped;
  for(const auto& path : files)
  {
    Mesh_entry e;
    e.name = path.filename().string();
    if(!CGAL::IO::read_polygon_mesh(path.string(), e.mesh) || faces(e.mesh).empty())
    {
      skipped.push_back(e.name + " (not readable as a polygon mesh)");
      continue;
    }
    const std::string why = not_a_disk(e.mesh);
    if(!why.empty())
    {
      skipped.push_back(e.name + " (" + why + ")");
      continue;
    }
    meshes.push_back(std::move(e));
  }
  std::printf("%d runs per method (median), load average at start %.2f\n", runs, load_average());
  if(automatic)
    auto_table(meshes, runs);
  else
    paper_tables(meshes, runs, exact_cap);
  std::printf("\n");
  for(const std::string& s : skipped)
    std::printf("skipped: %s\n", s.c_str());
  return 0;
}
