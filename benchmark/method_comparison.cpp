// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// Time, peak memory and distortion of this package's Measured_conformal_parameterizer_3
// against CGAL's parameterizers, on every disk mesh of a directory: the paper's Tables 1
// (distortion) and 3 (time), plus the cost of one factorization as a floor.
//
//   method_comparison [options] [MESH_DIR]   (default MESH_DIR: ../shared/data/meshes, as configured)
//
//   --runs N        timed runs per method and mesh (default 5); the median is reported
//   --mesh NAME     only this file of MESH_DIR (repeatable), e.g. to rerun a noisy row
//   --no-memory     skip the peak memory measurement
//   --scale         scale mode: the mesh of --scale-mesh refined by 1-to-4 midpoint
//                   subdivision (every edge split at its midpoint, every triangle into 4)
//   --scale-mesh F  the mesh the scale mode refines (default MESH_DIR/bimba_i.obj)
//   --levels L      scale mode: subdivision levels up to L (default 2)
//   --first-level K scale mode: the first level measured (default 1), e.g. to rerun a row
//   --dcp-cap S     scale mode: CGAL's DCP runs once, in a child process killed after S
//                   seconds (default 900)
//
// Methods (all through SMP::parameterize(mesh, parameterizer, longest border, uv map)):
//   ours LDLT      SMP::Measured_conformal_parameterizer_3, Default_sparse_cholesky_traits
//                  (Eigen's SimplicialLDLT), default use_concurrency(true): the spring
//                  Laplacian is factorized in a second thread while the center is located;
//                  default repair (an invalid result is blended toward a circle)
//   ours LDLT seq  the same with use_concurrency(false)
//   ours CHOLMOD   the same with Cholmod_supernodal_cholesky_traits (only when built with
//                  CHOLMOD, i.e. MBP_WITH_CHOLMOD), concurrent and sequential
//   DCP            CGAL's Discrete_conformal_map_parameterizer_3, defaults (circular
//                  arc-length border, BiCGSTAB + IncompleteLUT)
//   LSCM           CGAL's LSCM_parameterizer_3, defaults (two fixed vertices)
//   MVC            CGAL's Mean_value_coordinates_parameterizer_3, defaults (circular
//                  arc-length border, BiCGSTAB + IncompleteLUT)
//
// Time: wall-clock seconds of the SMP::parameterize() call (reading the mesh, the quality
// measure and printing are outside), median of N runs. The runs are interleaved (run 1 of
// every method, then run 2, ...) so that load from other processes spreads over all methods.
// "other load": the share of the machine's cores that other processes kept busy during the
// timed runs of the row (/proc/stat minus this process); rerun rows where it is high.
//
// Floor: one analyzePattern() + factorize() of the interior cotangent Laplacian L_II (border
// eliminated), with the solver of the method: Eigen's SimplicialLDLT, or the configured
// CholmodSupernodalLLT of Cholmod_supernodal_cholesky_traits (AMD ordering, nmethods = 1).
// L_II is assembled once, outside the timing, with Parameterization_patch_3 and
// internal::laplacian_triplets. Any method that factorizes L_II costs at least this; ours
// also factorizes the spring Laplacian. "ratio" = method time / floor time (medians).
//
// Peak memory: each method runs once more in a child process (this program, fork()ed and
// exec()ed with the hidden option --child), which reads the mesh, runs the method on a small
// grid (so that code pages and library buffers are in place), releases free heap memory
// (malloc_trim), resets its peak resident set size (/proc/self/clear_refs "5"), reads VmRSS,
// runs the method on the mesh and reads VmHWM. Reported: VmHWM - VmRSS, in MB: what the
// call adds to a process that holds the mesh (the UV map included, it is added before).
//
// Distortion (METHOD.md section 5): SMP::measure_quality(), the paper's angle distortion
// (Sheffer-de Sturler, optimal angles, divided by |V|) and Sander's L2 stretch (1 = optimal).
//
// Meshes that are not a single disk are skipped with the reason. The program prints
// markdown tables on stdout and progress on stderr; it ends with the targets of the issue
// (met / not met) evaluated on the numbers of this run.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_conformal_map_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Mean_value_coordinates_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <CGAL/Surface_mesh_parameterization/Measured_conformal_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_patch_3.h>
#include <CGAL/Surface_mesh_parameterization/internal/laplacian.h>
#include <CGAL/Surface_mesh_parameterization/measure_quality.h>
#ifdef MBP_WITH_CHOLMOD
#include <CGAL/Surface_mesh_parameterization/Cholmod_supernodal_cholesky_traits.h>
#endif

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <malloc.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include "benchmark_support.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace SMP = CGAL::Surface_mesh_parameterization;
typedef CGAL::Simple_cartesian<double>                          K;
typedef CGAL::Surface_mesh<K::Point_3>                          Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor            vertex_descriptor;
typedef boost::graph_traits<Mesh>::halfedge_descriptor          halfedge_descriptor;
typedef Mesh::Property_map<vertex_descriptor, K::Point_2>       UV_map;
typedef std::chrono::steady_clock                               Clock;

typedef SMP::Measured_conformal_parameterizer_3<Mesh>           Ours_ldlt;
typedef SMP::Measured_conformal_parameterizer_3<Mesh, CGAL::Default, CGAL::Default, CGAL::Default,
                                                CGAL::Parallel_tag> Ours_ldlt_parallel;
#ifdef MBP_WITH_CHOLMOD
typedef SMP::Measured_conformal_parameterizer_3<Mesh, CGAL::Default, CGAL::Default,
                                                SMP::Cholmod_supernodal_cholesky_traits> Ours_cholmod;
typedef SMP::Measured_conformal_parameterizer_3<Mesh, CGAL::Default, CGAL::Default,
                                                SMP::Cholmod_supernodal_cholesky_traits,
                                                CGAL::Parallel_tag> Ours_cholmod_parallel;
