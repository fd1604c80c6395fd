// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// Time, peak memory and distortion of this package's Measured_conformal_parameterizer_3
// against CGAL's parameterizers, on every disk mesh of a directory (the paper's Tables 1 and
// 3), with the cost of one factorization as a floor; and a scale mode up to 2 million
// vertices, in-process and whole process (the command-line program against Boundary First
// Flattening's).
//
//   method_comparison [options] [MESH_DIR]   (default MESH_DIR: the project's meshes, as configured)
//
//   --runs N        timed runs per method and mesh (default 5); the median is reported
//   --mesh NAME     only this file of MESH_DIR (repeatable), e.g. to rerun a noisy row
//   --no-memory     skip the peak memory measurement
//   --scale         scale mode (see below)
//   --scale-case F:K[,K...]  scale mode: the mesh F (a path, or a file of MESH_DIR) refined K
//                   times by 1-to-4 midpoint subdivision, for each K (repeatable; default
//                   bimba_i.obj:0,1,2 and mask.off:3: 44.8k, 179k, 714k and 2.0M vertices)
//   --large-runs N  scale mode: timed runs at 1M vertices or more (default 3)
//   --dcp-cap S     scale mode: CGAL's DCP runs once, in a child process killed after S
//                   seconds (default 600; 0: no DCP)
//   --cli PATH      scale mode, whole process: the command-line program (default, as
//                   configured: the build's cli/measured_parameterization); none: skip
//   --bff PATH      scale mode, whole process: Boundary First Flattening's command line
//                   (default, as configured: ../shared/peers/bff-command-line); none: skip
//   --whole-runs N  scale mode: whole-process runs of each program (default 3, interleaved)
//   --work DIR      scale mode: where the refined meshes are written as OBJ files for the
//                   whole-process runs, with the programs' outputs (default /tmp/mbp-scale)
//
// Methods (all through SMP::parameterize(mesh, parameterizer, longest border, uv map)):
//   auto LDLT      the library's default path with the automatic border, as the command
//                  line runs it: Conformal_parameterizer_3<Mesh, Automatic_border<
//                  Poisson_center_locator, Geodesic_border_distance<Fast_marching_geodesics> >,
//                  Solver>, Sequential_tag, default repair; Solver =
//                  Default_sparse_cholesky_traits (Eigen's SimplicialLDLT)
//   auto CHOLMOD   the same with Cholmod_supernodal_cholesky_traits (AMD), when built with
//                  CHOLMOD (MBP_WITH_CHOLMOD)
//   MBPPP LDLT,    the paper's method: Measured_conformal_parameterizer_3 with its default
//   MBPPP CHOLMOD  policies (Poisson center, Poisson distances), i.e. the border policy
//                  Measured_border<> (two factorizations: L_II and the spring Laplacian); the
//                  scale mode runs the
//                  CHOLMOD one only
//   DCP            CGAL's Discrete_conformal_map_parameterizer_3, defaults (circular
//                  arc-length border, BiCGSTAB + IncompleteLUT); in the scale mode once, in a
//                  capped child process
//   LSCM, MVC      CGAL's LSCM_parameterizer_3 and Mean_value_coordinates_parameterizer_3,
//                  defaults (not in the scale mode)
//
// Time: wall-clock seconds of the SMP::parameterize() call (ours with its report; reading the mesh, the quality
// measure and printing are outside), median of N runs. The runs are interleaved (run 1 of
// every method and of the floors, then run 2, ...) so that load from other processes spreads
// over all of them. Each row prints the 1-minute load average (/proc/loadavg) at its start and
// "other load": the share of the machine's cores that other processes kept busy during its
// timed runs (/proc/stat minus this process).
//
// Floor: one factorization of the interior cotangent Laplacian L_II (border eliminated) by
// the solver traits of the method: SolverTraits::factor(), i.e. Eigen's SimplicialLDLT
// compute() (analyzePattern + factorize), or Cholmod_supernodal_cholesky_traits (AMD:
// cholmod_analyze + cholmod_factorize). L_II is assembled once, outside the timing, with
// Eigen from the mesh, as the package assembles it (benchmark_support.h: cotangent weights,
// the package's vertex numbering, holes filled the same way). Any method that solves the
// discrete conformal map costs at least this. "ratio" = method time / floor time of its
// solver (medians).
//
// Peak memory (in-process): each method runs once more in a child process (this program,
// fork()ed and exec()ed with the hidden option --child), which reads the mesh, runs the
// method on a small grid (so that code pages and library buffers are in place), releases free
// heap memory (malloc_trim), resets its peak resident set size (/proc/self/clear_refs "5"),
// reads VmRSS, runs the method on the mesh and reads VmHWM. Reported: VmHWM - VmRSS, in MiB:
// what the call adds to a process that holds the mesh (the UV map included).
//
// Whole process (scale mode): each refined mesh is written once as an OBJ file (9
// significant digits, as scripts/refine_mesh.py writes), then the command-line program
// (defaults: automatic border, fast marching distances, CHOLMOD when built with it; --json)
// and BFF's command line (no option: its conformal map) run on it, interleaved, N times each.
// Each run is a child of a small intermediate process (this program exec()ed with --spawn,
// which fork()s and exec()s the program and wait4()s it): wall-clock seconds from fork() to
// the end of wait4(), and ru_maxrss, the peak resident set of the program (a child fork()ed
// directly from this large process would inherit its high-water mark). Medians reported.
// The stage times of our runs come from the program's --json (io_times.read, times.*,
// io_times.quality, io_times.write, statistics.factorizations).
//
// Distortion: SMP::measure_quality(), the paper's angle distortion (Sheffer-de Sturler,
// optimal angles, divided by |V|) and Sander's L2 stretch (1 = optimal).
//
// Meshes that are not a single disk are skipped with the reason. The program prints
// markdown tables on stdout and progress on stderr; it ends with the targets of issues 13 and
// 3, evaluated on the numbers of this run.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_conformal_map_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Mean_value_coordinates_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <CGAL/Surface_mesh_parameterization/Automatic_border.h>
#include <CGAL/Surface_mesh_parameterization/Conformal_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Default_sparse_cholesky_traits.h>
#include <CGAL/Surface_mesh_parameterization/Geodesic_border_distance.h>
#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_report.h>
#include <CGAL/Surface_mesh_parameterization/Poisson_border_distance.h>
#include <CGAL/Surface_mesh_parameterization/Poisson_center_locator.h>
#include <CGAL/Surface_mesh_parameterization/geodesic_method_tags.h>
#include <CGAL/Surface_mesh_parameterization/measure_quality.h>
#ifdef MBP_WITH_CHOLMOD
#include <CGAL/Surface_mesh_parameterization/Cholmod_supernodal_cholesky_traits.h>
#endif

#include <Eigen/Sparse>

#include <fcntl.h>
#include <malloc.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
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

#ifndef MBP_CLI_PROGRAM
#define MBP_CLI_PROGRAM ""
#endif
#ifndef MBP_BFF_PROGRAM
#define MBP_BFF_PROGRAM ""
#endif

namespace SMP = CGAL::Surface_mesh_parameterization;
typedef CGAL::Simple_cartesian<double>                          K;
typedef CGAL::Surface_mesh<K::Point_3>                          Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor            vertex_descriptor;
typedef boost::graph_traits<Mesh>::halfedge_descriptor          halfedge_descriptor;
typedef Mesh::Property_map<vertex_descriptor, K::Point_2>       UV_map;
typedef std::chrono::steady_clock                               Clock;

