// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// A batch run: every mesh of a folder flattened by Measured_conformal_parameterizer_3, several
// meshes at a time on a pool of threads, with a progress bar and a summary table.
//
//   batch_parameterization MESH_DIR [THREADS]
//
// Reads every .off, .obj, .ply and .stl file of MESH_DIR (not recursively), parameterizes the
// longest border of each (holes are filled virtually; closed meshes and meshes with handles
// are reported as not disks, files that CGAL's readers reject as unreadable), and prints one
// row per file: size, status, angle distortion, flipped faces, whether the result was
// repaired, and the time of the call. THREADS defaults to the number of cores. The progress
// bar is drawn on stderr only when it is a terminal.
//
// Concurrency: each thread builds its own mesh and its own parameterizer (a parameterizer and
// its copies share their report, so one object must not be used by two threads at once). The
// parameterizers run with the default CGAL::Sequential_tag: the parallelism is across meshes here. The
// solver is the default (Eigen's LDLT); Cholmod_supernodal_cholesky_traits would set a
// process-wide OpenBLAS thread count while it runs, which is not meant for several
// parameterizers running at once.
//
// Exit status: 1 when MESH_DIR is not a directory, holds no mesh file, when no mesh could be
// parameterized, or when the method fails on a triangle mesh with a border that it accepts
// (a linear system not solved, a map that is not one-to-one, ...); 0 otherwise. A file that
// cannot be read, a mesh that is not a triangle mesh, not a disk, or that the parameterizer
// rejects for what it is (a face of zero area, no interior vertex, ...) is an expected
// outcome in a folder of arbitrary meshes: reported in the table and counted, not a failure.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <CGAL/Surface_mesh_parameterization/Measured_conformal_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/measure_quality.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#ifdef _WIN32
#include <io.h>
#define MBP_ISATTY(f) _isatty(_fileno(f))
#else
#include <unistd.h>
#define MBP_ISATTY(f) isatty(fileno(f))
#endif

typedef CGAL::Simple_cartesian<double>                           Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3>                      Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor             vertex_descriptor;
typedef boost::graph_traits<Mesh>::halfedge_descriptor           halfedge_descriptor;

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace fs = std::filesystem;

// One row of the summary table.
struct Result
{
  std::string name;
  std::size_t vertices = 0, faces = 0;
  bool read = false;       // the file was read as a polygon mesh
  bool triangles = false;  // every face is a triangle
  bool has_border = false;
  SMP::Error_code status = SMP::ERROR_EMPTY_MESH;
  bool one_to_one = false;
  double angle_distortion = 0.;
  std::size_t flipped_faces = 0;
  bool repaired = false;
  double seconds = 0.;
};

// Whether `status` says that the input cannot be parameterized as it is (a degenerate face,
// no interior vertex, a border too short, a non-finite coordinate), an expected outcome in a
// folder of arbitrary meshes, rather than a failure of the method.
bool rejects_the_input(SMP::Error_code status)
{
  return status == SMP::ERROR_EMPTY_MESH || status == SMP::ERROR_NON_TRIANGULAR_MESH ||
         status == SMP::ERROR_BORDER_TOO_SHORT || status == SMP::ERROR_DEGENERATE_FACE ||
         status == SMP::ERROR_NON_FINITE_COORDINATES || status == SMP::ERROR_NO_INTERIOR_VERTEX;
}

// Reads and parameterizes one mesh: everything here is local to the calling thread.
Result process(const fs::path& file)
{
  Result r;
  r.name = file.filename().string();
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(file.string(), mesh) || faces(mesh).empty())
    return r;
  r.read = true;
  r.vertices = num_vertices(mesh);
  r.faces = num_faces(mesh);
  r.triangles = CGAL::is_triangle_mesh(mesh);
  if(!r.triangles)
    return r;  // triangulate first (CGAL::Polygon_mesh_processing::triangulate_faces)

  const halfedge_descriptor bhd = CGAL::Polygon_mesh_processing::longest_border(mesh).first;
  r.has_border = (bhd != boost::graph_traits<Mesh>::null_halfedge());
  if(!r.has_border)
    return r;  // closed: it needs seams (see seam_parameterization.cpp)

  auto uvmap = mesh.add_property_map<vertex_descriptor, Kernel::Point_2>("v:uv").first;
  SMP::Measured_conformal_parameterizer_3<Mesh> parameterizer;
  r.status = SMP::parameterize(mesh, parameterizer, bhd, uvmap);
  r.seconds = parameterizer.last_report().total_seconds;
  if(r.status != SMP::OK)
    return r;
  r.repaired = parameterizer.last_report().repaired;

  // Only the parameterized component (the one of the border): the UVs of the other
  // components of a mesh are not set.
  std::vector<Mesh::Face_index> component;
  CGAL::Polygon_mesh_processing::connected_component(face(opposite(bhd, mesh), mesh), mesh,
                                                      std::back_inserter(component));
  const SMP::Parameterization_quality q = SMP::measure_quality(mesh, component, uvmap);
  r.angle_distortion = q.angle_distortion;
  r.flipped_faces = q.flipped_faces;
  r.one_to_one = SMP::is_one_to_one_uv_map(mesh, component, uvmap);
  return r;
}

