// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_CHOLMOD_SUPERNODAL_CHOLESKY_TRAITS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_CHOLMOD_SUPERNODAL_CHOLESKY_TRAITS_H

/// \file Cholmod_supernodal_cholesky_traits.h
/// CHOLMOD's supernodal sparse Cholesky factorization (SuiteSparse) as solver traits.
/// Including this header requires SuiteSparse's `cholmod.h`; programs must link CHOLMOD and a
/// BLAS (with CMake: the `MeasuredParameterization::Cholmod` target, defined when CHOLMOD was
/// found). A multithreaded BLAS such as OpenBLAS makes the factorization use every core.

#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/Eigen_sparse_matrix.h>

#include <Eigen/CholmodSupport>

#include <dlfcn.h>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgSurfaceMeshParameterizationMeasured
///
/// CHOLMOD's supernodal \f$ LL^T \f$ factorization through CGAL's `Eigen_solver_traits`: a
/// model of `SparseLinearAlgebraWithFactorTraits_d` for the symmetric positive definite
/// systems of this package, usually the fastest on large meshes.
///
/// The fill-reducing ordering is AMD alone. CHOLMOD's default also tries METIS when AMD's
/// fill is large and keeps the better one; on mesh Laplacians METIS saves some factorization
/// time but its ordering costs more than it saves (measured on a 700k-vertex mesh: AMD
/// 0.7 s analysis + 2.1 s factorization; the default 4.1 s + 1.4 s).
class Cholmod_supernodal_cholesky_traits
  : public CGAL::Eigen_solver_traits<
             Eigen::CholmodSupernodalLLT<CGAL::Eigen_sparse_matrix<double>::EigenType> >
{
  typedef CGAL::Eigen_solver_traits<
            Eigen::CholmodSupernodalLLT<CGAL::Eigen_sparse_matrix<double>::EigenType> > Base;

public:
  Cholmod_supernodal_cholesky_traits()
  {
    cholmod_common& common = Base::solver().cholmod();
    common.nmethods = 1;
    common.method[0].ordering = CHOLMOD_AMD;
    common.postorder = 1;
  }

  /// While an object of this type lives, OpenBLAS (when it is the BLAS in use) runs on one
  /// thread; the previous thread count is restored on destruction. The parameterizers of
  /// this package hold one while they run two factorizations concurrently: two
  /// factorizations on one BLAS thread each are much faster than two that each start a
  /// thread per core (measured on a 700k-vertex mesh and 2 cores: 4.7 s against 8.7 s; 7.7 s
  /// one after the other). With another BLAS this does nothing.
  class Concurrent_section
  {
    typedef void (*Set)(int);
    typedef int (*Get)();

  public:
    Concurrent_section()
      : m_set(reinterpret_cast<Set>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"))),
        m_get(reinterpret_cast<Get>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads")))
    {
      if(m_set != nullptr && m_get != nullptr)
      {
        m_previous = m_get();
        m_set(1);
      }
    }
    ~Concurrent_section()
    {
      if(m_set != nullptr && m_get != nullptr && m_previous > 0)
        m_set(m_previous);
    }
    Concurrent_section(const Concurrent_section&) = delete;
    Concurrent_section& operator=(const Concurrent_section&) = delete;

  private:
    Set m_set;
    Get m_get;
    int m_previous = 0;
  };
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_CHOLMOD_SUPERNODAL_CHOLESKY_TRAITS_H
