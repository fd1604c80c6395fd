// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_POISSON_CENTER_LOCATOR_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_POISSON_CENTER_LOCATOR_H

/// \file Poisson_center_locator.h

#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/internal/distances/center_selection.h>
#include <CGAL/Surface_mesh_parameterization/internal/distances/poisson_distance.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgSurfaceMeshParameterizationMeasured
///
/// The paper's center locator (section 4.1): the center is the maximum, over the interior
/// vertices (not on a hole's border), of the boundary Poisson distance map (`boundary_poisson_distance_map()`,
/// cotangent weights, the border loop constrained).
///
/// Ties: values within a relative `1e-9` of the maximum count as tied. Among several tied
/// maxima, the interior vertices are ranked by their distance to the mean position of the
/// tied maxima, and the center is the nearest vertex that is alone at its distance
/// (vertices at a shared distance are skipped; if every distance is shared, the smallest
/// disk index among the nearest). A symmetry of the mesh permutes the vertices at each
/// distance, so a vertex alone at its distance is fixed by every symmetry: on a
/// mirror-symmetric mesh the center lies on the mirror whenever a vertex there allows it.
/// The result is deterministic for a given mesh, and, since the map is invariant under
/// rigid motions and uniform scaling, so is the center.
///
/// Cost: one back-substitution with the disk's factorization of the interior cotangent
/// Laplacian, which it creates when it is the first to need it; the discrete conformal
/// interior solve of `Conformal_parameterizer_3` reuses it.
///
/// \cgalModels `MeasuredCenterLocator`
class Poisson_center_locator
{
public:
  /// stores in `center` the disk index of the maximum of the boundary Poisson distance map.
  /// \tparam Disk a model of `MeasuredDisk`.
  /// \return `OK`, `ERROR_CANNOT_SOLVE_LINEAR_SYSTEM` or `ERROR_NO_INTERIOR_VERTEX`.
  template <class Disk>
  Error_code locate_center(Disk& disk, std::size_t& center) const
  {
    std::vector<double> values;
    const Error_code status = internal::boundary_poisson_distance(disk, values);
    return internal::center_at_maximum(disk, status, values, center);
  }
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_POISSON_CENTER_LOCATOR_H
