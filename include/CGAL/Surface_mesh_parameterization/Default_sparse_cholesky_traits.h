// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_DEFAULT_SPARSE_CHOLESKY_TRAITS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_DEFAULT_SPARSE_CHOLESKY_TRAITS_H

/// \file Default_sparse_cholesky_traits.h
/// The default sparse solver of the package.

#include <CGAL/Default.h>
#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/Eigen_sparse_matrix.h>

#include <Eigen/SparseCholesky>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgSurfaceMeshParameterizationMeasured
/// The default sparse solver of this package: Eigen's simplicial LDLT Cholesky
/// factorization, through CGAL's `Eigen_solver_traits` (a model of
/// `SparseLinearAlgebraWithFactorTraits_d`).
///
/// The parameterizers of the package keep one solver per system they factorize. A solver
/// traits object given to them is copied once per system; since copies of CGAL's
/// `Eigen_solver_traits` share one solver, a new object is default-constructed for them instead.
typedef CGAL::Eigen_solver_traits<
          Eigen::SimplicialLDLT<CGAL::Eigen_sparse_matrix<double>::EigenType> >
        Default_sparse_cholesky_traits;

/// \ingroup PkgSurfaceMeshParameterizationMeasured
/// `SolverTraits`, or `Default_sparse_cholesky_traits` when it is `CGAL::Default`.
template <class SolverTraits>
using Default_or_sparse_cholesky_traits =
  typename CGAL::Default::Get<SolverTraits, Default_sparse_cholesky_traits>::type;

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_DEFAULT_SPARSE_CHOLESKY_TRAITS_H
