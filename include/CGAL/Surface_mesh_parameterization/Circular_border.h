// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_CIRCULAR_BORDER_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_CIRCULAR_BORDER_H

/// \file Circular_border.h

#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_report.h>
#include <CGAL/Surface_mesh_parameterization/internal/borders/border_search.h>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgSurfaceMeshParameterizationMeasured
///
/// The border policy of CGAL's circle: the border loop on the circle of diameter 1 centered
/// in \f$ [0,1]^2 \f$, with angles proportional to the 3D arc length (the border of
/// `Circular_border_arc_length_parameterizer_3`). Convex, so the discrete conformal interior
/// of `Conformal_parameterizer_3` needs no repair unless cotangent weights fold it; no center
/// and no distances: the interior Laplacian is the only matrix factorized.
///
/// \cgalModels `BorderPolicy`
class Circular_border
{
public:
  /// \cond SKIP_IN_MANUAL
  static constexpr Border_family member = CIRCLE;  // the circle is always a member: nothing to build
  static constexpr bool searches = false;
  template <class Step> Error_code build(Step&) const { return OK; }
  /// \endcond
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_CIRCULAR_BORDER_H
