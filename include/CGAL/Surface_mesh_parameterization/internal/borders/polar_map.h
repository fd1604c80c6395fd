// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_BORDERS_POLAR_MAP_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_BORDERS_POLAR_MAP_H

// Step 3 of the method (user manual: The method in a page): the polar border map, placed as CGAL's
// circular border parameterizers place theirs.

#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/triangle_geometry.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/validity.h>

#include <CGAL/number_type_config.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

struct Polar_border
{
  std::vector<double> angles;          // phi_k in [0, 2 pi), phi_0 = 0, strictly increasing
  std::vector<Eigen::Vector2d> uv;     // positions inside [0,1]^2
  Eigen::Vector2d origin = Eigen::Vector2d(0.5, 0.5);  // UV of the polar origin (the center)
  double scale = 1.;                   // UV length per unit of distance: uv = origin + scale r (cos, sin)
  bool strictly_convex = false;
};

// Smallest polar angle increment (radians, after normalisation to a full turn) between two
// consecutive border vertices: below it the two are taken as seen in the same direction
// from the center (for example both sides of a slit that points at the center), and the
// polygon would not be star-shaped.
constexpr double min_angle_increment = 1e-12;

// CGAL's placement of a border polygon: scales uniformly and translates `p` so that its
// bounding box is centered in [0,1]^2 with its longest side spanning [0,1] (CGAL's circle:
// center (0.5,0.5), radius 0.5). `origin` and `scale` tell where the old origin went and how
// much lengths were scaled. False when the polygon has no extent or is not finite.
inline bool fit_into_unit_square(std::vector<Eigen::Vector2d>& p, Eigen::Vector2d& origin, double& scale)
{
  Eigen::Vector2d lo(std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity());
  Eigen::Vector2d hi = -lo;
  for(const Eigen::Vector2d& q : p)
  {
    lo = lo.cwiseMin(q);
    hi = hi.cwiseMax(q);
  }
  const double extent = (std::max)(hi.x() - lo.x(), hi.y() - lo.y());
  if(!(extent > 0.) || !std::isfinite(extent))
    return false;
  const Eigen::Vector2d mid = 0.5 * (lo + hi);
  scale = 1. / extent;
  origin = Eigen::Vector2d(0.5, 0.5) - mid / extent;
  for(Eigen::Vector2d& q : p)
  {
    q = Eigen::Vector2d(0.5, 0.5) + (q - mid) / extent;
    q = q.cwiseMax(Eigen::Vector2d(0., 0.)).cwiseMin(Eigen::Vector2d(1., 1.));  // rounding only
  }
  return true;
}

// Places border vertex k at radius radii[k] and polar angle -angles[k] (angles strictly
// increasing in [0, 2 pi), radii positive), then scales uniformly and translates so that the
// bounding box is centered in [0,1]^2 with its longest side spanning [0,1].
inline Error_code place_polar_border(const std::vector<double>& angles, const std::vector<double>& radii,
                                     Polar_border& out)
{
  const std::size_t m = angles.size();
  if(radii.size() != m || m < 3)
    return ERROR_WRONG_PARAMETER;
  for(double r : radii)
    if(!(r > 0.) || !std::isfinite(r))
      return ERROR_DEGENERATE_BORDER_MAP;
  for(std::size_t k = 0; k < m; ++k)
  {
    const double next = (k + 1 < m) ? angles[k + 1] : angles[0] + 2. * CGAL_PI;
    if(!(next - angles[k] > min_angle_increment))
      return ERROR_DEGENERATE_BORDER_MAP;
  }
  out.angles = angles;
  out.uv.resize(m);
  for(std::size_t k = 0; k < m; ++k)
    out.uv[k] = Eigen::Vector2d(radii[k] * std::cos(-angles[k]), radii[k] * std::sin(-angles[k]));
  if(!fit_into_unit_square(out.uv, out.origin, out.scale))
    return ERROR_DEGENERATE_BORDER_MAP;
  out.strictly_convex = is_strictly_convex_clockwise(out.uv);
  return OK;
}

// For the loop b_0..b_{m-1} (patch.border()) around the center c:
//   theta_k = angle in 3D between b_k - c and b_{k+1} - c,
//   phi_k   = 2 pi (theta_0 + ... + theta_{k-1}) / (theta_0 + ... + theta_{m-1}),
//   uv_k    = r_k (cos(-phi_k), sin(-phi_k))   (negative angles, as CGAL's circle),
// then scaled uniformly and translated so that the bounding box is centered in [0,1]^2 with
// its longest side spanning [0,1] (CGAL's circle: center (0.5,0.5), radius 0.5).
template <class Disk>
Error_code polar_border_map(const Disk& patch, std::size_t center,
                            const std::vector<double>& radii, Polar_border& out)
{
  const std::vector<int>& border = patch.border();
  const std::size_t m = border.size();
  if(m < 3)
    return ERROR_BORDER_TOO_SHORT;
  if(radii.size() != m || center >= patch.number_of_vertices())
    return ERROR_WRONG_PARAMETER;

  const Eigen::Vector3d& c = patch.point(center);
  std::vector<double> theta(m);
  double total = 0.;
  for(std::size_t k = 0; k < m; ++k)
  {
    const Eigen::Vector3d a = patch.point(static_cast<std::size_t>(border[k])) - c;
    const Eigen::Vector3d b = patch.point(static_cast<std::size_t>(border[(k + 1) % m])) - c;
    theta[k] = corner_angle(a, b);
    total += theta[k];
  }
  if(!(total > 0.) || !std::isfinite(total))
    return ERROR_DEGENERATE_BORDER_MAP;
  for(double t : theta)  // same direction (or a zero vector): not strictly monotone
    if(!(2. * CGAL_PI * t / total > min_angle_increment))
      return ERROR_DEGENERATE_BORDER_MAP;
  std::vector<double> angles(m);
  double sum = 0.;
  for(std::size_t k = 0; k < m; ++k)
  {
    angles[k] = 2. * CGAL_PI * sum / total;
    sum += theta[k];
  }
  return place_polar_border(angles, radii, out);
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_BORDERS_POLAR_MAP_H
