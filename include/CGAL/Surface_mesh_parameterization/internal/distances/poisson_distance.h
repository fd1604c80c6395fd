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

// b_i = d_i g_i, the right-hand side of Eq. 1 at every vertex.
inline std::vector<double> poisson_right_hand_side(const std::vector<double>& d, const std::vector<double>& g)
{
  std::vector<double> b(d.size());
  for(std::size_t i = 0; i < b.size(); ++i)
    b[i] = d[i] * g[i];
  return b;
}

// Boundary Poisson distance map: cotangent weights, the main border loop constrained. Uses
// (and, on first use, creates) the patch's factorization of L_II. `values` gets one entry per
// patch vertex (0 on the border loop).
template <class Disk>
Error_code boundary_poisson_distance(Disk& disk, std::vector<double>& values)
{
  auto* system = disk.systems().interior();
  if(system == nullptr)
    return disk.systems().interior_status();
  return system->solve_scattered(poisson_right_hand_side(disk.cotangent_row_sums(), disk.mean_spoke_lengths()), values);
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
    status = engine->solve_scattered(poisson_right_hand_side(engine->row_sums(), disk.mean_spoke_lengths()), values);
  disk.systems().add_statistics(engine->statistics());
  return status;
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DISTANCES_POISSON_DISTANCE_H