typedef SMP::Geodesic_border_distance<SMP::Fast_marching_geodesics>          Fast_marching_distance;
typedef SMP::Automatic_border<SMP::Poisson_center_locator, Fast_marching_distance> Automatic;
typedef SMP::Default_sparse_cholesky_traits                                   Ldlt_traits;
typedef SMP::Conformal_parameterizer_3<Mesh, Automatic, Ldlt_traits>          Auto_ldlt;
typedef SMP::Measured_conformal_parameterizer_3<Mesh>                         Mbppp_ldlt;
#ifdef MBP_WITH_CHOLMOD
typedef SMP::Cholmod_supernodal_cholesky_traits                               Cholmod_traits;
typedef SMP::Conformal_parameterizer_3<Mesh, Automatic, Cholmod_traits>       Auto_cholmod;
typedef SMP::Measured_conformal_parameterizer_3<Mesh, SMP::Poisson_center_locator, SMP::Poisson_border_distance,
                                                Cholmod_traits>               Mbppp_cholmod;
#endif
typedef SMP::Discrete_conformal_map_parameterizer_3<Mesh>       Cgal_dcp;
typedef SMP::LSCM_parameterizer_3<Mesh>                         Cgal_lscm;
typedef SMP::Mean_value_coordinates_parameterizer_3<Mesh>       Cgal_mvc;

namespace {

const double nan_value = std::numeric_limits<double>::quiet_NaN();

// ---------------------------------------------------------------------------------------
// Methods

enum Method { AUTO_LDLT, AUTO_CHOLMOD, MBPPP_LDLT, MBPPP_CHOLMOD, CGAL_DCP, CGAL_LSCM, CGAL_MVC,
              NUMBER_OF_METHODS };

enum Solver { LDLT, CHOLMOD, NUMBER_OF_SOLVERS };

const char* method_name(int m)
{
  static const char* names[NUMBER_OF_METHODS] = {"auto LDLT", "auto CHOLMOD", "MBPPP LDLT", "MBPPP CHOLMOD",
                                                 "CGAL DCP", "CGAL LSCM", "CGAL MVC"};
  return names[m];
}

bool is_ours(int m) { return m <= MBPPP_CHOLMOD; }

// The solver of our methods (its floor), -1 for CGAL's.
int solver_of(int m)
{
  if(m == AUTO_LDLT || m == MBPPP_LDLT)
    return LDLT;
  if(m == AUTO_CHOLMOD || m == MBPPP_CHOLMOD)
    return CHOLMOD;
  return -1;
}

bool solver_available(int s)
{
#ifdef MBP_WITH_CHOLMOD
  (void)s;
  return true;
#else
  return s == LDLT;
#endif
}

bool method_available(int m) { return solver_of(m) < 0 || solver_available(solver_of(m)); }

const char* solver_name(int s) { return s == LDLT ? "LDLT" : "CHOLMOD"; }

// Stage times and work of our parameterizer (its own report), seconds.
struct Stages
{
  double preparation = 0., conformal_border = 0., center = 0., distance = 0., border_map = 0., interior = 0.,
         repair = 0., output = 0., total = 0., factorization_seconds = 0.;
  int factorizations = 0, back_substitutions = 0;
};

// What our parameterizer kept (its report).
struct Choice_info
{
  int kept = -1;                 // Border_family: CIRCLE, MEASURED, CONFORMAL
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
  Choice_info choice;
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
  const Ours ours;
  SMP::Parameterization_report report;
  Run r;
  const Clock::time_point start = Clock::now();
  r.status = SMP::parameterize(mesh, ours, bhd, uv, &report);
  r.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  r.is_ours = true;
  r.stages.preparation = report.preparation_seconds;
  r.stages.conformal_border = report.conformal_border_seconds;
  r.stages.center = report.center_seconds;
  r.stages.distance = report.distance_seconds;
  r.stages.border_map = report.border_map_seconds;
  r.stages.interior = report.interior_seconds;
  r.stages.repair = report.repair_seconds;
  r.stages.output = report.output_seconds;
  r.stages.total = report.total_seconds;
  r.stages.factorization_seconds = report.statistics.factorization_seconds;
  r.stages.factorizations = report.statistics.factorizations;
  r.stages.back_substitutions = report.statistics.back_substitutions;
  r.choice.kept = static_cast<int>(report.kept_border);
  r.choice.flips_before = report.flipped_faces_before_repair;
  r.choice.repaired = report.repaired;
  r.choice.blend = report.blend;
  r.choice.mean_value_interior = report.mean_value_interior;
  return r;
}

Run run_method(int m, Mesh& mesh, halfedge_descriptor bhd, UV_map uv)
{
  switch(m)
  {
  case AUTO_LDLT:     return time_ours<Auto_ldlt>(mesh, bhd, uv);
  case MBPPP_LDLT:    return time_ours<Mbppp_ldlt>(mesh, bhd, uv);
#ifdef MBP_WITH_CHOLMOD
  case AUTO_CHOLMOD:  return time_ours<Auto_cholmod>(mesh, bhd, uv);
  case MBPPP_CHOLMOD: return time_ours<Mbppp_cholmod>(mesh, bhd, uv);
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
// Floor: one factorization of L_II by the solver traits

template <class Traits>
double time_traits_factor(const Eigen::SparseMatrix<double>& A)
{
  const typename Traits::Matrix M(A);  // copied outside the timing
  Traits traits;
  double D = 1.;
  const Clock::time_point start = Clock::now();
  const bool ok = traits.factor(M, D);
  const double t = std::chrono::duration<double>(Clock::now() - start).count();
  return ok ? t : -1.;
}

// Seconds of one factorization of A with solver s, or a negative value on failure.
double time_factorization(int s, const Eigen::SparseMatrix<double>& A)
{
  if(s == LDLT)
    return time_traits_factor<Ldlt_traits>(A);
#ifdef MBP_WITH_CHOLMOD
  return time_traits_factor<Cholmod_traits>(A);
#else
  return -1.;
#endif
}

// ---------------------------------------------------------------------------------------
// Child processes

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

// Runs this program again as `self flag FD args...` (fork() and exec(): a fork() alone would
// inherit the state of the threading runtimes, OpenMP in CHOLMOD and OpenBLAS, which do not
// survive it) and reads one T that it writes to the pipe FD. `cap_seconds` > 0: the child is
// killed after that long (`killed`). Returns whether a whole T arrived.
template <class T>
bool run_self(const char* flag, const std::vector<std::string>& args, double cap_seconds, T& result, bool& killed)
{
  static_assert(std::is_trivially_copyable<T>::value, "sent through a pipe");
  killed = false;
  int fds[2];
  if(::pipe(fds) != 0)
    return false;
  const std::string fd = std::to_string(fds[1]);
  std::vector<std::string> all = {"/proc/self/exe", flag, fd};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for(std::string& a : all)
    argv.push_back(&a[0]);
  argv.push_back(nullptr);

  std::fflush(stdout);
  std::fflush(stderr);
  const pid_t pid = ::fork();
  if(pid < 0)
  {
    ::close(fds[0]);
    ::close(fds[1]);
    return false;
  }
  if(pid == 0)
  {
    ::close(fds[0]);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }

  ::close(fds[1]);
  const Clock::time_point deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                                      std::chrono::duration<double>(cap_seconds));
  char* p = reinterpret_cast<char*>(&result);
  std::size_t got = 0;
  while(got < sizeof(T))
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
    const ssize_t r = ::read(fds[0], p + got, sizeof(T) - got);
    if(r < 0 && errno == EINTR)
      continue;
    if(r <= 0)
      break;  // the child died without reporting
    got += static_cast<std::size_t>(r);
  }
  ::close(fds[0]);
  int wstatus = 0;
  while(::waitpid(pid, &wstatus, 0) < 0 && errno == EINTR) { }
  return got == sizeof(T);
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

// Where a child process gets its mesh: a file, refined `levels` times by midpoint subdivision.
struct Mesh_source
{
  std::string path;
  int levels = 0;
};

// Runs method m once in a child process (see the top of the file), with its distortion when
// `with_quality`. `cap_seconds` > 0: the child is killed after that long.
Child_result run_in_child(int m, const Mesh_source& source, bool with_quality, double cap_seconds)
{
  Child_result result;
  bool killed = false;
  if(!run_self("--child", {std::to_string(m), source.path, std::to_string(source.levels), with_quality ? "1" : "0"},
               cap_seconds, result, killed))
  {
    result = Child_result();
    result.timed_out = killed;
  }
  return result;
}

// A program run as a whole process (through the --spawn intermediate).
struct Process_result  // trivially copyable: travels through a pipe
{
  bool ran = false;      // the intermediate reported back
  int exit_status = -1;  // -1: killed by a signal or not started
  double seconds = 0.;   // fork() to the end of wait4()
  long maxrss_kb = 0;    // ru_maxrss of the program
};

// Runs `program args...` with stdout to `out` and stderr to `err`.
Process_result run_process(const std::string& program, const std::vector<std::string>& args,
                           const std::string& out, const std::string& err)
{
  std::vector<std::string> all = {out, err, program};
  all.insert(all.end(), args.begin(), args.end());
  Process_result result;
  bool killed = false;
  if(!run_self("--spawn", all, 0., result, killed))
    result = Process_result();
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
    return nan_value;
  return (std::max)(0., ((b.busy - a.busy) - (b.own - a.own)) / (ticks * seconds * cores));
}

// The 1-minute load average.
double load_average()
{
  std::ifstream in("/proc/loadavg");
  double one = nan_value;
  in >> one;
  return in ? one : nan_value;
}

// ---------------------------------------------------------------------------------------
// Meshes

using mbp_benchmark::not_a_disk;
using mbp_benchmark::midpoint_subdivision;

// Writes the mesh as OBJ ('v' with 9 significant digits, as scripts/refine_mesh.py, and 'f').
bool write_obj_file(const Mesh& mesh, const std::string& path)
{
  std::FILE* f = std::fopen(path.c_str(), "w");
  if(f == nullptr)
    return false;
  std::vector<char> buffer(1 << 20);
  std::setvbuf(f, buffer.data(), _IOFBF, buffer.size());
  std::vector<std::size_t> index(mesh.number_of_vertices() + mesh.number_of_removed_vertices());
  std::size_t next = 1;
  for(vertex_descriptor v : vertices(mesh))
  {
    const K::Point_3& p = mesh.point(v);
    std::fprintf(f, "v %.9g %.9g %.9g\n", p.x(), p.y(), p.z());
    index[v.idx()] = next++;
  }
  for(auto fd : faces(mesh))
  {
    std::fputc('f', f);
    for(vertex_descriptor v : vertices_around_face(halfedge(fd, mesh), mesh))
      std::fprintf(f, " %zu", index[v.idx()]);
    std::fputc('\n', f);
  }
  const bool ok = std::ferror(f) == 0;
  return (std::fclose(f) == 0) && ok;
}

// ---------------------------------------------------------------------------------------
// Measurements of one mesh

double median(std::vector<double> v)
{
  v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return std::isnan(x); }), v.end());
  if(v.empty())
    return nan_value;
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
  bool has_choice = false;
  Choice_info choice;          // of the first run
  Child_result memory;         // the child run (memory, and time when timed_in_child)

  bool ok() const { return planned && status == SMP::OK && !seconds.empty(); }
  double time() const { return median(seconds); }
  bool has_memory() const { return memory.finished && memory.peak_reset && memory.status == SMP::OK; }
  double memory_mb() const { return double(memory.peak_kb - memory.base_kb) / 1024.; }
};

