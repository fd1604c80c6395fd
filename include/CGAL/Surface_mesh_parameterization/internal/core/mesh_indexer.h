// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CORE_MESH_INDEXER_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CORE_MESH_INDEXER_H

// The one mesh indexer of the package: dense local indices 0..n-1 for the vertices of a
// mesh, in the order they are first seen, with their positions as double, so that generic
// code never relies on the mesh's own vertex descriptors being integers. The checked disk
// indexes one component with it, the automatic seams the whole mesh.

#include <CGAL/boost/graph/properties.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

template <class TriangleMesh>
class Mesh_indexer
{
public:
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;

  Mesh_indexer() = default;

  explicit Mesh_indexer(const TriangleMesh& tm)
    : m_index_map(get(CGAL::dynamic_vertex_property_t<int>(), tm))
  { }

  // the local index of `v`, or -1 when it has none yet (the map stores index + 1, so that its
  // default value 0 means "not indexed")
  int index(vertex_descriptor v) const { return get(m_index_map, v) - 1; }

  // the local index of `v`, given on first sight with its position read from `vpm`
  template <class VertexPointMap>
  int add(vertex_descriptor v, VertexPointMap vpm)
  {
    const std::size_t seen = m_vertices.size();
    const int id = add(v);
    if(m_vertices.size() > seen)  // first sight
    {
      const auto& p = get(vpm, v);
      m_points.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    }
    return id;
  }

  // the local index of `v`, given on first sight (no position recorded)
  int add(vertex_descriptor v)
  {
    int id = index(v);
    if(id >= 0)
      return id;
    id = static_cast<int>(m_vertices.size());
    put(m_index_map, v, id + 1);
    m_vertices.push_back(v);
    return id;
  }

  // the vertices and their positions, by local index
  const std::vector<vertex_descriptor>& vertices() const { return m_vertices; }
  std::vector<vertex_descriptor>& vertices() { return m_vertices; }
  std::vector<Eigen::Vector3d>& points() { return m_points; }
  const std::vector<Eigen::Vector3d>& points() const { return m_points; }

private:
  typename boost::property_map<TriangleMesh, CGAL::dynamic_vertex_property_t<int> >::const_type m_index_map;
  std::vector<vertex_descriptor> m_vertices;
  std::vector<Eigen::Vector3d> m_points;
};

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CORE_MESH_INDEXER_H
