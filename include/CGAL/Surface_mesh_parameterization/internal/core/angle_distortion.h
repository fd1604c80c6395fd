// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CORE_ANGLE_DISTORTION_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CORE_ANGLE_DISTORTION_H

// The paper's angle distortion (Sheffer and de Sturler's angle error), written once:
//     (1 / |V|) sum over corners of ((alpha - phi) / phi)^2,
// alpha the UV corner angle, phi ABF's optimal angle: the 3D corner angle beta, scaled at
// interior vertices so that the angles around the vertex sum to 2 pi (unchanged at border
// vertices). measure_quality() reports it; the border search minimizes it.

#include <CGAL/Surface_mesh_parameterization/internal/core/triangle_geometry.h>

#include <CGAL/number_type_config.h>

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// The factor c with phi = c beta at a vertex: 2 pi / (sum of its 3D angles) at an interior
// vertex, 1 on a border.
inline double optimal_angle_scale(double angle_sum, bool on_border)
{
  return (!on_border && angle_sum > 0.) ? 2. * CGAL_PI / angle_sum : 1.;
}

// One corner's term ((alpha - phi) / phi)^2 (0 for a corner of zero optimal angle).
inline double corner_angle_error(double alpha, double phi)
{
  if(!(phi > 0.))
    return 0.;
  const double x = (alpha - phi) / phi;
  return x * x;
}

// The angle distortion of many layouts of one indexed triangle set, with the optimal angles
// computed once.
class Angle_distortion
{
public:
  // `faces`: the measured faces; `on_border[i]`: whether vertex i lies on a border curve;
  // `vertices`: |V|, the number of vertices of the measured faces.
  Angle_distortion(const std::vector<Eigen::Vector3d>& points, std::vector<Face_indices> faces,
                   const std::vector<bool>& on_border, std::size_t vertices)
    : m_faces(std::move(faces)), m_vertices(double(vertices))
  {
    corner_angles(points, m_faces, m_optimal);
    std::vector<double> sum(points.size(), 0.);
    for(std::size_t f = 0; f < m_faces.size(); ++f)
      for(std::size_t k = 0; k < 3; ++k)
        sum[static_cast<std::size_t>(m_faces[f][k])] += m_optimal[3 * f + k];
    for(std::size_t f = 0; f < m_faces.size(); ++f)
      for(std::size_t k = 0; k < 3; ++k)
      {
        const std::size_t i = static_cast<std::size_t>(m_faces[f][k]);
        if(!on_border[i] && sum[i] > 0.)
          m_optimal[3 * f + k] *= 2. * CGAL_PI / sum[i];
      }
  }

  // The angle distortion of the layout `uv` (one UV per vertex). The layout must have no
  // flipped or degenerate face (the callers test validity first): the third angle of each
  // triangle is then pi minus the other two, which saves a third of the atan2 calls.
  double operator()(const std::vector<Eigen::Vector2d>& uv) const
  {
    double total = 0.;
    for(std::size_t f = 0; f < m_faces.size(); ++f)
    {
      const Eigen::Vector2d& p0 = uv[static_cast<std::size_t>(m_faces[f][0])];
      const Eigen::Vector2d& p1 = uv[static_cast<std::size_t>(m_faces[f][1])];
      const Eigen::Vector2d& p2 = uv[static_cast<std::size_t>(m_faces[f][2])];
      const Eigen::Vector2d e01 = p1 - p0, e02 = p2 - p0, e12 = p2 - p1;
      const double twice_area = std::abs(e01.x() * e02.y() - e01.y() * e02.x());
      double alpha[3];
      alpha[0] = std::atan2(twice_area, e01.dot(e02));
      alpha[1] = std::atan2(twice_area, -e01.dot(e12));
      alpha[2] = CGAL_PI - alpha[0] - alpha[1];
      for(std::size_t k = 0; k < 3; ++k)
        total += corner_angle_error(alpha[k], m_optimal[3 * f + k]);
    }
    return (m_vertices > 0.) ? total / m_vertices : 0.;
  }

private:
  std::vector<Face_indices> m_faces;
  std::vector<double> m_optimal;
  double m_vertices = 0.;
};

// The real faces of a disk (hole fillings left out).
template <class Disk>
std::vector<Face_indices> disk_real_faces(const Disk& disk)
{
  const std::vector<Face_indices>& faces = disk.faces_indices();
  return std::vector<Face_indices>(faces.begin(), faces.begin() + static_cast<std::ptrdiff_t>(disk.number_of_real_faces()));
}

// The angle distortion of the real faces of a disk (the vertices of the holes count as border
// vertices).
template <class Disk>
Angle_distortion disk_angle_distortion(const Disk& disk)
{
  const std::size_t n = disk.number_of_real_vertices();
  std::vector<bool> on_border(disk.number_of_vertices(), false);
  for(int b : disk.border())
    on_border[static_cast<std::size_t>(b)] = true;
  for(const std::vector<int>& hole : disk.hole_loops())
    for(int b : hole)
      on_border[static_cast<std::size_t>(b)] = true;
  return Angle_distortion(disk.points(), disk_real_faces(disk), on_border, n);
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CORE_ANGLE_DISTORTION_H
