// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_POISSON_BORDER_DISTANCE_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_POISSON_BORDER_DISTANCE_H

/// \file Poisson_border_distance.h

#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>

#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgSurfaceMeshParameterizationMeasured
///
/// The paper's border distance (section 4.2, MBPPP): the Poisson distance map from the
/// center (`poisson_distance_map()`, spring weights \f$ |x_i - x_j|^{-r} \f$, only the center
/// constrained), read at the border vertices. Positive by the paper's Theorem A1.
///
/// Cost: one factorization of the spring Laplacian and one back-substitution. The
/// factorization is that of the Laplacian grounded at a fixed vertex
/// (`MeasuredDisk::factorize_spring_laplacian()`), which does not depend on the center:
/// `prepare()` computes it, and the parameterizers of this package with `CGAL::Parallel_tag`
/// run `prepare()` concurrently with the center locator. The distance from the center then
/// follows from one back-substitution (`MeasuredDisk::solve_spring_poisson()`); it equals the
/// solution of the system restricted to all vertices but the center.
///
/// \cgalModels `MeasuredBorderDistance`
class Poisson_border_distance
{
public:
  /// \param spring_exponent the exponent \f$ r \f$ of the spring weights (default 1).
  explicit Poisson_border_distance(double spring_exponent = 1.)
    : m_exponent(spring_exponent)
  { }

  /// the exponent of the spring weights.
  double spring_exponent() const { return m_exponent; }

  /// the center-independent work: factorizes the disk's grounded spring Laplacian.
  /// \tparam Disk a model of `MeasuredDisk`.
  template <class Disk>
  Error_code prepare(Disk& disk) const
  {
    return disk.factorize_spring_laplacian(m_exponent);
  }

  /// stores in `distances[k]` the Poisson distance from `center` to `disk.border()[k]`.
  /// \return `OK`, `ERROR_WRONG_PARAMETER` (non-finite exponent or bad center), or
  ///         `ERROR_CANNOT_SOLVE_LINEAR_SYSTEM`.
  template <class Disk>
  Error_code compute_border_distances(Disk& disk, std::size_t center,
                                      std::vector<double>& distances) const
  {
    if(!std::isfinite(m_exponent) || center >= disk.number_of_vertices())
      return ERROR_WRONG_PARAMETER;
    std::vector<double> values;
    const Error_code status = disk.solve_spring_poisson(center, m_exponent, values);
    if(status != OK)
      return status;
    distances.resize(disk.border().size());
    for(std::size_t k = 0; k < distances.size(); ++k)
      distances[k] = values[static_cast<std::size_t>(disk.border()[k])];
    return OK;
  }

private:
  double m_exponent;
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_POISSON_BORDER_DISTANCE_H
