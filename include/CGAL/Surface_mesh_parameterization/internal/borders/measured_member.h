// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_BORDERS_MEASURED_MEMBER_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_BORDERS_MEASURED_MEMBER_H

// The paper's measured border, steps 1-3 (user manual: The method in a page): the center
// (a MeasuredCenterLocator), the distances from it to the border (a MeasuredBorderDistance),
// the polar border map. When the distance policy has the optional `prepare(disk)` step and the
// call is parallel, that step runs in a second thread while the center is located.

#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_report.h>
#include <CGAL/Surface_mesh_parameterization/internal/borders/polar_map.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/concurrency.h>

#include <chrono>
#include <cstddef>
#include <future>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// Whether a border distance policy has the optional `prepare(disk)` step.
template <class Policy, class Disk, class = void>
struct Has_prepare : std::false_type {};

template <class Policy, class Disk>
struct Has_prepare<Policy, Disk, std::void_t<decltype(std::declval<const Policy&>().prepare(std::declval<Disk&>()))> >
  : std::true_type {};

// What steps 1-3 computed (lengths in the disk's unit).
struct Measured_member
{
  bool located = false;        // whether a center was located (also when a later step failed)
  std::size_t center = 0;      // its local index
  std::vector<double> distances;
  Polar_border polar;
};

// Step 1, with the distance policy's preparation (in a second thread when `parallel`) and,
// when `factorize_interior`, the factorization of L_II (if the locator does not do it anyway).
template <class Disk, class CenterLocator, class BorderDistance>
Error_code locate_center(Disk& disk, const CenterLocator& locator, const BorderDistance& distance, bool parallel,
                         bool factorize_interior, Measured_member& out)
{
  Error_code prepared = OK, status = OK;
  std::future<Error_code> preparing;
  if constexpr(Has_prepare<BorderDistance, Disk>::value)
  {
    if(parallel)
      preparing = start_thread([&distance, &disk] { return distance.prepare(disk); });
    else
      prepared = distance.prepare(disk);
  }
  if(factorize_interior && disk.systems().interior() == nullptr)
    status = disk.systems().interior_status();
  if(status == OK)
    status = locator.locate_center(disk, out.center);
  out.located = (status == OK);
  if(preparing.valid())
    prepared = preparing.get();
  return status == OK ? prepared : status;
}

// Steps 1-3; the report gets the stage times and the unreachable border vertices.
template <class Disk, class CenterLocator, class BorderDistance>
Error_code build_measured_member(Disk& disk, const CenterLocator& locator, const BorderDistance& distance,
                                 bool parallel, bool factorize_interior, Measured_member& out,
                                 Parameterization_report& report)
{
  typedef std::chrono::steady_clock Clock;
  Clock::time_point t0 = Clock::now();
  Error_code status = locate_center(disk, locator, distance, parallel, factorize_interior, out);
  Clock::time_point t1 = Clock::now();
  report.center_seconds = std::chrono::duration<double>(t1 - t0).count();
  if(status == OK)
  {
    status = distance.compute_border_distances(disk, out.center, out.distances);
    disk.systems().release_spring();  // only one factor stays alive: the interior system's
    report.unreachable_border_vertices = 0;
    for(std::size_t k = 0; status == ERROR_DISTANCE_COMPUTATION_FAILED && k < out.distances.size(); ++k)
      report.unreachable_border_vertices += (out.distances[k] > 0.) ? 0 : 1;
    t0 = Clock::now();
    report.distance_seconds = std::chrono::duration<double>(t0 - t1).count();
  }
  if(status == OK)
  {
    status = polar_border_map(disk, out.center, out.distances, out.polar);
    report.border_map_seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  }
  return status;
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_BORDERS_MEASURED_MEMBER_H
