// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_SEAMS_SURFACE_INDEXING_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_SEAMS_SURFACE_INDEXING_H

// The indexed surface of a whole mesh for the automatic seams (compute_disk_seams.h), with the
// checks of its input: triangles, manifold vertices, one component, finite points. The
// vertices are indexed by the package's one mesh indexer (core/mesh_indexer.h), the edges and
// faces in the order of `edges(tm)` and `faces(tm)`. Back to the mesh:
// Surface_indexer::write_seams().

#include <CGAL/Surface_mesh_parameterization/Disk_seams_report.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/mesh_indexer.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/union_find.h>
#include <CGAL/Surface_mesh_parameterization/internal/seams/cut_graph.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Dynamic_property_map.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <array>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// The number of connected components of the faces of an indexed surface.
inline std::size_t number_of_face_components(const Indexed_surface& s)
{
  Union_find pieces(s.faces.size());
  std::size_t components = s.faces.size();
  for(const std::array<int, 2>& ef : s.edge_faces)
    if(ef[1] >= 0 && pieces.unite(static_cast<std::size_t>(ef[0]), static_cast<std::size_t>(ef[1])))
      --components;
  return components;
}

// Indexes `tm` into the surface `s` (vertices in faces only), naming what is wrong in the
// report, and writes a cut of `s` back into the seam maps of `tm`. The vertices keep their
// descriptors and their positions in `vertices(tm)`, the edges their descriptors.
template <class TriangleMesh>
class Surface_indexer
{
  typedef boost::graph_traits<TriangleMesh>           GT;
  typedef typename GT::vertex_descriptor              vertex_descriptor;
  typedef typename GT::halfedge_descriptor            halfedge_descriptor;
  typedef typename GT::edge_descriptor                edge_descriptor;
  typedef typename GT::face_descriptor                face_descriptor;

public:
  Surface_indexer(const TriangleMesh& tm, Indexed_surface& s, Disk_seams_report& report)
    : m_tm(tm), m_surface(s), m_report(report), m_vertices(tm),
      m_edge_index(get(CGAL::dynamic_edge_property_t<int>(), tm)),
      m_face_index(get(CGAL::dynamic_face_property_t<int>(), tm))
  { }

  // Indexes the mesh; checks triangles, manifold vertices, one component and finite points,
  // in this order of concern: coordinates, edges in no face, faces, vertices, components.
  template <class VertexPointMap>
  Disk_seams_problem index(VertexPointMap vpm)
  {
    if(faces(m_tm).empty())
      return EMPTY_INPUT_MESH;
    Disk_seams_problem problem = index_vertices(vpm);
    if(problem == NO_PROBLEM)
      problem = index_edges();
    if(problem == NO_PROBLEM)
      problem = index_faces();
    if(problem != NO_PROBLEM)
      return problem;
    index_edge_faces();
    if((problem = index_rotations()) != NO_PROBLEM)
      return problem;
    m_report.number_of_components = number_of_face_components(m_surface);
    if(m_report.number_of_components > 1)
      return SEVERAL_COMPONENTS;
    index_border_loops();
    return NO_PROBLEM;
  }

  // Writes the cut into the maps of `CGAL::Seam_mesh` (every edge and vertex gets a value),
  // and the seams and cones into the report.
  template <class SeamEdgeMap, class SeamVertexMap>
  void write_seams(const std::vector<char>& cut, const std::vector<int>& cones, SeamEdgeMap seam_edges,
                   SeamVertexMap seam_vertices)
  {
    for(edge_descriptor e : edges(m_tm))
      put(seam_edges, e, false);
    for(vertex_descriptor v : vertices(m_tm))
      put(seam_vertices, v, false);
    for(std::size_t e = 0; e < cut.size(); ++e)
    {
      if(!cut[e])
        continue;
      put(seam_edges, m_edge_of[e], true);
      for(int v : m_surface.edge_vertices[e])
        put(seam_vertices, m_vertices.vertices()[static_cast<std::size_t>(v)], true);
      ++m_report.number_of_seam_edges;
      const std::array<int, 2>& ev = m_surface.edge_vertices[e];
      m_report.seam_length += (m_surface.points[static_cast<std::size_t>(ev[0])] -
                               m_surface.points[static_cast<std::size_t>(ev[1])]).norm();
    }
    for(int c : cones)
      m_report.cones.push_back(m_vertex_position[static_cast<std::size_t>(c)]);
  }

