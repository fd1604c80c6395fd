// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// Generated polygon soups, one defect each, for the suites of the atlas (test_soup_repair.cpp,
// test_atlas.cpp).

#ifndef MBP_TEST_ATLAS_SOUPS_H
#define MBP_TEST_ATLAS_SOUPS_H

#include "test_support.h"

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace mbp_test {

inline Soup square(double x0 = 0.)
{
  Soup s;
  s.points = {{{x0, 0., 0.}}, {{x0 + 1., 0., 0.}}, {{x0 + 1., 1., 0.}}, {{x0, 1., 0.}}};
  s.faces = {{0, 1, 2}, {0, 2, 3}};
  return s;
}

inline void append(Soup& soup, const Soup& other)
{
  const std::size_t offset = soup.points.size();
  soup.points.insert(soup.points.end(), other.points.begin(), other.points.end());
  for(std::vector<std::size_t> polygon : other.faces)
  {
    for(std::size_t& i : polygon)
      i += offset;
    soup.faces.push_back(polygon);
  }
}

// An n x n grid of unit squares in z = 0, two triangles each, turning counterclockwise
// seen from +z.
inline Soup grid(int n)
{
  Soup s;
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i)
      s.points.push_back({{double(i), double(j), 0.}});
  auto id = [n](int i, int j) { return std::size_t(j * (n + 1) + i); };
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i)
    {
      s.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      s.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return s;
}

// A vertex shared by two cones: apex 0; a closed fan of 4 triangles up to the ring z = 1,
// another down to z = -1.
inline Soup two_cones()
{
  Soup s;
  s.points.push_back({{0., 0., 0.}});
  for(double z : {1., -1.})
    for(int k = 0; k < 4; ++k)
      s.points.push_back({{std::cos(k * M_PI / 2), std::sin(k * M_PI / 2), z}});
  for(std::size_t k = 0; k < 4; ++k)
  {
    s.faces.push_back({0, 1 + k, 1 + (k + 1) % 4});
    s.faces.push_back({0, 5 + (k + 1) % 4, 5 + k});
  }
  return s;
}

// A square A B C D (0-3); E F (4, 5) apart; a bow tie G H I G J K (6-10); polygons through a
// point twice: 3 degenerate ones (one on an edge A B, one on the edge C D, one whose points no
// face has), one that simplifies to a duplicate, one that splits into two triangles.
inline Soup polygons_through_a_point_twice_soup()
{
  Soup s = square();
  s.points.insert(s.points.end(), {{{5., 5., 0.}}, {{6., 5., 0.}}, {{3., 0., 0.}}, {{4., 0., 0.}},
                                   {{4., 1., 0.}}, {{2., 1., 0.}}, {{2., -1., 0.}}});
  s.faces.push_back({0, 1, 0});           // 2 points: on the edge A B
  s.faces.push_back({2, 2, 3, 3});        // 2 points: on the edge C D
  s.faces.push_back({1, 1, 2, 0});        // A B C once simplified: a duplicate of the first face
  s.faces.push_back({4, 5, 4});           // 2 points no face has: isolated
  s.faces.push_back({6, 7, 8, 6, 9, 10}); // two triangles meeting at G
  return s;
}

// A grid with every `step`-th face of `s`, from `first`, reversed.
inline Soup with_reversed_faces(Soup s, std::size_t first, std::size_t step)
{
  for(std::size_t f = first; f < s.faces.size(); f += step)
    std::reverse(s.faces[f].begin(), s.faces[f].end());
  return s;
}

// An edge with three faces: three triangles on the edge (0, 1).
inline Soup edge_with_three_faces_soup()
{
  Soup s;
  s.points = {{{0., 0., 0.}}, {{1., 0., 0.}}, {{.5, 1., 0.}}, {{.5, -1., 0.}}, {{.5, 0., 1.}}};
  s.faces = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  return s;
}

// A(0) B(1) C(2) M(3) E(4): the sliver A M B (M the middle of AB) along the edge AB of the
// face A B C; the only link between A B C and the two faces below it.
inline Soup zero_area_face_on_an_edge_soup()
{
  Soup s;
  s.points = {{{0., 0., 0.}}, {{2., 0., 0.}}, {{1., 1., 0.}}, {{1., 0., 0.}}, {{1., -1., 0.}}};
  s.faces = {{0, 1, 2}, {0, 4, 3}, {3, 4, 1}, {0, 3, 1}};
  return s;
}

