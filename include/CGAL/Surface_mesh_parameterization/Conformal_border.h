// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_CONFORMAL_BORDER_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_CONFORMAL_BORDER_H

/// \file Conformal_border.h

#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_report.h>
#include <CGAL/Surface_mesh_parameterization/internal/borders/border_reports.h>
#include <CGAL/Surface_mesh_parameterization/internal/borders/border_search.h>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgSurfaceMeshParameterizationMeasured
///
/// The border policy of the *conformal* border: the border that Boundary First Flattening
/// (Sawhney and Crane, ACM Transactions on Graphics 37(1), 2017) computes with boundary scale
/// factors 0, i.e. the border for which the discrete conformal map of the interior has (to
/// first order) the least angle distortion while the border edges keep their 3D lengths. It
/// needs one factorization of the interior cotangent Laplacian \f$ L_{II} \f$ (the one the
/// discrete conformal interior uses) and one back-substitution:
///
/// 1. the angle sums \f$ s_i \f$ of the 3D corner angles; angle defects
///    \f$ \Omega_i = 2\pi - s_i \f$ of the interior vertices, geodesic curvature
///    \f$ \kappa_i = \pi - s_i \f$ of the border vertices;
/// 2. \f$ L_{II} u_I = \Omega_I \f$ (with \f$ u_B = 0 \f$) and \f$ h = L_{BI} u_I \f$, where
///    \f$ L = D - W \f$ is the cotangent Laplacian;
/// 3. the target turning angles \f$ \tilde\kappa_i = \kappa_i - h_i \f$, which sum to
///    \f$ 2\pi \f$ (discrete Gauss-Bonnet);
/// 4. the polygon with these turning angles and the 3D border edge lengths \f$ l \f$,
///    closed with the smallest change of lengths,
///    \f$ l^* = l - N^{-1} T^\top (T N^{-1} T^\top)^{-1} T l \f$, with \f$ T \f$ the
///    \f$ 2 \times m \f$ matrix of edge directions and \f$ N^{-1} = \mathrm{diag}(l) \f$.
///
/// A planar disk is reproduced exactly (up to a similarity), a developable one is unrolled.
/// The polygon is not star-shaped in general and can self-intersect (long, thin or
/// spiralling borders). It is checked, and when it is not simple the turning angles are
/// blended toward those of the arc-length circle, \f$ (1 - t) \tilde\kappa + t c \f$ with
/// \f$ c_i = \pi (l_{i-1} + l_i) / \sum l \f$, the lengths kept: the smallest \f$ t \f$ with a
/// simple polygon is found by 20 bisection steps (at \f$ t = 1 \f$ every turning angle is
/// positive, so the polygon is convex). The report gives the blend
/// (`Parameterization_report::conformal_blend`) and every quantity above.
///
/// \cgalModels `BorderPolicy`
class Conformal_border
{
public:
  /// \cond SKIP_IN_MANUAL
  static constexpr Border_family member = CONFORMAL;
  static constexpr bool searches = false;

  template <class Step>
  Error_code build(Step& step) const
  {
    return internal::build_conformal_member(
      step, CONFORMAL,
      [&step](auto& disk, auto& polygon, auto& closed) { return step.members.add_conformal(disk, polygon, closed); },
      step.report.conformal_border_seconds);
  }
  /// \endcond
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_CONFORMAL_BORDER_H