  // Makes the cut avoid the edges `avoid` flags: each costs, in every length the cut graph
  // compares, more than all the other edges together, so that a cut crosses one only where
  // every other cut crosses more (the edges inside an input polygon, say). Border edges are
  // never cut anyway.
  template <class EdgeFlagMap>
  void avoid_edges(EdgeFlagMap avoid)
  {
    double total = 0.;
    for(double l : m_surface.edge_lengths)
      total += l;
    const double penalty = 2. * total + 1.;
    for(std::size_t e = 0; e < m_edge_of.size(); ++e)
      if(get(avoid, m_edge_of[e]) && !m_surface.border_edge[e])
        m_surface.edge_lengths[e] += penalty;
  }

private:
  // The vertices in faces, in the order of `vertices(tm)`, with their points (finite).
  template <class VertexPointMap>
  Disk_seams_problem index_vertices(VertexPointMap vpm)
  {
    std::size_t position = 0;
    for(vertex_descriptor v : vertices(m_tm))
    {
      if(halfedge(v, m_tm) != GT::null_halfedge())
      {
        const int i = m_vertices.add(v, vpm);
        m_vertex_position.push_back(position);
        if(!m_vertices.points()[static_cast<std::size_t>(i)].allFinite())
        {
          m_report.problem_vertex = position;
          return NON_FINITE_COORDINATE;
        }
      }
      ++position;
    }
    m_surface.points = std::move(m_vertices.points());
    return NO_PROBLEM;
  }

  // The edges: their ends, lengths and border flags; every edge must have a face.
  Disk_seams_problem index_edges()
  {
    Indexed_surface& s = m_surface;
    for(edge_descriptor e : edges(m_tm))
    {
      put(m_edge_index, e, static_cast<int>(m_edge_of.size()));
      m_edge_of.push_back(e);
      const halfedge_descriptor h = halfedge(e, m_tm);
      const int a = m_vertices.index(source(h, m_tm)), b = m_vertices.index(target(h, m_tm));
      s.edge_vertices.push_back({{a, b}});
      s.edge_lengths.push_back((s.points[static_cast<std::size_t>(a)] - s.points[static_cast<std::size_t>(b)]).norm());
      s.edge_faces.push_back({{-1, -1}});
      s.border_edge.push_back(is_border(e, m_tm) ? 1 : 0);
      if(is_border(h, m_tm) && is_border(opposite(h, m_tm), m_tm))
      {
        m_report.problem_vertex = m_vertex_position[static_cast<std::size_t>(a)];
        return NON_MANIFOLD_VERTEX;  // an edge in no face
      }
    }
    return NO_PROBLEM;
  }

  // The vertices and edges of face f, when it is a triangle.
  bool triangle_corners(face_descriptor f, std::array<int, 3>& t, std::array<int, 3>& te) const
  {
    std::size_t k = 0;
    for(halfedge_descriptor h : halfedges_around_face(halfedge(f, m_tm), m_tm))
    {
      if(k == 3)
        return false;
      t[k] = m_vertices.index(source(h, m_tm));
      te[k] = get(m_edge_index, edge(h, m_tm));
      ++k;
    }
    return k == 3;
  }

