// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_CONFORMAL_LENGTH_BORDER_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_CONFORMAL_LENGTH_BORDER_H

/// \file Conformal_length_border.h

#include <CGAL/Surface_mesh_parameterization/Conformal_border.h>
#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_report.h>
#include <CGAL/Surface_mesh_parameterization/internal/borders/border_reports.h>
#include <CGAL/Surface_mesh_parameterization/internal/borders/border_search.h>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgSurfaceMeshParameterizationMeasured
///
/// The border policy of the *conformal-length* border (`CONFORMAL_LENGTHS`): the conformal
/// border (`Conformal_border`) when its polygon is simple; otherwise a blend toward the
/// circle in which the lengths are conformal too. The conformal border's blend,
/// \f$ (1 - t) \tilde\kappa + t c \f$, keeps the 3D lengths of the border edges, so that its
/// layout is not conformal; this member solves Boundary First Flattening's general boundary
/// problem (Sawhney and Crane 2017) for the circle's turning angles \f$ c \f$:
///
/// 1. on the whole cotangent Laplacian \f$ L = D - W \f$ (one vertex pinned, the right-hand
///    side sums to 0 by discrete Gauss-Bonnet, the mean of \f$ u \f$ removed),
///    \f$ L u = (\Omega_I, \kappa_B - c) \f$, with \f$ \Omega_i = 2\pi - s_i \f$ and
///    \f$ \kappa_i = \pi - s_i \f$ as for the conformal border;
/// 2. the member of blend \f$ t \f$ has the turning angles \f$ (1 - t) \tilde\kappa + t c \f$
///    and the edge lengths \f$ l_{ij} e^{-t (u_i + u_j) / 2} \f$ (the scale factors of the
///    border are linear in \f$ t \f$: one solve serves every blend), closed as the conformal
///    border is. At \f$ t = 0 \f$ it is the conformal border.
///
/// Its blend is the smallest \f$ t \f$ (20 bisection steps) at which the polygon is simple. It
/// costs one more sparse factorization than `Conformal_border`, that of \f$ L \f$ with one
/// vertex pinned, of about the cost of \f$ L_{II} \f$'s. The lengths can crush limbs (much
/// area distortion where the conformal factors span many units): the angle distortion alone
/// does not tell whether it is the better border: `Automatic_border` tries it and ranks it by
/// angle and area together (`Distortion_bound`).
/// The report gives the conformal border's quantities, the blend
/// (`Parameterization_report::conformal_blend`) and the scale factors
/// (`Parameterization_report::scale_factors`).
///
/// \cgalModels `BorderPolicy`
class Conformal_length_border
{
public:
  /// \cond SKIP_IN_MANUAL
  static constexpr Border_family member = CONFORMAL_LENGTHS;
  static constexpr bool searches = false;

  template <class Step>
  Error_code build(Step& step) const
  {
    const Error_code status = step.members.has(CONFORMAL) ? OK : Conformal_border().build(step);
    return status == OK ? internal::build_conformal_length_member(step, true) : status;
  }
  /// \endcond
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_CONFORMAL_LENGTH_BORDER_H
