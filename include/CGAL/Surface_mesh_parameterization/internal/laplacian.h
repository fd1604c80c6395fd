// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_LAPLACIAN_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_LAPLACIAN_H

// Edge weights and Laplacian assembly over an indexed triangle set (METHOD.md section 2).
//
// Faces are triples of local vertex indices. The weight of "corner k of face f" is the
// contribution of face f to the edge opposite corner k, i.e. the edge between
// faces[f][(k+1)%3] and faces[f][(k+2)%3]; an edge's weight is the sum over its (one or two)
// faces. The unnormalised Laplacian is L = D - W with D_ii = sum_j w_ij.

#include <CGAL/Surface_mesh_parameterization/internal/sparse_solver.h>

#include <Eigen/Core>
#include <Eigen/Sparse>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

typedef std::array<int, 3> Face_indices;

// Emits the triplets of L restricted to the unknowns: `unknown[i]` is the row of vertex i,
// or -1 for a constrained vertex. Constrained neighbours still count in the diagonal.
template <class CornerWeight>
void laplacian_triplets(const std::vector<Face_indices>& faces,
                        const std::vector<int>& unknown,
                        const CornerWeight& weight,
                        std::vector<Triplet>& triplets)
{
  triplets.clear();
  triplets.reserve(faces.size() * 9);
  for(std::size_t f = 0; f < faces.size(); ++f)
  {
    for(int k = 0; k < 3; ++k)
    {
      const int a = faces[f][(k + 1) % 3], b = faces[f][(k + 2) % 3];
      const double w = weight(f, k);
      const int ia = unknown[static_cast<std::size_t>(a)];
      const int ib = unknown[static_cast<std::size_t>(b)];
      if(ia >= 0)
        triplets.emplace_back(ia, ia, w);
      if(ib >= 0)
        triplets.emplace_back(ib, ib, w);
      if(ia >= 0 && ib >= 0)
      {
        triplets.emplace_back(ia, ib, -w);
        triplets.emplace_back(ib, ia, -w);
      }
    }
  }
}

// The sparsity pattern of the vertex graph (every vertex with itself and its neighbours,
// sorted), built once per patch. It assembles the Laplacian restricted to a set of unknowns
// directly in compressed column form: no triplet list (9 per face) and no sorting.
class Laplacian_pattern
{
public:
  Laplacian_pattern() = default;

  Laplacian_pattern(std::size_t n, const std::vector<Face_indices>& faces)
  {
    // neighbours from the face edges (each edge seen from both faces, or once on a border)
    std::vector<int> count(n, 1);  // the vertex itself
    for(const Face_indices& t : faces)
      for(int k = 0; k < 3; ++k)
      {
        ++count[static_cast<std::size_t>(t[static_cast<std::size_t>(k)])];
        ++count[static_cast<std::size_t>(t[static_cast<std::size_t>((k + 1) % 3)])];
      }
    m_offsets.assign(n + 1, 0);
    for(std::size_t i = 0; i < n; ++i)
      m_offsets[i + 1] = m_offsets[i] + static_cast<std::size_t>(count[i]);
    m_neighbors.resize(m_offsets[n]);
    std::vector<std::size_t> fill(m_offsets.begin(), m_offsets.end() - 1);
    for(std::size_t i = 0; i < n; ++i)
      m_neighbors[fill[i]++] = static_cast<int>(i);
    for(const Face_indices& t : faces)
      for(int k = 0; k < 3; ++k)
      {
        const int a = t[static_cast<std::size_t>(k)], b = t[static_cast<std::size_t>((k + 1) % 3)];
        m_neighbors[fill[static_cast<std::size_t>(a)]++] = b;
        m_neighbors[fill[static_cast<std::size_t>(b)]++] = a;
      }
    // sort and remove duplicates in place, then compact
    std::size_t out = 0;
    for(std::size_t i = 0; i < n; ++i)
    {
      const std::size_t begin = m_offsets[i], end = m_offsets[i + 1];
      std::sort(m_neighbors.begin() + static_cast<std::ptrdiff_t>(begin),
                m_neighbors.begin() + static_cast<std::ptrdiff_t>(end));
      m_offsets[i] = out;
      for(std::size_t e = begin; e < end; ++e)
        if(e == begin || m_neighbors[e] != m_neighbors[e - 1])
          m_neighbors[out++] = m_neighbors[e];
    }
    m_offsets[n] = out;
    m_neighbors.resize(out);
    m_neighbors.shrink_to_fit();
  }

  std::size_t size() const { return m_offsets.empty() ? 0 : m_offsets.size() - 1; }

