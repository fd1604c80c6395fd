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
#include <CGAL/Surface_mesh_parameterization/internal/straightest_geodesic.h>

#include <boost/graph/graph_traits.hpp>

#include <cstddef>
#include <memory>
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
/// and `last_failure()` says which border vertex could not be reached and how many could
/// not. A wrong distance is never returned. On flat meshes the curve is the straight segment,
/// so every border vertex visible from the center is reached with its Euclidean distance.
///
/// The record of the last call is shared by copies of the policy (so it can be read from
/// the object given to a parameterizer's constructor).
///
/// \cgalModels `MeasuredBorderDistance`
///
/// \tparam TriangleMesh a model of `FaceGraph`.
template <class TriangleMesh>
class Straightest_geodesic_border_distance
{
public:
  /// Vertex type of the mesh.
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;

  /// What the last call could not do.
  struct Failure
  {
    /// number of border vertices that could not be reached (0: the call succeeded)
    std::size_t unreachable = 0;
    /// the first of them along the border loop
    vertex_descriptor vertex = boost::graph_traits<TriangleMesh>::null_vertex();
    /// its position in the border loop (`patch.border()` order)
    std::size_t border_index = 0;
  };

  Straightest_geodesic_border_distance() : m_failure(std::make_shared<Failure>()) { }

  /// the adjacency of the patch, shared on the patch.
  template <class Patch>
  Error_code prepare(Patch& patch) const
  {
    patch.template shared_object<Tracer<Patch> >();
    return OK;
  }

  /// stores in `distances[k]` the length of the straightest geodesic from `center` to
  /// `patch.border()[k]`.
  /// \return `OK`, `ERROR_WRONG_PARAMETER` (bad center), or
  ///         `ERROR_DISTANCE_COMPUTATION_FAILED` when some border vertex is not reached
  ///         (see `last_failure()`).
  template <class Patch>
  Error_code compute_border_distances(Patch& patch, std::size_t center,
                                      std::vector<double>& distances) const
  {
    *m_failure = Failure();
    if(center >= patch.number_of_vertices())
      return ERROR_WRONG_PARAMETER;
    const internal::Straightest_geodesic_tracer& tracer = patch.template shared_object<Tracer<Patch> >().tracer;
    const std::vector<int>& border = patch.border();
    distances.assign(border.size(), 0.);
    for(std::size_t k = 0; k < border.size(); ++k)
    {
      double length = 0.;
      if(!tracer.trace(static_cast<int>(center), border[k], length) || !(length > 0.))
      {
        if(m_failure->unreachable++ == 0)
        {
          m_failure->vertex = patch.vertex(static_cast<std::size_t>(border[k]));
          m_failure->border_index = k;
        }
        continue;
      }
      distances[k] = length;
    }
    return (m_failure->unreachable == 0) ? OK : ERROR_DISTANCE_COMPUTATION_FAILED;
  }

  /// the border vertices the last call could not reach.
  const Failure& last_failure() const { return *m_failure; }

private:
  template <class Patch>
  struct Tracer
  {
    explicit Tracer(const Patch& patch) : tracer(patch.points(), patch.faces_indices()) { }
    internal::Straightest_geodesic_tracer tracer;
  };

  std::shared_ptr<Failure> m_failure;
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_STRAIGHTEST_GEODESIC_BORDER_DISTANCE_H