// The stage times of one run of the command-line program (its --json).
struct Cli_stages
{
  double read = nan_value, preparation = nan_value, conformal_border = nan_value, center = nan_value,
         distances = nan_value, border_map = nan_value, interior = nan_value, repair = nan_value,
         output = nan_value, total = nan_value, quality = nan_value, write = nan_value,
         factorizations = nan_value, factorization_seconds = nan_value;
  std::string solver, border, distance, kept;
};

struct Whole_process
{
  bool planned = false;
  std::vector<Process_result> ours, bff;
  std::vector<Cli_stages> ours_stages;
  std::string failure;  // of a run
  double load_before = nan_value, load_after = nan_value;

  static double median_seconds(const std::vector<Process_result>& v)
  {
    std::vector<double> s;
    for(const Process_result& p : v)
      if(p.ran && p.exit_status == 0)
        s.push_back(p.seconds);
    return median(s);
  }
  static double median_rss_mb(const std::vector<Process_result>& v)
  {
    std::vector<double> s;
    for(const Process_result& p : v)
      if(p.ran && p.exit_status == 0)
        s.push_back(double(p.maxrss_kb) / 1024.);
    return median(s);
  }
};

struct Mesh_result
{
  std::string name;
  std::size_t V = 0, F = 0;
  std::array<Method_result, NUMBER_OF_METHODS> methods;
  std::array<std::vector<double>, NUMBER_OF_SOLVERS> floors;
  bool floor_failed[NUMBER_OF_SOLVERS] = {false, false};
  double other_load = nan_value;  // during the timed runs
  double load_average = nan_value;  // 1-minute load average at the start of the row
  int runs = 0;
  Whole_process whole;

  double floor(int s) const { return floors[s].empty() ? nan_value : median(floors[s]); }
};

struct Plan
{
  std::vector<int> timed;          // N runs here, interleaved
  std::vector<int> timed_in_child; // one capped run in a child (time, memory, distortion)
  bool memory = true;              // a child run of every timed method for its memory
  int runs = 5;
  int large_runs = 3;              // runs at 1M vertices or more
  double cap_seconds = 0.;
  // whole process (scale mode)
  std::string cli, bff, work;
  int whole_runs = 3;
};

// The number after "key": inside the first flat object "object": {...} of a JSON text.
double json_number(const std::string& text, const std::string& object, const std::string& key)
{
  std::size_t at = 0;
  if(!object.empty())
  {
    at = text.find("\"" + object + "\"");
    if(at == std::string::npos)
      return nan_value;
  }
  const std::size_t end = object.empty() ? text.size() : text.find('}', at);
  const std::size_t k = text.find("\"" + key + "\"", at);
  if(k == std::string::npos || k > end)
    return nan_value;
  const std::size_t colon = text.find(':', k);
  if(colon == std::string::npos)
    return nan_value;
  char* stop = nullptr;
  const double x = std::strtod(text.c_str() + colon + 1, &stop);
  return stop == text.c_str() + colon + 1 ? nan_value : x;
}

