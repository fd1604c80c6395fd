// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_DISTORTION_BOUND_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_DISTORTION_BOUND_H

/// \file Distortion_bound.h

#include <limits>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgSurfaceMeshParameterizationMeasured
///
/// A bound on the distortion of a map: on the paper's angle distortion and on the area spread
/// (the area-weighted mean of \f$ |\log(A^{uv}_T / A_T)| \f$ after the UV areas are scaled
/// to the 3D total: `Parameterization_quality::area_distortion_mean`). A layout *meets* the
/// bound when both figures are at most their bound. `Automatic_border` ranks its one-to-one
/// layouts by it (`rank()`), and the atlas's charts meet it (`Atlas_options`, whose defaults
/// are the same). A bound may be `+infinity` (no bound on that figure).
struct Distortion_bound
{
  /// the bound on the angle distortion
  double max_angle_distortion = 0.2;
  /// the bound on the area spread
  double max_area_spread = 0.2;

  /// whether a layout of angle distortion `angle` and area spread `area` meets the bound.
  bool met_by(double angle, double area) const { return angle <= max_angle_distortion && area <= max_area_spread; }

  /// The rank of a layout, lower is better. Within the bound, \f$ a / (1 + a) < 1 \f$ for the
  /// angle distortion \f$ a \f$: by angle alone (conformal where it can be). Otherwise
  /// \f$ 1 + (a / A) (s / S) \f$ for the area spread \f$ s \f$ and the bounds \f$ A, S \f$:
  /// angle and area together, by a relative trade (halving one figure is worth doubling the
  /// other), so that a layout does not win by a small gain on one figure for a large loss on
  /// the other. Every layout within the bound ranks before every other. A figure whose bound is
  /// infinite does not count (its factor is 1); a zero bound exceeded gives `+infinity`.
  double rank(double angle, double area) const
  {
    if(met_by(angle, area))
      return angle / (1. + angle);
    const double product = ratio(angle, max_angle_distortion) * ratio(area, max_area_spread);
    return product == product ? 1. + product : std::numeric_limits<double>::infinity();  // 0 times infinity
  }

private:
  static double ratio(double value, double bound)
  {
    if(!(bound < std::numeric_limits<double>::infinity()))
      return 1.;
    if(bound > 0.)
      return value / bound;
    return value > 0. ? std::numeric_limits<double>::infinity() : 0.;
  }
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_DISTORTION_BOUND_H