#endif
typedef SMP::Discrete_conformal_map_parameterizer_3<Mesh>       Cgal_dcp;
typedef SMP::LSCM_parameterizer_3<Mesh>                         Cgal_lscm;
typedef SMP::Mean_value_coordinates_parameterizer_3<Mesh>       Cgal_mvc;

namespace {

// ---------------------------------------------------------------------------------------
// Methods

enum Method { OURS_LDLT, OURS_LDLT_SEQ, OURS_CHOLMOD, OURS_CHOLMOD_SEQ, CGAL_DCP, CGAL_LSCM, CGAL_MVC,
              NUMBER_OF_METHODS };

const char* method_name(int m)
{
  static const char* names[NUMBER_OF_METHODS] = {"ours LDLT", "ours LDLT seq", "ours CHOLMOD", "ours CHOLMOD seq",
                                                 "CGAL DCP", "CGAL LSCM", "CGAL MVC"};
  return names[m];
}

bool method_available(int m)
{
#ifdef MBP_WITH_CHOLMOD
  (void)m;
  return true;
#else
  return m != OURS_CHOLMOD && m != OURS_CHOLMOD_SEQ;
#endif
}

// Stage times of our parameterizer (its own report), seconds.
struct Stages
{
  double preparation = 0., center = 0., distance = 0., border_map = 0., interior = 0., repair = 0., output = 0.,
         total = 0., factorizations = 0.;
};

// What our parameterizer's validity check and repair did (its report).
struct Repair_info
{
  std::size_t flips_before = 0;
  bool repaired = false;
  double blend = 0.;
  bool mean_value_interior = false;
};

struct Run
{
  SMP::Error_code status = SMP::OK;
  double seconds = 0.;
  bool is_ours = false;
  Stages stages;
  Repair_info repair;
};

template <class Parameterizer>
Run time_parameterize(Mesh& mesh, Parameterizer& parameterizer, halfedge_descriptor bhd, UV_map uv)
{
  Run r;
  const Clock::time_point start = Clock::now();
  r.status = SMP::parameterize(mesh, parameterizer, bhd, uv);
  r.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return r;
}

template <class Ours>
Run time_ours(Mesh& mesh, halfedge_descriptor bhd, UV_map uv)
{
  Ours ours;
  Run r = time_parameterize(mesh, ours, bhd, uv);  // copies share the report
  const typename Ours::Report& report = ours.last_report();
  r.is_ours = true;
  r.stages.preparation = report.preparation_seconds;
  r.stages.center = report.center_seconds;
  r.stages.distance = report.distance_seconds;
  r.stages.border_map = report.border_map_seconds;
  r.stages.interior = report.interior_seconds;
  r.stages.repair = report.repair_seconds;
  r.stages.output = report.output_seconds;
  r.stages.total = report.total_seconds;
  r.stages.factorizations = report.statistics.factorization_seconds;
  r.repair.flips_before = report.flipped_faces_before_repair;
  r.repair.repaired = report.repaired;
  r.repair.blend = report.blend;
  r.repair.mean_value_interior = report.mean_value_interior;
  return r;
}

Run run_method(int m, Mesh& mesh, halfedge_descriptor bhd, UV_map uv)
{
  switch(m)
  {
  case OURS_LDLT:        return time_ours<Ours_ldlt_parallel>(mesh, bhd, uv);
  case OURS_LDLT_SEQ:    return time_ours<Ours_ldlt>(mesh, bhd, uv);
#ifdef MBP_WITH_CHOLMOD
  case OURS_CHOLMOD:     return time_ours<Ours_cholmod_parallel>(mesh, bhd, uv);
  case OURS_CHOLMOD_SEQ: return time_ours<Ours_cholmod>(mesh, bhd, uv);
#endif
  case CGAL_DCP:  { Cgal_dcp p;  return time_parameterize(mesh, p, bhd, uv); }
  case CGAL_LSCM: { Cgal_lscm p; return time_parameterize(mesh, p, bhd, uv); }
  case CGAL_MVC:  { Cgal_mvc p;  return time_parameterize(mesh, p, bhd, uv); }
  default: break;
  }
  Run r;
  r.status = SMP::ERROR_WRONG_PARAMETER;
  return r;
}

// ---------------------------------------------------------------------------------------
// Floor: one analyze + factorize of L_II

enum Solver { LDLT, CHOLMOD, NUMBER_OF_SOLVERS };

bool solver_available(int s)
{
#ifdef MBP_WITH_CHOLMOD
  (void)s;
  return true;
#else
  return s == LDLT;
#endif
}

// The interior cotangent Laplacian, as the package assembles it.
bool interior_cotangent_laplacian(const Mesh& mesh, halfedge_descriptor bhd, Eigen::SparseMatrix<double>& A)
{
  SMP::Parameterization_patch_3<Mesh> patch;
  if(patch.build_disk(mesh, bhd, get(CGAL::vertex_point, mesh)) != SMP::OK)
    return false;
  std::vector<int> unknown(patch.number_of_vertices());
  for(std::size_t i = 0; i < unknown.size(); ++i)
    unknown[i] = patch.interior_index(i);
  patch.pattern().assemble(patch.faces_indices(), unknown, static_cast<int>(patch.interior_vertices().size()),
                           SMP::internal::Cotangent_weight{&patch.half_cotangents()}, A);
  return true;
}

// Seconds of one analyzePattern() + factorize(), or a negative value on failure.
double time_factorization(int s, const Eigen::SparseMatrix<double>& A)
{
  if(s == LDLT)
  {
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double> > ldlt;
    const Clock::time_point start = Clock::now();
    ldlt.analyzePattern(A);
    ldlt.factorize(A);
    const double t = std::chrono::duration<double>(Clock::now() - start).count();
    return ldlt.info() == Eigen::Success ? t : -1.;
  }
#ifdef MBP_WITH_CHOLMOD
  SMP::Cholmod_supernodal_cholesky_traits traits;  // CholmodSupernodalLLT, AMD, nmethods = 1
  auto& llt = traits.solver();
  const Clock::time_point start = Clock::now();
  llt.analyzePattern(A);
  llt.factorize(A);
  const double t = std::chrono::duration<double>(Clock::now() - start).count();
  return llt.info() == Eigen::Success ? t : -1.;
#else
  return -1.;
#endif
}

// ---------------------------------------------------------------------------------------
// Peak memory, in a child process

long status_kb(const char* key)  // a "Vm...:  N kB" line of /proc/self/status
{
  std::ifstream in("/proc/self/status");
  std::string line;
  const std::size_t n = std::strlen(key);
  while(std::getline(in, line))
    if(line.compare(0, n, key) == 0 && line.size() > n && line[n] == ':')
      return std::atol(line.c_str() + n + 1);
  return -1;
}

bool reset_peak_rss()
{
  std::ofstream out("/proc/self/clear_refs");
  out << "5";
  out.flush();
  return bool(out);
}

struct Child_result  // trivially copyable: travels through a pipe
{
  bool finished = false;   // the child reported back
  bool timed_out = false;  // killed after the cap
  bool peak_reset = false; // VmHWM could be reset, so peak_kb - base_kb is meaningful
  SMP::Error_code status = SMP::OK;
  double seconds = 0.;
  long base_kb = 0, peak_kb = 0;
  bool has_quality = false;
  SMP::Parameterization_quality quality;
};
static_assert(std::is_trivially_copyable<Child_result>::value, "sent through a pipe");

// A small disk (a triangulated grid, slightly bent) to run each method on first.
struct Warm_up
{
  Mesh mesh;
  halfedge_descriptor bhd;
  UV_map uv;

