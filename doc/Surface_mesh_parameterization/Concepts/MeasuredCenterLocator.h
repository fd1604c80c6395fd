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

A center locator chooses the vertex around which the measured border is laid out as a polar
map (step 1 of the method). It works on a disk, a model of `MeasuredDisk`,
the checked and indexed view of the disk being parameterized. What a locator may use of it:
- the checked disk, read only: `number_of_vertices()`, `point(i)`, `faces_indices()`,
  `border()`, `interior_vertices()`, `interior_index(i)`, `is_virtual(i)`, `vertex(i)`,
  `index(v)`, `cotangent_row_sums()`, `mean_spoke_lengths()`;
- the interior system, the cotangent Laplacian `L_II` with the border eliminated, factorized
  once for every step (`solve_interior()` for one or many right-hand sides). A locator that
  needs that matrix must use it through the disk, so that the factorization is done once;
- `shared_object<T>()`, to share center-independent work with the border distance (for
  example a geodesic solver's precomputation).

The center must be an interior vertex of the disk (not on its border loop). The choice
must be deterministic: the same mesh gives the same center.

\cgalHasModel `CGAL::Surface_mesh_parameterization::Poisson_center_locator`
\cgalHasModel `CGAL::Surface_mesh_parameterization::Geodesic_center_locator<Method>`
\cgalHasModel `CGAL::Surface_mesh_parameterization::Fixed_center<TriangleMesh>`

\sa `MeasuredBorderDistance`
\sa `CGAL::Surface_mesh_parameterization::Measured_border`
*/
class MeasuredCenterLocator
{
public:
  /// \name Creation
  /// @{

  /// Copy constructor (parameterizers store their policies by value).
  MeasuredCenterLocator(const MeasuredCenterLocator&);

  /// @}

  /// \name Operations
  /// @{

  /// stores in `center` the disk index (`0 <= center < disk.number_of_vertices()`) of the
  /// chosen interior vertex.
  ///
  /// \tparam Disk an instance of disk, a model of `MeasuredDisk`.
  /// \return `OK` on success, otherwise an `Error_code` saying why (for example
  ///         `ERROR_WRONG_PARAMETER` for a user vertex that is not interior,
  ///         `ERROR_CANNOT_SOLVE_LINEAR_SYSTEM`). `center` is unspecified on failure.
  template <class Disk>
  Error_code locate_center(Disk& disk, std::size_t& center) const;

  /// @}
};
