// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// Choosing the policies of Conformal_parameterizer_3: the border policy (measured, conformal,
// circle, automatic), and for the measured border how the center is located and how the
// border distances are measured; the sparse solver. Each configuration flattens the same
// mesh; the program prints a table of center, angle distortion and time.
//
//   choosing_policies [INPUT] [OUTPUT.off]
//
// Default input: CGAL's nefertiti.off (CGAL's data meshes, Debian package libcgal-demo).
// The OFF file (default: choosing_policies.off) is the UV layout of the automatic border.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/IO/File_off.h>

#include <CGAL/Surface_mesh_parameterization/Conformal_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Fixed_center.h>
#include <CGAL/Surface_mesh_parameterization/Geodesic_border_distance.h>
#include <CGAL/Surface_mesh_parameterization/Geodesic_center_locator.h>
#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_report.h>
#include <CGAL/Surface_mesh_parameterization/Straightest_geodesic_border_distance.h>
#include <CGAL/Surface_mesh_parameterization/geodesic_method_tags.h>
#include <CGAL/Surface_mesh_parameterization/measure_quality.h>
#ifdef MBP_WITH_CHOLMOD
#include <CGAL/Surface_mesh_parameterization/Cholmod_supernodal_cholesky_traits.h>
#endif

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>

typedef CGAL::Simple_cartesian<double>                           Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3>                      Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor             vertex_descriptor;
typedef boost::graph_traits<Mesh>::halfedge_descriptor           halfedge_descriptor;
typedef Mesh::Property_map<vertex_descriptor, Kernel::Point_2>   UV_map;

namespace SMP = CGAL::Surface_mesh_parameterization;

// Runs `parameterizer` on the mesh, prints one row of the table and returns the report.
template <class Parameterizer>
SMP::Parameterization_report run(const char* name, Mesh& mesh, halfedge_descriptor bhd,
                                 const Parameterizer& parameterizer, UV_map uvmap)
{
  SMP::Parameterization_report report;
  if(SMP::parameterize(mesh, parameterizer, bhd, uvmap, &report) != SMP::OK)
  {
    std::printf("%-42s failed: %s\n", name, SMP::get_measured_error_message(report.status));
    return report;
  }
  const SMP::Parameterization_quality q = SMP::measure_quality(mesh, faces(mesh), uvmap);
  const std::string center = report.has_center ? std::to_string(report.center) : "-";
  std::printf("%-42s %8s %10.4f %6zu %8s %9.4f\n", name, center.c_str(), q.angle_distortion, q.flipped_faces,
              report.repaired ? "yes" : "no", report.total_seconds);
  return report;
}

