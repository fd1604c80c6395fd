// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DISTANCES_POISSON_DISTANCE_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DISTANCES_POISSON_DISTANCE_H

// Paper Eq. 1 on a checked disk (user manual: The method in a page):
//   sum_j w_ij (f_i - f_j) = d_i g_i  on the unknowns,  f = 0 on the constrained vertices,
// i.e. the normalised Laplacian equation  Delta f = -g  multiplied by d_i = sum_j w_ij.

#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/laplacian.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// Boundary Poisson distance map: cotangent weights, the main border loop constrained. Uses
// (and, on first use, creates) the patch's factorization of L_II. `values` gets one entry per
// patch vertex (0 on the border loop).
template <class Disk>
Error_code boundary_poisson_distance(Disk& patch, std::vector<double>& values)
{
  const std::vector<int>& interior = patch.interior_vertices();
  const std::vector<double>& d = patch.cotangent_row_sums();
  const std::vector<double>& g = patch.mean_spoke_lengths();
  std::vector<double> rhs(interior.size()), x;
  for(std::size_t r = 0; r < interior.size(); ++r)
  {
    const std::size_t i = static_cast<std::size_t>(interior[r]);
    rhs[r] = d[i] * g[i];
  }
  const Error_code status = patch.solve_interior(rhs, x);
  if(status != OK)
    return status;
  values.assign(patch.number_of_vertices(), 0.);
  for(std::size_t r = 0; r < interior.size(); ++r)
    values[static_cast<std::size_t>(interior[r])] = x[r];
  return OK;
}

// Poisson distance map from `sources` (local indices): spring weights |x_i - x_j|^(-r), every
// other vertex of the disk unknown. One factorization of its own (recorded in the disk's
// statistics). `values` gets one entry per disk vertex (0 at the sources).
template <class Disk>
Error_code spring_poisson_distance(Disk& disk, const std::vector<int>& sources, double exponent,
                                   std::vector<double>& values)
{
  const std::size_t n = disk.number_of_vertices();
  if(sources.empty())
    return ERROR_WRONG_PARAMETER;
  auto engine = disk.systems().make_engine();
  const Spring_weight weight{&disk.faces_indices(), &disk.points(), &disk.single_edge_masks(), exponent};
  Error_code status = engine->build(disk.pattern(), disk.faces_indices(), n, sources, weight);
  values.assign(n, 0.);
  if(status == OK && engine->number_of_free_vertices() > 0)
  {
    const std::vector<double>& d = engine->row_sums();
    const std::vector<double>& g = disk.mean_spoke_lengths();
    std::vector<double> f(n);
    for(std::size_t i = 0; i < n; ++i)
      f[i] = d[i] * g[i];
    status = engine->solve_scattered(f, values);
  }
  disk.systems().add_statistics(engine->statistics());
  return status;
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DISTANCES_POISSON_DISTANCE_H
