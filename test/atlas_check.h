// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// An independent check of a packed atlas (test_atlas_packing.cpp, benchmark/atlas_packing.cpp):
// it knows nothing of the packer's rasters. Every UV finite and inside [0,1]^2, and at least
// the gutter away from its border; no two triangles of different charts overlap (exact
// predicates: an edge of one crosses an edge of the other, or a vertex of one lies in the
// other); the smallest distance between triangles of different charts (the smallest distance
// between their edges), over the pairs whose boxes, grown by the gutter, meet
// (CGAL::box_self_intersection_d). A chart without triangles counts each of its UVs as a
// point. And, per chart, whether its placed UVs are a similarity of its input UVs: the
// ratios of the edge lengths, and the orientations of its triangles.

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
  std::size_t near_border = 0;         // UVs closer than the gutter to the border of [0,1]^2
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
      const double border = std::min(std::min(p.x(), 1. - p.x()), std::min(p.y(), 1. - p.y()));
      result.near_border += border >= gutter - 1e-12 ? 0 : 1;
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
    result.close_pairs += distance < gutter - 1e-12 ? 1 : 0;
  });
  return result;
}

// Whether a chart's placed UVs are a similarity of its input UVs (no reflection).
struct Shape_check
{
  double ratio = 0.;            // placed length / input length of the first edge measured
  double max_deviation = 0.;    // the largest |ratio of an edge / ratio - 1|
  std::size_t reflected = 0;    // triangles whose orientation changed
  std::size_t edges = 0;        // edges measured (input length above `shortest`)
};

// The check of one chart: every triangle edge (or, without triangles, the segment from the
// first UV to each other) longer than `shortest` in the input.
template <class Face>
Shape_check check_shape(const std::vector<Eigen::Vector2d>& input, const std::vector<Eigen::Vector2d>& placed,
                        const std::vector<Face>& faces, double shortest)
{
  Shape_check c;
  const auto measure = [&](std::size_t a, std::size_t b) {
    const double in = (input[a] - input[b]).norm(), out = (placed[a] - placed[b]).norm();
    if(!(in > shortest))
      return;
    if(c.edges++ == 0)
      c.ratio = out / in;
    else  // (a chart placed as a point: every ratio 0)
      c.max_deviation = std::max(c.max_deviation, c.ratio > 0. ? std::abs(out / in / c.ratio - 1.) : out / in);
  };
  const auto cross = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& d) {
    return (b - a).x() * (d - a).y() - (b - a).y() * (d - a).x();
  };
  for(const Face& f : faces)
  {
    const std::size_t i = std::size_t(f[0]), j = std::size_t(f[1]), k = std::size_t(f[2]);
    measure(i, j);
    measure(j, k);
    measure(k, i);
    const double before = cross(input[i], input[j], input[k]), after = cross(placed[i], placed[j], placed[k]);
    c.reflected += (before > 0. && after < 0.) || (before < 0. && after > 0.) ? 1 : 0;
  }
  for(std::size_t v = 1; faces.empty() && v < input.size(); ++v)
    measure(0, v);
  return c;
}

// The total area of the triangles of a chart.
template <class Face>
double uv_area(const std::vector<Eigen::Vector2d>& uv, const std::vector<Face>& faces)
{
  double area = 0.;
  for(const Face& f : faces)
  {
    const Eigen::Vector2d a = uv[std::size_t(f[0])], b = uv[std::size_t(f[1])], d = uv[std::size_t(f[2])];
    area += 0.5 * std::abs((b - a).x() * (d - a).y() - (b - a).y() * (d - a).x());
  }
  return area;
}

} // namespace mbp_atlas_check

#endif // MBP_TEST_ATLAS_CHECK_H
