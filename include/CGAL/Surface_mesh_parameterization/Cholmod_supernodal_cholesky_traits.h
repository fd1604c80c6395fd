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

#include <CGAL/Eigen_matrix.h>
#include <CGAL/Eigen_vector.h>
#include <CGAL/Eigen_sparse_matrix.h>

#include <Eigen/Core>
#include <Eigen/Sparse>

#include <cholmod.h>

#include <algorithm>
#include <cstddef>
#include <memory>
#include <vector>

#ifdef CGAL_SMP_USE_OPENBLAS_THREADS
// OpenBLAS's documented API (declared here rather than through its cblas.h, whose name and
// contents differ between BLAS implementations). CGAL_SMP_USE_OPENBLAS_THREADS is defined by
// the target MeasuredParameterization::Cholmod when CMake found that the BLAS under CHOLMOD is
// OpenBLAS (cmake/MbpOpenblasThreads.cmake), and that target then links OpenBLAS.
extern "C" void openblas_set_num_threads(int num_threads);
extern "C" int openblas_get_num_threads(void);
#endif

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgSurfaceMeshParameterizationMeasured
///
/// CHOLMOD's supernodal Cholesky factorization (SuiteSparse) for the symmetric positive
/// definite systems of this package, a model of `SparseLinearAlgebraWithFactorTraits_d`
/// (link `MeasuredParameterization::Cholmod`).
///
/// The fill-reducing ordering is chosen, not left to CHOLMOD's default sequence of trials:
/// `AMD` (approximate minimum degree) by default, or `NESTED_DISSECTION` (METIS's nested
/// dissection, CHOLMOD's `CHOLMOD_METIS`). Measured on the package's interior Laplacians
/// (`benchmark/README.md`, section *CHOLMOD ordering*): from 179k vertices up, nested
/// dissection gives 29-38% less fill and a numeric refactorization up to 1.5 times as fast,
/// but computing it costs more than it saves in a single factorization (714k vertices: 4.4 s
/// against 2.6 s for AMD, analysis included), and every system of a call has its own
/// pattern. Pass `Cholmod_supernodal_cholesky_traits(NESTED_DISSECTION)` to a parameterizer's
/// constructor, or use the type `Cholmod_nested_dissection_cholesky_traits`. The
/// symbolic analysis (ordering and supernodal structure) is kept and reused when the same object
/// factorizes a matrix with the same pattern again (only the numeric factorization is
/// redone): with nested dissection, such refactorizations are the fastest.
///
/// The factor lives in CHOLMOD's memory; the matrix is not needed after `factor()`.
/// A copy is a new solver with the same settings: it has no factor (the parameterizers copy
/// the object they are given once per system).
///
/// CHOLMOD's supernodal factorization runs its dense blocks in the BLAS, which may be
/// multithreaded (OpenBLAS starts a thread per core by default, and its threads spin: beside
/// another busy program, they wait for each other). The traits set the BLAS's thread count
/// before each factorization: `blas_threads` (default 1; 0 leaves the BLAS alone). Measured
/// on 2 cores, the command line on a 714k-vertex disk (`benchmark/README.md`, section *BLAS
/// threads and batches*): idle, 9.1-9.6 s with one BLAS thread against 8.3-8.5 s with
/// OpenBLAS's default of one per core; beside a program that keeps both cores busy, 14 s
/// against 61 s (with a third, unrelated build running too: 29 s against 60 s). The count is set with
/// OpenBLAS's `openblas_set_num_threads()`, which is process-wide (it applies to every BLAS
/// call of the program, from any thread), and only when CMake found that the BLAS linked by
/// CHOLMOD is OpenBLAS (the target `MeasuredParameterization::Cholmod` then defines
/// `CGAL_SMP_USE_OPENBLAS_THREADS`); with another BLAS the setting has no effect and the BLAS
/// keeps its own settings (e.g. `OMP_NUM_THREADS`). The package's own threads are those of the
/// parameterizers' `ConcurrencyTag`, independent of this setting.
class Cholmod_supernodal_cholesky_traits
{
public:
  /// Number type
  typedef double                               NT;
  /// Matrix type (both triangles stored; the lower one is read)
  typedef CGAL::Eigen_sparse_matrix<double>    Matrix;
  /// Vector type
  typedef CGAL::Eigen_vector<double>           Vector;

  /// The fill-reducing orderings.
  enum Ordering
  {
    /// approximate minimum degree
    AMD,
    /// METIS's nested dissection (CHOLMOD's `CHOLMOD_METIS`)
    NESTED_DISSECTION,
    /// SuiteSparse's own nested dissection (CHOLMOD's `CHOLMOD_NESDIS`: METIS bisections,
    /// constrained minimum degree inside)
    SUITESPARSE_NESTED_DISSECTION
  };

