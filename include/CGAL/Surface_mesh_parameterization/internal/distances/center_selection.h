// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DISTANCES_CENTER_SELECTION_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DISTANCES_CENTER_SELECTION_H

// The deterministic argmax shared by the center locators (user manual: The method in a page).

#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// Relative tolerance under which two values of a distance map count as tied maxima.
constexpr double center_tie_tolerance = 1e-9;

// Returns the interior vertex (local index) that maximizes `values`, or -1 when there is no
// candidate or a value is not finite. Candidates are the interior vertices of the surface:
// neither virtual (the filling of a hole) nor on a hole's border (a vertex on a hole can sit
// at the same 3D point as a vertex of the main border, for example where a seam opened the
// hole, which would make the polar map degenerate).
//
// Ties: every interior vertex whose value is within `center_tie_tolerance * |max|` of the
// maximum is a tied maximum. When there are several, the center is chosen by the distance
// (3D, Euclidean) of the interior vertices to the mean position m of the tied maxima: the
// nearest vertex when it is the only one at its distance; otherwise the vertices at that
// distance are set aside and the next distance is examined, and so on (distances equal
// within 1e-12 of the squared bounding box diagonal count as equal). If no distance has a
// single vertex, the smallest local index among the nearest ones is taken.
//
// Why: a symmetry of the mesh maps the tied maxima, hence m, onto themselves, so it permutes
// the vertices at each distance from m; a distance held by one vertex is held by a vertex
// that every symmetry fixes. So on a mirror-symmetric patch the center lies on the mirror
// (for example on the paper's ellipse, whose boundary geodesic distance has two maxima, the
// center is the vertex between them) whenever such a vertex exists.
template <class Patch>
int argmax_with_tie_break(const Patch& patch, const std::vector<double>& values)
{
  std::vector<int> interior;
  interior.reserve(patch.interior_vertices().size());
  for(int i : patch.interior_vertices())
    if(!patch.is_virtual(static_cast<std::size_t>(i)) && !patch.is_on_hole(static_cast<std::size_t>(i)))
      interior.push_back(i);
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

  Eigen::AlignedBox3d box;
  for(int i : interior)
    box.extend(patch.point(static_cast<std::size_t>(i)));
  const double equal = 1e-12 * box.diagonal().squaredNorm();

  std::vector<std::pair<double, int> > by_distance;
  by_distance.reserve(interior.size());
  for(int i : interior)
    by_distance.emplace_back((patch.point(static_cast<std::size_t>(i)) - mean).squaredNorm(), i);
  std::sort(by_distance.begin(), by_distance.end());
  for(std::size_t k = 0; k < by_distance.size(); )
  {
    std::size_t end = k + 1;
    while(end < by_distance.size() && by_distance[end].first - by_distance[k].first <= equal)
      ++end;
    if(end == k + 1)
      return by_distance[k].second;
    k = end;
  }
  int smallest = by_distance.front().second;  // no distance held by a single vertex
  for(std::size_t k = 1; k < by_distance.size() && by_distance[k].first - by_distance[0].first <= equal; ++k)
    smallest = (std::min)(smallest, by_distance[k].second);
  return smallest;
}

// The center at the maximum of a distance map that was computed with `status`: OK, or the
// status when it failed, or ERROR_NO_INTERIOR_VERTEX when there is no candidate (the
// values are finite: the solvers check them).
template <class Disk>
Error_code center_at_maximum(const Disk& disk, Error_code status, const std::vector<double>& values,
                             std::size_t& center)
{
  if(status != OK)
    return status;
  const int c = argmax_with_tie_break(disk, values);
  if(c < 0)
    return ERROR_NO_INTERIOR_VERTEX;
  center = static_cast<std::size_t>(c);
  return OK;
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DISTANCES_CENTER_SELECTION_H
