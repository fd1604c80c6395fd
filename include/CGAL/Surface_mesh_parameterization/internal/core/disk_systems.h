// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CORE_DISK_SYSTEMS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CORE_DISK_SYSTEMS_H

// The Dirichlet systems of a checked disk that the steps of a call share, each assembled and
// factorized once on first use (Dirichlet_engine), then solved for any number of right-hand
// sides:
// - the interior system: the cotangent Laplacian L_II with the border loop eliminated
//   (symmetric positive definite); it serves the boundary Poisson distance map, the
//   conformal border and the discrete conformal interior;
// - the grounded cotangent system: the whole cotangent Laplacian L with one vertex (the first
//   border vertex) pinned, which serves the conformal-length border member (L u = f with
//   sum f = 0); built only when that member is;
// - the spring system: the spring Laplacian grounded at one vertex, which serves the paper's
//   Poisson distance map from any single source; freed once the distances are known;
// - the mean value system (the repair): the mean value weights with the border loop
//   eliminated (not symmetric: a sparse LU).

#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_report.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/checked_disk.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/dirichlet_engine.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/laplacian.h>

#include <cmath>
#include <cstddef>
#include <memory>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

template <class SolverTraits>
class Disk_systems
{
public:
  typedef Dirichlet_engine<SolverTraits> Engine;

  Disk_systems(const Indexed_disk& disk, const SolverTraits& traits, bool parallel)
    : m_disk(disk), m_traits(traits), m_parallel(parallel)
  { }
  Disk_systems(const Disk_systems&) = delete;
  Disk_systems& operator=(const Disk_systems&) = delete;

  // the interior system, factorized on first use (nullptr when the disk has no main border
  // or no interior vertex, or the factorization failed: see interior_status())
  Engine* interior()
  {
    if(!m_interior && !m_disk.border().empty() && !m_disk.interior_vertices().empty())
      m_interior_status = build(m_interior, m_disk.border(), Cotangent_weight{&m_disk.half_cotangents()});
    return (m_interior && m_interior_status == OK) ? m_interior.get() : nullptr;
  }
  Error_code interior_status() const { return m_interior ? m_interior_status : ERROR_WRONG_PARAMETER; }

  // the grounded cotangent system, factorized on first use (nullptr when the disk has no main
  // border or the factorization failed: see grounded_cotangent_status())
  Engine* grounded_cotangent()
  {
    if(!m_grounded && !m_disk.border().empty())
      m_grounded_status = build(m_grounded, std::vector<int>(1, m_disk.border().front()),
                                Cotangent_weight{&m_disk.half_cotangents()});
    return (m_grounded && m_grounded_status == OK) ? m_grounded.get() : nullptr;
  }
  Error_code grounded_cotangent_status() const { return m_grounded ? m_grounded_status : ERROR_WRONG_PARAMETER; }

  // the x, one entry per vertex, with (L x)_i = f_i for every vertex but the ground (and for
  // the ground too when sum f = 0), x = 0 at the ground: one back-substitution of the
  // grounded cotangent system
  Error_code solve_cotangent_poisson(const std::vector<double>& f, std::vector<double>& x)
  {
    Engine* e = grounded_cotangent();
    if(!e)
      return m_grounded ? m_grounded_status : ERROR_WRONG_PARAMETER;
    if(f.size() != m_disk.number_of_vertices())
      return ERROR_WRONG_PARAMETER;
    return e->solve_with_zero_at(static_cast<std::size_t>(m_disk.border().front()), f, x);
  }

  // the spring system of exponent r, grounded at the first border vertex (vertex 0 without a
  // border), factorized unless it already is for this exponent
  Error_code factorize_spring(double exponent)
  {
    if(m_spring && m_spring_exponent == exponent)
      return m_spring_status;
    if(m_disk.number_of_vertices() < 2 || !std::isfinite(exponent))
      return ERROR_WRONG_PARAMETER;
    release_spring();
    m_spring_exponent = exponent;
    const int ground = m_disk.border().empty() ? 0 : m_disk.border().front();
    const Spring_weight weight{&m_disk.faces_indices(), &m_disk.points(), &m_disk.single_edge_masks(), exponent};
    m_spring_status = build(m_spring, std::vector<int>(1, ground), weight);
    return m_spring_status;
  }

  // the paper's Poisson distance map (Eq. 1: (L f)_i = d_i g_i, spring weights) from the
  // single vertex `source`, f_source = 0, one value per vertex: one back-substitution
  Error_code solve_spring_poisson(std::size_t source, double exponent, std::vector<double>& values)
  {
    if(source >= m_disk.number_of_vertices())
      return ERROR_WRONG_PARAMETER;
    const Error_code status = factorize_spring(exponent);
    if(status != OK)
      return status;
    const std::vector<double>& d = m_spring->row_sums();
    const std::vector<double>& g = m_disk.mean_spoke_lengths();
    std::vector<double> f(d.size());
    for(std::size_t i = 0; i < f.size(); ++i)
      f[i] = d[i] * g[i];  // the right-hand side of the paper's Eq. 1
    return m_spring->solve_with_zero_at(source, f, values);
  }

  // frees the spring system's factorization (its work stays in statistics())
  void release_spring()
  {
    if(m_spring)
      m_released.add(m_spring->statistics());
    m_spring.reset();
  }

  // the mean value system, factorized (sparse LU) on first use; nullptr when it cannot be
  Engine* mean_value()
  {
    if(!m_mean_value && !m_disk.border().empty() && !m_disk.interior_vertices().empty())
      m_mean_value_status = build(m_mean_value, m_disk.border(),
                                  Mean_value_weight{&m_disk.faces_indices(), &m_disk.points()});
    return (m_mean_value && m_mean_value_status == OK) ? m_mean_value.get() : nullptr;
  }

  // a system of the caller's own, with the same solver traits and concurrency
  std::unique_ptr<Engine> make_engine() const
  {
    std::unique_ptr<Engine> e = std::make_unique<Engine>(m_traits);
    e->set_parallel(m_parallel);
    return e;
  }

  // records the work of a system solved outside (so that statistics() tells the whole cost)
  void add_statistics(const Solver_statistics& s) { m_released.add(s); }

  Solver_statistics statistics() const
  {
    Solver_statistics s = m_released;
    for(const std::unique_ptr<Engine>* e : {&m_interior, &m_spring, &m_mean_value, &m_grounded})
      if(*e)
        s.add((*e)->statistics());
    return s;
  }

private:
  template <class Weight>
  Error_code build(std::unique_ptr<Engine>& engine, const std::vector<int>& fixed, const Weight& weight)
  {
    engine = make_engine();
    return engine->build(m_disk.pattern(), m_disk.faces_indices(), m_disk.number_of_vertices(), fixed, weight);
  }

  const Indexed_disk& m_disk;
  SolverTraits m_traits;
  bool m_parallel;
  std::unique_ptr<Engine> m_interior, m_spring, m_mean_value, m_grounded;
  Error_code m_interior_status = OK, m_spring_status = OK, m_mean_value_status = OK, m_grounded_status = OK;
  double m_spring_exponent = 0.;
  Solver_statistics m_released;
};

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CORE_DISK_SYSTEMS_H