  Warm_up()
  {
    const int n = 12;
    std::vector<vertex_descriptor> v;
    for(int j = 0; j <= n; ++j)
      for(int i = 0; i <= n; ++i)
      {
        const double x = double(i) / n, y = double(j) / n;
        v.push_back(mesh.add_vertex(K::Point_3(x, y, 0.2 * x * x - 0.1 * y * y)));
      }
    auto at = [&](int i, int j) { return v[static_cast<std::size_t>(j * (n + 1) + i)]; };
    for(int j = 0; j < n; ++j)
      for(int i = 0; i < n; ++i)
      {
        mesh.add_face(at(i, j), at(i + 1, j), at(i + 1, j + 1));
        mesh.add_face(at(i, j), at(i + 1, j + 1), at(i, j + 1));
      }
    bhd = CGAL::Polygon_mesh_processing::longest_border(mesh).first;
    uv = mesh.add_property_map<vertex_descriptor, K::Point_2>("v:bench_uv").first;
  }
};

bool write_all(int fd, const void* data, std::size_t size)
{
  const char* p = static_cast<const char*>(data);
  while(size > 0)
  {
    const ssize_t w = ::write(fd, p, size);
    if(w < 0 && errno == EINTR)
      continue;
    if(w <= 0)
      return false;
    p += w;
    size -= static_cast<std::size_t>(w);
  }
  return true;
}

// Where a child process gets its mesh: a file, refined `levels` times by midpoint subdivision.
struct Mesh_source
{
  std::string path;
  int levels = 0;
};

// Runs method m once in a child process (see the top of the file), with its distortion when
// `with_quality`. `cap_seconds` > 0: the child is killed after that long. The child is this
// program run again (fork() and exec()): a fork() alone would inherit the state of the
// threading runtimes (OpenMP in CHOLMOD, OpenBLAS), which do not survive it.
Child_result run_in_child(int m, const Mesh_source& source, bool with_quality, double cap_seconds)
{
  Child_result result;
  int fds[2];
  if(::pipe(fds) != 0)
    return result;
  const std::string method = std::to_string(m), levels = std::to_string(source.levels),
                    quality = with_quality ? "1" : "0", fd = std::to_string(fds[1]);
  std::vector<char*> args;
  for(const std::string* a : {&method, &source.path, &levels, &quality, &fd})
    args.push_back(const_cast<char*>(a->c_str()));
  char child_flag[] = "--child";
  args.insert(args.begin(), child_flag);
  char self[] = "/proc/self/exe";
  args.insert(args.begin(), self);
  args.push_back(nullptr);

  std::fflush(stdout);
  std::fflush(stderr);
  const pid_t pid = ::fork();
  if(pid < 0)
  {
    ::close(fds[0]);
    ::close(fds[1]);
    return result;
  }
  if(pid == 0)
  {
    ::close(fds[0]);
    ::execv(self, args.data());
    ::_exit(127);
  }

  ::close(fds[1]);
  const Clock::time_point deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                                      std::chrono::duration<double>(cap_seconds));
  char* p = reinterpret_cast<char*>(&result);
  std::size_t got = 0;
  bool killed = false;
  while(got < sizeof(result))
  {
    int timeout_ms = -1;
    if(cap_seconds > 0.)
    {
      const double left = std::chrono::duration<double>(deadline - Clock::now()).count();
      if(left <= 0.)
      {
        ::kill(pid, SIGKILL);
        killed = true;
        break;
      }
      timeout_ms = static_cast<int>(std::min(left * 1000. + 1., 60000.));
    }
    pollfd pfd{fds[0], POLLIN, 0};
    const int ready = ::poll(&pfd, 1, timeout_ms);
    if(ready < 0 && errno == EINTR)
      continue;
    if(ready < 0)
      break;
    if(ready == 0)
      continue;
    const ssize_t r = ::read(fds[0], p + got, sizeof(result) - got);
    if(r < 0 && errno == EINTR)
      continue;
    if(r <= 0)
      break;  // the child died without reporting
    got += static_cast<std::size_t>(r);
  }
  ::close(fds[0]);
  int wstatus = 0;
  while(::waitpid(pid, &wstatus, 0) < 0 && errno == EINTR) { }
  if(got < sizeof(result))
  {
    result = Child_result();
    result.timed_out = killed;
  }
  return result;
}

