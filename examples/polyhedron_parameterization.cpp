// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// The complete method of the paper on a CGAL::Polyhedron_3: Measured_conformal_parameterizer_3
// finds the center, measures the border, lays it out as a polar map and solves the discrete
// conformal interior, with one factorization shared by the first and the last step.
//
//   polyhedron_parameterization [INPUT] [OUTPUT.off]
//
// Reads a disk-like triangle mesh (default: CGAL's nefertiti.off), writes the UV
// layout as an OFF file (default: polyhedron_parameterization.off), and prints the report of
// the call (center, time of every stage, factorizations) and the quality of the map.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/IO/File_off.h>

#include <CGAL/Surface_mesh_parameterization/Measured_conformal_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_report.h>
#include <CGAL/Surface_mesh_parameterization/measure_quality.h>

#include <cstddef>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>

typedef CGAL::Simple_cartesian<double>                           Kernel;
typedef CGAL::Polyhedron_3<Kernel>                               Polyhedron;
typedef boost::graph_traits<Polyhedron>::vertex_descriptor       vertex_descriptor;
typedef boost::graph_traits<Polyhedron>::halfedge_descriptor     halfedge_descriptor;

namespace SMP = CGAL::Surface_mesh_parameterization;

int main(int argc, char** argv)
{
  const std::string input = (argc > 1) ? argv[1] : MBP_DEFAULT_MESH;
  const std::string output = (argc > 2) ? argv[2] : "polyhedron_parameterization.off";

  Polyhedron mesh;
  if(!CGAL::IO::read_polygon_mesh(input, mesh) || faces(mesh).empty())
  {
    std::cerr << "error: cannot read a polygon mesh from '" << input << "'\n";
    return EXIT_FAILURE;
  }

  // The border to measure: the longest border loop (the others, if any, are holes).
  const halfedge_descriptor bhd = CGAL::Polygon_mesh_processing::longest_border(mesh).first;

  // Polyhedron_3 has no built-in property maps: a dynamic property map holds the UVs.
  auto uvmap = get(CGAL::dynamic_vertex_property_t<Kernel::Point_2>(), mesh);

  // Default policies: the center is the maximum of the boundary Poisson distance map, the
  // border distances are the Poisson distance map from the center (the paper's MBPPP).
  // The report of the call is an optional out-argument.
  SMP::Measured_conformal_parameterizer_3<Polyhedron> parameterizer;
  SMP::Parameterization_report report;
  const SMP::Error_code status = SMP::parameterize(mesh, parameterizer, bhd, uvmap, &report);
  if(status != SMP::OK)
  {
    std::cerr << "error: " << SMP::get_measured_error_message(status) << "\n";
    return EXIT_FAILURE;
  }

  // The report names the center by its position in vertices(mesh).
  const vertex_descriptor center = *std::next(vertices(mesh).begin(), std::ptrdiff_t(report.center));
  std::cout << input << ": " << report.vertices << " vertices, " << report.faces << " faces\n"
            << "center: " << center->point() << "\n"
            << "border: " << report.border_uv.size() << " vertices\n"
            << "stages (s): preparation " << report.preparation_seconds
            << ", 1 center " << report.center_seconds
            << ", 2 distances " << report.distance_seconds
            << ", 3 border map " << report.border_map_seconds
            << ", 4 interior " << report.interior_seconds
            << ", repair check " << report.repair_seconds
            << ", output " << report.output_seconds
            << ", total " << report.total_seconds << "\n"
            << "solver: " << report.statistics.factorizations << " factorizations ("
            << report.statistics.factorization_seconds << " s), " << report.statistics.back_substitutions
            << " back-substitutions (" << report.statistics.back_substitution_seconds << " s)\n";
  if(report.repaired)
    std::cout << "repair: " << report.flipped_faces_before_repair << " flipped faces; border blended toward a circle"
              << " by " << report.blend << ", " << (report.mean_value_interior ? "mean value" : "discrete conformal")
              << " interior\n";
  else
    std::cout << "repair: none needed\n";

  // The quality of the map (measure_quality.h) and the global overlap test.
  const SMP::Parameterization_quality q = SMP::measure_quality(mesh, faces(mesh), uvmap);
  std::cout << "angle distortion " << q.angle_distortion << " (per corner " << q.angle_distortion_per_corner
            << "), quasi-conformal mean " << q.quasi_conformal_mean << " max " << q.quasi_conformal_max
            << ", L2 stretch " << q.l2_stretch << ", Linf stretch " << q.linf_stretch
            << ", flipped faces " << q.flipped_faces << "\n";
  if(!SMP::is_one_to_one_uv_map(mesh, faces(mesh), uvmap))
  {
    std::cerr << "error: the UV map is not one-to-one\n";
    return EXIT_FAILURE;
  }

  std::ofstream out(output);
  SMP::IO::output_uvmap_to_off(mesh, bhd, uvmap, out);
  if(!out)
  {
    std::cerr << "error: cannot write '" << output << "'\n";
    return EXIT_FAILURE;
  }
  std::cout << "UV layout written to " << output << "\n";
  return EXIT_SUCCESS;
}
