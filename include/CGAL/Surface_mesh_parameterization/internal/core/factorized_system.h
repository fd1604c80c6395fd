// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CORE_FACTORIZED_SYSTEM_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CORE_FACTORIZED_SYSTEM_H

// A symmetric positive definite system factorized once and back-substituted many times,
// through CGAL's `SparseLinearAlgebraWithFactorTraits_d` concept (for example
// `CGAL::Eigen_solver_traits`).

#include <CGAL/Surface_mesh_parameterization/Default_sparse_cholesky_traits.h>
#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_report.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/concurrency.h>

#include <CGAL/Eigen_solver_traits.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <chrono>
#include <cmath>
#include <cstddef>
#include <future>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// Detects matrices that wrap an `Eigen::SparseMatrix<double>` (CGAL's `Eigen_sparse_matrix`),
// which can be filled without keeping a second copy of the triplets alive.
template <class Matrix, class = void>
struct Wraps_eigen_sparse_matrix : std::false_type {};

template <class Matrix>
struct Wraps_eigen_sparse_matrix<Matrix,
  std::void_t<decltype(std::declval<Matrix&>().eigen_object())> >
  : std::is_same<std::decay_t<decltype(std::declval<Matrix&>().eigen_object())>,
                 Eigen::SparseMatrix<double> > {};

// Whether the traits are (or derive from) CGAL's Eigen_solver_traits, whose linear_solver(B, X)
// uses only the factorization, not the matrix.
template <class Traits, class = void>
struct Is_eigen_solver_traits : std::false_type {};

template <class Traits>
struct Is_eigen_solver_traits<Traits, std::void_t<typename Traits::Solver> >
  : std::is_base_of<CGAL::Eigen_solver_traits<typename Traits::Solver>, Traits> {};

// Traits that solve many columns at once from their factor alone, with a member
// `bool solve(const Eigen::MatrixXd& B, Eigen::MatrixXd& X)` (Cholmod_supernodal_cholesky_traits).
template <class Traits, class = void>
struct Has_block_solve : std::false_type {};

template <class Traits>
struct Has_block_solve<Traits, std::void_t<decltype(std::declval<Traits&>().solve(
  std::declval<const Eigen::MatrixXd&>(), std::declval<Eigen::MatrixXd&>()))> > : std::true_type {};

// Eigen's SimplicialLDLT, whose factor can be read for a blocked multi-column solve.
template <class Solver>
struct Is_simplicial_ldlt : std::false_type {};

template <class MatrixType, int UpLo, class Ordering>
struct Is_simplicial_ldlt<Eigen::SimplicialLDLT<MatrixType, UpLo, Ordering> > : std::true_type {};

// Solves P^T L D L^T P X = B for all columns of B at once: every entry of L is read once for
// all columns (Eigen's own dense-RHS solve runs one column after the other, reading the
// whole factor each time). Rows of the work array are contiguous across columns.
template <class LDLT>
void ldlt_block_solve(const LDLT& solver, const Eigen::MatrixXd& B, Eigen::MatrixXd& X)
{
  typedef Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> Row_major;
  const auto& L = solver.matrixL().nestedExpression();  // unit lower triangle, column-major
  const Eigen::Index n = L.cols(), k = B.cols();
  Row_major Y(n, k);
  if(solver.permutationP().size() > 0)
    Y = solver.permutationP() * B;
  else
    Y = B;
  double* y = Y.data();
  const int* outer = L.outerIndexPtr();
  const int* inner = L.innerIndexPtr();
  const double* value = L.valuePtr();
  const int* nnz = L.innerNonZeroPtr();  // null when compressed
  for(Eigen::Index j = 0; j < n; ++j)  // L Z = Y
  {
    const double* yj = y + j * k;
    const int end = nnz ? outer[j] + nnz[j] : outer[j + 1];
    for(int p = outer[j]; p < end; ++p)
      if(inner[p] > j)
      {
        double* yi = y + static_cast<Eigen::Index>(inner[p]) * k;
        const double l = value[p];
        for(Eigen::Index c = 0; c < k; ++c)
          yi[c] -= l * yj[c];
      }
  }
  const auto& D = solver.vectorD();
  for(Eigen::Index j = 0; j < n; ++j)  // D W = Z
  {
    const double d = 1. / D[j];
    for(Eigen::Index c = 0; c < k; ++c)
      y[j * k + c] *= d;
  }
  for(Eigen::Index j = n - 1; j >= 0; --j)  // L^T V = W
  {
    double* yj = y + j * k;
    const int end = nnz ? outer[j] + nnz[j] : outer[j + 1];
    for(int p = outer[j]; p < end; ++p)
      if(inner[p] > j)
      {
        const double* yi = y + static_cast<Eigen::Index>(inner[p]) * k;
        const double l = value[p];
        for(Eigen::Index c = 0; c < k; ++c)
          yj[c] -= l * yi[c];
      }
  }
  if(solver.permutationPinv().size() > 0)
    X = solver.permutationPinv() * Y;
  else
    X = Y;
}

