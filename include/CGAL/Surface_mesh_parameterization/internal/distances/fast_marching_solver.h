// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DISTANCES_FAST_MARCHING_SOLVER_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DISTANCES_FAST_MARCHING_SOLVER_H

// The geodesic solver interface on a checked disk (one class per method, the
// source-independent work done once in the constructor and shared on the patch), with the
// fast marching solver. The other methods are in geodesic_solvers.h.

#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/geodesic_method_tags.h>
#include <CGAL/Surface_mesh_parameterization/internal/distances/fast_marching.h>

#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// Every value finite and >= 0 (sources at 0); the solvers' results are checked with it.
inline Error_code check_distances(std::vector<double>& d)
{
  for(double& x : d)
  {
    if(!std::isfinite(x))
      return ERROR_DISTANCE_COMPUTATION_FAILED;
    if(x < 0.)
      x = 0.;  // rounding in the heat method's normalisation
  }
  return OK;
}

template <class Method>
class Geodesic_solver;

// ---------------------------------------------------------------- fast marching

template <>
class Geodesic_solver<Fast_marching_geodesics>
{
public:
  template <class Patch>
  explicit Geodesic_solver(const Patch& patch)
    : m_fm(patch.points(), patch.faces_indices())
  { }

  Error_code compute(const std::vector<int>& sources, std::vector<double>& distances) const
  {
    m_fm.compute(sources, distances);
    return check_distances(distances);
  }

private:
  Fast_marching m_fm;
};

// The solver of `Method` shared by everything that works on `patch`.
template <class Method, class Disk>
Geodesic_solver<Method>& shared_geodesic_solver(Disk& patch)
{
  return patch.template shared_object<Geodesic_solver<Method> >();
}

// Distances from `sources` (local indices), one per patch vertex.
template <class Method, class Disk>
Error_code geodesic_distances(Disk& patch, const std::vector<int>& sources, std::vector<double>& distances)
{
  if(sources.empty())
    return ERROR_WRONG_PARAMETER;
  for(int s : sources)
    if(s < 0 || static_cast<std::size_t>(s) >= patch.number_of_vertices())
      return ERROR_WRONG_PARAMETER;
  return shared_geodesic_solver<Method>(patch).compute(sources, distances);
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DISTANCES_FAST_MARCHING_SOLVER_H