// Two quads and a pentagon, planar (z = 0), counterclockwise seen from +z.
inline Soup quads_and_a_pentagon_soup()
{
  Soup s;
  s.points = {{{0., 0., 0.}}, {{1., 0., 0.}}, {{2., 0., 0.}}, {{0., 1., 0.}}, {{1., 1., 0.}}, {{2., 1., 0.}},
              {{1.2, 1.8, 0.}}, {{.5, 2.3, 0.}}, {{-.2, 1.8, 0.}}};
  s.faces = {{0, 1, 4, 3}, {1, 2, 5, 4}, {3, 4, 6, 7, 8}};
  return s;
}

// A Moebius strip of n quads around a circle, the strip's direction turning half a turn: the
// last quad meets the first upside down.
inline Soup moebius_strip_soup(int n)
{
  Soup s;
  for(int i = 0; i < n; ++i)
  {
    const double a = 2 * M_PI * i / n;
    const Eigen::Vector3d c(std::cos(a), std::sin(a), 0.);
    const Eigen::Vector3d w = std::cos(a / 2) * c + std::sin(a / 2) * Eigen::Vector3d::UnitZ();
    for(double side : {-.25, .25})
      s.points.push_back({{c.x() + side * w.x(), c.y() + side * w.y(), c.z() + side * w.z()}});
  }
  for(std::size_t i = 0; i + 1 < std::size_t(n); ++i)
    s.faces.push_back({2 * i, 2 * i + 2, 2 * i + 3, 2 * i + 1});
  const std::size_t last = 2 * std::size_t(n - 1);
  s.faces.push_back({last, 1, 0, last + 1});
  return s;
}

// A closed torus of n x n quads sheared so that one diagonal of each quad runs along a
// meridian: the shortest meridian loop crosses every quad it meets through that diagonal
// (vertex (i, j) at the angles 2 pi (i - j) / n around the axis and 2 pi j / n around the tube).
inline Soup sheared_quad_torus(int n)
{
  Soup s;
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < n; ++j)
    {
      const double u = 2. * M_PI * (i - j) / n, v = 2. * M_PI * j / n;
      s.points.push_back({{(2. + 0.7 * std::cos(v)) * std::cos(u), (2. + 0.7 * std::cos(v)) * std::sin(u), 0.7 * std::sin(v)}});
    }
  auto id = [n](int i, int j) { return std::size_t(((i + n) % n) * n + (j + n) % n); };
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < n; ++j)
      s.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  return s;
}


// A developable strip wound 1.5 turns around a cone: the cone over the curve of unit
// directions d(t) = (cos t, sin t, 0.15 t) / |.| for t in [0, 3 pi] (a helix seen from its
// axis' origin: the apex), between distances 1 and 2 from the apex; n quads along the strip,
// 2 across, each planar (its four corners on two rays from the apex). Its flattening keeps the
// distances to the apex as radii and unrolls the curve of directions to its length, about 7.7
// radians: more than a turn, so the one-chart flattening overlaps itself.
inline Soup strip_around_a_cone(int n)
{
  Soup s;
  for(int i = 0; i <= n; ++i)
  {
    const double t = 3. * M_PI * i / n;
    const Eigen::Vector3d d = Eigen::Vector3d(std::cos(t), std::sin(t), 0.15 * t).normalized();
    for(double r : {1., 1.5, 2.})
      s.points.push_back({{r * d.x(), r * d.y(), r * d.z()}});
  }
  for(std::size_t i = 0; i < std::size_t(n); ++i)
    for(std::size_t k = 0; k < 2; ++k)
      s.faces.push_back({3 * i + k, 3 * i + k + 1, 3 * i + k + 4, 3 * i + k + 3});
  return s;
}

// The unit cube, each side an n x n grid of quads (turning counterclockwise seen from
// outside); the sides' shared points are listed once per side (the repair merges them).
inline Soup cube_of_quads(int n)
{
  Soup s;
  for(int axis = 0; axis < 3; ++axis)
    for(int sign = 0; sign < 2; ++sign)
    {
      Eigen::Vector3d normal = Eigen::Vector3d::Zero(), u = normal, v = normal;
      normal[axis] = sign ? 1. : -1.;
      u[(axis + 1) % 3] = 1.;
      v = normal.cross(u);
      const std::size_t first = s.points.size();
      for(int j = 0; j <= n; ++j)
        for(int i = 0; i <= n; ++i)
        {
          const Eigen::Vector3d p = Eigen::Vector3d::Constant(0.5) + 0.5 * normal + (double(i) / n - 0.5) * u +
                                    (double(j) / n - 0.5) * v;
          s.points.push_back({{p.x(), p.y(), p.z()}});
        }
      auto id = [first, n](int i, int j) { return first + std::size_t(j * (n + 1) + i); };
      for(int j = 0; j < n; ++j)
        for(int i = 0; i < n; ++i)
          s.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return s;
}

} // namespace mbp_test

#endif // MBP_TEST_ATLAS_SOUPS_H
