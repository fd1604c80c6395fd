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
works on a disk, a model of `MeasuredDisk`: the checked disk
(read only, see `MeasuredCenterLocator`), `shared_object<T>()`, and the spring system that the
paper's Poisson distance map needs (`factorize_spring_laplacian()`,
`solve_spring_poisson()`; the parameterizer frees it once the distances are measured, so that
only the interior system's factor stays alive).

Every distance must be a positive finite number. A model that cannot measure some border
vertex (for example a straightest geodesic that does not reach it) sets its distance to 0 and
returns `ERROR_DISTANCE_COMPUTATION_FAILED` instead of a wrong value; the parameterizers'
report counts such vertices (`Parameterization_report::unreachable_border_vertices`).

A model may also have the optional operation `prepare()` (see below): the
parameterizers detect it and, with `CGAL::Parallel_tag`, run it in a second thread while the
center is located.

\cgalHasModel `CGAL::Surface_mesh_parameterization::Poisson_border_distance`
\cgalHasModel `CGAL::Surface_mesh_parameterization::Geodesic_border_distance<Method>`
\cgalHasModel `CGAL::Surface_mesh_parameterization::Straightest_geodesic_border_distance`

\sa `MeasuredCenterLocator`
\sa `CGAL::Surface_mesh_parameterization::Measured_border`
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

  /// resizes `distances` to `disk.border().size()` and stores in `distances[k]` the
  /// distance from the vertex of disk index `center` to the border vertex of disk index
  /// `disk.border()[k]`.
  ///
  /// \tparam Disk an instance of disk, a model of `MeasuredDisk`.
  /// \return `OK` on success, otherwise an `Error_code` saying why.
  template <class Disk>
  Error_code compute_border_distances(Disk& disk, std::size_t center,
                                      std::vector<double>& distances) const;

  /// optional: the work that does not depend on the center (for example factorizing a
  /// matrix), run concurrently with the center search when the parameterizer's concurrency
  /// tag is `CGAL::Parallel_tag`, otherwise before it. A model without this member does all
  /// its work in `compute_border_distances()`.
  ///
  /// \tparam Disk an instance of disk, a model of `MeasuredDisk`.
  /// \return `OK` on success, otherwise an `Error_code` saying why; the parameterizer then
  ///         fails with it.
  template <class Disk>
  Error_code prepare(Disk& disk) const;

  /// @}
};
