// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CORE_TRIANGLE_GEOMETRY_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CORE_TRIANGLE_GEOMETRY_H

// The triangle kernels of the package, each written once: corner angles (3D and 2D), the
// half cotangents of a triangle, the degenerate-face test, and the angle sums of an indexed
// triangle set.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// Three local vertex indices, in the mesh's face orientation.
typedef std::array<int, 3> Face_indices;

// Relative threshold below which a face counts as degenerate: 2A <= 1e-12 l_max^2.
constexpr double degenerate_face_threshold = 1e-12;

// The angle between two 3D vectors, in [0, pi] (atan2: accurate near 0 and pi).
inline double corner_angle(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

// The angle between two 2D vectors, in [0, pi].
inline double corner_angle(const Eigen::Vector2d& a, const Eigen::Vector2d& b)
{
  return std::atan2(std::abs(a.x() * b.y() - a.y() * b.x()), a.dot(b));
}

// The angle of triangle (p0, p1, p2) at corner k.
template <class Point>
double corner_angle(const std::array<Point, 3>& p, int k)
{
  const Point& c = p[static_cast<std::size_t>(k)];
  return corner_angle(Point(p[static_cast<std::size_t>((k + 1) % 3)] - c),
                      Point(p[static_cast<std::size_t>((k + 2) % 3)] - c));
}

// Whether the triangle is degenerate: not finite, or 2A <= threshold * (longest edge)^2.
inline bool is_degenerate_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& q, const Eigen::Vector3d& r)
{
  const double longest2 = (std::max)({(q - p).squaredNorm(), (r - q).squaredNorm(), (p - r).squaredNorm()});
  const double double_area = (q - p).cross(r - p).norm();
  return !(double_area > degenerate_face_threshold * longest2) || !std::isfinite(double_area);
}

// Half the cotangent of the angle at each corner of a non-degenerate triangle: the share of
// the face in the cotangent weight of the opposite edge.
inline std::array<double, 3> half_cotangents(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                                             const Eigen::Vector3d& p2)
{
  const std::array<const Eigen::Vector3d*, 3> p = {{&p0, &p1, &p2}};
  const double double_area = (p1 - p0).cross(p2 - p0).norm();
  std::array<double, 3> h;
  for(std::size_t k = 0; k < 3; ++k)
  {
    const Eigen::Vector3d a = *p[(k + 1) % 3] - *p[k];
    const Eigen::Vector3d b = *p[(k + 2) % 3] - *p[k];
    h[k] = 0.5 * a.dot(b) / double_area;
  }
  return h;
}

// The 3D angle at each corner of each face, three per face.
inline void corner_angles(const std::vector<Eigen::Vector3d>& points, const std::vector<Face_indices>& faces,
                          std::vector<double>& angles)
{
  angles.resize(3 * faces.size());
  for(std::size_t f = 0; f < faces.size(); ++f)
  {
    const std::array<Eigen::Vector3d, 3> p = {{points[static_cast<std::size_t>(faces[f][0])],
                                              points[static_cast<std::size_t>(faces[f][1])],
                                              points[static_cast<std::size_t>(faces[f][2])]}};
    for(int k = 0; k < 3; ++k)
      angles[3 * f + static_cast<std::size_t>(k)] = corner_angle(p, k);
  }
}

// The sum of the 3D corner angles at every vertex.
inline void angle_sums(const std::vector<Eigen::Vector3d>& points, const std::vector<Face_indices>& faces,
                       std::vector<double>& sums)
{
  std::vector<double> angles;
  corner_angles(points, faces, angles);
  sums.assign(points.size(), 0.);
  for(std::size_t f = 0; f < faces.size(); ++f)
    for(std::size_t k = 0; k < 3; ++k)
      sums[static_cast<std::size_t>(faces[f][k])] += angles[3 * f + k];
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CORE_TRIANGLE_GEOMETRY_H
