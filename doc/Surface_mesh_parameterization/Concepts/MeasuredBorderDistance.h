// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

/*!
\ingroup PkgSurfaceMeshParameterizationConcepts
\cgalConcept

A border distance measures a distance from the center vertex to every vertex of the border
loop (step 2 of the method); these distances become the radii of the polar border map. It
works on a `CGAL::Surface_mesh_parameterization::Parameterization_patch_3`: the checked disk
(read only, see `MeasuredCenterLocator`), `shared_object<T>()`, and the spring system that the
paper's Poisson distance map needs (`factorize_spring_laplacian()`,
`solve_spring_poisson()`; the parameterizer frees it once the distances are measured, so that
only the interior system's factor stays alive).

Every distance must be a positive finite number. A model that cannot measure some border
vertex (for example a straightest geodesic that does not reach it) returns
`ERROR_DISTANCE_COMPUTATION_FAILED` instead of a wrong value.

A model may also have the optional operation `prepare()` (see below): the
parameterizers detect it and, with `CGAL::Parallel_tag`, run it in a second thread while the
center is located.

\cgalHasModel `CGAL::Surface_mesh_parameterization::Poisson_border_distance<TriangleMesh>`
\cgalHasModel `CGAL::Surface_mesh_parameterization::Geodesic_border_distance<TriangleMesh, Method>`
\cgalHasModel `CGAL::Surface_mesh_parameterization::Straightest_geodesic_border_distance<TriangleMesh>`

\sa `MeasuredCenterLocator`
\sa `CGAL::Surface_mesh_parameterization::Measured_border_parameterizer_3`
*/
class MeasuredBorderDistance
{
public:
  /// \name Creation
  /// @{

  /// Copy constructor (parameterizers store their policies by value).
  MeasuredBorderDistance(const MeasuredBorderDistance&);

  /// @}

  /// \name Operations
  /// @{

  /// resizes `distances` to `patch.border().size()` and stores in `distances[k]` the
  /// distance from the vertex of patch index `center` to the border vertex of patch index
  /// `patch.border()[k]`.
  ///
  /// \tparam Patch an instance of `CGAL::Surface_mesh_parameterization::Parameterization_patch_3`.
  /// \return `OK` on success, otherwise an `Error_code` saying why.
  template <class Patch>
  Error_code compute_border_distances(Patch& patch, std::size_t center,
                                      std::vector<double>& distances) const;

  /// optional: the work that does not depend on the center (for example factorizing a
  /// matrix), run concurrently with the center search when the parameterizer's concurrency
  /// tag is `CGAL::Parallel_tag`, otherwise before it. A model without this member does all
  /// its work in `compute_border_distances()`.
  ///
  /// \tparam Patch an instance of `CGAL::Surface_mesh_parameterization::Parameterization_patch_3`.
  /// \return `OK` on success, otherwise an `Error_code` saying why; the parameterizer then
  ///         fails with it.
  template <class Patch>
  Error_code prepare(Patch& patch) const;

  /// @}
};
