// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// Choosing the policies of Measured_conformal_parameterizer_3: how the center is located,
// how the border distances are measured, which sparse solver factorizes the systems, and the
// automatic border. Each configuration flattens the same mesh; the program prints a table of
// center, angle distortion and time.
//
//   choosing_policies [INPUT] [OUTPUT.off]
//
// Default input: CGAL's nefertiti.off (CGAL's data meshes, Debian package libcgal-demo).
// The OFF file (default: choosing_policies.off) is the UV layout of the automatic border.
//
// Configurations:
//   1. the paper's MBPPP (the defaults): Poisson center + Poisson border distances
//   2. the paper's MBPGP: Poisson center + fast marching geodesic distances
//   3. geodesic center (CGAL's heat method) + exact geodesic distances
//   4. a center chosen by the user (Fixed_center) + straightest geodesics (MBPSGP), which
//      can fail to reach a border vertex: the policy then names it
//   5. the defaults with CHOLMOD's supernodal Cholesky (only when built with MBP_WITH_CHOLMOD,
//      CMake target MeasuredParameterization::Cholmod)
//   6. the automatic border: the best of a family of borders (circle, measured borders and
//      their blends toward the circle) by angle distortion

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/IO/File_off.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <CGAL/Surface_mesh_parameterization/Measured_conformal_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/Fixed_center.h>
#include <CGAL/Surface_mesh_parameterization/Geodesic_border_distance.h>
#include <CGAL/Surface_mesh_parameterization/Geodesic_center_locator.h>
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
#include <limits>
#include <string>

typedef CGAL::Simple_cartesian<double>                           Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3>                      Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor             vertex_descriptor;
typedef boost::graph_traits<Mesh>::halfedge_descriptor           halfedge_descriptor;
typedef Mesh::Property_map<vertex_descriptor, Kernel::Point_2>   UV_map;

namespace SMP = CGAL::Surface_mesh_parameterization;

// Runs `parameterizer` on the mesh and prints one row of the table; returns the status.
template <class Parameterizer>
SMP::Error_code run(const char* name, Mesh& mesh, halfedge_descriptor bhd, Parameterizer& parameterizer,
                    UV_map uvmap)
{
  const SMP::Error_code status = SMP::parameterize(mesh, parameterizer, bhd, uvmap);
  if(status != SMP::OK)
  {
    std::printf("%-44s failed: %s\n", name, SMP::get_measured_error_message(status));
    return status;
  }
  const auto& report = parameterizer.last_report();
  const SMP::Parameterization_quality q = SMP::measure_quality(mesh, faces(mesh), uvmap);
  std::printf("%-44s %8zu %10.4f %6zu %8s %9.4f\n", name, std::size_t(parameterizer.center()),
              q.angle_distortion, q.flipped_faces, report.repaired ? "yes" : "no", report.total_seconds);
  return status;
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
  std::printf("%-44s %8s %10s %6s %8s %9s\n", "configuration", "center", "angle dist", "flips", "repaired",
              "time (s)");
  int failures = 0;

  // 1. The defaults: Poisson_center_locator + Poisson_border_distance, Eigen's LDLT.
  SMP::Measured_conformal_parameterizer_3<Mesh> mbppp;
  failures += run("1 Poisson center + Poisson border (MBPPP)", mesh, bhd, mbppp, uvmap) != SMP::OK;
  const vertex_descriptor poisson_center = mbppp.center();

  // 2. Geodesic border distances by fast marching (the paper's MBPGP). The method is a tag
  //    of geodesic_method_tags.h: Fast_marching_geodesics, Dijkstra_geodesics,
  //    Heat_method_geodesics<> or Exact_geodesics.
  typedef SMP::Geodesic_border_distance<Mesh, SMP::Fast_marching_geodesics> Fast_marching_border;
  SMP::Measured_conformal_parameterizer_3<Mesh, SMP::Poisson_center_locator<Mesh>, Fast_marching_border> mbpgp;
  failures += run("2 Poisson center + fast marching (MBPGP)", mesh, bhd, mbpgp, uvmap) != SMP::OK;

  // 3. The center at the maximum of the geodesic distance from the border (heat method),
  //    exact geodesic distances to the border.
  typedef SMP::Geodesic_center_locator<Mesh, SMP::Heat_method_geodesics<> > Heat_center;
  typedef SMP::Geodesic_border_distance<Mesh, SMP::Exact_geodesics>          Exact_border;
  SMP::Measured_conformal_parameterizer_3<Mesh, Heat_center, Exact_border> geodesic;
  failures += run("3 heat method center + exact geodesics", mesh, bhd, geodesic, uvmap) != SMP::OK;

  // 4. A center given by the user (here the Poisson center of run 1) and straightest
  //    geodesics. A straightest geodesic can miss its border vertex: the policy's
  //    last_failure() says which one (shared by the policy's copies, like the report).
  SMP::Straightest_geodesic_border_distance<Mesh> straightest;
  SMP::Measured_conformal_parameterizer_3<Mesh, SMP::Fixed_center<Mesh>, SMP::Straightest_geodesic_border_distance<Mesh> >
    mbpsgp(SMP::Fixed_center<Mesh>(poisson_center), straightest);
  if(run("4 fixed center + straightest geodesics", mesh, bhd, mbpsgp, uvmap) == SMP::ERROR_DISTANCE_COMPUTATION_FAILED)
    std::cout << "  (expected on some meshes: " << straightest.last_failure().unreachable
              << " border vertices unreachable, the first is vertex " << straightest.last_failure().vertex << ")\n";

  // 5. CHOLMOD's supernodal Cholesky for every system (the fourth template parameter).
#ifdef MBP_WITH_CHOLMOD
  SMP::Measured_conformal_parameterizer_3<Mesh, SMP::Poisson_center_locator<Mesh>, SMP::Poisson_border_distance<Mesh>,
                                          SMP::Cholmod_supernodal_cholesky_traits> cholmod;
  failures += run("5 defaults with CHOLMOD", mesh, bhd, cholmod, uvmap) != SMP::OK;
#else
  std::printf("%-44s (built without CHOLMOD)\n", "5 defaults with CHOLMOD");
#endif

  // 6. The automatic border, run last so that its UVs are the ones written out.
  SMP::Measured_conformal_parameterizer_3<Mesh> automatic;
  automatic.set_border_choice(SMP::Measured_conformal_parameterizer_3<Mesh>::AUTOMATIC_BORDER);
  const SMP::Error_code status = run("6 automatic border", mesh, bhd, automatic, uvmap);
  failures += status != SMP::OK;
  if(status == SMP::OK)
  {
    // every layout tried, in the order tried, and the kept one
    const auto& report = automatic.last_report();
    const char* family_names[] = {"circle", "measured", "conformal"};
    std::cout << "  automatic border: " << report.border_candidates.size() << " candidates in "
              << report.interior_seconds << " s\n";
    for(std::size_t i = 0; i < report.border_candidates.size(); ++i)
    {
      const auto& c = report.border_candidates[i];
      std::printf("    %-14s t = %.4f  %s  angle distortion %.4f%s\n", family_names[c.family], c.blend,
                  c.valid ? "valid  " : "invalid", c.valid ? c.objective : std::numeric_limits<double>::infinity(),
                  int(i) == report.chosen_candidate ? "  <- kept" : "");
    }

    std::ofstream out(output);
    SMP::IO::output_uvmap_to_off(mesh, bhd, uvmap, out);
    if(!out)
    {
      std::cerr << "error: cannot write '" << output << "'\n";
      return EXIT_FAILURE;
    }
    std::cout << "UV layout of the automatic border written to " << output << "\n";
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
