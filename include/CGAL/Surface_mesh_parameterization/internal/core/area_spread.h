// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CORE_AREA_SPREAD_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CORE_AREA_SPREAD_H

// The area spread, written once for the atlas's charts and the border search: the
// area-weighted mean of |log(A_uv / A_3d)| over the faces after the UV areas are scaled to
// the 3D total (0 when every area is kept up to one scale; measure_quality()'s
// area_distortion_mean). Faces of zero area (3D or UV) add nothing.

#include <CGAL/Surface_mesh_parameterization/internal/core/triangle_geometry.h>

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// The area spread of faces of 3D areas `area3` and UV areas `area_uv` (both non-negative).
inline double area_spread(const std::vector<double>& area3, const std::vector<double>& area_uv)
{
  double total3 = 0., total_uv = 0.;
  for(std::size_t i = 0; i < area3.size(); ++i)
  {
    total3 += area3[i];
    total_uv += area_uv[i];
  }
  if(!(total3 > 0.) || !(total_uv > 0.))
    return 0.;
  const double log_scale = std::log(total3 / total_uv);
  double sum = 0.;
  for(std::size_t i = 0; i < area3.size(); ++i)
    if(area3[i] > 0. && area_uv[i] > 0.)
      sum += area3[i] * std::abs(std::log(area_uv[i] / area3[i]) + log_scale);
  return sum / total3;
}

// The unsigned area of a UV triangle.
inline double uv_triangle_area(const Eigen::Vector2d& p0, const Eigen::Vector2d& p1, const Eigen::Vector2d& p2)
{
  const Eigen::Vector2d e = p1 - p0, g = p2 - p0;
  return 0.5 * std::abs(e.x() * g.y() - e.y() * g.x());
}

// The area spread of many layouts of one indexed triangle set, with the 3D areas computed
// once (the border search's second figure, beside Angle_distortion).
class Area_spread
{
public:
  Area_spread(const std::vector<Eigen::Vector3d>& points, std::vector<Face_indices> faces)
    : m_faces(std::move(faces)), m_area3(m_faces.size()), m_area_uv(m_faces.size())
  {
    for(std::size_t f = 0; f < m_faces.size(); ++f)
    {
      const Eigen::Vector3d& p0 = points[static_cast<std::size_t>(m_faces[f][0])];
      m_area3[f] = 0.5 * (points[static_cast<std::size_t>(m_faces[f][1])] - p0)
                           .cross(points[static_cast<std::size_t>(m_faces[f][2])] - p0).norm();
    }
  }

  // The area spread of the layout `uv` (one UV per vertex; a flipped face counts by its
  // unsigned area).
  double operator()(const std::vector<Eigen::Vector2d>& uv)
  {
    for(std::size_t f = 0; f < m_faces.size(); ++f)
      m_area_uv[f] = uv_triangle_area(uv[static_cast<std::size_t>(m_faces[f][0])],
                                      uv[static_cast<std::size_t>(m_faces[f][1])],
                                      uv[static_cast<std::size_t>(m_faces[f][2])]);
    return area_spread(m_area3, m_area_uv);
  }

private:
  std::vector<Face_indices> m_faces;
  std::vector<double> m_area3, m_area_uv;  // m_area_uv: the buffer of one call
};

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CORE_AREA_SPREAD_H
