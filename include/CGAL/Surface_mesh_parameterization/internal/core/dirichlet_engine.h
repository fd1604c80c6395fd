// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CORE_DIRICHLET_ENGINE_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CORE_DIRICHLET_ENGINE_H

// The one Dirichlet engine of the package, in the manner of libigl's min_quad_with_fixed
// (precompute once, solve many) and of CGAL's Fixed_border_parameterizer_3 (only the weight
// varies): for a triangle set, a weight policy (internal/laplacian.h) and a set of fixed
// vertices C, it assembles the Laplacian restricted to the free vertices F, eliminating C,
// factorizes it once, and then solves
//
//     L_FF x_F = b - L_FC x_C      for any number of right-hand sides (columns) at once.
//
// Symmetric weights (cotangent, spring) give a symmetric positive definite L_FF (at least
// one fixed vertex per component), factorized with the solver traits' sparse Cholesky;
// non-symmetric weights (mean value) with a sparse LU.
//
// With a single fixed vertex (the *ground*) on a connected triangle set, the engine also
// solves the singular problem of the whole Laplacian with the value 0 at any other vertex
// (solve_with_zero_at()): one factorization serves every such vertex.

#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/laplacian.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/factorized_system.h>

#include <Eigen/Core>
#include <Eigen/Sparse>
#include <Eigen/SparseLU>

#include <chrono>
#include <cstddef>
#include <memory>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

template <class SolverTraits>
class Dirichlet_engine
{
public:
  explicit Dirichlet_engine(const SolverTraits& traits = SolverTraits()) : m_cholesky(traits) { }
  Dirichlet_engine(const Dirichlet_engine&) = delete;
  Dirichlet_engine& operator=(const Dirichlet_engine&) = delete;

  // Assembles L_FF for the weight policy with the vertices of `fixed` constrained (their
  // values are given in this order to rhs_from_fixed()), and factorizes it. The row sums
  // d_i = sum_j w_ij of every vertex are kept (row_sums()).
  template <class Weight>
  Error_code build(const Laplacian_pattern& pattern, const std::vector<Face_indices>& faces,
                   std::size_t number_of_vertices, const std::vector<int>& fixed, const Weight& weight)
  {
    clear();
    std::vector<int> position(number_of_vertices, -1);  // of a fixed vertex in `fixed`
    for(std::size_t k = 0; k < fixed.size(); ++k)
    {
      if(fixed[k] < 0 || static_cast<std::size_t>(fixed[k]) >= number_of_vertices)
        return ERROR_WRONG_PARAMETER;
      position[static_cast<std::size_t>(fixed[k])] = static_cast<int>(k);
    }
    m_row.assign(number_of_vertices, -1);
    for(std::size_t i = 0; i < number_of_vertices; ++i)
      if(position[i] < 0)
      {
        m_row[i] = static_cast<int>(m_free.size());
        m_free.push_back(static_cast<int>(i));
      }
    m_fixed = fixed.size();
    laplacian_row_sums(faces, number_of_vertices, weight, m_row_sums);
    if(m_free.empty())
      return OK;  // nothing to solve
    Eigen::SparseMatrix<double> L;
    pattern.assemble(faces, m_row, static_cast<int>(m_free.size()), weight, L,
                     [this, &position](int row, int vertex, double w) {
                       m_coupling.push_back({row, position[static_cast<std::size_t>(vertex)], w});
                     });
    if constexpr(Weight::symmetric)
      return m_cholesky.factor(L);
    else
      return factor_lu(L);
  }

  std::size_t number_of_free_vertices() const { return m_free.size(); }
  // the vertex of each row
  const std::vector<int>& free_vertices() const { return m_free; }
  // the row of vertex i, -1 for a fixed vertex
  int row(std::size_t i) const { return m_row[i]; }
  // d_i = sum_j w_ij, for every vertex
  const std::vector<double>& row_sums() const { return m_row_sums; }

  // -L_FC x_C: rhs_r = sum over the fixed neighbours j of w_rj x_j, for every column of
  // `fixed_values` (one row per fixed vertex, in the order given to build()).
  void rhs_from_fixed(const Eigen::MatrixXd& fixed_values, Eigen::MatrixXd& rhs) const
  {
    rhs.setZero(static_cast<Eigen::Index>(m_free.size()), fixed_values.cols());
    for(const Coupling& c : m_coupling)
      rhs.row(c.row) += c.weight * fixed_values.row(c.fixed);
  }

  void rhs_from_fixed(const std::vector<double>& fixed_values, std::vector<double>& rhs) const
  {
    rhs.assign(m_free.size(), 0.);
    for(const Coupling& c : m_coupling)
      rhs[static_cast<std::size_t>(c.row)] += c.weight * fixed_values[static_cast<std::size_t>(c.fixed)];
  }

