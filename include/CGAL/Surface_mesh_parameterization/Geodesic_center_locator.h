// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_GEODESIC_CENTER_LOCATOR_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_GEODESIC_CENTER_LOCATOR_H

/// \file Geodesic_center_locator.h

#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/geodesic_method_tags.h>
#include <CGAL/Surface_mesh_parameterization/internal/distances/center_selection.h>
#include <CGAL/Surface_mesh_parameterization/internal/distances/geodesic_solvers.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgSurfaceMeshParameterizationMeasured
///
/// The boundary geodesic distance map center (the paper's BGDM, section 4.1): the geodesic
/// distance from the whole border loop (all its vertices are sources) is computed with
/// `Method`, and the center is its maximum over the interior vertices (not on a hole's
/// border).
///
/// Ties, which BGDM has on symmetric shapes (two maxima on the paper's ellipse), are broken
/// as for `Poisson_center_locator`: by the distance to the mean position of the tied maxima,
/// taking the nearest vertex alone at its distance, which on a mirror-symmetric mesh lies
/// on the mirror (on the ellipse: the vertex between the two maxima).
///
/// Cost: one multi-source distance computation. The method's precomputation is shared with
/// a `Geodesic_border_distance` of the same `Method` on the same disk.
///
/// \cgalModels `MeasuredCenterLocator`
///
/// \tparam Method `Fast_marching_geodesics` (default), `Dijkstra_geodesics`,
///         `Heat_method_geodesics<Mode>` or `Exact_geodesics`.
template <class Method = Fast_marching_geodesics>
class Geodesic_center_locator
{
public:
  /// The geodesic method.
  typedef Method Geodesic_method;

  /// stores in `center` the disk index of the maximum of the boundary geodesic distance.
  /// \return `OK`, `ERROR_NO_INTERIOR_VERTEX` or `ERROR_DISTANCE_COMPUTATION_FAILED`.
  /// \tparam Disk a model of `MeasuredDisk`.
  template <class Disk>
  Error_code locate_center(Disk& disk, std::size_t& center) const
  {
    if(disk.interior_vertices().empty())
      return ERROR_NO_INTERIOR_VERTEX;
    std::vector<double> values;
    const Error_code status = internal::geodesic_distances<Method>(disk, disk.border(), values);
    return internal::center_at_maximum(disk, status, values, center);
  }
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_GEODESIC_CENTER_LOCATOR_H
