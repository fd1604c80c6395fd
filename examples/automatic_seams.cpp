// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// Parameterizing a closed surface without a seam file: compute_disk_seams() cuts the mesh
// into a topological disk (through a few cone vertices on a surface of genus 0, along 2g
// loops on a surface of genus g, joining the holes of a surface with border), CGAL::Seam_mesh
// cuts it open along those seams, and Conformal_parameterizer_3 flattens it with the conformal
// border (Boundary First Flattening's border with scale factor 0 along the cut).
//
//   automatic_seams [INPUT] [OUTPUT.obj] [CONES]
//
// Defaults: CGAL's bear.off (closed, genus 0), automatic_seams.obj, and the default number
// of cones (Disk_seams_options::default_number_of_cones). The program prints the seams, the
// cones and the distortion, writes the OBJ (one 'vt' per seam mesh vertex: a vertex on a
// seam gets one UV per side of the cut), and exits with a failure when the result is not
// valid: the cut is not a disk, a face is flipped or two UV triangles overlap.
//
// Area distortion: log(A_uv / A_3D) per face; its area-weighted standard deviation does not
// depend on the global scale of the layout (0 for a map that scales every face alike).

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Seam_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <CGAL/Surface_mesh_parameterization/Conformal_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/compute_disk_seams.h>
#include <CGAL/Surface_mesh_parameterization/measure_quality.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#ifndef MBP_AUTOMATIC_SEAMS_MESH
#define MBP_AUTOMATIC_SEAMS_MESH "bear.off"
#endif

typedef CGAL::Simple_cartesian<double>                               Kernel;
typedef Kernel::Point_2                                              Point_2;
typedef Kernel::Point_3                                              Point_3;
typedef CGAL::Surface_mesh<Point_3>                                  Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor                 SM_vertex_descriptor;
typedef boost::graph_traits<Mesh>::halfedge_descriptor               SM_halfedge_descriptor;
typedef boost::graph_traits<Mesh>::edge_descriptor                   SM_edge_descriptor;

typedef Mesh::Property_map<SM_edge_descriptor, bool>                 Seam_edge_pmap;
typedef Mesh::Property_map<SM_vertex_descriptor, bool>               Seam_vertex_pmap;
typedef CGAL::Seam_mesh<Mesh, Seam_edge_pmap, Seam_vertex_pmap>      Seam_mesh;
typedef boost::graph_traits<Seam_mesh>::vertex_descriptor            vertex_descriptor;
typedef boost::graph_traits<Seam_mesh>::halfedge_descriptor          halfedge_descriptor;
typedef boost::graph_traits<Seam_mesh>::face_descriptor              face_descriptor;
typedef boost::property_map<Seam_mesh, CGAL::dynamic_vertex_property_t<Point_2> >::type UV_map;

namespace SMP = CGAL::Surface_mesh_parameterization;
typedef SMP::Conformal_parameterizer_3<Seam_mesh, SMP::Conformal_border> Parameterizer;

// The area-weighted standard deviation of log(A_uv / A_3D) over the faces.
double log_area_ratio_deviation(const Seam_mesh& sm, UV_map uvmap)
{
  std::vector<std::pair<double, double> > areas;  // (3D, UV)
  double total = 0., mean = 0.;
  for(face_descriptor f : faces(sm))
  {
    const halfedge_descriptor h = halfedge(f, sm);
    const vertex_descriptor a = target(h, sm), b = target(next(h, sm), sm), c = source(h, sm);
    const auto vpm = get(CGAL::vertex_point, sm);
    const double a3 = std::sqrt(CGAL::squared_area(get(vpm, a), get(vpm, b), get(vpm, c)));
    const double auv = std::abs(CGAL::area(get(uvmap, a), get(uvmap, b), get(uvmap, c)));
    if(!(a3 > 0.) || !(auv > 0.))
      return std::numeric_limits<double>::infinity();
    areas.emplace_back(a3, auv);
    total += a3;
    mean += a3 * std::log(auv / a3);
  }
  mean /= total;
  double variance = 0.;
  for(const auto& a : areas)
    variance += a.first * std::pow(std::log(a.second / a.first) - mean, 2);
  return std::sqrt(variance / total);
}

// 1. The seams, written into the two maps that CGAL::Seam_mesh reads; the report names the
// cones by their position in vertices(mesh), here their index (a mesh just read).
bool compute_seams(const std::string& input, const Mesh& mesh, const SMP::Disk_seams_options& options,
                   Seam_edge_pmap seam_edges, Seam_vertex_pmap seam_vertices, SMP::Disk_seams_report& seams)
{
  if(SMP::compute_disk_seams(mesh, seam_edges, seam_vertices, options, &seams) != SMP::OK)
  {
    std::cerr << "error: " << input << ": " << SMP::disk_seams_problem_message(seams.problem) << "\n";
    return false;
  }
  std::cout << input << ": " << num_vertices(mesh) << " vertices, " << num_faces(mesh) << " faces, genus "
            << seams.genus << ", " << seams.number_of_border_loops << " border loops\n"
            << "seams: " << seams.number_of_seam_edges << " edges, length " << seams.seam_length << ", "
            << seams.number_of_loops << (seams.number_of_border_loops > 0 ? " arcs" : " loops") << ", "
            << seams.cones.size() << " cones (" << seams.seconds << " s)\n";
  for(std::size_t c : seams.cones)
    std::cout << "  cone at vertex " << c << " (" << mesh.point(SM_vertex_descriptor(Mesh::size_type(c))) << ")\n";
  return true;
}