  // The Laplacian L = D - W restricted to the unknowns (`unknown[i]` = row of vertex i, or -1;
  // rows must increase with i), with the weights given per face corner as for
  // laplacian_triplets(). `M` becomes m x m, compressed, both triangles stored.
  template <class CornerWeight>
  void assemble(const std::vector<Face_indices>& faces, const std::vector<int>& unknown, int m,
                const CornerWeight& weight, Eigen::SparseMatrix<double>& M) const
  {
    std::vector<double> values(m_neighbors.size(), 0.);
    auto slot = [this](int a, int b) {  // position of b among the neighbours of a
      const int* first = m_neighbors.data() + m_offsets[static_cast<std::size_t>(a)];
      const int* last = m_neighbors.data() + m_offsets[static_cast<std::size_t>(a) + 1];
      return static_cast<std::size_t>(std::lower_bound(first, last, b) - m_neighbors.data());
    };
    for(std::size_t f = 0; f < faces.size(); ++f)
      for(int k = 0; k < 3; ++k)
      {
        const int a = faces[f][static_cast<std::size_t>((k + 1) % 3)];
        const int b = faces[f][static_cast<std::size_t>((k + 2) % 3)];
        const double w = weight(f, k);
        values[slot(a, b)] -= w;
        values[slot(b, a)] -= w;
        values[slot(a, a)] += w;
        values[slot(b, b)] += w;
      }
    std::size_t nnz = 0;
    for(std::size_t i = 0; i < size(); ++i)
      if(unknown[i] >= 0)
        for(std::size_t e = m_offsets[i]; e < m_offsets[i + 1]; ++e)
          if(unknown[static_cast<std::size_t>(m_neighbors[e])] >= 0)
            ++nnz;
    M.resize(m, m);
    M.makeCompressed();
    M.resizeNonZeros(static_cast<Eigen::Index>(nnz));
    int* outer = M.outerIndexPtr();
    int* inner = M.innerIndexPtr();
    double* value = M.valuePtr();
    std::size_t p = 0;
    int column = 0;
    outer[0] = 0;
    for(std::size_t i = 0; i < size(); ++i)
    {
      if(unknown[i] < 0)
        continue;
      for(std::size_t e = m_offsets[i]; e < m_offsets[i + 1]; ++e)
      {
        const int row = unknown[static_cast<std::size_t>(m_neighbors[e])];
        if(row < 0)
          continue;
        inner[p] = row;
        value[p] = values[e];
        ++p;
      }
      outer[++column] = static_cast<int>(p);
    }
  }

private:
  std::vector<std::size_t> m_offsets;
  std::vector<int> m_neighbors;
};

// d_i = sum_j w_ij over all neighbours.
template <class CornerWeight>
void laplacian_row_sums(const std::vector<Face_indices>& faces,
                        std::size_t number_of_vertices,
                        const CornerWeight& weight,
                        std::vector<double>& row_sums)
{
  row_sums.assign(number_of_vertices, 0.);
  for(std::size_t f = 0; f < faces.size(); ++f)
    for(int k = 0; k < 3; ++k)
    {
      const double w = weight(f, k);
      row_sums[static_cast<std::size_t>(faces[f][(k + 1) % 3])] += w;
      row_sums[static_cast<std::size_t>(faces[f][(k + 2) % 3])] += w;
    }
}

// Share of face f in the edge opposite corner k: 1 on a border edge (one face), 1/2 otherwise.
inline double edge_share(unsigned char single_edge_mask, int k)
{
  return ((single_edge_mask >> k) & 1) ? 1. : 0.5;
}

// Spring weight |x_a - x_b|^(-r) of the edge opposite each corner, counted once per edge.
struct Spring_weight
{
  const std::vector<Face_indices>* faces;
  const std::vector<Eigen::Vector3d>* points;
  const std::vector<unsigned char>* single_edges;
  double exponent;

  double operator()(std::size_t f, int k) const
  {
    const Face_indices& t = (*faces)[f];
    const double l = ((*points)[static_cast<std::size_t>(t[(k + 1) % 3])] -
                      (*points)[static_cast<std::size_t>(t[(k + 2) % 3])]).norm();
    // l > 0: faces were checked non-degenerate; exponent 0 gives uniform weights.
    return std::pow(l, -exponent) * edge_share((*single_edges)[f], k);
  }
};

// Cotangent weight: each face gives cot(angle at k) / 2 to the opposite edge.
struct Cotangent_weight
{
  const std::vector<std::array<double, 3> >* half_cotangents;

  double operator()(std::size_t f, int k) const
  {
    return (*half_cotangents)[f][static_cast<std::size_t>(k)];
  }
};

// g_i: mean length of the edges at vertex i (paper Eq. 1's right-hand side).
inline void mean_spoke_lengths(const std::vector<Face_indices>& faces,
                               const std::vector<Eigen::Vector3d>& points,
                               const std::vector<unsigned char>& single_edges,
                               std::vector<double>& g)
{
  std::vector<double> count(points.size(), 0.);
  g.assign(points.size(), 0.);
  for(std::size_t f = 0; f < faces.size(); ++f)
    for(int k = 0; k < 3; ++k)
    {
      const std::size_t a = static_cast<std::size_t>(faces[f][(k + 1) % 3]);
      const std::size_t b = static_cast<std::size_t>(faces[f][(k + 2) % 3]);
      const double share = edge_share(single_edges[f], k);
      const double l = (points[a] - points[b]).norm();
      g[a] += share * l;
      g[b] += share * l;
      count[a] += share;
      count[b] += share;
    }
  for(std::size_t i = 0; i < g.size(); ++i)
    g[i] = (count[i] > 0.) ? g[i] / count[i] : 0.;
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_LAPLACIAN_H
