// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CORE_UNION_FIND_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CORE_UNION_FIND_H

// Disjoint sets of the items 0..n-1 (the cut graph's pieces, the soup's corners). Written
// here rather than taken from CGAL's Union_find, which hands out handles to its own nodes
// instead of working on indices.

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// Union-find with path halving; the smallest item of a set is its root (deterministic).
class Union_find
{
public:
  explicit Union_find(std::size_t n) : m_parent(n) { std::iota(m_parent.begin(), m_parent.end(), std::size_t(0)); }

  std::size_t find(std::size_t i)
  {
    while(m_parent[i] != i)
      i = m_parent[i] = m_parent[m_parent[i]];
    return i;
  }

  // Joins the sets of a and b; false when they were one set already.
  bool unite(std::size_t a, std::size_t b)
  {
    a = find(a);
    b = find(b);
    if(a == b)
      return false;
    m_parent[(std::max)(a, b)] = (std::min)(a, b);
    return true;
  }

private:
  std::vector<std::size_t> m_parent;
};

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CORE_UNION_FIND_H
