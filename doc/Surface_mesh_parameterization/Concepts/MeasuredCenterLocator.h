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
map (step 1 of the method). It works on a `CGAL::Surface_mesh_parameterization::Parameterization_patch_3`,
the checked and indexed view of the disk being parameterized, which gives access to the mesh,
the vertex positions, the faces, the border loop and the interior vertices, and owns the
factorization of the interior cotangent Laplacian that all steps share
(`factorize_interior_laplacian()`, `solve_interior()`). A locator that needs that matrix
must use it through the patch, so that the factorization is done once.

The center must be an interior vertex of the patch (not on its border loop). The choice
must be deterministic: the same mesh gives the same center.

\cgalHasModel `CGAL::Surface_mesh_parameterization::Poisson_center_locator<TriangleMesh>`
\cgalHasModel `CGAL::Surface_mesh_parameterization::Geodesic_center_locator<TriangleMesh, Method>`
\cgalHasModel `CGAL::Surface_mesh_parameterization::Fixed_center<TriangleMesh>`

\sa `MeasuredBorderDistance`
\sa `CGAL::Surface_mesh_parameterization::Measured_border_parameterizer_3`
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

  /// stores in `center` the patch index (`0 <= center < patch.number_of_vertices()`) of the
  /// chosen interior vertex.
  ///
  /// \tparam Patch an instance of `CGAL::Surface_mesh_parameterization::Parameterization_patch_3`.
  /// \return `OK` on success, otherwise an `Error_code` saying why (for example
  ///         `ERROR_WRONG_PARAMETER` for a user vertex that is not interior,
  ///         `ERROR_CANNOT_SOLVE_LINEAR_SYSTEM`). `center` is unspecified on failure.
  template <class Patch>
  Error_code locate_center(Patch& patch, std::size_t& center) const;

  /// @}
};
