// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// The measured border as a drop-in border parameterizer of CGAL's discrete conformal map.
//
//   measured_border_dcp [INPUT] [OUTPUT.off]
//
// Reads a disk-like triangle mesh (default: CGAL's nefertiti.off), flattens it
// with CGAL's Discrete_conformal_map_parameterizer_3 using the measured border of the paper
// "Measured boundary parameterization based on Poisson's equation", writes the UV layout as
// an OFF file (default: measured_border_dcp.off), and compares the angle distortion with
// CGAL's default circular border.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/property_map.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_conformal_map_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/IO/File_off.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <CGAL/Surface_mesh_parameterization/Measured_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_report.h>
#include <CGAL/Surface_mesh_parameterization/measure_quality.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>

typedef CGAL::Simple_cartesian<double>                           Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3>                      Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor             vertex_descriptor;
typedef boost::graph_traits<Mesh>::halfedge_descriptor           halfedge_descriptor;

namespace SMP = CGAL::Surface_mesh_parameterization;

int main(int argc, char** argv)
{
  const std::string input = (argc > 1) ? argv[1] : MBP_DEFAULT_MESH;
  const std::string output = (argc > 2) ? argv[2] : "measured_border_dcp.off";

  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(input, mesh) || faces(mesh).empty())
  {
    std::cerr << "error: cannot read a polygon mesh from '" << input << "'\n";
    return EXIT_FAILURE;
  }
  const halfedge_descriptor bhd = CGAL::Polygon_mesh_processing::longest_border(mesh).first;
  auto uvmap = mesh.add_property_map<vertex_descriptor, Kernel::Point_2>("v:uv").first;

  // The measured border inside CGAL's DCP: a drop-in for CGAL's circular border
  // parameterizers (the DCP keeps its own copy of the border parameterizer).
  typedef SMP::Measured_border_parameterizer_3<Mesh> Border;
  SMP::Discrete_conformal_map_parameterizer_3<Mesh, Border> dcp;
  const SMP::Error_code status = SMP::parameterize(mesh, dcp, bhd, uvmap);
  if(status != SMP::OK)
  {
    std::cerr << "error: " << SMP::get_measured_error_message(status) << "\n";
    return EXIT_FAILURE;
  }
  // CGAL's parameterizers return OK whatever the layout: a measured border is star-shaped but
  // not always convex, so the discrete conformal interior can fold. Check the result (the
  // global test: no flipped triangle, no two overlapping triangles).
  const SMP::Parameterization_quality measured = SMP::measure_quality(mesh, faces(mesh), uvmap);
  if(!SMP::is_one_to_one_uv_map(mesh, faces(mesh), uvmap))
  {
    std::cerr << "error: the layout is not one-to-one (" << measured.flipped_faces << " flipped faces); "
              << "Measured_conformal_parameterizer_3 repairs such layouts\n";
    return EXIT_FAILURE;
  }

  // The border parameterizer can also run alone, with the report of its call (the center,
  // the measured distances, the polygon). CGAL's DCP calls it without a report. The report
  // names the center by its position in vertices(mesh): its index in a Surface_mesh without
  // removed vertices. Poisson_border_distance measures in values of the paper's Eq. 1, not
  // in lengths: only their ratios shape the border.
  SMP::Parameterization_report report;
  auto border_uv = mesh.add_property_map<vertex_descriptor, Kernel::Point_2>("v:border_uv").first;
  auto border_done = mesh.add_property_map<vertex_descriptor, bool>("v:border_done", false).first;
  Border().parameterize(mesh, bhd, border_uv, CGAL::Identity_property_map<vertex_descriptor>(), border_done, &report);
  std::cout << input << ": " << num_vertices(mesh) << " vertices, center " << Mesh::Vertex_index(report.center)
            << " at " << mesh.point(Mesh::Vertex_index(report.center)) << ", border of " << report.border_uv.size()
            << " vertices (" << (report.border_convex ? "convex" : "not convex") << "), measured distances from "
            << *std::min_element(report.border_distances.begin(), report.border_distances.end()) << " to "
            << *std::max_element(report.border_distances.begin(), report.border_distances.end()) << "\n";

  std::ofstream out(output);
  SMP::IO::output_uvmap_to_off(mesh, bhd, uvmap, out);
  if(!out)
  {
    std::cerr << "error: cannot write '" << output << "'\n";
    return EXIT_FAILURE;
  }

  // The same with CGAL's default border, for comparison.
  auto circle_uv = mesh.add_property_map<vertex_descriptor, Kernel::Point_2>("v:circle_uv").first;
  SMP::Discrete_conformal_map_parameterizer_3<Mesh> circle_dcp;
  if(SMP::parameterize(mesh, circle_dcp, bhd, circle_uv) != SMP::OK)
    return EXIT_FAILURE;
  const SMP::Parameterization_quality circle = SMP::measure_quality(mesh, faces(mesh), circle_uv);

  std::cout << "angle distortion: measured border " << measured.angle_distortion << ", circle "
            << circle.angle_distortion << "\n"
            << "L2 stretch:       measured border " << measured.l2_stretch << ", circle " << circle.l2_stretch << "\n"
            << "flipped faces:    measured border " << measured.flipped_faces << ", circle "
            << circle.flipped_faces << "\n"
            << "UV layout written to " << output << "\n";
  return EXIT_SUCCESS;
}