  // h = L_CF x_F, one value per fixed vertex (symmetric weights: the transpose of -L_FC).
  void fixed_rows_times_free(const std::vector<double>& x, std::vector<double>& h) const
  {
    h.assign(m_fixed, 0.);
    for(const Coupling& c : m_coupling)
      h[static_cast<std::size_t>(c.fixed)] -= c.weight * x[static_cast<std::size_t>(c.row)];
  }

  // x = 0 on the fixed vertices and L_FF x_F = f_F, with f and x given per vertex.
  Error_code solve_scattered(const std::vector<double>& f, std::vector<double>& x)
  {
    std::vector<double> rhs(m_free.size()), y;
    for(std::size_t r = 0; r < m_free.size(); ++r)
      rhs[r] = f[static_cast<std::size_t>(m_free[r])];
    const Error_code status = solve(rhs, y);
    if(status != OK)
      return status;
    x.assign(m_row.size(), 0.);
    for(std::size_t r = 0; r < m_free.size(); ++r)
      x[static_cast<std::size_t>(m_free[r])] = y[r];
    return OK;
  }

  // For an engine with one fixed vertex (the ground) over a connected set: the x, one entry
  // per vertex, with (L x)_i = f_i for every vertex i != s and x_s = 0 (f_s is not read).
  // Set r = f off s and r_s = -sum_{i != s} f_i: then sum r = 0, so L y = r has the
  // solutions y + c 1, one of which the grounded system gives, and x = y - y_s 1.
  Error_code solve_with_zero_at(std::size_t s, const std::vector<double>& f, std::vector<double>& x)
  {
    if(s >= m_row.size() || m_free.size() + 1 != m_row.size())
      return ERROR_WRONG_PARAMETER;
    std::vector<double> r(f);
    r[s] = 0.;
    double sum = 0.;
    for(double v : r)
      sum += v;
    r[s] = -sum;
    const Error_code status = solve_scattered(r, x);
    if(status != OK)
      return status;
    const double shift = x[s];
    for(double& v : x)
      v -= shift;
    x[s] = 0.;
    return OK;
  }

  // L_FF x = b (one entry per row). Fails when the result is not finite.
  Error_code solve(const std::vector<double>& b, std::vector<double>& x)
  {
    if(m_lu)
    {
      Eigen::MatrixXd B = Eigen::Map<const Eigen::VectorXd>(b.data(), static_cast<Eigen::Index>(b.size())), X;
      const Error_code status = solve(B, X);
      if(status == OK)
        x.assign(X.data(), X.data() + X.rows());
      return status;
    }
    return m_cholesky.solve(b, x);
  }

  // L_FF X = B for every column of B.
  Error_code solve(const Eigen::MatrixXd& B, Eigen::MatrixXd& X)
  {
    if(!m_lu)
      return m_cholesky.solve(B, X);
    if(B.rows() != static_cast<Eigen::Index>(m_free.size()))
      return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
    const std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
    X = m_lu->solve(B);
    m_lu_statistics.back_substitution_seconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    m_lu_statistics.back_substitutions += static_cast<int>(B.cols());
    return (m_lu->info() == Eigen::Success && X.allFinite()) ? OK : ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
  }

  // Multi-column solves of the Cholesky factor may split the columns over two threads.
  void set_parallel(bool parallel) { m_cholesky.set_parallel(parallel); }

  Solver_statistics statistics() const
  {
    Solver_statistics s = m_cholesky.statistics();
    s.add(m_lu_statistics);
    return s;
  }

private:
  struct Coupling
  {
    int row;       // free row
    int fixed;     // position of the fixed vertex
    double weight; // w_{row, fixed}
  };

  void clear()
  {
    m_row.clear();
    m_free.clear();
    m_row_sums.clear();
    m_coupling.clear();
    m_fixed = 0;
    m_lu.reset();
  }

  Error_code factor_lu(Eigen::SparseMatrix<double>& L)
  {
    const std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
    m_lu = std::make_unique<Eigen::SparseLU<Eigen::SparseMatrix<double> > >();
    m_lu->compute(L);
    m_lu_statistics.factorization_seconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ++m_lu_statistics.factorizations;
    return (m_lu->info() == Eigen::Success) ? OK : ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
  }

  std::vector<int> m_row, m_free;
  std::vector<double> m_row_sums;
  std::vector<Coupling> m_coupling;
  std::size_t m_fixed = 0;
  Factorized_system<SolverTraits> m_cholesky;
  std::unique_ptr<Eigen::SparseLU<Eigen::SparseMatrix<double> > > m_lu;
  Solver_statistics m_lu_statistics;
};

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CORE_DIRICHLET_ENGINE_H
