// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_GEODESIC_BORDER_DISTANCE_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_GEODESIC_BORDER_DISTANCE_H

/// \file Geodesic_border_distance.h

#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/geodesic_method_tags.h>
#include <CGAL/Surface_mesh_parameterization/internal/distances/geodesic_solvers.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgSurfaceMeshParameterizationMeasured
///
/// The geodesic border distance (the paper's MBPGP, section 4.2): the geodesic distance from
/// the center, computed with `Method`, read at the border vertices. With exact geodesics a
/// flat mesh that is star-shaped from the center is reproduced exactly by the polar border
/// map and the discrete conformal interior.
///
/// Cost: one distance computation from one source. The method's source-independent work
/// (`prepare()`: adjacency, mesh copy, the heat method's factorizations) is done once per
/// disk and shared with a `Geodesic_center_locator` of the same `Method`; the
/// parameterizers run `prepare()` concurrently with the center locator.
///
/// \cgalModels `MeasuredBorderDistance`
///
/// \tparam Method `Fast_marching_geodesics` (default), `Dijkstra_geodesics`,
///         `Heat_method_geodesics<Mode>` or `Exact_geodesics`.
template <class Method = Fast_marching_geodesics>
class Geodesic_border_distance
{
public:
  /// The geodesic method.
  typedef Method Geodesic_method;

  /// the source-independent work of the method, shared on the disk.
  /// \tparam Disk a model of `MeasuredDisk`.
  template <class Disk>
  Error_code prepare(Disk& disk) const
  {
    internal::shared_geodesic_solver<Method>(disk);
    return OK;
  }

  /// stores in `distances[k]` the geodesic distance from `center` to `disk.border()[k]`
  /// (0 for a vertex not reached).
  /// \return `OK`, `ERROR_WRONG_PARAMETER` (bad center), or
  ///         `ERROR_DISTANCE_COMPUTATION_FAILED` (a distance that is not positive and finite).
  template <class Disk>
  Error_code compute_border_distances(Disk& disk, std::size_t center,
                                      std::vector<double>& distances) const
  {
    std::vector<double> values;
    const Error_code status =
      internal::geodesic_distances<Method>(disk, std::vector<int>(1, static_cast<int>(center)), values);
    if(status != OK)
      return status;
    distances.resize(disk.border().size());
    bool reached = true;
    for(std::size_t k = 0; k < distances.size(); ++k)
    {
      distances[k] = values[static_cast<std::size_t>(disk.border()[k])];
      if(!(distances[k] > 0.))
      {
        distances[k] = 0.;
        reached = false;
      }
    }
    return reached ? OK : ERROR_DISTANCE_COMPUTATION_FAILED;
  }
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_GEODESIC_BORDER_DISTANCE_H