std::string json_string(const std::string& text, const std::string& object, const std::string& key)
{
  std::size_t at = 0;
  if(!object.empty())
  {
    at = text.find("\"" + object + "\"");
    if(at == std::string::npos)
      return "";
  }
  const std::size_t k = text.find("\"" + key + "\"", at);
  if(k == std::string::npos)
    return "";
  const std::size_t open = text.find('"', text.find(':', k));
  const std::size_t close = open == std::string::npos ? open : text.find('"', open + 1);
  return close == std::string::npos ? "" : text.substr(open + 1, close - open - 1);
}

Cli_stages read_cli_json(const std::string& path)
{
  std::ifstream in(path);
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string t = buffer.str();
  Cli_stages s;
  s.read = json_number(t, "io_times", "read");
  s.quality = json_number(t, "io_times", "quality");
  s.write = json_number(t, "io_times", "write");
  s.preparation = json_number(t, "times", "preparation");
  s.conformal_border = json_number(t, "times", "conformal_border");
  s.center = json_number(t, "times", "center");
  s.distances = json_number(t, "times", "distances");
  s.border_map = json_number(t, "times", "border_map");
  s.interior = json_number(t, "times", "interior");
  s.output = json_number(t, "times", "output");
  s.total = json_number(t, "times", "total");
  s.repair = json_number(t, "repair", "seconds");
  s.factorizations = json_number(t, "statistics", "factorizations");
  s.factorization_seconds = json_number(t, "statistics", "factorization_seconds");
  s.solver = json_string(t, "", "solver");
  s.distance = json_string(t, "", "border_distance");
  s.border = json_string(t, "border_choice", "mode");
  s.kept = json_string(t, "chosen", "kind");
  return s;
}

// The command line and BFF on the OBJ file of the mesh, interleaved (scale mode).
void measure_whole_process(const std::string& obj, const std::string& stem, const Plan& plan, Whole_process& w)
{
  w.planned = true;
  w.load_before = load_average();
  const std::string base = (std::filesystem::path(plan.work) / stem).string();
  for(int r = 0; r < plan.whole_runs; ++r)
  {
    if(!plan.cli.empty())
    {
      std::cerr << "    whole process, ours, run " << r + 1 << std::endl;
      const Process_result p = run_process(plan.cli, {obj, "--output=" + base + "_ours_uv.obj", "--json"},
                                           base + "_ours.json", base + "_ours.log");
      w.ours.push_back(p);
      if(p.ran && p.exit_status == 0)
        w.ours_stages.push_back(read_cli_json(base + "_ours.json"));
      else
        w.failure += "ours exit " + std::to_string(p.exit_status) + " (see " + base + "_ours.log); ";
    }
    if(!plan.bff.empty())
    {
      std::cerr << "    whole process, BFF, run " << r + 1 << std::endl;
      const Process_result p = run_process(plan.bff, {obj, base + "_bff_uv.obj"}, base + "_bff.log", base + "_bff.log");
      w.bff.push_back(p);
      if(!(p.ran && p.exit_status == 0))
        w.failure += "BFF exit " + std::to_string(p.exit_status) + " (see " + base + "_bff.log); ";
    }
  }
  w.load_after = load_average();
}