// A solver traits object of its own for one system: copies of CGAL's Eigen_solver_traits
// share one solver (so two systems built from copies would overwrite each other's
// factorization): a new one is default-constructed; other traits are copied.
template <class SolverTraits>
SolverTraits independent_traits(const SolverTraits& prototype)
{
  if constexpr(Is_eigen_solver_traits<SolverTraits>::value)
    return SolverTraits();
  else
    return prototype;
}

// A symmetric positive definite system factorized once. The matrix lives on the heap because
// `Eigen_solver_traits` keeps a pointer to it: moving this object keeps that pointer valid.
template <class SolverTraits>
class Factorized_system
{
  typedef std::chrono::steady_clock          Clock;

public:
  typedef SolverTraits                       Solver_traits;
  typedef typename Solver_traits::Matrix     Matrix;
  typedef typename Solver_traits::Vector     Vector;

  explicit Factorized_system(const Solver_traits& traits = Solver_traits())
    : m_traits(independent_traits(traits))
  { }

  // whether multi-column solves may use a second thread (CGAL's Parallel_tag)
  void set_parallel(bool parallel) { m_parallel = parallel; }
  int size() const { return m_n; }
  const Solver_statistics& statistics() const { return m_stats; }

  // Factorizes the compressed n x n matrix M (both triangles). Takes its storage.
  Error_code factor(Eigen::SparseMatrix<double>& M)
  {
    const int n = static_cast<int>(M.rows());
    m_matrix = std::make_unique<Matrix>(n, n);
    if constexpr(Wraps_eigen_sparse_matrix<Matrix>::value)
      m_matrix->eigen_object().swap(M);
    else
    {
      for(int j = 0; j < M.outerSize(); ++j)
        for(Eigen::SparseMatrix<double>::InnerIterator it(M, j); it; ++it)
          m_matrix->add_coef(static_cast<std::size_t>(it.row()), static_cast<std::size_t>(it.col()), it.value());
    }
    Eigen::SparseMatrix<double>().swap(M);
    return factor_matrix(n);
  }

  // Solves A x = b with the factorization. Fails when the result is not finite.
  Error_code solve(const std::vector<double>& b, std::vector<double>& x)
  {
    if(!m_factorized || static_cast<int>(b.size()) != m_n)
      return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
    Vector B(m_n), X(m_n);
    for(int i = 0; i < m_n; ++i)
      B[i] = b[static_cast<std::size_t>(i)];
    const Clock::time_point start = Clock::now();
    const bool ok = m_traits.linear_solver(B, X);
    count_solves(start, 1);
    if(!ok)
      return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
    x.resize(static_cast<std::size_t>(m_n));
    for(int i = 0; i < m_n; ++i)
    {
      x[static_cast<std::size_t>(i)] = X[i];
      if(!std::isfinite(X[i]))
        return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
    }
    return OK;
  }