int main(int argc, char** argv)
{
  const std::string input = (argc > 1) ? argv[1] : MBP_DEFAULT_MESH;
  const std::string output = (argc > 2) ? argv[2] : "choosing_policies.off";

  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(input, mesh) || faces(mesh).empty())
  {
    std::cerr << "error: cannot read a polygon mesh from '" << input << "'\n";
    return EXIT_FAILURE;
  }
  const halfedge_descriptor bhd = CGAL::Polygon_mesh_processing::longest_border(mesh).first;
  UV_map uvmap = mesh.add_property_map<vertex_descriptor, Kernel::Point_2>("v:uv").first;

  std::cout << input << ": " << num_vertices(mesh) << " vertices, " << num_faces(mesh) << " faces\n";
  std::printf("%-42s %8s %10s %6s %8s %9s\n", "configuration", "center", "angle dist", "flips", "repaired",
              "time (s)");
  int failures = 0;

  // 1. The paper's MBPPP: the measured border with its default policies, Poisson_center_locator
  //    and Poisson_border_distance; Eigen's LDLT.
  SMP::Measured_conformal_parameterizer_3<Mesh> measured;
  const SMP::Parameterization_report mbppp = run("1 measured: Poisson (MBPPP)", mesh, bhd, measured, uvmap);
  failures += mbppp.status != SMP::OK;

  // 2. Geodesic border distances by fast marching (the paper's MBPGP). The method is a tag
  //    of geodesic_method_tags.h: Fast_marching_geodesics, Dijkstra_geodesics,
  //    Heat_method_geodesics<> or Exact_geodesics.
  typedef SMP::Geodesic_border_distance<SMP::Fast_marching_geodesics> Fast_marching_distance;
  SMP::Measured_conformal_parameterizer_3<Mesh, SMP::Poisson_center_locator, Fast_marching_distance> mbpgp;
  failures += run("2 measured: fast marching (MBPGP)", mesh, bhd, mbpgp, uvmap).status != SMP::OK;

  // 3. The center at the maximum of the geodesic distance from the border (heat method),
  //    exact geodesic distances to the border.
  typedef SMP::Geodesic_center_locator<SMP::Heat_method_geodesics<> > Heat_center;
  typedef SMP::Geodesic_border_distance<SMP::Exact_geodesics>         Exact_distance;
  SMP::Measured_conformal_parameterizer_3<Mesh, Heat_center, Exact_distance> geodesic;
  failures += run("3 measured: heat center + exact geodesics", mesh, bhd, geodesic, uvmap).status != SMP::OK;

  // 4. A center given by the user (here the center of run 1) and straightest geodesics
  //    (MBPSGP), which can miss a border vertex: the report counts the vertices not reached.
  typedef SMP::Measured_border<SMP::Fixed_center<Mesh>, SMP::Straightest_geodesic_border_distance> Straightest;
  const SMP::Conformal_parameterizer_3<Mesh, Straightest> mbpsgp(
    Straightest(SMP::Fixed_center<Mesh>(Mesh::Vertex_index(mbppp.center))));
  const SMP::Parameterization_report straightest =
    run("4 measured: fixed center + straightest", mesh, bhd, mbpsgp, uvmap);
  if(straightest.status == SMP::ERROR_DISTANCE_COMPUTATION_FAILED)
    std::cout << "  (expected on some meshes: " << straightest.unreachable_border_vertices
              << " border vertices not reached)\n";

  // 5. CHOLMOD's supernodal Cholesky for every system (the solver traits parameter).
#ifdef MBP_WITH_CHOLMOD
  SMP::Measured_conformal_parameterizer_3<Mesh, SMP::Poisson_center_locator, SMP::Poisson_border_distance,
                                          SMP::Cholmod_supernodal_cholesky_traits> cholmod;
  failures += run("5 measured (MBPPP) with CHOLMOD", mesh, bhd, cholmod, uvmap).status != SMP::OK;
#else
  std::printf("%-42s (built without CHOLMOD)\n", "5 measured (MBPPP) with CHOLMOD");
#endif

  // 6. Another border policy: the conformal border (Boundary First Flattening's border with
  //    scale factors 0). Circular_border is CGAL's circle.
  SMP::Conformal_parameterizer_3<Mesh, SMP::Conformal_border> conformal;
  failures += run("6 conformal border", mesh, bhd, conformal, uvmap).status != SMP::OK;

  // 7. The default border policy, Automatic_border<>: the best of the circle, the measured
  //    and the conformal border by angle distortion. Run last: its UVs are written out.
  SMP::Conformal_parameterizer_3<Mesh> automatic;
  const SMP::Parameterization_report report = run("7 automatic border (the default)", mesh, bhd, automatic, uvmap);
  if(report.status != SMP::OK)
    return EXIT_FAILURE;
  // every layout tried by the automatic border, in the order tried, and the kept one
  const char* family_names[] = {"circle", "measured", "conformal", "conformal-lengths"};
  for(std::size_t i = 0; i < report.border_candidates.size(); ++i)
  {
    const SMP::Border_candidate& c = report.border_candidates[i];
    std::printf("    %-10s t = %.4f  %s  angle distortion %.4f%s\n", family_names[c.family], c.blend,
                c.valid ? "valid  " : "invalid", c.objective, int(i) == report.chosen_candidate ? "  <- kept" : "");
  }

  std::ofstream out(output);
  SMP::IO::output_uvmap_to_off(mesh, bhd, uvmap, out);
  std::cout << (out ? "UV layout of the automatic border written to " : "error: cannot write ") << output << "\n";
  return (failures == 0 && out) ? EXIT_SUCCESS : EXIT_FAILURE;
}
