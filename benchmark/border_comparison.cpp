// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// Compares, on every disk mesh of a directory, CGAL's discrete conformal map (DCP) with the
// measured border of this package against DCP with CGAL's circular arc-length border.
// Both solve with the same direct solver (Eigen's SparseLU), so only the border differs.
//
//   border_comparison [MESH_DIR]      (default: ../shared/data/meshes, as configured)
//
// Prints one row per mesh: V, F, border length, the paper's angle distortion and Sander's L2
// stretch for both borders (user manual: Measuring a parameterization), flipped faces, and whether the measured
// polygon is convex. Meshes that are not disks (several components or borders, handles,
// closed) are listed as skipped with the reason.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/Eigen_sparse_matrix.h>
#include <CGAL/property_map.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Surface_mesh_parameterization/Circular_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_conformal_map_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <CGAL/Surface_mesh_parameterization/Measured_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_report.h>
#include <CGAL/Surface_mesh_parameterization/measure_quality.h>

#include <Eigen/SparseLU>

#include "benchmark_support.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

namespace SMP = CGAL::Surface_mesh_parameterization;
typedef CGAL::Simple_cartesian<double>                          K;
typedef CGAL::Surface_mesh<K::Point_3>                          Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor            vertex_descriptor;
typedef CGAL::Eigen_solver_traits<Eigen::SparseLU<CGAL::Eigen_sparse_matrix<double>::EigenType> > LU;
typedef SMP::Measured_border_parameterizer_3<Mesh>              Measured;
typedef SMP::Circular_border_arc_length_parameterizer_3<Mesh>   Circle;

namespace {

struct Run
{
  SMP::Error_code status = SMP::OK;
  SMP::Parameterization_quality quality;
  double seconds = 0.;
};

template <class Border>
Run run_dcp(Mesh& mesh, Border border)
{
  typedef std::chrono::steady_clock Clock;
  Run r;
  auto uv = mesh.add_property_map<vertex_descriptor, K::Point_2>("v:bench_uv").first;
  SMP::Discrete_conformal_map_parameterizer_3<Mesh, Border, LU> dcp(border);
  const Clock::time_point start = Clock::now();
  r.status = SMP::parameterize(mesh, dcp, CGAL::Polygon_mesh_processing::longest_border(mesh).first, uv);
  r.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  if(r.status == SMP::OK)
    r.quality = SMP::measure_quality(mesh, faces(mesh), uv);
  mesh.remove_property_map(uv);
  return r;
}

using mbp_benchmark::not_a_disk;

} // namespace

int main(int argc, char** argv)
{
  const std::string dir = (argc > 1) ? argv[1] : MBP_MESH_DIR;
  const std::vector<std::filesystem::path> files = mbp_benchmark::mesh_files_in(dir);
  if(files.empty())
  {
    std::cerr << "error: no mesh in '" << dir << "'\n";
    return 1;
  }

  std::printf("| mesh | V | F | border | angle dist. DCP circle | angle dist. DCP measured | ratio |"
              " L2 circle | L2 measured | flips circle | flips measured | measured convex |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  std::vector<std::string> skipped;
  for(const auto& path : files)
  {
    Mesh mesh;
    if(!CGAL::IO::read_polygon_mesh(path.string(), mesh) || faces(mesh).empty())
    {
      skipped.push_back(path.filename().string() + " (not readable as a polygon mesh)");
      continue;
    }
    const std::string why = not_a_disk(mesh);
    if(!why.empty())
    {
      skipped.push_back(path.filename().string() + " (" + why + ")");
      continue;
    }
    const Run m = run_dcp(mesh, Measured());
    // whether the measured polygon is convex: the report of the border parameterizer called
    // alone (the copy inside the DCP cannot be asked)
    SMP::Parameterization_report report;
    {
      auto uv = mesh.add_property_map<vertex_descriptor, K::Point_2>("v:bench_border_uv").first;
      auto done = mesh.add_property_map<vertex_descriptor, bool>("v:bench_border_done", false).first;
      Measured().parameterize(mesh, CGAL::Polygon_mesh_processing::longest_border(mesh).first, uv,
                              CGAL::Identity_property_map<vertex_descriptor>(), done, &report);
      mesh.remove_property_map(uv);
      mesh.remove_property_map(done);
    }
    const Run c = run_dcp(mesh, Circle());
    const std::size_t border = CGAL::Polygon_mesh_processing::longest_border(mesh).second > 0
                                 ? halfedges_around_face(CGAL::Polygon_mesh_processing::longest_border(mesh).first, mesh).size()
                                 : 0;
    if(m.status != SMP::OK || c.status != SMP::OK)
    {
      std::printf("| %s | %zu | %zu | %zu | %s | %s | - | - | - | - | - | - |\n", path.filename().string().c_str(),
                  std::size_t(num_vertices(mesh)), std::size_t(num_faces(mesh)), border, SMP::get_measured_error_message(c.status),
                  SMP::get_measured_error_message(m.status));
      continue;
    }
    std::printf("| %s | %zu | %zu | %zu | %.4f | %.4f | %.2f | %.4f | %.4f | %zu | %zu | %s |\n",
                path.filename().string().c_str(), std::size_t(num_vertices(mesh)), std::size_t(num_faces(mesh)), border,
                c.quality.angle_distortion, m.quality.angle_distortion,
                m.quality.angle_distortion / c.quality.angle_distortion,
                c.quality.l2_stretch, m.quality.l2_stretch, c.quality.flipped_faces, m.quality.flipped_faces,
                report.border_convex ? "yes" : "no");
    std::fflush(stdout);
  }
  for(const std::string& s : skipped)
    std::printf("skipped: %s\n", s.c_str());
  return 0;
}
