// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_GEODESIC_DISTANCE_MAP_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_GEODESIC_DISTANCE_MAP_H

/// \file geodesic_distance_map.h
/// Geodesic distance from a set of source vertices, by fast marching, Dijkstra along edges,
/// the heat method or exact geodesics, behind one call.

#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/Default_sparse_cholesky_traits.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/disk.h>
#include <CGAL/Surface_mesh_parameterization/geodesic_method_tags.h>
#include <CGAL/Surface_mesh_parameterization/internal/distances/geodesic_solvers.h>
#include <CGAL/Surface_mesh_parameterization/internal/distances/source_components.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>

#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgSurfaceMeshParameterizationMeasured
///
/// computes the geodesic distance from the vertices of `sources` (the distance to the
/// nearest source) with the algorithm `Method`: `Fast_marching_geodesics` (default),
/// `Dijkstra_geodesics`, `Heat_method_geodesics<Mode>` or `Exact_geodesics`.
///
/// Each connected component that holds a source is solved; vertices of other components are
/// not written. Any topology is accepted.
///
/// \tparam Method one of the tags of `geodesic_method_tags.h`.
/// \tparam VertexRange a range of `vertex_descriptor`.
/// \tparam VertexDistanceMap a model of `WritablePropertyMap` with `vertex_descriptor` as
///         key and a floating point type as value.
/// \param tm the triangle mesh.
/// \param sources the source vertices (distance 0).
/// \param distance_map receives the distance of every vertex of a component holding a source.
/// \param np optional named parameter `vertex_point_map`.
/// \return `OK`; `ERROR_WRONG_PARAMETER` (no source), `ERROR_EMPTY_MESH`,
///         `ERROR_NON_TRIANGULAR_MESH`, `ERROR_NON_FINITE_COORDINATES`,
///         `ERROR_DEGENERATE_FACE`, or `ERROR_DISTANCE_COMPUTATION_FAILED` (a non-finite
///         distance). Nothing is written on failure.
template <class Method = Fast_marching_geodesics, class TriangleMesh, class VertexRange,
          class VertexDistanceMap, class NamedParameters = parameters::Default_named_parameters>
Error_code geodesic_distance_map(const TriangleMesh& tm,
                                 const VertexRange& sources,
                                 VertexDistanceMap distance_map,
                                 const NamedParameters& np = parameters::default_values())
{
  typedef Default_sparse_cholesky_traits Solver;
  const auto vpm = parameters::choose_parameter(parameters::get_parameter(np, internal_np::vertex_point),
                                                get_const_property_map(vertex_point, tm));
  return internal::distance_map_over_source_components<Solver>(
    tm, sources, vpm, distance_map,
    [](internal::Disk<TriangleMesh, Solver>& patch, const std::vector<int>& local_sources,
       std::vector<double>& values) {
      return internal::geodesic_distances<Method>(patch, local_sources, values);
    });
}

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_GEODESIC_DISTANCE_MAP_H
