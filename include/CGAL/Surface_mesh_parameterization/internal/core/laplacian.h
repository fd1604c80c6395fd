// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CORE_LAPLACIAN_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CORE_LAPLACIAN_H

// Edge weights and the one Laplacian assembly over an indexed triangle set (user
// manual: The method in a page).
//
// Faces are triples of local vertex indices. A weight policy gives, for a face f and two of
// its corners a != b, the weight `w(f, a, b)` that face f contributes to the directed edge
// from vertex faces[f][a] to vertex faces[f][b]; an edge's weight is the sum over its (one or
// two) faces. Row i of the Laplacian is  (L x)_i = sum_j w_ij (x_i - x_j), i.e. L = D - W with
// D_ii = sum_j w_ij. A policy with `symmetric == true` has w(f, a, b) = w(f, b, a), so L is
// symmetric (positive semi-definite for positive or cotangent weights).
//
// Policies: cotangent weights (cot of the opposite angle / 2 per face), spring weights
// |x_i - x_j|^-r (the paper's Poisson distance map), mean value weights
// tan(angle at i / 2) / |x_i - x_j| (Floater 2003; not symmetric).

#include <CGAL/Surface_mesh_parameterization/internal/core/triangle_geometry.h>

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
  // rows must increase with i), with the weights of the policy `weight` (see the top of this
  // file). `M` becomes m x m, compressed, both triangles stored; the weights from unknowns to
  // constrained vertices go through `coupling(row, vertex, w)`.
  template <class Weight, class Coupling>
  void assemble(const std::vector<Face_indices>& faces, const std::vector<int>& unknown, int m,
                const Weight& weight, Eigen::SparseMatrix<double>& M, const Coupling& coupling) const
  {
    std::vector<double> values(m_neighbors.size(), 0.);
    auto slot = [this](int a, int b) {  // position of b among the neighbours of a
      const int* first = m_neighbors.data() + m_offsets[static_cast<std::size_t>(a)];
      const int* last = m_neighbors.data() + m_offsets[static_cast<std::size_t>(a) + 1];
      return static_cast<std::size_t>(std::lower_bound(first, last, b) - m_neighbors.data());
    };
    for(std::size_t f = 0; f < faces.size(); ++f)
      for(int a = 0; a < 3; ++a)
      {
        const int i = faces[f][static_cast<std::size_t>(a)];
        if(unknown[static_cast<std::size_t>(i)] < 0)
          continue;
        for(int b : {(a + 1) % 3, (a + 2) % 3})
        {
          const int j = faces[f][static_cast<std::size_t>(b)];
          const double w = weight(f, a, b);
          values[slot(i, i)] += w;
          if(unknown[static_cast<std::size_t>(j)] >= 0)
            values[slot(i, j)] -= w;
          else
            coupling(unknown[static_cast<std::size_t>(i)], j, w);
        }
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
    // column i holds the neighbours' entries of row i: that is the transpose of L, which is
    // L itself for symmetric weights
    if constexpr(!Weight::symmetric)
      M = Eigen::SparseMatrix<double>(M.transpose());
  }

  // the same without constrained neighbours to report
  template <class Weight>
  void assemble(const std::vector<Face_indices>& faces, const std::vector<int>& unknown, int m,
                const Weight& weight, Eigen::SparseMatrix<double>& M) const
  {
    assemble(faces, unknown, m, weight, M, [](int, int, double) {});
  }

private:
  std::vector<std::size_t> m_offsets;
  std::vector<int> m_neighbors;
};

// d_i = sum_j w_ij over all neighbours.
template <class Weight>
void laplacian_row_sums(const std::vector<Face_indices>& faces,
                        std::size_t number_of_vertices,
                        const Weight& weight,
                        std::vector<double>& row_sums)
{
  row_sums.assign(number_of_vertices, 0.);
  for(std::size_t f = 0; f < faces.size(); ++f)
    for(int a = 0; a < 3; ++a)
      row_sums[static_cast<std::size_t>(faces[f][static_cast<std::size_t>(a)])] +=
        weight(f, a, (a + 1) % 3) + weight(f, a, (a + 2) % 3);
}

// Share of face f in the edge opposite corner k: 1 on a border edge (one face), 1/2 otherwise.
inline double edge_share(unsigned char single_edge_mask, int k)
{
  return ((single_edge_mask >> k) & 1) ? 1. : 0.5;
}

// Spring weight |x_a - x_b|^(-r), counted once per edge (half from each of its faces).
struct Spring_weight
{
  static constexpr bool symmetric = true;
  const std::vector<Face_indices>* faces;
  const std::vector<Eigen::Vector3d>* points;
  const std::vector<unsigned char>* single_edges;
  double exponent;

  double operator()(std::size_t f, int a, int b) const
  {
    const Face_indices& t = (*faces)[f];
    const double l = ((*points)[static_cast<std::size_t>(t[static_cast<std::size_t>(a)])] -
                      (*points)[static_cast<std::size_t>(t[static_cast<std::size_t>(b)])]).norm();
    // l > 0: faces were checked non-degenerate; exponent 0 gives uniform weights.
    return std::pow(l, -exponent) * edge_share((*single_edges)[f], 3 - a - b);
  }
};

// Cotangent weight: each face gives cot(angle at the third corner) / 2 to the edge.
struct Cotangent_weight
{
  static constexpr bool symmetric = true;
  const std::vector<std::array<double, 3> >* half_cotangents;

  double operator()(std::size_t f, int a, int b) const
  {
    return (*half_cotangents)[f][static_cast<std::size_t>(3 - a - b)];
  }
};

// Mean value weight (Floater 2003): face f gives tan(alpha / 2) / |x_a - x_b| to the directed
// edge a -> b, alpha its angle at a. Positive, not symmetric.
struct Mean_value_weight
{
  static constexpr bool symmetric = false;
  const std::vector<Face_indices>* faces;
  const std::vector<Eigen::Vector3d>* points;

  double operator()(std::size_t f, int a, int b) const
  {
    const Face_indices& t = (*faces)[f];
    const Eigen::Vector3d& p = (*points)[static_cast<std::size_t>(t[static_cast<std::size_t>(a)])];
    const Eigen::Vector3d u = (*points)[static_cast<std::size_t>(t[static_cast<std::size_t>(b)])] - p;
    const Eigen::Vector3d v = (*points)[static_cast<std::size_t>(t[static_cast<std::size_t>(3 - a - b)])] - p;
    const double alpha = corner_angle(u, v);
    return std::tan(0.5 * alpha) / u.norm();  // |u| > 0: faces were checked non-degenerate
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

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CORE_LAPLACIAN_H
