// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_CONFORMAL_BORDER_PARAMETERIZER_3_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_CONFORMAL_BORDER_PARAMETERIZER_3_H

/// \file Conformal_border_parameterizer_3.h

#include <CGAL/Surface_mesh_parameterization/Border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Conformal_border.h>

#include <CGAL/Default.h>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgSurfaceMeshParameterizationMeasured
///
/// A border parameterizer that maps the border of a disk-like mesh onto the *conformal*
/// border (Boundary First Flattening's border with boundary scale factors 0; see
/// `Conformal_border`), a drop-in replacement for CGAL's circular border parameterizers in
/// its fixed border parameterizers: `Border_parameterizer_3` with the border policy
/// `Conformal_border`. It factorizes the interior cotangent Laplacian once and
/// back-substitutes once.
///
/// \tparam TriangleMesh a model of `FaceGraph`.
/// \tparam SolverTraits a model of `SparseLinearAlgebraWithFactorTraits_d`. %Default:
///         `Default_sparse_cholesky_traits`.
template <class TriangleMesh, class SolverTraits = Default>
using Conformal_border_parameterizer_3 = Border_parameterizer_3<TriangleMesh, Conformal_border, SolverTraits>;

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_CONFORMAL_BORDER_PARAMETERIZER_3_H
