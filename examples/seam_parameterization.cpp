// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// Parameterizing a closed surface: the mesh is cut open along seams with CGAL::Seam_mesh,
// and the measured boundary parameterization maps the cut mesh, whose border runs along
// both sides of every seam.
//
//   seam_parameterization [INPUT] [SEAMS.selection.txt] [OUTPUT.obj]
//
// Defaults: fandisk.off (a closed CAD model of genus 0, from CGAL's data meshes), the seams
// data/fandisk.selection.txt beside this file, and seam_parameterization.obj. The seams are a CGAL selection file, as in CGAL's
// seam_Polyhedron_3 example: its third line lists the seam edges as pairs of 0-based vertex
// indices in file order (the first two lines, selected vertices and faces, are not used).
//
// The OBJ has the vertices of the mesh ('v' lines, input order), one UV per vertex of the
// seam mesh ('vt' lines: a vertex on a seam gets one UV for each side of the cut, grouped by
// input vertex), and the faces as 'f v/vt v/vt v/vt'.
//
// The seams must cut the surface into a topological disk: on a closed surface of genus 0 a
// tree of edges is enough; a surface of genus g needs a cut graph with 2g independent loops
// (for a torus, a meridian and a longitude through one vertex). The program checks that the
// cut leaves one piece and no new border loop (a closed loop of seams alone, as a meridian
// of a torus, leaves a cylinder, whose second border the parameterizer would take for a
// hole). When the seams leave a handle uncut, the parameterizer returns
// ERROR_NO_TOPOLOGICAL_DISC and the program explains it: try the generated torus
// data/torus.off with data/torus_meridian_path.selection.txt (a path that closes no loop),
// and with data/torus_cut_graph.selection.txt (a meridian and a longitude through one
// vertex, which cut it into a disk). data/make_torus.py wrote these three files.
//
// data/fandisk.selection.txt was made by
//   python3 data/make_seam_selection.py fandisk.off data/fandisk.selection.txt
// the shortest edge path (Euclidean edge lengths) between two far-apart vertices, 6395 and
// 3396 (a double sweep of farthest vertices): 59 seam edges. The script can also join more
// far-apart vertices into a tree of shortest paths; on the fandisk that raised the angle
// distortion of the result (0.23 with 2 vertices, 0.68 with 3, 0.90 with 4).

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Seam_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <CGAL/Surface_mesh_parameterization/Measured_conformal_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/measure_quality.h>

#include "cli/seam_selection.h"

#include <algorithm>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#ifndef MBP_SEAM_DEFAULT_MESH
#define MBP_SEAM_DEFAULT_MESH "fandisk.off"
#endif
#ifndef MBP_SEAM_DEFAULT_SELECTION
#define MBP_SEAM_DEFAULT_SELECTION "data/fandisk.selection.txt"
#endif

typedef CGAL::Simple_cartesian<double>                               Kernel;
typedef Kernel::Point_2                                              Point_2;
typedef Kernel::Point_3                                              Point_3;
typedef CGAL::Surface_mesh<Point_3>                                  Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor                 SM_vertex_descriptor;
typedef boost::graph_traits<Mesh>::halfedge_descriptor               SM_halfedge_descriptor;
typedef boost::graph_traits<Mesh>::edge_descriptor                   SM_edge_descriptor;

// The seam flags live in the underlying mesh.
typedef Mesh::Property_map<SM_edge_descriptor, bool>                 Seam_edge_pmap;
typedef Mesh::Property_map<SM_vertex_descriptor, bool>               Seam_vertex_pmap;
typedef CGAL::Seam_mesh<Mesh, Seam_edge_pmap, Seam_vertex_pmap>      Seam_mesh;
// A vertex of the seam mesh is a halfedge of the mesh: one per side of a seam.
typedef boost::graph_traits<Seam_mesh>::vertex_descriptor            vertex_descriptor;
typedef boost::graph_traits<Seam_mesh>::halfedge_descriptor          halfedge_descriptor;
typedef boost::graph_traits<Seam_mesh>::face_descriptor              face_descriptor;

namespace SMP = CGAL::Surface_mesh_parameterization;

// the vertex of the underlying mesh of seam mesh vertex `v`
SM_vertex_descriptor underlying_vertex(const Seam_mesh& seam_mesh, vertex_descriptor v)
{
  return target(SM_halfedge_descriptor(v), seam_mesh.mesh());
}

