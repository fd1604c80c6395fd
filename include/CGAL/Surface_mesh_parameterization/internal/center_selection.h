// Copyright (c) 2026 The measured boundary parameterization authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// This file is part of the measured boundary parameterization package for CGAL.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CENTER_SELECTION_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CENTER_SELECTION_H

// The deterministic argmax shared by the center locators (METHOD.md section 3, step 1).

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// Relative tolerance under which two values of a distance map count as tied maxima.
constexpr double center_tie_tolerance = 1e-9;

// Returns the interior vertex (local index) that maximizes `values`, or -1 when there is no
// interior vertex or a value is not finite. Ties: every interior vertex whose value is within
// `center_tie_tolerance * |max|` of the maximum is a tied maximum; when there are several,
// the center is the interior vertex nearest (3D Euclidean distance) to the mean position of
// the tied maxima, and among equally near ones the smallest local index.
template <class Patch>
int argmax_with_tie_break(const Patch& patch, const std::vector<double>& values)
{
  const std::vector<int>& interior = patch.interior_vertices();
  double best = -std::numeric_limits<double>::infinity();
  for(int i : interior)
  {
    const double v = values[static_cast<std::size_t>(i)];
    if(!std::isfinite(v))
      return -1;
    if(v > best)
      best = v;
  }
  if(interior.empty())
    return -1;

  const double threshold = best - center_tie_tolerance * std::abs(best);
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  int tied = 0, first = -1;
  for(int i : interior)
    if(values[static_cast<std::size_t>(i)] >= threshold)
    {
      mean += patch.point(static_cast<std::size_t>(i));
      if(tied++ == 0)
        first = i;
    }
  if(tied == 1)
    return first;
  mean /= double(tied);

  int center = -1;
  double nearest = std::numeric_limits<double>::infinity();
  for(int i : interior)  // increasing local index: strict '<' keeps the smallest on ties
  {
    const double d2 = (patch.point(static_cast<std::size_t>(i)) - mean).squaredNorm();
    if(d2 < nearest)
    {
      nearest = d2;
      center = i;
    }
  }
  return center;
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CENTER_SELECTION_H
