// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_STRAIGHTEST_GEODESIC_BORDER_DISTANCE_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_STRAIGHTEST_GEODESIC_BORDER_DISTANCE_H

/// \file Straightest_geodesic_border_distance.h

#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/internal/distances/straightest_geodesic.h>

#include <boost/graph/graph_traits.hpp>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgSurfaceMeshParameterizationMeasured
///
/// The straightest geodesic border distance of Lee et al. (2006), the paper's MBPSGP: the
/// distance from the center to a border vertex `b` is the length of the curve cut on the
/// surface by the plane through the center, `b`, and the normal at the center, traced from
/// the center towards `b`.
///
/// Such a curve may never reach `b` (it leaves through the border elsewhere, or closes on
/// itself; the paper's Fig. 2): then the call fails with `ERROR_DISTANCE_COMPUTATION_FAILED`,
/// the distance of every vertex not reached is 0, and the parameterizers' report counts them
/// (`Parameterization_report::unreachable_border_vertices`; its `border_distances` show which).
/// A wrong distance is never returned. On flat meshes the curve is the straight segment, so
/// every border vertex visible from the center is reached with its Euclidean distance.
///
/// \cgalModels `MeasuredBorderDistance`
class Straightest_geodesic_border_distance
{
public:
  /// the adjacency of the disk, shared on the disk.
  /// \tparam Disk a model of `MeasuredDisk`.
  template <class Disk>
  Error_code prepare(Disk& disk) const
  {
    disk.template shared_object<Tracer>();
    return OK;
  }

  /// stores in `distances[k]` the length of the straightest geodesic from `center` to
  /// `disk.border()[k]` (0 when it does not reach it).
  /// \return `OK`, `ERROR_WRONG_PARAMETER` (bad center), or
  ///         `ERROR_DISTANCE_COMPUTATION_FAILED` when some border vertex is not reached.
  template <class Disk>
  Error_code compute_border_distances(Disk& disk, std::size_t center, std::vector<double>& distances) const
  {
    if(center >= disk.number_of_vertices())
      return ERROR_WRONG_PARAMETER;
    const internal::Straightest_geodesic_tracer& tracer = disk.template shared_object<Tracer>().tracer;
    const std::vector<int>& border = disk.border();
    distances.assign(border.size(), 0.);
    bool reached = true;
    for(std::size_t k = 0; k < border.size(); ++k)
    {
      double length = 0.;
      if(tracer.trace(static_cast<int>(center), border[k], length) && length > 0.)
        distances[k] = length;
      else
        reached = false;
    }
    return reached ? OK : ERROR_DISTANCE_COMPUTATION_FAILED;
  }

private:
  struct Tracer
  {
    template <class Disk>
    explicit Tracer(const Disk& disk) : tracer(disk.points(), disk.faces_indices()) { }
    internal::Straightest_geodesic_tracer tracer;
  };
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_STRAIGHTEST_GEODESIC_BORDER_DISTANCE_H