// A one-line progress bar on stderr, redrawn in place; nothing when stderr is not a terminal
// (a log file or a pipe would get every redraw).
void draw_progress(std::size_t done, std::size_t total, const std::string& last)
{
  static const bool terminal = MBP_ISATTY(stderr);
  if(!terminal)
    return;
  const int width = 30;
  const int filled = int(width * done / (total ? total : 1));
  std::fprintf(stderr, "\r[%s%s] %zu/%zu %-28.28s", std::string(std::size_t(filled), '#').c_str(),
               std::string(std::size_t(width - filled), '.').c_str(), done, total, last.c_str());
  if(done == total)
    std::fprintf(stderr, "\n");
  std::fflush(stderr);
}

int main(int argc, char** argv)
{
  if(argc < 2 || argc > 3)
  {
    std::cerr << "usage: batch_parameterization MESH_DIR [THREADS]\n";
    return EXIT_FAILURE;
  }
  const fs::path dir = argv[1];
  std::error_code ec;
  if(!fs::is_directory(dir, ec))
  {
    std::cerr << "error: '" << dir.string() << "' is not a directory\n";
    return EXIT_FAILURE;
  }
  std::vector<fs::path> files;
  for(const fs::directory_entry& e : fs::directory_iterator(dir, ec))
  {
    std::string ext = e.path().extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if(e.is_regular_file() && (ext == ".off" || ext == ".obj" || ext == ".ply" || ext == ".stl"))
      files.push_back(e.path());
  }
  if(ec || files.empty())
  {
    std::cerr << "error: no mesh (.off, .obj, .ply, .stl) in '" << dir.string() << "'\n";
    return EXIT_FAILURE;
  }
  std::sort(files.begin(), files.end());

  unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  if(argc > 2)
    threads = unsigned(std::max(1, std::atoi(argv[2])));
  threads = std::min<unsigned>(threads, unsigned(files.size()));
  std::cout << files.size() << " meshes in " << dir.string() << ", " << threads << " threads\n";

  // The pool: each thread takes the next file until none is left.
  std::vector<Result> results(files.size());
  std::atomic<std::size_t> next(0);
  std::size_t done = 0;
  std::mutex progress_mutex;
  const auto start = std::chrono::steady_clock::now();
  auto worker = [&]() {
    for(std::size_t i = next++; i < files.size(); i = next++)
    {
      results[i] = process(files[i]);
      std::lock_guard<std::mutex> lock(progress_mutex);
      draw_progress(++done, files.size(), results[i].name);
    }
  };
  draw_progress(0, files.size(), "");
  std::vector<std::thread> pool;
  for(unsigned t = 0; t < threads; ++t)
    pool.emplace_back(worker);
  for(std::thread& t : pool)
    t.join();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  // The summary table (markdown).
  std::printf("\n| mesh | V | F | status | angle dist. | flips | repaired | time (s) |\n|---|---|---|---|---|---|---|---|\n");
  int parameterized = 0, not_disks = 0, skipped = 0, unreadable = 0, rejected = 0, failures = 0;
  double sum_seconds = 0.;
  for(const Result& r : results)
  {
    if(!r.read)
    {
      // a format variant CGAL's reader does not take, or not a mesh: reported, not a failure
      std::printf("| %s | | | unreadable: CGAL's reader rejects it (or no faces) | | | | |\n", r.name.c_str());
      ++unreadable;
      continue;
    }
    if(!r.triangles)
    {
      std::printf("| %s | %zu | %zu | skipped: not a triangle mesh | | | | |\n", r.name.c_str(), r.vertices, r.faces);
      ++skipped;
      continue;
    }
    if(!r.has_border || r.status == SMP::ERROR_NO_TOPOLOGICAL_DISC)
    {
      // closed (it needs seams: seam_parameterization.cpp), or handles, a pinched vertex...
      std::printf("| %s | %zu | %zu | not a disk: %s | | | | |\n", r.name.c_str(), r.vertices, r.faces,
                  r.has_border ? "not a topological disc" : "closed");
      ++not_disks;
      continue;
    }
    if(rejects_the_input(r.status))
    {
      std::printf("| %s | %zu | %zu | input rejected: %s | | | | |\n", r.name.c_str(), r.vertices, r.faces,
                  SMP::get_measured_error_message(r.status));
      ++rejected;
      continue;
    }
    if(r.status != SMP::OK || !r.one_to_one)
    {
      std::printf("| %s | %zu | %zu | FAILED: %s | | | | %.4f |\n", r.name.c_str(), r.vertices, r.faces,
                  r.status != SMP::OK ? SMP::get_measured_error_message(r.status) : "not one-to-one", r.seconds);
      ++failures;
      continue;
    }
    std::printf("| %s | %zu | %zu | ok | %.4f | %zu | %s | %.4f |\n", r.name.c_str(), r.vertices, r.faces,
                r.angle_distortion, r.flipped_faces, r.repaired ? "yes" : "no", r.seconds);
    ++parameterized;
    sum_seconds += r.seconds;
  }
  std::printf("\n%d parameterized (%.2f s of calls), %d not disks, %d not triangle meshes, %d unreadable, "
              "%d rejected inputs, %d failed; wall time %.2f s on %u threads\n",
              parameterized, sum_seconds, not_disks, skipped, unreadable, rejected, failures, wall, threads);
  return (failures == 0 && parameterized > 0) ? EXIT_SUCCESS : EXIT_FAILURE;
}