  // Solves A X = B for every column of B (n x k): with CGAL's Eigen_solver_traits in one
  // pass over the factor, with traits that have a block solve through it, otherwise column by
  // column. Counts k back-substitutions.
  Error_code solve(const Eigen::MatrixXd& B, Eigen::MatrixXd& X)
  {
    if(!m_factorized || B.rows() != m_n)
      return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
    const Clock::time_point start = Clock::now();
    bool ok = true;
    if constexpr(Is_eigen_solver_traits<Solver_traits>::value)
      ok = eigen_block_solve(B, X);
    else if constexpr(Has_block_solve<Solver_traits>::value)
      ok = m_traits.solve(B, X);
    else
      ok = column_by_column(B, X);
    count_solves(start, static_cast<int>(B.cols()));
    return (ok && X.allFinite()) ? OK : ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
  }

private:
  Error_code factor_matrix(int n)
  {
    m_factorized = false;
    m_n = n;
    const Clock::time_point start = Clock::now();
    double D = 1.;
    const bool ok = m_traits.factor(*m_matrix, D);
    m_stats.factorization_seconds += std::chrono::duration<double>(Clock::now() - start).count();
    ++m_stats.factorizations;
    // CGAL's Eigen_solver_traits and traits with a block solve work from the factor alone: the
    // matrix can go
    if constexpr(Is_eigen_solver_traits<Solver_traits>::value || Has_block_solve<Solver_traits>::value)
      m_matrix.reset();
    if(!ok || D != 1.)
      return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
    m_factorized = true;
    return OK;
  }

  void count_solves(Clock::time_point start, int columns)
  {
    m_stats.back_substitution_seconds += std::chrono::duration<double>(Clock::now() - start).count();
    m_stats.back_substitutions += columns;
  }

  // Eigen's solvers: SimplicialLDLT by the blocked solve (with Parallel_tag and many columns
  // on a large system: two threads, each with half of the columns; the factor is only read).
  bool eigen_block_solve(const Eigen::MatrixXd& B, Eigen::MatrixXd& X)
  {
    if constexpr(Is_simplicial_ldlt<typename Solver_traits::Solver>::value)
    {
      const Eigen::Index k = B.cols();
      if(m_parallel && k >= 4 && m_n >= 10000)
      {
        const Eigen::Index half = k / 2;
        Eigen::MatrixXd X1, X2;
        const Eigen::MatrixXd B1 = B.leftCols(half), B2 = B.rightCols(k - half);
        std::future<void> other = start_thread([&] { ldlt_block_solve(m_traits.solver(), B2, X2); });
        ldlt_block_solve(m_traits.solver(), B1, X1);
        other.get();
        X.resize(B.rows(), k);
        X.leftCols(half) = X1;
        X.rightCols(k - half) = X2;
      }
      else
        ldlt_block_solve(m_traits.solver(), B, X);
    }
    else
      X = m_traits.solver().solve(B);
    return m_traits.solver().info() == Eigen::Success;
  }

  bool column_by_column(const Eigen::MatrixXd& B, Eigen::MatrixXd& X)
  {
    X.resize(B.rows(), B.cols());
    Vector b(m_n), x(m_n);
    for(Eigen::Index j = 0; j < B.cols(); ++j)
    {
      for(int i = 0; i < m_n; ++i)
        b[i] = B(i, j);
      if(!m_traits.linear_solver(b, x))
        return false;
      for(int i = 0; i < m_n; ++i)
        X(i, j) = x[i];
    }
    return true;
  }

  Solver_traits m_traits;
  std::unique_ptr<Matrix> m_matrix;
  int m_n = 0;
  bool m_factorized = false;
  bool m_parallel = false;
  Solver_statistics m_stats;
};

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CORE_FACTORIZED_SYSTEM_H