  // The faces (triangles only), in the order of `faces(tm)`.
  Disk_seams_problem index_faces()
  {
    for(face_descriptor f : faces(m_tm))
    {
      put(m_face_index, f, static_cast<int>(m_surface.faces.size()));
      std::array<int, 3> t, te;
      if(!triangle_corners(f, t, te))
      {
        m_report.problem_face = m_surface.faces.size();
        return FACE_NOT_A_TRIANGLE;
      }
      m_surface.faces.push_back(t);
      m_surface.face_edges.push_back(te);
    }
    return NO_PROBLEM;
  }

  // The faces on both sides of every edge.
  void index_edge_faces()
  {
    for(edge_descriptor e : edges(m_tm))
    {
      const halfedge_descriptor h = halfedge(e, m_tm);
      std::array<int, 2>& ef = m_surface.edge_faces[static_cast<std::size_t>(get(m_edge_index, e))];
      if(!is_border(h, m_tm))
        ef[0] = get(m_face_index, face(h, m_tm));
      if(!is_border(opposite(h, m_tm), m_tm))
        ef[ef[0] < 0 ? 0 : 1] = get(m_face_index, face(opposite(h, m_tm), m_tm));
    }
  }

  // The rotation of edges around every vertex; a manifold vertex has one fan, so all its
  // corners lie around one cycle of halfedges with at most one border gap.
  Disk_seams_problem index_rotations()
  {
    Indexed_surface& s = m_surface;
    std::vector<int> corners(s.points.size(), 0);
    for(const std::array<int, 3>& t : s.faces)
      for(int v : t)
        ++corners[static_cast<std::size_t>(v)];
    s.border_vertex.assign(s.points.size(), 0);
    s.ring_offsets.assign(1, 0);
    for(std::size_t i = 0; i < s.points.size(); ++i)
    {
      const halfedge_descriptor first = halfedge(m_vertices.vertices()[i], m_tm);
      halfedge_descriptor start = first;
      int around = 0, gaps = 0;
      for(halfedge_descriptor h : halfedges_around_target(first, m_tm))
      {
        ++(is_border(h, m_tm) ? gaps : around);
        start = is_border(h, m_tm) ? h : start;
      }
      if(around != corners[i] || gaps > 1)
      {
        m_report.problem_vertex = m_vertex_position[i];
        return NON_MANIFOLD_VERTEX;
      }
      s.border_vertex[i] = (gaps == 1) ? 1 : 0;
      for(halfedge_descriptor h : halfedges_around_target(start, m_tm))
        s.ring_edges.push_back(get(m_edge_index, edge(h, m_tm)));
      s.ring_offsets.push_back(static_cast<int>(s.ring_edges.size()));
    }
    return NO_PROBLEM;
  }

  // The border loops, each as its vertices in order.
  void index_border_loops()
  {
    auto walked = get(CGAL::dynamic_halfedge_property_t<bool>(), m_tm);
    for(halfedge_descriptor h : halfedges(m_tm))
      put(walked, h, false);
    for(halfedge_descriptor h : halfedges(m_tm))
    {
      if(!is_border(h, m_tm) || get(walked, h))
        continue;
      m_surface.border_loops.emplace_back();
      for(halfedge_descriptor b : halfedges_around_face(h, m_tm))
      {
        put(walked, b, true);
        m_surface.border_loops.back().push_back(m_vertices.index(source(b, m_tm)));
      }
    }
  }

  const TriangleMesh& m_tm;
  Indexed_surface& m_surface;
  Disk_seams_report& m_report;
  Mesh_indexer<TriangleMesh> m_vertices;
  std::vector<std::size_t> m_vertex_position;  // in vertices(tm), by local index
  typename boost::property_map<TriangleMesh, CGAL::dynamic_edge_property_t<int> >::const_type m_edge_index;
  typename boost::property_map<TriangleMesh, CGAL::dynamic_face_property_t<int> >::const_type m_face_index;
  std::vector<edge_descriptor> m_edge_of;
};

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_SEAMS_SURFACE_INDEXING_H
