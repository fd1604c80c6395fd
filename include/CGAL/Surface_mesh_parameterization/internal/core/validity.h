// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CORE_VALIDITY_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CORE_VALIDITY_H

// The validity tests of the package, each written once, with exact predicates: flipped
// triangles, the intersection of non-adjacent segments (a sweep along x) that serves the
// simple-polygon test and the border-curve test, strict convexity, and the overlap of two UV
// triangles (the global one-to-one test of measure_quality.h).
//
// The one-to-one test of a disk's layout (user manual: Validity and repair). Orient every
// border curve so that the faces are on its left: the outer border counterclockwise, each hole
// clockwise. If every real face is positively oriented in UV, the number of faces covering a
// point q (away from the curves) is the sum of the winding numbers of these curves around q.
// When the curves are simple, pairwise disjoint, and each hole (traversed along its border
// halfedges) is counterclockwise in UV, that sum is 1 inside the outer curve and outside the
// holes, and 0 elsewhere: the map is one-to-one and every hole is a simple polygon. The test
// checks exactly these conditions, in O(F + m log m) time for m border vertices. The outer
// border of the package's layouts is a simple polygon by construction (star-shaped, convex,
// or tested with is_simple_polygon()).

#include <CGAL/box_intersection_d.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/squared_distance_2.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Validity_kernel;

inline Validity_kernel::Point_2 exact_point(const Eigen::Vector2d& p) { return Validity_kernel::Point_2(p.x(), p.y()); }

// Relative tolerance of the convexity test: a turn counts as convex when
// cross(e_prev, e_next) < -convexity_tolerance * |e_prev| |e_next| (clockwise polygon).
constexpr double convexity_tolerance = 1e-12;

// Whether the closed polygon, traversed clockwise, turns strictly right at every vertex.
inline bool is_strictly_convex_clockwise(const std::vector<Eigen::Vector2d>& p)
{
  const std::size_t m = p.size();
  if(m < 3)
    return false;
  for(std::size_t k = 0; k < m; ++k)
  {
    const Eigen::Vector2d e1 = p[k] - p[(k + m - 1) % m];
    const Eigen::Vector2d e2 = p[(k + 1) % m] - p[k];
    const double cross = e1.x() * e2.y() - e1.y() * e2.x();
    if(!(cross < -convexity_tolerance * e1.norm() * e2.norm()))
      return false;
  }
  return true;
}

// Triangles of `faces` (the first `count` of them) whose UV triangle is not positively
// oriented; the count stops at `enough` (1: whether there is one).
template <class Faces>
std::size_t count_flips(const Faces& faces, std::size_t count, const std::vector<Eigen::Vector2d>& uv,
                        std::size_t enough = std::size_t(-1))
{
  std::size_t flips = 0;
  for(std::size_t f = 0; f < count && flips < enough; ++f)
  {
    const auto& t = faces[f];
    if(CGAL::orientation(exact_point(uv[static_cast<std::size_t>(t[0])]), exact_point(uv[static_cast<std::size_t>(t[1])]),
                         exact_point(uv[static_cast<std::size_t>(t[2])])) != CGAL::LEFT_TURN)
      ++flips;
  }
  return flips;
}

// Whether two of the segments (pairs of indices into `uv`) that share no end index meet:
// a sweep along x tests the pairs whose x-ranges overlap.
inline bool non_adjacent_segments_meet(const std::vector<Eigen::Vector2d>& uv,
                                       const std::vector<std::array<int, 2> >& segments)
{
  struct Range
  {
    double xmin, xmax;
    std::size_t segment;
  };
  std::vector<Range> ranges;
  ranges.reserve(segments.size());
  for(std::size_t s = 0; s < segments.size(); ++s)
  {
    const double xa = uv[static_cast<std::size_t>(segments[s][0])].x(), xb = uv[static_cast<std::size_t>(segments[s][1])].x();
    ranges.push_back({(std::min)(xa, xb), (std::max)(xa, xb), s});
  }
  std::sort(ranges.begin(), ranges.end(), [](const Range& a, const Range& b) { return a.xmin < b.xmin; });
  auto segment = [&](std::size_t s) {
    return Validity_kernel::Segment_2(exact_point(uv[static_cast<std::size_t>(segments[s][0])]),
                                      exact_point(uv[static_cast<std::size_t>(segments[s][1])]));
  };
  for(std::size_t i = 0; i < ranges.size(); ++i)
    for(std::size_t j = i + 1; j < ranges.size() && ranges[j].xmin <= ranges[i].xmax; ++j)
    {
      const std::array<int, 2>& s = segments[ranges[i].segment];
      const std::array<int, 2>& t = segments[ranges[j].segment];
      if(s[0] == t[0] || s[0] == t[1] || s[1] == t[0] || s[1] == t[1])
        continue;  // consecutive segments of one curve
      if(CGAL::do_intersect(segment(ranges[i].segment), segment(ranges[j].segment)))
        return true;
    }
  return false;
}

