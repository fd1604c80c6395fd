// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// A packed texture atlas of any mesh file, as a user has it: compute_atlas_of_polygon_soup()
// repairs the polygon soup (several components, polygons, misoriented or non-manifold faces),
// flattens every component into one or more charts and packs them into the unit square.
//
//   texture_atlas [INPUT] [OUTPUT.obj] [RESOLUTION] [GUTTER]
//
// Reads any format CGAL reads (default: CGAL's blobby_3cc.off, three components), writes an
// OBJ with the input's points and polygons, one texture coordinate per polygon corner and one
// group per chart (default: texture_atlas.obj), and prints what was repaired and the charts.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/IO/polygon_soup_io.h>

#include <CGAL/Surface_mesh_parameterization/Atlas_report.h>
#include <CGAL/Surface_mesh_parameterization/compute_atlas.h>
#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>

#include <cstddef>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Simple_cartesian<double> Kernel;
typedef Kernel::Point_3                Point_3;
typedef Kernel::Point_2                Point_2;

namespace SMP = CGAL::Surface_mesh_parameterization;

// The OBJ: the input's points and polygons, a texture coordinate per corner, a group per chart.
bool write_obj(const std::string& file, const std::vector<Point_3>& points,
               const std::vector<std::vector<std::size_t> >& polygons,
               const std::vector<std::vector<Point_2> >& uvs, const std::vector<std::size_t>& charts)
{
  std::ofstream out(file);
  out.precision(17);
  for(const Point_3& p : points)
    out << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  for(const std::vector<Point_2>& polygon : uvs)
    for(const Point_2& uv : polygon)
      out << "vt " << uv.x() << ' ' << uv.y() << '\n';
  std::size_t corner = 1;
  for(std::size_t p = 0; p < polygons.size(); ++p)
  {
    if(p == 0 || charts[p] != charts[p - 1])
      out << "g chart_" << charts[p] << '\n';
    out << 'f';
    for(std::size_t v : polygons[p])
      out << ' ' << v + 1 << '/' << corner++;
    out << '\n';
  }
  return bool(out);
}

void print_report(const SMP::Atlas_report& r)
{
  const SMP::Soup_repair_report& repair = r.repair;
  std::cout << "input: " << repair.input_points << " points, " << repair.input_polygons << " polygons\n"
            << "repaired: " << repair.merged_points << " points merged, " << repair.reoriented_polygons
            << " polygons reoriented, " << repair.triangulated_polygons << " polygons triangulated, "
            << repair.pinched_vertices + repair.non_manifold_edges << " non-manifold places split, "
            << repair.zero_area_triangles << " zero-area triangles set aside\n"
            << "atlas: " << repair.components << " components, " << r.charts.size() << " charts, utilization "
            << r.utilization << ", angle distortion " << r.angle_distortion << ", area spread " << r.area_spread
            << ", " << r.total_seconds << " s\n";
  const char* kinds[] = {"disk", "cut along seams", "unfolded"};
  for(std::size_t c = 0; c < r.charts.size() && c < 10; ++c)
    std::cout << "  chart " << c << ": " << r.charts[c].faces << " faces, " << kinds[r.charts[c].flattening]
              << ", angle distortion " << r.charts[c].angle_distortion << '\n';
}

int main(int argc, char** argv)
{
  const std::string input = (argc > 1) ? argv[1] : MBP_ATLAS_DEFAULT_MESH;
  const std::string output = (argc > 2) ? argv[2] : "texture_atlas.obj";
  SMP::Atlas_options options;
  if(argc > 3)
    options.resolution = unsigned(std::stoul(argv[3]));
  if(argc > 4)
    options.gutter = unsigned(std::stoul(argv[4]));

  std::vector<Point_3> points;
  std::vector<std::vector<std::size_t> > polygons;
  if(!CGAL::IO::read_polygon_soup(input, points, polygons) || polygons.empty())
  {
    std::cerr << "error: cannot read a polygon soup from '" << input << "'\n";
    return EXIT_FAILURE;
  }

  std::vector<std::vector<Point_2> > uvs;  // per polygon, per corner
  std::vector<std::size_t> charts;         // per polygon
  SMP::Atlas_report report;
  const SMP::Error_code status = SMP::compute_atlas_of_polygon_soup(points, polygons, uvs, charts, options, &report);
  if(status != SMP::OK)
  {
    std::cerr << "error: " << SMP::get_measured_error_message(status) << '\n';
    return EXIT_FAILURE;
  }
  print_report(report);
  if(!write_obj(output, points, polygons, uvs, charts))
  {
    std::cerr << "error: cannot write '" << output << "'\n";
    return EXIT_FAILURE;
  }
  std::cout << "wrote " << output << '\n';
  return EXIT_SUCCESS;
}
