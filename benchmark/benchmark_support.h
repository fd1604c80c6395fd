// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// Helpers shared by the benchmark programs.

#ifndef MBP_BENCHMARK_SUPPORT_H
#define MBP_BENCHMARK_SUPPORT_H

#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/boost/graph/properties.h>

#include <iterator>
#include <string>
#include <vector>

namespace mbp_benchmark {

// Why the mesh is not a single disk ("2 components", "closed", "3 borders", "genus 1"), or an
// empty string when it is one.
template <class TriangleMesh>
std::string not_a_disk(TriangleMesh& mesh)
{
  auto fcc = get(CGAL::dynamic_face_property_t<std::size_t>(), mesh);
  const std::size_t components = CGAL::Polygon_mesh_processing::connected_components(mesh, fcc);
  if(components != 1)
    return std::to_string(components) + " components";
  std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor> borders;
  CGAL::Polygon_mesh_processing::extract_boundary_cycles(mesh, std::back_inserter(borders));
  if(borders.empty())
    return "closed";
  if(borders.size() > 1)
    return std::to_string(borders.size()) + " borders";
  const long chi = long(num_vertices(mesh)) - long(num_edges(mesh)) + long(num_faces(mesh));
  if(chi != 1)
    return "genus " + std::to_string((1 - chi) / 2);
  return "";
}

// (CGAL::Surface_mesh)
// 1-to-4 midpoint subdivision: every edge split at its midpoint, every triangle into four.
// The surface does not move. Returns false on a non-triangle face.
template <class Mesh>
bool midpoint_subdivision(const Mesh& in, Mesh& out)
{
  out.clear();
  out.reserve(num_vertices(in) + num_edges(in), 2 * num_edges(in) + 3 * num_faces(in), 4 * num_faces(in));
  std::vector<typename Mesh::Vertex_index> corner(in.number_of_vertices() + in.number_of_removed_vertices());
  std::vector<typename Mesh::Vertex_index> middle(in.number_of_edges() + in.number_of_removed_edges());
  for(typename Mesh::Vertex_index v : vertices(in))
    corner[v.idx()] = out.add_vertex(in.point(v));
  for(auto e : edges(in))
    middle[e.idx()] = out.add_vertex(CGAL::midpoint(in.point(source(halfedge(e, in), in)),
                                                    in.point(target(halfedge(e, in), in))));
  for(auto f : faces(in))
  {
    const typename Mesh::Halfedge_index h0 = halfedge(f, in), h1 = next(h0, in), h2 = next(h1, in);
    if(next(h2, in) != h0)
      return false;
    const typename Mesh::Vertex_index a = corner[source(h0, in).idx()], b = corner[source(h1, in).idx()],
                            c = corner[source(h2, in).idx()];
    const typename Mesh::Vertex_index ab = middle[edge(h0, in).idx()], bc = middle[edge(h1, in).idx()],
                            ca = middle[edge(h2, in).idx()];
    if(out.add_face(a, ab, ca) == Mesh::null_face() || out.add_face(ab, b, bc) == Mesh::null_face() ||
       out.add_face(ca, bc, c) == Mesh::null_face() || out.add_face(ab, bc, ca) == Mesh::null_face())
      return false;
  }
  return true;
}

} // namespace mbp_benchmark

#endif // MBP_BENCHMARK_SUPPORT_H
