// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// Parameterizing a closed surface: the mesh is cut open along seams with CGAL::Seam_mesh and
// the measured boundary parameterization maps the cut mesh, whose border runs along both
// sides of every seam.
//
//   seam_parameterization [INPUT] [SEAMS.selection.txt] [OUTPUT.obj]
//
// Defaults: CGAL's fandisk.off, data/fandisk.selection.txt (a CGAL selection file: its third
// line lists the seam edges as pairs of 0-based vertex indices in file order), and
// seam_parameterization.obj ('v' per mesh vertex, 'vt' per seam mesh vertex). The seams must
// cut the surface into a disk: a tree on a surface of genus 0, 2g independent loops for genus
// g (data/torus.off with data/torus_cut_graph.selection.txt; torus_meridian_path leaves a handle).

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Seam_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include <CGAL/Surface_mesh_parameterization/Measured_conformal_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_report.h>
#include <CGAL/Surface_mesh_parameterization/measure_quality.h>

#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

typedef CGAL::Simple_cartesian<double>                               Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3>                          Mesh;
// The seam flags live in the underlying mesh.
typedef Mesh::Property_map<Mesh::Edge_index, bool>                   Seam_edge_pmap;
typedef Mesh::Property_map<Mesh::Vertex_index, bool>                 Seam_vertex_pmap;
typedef CGAL::Seam_mesh<Mesh, Seam_edge_pmap, Seam_vertex_pmap>      Seam_mesh;
// A vertex of the seam mesh is a halfedge of the mesh: one per side of a seam.
typedef boost::graph_traits<Seam_mesh>::vertex_descriptor            vertex_descriptor;
typedef boost::graph_traits<Seam_mesh>::halfedge_descriptor          halfedge_descriptor;

namespace SMP = CGAL::Surface_mesh_parameterization;

// The number of border loops of a connected mesh, and its genus (V - E + F = 2 - 2g - b).
template <class Graph>
std::pair<long, long> loops_and_genus(const Graph& g)
{
  std::vector<typename boost::graph_traits<Graph>::halfedge_descriptor> loops;
  CGAL::Polygon_mesh_processing::extract_boundary_cycles(g, std::back_inserter(loops));
  const long b = long(loops.size()), chi = long(num_vertices(g)) - long(num_edges(g)) + long(num_faces(g));
  return {b, (2 - chi - b) / 2};
}

int main(int argc, char** argv)
{
  const std::string input = (argc > 1) ? argv[1] : MBP_SEAM_DEFAULT_MESH;
  const std::string selection = (argc > 2) ? argv[2] : MBP_SEAM_DEFAULT_SELECTION;
  const std::string output = (argc > 3) ? argv[3] : "seam_parameterization.obj";

  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(input, mesh) || faces(mesh).empty() || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "error: cannot read a triangle mesh from '" << input << "'\n";
    return EXIT_FAILURE;
  }
  Seam_edge_pmap seam_edges = mesh.add_property_map<Mesh::Edge_index, bool>("e:on_seam", false).first;
  Seam_vertex_pmap seam_vertices = mesh.add_property_map<Mesh::Vertex_index, bool>("v:on_seam", false).first;
  Seam_mesh seam_mesh(mesh, seam_edges, seam_vertices);
  if(seam_mesh.add_seams(selection.c_str()) == boost::graph_traits<Mesh>::null_halfedge())
  {
    std::cerr << "error: no seam edge of the mesh in '" << selection << "'\n";
    return EXIT_FAILURE;
  }

  // The cut must leave no new border loop, which the parameterizer would take for a hole (a
  // closed loop of seams on a torus leaves a cylinder; seams away from the border, slits).
  const std::pair<long, long> before = loops_and_genus(mesh), after = loops_and_genus(seam_mesh);
  std::cout << input << ": " << num_vertices(mesh) << " vertices, genus " << before.second << "; "
            << seam_mesh.number_of_seam_edges() << " seam edges; cut mesh: " << num_vertices(seam_mesh)
            << " vertices, genus " << after.second << ", " << after.first << " border loops\n";
  if(after.first > std::max(1L, before.first))
  {
    std::cerr << "error: the seams open " << after.first << " border loops: use one cut graph joined to the border\n";
    return EXIT_FAILURE;
  }

  // The longest border of the seam mesh: on a closed mesh, the loop around the seams.
  const halfedge_descriptor bhd = CGAL::Polygon_mesh_processing::longest_border(seam_mesh).first;
  auto uvmap = get(CGAL::dynamic_vertex_property_t<Kernel::Point_2>(), seam_mesh);
  SMP::Measured_conformal_parameterizer_3<Seam_mesh> parameterizer;
  SMP::Parameterization_report report;
  const SMP::Error_code status = SMP::parameterize(seam_mesh, parameterizer, bhd, uvmap, &report);
  if(status != SMP::OK)
  {
    const bool handle_left = (status == SMP::ERROR_NO_TOPOLOGICAL_DISC && after.second > 0);
    std::cerr << "error: " << SMP::get_measured_error_message(status)
              << (handle_left ? ": the seams do not cut every handle (genus g needs 2g loops)" : "") << "\n";
    return EXIT_FAILURE;
  }

  // The report names the center by its position in vertices(seam_mesh).
  const vertex_descriptor center = *std::next(vertices(seam_mesh).begin(), std::ptrdiff_t(report.center));
  std::cout << "center at " << get(get(CGAL::vertex_point, seam_mesh), center) << "; border: "
            << report.border_uv.size() << " vertices (both sides of the seams); " << report.total_seconds
            << " s; repaired: " << (report.repaired ? "yes" : "no") << "\n";

  // The distortion, and CGAL's global overlap test, both on the seam mesh.
  const SMP::Parameterization_quality quality = SMP::measure_quality(seam_mesh, faces(seam_mesh), uvmap);
  const bool one_to_one = SMP::is_one_to_one_uv_map(seam_mesh, faces(seam_mesh), uvmap);
  std::cout << "angle distortion " << quality.angle_distortion << ", L2 stretch " << quality.l2_stretch
            << ", flipped faces " << quality.flipped_faces << ", one-to-one: " << (one_to_one ? "yes" : "no") << "\n";
  if(!one_to_one)
    return EXIT_FAILURE;

  // The OBJ: a vertex on a seam has one 'vt' per side.
  std::ofstream out(output);
  out.precision(17);
  for(Mesh::Vertex_index v : vertices(mesh))
    out << "v " << mesh.point(v) << "\n";
  auto vt = get(CGAL::dynamic_vertex_property_t<std::size_t>(), seam_mesh);
  std::size_t n = 0;
  for(vertex_descriptor v : vertices(seam_mesh))
  {
    put(vt, v, ++n);
    out << "vt " << get(uvmap, v) << "\n";
  }
  for(auto f : faces(seam_mesh))
  {
    out << "f";
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, seam_mesh), seam_mesh))
      out << " " << std::size_t(target(h.tmhd, mesh)) + 1 << "/" << get(vt, target(h, seam_mesh));
    out << "\n";
  }
  std::cout << (out ? "wrote " : "error: cannot write ") << output << "\n";
  return out ? EXIT_SUCCESS : EXIT_FAILURE;
}
