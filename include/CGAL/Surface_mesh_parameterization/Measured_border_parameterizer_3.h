// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_MEASURED_BORDER_PARAMETERIZER_3_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_MEASURED_BORDER_PARAMETERIZER_3_H

/// \file Measured_border_parameterizer_3.h

#include <CGAL/Surface_mesh_parameterization/Border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Measured_border.h>

#include <CGAL/Default.h>
#include <CGAL/tags.h>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgSurfaceMeshParameterizationMeasured
///
/// The border parameterizer of the paper "Measured boundary parameterization based on
/// Poisson's equation", a drop-in replacement for CGAL's circular border parameterizers in
/// its fixed border parameterizers: `Border_parameterizer_3` with the border policy
/// `Measured_border<CenterLocator, BorderDistance>` (the center, the distances from it to the
/// border, the polar border map).
///
/// \tparam TriangleMesh a model of `FaceGraph`.
/// \tparam CenterLocator a model of `MeasuredCenterLocator`. %Default: `Poisson_center_locator`.
/// \tparam BorderDistance a model of `MeasuredBorderDistance`. %Default: `Poisson_border_distance`.
/// \tparam SolverTraits a model of `SparseLinearAlgebraWithFactorTraits_d`. %Default:
///         `Default_sparse_cholesky_traits`.
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` (default) or `CGAL::Parallel_tag`.
template <class TriangleMesh,
          class CenterLocator = Poisson_center_locator,
          class BorderDistance = Poisson_border_distance,
          class SolverTraits = Default,
          class ConcurrencyTag = CGAL::Sequential_tag>
using Measured_border_parameterizer_3 =
  Border_parameterizer_3<TriangleMesh, Measured_border<CenterLocator, BorderDistance>, SolverTraits, ConcurrencyTag>;

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_MEASURED_BORDER_PARAMETERIZER_3_H
