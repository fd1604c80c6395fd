// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_MEASURED_BORDER_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_MEASURED_BORDER_H

/// \file Measured_border.h

#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_report.h>
#include <CGAL/Surface_mesh_parameterization/Poisson_border_distance.h>
#include <CGAL/Surface_mesh_parameterization/Poisson_center_locator.h>
#include <CGAL/Surface_mesh_parameterization/internal/borders/border_reports.h>
#include <CGAL/Surface_mesh_parameterization/internal/borders/border_search.h>
#include <CGAL/Surface_mesh_parameterization/internal/borders/measured_member.h>

#include <CGAL/Default.h>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgSurfaceMeshParameterizationMeasured
///
/// The border policy of the paper "Measured boundary parameterization based on Poisson's
/// equation":
///
/// 1. a center vertex is found by the `CenterLocator` policy (default: the maximum of the
///    boundary Poisson distance map);
/// 2. the distance \f$ r_k \f$ from the center to every border vertex \f$ b_k \f$ is measured
///    by the `BorderDistance` policy (default: the Poisson distance map from the center);
/// 3. the border is laid out as a polar map around the center: the angle of \f$ b_k \f$ is
///    \f$ -2\pi (\theta_0 + \dots + \theta_{k-1}) / (\theta_0 + \dots + \theta_{m-1}) \f$,
///    where \f$ \theta_l \f$ is the 3D angle at the center between \f$ b_l \f$ and
///    \f$ b_{l+1} \f$, and its radius is \f$ r_k \f$.
///
/// The measured polygon is star-shaped around the center, hence simple, but in general not
/// convex. The report gives the center, the distances, the polar angles and the placement.
///
/// \cgalModels `BorderPolicy`
///
/// \tparam CenterLocator a model of `MeasuredCenterLocator`. %Default: `Poisson_center_locator`.
/// \tparam BorderDistance a model of `MeasuredBorderDistance`. %Default: `Poisson_border_distance`.
template <class CenterLocator = Poisson_center_locator, class BorderDistance = Poisson_border_distance>
class Measured_border
{
public:
  /// Center locator type
  typedef typename Default::Get<CenterLocator, Poisson_center_locator>::type   Center_locator;
  /// Border distance type
  typedef typename Default::Get<BorderDistance, Poisson_border_distance>::type Border_distance;

  /// creates the policy with the given center locator and border distance.
  explicit Measured_border(Center_locator center_locator = Center_locator(),
                           Border_distance border_distance = Border_distance())
    : m_center_locator(center_locator), m_border_distance(border_distance)
  { }

  /// the center locator.
  const Center_locator& center_locator() const { return m_center_locator; }
  /// the border distance policy.
  const Border_distance& border_distance() const { return m_border_distance; }

  /// \cond SKIP_IN_MANUAL
  static constexpr Border_family member = MEASURED;
  static constexpr bool searches = false;

  template <class Step>
  Error_code build(Step& step) const
  {
    internal::Measured_member measured;
    const Error_code status = internal::build_measured_member(step.disk, m_center_locator, m_border_distance,
                                                              step.parallel, step.factorize_interior, measured,
                                                              step.report);
    internal::report_measured(step.disk, measured, step.report);
    if(status == OK)
      step.members.add_measured(measured.polar.angles, measured.distances);
    return status;
  }
  /// \endcond

private:
  Center_locator m_center_locator;
  Border_distance m_border_distance;
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_MEASURED_BORDER_H