  /// creates traits with the given ordering, whose factorizations set the BLAS to
  /// `blas_threads` threads (0: the BLAS is left alone; negative values are taken as 0). The
  /// setting applies only when the BLAS is OpenBLAS (`CGAL_SMP_USE_OPENBLAS_THREADS`).
  explicit Cholmod_supernodal_cholesky_traits(Ordering ordering = AMD, int blas_threads = 1)
    : m_state(std::make_unique<State>(ordering, blas_threads))
  { }

  /// creates traits with the settings of `other` and no factor.
  Cholmod_supernodal_cholesky_traits(const Cholmod_supernodal_cholesky_traits& other)
    : m_state(std::make_unique<State>(other.ordering(), other.blas_threads()))
  { }

  /// forgets the factor and takes the settings of `other`.
  Cholmod_supernodal_cholesky_traits& operator=(const Cholmod_supernodal_cholesky_traits& other)
  {
    if(this != &other)
      m_state = std::make_unique<State>(other.ordering(), other.blas_threads());
    return *this;
  }

  /// move construction and assignment keep the factor.
  Cholmod_supernodal_cholesky_traits(Cholmod_supernodal_cholesky_traits&&) = default;
  /// \copydoc Cholmod_supernodal_cholesky_traits(Cholmod_supernodal_cholesky_traits&&)
  Cholmod_supernodal_cholesky_traits& operator=(Cholmod_supernodal_cholesky_traits&&) = default;

  /// the ordering.
  Ordering ordering() const { return m_state->ordering; }

  /// the number of BLAS threads set before each factorization (0: the BLAS is left alone).
  int blas_threads() const { return m_state->blas_threads; }

  /// whether the BLAS's thread count is set by this class in this build (the BLAS under
  /// CHOLMOD is OpenBLAS: `CGAL_SMP_USE_OPENBLAS_THREADS`).
  static constexpr bool sets_blas_threads()
  {
#ifdef CGAL_SMP_USE_OPENBLAS_THREADS
    return true;
#else
    return false;
#endif
  }

  /// factorizes `A` (symmetric positive definite; its lower triangle is read). Sets `D` to 1.
  /// Returns `false` when `A` is not positive definite or CHOLMOD fails.
  bool factor(const Matrix& A, NT& D)
  {
    D = 1.;
    return m_state->factor(A.eigen_object());
  }

  /// solves `A X = B` with the factor.
  bool linear_solver(const Vector& B, Vector& X)
  {
    Eigen::MatrixXd b(B.size(), 1), x;
    for(Eigen::Index i = 0; i < B.size(); ++i)
      b(i, 0) = B[i];
    if(!m_state->solve(b, x))
      return false;
    X.resize(x.rows());
    for(Eigen::Index i = 0; i < x.rows(); ++i)
      X[i] = x(i, 0);
    return true;
  }

  /// solves `A X = B` for every column of `B` with one pass over the factor.
  bool solve(const Eigen::MatrixXd& B, Eigen::MatrixXd& X) { return m_state->solve(B, X); }

  /// number of nonzeros of the factor (0 before a factorization).
  std::size_t factor_nonzeros() const
  {
    const cholmod_factor* L = m_state->L;
    if(L == nullptr || !L->is_super)
      return 0;
    const int* super = static_cast<const int*>(L->super);
    const int* pi = static_cast<const int*>(L->pi);
    std::size_t nnz = 0;
    for(std::size_t s = 0; s < L->nsuper; ++s)  // a supernode: a dense trapezoid
    {
      const std::size_t columns = static_cast<std::size_t>(super[s + 1] - super[s]);
      const std::size_t rows = static_cast<std::size_t>(pi[s + 1] - pi[s]);
      nnz += columns * rows - columns * (columns - 1) / 2;
    }
    return nnz;
  }

private:
  struct State
  {
    State(Ordering o, int threads) : ordering(o), blas_threads(std::max(threads, 0))
    {
      cholmod_start(&common);
      common.nmethods = 1;
      common.method[0].ordering = (o == AMD) ? CHOLMOD_AMD : (o == NESTED_DISSECTION) ? CHOLMOD_METIS : CHOLMOD_NESDIS;
      common.postorder = 1;
      common.supernodal = CHOLMOD_SUPERNODAL;
    }
    ~State()
    {
      if(L != nullptr)
        cholmod_free_factor(&L, &common);
      cholmod_finish(&common);
    }
    State(const State&) = delete;
    State& operator=(const State&) = delete;

