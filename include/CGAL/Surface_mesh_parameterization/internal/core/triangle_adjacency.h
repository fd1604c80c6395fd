// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CORE_TRIANGLE_ADJACENCY_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CORE_TRIANGLE_ADJACENCY_H

// Adjacency of an indexed, consistently oriented, manifold triangle set (a patch): the face
// across each edge, and the faces around each vertex. Used by the geodesic algorithms that
// walk over triangles (fast marching, straightest geodesics).

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

class Triangle_adjacency
{
public:
  typedef std::array<int, 3> Face;

  // A corner: face f, local corner k (the vertex faces[f][k]).
  struct Corner
  {
    int face;
    int k;
  };

  Triangle_adjacency() = default;

  // `faces` are triples of vertex indices in [0, number_of_vertices).
  Triangle_adjacency(std::size_t number_of_vertices, const std::vector<Face>& faces)
  {
    build(number_of_vertices, faces);
  }

  void build(std::size_t number_of_vertices, const std::vector<Face>& faces)
  {
    m_faces = &faces;
    const std::size_t F = faces.size();

    // faces around each vertex (CSR)
    m_offsets.assign(number_of_vertices + 1, 0);
    for(const Face& t : faces)
      for(int v : t)
        ++m_offsets[static_cast<std::size_t>(v) + 1];
    for(std::size_t i = 0; i < number_of_vertices; ++i)
      m_offsets[i + 1] += m_offsets[i];
    m_corners.resize(m_offsets.back());
    std::vector<std::size_t> fill(m_offsets.begin(), m_offsets.end() - 1);
    for(std::size_t f = 0; f < F; ++f)
      for(int k = 0; k < 3; ++k)
        m_corners[fill[static_cast<std::size_t>(faces[f][static_cast<std::size_t>(k)])]++] =
          Corner{static_cast<int>(f), k};

    // face across the edge opposite each corner: the edge (a, b) = (t[k+1], t[k+2]) of face f
    // is the edge (b, a) of its neighbour; look for it among the faces around b.
    m_neighbor.assign(F, {{-1, -1, -1}});
    m_neighbor_corner.assign(F, {{-1, -1, -1}});
    for(std::size_t f = 0; f < F; ++f)
      for(int k = 0; k < 3; ++k)
      {
        const int a = faces[f][static_cast<std::size_t>((k + 1) % 3)];
        const int b = faces[f][static_cast<std::size_t>((k + 2) % 3)];
        for(std::size_t c = m_offsets[static_cast<std::size_t>(b)]; c < m_offsets[static_cast<std::size_t>(b) + 1]; ++c)
        {
          const Corner& corner = m_corners[c];  // corner of b in face g: its next vertex must be a
          if(corner.face == static_cast<int>(f))
            continue;
          const Face& g = faces[static_cast<std::size_t>(corner.face)];
          if(g[static_cast<std::size_t>((corner.k + 1) % 3)] == a)
          {
            m_neighbor[f][static_cast<std::size_t>(k)] = corner.face;
            m_neighbor_corner[f][static_cast<std::size_t>(k)] = (corner.k + 2) % 3;
            break;
          }
        }
      }
  }

  std::size_t number_of_vertices() const { return m_offsets.empty() ? 0 : m_offsets.size() - 1; }
  std::size_t number_of_faces() const { return m_neighbor.size(); }
  const Face& face(std::size_t f) const { return (*m_faces)[f]; }

  // the face across the edge opposite corner k of face f, or -1 on the border
  int neighbor(std::size_t f, int k) const { return m_neighbor[f][static_cast<std::size_t>(k)]; }
  // in that neighbour, the corner opposite the shared edge
  int neighbor_corner(std::size_t f, int k) const { return m_neighbor_corner[f][static_cast<std::size_t>(k)]; }

  // the corners at vertex v: [corners_begin(v), corners_end(v))
  const Corner* corners_begin(std::size_t v) const { return m_corners.data() + m_offsets[v]; }
  const Corner* corners_end(std::size_t v) const { return m_corners.data() + m_offsets[v + 1]; }

private:
  const std::vector<Face>* m_faces = nullptr;
  std::vector<std::size_t> m_offsets;
  std::vector<Corner> m_corners;
  std::vector<std::array<int, 3> > m_neighbor;
  std::vector<std::array<int, 3> > m_neighbor_corner;
};

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CORE_TRIANGLE_ADJACENCY_H