// 3.-4. The flattening of the disk, checked: no flipped face, one-to-one.
bool flatten(Seam_mesh& seam_mesh, UV_map uvmap)
{
  const halfedge_descriptor bhd = CGAL::Polygon_mesh_processing::longest_border(seam_mesh).first;
  SMP::Parameterization_report report;
  const SMP::Error_code status = SMP::parameterize(seam_mesh, Parameterizer(), bhd, uvmap, &report);
  if(status != SMP::OK)
  {
    std::cerr << "error: " << SMP::get_measured_error_message(status) << "\n";
    return false;
  }
  const SMP::Parameterization_quality quality = SMP::measure_quality(seam_mesh, faces(seam_mesh), uvmap);
  const bool one_to_one = SMP::is_one_to_one_uv_map(seam_mesh, faces(seam_mesh), uvmap);
  std::cout << "flattening: " << report.total_seconds << " s; angle distortion " << quality.angle_distortion
            << ", area distortion (deviation of log area ratios) " << log_area_ratio_deviation(seam_mesh, uvmap)
            << ", flipped faces " << quality.flipped_faces << ", one-to-one: " << (one_to_one ? "yes" : "no") << "\n";
  if(quality.flipped_faces == 0 && one_to_one)
    return true;
  std::cerr << "error: the UV map is not one-to-one\n";
  return false;
}

// 5. The OBJ: 'v' lines are the mesh vertices, 'vt' lines the seam mesh vertices (in the order
// of their mesh vertex).
bool write_obj(const std::string& output, const std::string& comment, const Seam_mesh& seam_mesh, UV_map uvmap)
{
  const Mesh& mesh = seam_mesh.mesh();
  auto mesh_index = [&mesh](vertex_descriptor v) { return std::size_t(target(SM_halfedge_descriptor(v), mesh)); };
  std::vector<std::pair<std::size_t, vertex_descriptor> > uv_order;
  for(vertex_descriptor v : vertices(seam_mesh))
    uv_order.emplace_back(mesh_index(v), v);
  std::stable_sort(uv_order.begin(), uv_order.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  auto vt_index = get(CGAL::dynamic_vertex_property_t<std::size_t>(), seam_mesh);
  for(std::size_t i = 0; i < uv_order.size(); ++i)
    put(vt_index, uv_order[i].second, i + 1);
  std::ofstream out(output);
  out.precision(17);
  out << "# " << comment << "\n";
  for(SM_vertex_descriptor v : vertices(mesh))
    out << "v " << mesh.point(v) << "\n";
  for(const auto& u : uv_order)
    out << "vt " << get(uvmap, u.second) << "\n";
  for(face_descriptor f : faces(seam_mesh))
  {
    out << "f";
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, seam_mesh), seam_mesh))
      out << " " << mesh_index(target(h, seam_mesh)) + 1 << "/" << get(vt_index, target(h, seam_mesh));
    out << "\n";
  }
  out.close();
  return !out.fail();
}

int main(int argc, char** argv)
{
  if(argc > 4)
  {
    std::cerr << "usage: automatic_seams [INPUT] [OUTPUT.obj] [CONES]\n";
    return EXIT_FAILURE;
  }
  const std::string input = (argc > 1) ? argv[1] : MBP_AUTOMATIC_SEAMS_MESH;
  const std::string output = (argc > 2) ? argv[2] : "automatic_seams.obj";
  SMP::Disk_seams_options options;
  if(argc > 3)
    options.number_of_cones = std::atoi(argv[3]);
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(input, mesh) || faces(mesh).empty())
  {
    std::cerr << "error: cannot read a polygon mesh from '" << input << "'\n";
    return EXIT_FAILURE;
  }
  Seam_edge_pmap seam_edges = mesh.add_property_map<SM_edge_descriptor, bool>("e:on_seam", false).first;
  Seam_vertex_pmap seam_vertices = mesh.add_property_map<SM_vertex_descriptor, bool>("v:on_seam", false).first;
  SMP::Disk_seams_report seams;
  if(!compute_seams(input, mesh, options, seam_edges, seam_vertices, seams))
    return EXIT_FAILURE;
  // 2. The mesh cut open: the seam mesh counts the seams it is told about.
  Seam_mesh seam_mesh(mesh, seam_edges, seam_vertices);
  seam_mesh.set_seam_edges_number(seams.number_of_seam_edges);
  UV_map uvmap = get(CGAL::dynamic_vertex_property_t<Point_2>(), seam_mesh);
  if(!flatten(seam_mesh, uvmap))
    return EXIT_FAILURE;
  if(!write_obj(output, input + " cut along " + std::to_string(seams.number_of_seam_edges) + " automatic seam edges",
                seam_mesh, uvmap))
  {
    std::cerr << "error: cannot write '" << output << "'\n";
    std::remove(output.c_str());
    return EXIT_FAILURE;
  }
  std::cout << "wrote " << output << "\n";
  return EXIT_SUCCESS;
}