// Whether two of the segments (pairs of indices into `uv`) come within `clearance` of each
// other: two that share no end index anywhere, two that share one (consecutive along a
// curve) by the other end of one against the other one (a spike, or a crack between them). A
// curve that passes is a rounding of the coordinates away from meeting itself. A sweep along x
// tests the pairs whose x-ranges, grown by the clearance, overlap.
inline bool segments_within_clearance(const std::vector<Eigen::Vector2d>& uv,
                                      const std::vector<std::array<int, 2> >& segments, double clearance)
{
  typedef Validity_kernel::Point_2 Point;
  typedef Validity_kernel::Segment_2 Segment;
  std::vector<std::pair<double, std::size_t> > starts;  // (xmin - clearance, segment)
  std::vector<double> xmax(segments.size());
  for(std::size_t s = 0; s < segments.size(); ++s)
  {
    const double xa = uv[std::size_t(segments[s][0])].x(), xb = uv[std::size_t(segments[s][1])].x();
    starts.emplace_back((std::min)(xa, xb) - clearance, s);
    xmax[s] = (std::max)(xa, xb) + clearance;
  }
  std::sort(starts.begin(), starts.end());
  const double c2 = clearance * clearance;
  auto point = [&](int i) { return exact_point(uv[std::size_t(i)]); };
  auto segment = [&](std::size_t s) { return Segment(point(segments[s][0]), point(segments[s][1])); };
  auto near = [&](const Point& p, std::size_t s) { return CGAL::to_double(CGAL::squared_distance(p, segment(s))) < c2; };
  for(std::size_t i = 0; i < starts.size(); ++i)
    for(std::size_t j = i + 1; j < starts.size() && starts[j].first <= xmax[starts[i].second]; ++j)
    {
      const std::size_t a = starts[i].second, b = starts[j].second;
      const std::array<int, 2>&s = segments[a], &t = segments[b];
      const int shared = (s[0] == t[0] || s[0] == t[1]) ? s[0] : (s[1] == t[0] || s[1] == t[1]) ? s[1] : -1;
      if(shared < 0 ? CGAL::to_double(CGAL::squared_distance(segment(a), segment(b))) < c2
                    : near(point(s[0] == shared ? s[1] : s[0]), b) || near(point(t[0] == shared ? t[1] : t[0]), a))
        return true;
    }
  return false;
}

// The segments of a closed loop of indices.
inline void add_loop_segments(const std::vector<int>& loop, std::vector<std::array<int, 2> >& segments)
{
  for(std::size_t k = 0; k < loop.size(); ++k)
    segments.push_back({{loop[k], loop[(k + 1) % loop.size()]}});
}

// Whether the closed polygon is simple: no zero-length edge, no fold-back at a vertex, and no
// two non-adjacent edges that meet.
inline bool is_simple_polygon(const std::vector<Eigen::Vector2d>& p)
{
  const std::size_t m = p.size();
  if(m < 3)
    return false;
  for(std::size_t k = 0; k < m; ++k)
  {
    const Validity_kernel::Point_2 a = exact_point(p[(k + m - 1) % m]), b = exact_point(p[k]), c = exact_point(p[(k + 1) % m]);
    if(b == c)
      return false;
    if(CGAL::orientation(a, b, c) == CGAL::COLLINEAR && (b - a) * (c - b) < 0.)
      return false;  // the edge folds back onto the previous one
  }
  std::vector<int> loop(m);
  for(std::size_t k = 0; k < m; ++k)
    loop[k] = static_cast<int>(k);
  std::vector<std::array<int, 2> > segments;
  add_loop_segments(loop, segments);
  return !non_adjacent_segments_meet(p, segments);
}

// Twice the signed area of a loop of indices into `uv`.
inline double signed_double_area(const std::vector<int>& loop, const std::vector<Eigen::Vector2d>& uv)
{
  double area = 0.;
  for(std::size_t k = 0; k < loop.size(); ++k)
  {
    const Eigen::Vector2d& p = uv[static_cast<std::size_t>(loop[k])];
    const Eigen::Vector2d& q = uv[static_cast<std::size_t>(loop[(k + 1) % loop.size()])];
    area += p.x() * q.y() - p.y() * q.x();
  }
  return area;
}