// ---------------------------------------------------------------------------------------
// Load from other processes (the machine may be shared while the benchmark runs)

struct Cpu_sample
{
  double busy = 0.;  // jiffies the whole machine spent busy
  double own = 0.;   // jiffies of this process and its finished children
  Clock::time_point time = Clock::now();
};

Cpu_sample sample_cpu()
{
  Cpu_sample c;
  {
    std::ifstream in("/proc/stat");
    std::string cpu;
    double user = 0., nice = 0., system = 0., idle = 0., iowait = 0., irq = 0., softirq = 0., steal = 0.;
    in >> cpu >> user >> nice >> system >> idle >> iowait >> irq >> softirq >> steal;
    c.busy = user + nice + system + irq + softirq + steal;
  }
  {
    std::ifstream in("/proc/self/stat");
    std::string line;
    std::getline(in, line);
    const std::size_t close = line.rfind(')');
    if(close != std::string::npos)
    {
      std::istringstream fields(line.substr(close + 2));  // from field 3 (state) on
      std::string field;
      double times[4] = {0., 0., 0., 0.};
      for(int k = 3; k <= 17 && fields >> field; ++k)
        if(k >= 14)
          times[k - 14] = std::atof(field.c_str());  // utime stime cutime cstime
      c.own = times[0] + times[1] + times[2] + times[3];
    }
  }
  c.time = Clock::now();
  return c;
}

// Share of the machine's cores that other processes kept busy between two samples.
double other_load(const Cpu_sample& a, const Cpu_sample& b)
{
  const double seconds = std::chrono::duration<double>(b.time - a.time).count();
  const double ticks = double(::sysconf(_SC_CLK_TCK)), cores = double(::sysconf(_SC_NPROCESSORS_ONLN));
  if(!(seconds > 0.) || !(ticks > 0.) || !(cores > 0.))
    return std::numeric_limits<double>::quiet_NaN();
  return (std::max)(0., ((b.busy - a.busy) - (b.own - a.own)) / (ticks * seconds * cores));
}

// ---------------------------------------------------------------------------------------
// Meshes

using mbp_benchmark::not_a_disk;

using mbp_benchmark::midpoint_subdivision;

// ---------------------------------------------------------------------------------------
// Measurements of one mesh

