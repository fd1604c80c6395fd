// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_POISSON_DISTANCE_MAP_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_POISSON_DISTANCE_MAP_H

/// \file poisson_distance_map.h
/// The Poisson distance maps of the paper (Eq. 1): the boundary Poisson distance map (BPDM)
/// and the Poisson distance map from a set of source vertices (PDM).

#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/Default_sparse_cholesky_traits.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/disk.h>
#include <CGAL/Surface_mesh_parameterization/internal/distances/poisson_distance.h>
#include <CGAL/Surface_mesh_parameterization/internal/distances/source_components.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <cmath>
#include <cstddef>
#include <iterator>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

namespace internal {

template <class TriangleMesh, class NamedParameters>
struct Solver_from_np
{
  typedef typename internal_np::Lookup_named_param_def<internal_np::sparse_linear_solver_t,
                                                       NamedParameters,
                                                       Default>::type Given;
  typedef Default_or_sparse_cholesky_traits<Given> type;
};

} // namespace internal

/// \ingroup PkgSurfaceMeshParameterizationMeasured
///
/// computes the boundary Poisson distance map (BPDM, paper section 3.2.2) of the connected
/// component bounded by the border loop of `bhd`: the solution of
/// \f$ \Delta f = -g \f$ on the vertices off the loop, \f$ f = 0 \f$ on the loop, with the
/// cotangent weights \f$ w_{ij} = (\cot\alpha_{ij} + \cot\beta_{ij})/2 \f$ normalised to sum 1
/// (\f$ \Delta f(v_i) = \sum_j w_{ij} (f_j - f_i) / \sum_j w_{ij} \f$) and \f$ g(v_i) \f$ the
/// mean length of the edges at \f$ v_i \f$. Other border loops (holes) are filled
/// virtually (see `Conformal_parameterizer_3::parameterize()`), so their vertices are interior. The system is solved as the symmetric
/// positive definite \f$ L_{II} f_I = (d g)_I \f$ with a sparse Cholesky factorization.
///
/// The map is 0 on the border loop and positive inside; it scales like lengths and is
/// invariant under rigid motions. Its maximum is the package's default center
/// (`Poisson_center_locator`).
///
/// \tparam TriangleMesh a model of `FaceGraph`.
/// \tparam VertexDistanceMap a model of `WritablePropertyMap` with `vertex_descriptor` as key
///         and a floating point type as value.
/// \param tm the mesh.
/// \param bhd a border halfedge; its loop is the constrained set.
/// \param distance_map receives the map at every vertex of the component of `bhd`; other
///        vertices are not written. Nothing is written on failure.
/// \param np optional named parameters: `vertex_point_map` (default
///        `get(CGAL::vertex_point, tm)`); `sparse_linear_solver`, whose *type* (a model of
///        `SparseLinearAlgebraWithFactorTraits_d`, default `Default_sparse_cholesky_traits`)
///        selects the solver (a fresh object of that type is used).
/// \return `OK`, or the first failure of `Conformal_parameterizer_3::parameterize()`, or
///         `ERROR_CANNOT_SOLVE_LINEAR_SYSTEM`.
template <class TriangleMesh, class VertexDistanceMap,
          class NamedParameters = parameters::Default_named_parameters>
Error_code boundary_poisson_distance_map(
  const TriangleMesh& tm,
  typename boost::graph_traits<TriangleMesh>::halfedge_descriptor bhd,
  VertexDistanceMap distance_map,
  const NamedParameters& np = parameters::default_values())
{
  typedef typename boost::property_traits<VertexDistanceMap>::value_type FT;
  typedef typename internal::Solver_from_np<TriangleMesh, NamedParameters>::type Solver;

  const auto vpm = parameters::choose_parameter(parameters::get_parameter(np, internal_np::vertex_point),
                                                get_const_property_map(vertex_point, tm));
  internal::Disk<TriangleMesh, Solver> patch;
  Error_code status = patch.build_disk(tm, bhd, vpm);
  if(status != OK)
    return status;
  std::vector<double> values;
  status = internal::boundary_poisson_distance(patch, values);
  if(status != OK)
    return status;
  for(std::size_t i = 0; i < patch.number_of_real_vertices(); ++i)
    put(distance_map, patch.vertex(i), FT(values[i] * patch.length_unit()));
  return OK;
}

/// \ingroup PkgSurfaceMeshParameterizationMeasured
///
/// computes the Poisson distance map (PDM, paper section 3.2.1) from the vertices of
/// `sources`: the solution of \f$ \Delta f = -g \f$ off the sources, \f$ f = 0 \f$ at the
/// sources, with the spring weights \f$ w_{ij} = |x_i - x_j|^{-r} \f$ normalised to sum 1 and
/// \f$ g(v_i) \f$ the mean length of the edges at \f$ v_i \f$. Every vertex that is not a
/// source is an unknown, border vertices included (they use the neighbours they have). The
/// restricted Laplacian is symmetric positive definite for positive weights (paper Theorem
/// A1), so the map is 0 at the sources and strictly positive elsewhere.
///
/// Each connected component that contains a source is solved; vertices of components
/// without a source are not written. Components may be closed or have any number of
/// borders and handles.
///
/// \tparam VertexRange a range of `vertex_descriptor`.
/// \param tm the mesh.
/// \param sources the constrained vertices (at least one).
/// \param distance_map receives the map (see `boundary_poisson_distance_map()`).
/// \param spring_exponent \f$ r \f$: 1 (default, Floater's reciprocal edge length), 0
///        (uniform weights), 2, or any finite value.
/// \param np as for `boundary_poisson_distance_map()`.
/// \return `OK`; `ERROR_WRONG_PARAMETER` for no source or a non-finite exponent;
///         `ERROR_NON_TRIANGULAR_MESH`, `ERROR_NON_FINITE_COORDINATES`,
///         `ERROR_DEGENERATE_FACE` for bad input; `ERROR_CANNOT_SOLVE_LINEAR_SYSTEM`.
///         Nothing is written on failure.
template <class TriangleMesh, class VertexRange, class VertexDistanceMap,
          class NamedParameters = parameters::Default_named_parameters>
Error_code poisson_distance_map(const TriangleMesh& tm,
                                const VertexRange& sources,
                                VertexDistanceMap distance_map,
                                double spring_exponent = 1.,
                                const NamedParameters& np = parameters::default_values())
{
  typedef typename internal::Solver_from_np<TriangleMesh, NamedParameters>::type Solver;

  if(!std::isfinite(spring_exponent))
    return ERROR_WRONG_PARAMETER;
  const auto vpm = parameters::choose_parameter(parameters::get_parameter(np, internal_np::vertex_point),
                                                get_const_property_map(vertex_point, tm));
  return internal::distance_map_over_source_components<Solver>(
    tm, sources, vpm, distance_map,
    [spring_exponent](internal::Disk<TriangleMesh, Solver>& patch,
                      const std::vector<int>& local_sources, std::vector<double>& values) {
      return internal::spring_poisson_distance(patch, local_sources, spring_exponent, values);
    });
}

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_POISSON_DISTANCE_MAP_H
