// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CORE_DISK_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CORE_DISK_H

// What one call of a parameterizer works on, the model of the `MeasuredDisk` concept that the
// center locators and border distances see: the checked disk (read only), its shared Dirichlet
// systems, and the objects its policies share. Each part has one job; this class only puts
// them together and gives the policies the few solves the concept names.

#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_report.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/checked_disk.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/disk_systems.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/object_cache.h>

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

template <class TriangleMesh, class SolverTraits>
class Disk : public Checked_disk<TriangleMesh>
{
public:
  typedef Disk_systems<SolverTraits>          Systems;
  typedef typename Systems::Engine            Engine;

  explicit Disk(const SolverTraits& traits = SolverTraits(), bool parallel = false)
    : m_systems(*this, traits, parallel)
  { }
  Disk(const Disk&) = delete;
  Disk& operator=(const Disk&) = delete;

  // the Dirichlet systems of the disk (build the disk first)
  Systems& systems() { return m_systems; }

  // L_II x = b (one entry per interior vertex, in interior_vertices() order)
  Error_code solve_interior(const std::vector<double>& b, std::vector<double>& x)
  {
    Engine* e = m_systems.interior();
    return e ? e->solve(b, x) : m_systems.interior_status();
  }

  Error_code solve_interior(const Eigen::MatrixXd& B, Eigen::MatrixXd& X)
  {
    Engine* e = m_systems.interior();
    return e ? e->solve(B, X) : m_systems.interior_status();
  }

  // L x = f on the whole cotangent Laplacian (sum f = 0), x = 0 at the first border vertex,
  // one entry per vertex: the grounded cotangent system, factorized on first use
  Error_code solve_cotangent_poisson(const std::vector<double>& f, std::vector<double>& x)
  {
    return m_systems.solve_cotangent_poisson(f, x);
  }

  Error_code factorize_spring_laplacian(double exponent) { return m_systems.factorize_spring(exponent); }

  Error_code solve_spring_poisson(std::size_t source, double exponent, std::vector<double>& values)
  {
    return m_systems.solve_spring_poisson(source, exponent, values);
  }

  // the object of type T shared by the policies of this call, built as T(*this)
  template <class T>
  T& shared_object()
  {
    return m_objects.template get<T>(*this);
  }

  Solver_statistics statistics() const { return m_systems.statistics(); }

private:
  Systems m_systems;
  Object_cache m_objects;
};

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CORE_DISK_H