void run_children(const Plan& plan, const Mesh_source& source, const std::string& name, Mesh_result& res)
{
  for(int m : plan.timed_in_child)
  {
    std::cerr << "  " << name << ": " << method_name(m) << " (one run in a child, cap " << plan.cap_seconds << " s)"
              << std::endl;
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
    {
      std::cerr << "  " << name << ": " << method_name(m) << " (memory, in a child)" << std::endl;
      res.methods[m].memory = run_in_child(m, source, false, 0.);
    }
}

void time_one_run(int m, Mesh& mesh, halfedge_descriptor bhd, UV_map uv, bool first, Method_result& mr)
{
  if(!first && mr.status != SMP::OK)
    return;
  mr.planned = true;
  const Run run = run_method(m, mesh, bhd, uv);
  if(run.status != SMP::OK)
  {
    mr.status = run.status;
    return;
  }
  mr.seconds.push_back(run.seconds);
  if(run.is_ours)
    mr.stages.push_back(run.stages);
  if(run.is_ours && !mr.has_choice)
  {
    mr.choice = run.choice;
    mr.has_choice = true;
  }
  if(!mr.has_quality)
  {
    mr.quality = SMP::measure_quality(mesh, faces(mesh), uv);
    mr.has_quality = true;
  }
}

Mesh_result measure_mesh(const std::string& name, Mesh& mesh, const Mesh_source& source, const Plan& plan)
{
  Mesh_result res;
  res.name = name;
  res.V = num_vertices(mesh);
  res.F = num_faces(mesh);
  res.load_average = load_average();
  res.runs = res.V >= 1000000 ? plan.large_runs : plan.runs;
  const halfedge_descriptor bhd = CGAL::Polygon_mesh_processing::longest_border(mesh).first;
  UV_map uv = mesh.add_property_map<vertex_descriptor, K::Point_2>("v:bench_uv").first;

  run_children(plan, source, name, res);

  Eigen::SparseMatrix<double> A;
  const bool have_laplacian = mbp_benchmark::interior_cotangent_laplacian(mesh, bhd, A);
  bool needs_floor[NUMBER_OF_SOLVERS] = {false, false};
  for(int m : plan.timed)
    if(solver_of(m) >= 0)
      needs_floor[solver_of(m)] = true;

  const Cpu_sample before = sample_cpu();
  for(int r = 0; r < res.runs; ++r)
  {
    for(int m : plan.timed)
    {
      std::cerr << "  " << name << ": " << method_name(m) << ", run " << r + 1 << std::endl;
      time_one_run(m, mesh, bhd, uv, r == 0, res.methods[m]);
    }
    for(int s = 0; s < NUMBER_OF_SOLVERS; ++s)
    {
      if(!needs_floor[s] || !solver_available(s) || !have_laplacian || res.floor_failed[s])
        continue;
      std::cerr << "  " << name << ": floor " << solver_name(s) << ", run " << r + 1 << std::endl;
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
  return (std::isnan(a) || std::isnan(b) || !(b > 0.)) ? nan_value : a / b;
}

double time_of(const Mesh_result& r, int m)
{
  return r.methods[m].ok() ? r.methods[m].time() : nan_value;
}

double memory_of(const Mesh_result& r, int m)
{
  return r.methods[m].has_memory() ? r.methods[m].memory_mb() : nan_value;
}

double floor_ratio(const Mesh_result& r, int m)
{
  return solver_of(m) < 0 ? nan_value : ratio(time_of(r, m), r.floor(solver_of(m)));
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
    return " - | - | - |";
  return " " + fmt("%.4f", mr.quality.angle_distortion) + " | " + fmt("%.4f", mr.quality.l2_stretch) + " | " +
         std::to_string(mr.quality.flipped_faces) + " |";
}

const char* family_name(int kept)
{
  switch(kept)
  {
  case SMP::CIRCLE: return "circle";
  case SMP::MEASURED: return "measured";
  case SMP::CONFORMAL: return "conformal";
  case SMP::CONFORMAL_LENGTHS: return "conformal-lengths";
  default: return "-";
  }
}

std::string choice_cell(const Method_result& mr)
{
  if(!mr.has_choice)
    return "-";
  std::string s = family_name(mr.choice.kept);
  if(mr.choice.blend > 0.)
    s += ", blend " + fmt("%.3f", mr.choice.blend);
  if(mr.choice.mean_value_interior)
    s += ", MVC interior";
  if(mr.choice.repaired)
    s += " (repaired; " + std::to_string(mr.choice.flips_before) + " flips before)";
  return s;
}

// The methods measured in any row, in the order of the enum.
std::vector<int> planned_methods(const std::vector<Mesh_result>& results)
{
  std::vector<int> ms;
  for(int m = 0; m < NUMBER_OF_METHODS; ++m)
    for(const Mesh_result& r : results)
      if(r.methods[m].planned)
      {
        ms.push_back(m);
        break;
      }
  return ms;
}

bool planned(const std::vector<int>& ms, int m) { return std::find(ms.begin(), ms.end(), m) != ms.end(); }

std::string load_cells(const Mesh_result& r)
{
  return fmt("%.2f", r.load_average) + " | " + fmt("%.0f%%", 100. * r.other_load);
}

// Largest relative difference of the angle distortion and L2 stretch between LDLT and
// CHOLMOD for the same border choice.
double solver_disagreement(const Mesh_result& r)
{
  double worst = 0.;
  for(auto pair : {std::make_pair(AUTO_LDLT, AUTO_CHOLMOD), std::make_pair(MBPPP_LDLT, MBPPP_CHOLMOD)})
  {
    const Method_result& a = r.methods[pair.first];
    const Method_result& b = r.methods[pair.second];
    if(!a.has_quality || !b.has_quality)
      continue;
    worst = (std::max)(worst, std::abs(a.quality.angle_distortion - b.quality.angle_distortion) /
                                (std::max)(a.quality.angle_distortion, 1e-300));
    worst = (std::max)(worst, std::abs(a.quality.l2_stretch - b.quality.l2_stretch) / a.quality.l2_stretch);
  }
  return worst;
}

void print_quality_table(const std::vector<Mesh_result>& results)
{
  const std::vector<int> ms = planned_methods(results);
  std::printf("\n### Distortion (angle distortion, L2 stretch, flipped faces)\n\n| mesh | V | F |");
  std::string rule = "|---|---|---|";
  std::vector<int> shown;
  for(int m : ms)
    if(!(m == AUTO_LDLT && planned(ms, AUTO_CHOLMOD)) && !(m == MBPPP_LDLT && planned(ms, MBPPP_CHOLMOD)))
      shown.push_back(m);
  for(int m : shown)
  {
    const char* n = (m == AUTO_CHOLMOD || m == AUTO_LDLT) ? "auto" : (m == MBPPP_CHOLMOD || m == MBPPP_LDLT) ? "MBPPP"
                                                                                                            : method_name(m);
    std::printf(" %s: angle | %s: L2 | %s: flips |", n, n, n);
    rule += "---|---|---|";
    if(is_ours(m))
    {
      std::printf(" %s: kept |", n);
      rule += "---|";
    }
  }
  std::printf("\n%s\n", rule.c_str());
  double disagreement = 0.;
  for(const Mesh_result& r : results)
  {
    std::printf("| %s | %zu | %zu |", r.name.c_str(), r.V, r.F);
    for(int m : shown)
    {
      const Method_result& mr = r.methods[m];
      std::printf("%s", quality_cells(mr).c_str());
      if(is_ours(m))
        std::printf(" %s |", choice_cell(mr).c_str());
    }
    std::printf("\n");
    disagreement = (std::max)(disagreement, solver_disagreement(r));
  }
  std::printf("\nauto and MBPPP: the CHOLMOD configurations when built with CHOLMOD; LDLT gives the same"
              " figures within a relative %.1e.\n", disagreement);
}

void print_time_table(const std::vector<Mesh_result>& results)
{
  const std::vector<int> ms = planned_methods(results);
  std::printf("\n### Time (seconds, median of the row's runs) and ratio to the single-factorization floor\n\n");
  std::printf("| mesh | V | F | runs | floor LDLT | floor CHOLMOD |");
  std::string rule = "|---|---|---|---|---|---|";
  for(int m : ms)
  {
    std::printf(" %s |", method_name(m));
    rule += "---|";
    if(is_ours(m))
    {
      std::printf(" / floor |");
      rule += "---|";
    }
  }
  const bool dcp = planned(ms, CGAL_DCP);
  if(dcp)
  {
    std::printf(" DCP / auto LDLT | DCP / auto CHOLMOD |");
    rule += "---|---|";
  }
  std::printf(" load (1 min) | other load |\n%s---|---|\n", rule.c_str());
  for(const Mesh_result& r : results)
  {
    std::printf("| %s | %zu | %zu | %d | %s | %s |", r.name.c_str(), r.V, r.F, r.runs, seconds_cell(r.floor(LDLT)).c_str(),
                seconds_cell(r.floor(CHOLMOD)).c_str());
    for(int m : ms)
    {
      std::printf(" %s |", time_cell(r.methods[m]).c_str());
      if(is_ours(m))
        std::printf(" %s |", fmt("%.2f", floor_ratio(r, m)).c_str());
    }
    if(dcp)
      std::printf(" %s | %s |", fmt("%.1f", ratio(time_of(r, CGAL_DCP), time_of(r, AUTO_LDLT))).c_str(),
                  fmt("%.1f", ratio(time_of(r, CGAL_DCP), time_of(r, AUTO_CHOLMOD))).c_str());
    std::printf(" %s |\n", load_cells(r).c_str());
  }
}

void print_memory_table(const std::vector<Mesh_result>& results)
{
  const std::vector<int> ms = planned_methods(results);
  std::printf("\n### Peak memory of the call (MiB above the starting resident set, one run in a child process)\n\n");
  std::printf("| mesh | V |");
  std::string rule = "|---|---|";
  for(int m : ms)
  {
    std::printf(" %s |", method_name(m));
    rule += "---|";
  }
  const bool dcp = planned(ms, CGAL_DCP);
  if(dcp)
  {
    std::printf(" auto LDLT / DCP | auto CHOLMOD / DCP |");
    rule += "---|---|";
  }
  std::printf("\n%s\n", rule.c_str());
  for(const Mesh_result& r : results)
  {
    std::printf("| %s | %zu |", r.name.c_str(), r.V);
    for(int m : ms)
      std::printf(" %s |", memory_cell(r.methods[m]).c_str());
    if(dcp)
      std::printf(" %s | %s |", fmt("%.2f", ratio(memory_of(r, AUTO_LDLT), memory_of(r, CGAL_DCP))).c_str(),
                  fmt("%.2f", ratio(memory_of(r, AUTO_CHOLMOD), memory_of(r, CGAL_DCP))).c_str());
    std::printf("\n");
  }
}

void print_stage_table(const std::vector<Mesh_result>& results, std::size_t min_vertices)
{
  std::printf("\n### Where our time goes (seconds, median per stage; the parameterizer's report), meshes of >= %zu"
              " vertices\n\n", min_vertices);
  std::printf("| mesh | V | config | prep. | conformal border | center | distances | border map | layouts |"
              " repair | output | call total | factorizations | factorization s | back-subst. | SMP::parameterize |"
              " floor | call total - factorizations | call total / floor |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for(const Mesh_result& r : results)
  {
    if(r.V < min_vertices)
      continue;
    for(int m : {AUTO_LDLT, AUTO_CHOLMOD, MBPPP_LDLT, MBPPP_CHOLMOD})
    {
      const Method_result& mr = r.methods[m];
      if(!mr.ok() || mr.stages.empty())
        continue;
      auto med = [&](auto field) {
        std::vector<double> v;
        for(const Stages& s : mr.stages)
          v.push_back(static_cast<double>(s.*field));
        return median(v);
      };
      const double total = med(&Stages::total), fact = med(&Stages::factorization_seconds);
      std::printf("| %s | %zu | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n",
                  r.name.c_str(), r.V, method_name(m), seconds_cell(med(&Stages::preparation)).c_str(),
                  seconds_cell(med(&Stages::conformal_border)).c_str(), seconds_cell(med(&Stages::center)).c_str(),
                  seconds_cell(med(&Stages::distance)).c_str(), seconds_cell(med(&Stages::border_map)).c_str(),
                  seconds_cell(med(&Stages::interior)).c_str(), seconds_cell(med(&Stages::repair)).c_str(),
                  seconds_cell(med(&Stages::output)).c_str(), seconds_cell(total).c_str(),
                  fmt("%.0f", med(&Stages::factorizations)).c_str(), seconds_cell(fact).c_str(),
                  fmt("%.0f", med(&Stages::back_substitutions)).c_str(), seconds_cell(mr.time()).c_str(),
                  seconds_cell(r.floor(solver_of(m))).c_str(), seconds_cell(total - fact).c_str(),
                  fmt("%.2f", ratio(total, r.floor(solver_of(m)))).c_str());
    }
  }
}

double stage_median(const std::vector<Cli_stages>& v, double Cli_stages::*field)
{
  std::vector<double> x;
  for(const Cli_stages& s : v)
    x.push_back(s.*field);
  return median(x);
}

void print_whole_process_tables(const std::vector<Mesh_result>& results, const Plan& plan)
{
  std::printf("\n### Whole process: the command line against BFF's (median of %d interleaved runs each)\n\n",
              plan.whole_runs);
  std::printf("ours: `%s IN.obj --output=OUT.obj --json` (defaults); BFF: `%s IN.obj OUT.obj`. Peak memory:"
              " ru_maxrss of the process.\n\n", plan.cli.empty() ? "(none)" : plan.cli.c_str(),
              plan.bff.empty() ? "(none)" : plan.bff.c_str());
  std::printf("| mesh | V | F | ours (s) | ours peak (MiB) | BFF (s) | BFF peak (MiB) | BFF / ours time |"
              " ours / BFF memory | ours: solver, border, distances, kept | load (1 min) before, after | failures |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for(const Mesh_result& r : results)
  {
    const Whole_process& w = r.whole;
    if(!w.planned)
      continue;
    const double ot = Whole_process::median_seconds(w.ours), bt = Whole_process::median_seconds(w.bff);
    const double om = Whole_process::median_rss_mb(w.ours), bm = Whole_process::median_rss_mb(w.bff);
    std::string config = "-";
    if(!w.ours_stages.empty())
    {
      const Cli_stages& s = w.ours_stages.front();
      config = s.solver + ", " + s.border + ", " + s.distance + ", " + s.kept;
    }
    std::printf("| %s | %zu | %zu | %s | %s | %s | %s | %s | %s | %s | %s, %s | %s |\n", r.name.c_str(), r.V, r.F,
                seconds_cell(ot).c_str(), fmt("%.0f", om).c_str(), seconds_cell(bt).c_str(), fmt("%.0f", bm).c_str(),
                fmt("%.2f", ratio(bt, ot)).c_str(), fmt("%.2f", ratio(om, bm)).c_str(), config.c_str(),
                fmt("%.2f", w.load_before).c_str(), fmt("%.2f", w.load_after).c_str(),
                w.failure.empty() ? "none" : w.failure.c_str());
  }

  std::printf("\n### Whole process: stages of our run (seconds, medians of its --json)\n\n");
  std::printf("| mesh | V | process | read | prep. | conformal border | center | distances | border map | layouts |"
              " repair | output | parameterization total | quality | write | rest (process - read - total -"
              " quality - write) | factorizations | factorization s |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for(const Mesh_result& r : results)
  {
    const Whole_process& w = r.whole;
    if(!w.planned || w.ours_stages.empty())
      continue;
    const std::vector<Cli_stages>& v = w.ours_stages;
    const double process = Whole_process::median_seconds(w.ours);
    const double read = stage_median(v, &Cli_stages::read), total = stage_median(v, &Cli_stages::total),
                 quality = stage_median(v, &Cli_stages::quality), write = stage_median(v, &Cli_stages::write);
    std::printf("| %s | %zu | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n",
                r.name.c_str(), r.V, seconds_cell(process).c_str(), seconds_cell(read).c_str(),
                seconds_cell(stage_median(v, &Cli_stages::preparation)).c_str(),
                seconds_cell(stage_median(v, &Cli_stages::conformal_border)).c_str(),
                seconds_cell(stage_median(v, &Cli_stages::center)).c_str(),
                seconds_cell(stage_median(v, &Cli_stages::distances)).c_str(),
                seconds_cell(stage_median(v, &Cli_stages::border_map)).c_str(),
                seconds_cell(stage_median(v, &Cli_stages::interior)).c_str(),
                seconds_cell(stage_median(v, &Cli_stages::repair)).c_str(),
                seconds_cell(stage_median(v, &Cli_stages::output)).c_str(), seconds_cell(total).c_str(),
                seconds_cell(quality).c_str(), seconds_cell(write).c_str(),
                seconds_cell(process - read - total - quality - write).c_str(),
                fmt("%.0f", stage_median(v, &Cli_stages::factorizations)).c_str(),
                seconds_cell(stage_median(v, &Cli_stages::factorization_seconds)).c_str());
  }
}

// ---------------------------------------------------------------------------------------
// Targets, on this run's numbers

const char* verdict(bool met, bool any) { return !any ? "not evaluated" : (met ? "MET" : "NOT MET"); }

// Every row of >= min_vertices: method time / floor <= bound.
void print_floor_target(const std::vector<Mesh_result>& results, int m, std::size_t min_vertices, double bound)
{
  bool any = false, met = true;
  std::string list;
  for(const Mesh_result& r : results)
  {
    const double q = floor_ratio(r, m);
    if(r.V < min_vertices || std::isnan(q))
      continue;
    any = true;
    met = met && q <= bound;
    list += (list.empty() ? "" : ", ") + r.name + " " + fmt("%.2f", q) + "x";
  }
  std::printf("- in-process <= %.1fx the floor at every size >= %zu vertices, %s (SMP::parameterize): %s%s%s%s\n",
              bound, min_vertices, method_name(m), verdict(met, any), any ? " (" : "", list.c_str(), any ? ")" : "");
}

// The same with the parameterizer's own total (its report: without CGAL's SMP::parameterize()
// wrapper, which builds an index map of the component and two dynamic property maps).
void print_own_total_floor_target(const std::vector<Mesh_result>& results, int m, std::size_t min_vertices, double bound)
{
  bool any = false, met = true;
  std::string list;
  for(const Mesh_result& r : results)
  {
    const Method_result& mr = r.methods[m];
    if(r.V < min_vertices || !mr.ok() || mr.stages.empty() || solver_of(m) < 0)
      continue;
    std::vector<double> totals;
    for(const Stages& s : mr.stages)
      totals.push_back(s.total);
    const double q = ratio(median(totals), r.floor(solver_of(m)));
    if(std::isnan(q))
      continue;
    any = true;
    met = met && q <= bound;
    list += (list.empty() ? "" : ", ") + r.name + " " + fmt("%.2f", q) + "x";
  }
  std::printf("- the same with the parameterizer's own total (no CGAL wrapper), %s: %s%s%s%s\n", method_name(m),
              verdict(met, any), any ? " (" : "", list.c_str(), any ? ")" : "");
}

void print_issue13_whole_targets(const std::vector<Mesh_result>& results)
{
  for(const Mesh_result& r : results)
  {
    const Whole_process& w = r.whole;
    if(!w.planned)
      continue;
    const double ot = Whole_process::median_seconds(w.ours), bt = Whole_process::median_seconds(w.bff);
    const double om = Whole_process::median_rss_mb(w.ours), bm = Whole_process::median_rss_mb(w.bff);
    if(r.V >= 600000 && r.V < 1000000)
    {
      std::printf("- whole run at %zu vertices <= 6 s: %s (%s s)\n", r.V, verdict(ot <= 6., !std::isnan(ot)),
                  seconds_cell(ot).c_str());
      const double speed = ratio(bt, ot), memory = ratio(om, bm);
      std::printf("- >= 5x faster than BFF at %zu vertices: %s (%sx)\n", r.V, verdict(speed >= 5., !std::isnan(speed)),
                  fmt("%.2f", speed).c_str());
      std::printf("- peak memory <= 0.75x BFF's at %zu vertices: %s (%sx: %s against %s MiB)\n", r.V,
                  verdict(memory <= 0.75, !std::isnan(memory)), fmt("%.2f", memory).c_str(), fmt("%.0f", om).c_str(),
                  fmt("%.0f", bm).c_str());
    }
    if(r.V >= 1500000)
    {
      const double gb = om * 1024. * 1024. / 1e9;
      std::printf("- whole run at %zu vertices <= 20 s: %s (%s s)\n", r.V, verdict(ot <= 20., !std::isnan(ot)),
                  seconds_cell(ot).c_str());
      std::printf("- whole run at %zu vertices <= 2.5 GB: %s (%s GB = %s MiB)\n", r.V, verdict(gb <= 2.5, !std::isnan(gb)),
                  fmt("%.2f", gb).c_str(), fmt("%.0f", om).c_str());
    }
  }
}

// Issue 3's targets, with ours = the automatic border.
void print_issue3_targets(const std::vector<Mesh_result>& results)
{
  for(int m : {AUTO_LDLT, AUTO_CHOLMOD})
  {
    if(!method_available(m))
      continue;
    print_floor_target(results, m, 5000, 2.5);
    bool any = false, met = true;
    double least = std::numeric_limits<double>::infinity(), worst_memory = 0.;
    bool any_memory = false, met_memory = true;
    for(const Mesh_result& r : results)
    {
      const double q = ratio(time_of(r, CGAL_DCP), time_of(r, m));
      if(r.V >= 30000 && !std::isnan(q))
      {
        any = true;
        least = (std::min)(least, q);
        met = met && q >= 5.;
      }
      const double mq = ratio(memory_of(r, m), memory_of(r, CGAL_DCP));
      if(!std::isnan(mq))
      {
        any_memory = true;
        worst_memory = (std::max)(worst_memory, mq);
        met_memory = met_memory && mq <= 1.5;
      }
    }
    std::printf("- >= 5x faster than CGAL DCP at >= 30k vertices, %s: %s", method_name(m), verdict(met, any));
    if(any)
      std::printf(" (least %.1fx)", least);
    std::printf("\n- call's peak memory <= 1.5x CGAL DCP's, %s: %s", method_name(m), verdict(met_memory, any_memory));
    if(any_memory)
      std::printf(" (worst %.2fx)", worst_memory);
    std::printf("\n");
  }
}

void print_targets(const std::vector<Mesh_result>& results)
{
  std::printf("\n### Targets of issue 13 (this run)\n\n");
  for(int m : {AUTO_LDLT, AUTO_CHOLMOD})
    if(method_available(m))
    {
      print_floor_target(results, m, 45000, 1.3);
      print_own_total_floor_target(results, m, 45000, 1.3);
    }
  print_issue13_whole_targets(results);
  std::printf("\n### Targets of issue 3 (ours = the automatic border; this run)\n\n");
  print_issue3_targets(results);
}

// ---------------------------------------------------------------------------------------
// Hidden modes of the child processes

// --child FD METHOD MESH_FILE LEVELS QUALITY (run_in_child())
int child_main(char** argv)
{
  Child_result r;
  const int fd = std::atoi(argv[2]);
  const int m = std::atoi(argv[3]);
  const int levels = std::atoi(argv[5]);
  const bool with_quality = std::atoi(argv[6]) != 0;

  Mesh mesh;
  if(m < 0 || m >= NUMBER_OF_METHODS || !method_available(m) || !CGAL::IO::read_polygon_mesh(argv[4], mesh))
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

// --spawn FD STDOUT_FILE STDERR_FILE PROGRAM ARGS... (run_process()): this process is small
// (freshly exec()ed), so the program fork()ed from it starts with a small high-water mark.
int spawn_main(int argc, char** argv)
{
  Process_result r;
  const int fd = std::atoi(argv[2]);
  const char* out = argv[3];
  const char* err = argv[4];
  const Clock::time_point start = Clock::now();
  const pid_t pid = ::fork();
  if(pid < 0)
    return 1;
  if(pid == 0)
  {
    ::close(fd);
    const int o = ::open(out, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int e = std::strcmp(out, err) == 0 ? o : ::open(err, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if(o < 0 || e < 0 || ::dup2(o, 1) < 0 || ::dup2(e, 2) < 0)
      ::_exit(126);
    std::vector<char*> args(argv + 5, argv + argc);
    args.push_back(nullptr);
    ::execv(argv[5], args.data());
    ::_exit(127);
  }
  int wstatus = 0;
  rusage usage;
  std::memset(&usage, 0, sizeof(usage));
  while(::wait4(pid, &wstatus, 0, &usage) < 0)
    if(errno != EINTR)
      return 1;
  r.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  r.ran = true;
  r.exit_status = WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : -1;
  r.maxrss_kb = usage.ru_maxrss;
  return write_all(fd, &r, sizeof(r)) ? 0 : 1;
}

// ---------------------------------------------------------------------------------------
// The two modes

int usage(const char* program)
{
  std::cerr << "usage: " << program
            << " [--runs N] [--mesh NAME]... [--no-memory] [MESH_DIR]\n"
               "       "
            << program
            << " --scale [--scale-case FILE:K[,K...]]... [--runs N] [--large-runs N] [--no-memory]"
               " [--dcp-cap SECONDS] [--cli PATH|none] [--bff PATH|none] [--whole-runs N] [--work DIR] [MESH_DIR]\n";
  return 2;
}

struct Scale_case
{
  std::string file;
  std::vector<int> levels;
};

bool parse_scale_case(const std::string& spec, Scale_case& c)
{
  const std::size_t colon = spec.rfind(':');
  if(colon == std::string::npos || colon == 0)
    return false;
  c.file = spec.substr(0, colon);
  std::stringstream levels(spec.substr(colon + 1));
  std::string k;
  while(std::getline(levels, k, ','))
  {
    char* stop = nullptr;
    const long level = std::strtol(k.c_str(), &stop, 10);
    if(k.empty() || *stop != '\0' || level < 0 || level > 6)
      return false;
    c.levels.push_back(static_cast<int>(level));
  }
  std::sort(c.levels.begin(), c.levels.end());
  return !c.levels.empty();
}

int run_scale_mode(const std::string& dir, std::vector<Scale_case> cases, Plan& plan, std::vector<Mesh_result>& results)
{
  if(cases.empty())
    cases = {Scale_case{"bimba_i.obj", {0, 1, 2}}, Scale_case{"mask.off", {3}}};
  for(int m : {AUTO_LDLT, AUTO_CHOLMOD, MBPPP_CHOLMOD})
    if(method_available(m))
      plan.timed.push_back(m);
  if(plan.cap_seconds > 0.)
    plan.timed_in_child.push_back(CGAL_DCP);
  const bool whole = !plan.cli.empty() || !plan.bff.empty();
  std::error_code ec;
  if(whole && !std::filesystem::create_directories(plan.work, ec) && ec)
  {
    std::cerr << "error: cannot create '" << plan.work << "'\n";
    return 1;
  }
  for(const Scale_case& c : cases)
  {
    const std::string path = std::filesystem::exists(c.file) ? c.file : (std::filesystem::path(dir) / c.file).string();
    Mesh mesh;
    if(!CGAL::IO::read_polygon_mesh(path, mesh) || faces(mesh).empty() || !not_a_disk(mesh).empty())
    {
      std::cerr << "error: '" << path << "' is not a readable disk mesh\n";
      return 1;
    }
    const std::string base = std::filesystem::path(path).filename().string();
    int level = 0;
    for(int target : c.levels)
    {
      for(; level < target; ++level)
      {
        Mesh refined;
        if(!midpoint_subdivision(mesh, refined))
        {
          std::cerr << "error: subdivision failed\n";
          return 1;
        }
        mesh = std::move(refined);
      }
      const std::string name = base + " x" + std::to_string(target);
      std::cerr << name << ": V " << num_vertices(mesh) << ", F " << num_faces(mesh) << ", load "
                << load_average() << std::endl;
      results.push_back(measure_mesh(name, mesh, Mesh_source{path, target}, plan));
      if(whole)
      {
        const std::string stem = std::filesystem::path(base).stem().string() + "_x" + std::to_string(target);
        const std::string obj = (std::filesystem::path(plan.work) / (stem + ".obj")).string();
        if(!write_obj_file(mesh, obj))
        {
          std::cerr << "error: cannot write '" << obj << "'\n";
          return 1;
        }
        measure_whole_process(obj, stem, plan, results.back().whole);
      }
    }
  }
  return 0;
}

int run_directory_mode(const std::string& dir, const std::vector<std::string>& only, Plan& plan,
                       std::vector<Mesh_result>& results, std::vector<std::string>& skipped)
{
  const std::vector<std::filesystem::path> files = mbp_benchmark::mesh_files_in(dir, only);
  if(files.empty())
  {
    std::cerr << "error: no mesh in '" << dir << "'\n";
    return 1;
  }
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
  return 0;
}

std::string program_option(const std::string& value)
{
  if(value == "none")
    return "";
  return value;
}

} // namespace

int main(int argc, char** argv)
{
  if(argc == 7 && std::string(argv[1]) == "--child")
    return child_main(argv);
  if(argc >= 6 && std::string(argv[1]) == "--spawn")
    return spawn_main(argc, argv);
  std::string dir = MBP_MESH_DIR;
  std::vector<std::string> only;
  std::vector<Scale_case> cases;
  Plan plan;
  plan.cap_seconds = 600.;
  plan.cli = MBP_CLI_PROGRAM;
  plan.bff = MBP_BFF_PROGRAM;
  plan.work = "/tmp/mbp-scale";
  bool scale = false;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    const bool has_value = i + 1 < argc;
    if(a == "--runs" && has_value)             plan.runs = std::atoi(argv[++i]);
    else if(a == "--large-runs" && has_value)  plan.large_runs = std::atoi(argv[++i]);
    else if(a == "--mesh" && has_value)        only.push_back(argv[++i]);
    else if(a == "--no-memory")                plan.memory = false;
    else if(a == "--scale")                    scale = true;
    else if(a == "--scale-case" && has_value)
    {
      Scale_case c;
      if(!parse_scale_case(argv[++i], c))
        return usage(argv[0]);
      cases.push_back(c);
    }
    else if(a == "--dcp-cap" && has_value)     plan.cap_seconds = std::atof(argv[++i]);
    else if(a == "--cli" && has_value)         plan.cli = program_option(argv[++i]);
    else if(a == "--bff" && has_value)         plan.bff = program_option(argv[++i]);
    else if(a == "--whole-runs" && has_value)  plan.whole_runs = std::atoi(argv[++i]);
    else if(a == "--work" && has_value)        plan.work = argv[++i];
    else if(!a.empty() && a[0] == '-')         return usage(argv[0]);
    else                                       dir = a;
  }
  if(plan.runs < 1 || plan.large_runs < 1 || plan.whole_runs < 1 || !(plan.cap_seconds >= 0.))
    return usage(argv[0]);
  for(std::string* program : {&plan.cli, &plan.bff})
    if(!program->empty() && ::access(program->c_str(), X_OK) != 0)
    {
      std::cerr << "note: '" << *program << "' is not an executable: its whole-process column stays empty\n";
      program->clear();
    }
  if(plan.runs < 5)
    std::cerr << "note: fewer than 5 runs per method\n";

  std::vector<Mesh_result> results;
  std::vector<std::string> skipped;
  const int status = scale ? run_scale_mode(dir, cases, plan, results)
                           : run_directory_mode(dir, only, plan, results, skipped);
  if(status != 0)
    return status;

#ifdef MBP_WITH_CHOLMOD
  std::printf("Solvers: Eigen SimplicialLDLT; CHOLMOD supernodal (AMD)\n");
#else
  std::printf("Solvers: Eigen SimplicialLDLT (built without CHOLMOD: its columns are empty)\n");
#endif
  print_time_table(results);
  if(scale && plan.cap_seconds > 0.)
    std::printf("\nCGAL DCP: one run in a child process, killed after %.0f s (\"> cap\").\n", plan.cap_seconds);
  if(plan.memory || scale)
    print_memory_table(results);
  print_quality_table(results);
  print_stage_table(results, scale ? 0 : 20000);
  if(scale)
    print_whole_process_tables(results, plan);
  print_targets(results);
  if(!skipped.empty())
  {
    std::printf("\nSkipped (not disks):");
    for(const std::string& s : skipped)
      std::printf(" %s;", s.c_str());
    std::printf("\n");
  }
  return 0;
}