int main(int argc, char** argv)
{
  if(argc > 4)
  {
    std::cerr << "usage: seam_parameterization [INPUT] [SEAMS.selection.txt] [OUTPUT.obj]\n";
    return EXIT_FAILURE;
  }
  const std::string input = (argc > 1) ? argv[1] : MBP_SEAM_DEFAULT_MESH;
  const std::string selection = (argc > 2) ? argv[2] : MBP_SEAM_DEFAULT_SELECTION;
  const std::string output = (argc > 3) ? argv[3] : "seam_parameterization.obj";

  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(input, mesh) || faces(mesh).empty() || !CGAL::is_triangle_mesh(mesh))
  {
    std::cerr << "error: cannot read a triangle mesh from '" << input << "'\n";
    return EXIT_FAILURE;
  }

  // The seams, checked against the mesh (cli/seam_selection.h): every pair must be an
  // interior edge of the mesh.
  std::vector<SM_edge_descriptor> seams;
  const std::string error = mbp_cli::read_seam_selection(selection, mesh, seams);
  if(!error.empty())
  {
    std::cerr << "error: " << selection << ": " << error << "\n";
    return EXIT_FAILURE;
  }

  Seam_edge_pmap seam_edges = mesh.add_property_map<SM_edge_descriptor, bool>("e:on_seam", false).first;
  Seam_vertex_pmap seam_vertices = mesh.add_property_map<SM_vertex_descriptor, bool>("v:on_seam", false).first;
  Seam_mesh seam_mesh(mesh, seam_edges, seam_vertices);
  for(SM_edge_descriptor e : seams)
    seam_mesh.add_seam(source(e, mesh), target(e, mesh));

  // The cut must leave one piece and no new border loop (cli/seam_selection.h).
  const mbp_cli::Mesh_topology input_topology = mbp_cli::mesh_topology(mesh);
  const mbp_cli::Mesh_topology cut = mbp_cli::mesh_topology(seam_mesh);
  std::cout << input << ": " << input_topology.vertices << " vertices, " << input_topology.faces << " faces, genus "
            << input_topology.genus << ", " << input_topology.border_loops << " border loops; "
            << seam_mesh.number_of_seam_edges() << " seam edges from " << selection << "\n"
            << "cut mesh: " << num_vertices(seam_mesh) << " vertices, genus " << cut.genus << ", " << cut.border_loops
            << " border loops\n";
  const std::string cut_error = mbp_cli::check_cut(input_topology, cut);
  if(!cut_error.empty())
  {
    std::cerr << "error: " << cut_error << "\n";
    return EXIT_FAILURE;
  }

  // The longest border of the seam mesh: on a closed mesh, the loop around the seams.
  const halfedge_descriptor bhd = CGAL::Polygon_mesh_processing::longest_border(seam_mesh).first;

  // The UVs, one per seam mesh vertex.
  auto uvmap = get(CGAL::dynamic_vertex_property_t<Point_2>(), seam_mesh);
  SMP::Measured_conformal_parameterizer_3<Seam_mesh> parameterizer;
  const SMP::Error_code status = SMP::parameterize(seam_mesh, parameterizer, bhd, uvmap);
  if(status == SMP::ERROR_NO_TOPOLOGICAL_DISC)
  {
    std::cerr << "error: " << SMP::get_measured_error_message(status) << ": "
              << mbp_cli::explain_cut(input_topology, cut) << "\n";
    return EXIT_FAILURE;
  }
  if(status != SMP::OK)
  {
    std::cerr << "error: " << SMP::get_measured_error_message(status) << "\n";
    return EXIT_FAILURE;
  }

  // The report: the center, the work and what the validity check did.
  const auto& report = parameterizer.last_report();
  const vertex_descriptor center = parameterizer.center();
  std::cout << "center: vertex " << std::size_t(underlying_vertex(seam_mesh, center)) << " at "
            << get(get(CGAL::vertex_point, seam_mesh), center) << "\n"
            << "border: " << parameterizer.border_parameterizer().border_vertices().size()
            << " vertices (both sides of the seams)\n"
            << "time: " << report.total_seconds << " s, " << report.statistics.factorizations << " factorizations, "
            << report.statistics.back_substitutions << " back-substitutions\n";
  if(report.repaired)
    std::cout << "repair: " << report.flipped_faces_before_repair << " faces were flipped by the measured border;"
              << " repaired with the border blended toward a circle by " << report.blend << " and the "
              << (report.mean_value_interior ? "mean value" : "discrete conformal") << " interior\n";
  else
    std::cout << "repair: none needed\n";

  // The distortion, and CGAL's global overlap test, both on the seam mesh.
  const SMP::Parameterization_quality quality = SMP::measure_quality(seam_mesh, faces(seam_mesh), uvmap);
  const bool one_to_one = SMP::is_one_to_one_uv_map(seam_mesh, faces(seam_mesh), uvmap);
  std::cout << "angle distortion " << quality.angle_distortion << ", L2 stretch " << quality.l2_stretch
            << ", quasi-conformal mean " << quality.quasi_conformal_mean << ", flipped faces "
            << quality.flipped_faces << ", one-to-one: " << (one_to_one ? "yes" : "no") << "\n";
  if(!one_to_one)
  {
    std::cerr << "error: the UV map is not one-to-one\n";
    return EXIT_FAILURE;
  }

  // The OBJ numbering: 'vt' lines are the seam mesh vertices, grouped by input vertex.
  std::vector<std::pair<std::size_t, vertex_descriptor> > uv_order;
  for(vertex_descriptor v : vertices(seam_mesh))
    uv_order.emplace_back(std::size_t(underlying_vertex(seam_mesh, v)), v);
  std::stable_sort(uv_order.begin(), uv_order.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  auto vt_index = get(CGAL::dynamic_vertex_property_t<std::size_t>(), seam_mesh);
  for(std::size_t i = 0; i < uv_order.size(); ++i)
    put(vt_index, uv_order[i].second, i + 1);

  std::ofstream out(output);
  out.precision(17);
  out << "# " << input << " cut along " << seams.size() << " seam edges (" << selection
      << "), measured boundary parameterization\n";
  for(SM_vertex_descriptor v : vertices(mesh))
    out << "v " << mesh.point(v) << "\n";
  for(const auto& u : uv_order)
    out << "vt " << get(uvmap, u.second) << "\n";
  for(face_descriptor f : faces(seam_mesh))
  {
    out << "f";
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, seam_mesh), seam_mesh))
    {
      const vertex_descriptor v = target(h, seam_mesh);
      out << " " << std::size_t(underlying_vertex(seam_mesh, v)) + 1 << "/" << get(vt_index, v);
    }
    out << "\n";
  }
  out.close();
  if(!out)
  {
    std::cerr << "error: cannot write '" << output << "'\n";
    std::remove(output.c_str());
    return EXIT_FAILURE;
  }
  std::cout << "wrote " << output << ": " << num_vertices(mesh) << " v, " << uv_order.size() << " vt, "
            << num_faces(mesh) << " f\n";
  return EXIT_SUCCESS;
}