    // A view of an Eigen column-major compressed matrix, lower triangle used.
    static cholmod_sparse view(const Eigen::SparseMatrix<double>& A)
    {
      cholmod_sparse s;
      s.nrow = static_cast<std::size_t>(A.rows());
      s.ncol = static_cast<std::size_t>(A.cols());
      s.nzmax = static_cast<std::size_t>(A.nonZeros());
      s.p = const_cast<int*>(A.outerIndexPtr());
      s.i = const_cast<int*>(A.innerIndexPtr());
      s.nz = nullptr;
      s.x = const_cast<double*>(A.valuePtr());
      s.z = nullptr;
      s.stype = -1;
      s.itype = CHOLMOD_INT;
      s.xtype = CHOLMOD_REAL;
      s.dtype = CHOLMOD_DOUBLE;
      s.sorted = 1;
      s.packed = 1;
      return s;
    }

    bool same_pattern(const Eigen::SparseMatrix<double>& A) const
    {
      if(L == nullptr || A.rows() != static_cast<Eigen::Index>(pattern_outer.size()) - 1 ||
         A.nonZeros() != static_cast<Eigen::Index>(pattern_inner.size()))
        return false;
      return std::equal(pattern_outer.begin(), pattern_outer.end(), A.outerIndexPtr()) &&
             std::equal(pattern_inner.begin(), pattern_inner.end(), A.innerIndexPtr());
    }

    bool factor(const Eigen::SparseMatrix<double>& A)
    {
      if(!A.isCompressed() || A.rows() != A.cols() || A.rows() == 0)
        return false;
      cholmod_sparse s = view(A);
      if(!same_pattern(A))
      {
        if(L != nullptr)
          cholmod_free_factor(&L, &common);
        L = cholmod_analyze(&s, &common);
        if(L == nullptr || common.status != CHOLMOD_OK)
          return false;
        pattern_outer.assign(A.outerIndexPtr(), A.outerIndexPtr() + A.rows() + 1);
        pattern_inner.assign(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros());
      }
      set_blas_threads();
      factorized = cholmod_factorize(&s, L, &common) != 0 && common.status == CHOLMOD_OK &&
                   L->minor == L->n;
      return factorized;
    }

    // The BLAS's thread count, before a factorization. Set only when it differs: OpenBLAS
    // changes its thread pool under a lock, but a call that changes nothing touches nothing.
    void set_blas_threads() const
    {
#ifdef CGAL_SMP_USE_OPENBLAS_THREADS
      if(blas_threads > 0 && openblas_get_num_threads() != blas_threads)
        openblas_set_num_threads(blas_threads);
#endif
    }

    bool solve(const Eigen::MatrixXd& B, Eigen::MatrixXd& X)
    {
      if(!factorized || B.rows() != static_cast<Eigen::Index>(L->n))
        return false;
      cholmod_dense b;
      b.nrow = static_cast<std::size_t>(B.rows());
      b.ncol = static_cast<std::size_t>(B.cols());
      b.nzmax = b.nrow * b.ncol;
      b.d = b.nrow;
      b.x = const_cast<double*>(B.data());
      b.z = nullptr;
      b.xtype = CHOLMOD_REAL;
      b.dtype = CHOLMOD_DOUBLE;
      cholmod_dense* x = cholmod_solve(CHOLMOD_A, L, &b, &common);
      if(x == nullptr)
        return false;
      X = Eigen::Map<const Eigen::MatrixXd>(static_cast<const double*>(x->x), B.rows(), B.cols());
      cholmod_free_dense(&x, &common);
      return common.status == CHOLMOD_OK;
    }

    Ordering ordering;
    int blas_threads;
    cholmod_common common;
    cholmod_factor* L = nullptr;
    bool factorized = false;
    std::vector<int> pattern_outer, pattern_inner;
  };

  std::unique_ptr<State> m_state;
};

/// \ingroup PkgSurfaceMeshParameterizationMeasured
///
/// `Cholmod_supernodal_cholesky_traits` with METIS's nested dissection as its ordering, as a
/// type, e.g. `Conformal_parameterizer_3<Mesh, Automatic_border<>,
/// Cholmod_nested_dissection_cholesky_traits>`.
///
/// The choice for large meshes short of memory: from 179k vertices up the factor has 29-38%
/// fewer nonzeros than with AMD (714k vertices: 35.3M against 54.6M; 13% at 45k), for a
/// slower first factorization (4.4 s against 2.6 s at 714k; see `benchmark/README.md`,
/// section *CHOLMOD ordering*).
class Cholmod_nested_dissection_cholesky_traits : public Cholmod_supernodal_cholesky_traits
{
public:
  /// creates traits with the ordering `NESTED_DISSECTION` and `blas_threads` BLAS threads
  /// (see `Cholmod_supernodal_cholesky_traits`).
  explicit Cholmod_nested_dissection_cholesky_traits(int blas_threads = 1)
    : Cholmod_supernodal_cholesky_traits(NESTED_DISSECTION, blas_threads)
  { }
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_CHOLMOD_SUPERNODAL_CHOLESKY_TRAITS_H
