// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_AUTOMATIC_BORDER_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_AUTOMATIC_BORDER_H

/// \file Automatic_border.h

#include <CGAL/Surface_mesh_parameterization/Conformal_border.h>
#include <CGAL/Surface_mesh_parameterization/Distortion_bound.h>
#include <CGAL/Surface_mesh_parameterization/Measured_border.h>
#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_report.h>
#include <CGAL/Surface_mesh_parameterization/internal/borders/border_reports.h>
#include <CGAL/Surface_mesh_parameterization/internal/borders/border_search.h>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgSurfaceMeshParameterizationMeasured
///
/// The border policy that picks the best border of a family by the distortion of the discrete
/// conformal map it gives, angle and area together (`Distortion_bound`). The members of the
/// family (`Border_family`) are the circle (`Circular_border`), the measured border
/// (`Measured_border` with the given policies), the conformal border (`Conformal_border`)
/// and the conformal-length border (`Conformal_length_border`); each member is a path of
/// borders from the member itself to a convex border (its *blends*). Every candidate costs two
/// back-substitutions with the one factorization of \f$ L_{II} \f$, a validity check and an
/// evaluation of the angle distortion and the area spread. The search, deterministic:
/// 1. the circle and the conformal border (at its smallest simple blend toward the circle:
///    0 unless the conformal polygon self-intersects), in one batch;
/// 2. when the conformal polygon self-intersects or its layout is not one-to-one: the
///    conformal-length member at its own smallest simple blend (one more factorization, of
///    the whole cotangent Laplacian). Its angle distortion is much lower than the conformal
///    blend's, its area spread can be much higher (limbs crushed): the rank decides;
/// 3. only when the conformal layout is not one-to-one: the measured member (the policies'
///    center and distances; the spring Laplacian of the Poisson distance map is factorized
///    only when the `BorderDistance` policy asks for it). On the 23 real disks of the
///    benchmark (`benchmark/README.md`) the measured member never had less angle distortion
///    than a valid conformal layout, and building it costs a center search and a distance
///    map;
/// 4. for each member whose own layout is not one-to-one but ranks (as if it were valid)
///    before the best valid one so far, the smallest valid blend toward its convex border, by
///    five bisection steps (all such members in one batch per step); along a member the
///    distortion grows as the border moves toward the convex one, so the smallest valid
///    blend is the member's best;
/// 5. when the valid layout of lowest rank meets the bound: its holomorphic extension
///    (Boundary First Flattening's extension of a border curve), the first coordinate kept
///    and the second replaced by its harmonic conjugate (\f$ L y = h \f$ on the whole
///    cotangent Laplacian, \f$ h_k = (x_{k+1} - x_{k-1}) / 2 \f$ on the border: the discrete
///    Cauchy-Riemann equations), so that the border moves to where the map is conformal. Where
///    the border is not exactly conformal (its lengths closed by the least change, or
///    blended) it is more conformal than the layout it extends: on a locally refined
///    developable disk the mean angle error drops from 0.057 to 0.014 degrees (Boundary First
///    Flattening: 0.020). One more factorization (the whole cotangent Laplacian's), tried
///    only within the bound, where the layout is kept: an atlas splits the others. Kept when
///    it is one-to-one and ranks first (`Parameterization_report::holomorphic_extension`).
///    A constructor argument turns it off (the atlas does for the parts of its splits:
///    there it changed no median of the atlas benchmark and cost 5% of its time).
///
/// The valid layout of lowest rank (`Distortion_bound::rank()`) is kept: among the layouts
/// within the bound, the one of lowest angle distortion; when none is within, the one of lowest
/// sum of the angle distortion and the area spread, each over its bound. When none is valid,
/// `Conformal_parameterizer_3` repairs (`BLEND_TOWARD_CIRCLE`). The circle is convex and the
/// conformal border at blend 1 is convex, so the search always has a simple, convex end
/// point. The report lists every layout tried (`Parameterization_report::border_candidates`,
/// with each one's angle distortion and area spread).
///
/// \cgalModels `BorderPolicy`
///
/// \tparam CenterLocator a model of `MeasuredCenterLocator` for the measured member.
///         %Default: `Poisson_center_locator`.
/// \tparam BorderDistance a model of `MeasuredBorderDistance` for the measured member.
///         %Default: `Poisson_border_distance`.
template <class CenterLocator = Poisson_center_locator, class BorderDistance = Poisson_border_distance>
class Automatic_border
{
public:
  /// The policy of the measured member
  typedef Measured_border<CenterLocator, BorderDistance> Measured_member;

  /// creates the policy with the given measured member and bound (by default 0.2 on the angle
  /// distortion and 0.2 on the area spread, the atlas's defaults); `holomorphic_extension`
  /// (default `true`) enables step 5.
  explicit Automatic_border(Measured_member measured = Measured_member(), Distortion_bound bound = Distortion_bound(),
                            bool holomorphic_extension = true)
    : m_measured(measured), m_bound(bound), m_holomorphic_extension(holomorphic_extension)
  { }

  /// creates the policy with the default measured member and the given bound, step 5 enabled
  /// unless `holomorphic_extension` is `false`.
  explicit Automatic_border(Distortion_bound bound, bool holomorphic_extension = true)
    : Automatic_border(Measured_member(), bound, holomorphic_extension)
  { }

  /// the policy of the measured member.
  const Measured_member& measured_border() const { return m_measured; }
  /// the bound that ranks the layouts.
  const Distortion_bound& bound() const { return m_bound; }
  /// whether a layout within the bound is extended holomorphically (step 5).
  bool holomorphic_extension() const { return m_holomorphic_extension; }

  /// \cond SKIP_IN_MANUAL
  static constexpr bool searches = true;

  // the conformal member (a member that cannot be built is left out, unless the solver failed)
  template <class Step>
  Error_code build(Step& step) const
  {
    const Error_code status = Conformal_border().build(step);
    return status == ERROR_CANNOT_SOLVE_LINEAR_SYSTEM ? status : OK;
  }

  template <class Step, class Evaluator>
  Error_code choose(Step& step, Evaluator& evaluator) const
  {
    evaluator.rank_by(m_bound);
    return internal::automatic_search(
      evaluator, [&] { return m_measured.build(step); },
      [&] { return internal::build_conformal_length_member(step, false); }, step.report, step.repairable,
      m_holomorphic_extension);
  }
  /// \endcond

private:
  Measured_member m_measured;
  Distortion_bound m_bound;
  bool m_holomorphic_extension;
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_AUTOMATIC_BORDER_H