double median(std::vector<double> v)
{
  if(v.empty())
    return std::numeric_limits<double>::quiet_NaN();
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return (n % 2 == 1) ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

struct Method_result
{
  bool planned = false;        // measured in this run
  bool timed_in_child = false; // one run in a capped child instead of N runs here
  SMP::Error_code status = SMP::OK;
  std::vector<double> seconds;
  bool has_quality = false;
  SMP::Parameterization_quality quality;
  std::vector<Stages> stages;
  bool has_repair_info = false;
  Repair_info repair;          // of the first run
  Child_result memory;         // the child run (memory, and time when timed_in_child)

  bool ok() const { return planned && status == SMP::OK && !seconds.empty(); }
  double time() const { return median(seconds); }
  bool has_memory() const { return memory.finished && memory.peak_reset && memory.status == SMP::OK; }
  double memory_mb() const { return double(memory.peak_kb - memory.base_kb) / 1024.; }
};

struct Mesh_result
{
  std::string name;
  std::size_t V = 0, F = 0;
  std::array<Method_result, NUMBER_OF_METHODS> methods;
  std::array<std::vector<double>, NUMBER_OF_SOLVERS> floors;
  bool floor_failed[NUMBER_OF_SOLVERS] = {false, false};
  double other_load = std::numeric_limits<double>::quiet_NaN();  // during the timed runs

  double floor(int s) const { return floors[s].empty() ? std::numeric_limits<double>::quiet_NaN() : median(floors[s]); }
};

struct Plan
{
  std::vector<int> timed;          // N runs here, interleaved
  std::vector<int> timed_in_child; // one capped run in a child (time, memory, distortion)
  bool memory = true;              // a child run of every timed method for its memory
  int runs = 5;
  double cap_seconds = 0.;
};

Mesh_result measure_mesh(const std::string& name, Mesh& mesh, const Mesh_source& source, const Plan& plan)
{
  Mesh_result res;
  res.name = name;
  res.V = num_vertices(mesh);
  res.F = num_faces(mesh);
  const halfedge_descriptor bhd = CGAL::Polygon_mesh_processing::longest_border(mesh).first;
  UV_map uv = mesh.add_property_map<vertex_descriptor, K::Point_2>("v:bench_uv").first;

  // Child runs (memory; time and distortion of the capped method).
  for(int m : plan.timed_in_child)
  {
    std::cerr << "  " << name << ": " << method_name(m) << " (one run in a child, cap "
              << plan.cap_seconds << " s)" << std::endl;
    Method_result& mr = res.methods[m];
    mr.planned = true;
    mr.timed_in_child = true;
    mr.memory = run_in_child(m, source, true, plan.cap_seconds);
    if(mr.memory.finished)
    {
      mr.status = mr.memory.status;
      mr.seconds.push_back(mr.memory.seconds);
      mr.has_quality = mr.memory.has_quality;
      mr.quality = mr.memory.quality;
    }
    else
      mr.status = SMP::ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;  // killed (cap) or crashed
  }
  if(plan.memory)
    for(int m : plan.timed)
      res.methods[m].memory = run_in_child(m, source, false, 0.);

  Eigen::SparseMatrix<double> A;
  const bool have_laplacian = interior_cotangent_laplacian(mesh, bhd, A);

  const Cpu_sample before = sample_cpu();
  for(int r = 0; r < plan.runs; ++r)
  {
    for(int m : plan.timed)
    {
      Method_result& mr = res.methods[m];
      if(r > 0 && mr.status != SMP::OK)
        continue;
      mr.planned = true;
      const Run run = run_method(m, mesh, bhd, uv);
      if(r == 0)
        mr.status = run.status;
      if(run.status != SMP::OK)
      {
        mr.status = run.status;
        continue;
      }
      mr.seconds.push_back(run.seconds);
      if(run.is_ours)
        mr.stages.push_back(run.stages);
      if(run.is_ours && !mr.has_repair_info)
      {
        mr.repair = run.repair;
        mr.has_repair_info = true;
      }
      if(!mr.has_quality)
      {
        mr.quality = SMP::measure_quality(mesh, faces(mesh), uv);
        mr.has_quality = true;
      }
    }
    for(int s = 0; s < NUMBER_OF_SOLVERS; ++s)
    {
      if(!solver_available(s) || !have_laplacian || res.floor_failed[s])
        continue;
      const double t = time_factorization(s, A);
      if(t < 0.)
        res.floor_failed[s] = true;
      else
        res.floors[s].push_back(t);
    }
  }
  res.other_load = other_load(before, sample_cpu());
  mesh.remove_property_map(uv);
  return res;
}

// ---------------------------------------------------------------------------------------
// Printing

std::string fmt(const char* format, double x)
{
  if(std::isnan(x))
    return "-";
  char buf[64];
  std::snprintf(buf, sizeof(buf), format, x);
  return buf;
}

std::string seconds_cell(double s)
{
  if(std::isnan(s))
    return "-";
  return fmt(s < 100. ? "%.4f" : "%.1f", s);
}

std::string time_cell(const Method_result& mr)
{
  if(!mr.planned)
    return "-";
  if(mr.timed_in_child && mr.memory.timed_out)
    return "> cap";
  if(mr.timed_in_child && !mr.memory.finished)
    return "child failed";
  if(!mr.ok())
    return std::string("failed: ") + SMP::get_measured_error_message(mr.status);
  return seconds_cell(mr.time()) + (mr.timed_in_child ? " (1 run)" : "");
}

double ratio(double a, double b)
{
  return (std::isnan(a) || std::isnan(b) || !(b > 0.)) ? std::numeric_limits<double>::quiet_NaN() : a / b;
}

double time_of(const Mesh_result& r, int m)
{
  return r.methods[m].ok() ? r.methods[m].time() : std::numeric_limits<double>::quiet_NaN();
}

double memory_of(const Mesh_result& r, int m)
{
  return r.methods[m].has_memory() ? r.methods[m].memory_mb() : std::numeric_limits<double>::quiet_NaN();
}

std::string memory_cell(const Method_result& mr)
{
  if(!mr.planned)
    return "-";
  if(mr.memory.timed_out)
    return "> cap";
  if(!mr.memory.finished)
    return "-";
  if(!mr.memory.peak_reset)
    return "n/a";
  return fmt("%.1f", mr.memory_mb());
}

std::string quality_cells(const Method_result& mr)
{
  if(!mr.has_quality)
    return " - | - |";
  return " " + fmt("%.4f", mr.quality.angle_distortion) + " | " + fmt("%.4f", mr.quality.l2_stretch) + " |";
}

std::string repair_cell(const Method_result& mr)
{
  if(!mr.has_repair_info)
    return "-";
  if(!mr.repair.repaired)
    return "no";
  return "blend " + fmt("%.3f", mr.repair.blend) + (mr.repair.mean_value_interior ? ", MVC interior" : ", DCP interior");
}

// Largest relative difference of the angle distortion and L2 stretch among our configurations.
double ours_disagreement(const Mesh_result& r)
{
  const int ours[] = {OURS_LDLT, OURS_LDLT_SEQ, OURS_CHOLMOD, OURS_CHOLMOD_SEQ};
  double worst = 0.;
  const Method_result& ref = r.methods[OURS_LDLT];
  if(!ref.has_quality)
    return 0.;
  for(int m : ours)
  {
    const Method_result& mr = r.methods[m];
    if(!mr.has_quality)
      continue;
    worst = (std::max)(worst, std::abs(mr.quality.angle_distortion - ref.quality.angle_distortion) /
                                (std::max)(ref.quality.angle_distortion, 1e-300));
    worst = (std::max)(worst, std::abs(mr.quality.l2_stretch - ref.quality.l2_stretch) / ref.quality.l2_stretch);
  }
  return worst;
}

void print_quality_table(const std::vector<Mesh_result>& results, bool with_lscm_mvc)
{
  std::printf("\n### Distortion\n\n");
  std::printf("| mesh | V | F | ours: angle dist. | ours: L2 | ours: flips | ours: flips before repair | ours: repair |"
              " DCP: angle dist. | DCP: L2 | DCP: flips |");
  if(with_lscm_mvc)
    std::printf(" LSCM: angle dist. | LSCM: L2 | MVC: angle dist. | MVC: L2 |");
  std::printf("\n|---|---|---|---|---|---|---|---|---|---|---|%s\n", with_lscm_mvc ? "---|---|---|---|" : "");
  double disagreement = 0.;
  for(const Mesh_result& r : results)
  {
    const Method_result& ours = r.methods[OURS_LDLT];
    const Method_result& dcp = r.methods[CGAL_DCP];
    std::printf("| %s | %zu | %zu |%s %s | %s | %s |%s %s |", r.name.c_str(), r.V, r.F, quality_cells(ours).c_str(),
                ours.has_quality ? std::to_string(ours.quality.flipped_faces).c_str() : "-",
                ours.has_repair_info ? std::to_string(ours.repair.flips_before).c_str() : "-",
                repair_cell(ours).c_str(), quality_cells(dcp).c_str(),
                dcp.has_quality ? std::to_string(dcp.quality.flipped_faces).c_str() : "-");
    if(with_lscm_mvc)
      std::printf("%s%s", quality_cells(r.methods[CGAL_LSCM]).c_str(), quality_cells(r.methods[CGAL_MVC]).c_str());
    std::printf("\n");
    disagreement = (std::max)(disagreement, ours_disagreement(r));
  }
  std::printf("\nours = Measured_conformal_parameterizer_3 (LDLT, concurrent), default repair; its other"
              " configurations give the same figures within a relative %.1e.\n", disagreement);
}

void print_time_table(const std::vector<Mesh_result>& results, bool with_lscm_mvc, int runs)
{
  std::printf("\n### Time (seconds, median of %d runs) and ratio to the single-factorization floor\n\n", runs);
  std::printf("| mesh | V | F | ours LDLT | floor LDLT | ratio | ours LDLT seq | ratio |"
              " ours CHOLMOD | floor CHOLMOD | ratio | ours CHOLMOD seq | ratio |"
              " CGAL DCP | DCP / ours LDLT | DCP / ours CHOLMOD |");
  if(with_lscm_mvc)
    std::printf(" CGAL LSCM | CGAL MVC |");
  std::printf(" other load |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|%s---|\n",
              with_lscm_mvc ? "---|---|" : "");
  for(const Mesh_result& r : results)
  {
    const double fl = r.floor(LDLT), fc = r.floor(CHOLMOD);
    std::printf("| %s | %zu | %zu | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |",
                r.name.c_str(), r.V, r.F,
                time_cell(r.methods[OURS_LDLT]).c_str(), seconds_cell(fl).c_str(),
                fmt("%.2f", ratio(time_of(r, OURS_LDLT), fl)).c_str(),
                time_cell(r.methods[OURS_LDLT_SEQ]).c_str(), fmt("%.2f", ratio(time_of(r, OURS_LDLT_SEQ), fl)).c_str(),
                time_cell(r.methods[OURS_CHOLMOD]).c_str(), seconds_cell(fc).c_str(),
                fmt("%.2f", ratio(time_of(r, OURS_CHOLMOD), fc)).c_str(),
                time_cell(r.methods[OURS_CHOLMOD_SEQ]).c_str(),
                fmt("%.2f", ratio(time_of(r, OURS_CHOLMOD_SEQ), fc)).c_str(),
                time_cell(r.methods[CGAL_DCP]).c_str(),
                fmt("%.1f", ratio(time_of(r, CGAL_DCP), time_of(r, OURS_LDLT))).c_str(),
                fmt("%.1f", ratio(time_of(r, CGAL_DCP), time_of(r, OURS_CHOLMOD))).c_str());
    if(with_lscm_mvc)
      std::printf(" %s | %s |", time_cell(r.methods[CGAL_LSCM]).c_str(), time_cell(r.methods[CGAL_MVC]).c_str());
    std::printf(" %s |\n", fmt("%.0f%%", 100. * r.other_load).c_str());
  }
}

void print_memory_table(const std::vector<Mesh_result>& results, bool with_lscm_mvc)
{
  std::printf("\n### Peak memory (MB above the starting resident set, one run in a child process)\n\n");
  std::printf("| mesh | V | ours LDLT | ours LDLT seq | ours CHOLMOD | ours CHOLMOD seq | CGAL DCP |");
  if(with_lscm_mvc)
    std::printf(" CGAL LSCM | CGAL MVC |");
  std::printf(" ours LDLT / DCP | ours CHOLMOD / DCP |\n|---|---|---|---|---|---|---|---|---|%s\n",
              with_lscm_mvc ? "---|---|" : "");
  for(const Mesh_result& r : results)
  {
    std::printf("| %s | %zu |", r.name.c_str(), r.V);
    for(int m : {OURS_LDLT, OURS_LDLT_SEQ, OURS_CHOLMOD, OURS_CHOLMOD_SEQ, CGAL_DCP})
      std::printf(" %s |", memory_cell(r.methods[m]).c_str());
    if(with_lscm_mvc)
      std::printf(" %s | %s |", memory_cell(r.methods[CGAL_LSCM]).c_str(), memory_cell(r.methods[CGAL_MVC]).c_str());
    std::printf(" %s | %s |\n", fmt("%.2f", ratio(memory_of(r, OURS_LDLT), memory_of(r, CGAL_DCP))).c_str(),
                fmt("%.2f", ratio(memory_of(r, OURS_CHOLMOD), memory_of(r, CGAL_DCP))).c_str());
  }
}

void print_stage_table(const std::vector<Mesh_result>& results)
{
  std::printf("\n### Where our time goes (seconds, median per stage; Report of Measured_conformal_parameterizer_3)\n\n");
  std::printf("| mesh | V | config | prep. | center (L_II + spring fact. + center solve) | distance | border map |"
              " interior | check + repair | output | call total | sum of factorizations | SMP::parameterize |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for(const Mesh_result& r : results)
    for(int m : {OURS_LDLT, OURS_LDLT_SEQ, OURS_CHOLMOD, OURS_CHOLMOD_SEQ})
    {
      const Method_result& mr = r.methods[m];
      if(!mr.ok() || mr.stages.empty())
        continue;
      auto med = [&](double Stages::*field) {
        std::vector<double> v;
        for(const Stages& s : mr.stages)
          v.push_back(s.*field);
        return seconds_cell(median(v));
      };
      std::printf("| %s | %zu | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", r.name.c_str(), r.V,
                  method_name(m), med(&Stages::preparation).c_str(), med(&Stages::center).c_str(),
                  med(&Stages::distance).c_str(), med(&Stages::border_map).c_str(), med(&Stages::interior).c_str(),
                  med(&Stages::repair).c_str(), med(&Stages::output).c_str(), med(&Stages::total).c_str(), med(&Stages::factorizations).c_str(),
                  seconds_cell(mr.time()).c_str());
    }
}

// ---------------------------------------------------------------------------------------
// Targets of the issue, on this run's numbers

const char* verdict(bool met, bool any) { return !any ? "not evaluated" : (met ? "MET" : "NOT MET"); }

void print_floor_target(const std::vector<Mesh_result>& results, int m, int s)
{
  bool any = false, met = true;
  double worst = 0.;
  std::string where;
  for(const Mesh_result& r : results)
  {
    if(r.V < 5000)
      continue;
    const double q = ratio(time_of(r, m), r.floor(s));
    if(std::isnan(q))
      continue;
    any = true;
    if(q > worst) { worst = q; where = r.name; }
    met = met && q <= 2.5;
  }
  std::printf("- time <= 2.5x floor on meshes of >= 5k vertices, %s: %s", method_name(m), verdict(met, any));
  if(any)
    std::printf(" (worst %.2fx, %s)", worst, where.c_str());
  std::printf("\n");
}

void print_dcp_target(const std::vector<Mesh_result>& results, int m)
{
  bool any = false, met = true;
  double worst = std::numeric_limits<double>::infinity();
  std::string where;
  for(const Mesh_result& r : results)
  {
    if(r.V < 30000)
      continue;
    const double q = ratio(time_of(r, CGAL_DCP), time_of(r, m));
    if(std::isnan(q))
      continue;
    any = true;
    if(q < worst) { worst = q; where = r.name; }
    met = met && q >= 5.;
  }
  std::printf("- >= 5x faster than CGAL DCP (default solver) on meshes of >= 30k vertices, %s: %s", method_name(m),
              verdict(met, any));
  if(any)
    std::printf(" (least %.1fx, %s)", worst, where.c_str());
  std::printf("\n");
}

void print_memory_target(const std::vector<Mesh_result>& results, int m, std::size_t min_vertices)
{
  bool any = false, met = true;
  double worst = 0.;
  std::string where;
  for(const Mesh_result& r : results)
  {
    const double q = ratio(memory_of(r, m), memory_of(r, CGAL_DCP));
    if(r.V < min_vertices || std::isnan(q))
      continue;
    any = true;
    if(q > worst) { worst = q; where = r.name; }
    met = met && q <= 1.5;
  }
  std::printf("- peak memory <= 1.5x CGAL DCP's, meshes of >= %zu vertices, %s: %s", min_vertices, method_name(m),
              verdict(met, any));
  if(any)
    std::printf(" (worst %.2fx, %s)", worst, where.c_str());
  std::printf("\n");
}

void print_targets(const std::vector<Mesh_result>& results, bool scale)
{
  std::printf("\n### Targets (this run)\n\n");
  for(int m : {OURS_LDLT, OURS_CHOLMOD, OURS_LDLT_SEQ, OURS_CHOLMOD_SEQ})
    if(method_available(m))
      print_floor_target(results, m, (m == OURS_LDLT || m == OURS_LDLT_SEQ) ? LDLT : CHOLMOD);
  for(int m : {OURS_LDLT, OURS_CHOLMOD})
    if(method_available(m))
      print_dcp_target(results, m);
  if(scale)
    for(int m : {OURS_CHOLMOD, OURS_CHOLMOD_SEQ})
    {
      if(!method_available(m))
        continue;
      bool any = false, met = true;
      for(const Mesh_result& r : results)
        if(r.V >= 600000 && r.methods[m].ok())
        {
          any = true;
          met = met && r.methods[m].time() <= 10.;
          std::printf("- %zu-vertex mesh in <= 10 s, %s: %s (%.2f s)\n", r.V, method_name(m),
                      verdict(r.methods[m].time() <= 10., true), r.methods[m].time());
        }
      if(!any)
        std::printf("- 700k-vertex mesh in <= 10 s, %s: not evaluated\n", method_name(m));
    }
  for(std::size_t min_vertices : {std::size_t(0), std::size_t(5000)})
    for(int m : {OURS_LDLT, OURS_CHOLMOD})
      if(method_available(m))
        print_memory_target(results, m, min_vertices);
}

// ---------------------------------------------------------------------------------------

// The child process of run_in_child(): argv = --child METHOD MESH_FILE LEVELS QUALITY FD.
int child_main(char** argv)
{
  Child_result r;
  const int m = std::atoi(argv[2]);
  const int levels = std::atoi(argv[4]);
  const bool with_quality = std::atoi(argv[5]) != 0;
  const int fd = std::atoi(argv[6]);

  Mesh mesh;
  if(m < 0 || m >= NUMBER_OF_METHODS || !method_available(m) || !CGAL::IO::read_polygon_mesh(argv[3], mesh))
    return 1;
  for(int level = 0; level < levels; ++level)
  {
    Mesh refined;
    if(!midpoint_subdivision(mesh, refined))
      return 1;
    mesh = std::move(refined);
  }
  const halfedge_descriptor bhd = CGAL::Polygon_mesh_processing::longest_border(mesh).first;
  UV_map uv = mesh.add_property_map<vertex_descriptor, K::Point_2>("v:bench_uv").first;

  {
    Warm_up warm_up;
    run_method(m, warm_up.mesh, warm_up.bhd, warm_up.uv);
  }
  ::malloc_trim(0);
  r.peak_reset = reset_peak_rss();
  r.base_kb = status_kb("VmRSS");
  const Run run = run_method(m, mesh, bhd, uv);
  r.peak_kb = status_kb("VmHWM");
  r.status = run.status;
  r.seconds = run.seconds;
  if(with_quality && run.status == SMP::OK)
  {
    r.quality = SMP::measure_quality(mesh, faces(mesh), uv);
    r.has_quality = true;
  }
  r.finished = true;
  return write_all(fd, &r, sizeof(r)) ? 0 : 1;
}

int usage(const char* program)
{
  std::cerr << "usage: " << program
            << " [--runs N] [--mesh NAME]... [--no-memory] [--scale [--scale-mesh FILE] [--levels L]"
               " [--first-level K] [--dcp-cap SECONDS]] [MESH_DIR]\n";
  return 2;
}

} // namespace

int main(int argc, char** argv)
{
  if(argc == 7 && std::string(argv[1]) == "--child")
    return child_main(argv);
  std::string dir = MBP_MESH_DIR;
  std::string scale_mesh;
  std::vector<std::string> only;
  Plan plan;
  bool scale = false;
  int levels = 2, first_level = 1;
  double dcp_cap = 900.;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    const bool has_value = i + 1 < argc;
    if(a == "--runs" && has_value)            plan.runs = std::atoi(argv[++i]);
    else if(a == "--mesh" && has_value)       only.push_back(argv[++i]);
    else if(a == "--no-memory")               plan.memory = false;
    else if(a == "--scale")                   scale = true;
    else if(a == "--scale-mesh" && has_value) scale_mesh = argv[++i];
    else if(a == "--levels" && has_value)     levels = std::atoi(argv[++i]);
    else if(a == "--first-level" && has_value) first_level = std::atoi(argv[++i]);
    else if(a == "--dcp-cap" && has_value)    dcp_cap = std::atof(argv[++i]);
    else if(!a.empty() && a[0] == '-')        return usage(argv[0]);
    else                                      dir = a;
  }
  if(plan.runs < 1 || levels < 1 || first_level < 1 || first_level > levels || !(dcp_cap > 0.))
    return usage(argv[0]);
  if(plan.runs < 5)
    std::cerr << "note: fewer than 5 runs per method\n";

  std::vector<Mesh_result> results;
  std::vector<std::string> skipped;

  if(scale)
  {
    if(scale_mesh.empty())
      scale_mesh = (std::filesystem::path(dir) / "bimba_i.obj").string();
    Mesh mesh;
    if(!CGAL::IO::read_polygon_mesh(scale_mesh, mesh) || faces(mesh).empty() || !not_a_disk(mesh).empty())
    {
      std::cerr << "error: '" << scale_mesh << "' is not a readable disk mesh\n";
      return 1;
    }
    for(int m = OURS_LDLT; m <= OURS_CHOLMOD_SEQ; ++m)
      if(method_available(m))
        plan.timed.push_back(m);
    plan.timed_in_child.push_back(CGAL_DCP);
    plan.cap_seconds = dcp_cap;
    const std::string base = std::filesystem::path(scale_mesh).filename().string();
    for(int level = 1; level <= levels; ++level)
    {
      Mesh refined;
      if(!midpoint_subdivision(mesh, refined))
      {
        std::cerr << "error: subdivision failed\n";
        return 1;
      }
      mesh = std::move(refined);
      if(level < first_level)
        continue;
      const std::string name = base + " x" + std::to_string(level);
      std::cerr << name << ": V " << num_vertices(mesh) << ", F " << num_faces(mesh) << std::endl;
      results.push_back(measure_mesh(name, mesh, Mesh_source{scale_mesh, level}, plan));
    }
  }
  else
  {
    std::vector<std::filesystem::path> files;
    std::error_code ec;
    for(const auto& entry : std::filesystem::directory_iterator(dir, ec))
    {
      const std::string ext = entry.path().extension().string();
      const std::string file = entry.path().filename().string();
      if((ext == ".off" || ext == ".obj" || ext == ".ply" || ext == ".stl") &&
         (only.empty() || std::find(only.begin(), only.end(), file) != only.end()))
        files.push_back(entry.path());
    }
    if(ec || files.empty())
    {
      std::cerr << "error: no mesh in '" << dir << "'\n";
      return 1;
    }
    std::sort(files.begin(), files.end());
    for(int m = 0; m < NUMBER_OF_METHODS; ++m)
      if(method_available(m))
        plan.timed.push_back(m);
    for(const auto& path : files)
    {
      const std::string name = path.filename().string();
      Mesh mesh;
      if(!CGAL::IO::read_polygon_mesh(path.string(), mesh) || faces(mesh).empty())
      {
        skipped.push_back(name + " (not readable as a polygon mesh)");
        continue;
      }
      const std::string why = not_a_disk(mesh);
      if(!why.empty())
      {
        skipped.push_back(name + " (" + why + ")");
        continue;
      }
      std::cerr << name << ": V " << num_vertices(mesh) << ", F " << num_faces(mesh) << std::endl;
      results.push_back(measure_mesh(name, mesh, Mesh_source{path.string(), 0}, plan));
    }
  }

#ifdef MBP_WITH_CHOLMOD
  std::printf("Solvers: Eigen SimplicialLDLT; CHOLMOD supernodal (AMD)\n");
#else
  std::printf("Solvers: Eigen SimplicialLDLT (built without CHOLMOD: its columns are empty)\n");
#endif
  print_time_table(results, !scale, plan.runs);
  if(scale)
    std::printf("\nCGAL DCP: one run in a child process, killed after %.0f s (\"> cap\").\n", dcp_cap);
  if(plan.memory || scale)
    print_memory_table(results, !scale);
  print_quality_table(results, !scale);
  print_stage_table(results);
  print_targets(results, scale);
  if(!skipped.empty())
  {
    std::printf("\nSkipped (not disks):");
    for(const std::string& s : skipped)
      std::printf(" %s;", s.c_str());
    std::printf("\n");
  }
  return 0;
}
