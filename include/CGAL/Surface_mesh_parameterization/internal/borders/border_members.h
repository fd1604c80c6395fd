// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_BORDERS_BORDER_MEMBERS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_BORDERS_BORDER_MEMBERS_H

// The borders a parameterization can choose from. A member of the family (the public enum
// Border_family) is a path of borders B(t), t in [0,1], from the member itself (t = 0) to a
// convex border (t = 1), with ONE blend definition per member:
//   - CIRCLE: CGAL's arc-length circle (every t);
//   - MEASURED: the polar border of a center and its distances, blended toward the circle in
//     polar coordinates (angle and normalized radius);
//   - CONFORMAL: the conformal border, blended toward the circle's turning angles with the
//     edge lengths kept (conformal_border.h);
//   - CONFORMAL_LENGTHS: the same turning angles, the lengths scaled by the conformal factors
//     exp(-t u) of the whole cotangent Laplacian (conformal_length_data()).
// Every border a member yields is a simple polygon (star-shaped, convex, or tested), so a
// layout with no flipped face and valid holes is one-to-one (core/validity.h).

#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_report.h>
#include <CGAL/Surface_mesh_parameterization/internal/borders/conformal_border.h>
#include <CGAL/Surface_mesh_parameterization/internal/borders/polar_map.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/validity.h>

#include <CGAL/number_type_config.h>

#include <Eigen/Core>

#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// Polar angles of the circular arc-length border: 2 pi s_k / L, s_k the 3D length of the
// border from b_0 to b_k.
template <class Disk>
std::vector<double> arc_length_angles(const Disk& disk)
{
  const std::vector<int>& border = disk.border();
  const std::size_t m = border.size();
  std::vector<double> s(m, 0.);
  double total = 0.;
  for(std::size_t k = 0; k < m; ++k)
  {
    s[k] = total;
    total += (disk.point(static_cast<std::size_t>(border[(k + 1) % m])) -
              disk.point(static_cast<std::size_t>(border[k]))).norm();
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

// The members built so far on one disk (the circle always).
class Border_members
{
public:
  template <class Disk>
  explicit Border_members(const Disk& disk) : m_circle(arc_length_angles(disk)) { }

  // the conformal member (one back-substitution of the disk's L_II), at its smallest simple
  // blend; `polygon` gets that border
  template <class Disk>
  Error_code add_conformal(Disk& disk, std::vector<Eigen::Vector2d>& polygon, std::vector<double>& closed)
  {
    Error_code status = conformal_border_data(disk, m_conformal);
    if(status == OK)
      status = smallest_simple_blend(m_conformal, m_simple_blend, polygon, closed);
    m_has_conformal = (status == OK);
    return status;
  }

  // the conformal-length member (the conformal member's data if not built yet, and one
  // factorization of the whole cotangent Laplacian), at its own smallest simple blend;
  // `polygon` gets that border
  template <class Disk>
  Error_code add_conformal_lengths(Disk& disk, std::vector<Eigen::Vector2d>& polygon, std::vector<double>& closed)
  {
    Error_code status = m_has_conformal ? OK : add_conformal(disk, polygon, closed);
    if(status == OK)
      status = conformal_length_data(disk, m_conformal, m_scale);
    if(status == OK)
      status = smallest_simple_length_blend(m_conformal, m_scale, m_length_blend, polygon, closed);
    m_has_conformal_lengths = (status == OK);
    return status;
  }

  // the measured member: polar angles and radii of the border vertices around a center
  void add_measured(const std::vector<double>& angles, const std::vector<double>& radii)
  {
    m_angles = angles;
    m_radii = radii;
    m_has_measured = true;
  }

  bool has(Border_family m) const
  {
    return m == CIRCLE || (m == MEASURED && m_has_measured) || (m == CONFORMAL && m_has_conformal) ||
           (m == CONFORMAL_LENGTHS && m_has_conformal_lengths);
  }

  // The blend at which a member starts: the conformal members at their smallest simple blend
  // (0 when the conformal border is simple), the circle at 1, the measured member at 0.
  double own_blend(Border_family m) const
  {
    return (m == CIRCLE)              ? 1.
           : (m == CONFORMAL)         ? m_simple_blend
           : (m == CONFORMAL_LENGTHS) ? m_length_blend
                                      : 0.;
  }

  const Conformal_border_data& conformal() const { return m_conformal; }
  // the conformal-length member's scale factors u_B (mean of u over the disk removed)
  const std::vector<double>& scale_factors() const { return m_scale; }

  // B_m(t) placed in [0,1]^2, clockwise; false when it cannot be built or is not simple.
  bool border(Border_family m, double t, std::vector<Eigen::Vector2d>& uv) const
  {
    Polar_border polar;
    switch(m)
    {
    case CIRCLE:
      if(place_polar_border(m_circle, std::vector<double>(m_circle.size(), 1.), polar) != OK)
        return false;
      uv = std::move(polar.uv);
      return true;
    case MEASURED:  // star-shaped around the center, hence simple
      if(!m_has_measured || blended_border(m_angles, m_radii, m_circle, t, polar) != OK)
        return false;
      uv = std::move(polar.uv);
      return true;
    case CONFORMAL:
      return m_has_conformal &&
             polygon_from_turning_angles(blended_turning_angles(m_conformal, t), m_conformal.lengths, uv) == OK &&
             is_simple_polygon(uv);
    case CONFORMAL_LENGTHS:
      return m_has_conformal_lengths && conformal_length_polygon(m_conformal, m_scale, t, uv) == OK &&
             is_simple_polygon(uv);
    }
    return false;
  }

private:
  std::vector<double> m_circle;
  std::vector<double> m_angles, m_radii;
  Conformal_border_data m_conformal;
  std::vector<double> m_scale;
  double m_simple_blend = 0., m_length_blend = 0.;
  bool m_has_measured = false, m_has_conformal = false, m_has_conformal_lengths = false;
};

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_BORDERS_BORDER_MEMBERS_H
