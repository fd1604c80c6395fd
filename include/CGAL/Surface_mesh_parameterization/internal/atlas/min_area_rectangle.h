// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_ATLAS_MIN_AREA_RECTANGLE_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_ATLAS_MIN_AREA_RECTANGLE_H

// The rotation of a chart to its smallest bounding box: the minimum-area enclosing rectangle
// of a point set has a side on an edge of the convex hull (Freeman and Shapira 1975), found in
// O(h) over the h hull edges by rotating calipers (Toussaint 1983). The hull is CGAL's
// convex_hull_2 with exact predicates.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/convex_hull_2.h>

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <iterator>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// A rotation (cos, sin) that maps a point set onto its smallest axis-aligned bounding box:
// p -> (c p.x - s p.y, s p.x + c p.y); the box is `width` x `height` with width >= height.
struct Min_area_rectangle
{
  double cos_angle = 1.;
  double sin_angle = 0.;
  double width = 0.;
  double height = 0.;

  Eigen::Vector2d rotate(const Eigen::Vector2d& p) const
  {
    return Eigen::Vector2d(cos_angle * p.x() - sin_angle * p.y(), sin_angle * p.x() + cos_angle * p.y());
  }
};

// The convex hull of the points, counterclockwise, without repeated or collinear points.
inline void convex_hull(const std::vector<Eigen::Vector2d>& points, std::vector<Eigen::Vector2d>& hull)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  std::vector<K::Point_2> input, output;
  input.reserve(points.size());
  for(const Eigen::Vector2d& p : points)
    input.emplace_back(p.x(), p.y());
  CGAL::convex_hull_2(input.begin(), input.end(), std::back_inserter(output), K());
  hull.clear();
  for(const K::Point_2& p : output)
    hull.emplace_back(p.x(), p.y());
}

// Moves `j` forward around the hull while the value of `f` grows.
template <class F>
std::size_t advance_caliper(const std::vector<Eigen::Vector2d>& hull, std::size_t j, const F& f)
{
  const std::size_t h = hull.size();
  for(std::size_t steps = 0; steps < h && f(hull[(j + 1) % h]) > f(hull[j]); ++steps)
    j = (j + 1) % h;
  return j;
}

// The rectangle with a side on the hull edge `i`, its extremal points found from the
// previous ones (`j_*`, moved forward; the one opposite the first edge starts from the
// farthest point: along the hull come the largest projection on the edge's direction, the
// farthest point, then the smallest projection); returns its area, writes the box.
inline double caliper_rectangle(const std::vector<Eigen::Vector2d>& hull, std::size_t i, std::size_t& j_max,
                                std::size_t& j_far, std::size_t& j_min, Min_area_rectangle& box)
{
  const Eigen::Vector2d& p = hull[i];
  const Eigen::Vector2d edge = hull[(i + 1) % hull.size()] - p;
  const Eigen::Vector2d u = edge / edge.norm();
  const auto along = [&u](const Eigen::Vector2d& q) { return u.dot(q); };
  const auto across = [&u](const Eigen::Vector2d& q) { return u.x() * q.y() - u.y() * q.x(); };
  const auto behind = [&u](const Eigen::Vector2d& q) { return -u.dot(q); };
  j_max = advance_caliper(hull, j_max, along);
  j_far = advance_caliper(hull, j_far, across);
  if(i == 0)
    j_min = j_far;
  j_min = advance_caliper(hull, j_min, behind);
  box.cos_angle = u.x();
  box.sin_angle = -u.y();
  box.width = along(hull[j_max]) - along(hull[j_min]);
  box.height = across(hull[j_far]) - across(p);
  return box.width * box.height;
}

// The minimum-area bounding rectangle of the points (the first of equal areas, in the order
// of the hull edges), turned so that its width is at least its height.
inline Min_area_rectangle min_area_rectangle(const std::vector<Eigen::Vector2d>& points)
{
  std::vector<Eigen::Vector2d> hull;
  convex_hull(points, hull);
  Min_area_rectangle best;
  if(hull.size() == 2)
  {
    const Eigen::Vector2d edge = hull[1] - hull[0];
    const double length = edge.norm();
    best.cos_angle = edge.x() / length;
    best.sin_angle = -edge.y() / length;
    best.width = length;
  }
  if(hull.size() >= 3)
  {
    std::size_t j_max = 1, j_far = 1, j_min = 0;
    double best_area = HUGE_VAL;
    for(std::size_t i = 0; i < hull.size(); ++i)
    {
      Min_area_rectangle box;
      const double area = caliper_rectangle(hull, i, j_max, j_far, j_min, box);
      if(area < best_area)
      {
        best_area = area;
        best = box;
      }
    }
  }
  if(best.height > best.width)
    best = Min_area_rectangle{-best.sin_angle, best.cos_angle, best.height, best.width};
  return best;
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_ATLAS_MIN_AREA_RECTANGLE_H