// Whether the border curves of a disk (the outer border, a simple polygon, and the holes)
// are pairwise disjoint and simple, and the holes counterclockwise along their border
// halfedges (see the top of this file).
template <class Disk>
bool border_curves_are_valid(const Disk& disk, const std::vector<Eigen::Vector2d>& uv)
{
  if(disk.hole_loops().empty())
    return true;  // the outer border alone is simple
  std::vector<std::array<int, 2> > segments;
  add_loop_segments(disk.border(), segments);
  for(const std::vector<int>& hole : disk.hole_loops())
  {
    if(!(signed_double_area(hole, uv) > 0.))
      return false;
    add_loop_segments(hole, segments);
  }
  return !non_adjacent_segments_meet(uv, segments);
}

// The one-to-one test of a disk's layout (one UV per disk vertex): no flipped real face,
// valid border curves.
template <class Disk>
bool is_one_to_one(const Disk& disk, const std::vector<Eigen::Vector2d>& uv)
{
  return count_flips(disk.faces_indices(), disk.number_of_real_faces(), uv) == 0 && border_curves_are_valid(disk, uv);
}

// Whether the interiors of two counterclockwise UV triangles overlap (or touch beyond the
// vertices and edge they share in the mesh); `a` and `b` name their vertices.
inline bool uv_triangles_overlap(const std::array<std::size_t, 3>& a, const std::array<Validity_kernel::Point_2, 3>& p,
                                 const std::array<std::size_t, 3>& b, const std::array<Validity_kernel::Point_2, 3>& q)
{
  typedef Validity_kernel K;
  int shared = 0, ka = 0, kb = 0, ia = 0, ib = 0;
  for(int k = 0; k < 3; ++k)
  {
    const bool a_in_b = std::find(b.begin(), b.end(), a[std::size_t(k)]) != b.end();
    const bool b_in_a = std::find(a.begin(), a.end(), b[std::size_t(k)]) != a.end();
    if(a_in_b)
    {
      ++shared;
      ka = k;
    }
    else
      ia = k;
    if(b_in_a)
      kb = k;
    else
      ib = k;
  }
  if(shared >= 2)  // a shared edge: the two third vertices must lie on opposite sides of it
  {
    const K::Point_2& e0 = p[std::size_t((ia + 1) % 3)];
    const K::Point_2& e1 = p[std::size_t((ia + 2) % 3)];
    return shared > 2 || CGAL::orientation(e0, e1, p[std::size_t(ia)]) == CGAL::orientation(e0, e1, q[std::size_t(ib)]);
  }
  if(shared == 1)  // a shared vertex: the edge opposite it in one meets the other triangle
  {
    const K::Segment_2 sa(p[std::size_t((ka + 1) % 3)], p[std::size_t((ka + 2) % 3)]);
    const K::Segment_2 sb(q[std::size_t((kb + 1) % 3)], q[std::size_t((kb + 2) % 3)]);
    return CGAL::do_intersect(K::Triangle_2(p[0], p[1], p[2]), sb) || CGAL::do_intersect(K::Triangle_2(q[0], q[1], q[2]), sa);
  }
  return CGAL::do_intersect(K::Triangle_2(p[0], p[1], p[2]), K::Triangle_2(q[0], q[1], q[2]));
}

// Whether two of the UV triangles overlap (uv_triangles_overlap()); `vertices` name the corners
// of each triangle. Only the pairs whose bounding boxes meet are tested (CGAL's
// box_self_intersection_d), O(F log F) typically.
inline bool any_uv_triangles_overlap(const std::vector<std::array<std::size_t, 3> >& vertices,
                                     const std::vector<std::array<Validity_kernel::Point_2, 3> >& corners)
{
  typedef CGAL::Box_intersection_d::Box_with_info_d<double, 2, std::size_t, CGAL::Box_intersection_d::ID_FROM_BOX_ADDRESS> Box;
  std::vector<Box> boxes;
  boxes.reserve(corners.size());
  for(std::size_t i = 0; i < corners.size(); ++i)
    boxes.emplace_back(corners[i][0].bbox() + corners[i][1].bbox() + corners[i][2].bbox(), i);
  // pointers: the boxes' ids are their addresses, which the algorithm's copies keep
  std::vector<const Box*> pointers;
  pointers.reserve(boxes.size());
  for(const Box& b : boxes)
    pointers.push_back(&b);
  bool overlap = false;
  CGAL::box_self_intersection_d(pointers.begin(), pointers.end(), [&](const Box* a, const Box* b) {
    overlap = overlap || uv_triangles_overlap(vertices[a->info()], corners[a->info()], vertices[b->info()], corners[b->info()]);
  });
  return overlap;
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CORE_VALIDITY_H
