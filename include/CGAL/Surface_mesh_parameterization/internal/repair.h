// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_REPAIR_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_REPAIR_H

// Validity of a parameterization of a patch (user manual: Validity and repair): the one-to-one test.
//
// The one-to-one test. Orient every border curve of the patch so that the faces are on its
// left: the outer border counterclockwise, each hole clockwise. If every real face is
// positively oriented in UV, the number of faces covering a point q (away from the curves)
// is the sum of the winding numbers of these curves around q. When the curves are simple,
// pairwise disjoint, and each hole (traversed along its border halfedges) is counterclockwise
// in UV, that sum is 1 inside the outer curve and outside the holes, and 0 elsewhere: the map
// is one-to-one and every hole is a simple polygon. The test checks exactly these
// conditions (exact predicates for the segment intersections), in O(F + m log m) time for m
// border vertices. The outer border is star-shaped by construction, hence simple.

#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/internal/laplacian.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/number_type_config.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// UV of every patch vertex from the border UVs (border() order) and the interior solution
// (interior_vertices() order).
template <class Patch>
void assemble_uv(const Patch& patch, const std::vector<Eigen::Vector2d>& border_uv,
                 const std::vector<double>& u, const std::vector<double>& v,
                 std::vector<Eigen::Vector2d>& uv)
{
  uv.assign(patch.number_of_vertices(), Eigen::Vector2d::Zero());
  for(std::size_t k = 0; k < border_uv.size(); ++k)
    uv[static_cast<std::size_t>(patch.border()[k])] = border_uv[k];
  const std::vector<int>& interior = patch.interior_vertices();
  for(std::size_t r = 0; r < interior.size(); ++r)
    uv[static_cast<std::size_t>(interior[r])] = Eigen::Vector2d(u[r], v[r]);
}

// Real faces (the mesh's, not the hole fillings) whose UV triangle is not positively oriented.
template <class Patch>
std::size_t count_flips(const Patch& patch, const std::vector<Eigen::Vector2d>& uv)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  std::size_t flips = 0;
  const std::vector<std::array<int, 3> >& faces = patch.faces_indices();
  for(std::size_t f = 0; f < patch.number_of_real_faces(); ++f)
  {
    const std::array<int, 3>& t = faces[f];
    const Eigen::Vector2d &a = uv[static_cast<std::size_t>(t[0])], &b = uv[static_cast<std::size_t>(t[1])],
                          &c = uv[static_cast<std::size_t>(t[2])];
    if(CGAL::orientation(K::Point_2(a.x(), a.y()), K::Point_2(b.x(), b.y()), K::Point_2(c.x(), c.y())) !=
       CGAL::LEFT_TURN)
      ++flips;
  }
  return flips;
}

// Whether the border curves (outer border and holes) are simple, pairwise disjoint, and the
// holes counterclockwise along their border halfedges (see the top of this file).
template <class Patch>
bool border_curves_are_valid(const Patch& patch, const std::vector<Eigen::Vector2d>& uv)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  std::vector<const std::vector<int>*> loops(1, &patch.border());
  for(const std::vector<int>& hole : patch.hole_loops())
  {
    double area = 0.;
    for(std::size_t k = 0; k < hole.size(); ++k)
    {
      const Eigen::Vector2d& p = uv[static_cast<std::size_t>(hole[k])];
      const Eigen::Vector2d& q = uv[static_cast<std::size_t>(hole[(k + 1) % hole.size()])];
      area += p.x() * q.y() - p.y() * q.x();
    }
    if(!(area > 0.))
      return false;
    loops.push_back(&hole);
  }
  if(loops.size() == 1)
    return true;  // the outer border alone is star-shaped, hence simple

  // all border segments, swept along x: a segment is tested against those whose x-range
  // overlaps its own
  struct Segment
  {
    int a, b;
    double xmin, xmax;
  };
  std::vector<Segment> segments;
  for(const std::vector<int>* loop : loops)
    for(std::size_t k = 0; k < loop->size(); ++k)
    {
      const int a = (*loop)[k], b = (*loop)[(k + 1) % loop->size()];
      const double xa = uv[static_cast<std::size_t>(a)].x(), xb = uv[static_cast<std::size_t>(b)].x();
      segments.push_back({a, b, (std::min)(xa, xb), (std::max)(xa, xb)});
    }
  std::sort(segments.begin(), segments.end(),
            [](const Segment& s, const Segment& t) { return s.xmin < t.xmin; });
  auto point = [&uv](int i) {
    return K::Point_2(uv[static_cast<std::size_t>(i)].x(), uv[static_cast<std::size_t>(i)].y());
  };
  for(std::size_t i = 0; i < segments.size(); ++i)
    for(std::size_t j = i + 1; j < segments.size() && segments[j].xmin <= segments[i].xmax; ++j)
    {
      const Segment &s = segments[i], &t = segments[j];
      if(s.a == t.a || s.a == t.b || s.b == t.a || s.b == t.b)
        continue;  // consecutive segments of one curve (a fold-back there flips a face)
      if(CGAL::do_intersect(K::Segment_2(point(s.a), point(s.b)), K::Segment_2(point(t.a), point(t.b))))
        return false;
    }
  return true;
}

// The one-to-one test: no flipped real face, valid border curves.
template <class Patch>
bool is_one_to_one(const Patch& patch, const std::vector<Eigen::Vector2d>& uv)
{
  return count_flips(patch, uv) == 0 && border_curves_are_valid(patch, uv);
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_REPAIR_H
