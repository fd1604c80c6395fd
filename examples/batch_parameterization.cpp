// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// A batch run: the longest border of every .off, .obj, .ply and .stl mesh of a folder flattened
// by Conformal_parameterizer_3 (automatic border), THREADS meshes at a time (default: the
// number of cores), and a summary table.
//
//   batch_parameterization MESH_DIR [THREADS]
//
// A parameterizer holds no state of its calls: the threads share one; each call runs
// sequentially (the default CGAL::Sequential_tag). Exit status 1 when no mesh could be
// parameterized or the method fails on a mesh it accepts; unreadable files, closed meshes and
// inputs the parameterizer rejects (handles, a face of zero area...) are reported, not failures.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include <CGAL/Surface_mesh_parameterization/Conformal_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_report.h>
#include <CGAL/Surface_mesh_parameterization/measure_quality.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

typedef CGAL::Simple_cartesian<double>                           Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3>                      Mesh;
typedef boost::graph_traits<Mesh>::halfedge_descriptor           halfedge_descriptor;

namespace SMP = CGAL::Surface_mesh_parameterization;
typedef SMP::Conformal_parameterizer_3<Mesh>                     Parameterizer;  // automatic border
namespace fs = std::filesystem;

// Whether the parameterizer rejected the input for what it is (not a failure of the method).
bool rejected(SMP::Error_code s)
{
  return s == SMP::ERROR_EMPTY_MESH || s == SMP::ERROR_NON_TRIANGULAR_MESH || s == SMP::ERROR_BORDER_TOO_SHORT ||
         s == SMP::ERROR_DEGENERATE_FACE || s == SMP::ERROR_NON_FINITE_COORDINATES ||
         s == SMP::ERROR_NO_INTERIOR_VERTEX || s == SMP::ERROR_NO_TOPOLOGICAL_DISC;
}

// One row of the summary table.
struct Result
{
  std::string name, outcome = "unreadable";  // or "not triangles", "closed", "ok", an error
  std::size_t vertices = 0, faces = 0;
  bool ok = false, failed = false;
  SMP::Parameterization_report report;
  SMP::Parameterization_quality quality;
};

// Reads and parameterizes one mesh: everything here but the parameterizer is local to the thread.
Result process(const fs::path& file, const Parameterizer& parameterizer)
{
  Result r;
  r.name = file.filename().string();
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(file.string(), mesh) || faces(mesh).empty())
    return r;
  r.vertices = num_vertices(mesh);
  r.faces = num_faces(mesh);
  const halfedge_descriptor bhd = CGAL::Polygon_mesh_processing::longest_border(mesh).first;
  r.outcome = !CGAL::is_triangle_mesh(mesh) ? "not triangles"  // triangulate_faces() first
            : (bhd == boost::graph_traits<Mesh>::null_halfedge()) ? "closed"  // cut it (seam_parameterization.cpp)
            : "";
  if(!r.outcome.empty())
    return r;

  auto uvmap = mesh.add_property_map<Mesh::Vertex_index, Kernel::Point_2>("v:uv").first;
  const SMP::Error_code status = SMP::parameterize(mesh, parameterizer, bhd, uvmap, &r.report);
  r.outcome = SMP::get_measured_error_message(status);
  r.failed = (status != SMP::OK) && !rejected(status);
  if(status != SMP::OK)
    return r;
  // only the parameterized component: the UVs of the other components are not set
  std::vector<Mesh::Face_index> component;
  CGAL::Polygon_mesh_processing::connected_component(face(opposite(bhd, mesh), mesh), mesh,
                                                      std::back_inserter(component));
  r.quality = SMP::measure_quality(mesh, component, uvmap);
  r.ok = SMP::is_one_to_one_uv_map(mesh, component, uvmap);
  r.failed = !r.ok;
  r.outcome = r.ok ? "ok" : "not one-to-one";
  return r;
}

int main(int argc, char** argv)
{
  std::vector<fs::path> files;
  std::error_code ec;
  for(const fs::directory_entry& e : fs::directory_iterator(argc > 1 ? argv[1] : "", ec))
  {
    const std::string ext = e.path().extension().string();
    if(e.is_regular_file() && (ext == ".off" || ext == ".obj" || ext == ".ply" || ext == ".stl"))
      files.push_back(e.path());
  }
  if(argc < 2 || argc > 3 || ec || files.empty())
  {
    std::fprintf(stderr, "usage: batch_parameterization MESH_DIR [THREADS] (a folder of .off, .obj, .ply, .stl)\n");
    return EXIT_FAILURE;
  }
  std::sort(files.begin(), files.end());
  unsigned threads = (argc > 2) ? unsigned(std::max(1, std::atoi(argv[2]))) : std::thread::hardware_concurrency();
  threads = std::max(1u, std::min(threads, unsigned(files.size())));
  std::printf("%zu meshes in %s, %u threads\n", files.size(), argv[1], threads);

  // The pool: each thread takes the next file until none is left.
  const Parameterizer parameterizer;
  std::vector<Result> results(files.size());
  std::atomic<std::size_t> next(0);
  std::vector<std::thread> pool;
  for(unsigned t = 0; t < threads; ++t)
    pool.emplace_back([&] {
      for(std::size_t i = next++; i < files.size(); i = next++)
        results[i] = process(files[i], parameterizer);
    });
  for(std::thread& t : pool)
    t.join();

  // The summary table (markdown).
  std::printf("\n| mesh | V | F | outcome | angle dist. | flips | repaired | time (s) |\n"
              "|---|---|---|---|---|---|---|---|\n");
  std::size_t parameterized = 0, failures = 0;
  for(const Result& r : results)
  {
    std::printf("| %s | %zu | %zu | %s%s |", r.name.c_str(), r.vertices, r.faces, r.failed ? "FAILED: " : "",
                r.outcome.c_str());
    if(r.ok)
      std::printf(" %.4f | %zu | %s | %.4f |", r.quality.angle_distortion, r.quality.flipped_faces,
                  r.report.repaired ? "yes" : "no", r.report.total_seconds);
    std::printf(r.ok ? "\n" : " | | | |\n");
    parameterized += r.ok;
    failures += r.failed;
  }
  std::printf("\n%zu parameterized, %zu not parameterizable as they are, %zu failed\n", parameterized,
              results.size() - parameterized - failures, failures);
  return (failures == 0 && parameterized > 0) ? EXIT_SUCCESS : EXIT_FAILURE;
}
