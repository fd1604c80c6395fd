// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// An independent check of a packed atlas (test_atlas_packing.cpp, benchmark/atlas_packing.cpp):
// it knows nothing of the packer's rasters. Every UV finite and inside [0,1]^2; no two
// triangles of different charts overlap (exact predicates: an edge of one crosses an edge of
// the other, or a vertex of one lies in the other); the smallest distance between triangles of
// different charts, over the pairs whose boxes, grown by the gutter, meet
// (CGAL::box_self_intersection_d). A chart without triangles counts each of its UVs as a
// point.

#ifndef MBP_TEST_ATLAS_CHECK_H
#define MBP_TEST_ATLAS_CHECK_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace mbp_atlas_check {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef std::array<K::Point_2, 3> Triangle;

struct Atlas_check
{
  std::size_t non_finite = 0;          // UVs that are NaN or infinite
  std::size_t outside = 0;             // UVs outside [0,1]^2
  std::size_t overlapping_pairs = 0;   // pairs of triangles of different charts that meet
  std::size_t close_pairs = 0;         // pairs of different charts closer than the gutter
  double min_distance = std::numeric_limits<double>::infinity();  // between different charts
};

// Whether the point lies in the closed triangle (any orientation, degenerate included).
inline bool in_triangle(const K::Point_2& p, const Triangle& t)
{
  const CGAL::Orientation o0 = CGAL::orientation(t[0], t[1], p), o1 = CGAL::orientation(t[1], t[2], p),
                          o2 = CGAL::orientation(t[2], t[0], p);
  const bool no_right = o0 != CGAL::RIGHT_TURN && o1 != CGAL::RIGHT_TURN && o2 != CGAL::RIGHT_TURN;
  const bool no_left = o0 != CGAL::LEFT_TURN && o1 != CGAL::LEFT_TURN && o2 != CGAL::LEFT_TURN;
  if(CGAL::orientation(t[0], t[1], t[2]) != CGAL::COLLINEAR)
    return no_right || no_left;
  for(int k = 0; k < 3; ++k)  // a degenerate triangle is the union of its edges
    if(CGAL::do_intersect(K::Segment_2(t[std::size_t(k)], t[std::size_t((k + 1) % 3)]), p))
      return true;
  return false;
}

// Whether two closed triangles meet (exactly), and otherwise their distance.
inline bool triangles_meet(const Triangle& a, const Triangle& b, double& distance)
{
  double squared = std::numeric_limits<double>::infinity();
  for(int i = 0; i < 3; ++i)
    for(int j = 0; j < 3; ++j)
    {
      const K::Segment_2 s(a[std::size_t(i)], a[std::size_t((i + 1) % 3)]);
      const K::Segment_2 t(b[std::size_t(j)], b[std::size_t((j + 1) % 3)]);
      if(CGAL::do_intersect(s, t))
        return true;
      squared = std::min(squared, CGAL::to_double(CGAL::squared_distance(s, t)));
    }
  if(in_triangle(a[0], b) || in_triangle(b[0], a))
    return true;
  distance = std::sqrt(squared);
  return false;
}

// The check of charts (per chart: UVs and triangles) placed with the gutter `gutter` (in UV
// units: gutter texels / resolution).
template <class Faces>
Atlas_check check_atlas(const std::vector<std::vector<Eigen::Vector2d> >& uv, const std::vector<Faces>& faces,
                        double gutter)
{
  Atlas_check result;
  std::vector<Triangle> triangles;
  std::vector<std::size_t> chart_of;
  for(std::size_t c = 0; c < uv.size(); ++c)
  {
    for(const Eigen::Vector2d& p : uv[c])
    {
      result.non_finite += std::isfinite(p.x()) && std::isfinite(p.y()) ? 0 : 1;
      result.outside += p.x() >= 0. && p.x() <= 1. && p.y() >= 0. && p.y() <= 1. ? 0 : 1;
    }
    const auto point = [&](std::size_t v) { return K::Point_2(uv[c][v].x(), uv[c][v].y()); };
    for(const auto& f : faces[c])
      triangles.push_back(Triangle{{point(std::size_t(f[0])), point(std::size_t(f[1])), point(std::size_t(f[2]))}});
    for(std::size_t v = 0; faces[c].empty() && v < uv[c].size(); ++v)
      triangles.push_back(Triangle{{point(v), point(v), point(v)}});
    chart_of.resize(triangles.size(), c);
  }
  if(result.non_finite > 0)
    return result;
  typedef CGAL::Box_intersection_d::Box_with_info_d<double, 2, std::size_t> Box;
  std::vector<Box> boxes;
  for(std::size_t t = 0; t < triangles.size(); ++t)
  {
    CGAL::Bbox_2 b = triangles[t][0].bbox() + triangles[t][1].bbox() + triangles[t][2].bbox();
    b = CGAL::Bbox_2(b.xmin() - gutter / 2, b.ymin() - gutter / 2, b.xmax() + gutter / 2, b.ymax() + gutter / 2);
    boxes.push_back(Box(b, t));
  }
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), [&](const Box& a, const Box& b) {
    if(chart_of[a.info()] == chart_of[b.info()])
      return;
    double distance = 0.;
    const bool meet = triangles_meet(triangles[a.info()], triangles[b.info()], distance);
    result.overlapping_pairs += meet ? 1 : 0;
    result.min_distance = std::min(result.min_distance, distance);
    result.close_pairs += distance < gutter * (1. - 1e-9) ? 1 : 0;
  });
  return result;
}

} // namespace mbp_atlas_check

#endif // MBP_TEST_ATLAS_CHECK_H
