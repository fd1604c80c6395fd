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

} // namespace mbp_benchmark

#endif // MBP_BENCHMARK_SUPPORT_H
