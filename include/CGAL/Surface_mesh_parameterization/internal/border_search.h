// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_BORDER_SEARCH_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_BORDER_SEARCH_H

// What the automatic border needs: the circle's polar angles (arc length, CGAL's
// convention), the blend of a measured border toward the circle, and the objective (the
// paper's angle distortion with the 3D optimal angles computed once).

#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/internal/polar_map.h>

#include <CGAL/number_type_config.h>

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// Polar angles of the circular arc-length border: 2 pi s_k / L, s_k the 3D length of the
// border from b_0 to b_k.
template <class Patch>
std::vector<double> arc_length_angles(const Patch& patch)
{
  const std::vector<int>& border = patch.border();
  const std::size_t m = border.size();
  std::vector<double> s(m, 0.);
  double total = 0.;
  for(std::size_t k = 0; k < m; ++k)
  {
    s[k] = total;
    total += (patch.point(static_cast<std::size_t>(border[(k + 1) % m])) -
              patch.point(static_cast<std::size_t>(border[k]))).norm();
  }
  for(double& x : s)
    x = (total > 0.) ? 2. * CGAL_PI * x / total : 0.;
  return s;
}

// The blend of a measured border (polar angles `angles`, radii `radii`) toward the circle
// (angles `circle`, radius 1), in polar coordinates after normalizing the mean radius:
// angle (1 - t) angles + t circle, radius (1 - t) radii / mean + t.
inline Error_code blended_border(const std::vector<double>& angles, const std::vector<double>& radii,
                                 const std::vector<double>& circle, double t, Polar_border& out)
{
  double mean = 0.;
  for(double r : radii)
    mean += r;
  mean /= double(radii.size());
  if(!(mean > 0.))
    return ERROR_DEGENERATE_BORDER_MAP;
  std::vector<double> a(angles.size()), r(radii.size());
  for(std::size_t k = 0; k < angles.size(); ++k)
  {
    a[k] = (1. - t) * angles[k] + t * circle[k];
    r[k] = (1. - t) * radii[k] / mean + t;
  }
  return place_polar_border(a, r, out);
}

// The paper's angle distortion (measure_quality()'s `angle_distortion`) over the real faces
// of a patch, with the 3D optimal angles computed once for many layouts.
class Angle_distortion_objective
{
public:
  template <class Patch>
  explicit Angle_distortion_objective(const Patch& patch)
  {
    const std::size_t n = patch.number_of_real_vertices();
    const std::vector<std::array<int, 3> >& faces = patch.faces_indices();
    std::vector<bool> on_border(n, false);
    for(int b : patch.border())
      on_border[static_cast<std::size_t>(b)] = true;
    for(const std::vector<int>& hole : patch.hole_loops())
      for(int b : hole)
        on_border[static_cast<std::size_t>(b)] = true;
    m_faces.assign(faces.begin(), faces.begin() + static_cast<std::ptrdiff_t>(patch.number_of_real_faces()));
    m_optimal.resize(3 * m_faces.size());
    std::vector<double> sum(n, 0.);
    for(std::size_t f = 0; f < m_faces.size(); ++f)
      for(int k = 0; k < 3; ++k)
      {
        const Eigen::Vector3d& p = patch.point(static_cast<std::size_t>(m_faces[f][static_cast<std::size_t>(k)]));
        const Eigen::Vector3d a = patch.point(static_cast<std::size_t>(m_faces[f][static_cast<std::size_t>((k + 1) % 3)])) - p;
        const Eigen::Vector3d b = patch.point(static_cast<std::size_t>(m_faces[f][static_cast<std::size_t>((k + 2) % 3)])) - p;
        const double beta = std::atan2(a.cross(b).norm(), a.dot(b));
        m_optimal[3 * f + static_cast<std::size_t>(k)] = beta;
        sum[static_cast<std::size_t>(m_faces[f][static_cast<std::size_t>(k)])] += beta;
      }
    for(std::size_t f = 0; f < m_faces.size(); ++f)
      for(int k = 0; k < 3; ++k)
      {
        const std::size_t i = static_cast<std::size_t>(m_faces[f][static_cast<std::size_t>(k)]);
        if(!on_border[i] && sum[i] > 0.)
          m_optimal[3 * f + static_cast<std::size_t>(k)] *= 2. * CGAL_PI / sum[i];
      }
    m_vertices = double(n);
  }

  // the angle distortion of the layout `uv` (one UV per patch vertex). The layout must have no
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
      {
        const double phi = m_optimal[3 * f + k];
        if(phi > 0.)
          total += ((alpha[k] - phi) / phi) * ((alpha[k] - phi) / phi);
      }
    }
    return (m_vertices > 0.) ? total / m_vertices : 0.;
  }

private:
  std::vector<std::array<int, 3> > m_faces;
  std::vector<double> m_optimal;
  double m_vertices = 0.;
};

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_BORDER_SEARCH_H
