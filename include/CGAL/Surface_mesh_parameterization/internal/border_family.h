// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_BORDER_FAMILY_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_BORDER_FAMILY_H

// The borders a parameterization can choose from, and the one search over them.
//
// A member of the family is a path of borders B(t), t in [0,1], from the member itself
// (t = 0) to a convex border (t = 1), with ONE blend definition per member:
//   - circle: CGAL's arc-length circle (every t);
//   - measured: the polar border of a center and its distances, blended toward the circle in
//     polar coordinates (angle and normalized radius, internal::blended_border());
//   - conformal: the conformal border, blended toward the circle's turning angles with the
//     edge lengths kept (internal/conformal_border.h).
// Every border the family yields is a simple polygon (star-shaped, convex, or tested), so a
// layout with no flipped face and valid holes is one-to-one (internal/repair.h).
//
// A candidate is a border and an interior: the discrete conformal map (two back-substitutions
// of the shared factorization of L_II; candidates are solved in batches, one multi-column
// solve per batch) or the mean value map (positive weights: one-to-one for a convex border,
// by Floater's theorem; the patch's mean value system, factorized on first use). The evaluator records
// every candidate and keeps the valid one of lowest angle distortion.

#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/internal/border_search.h>
#include <CGAL/Surface_mesh_parameterization/internal/conformal_border.h>
#include <CGAL/Surface_mesh_parameterization/internal/polar_map.h>
#include <CGAL/Surface_mesh_parameterization/internal/repair.h>

#include <Eigen/Core>

#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// The members, in the order of the public `Border_family` enums.
enum Border_member { CIRCLE_MEMBER = 0, MEASURED_MEMBER = 1, CONFORMAL_MEMBER = 2 };

template <class Patch>
class Border_family
{
public:
  explicit Border_family(const Patch& patch) : m_circle(arc_length_angles(patch)) { }

  // Bisection steps of the conformal member's smallest simple blend.
  static constexpr int simple_blend_steps() { return 20; }

  // the conformal member (one back-substitution of the patch's L_II)
  Error_code add_conformal(Patch& patch)
  {
    Error_code status = conformal_border_data(patch, m_conformal);
    std::vector<Eigen::Vector2d> polygon;
    std::vector<double> closed;
    if(status == OK)
      status = smallest_simple_blend(m_conformal, simple_blend_steps(), m_simple_blend, polygon, closed);
    m_has_conformal = (status == OK);
    return status;
  }

  // The blend at which a member starts: the conformal member at its smallest simple blend
  // (0 when the conformal border is simple), the circle at 1, the measured member at 0.
  double own_blend(Border_member m) const
  {
    return (m == CIRCLE_MEMBER) ? 1. : (m == CONFORMAL_MEMBER) ? m_simple_blend : 0.;
  }

  // the measured member: polar angles and radii of the border vertices around a center
  void add_measured(const std::vector<double>& angles, const std::vector<double>& radii)
  {
    m_angles = angles;
    m_radii = radii;
    m_has_measured = true;
  }

  bool has(Border_member m) const
  {
    return m == CIRCLE_MEMBER || (m == MEASURED_MEMBER && m_has_measured) ||
           (m == CONFORMAL_MEMBER && m_has_conformal);
  }

  const Conformal_border_data& conformal_data() const { return m_conformal; }

  // B_m(t) placed in [0,1]^2, clockwise; false when it cannot be built or is not simple.
  bool border(Border_member m, double t, std::vector<Eigen::Vector2d>& uv) const
  {
    Polar_border polar;
    switch(m)
    {
    case CIRCLE_MEMBER:
      if(place_polar_border(m_circle, std::vector<double>(m_circle.size(), 1.), polar) != OK)
        return false;
      uv = std::move(polar.uv);
      return true;
    case MEASURED_MEMBER:  // star-shaped around the center, hence simple
      if(!m_has_measured || blended_border(m_angles, m_radii, m_circle, t, polar) != OK)
        return false;
      uv = std::move(polar.uv);
      return true;
    case CONFORMAL_MEMBER:
      return m_has_conformal &&
             polygon_from_turning_angles(blended_turning_angles(m_conformal, t), m_conformal.lengths, uv) == OK &&
             is_simple_polygon(uv);
    }
    return false;
  }

private:
  std::vector<double> m_circle;
  std::vector<double> m_angles, m_radii;
  Conformal_border_data m_conformal;
  double m_simple_blend = 0.;
  bool m_has_measured = false, m_has_conformal = false;
};

// One candidate tried.
struct Border_trial
{
  Border_member member;
  double blend;
  bool mean_value;    // mean value interior (rather than the discrete conformal map)
  bool valid;         // one-to-one
  std::size_t flipped_faces;  // real faces not positively oriented (0 when there is no layout)
  double objective;   // angle distortion; +infinity when not valid
  double estimate;    // angle distortion of the layout even when not valid (+infinity when
                      // there is no layout: the border could not be built or solved)
};

// A layout: border UVs (patch.border() order) and interior UVs (interior_vertices() order).
struct Border_solution
{
  std::vector<Eigen::Vector2d> border_uv;
  std::vector<double> u, v;
};

template <class Patch>
class Border_evaluator
{
public:
  typedef std::pair<Border_member, double> Request;

  Border_evaluator(Patch& patch, const Border_family<Patch>& family)
    : m_patch(patch), m_family(family), m_objective(patch)
  { }

  // evaluates the requested borders with one interior; returns their trials
  std::vector<Border_trial> evaluate(const std::vector<Request>& batch, bool mean_value)
  {
    std::vector<Border_solution> solutions(batch.size());
    std::vector<bool> placed(batch.size());
    for(std::size_t i = 0; i < batch.size(); ++i)
      placed[i] = m_family.border(batch[i].first, batch[i].second, solutions[i].border_uv);
    const bool solved = solve(placed, solutions, mean_value);
    std::vector<Border_trial> result;
    std::vector<Eigen::Vector2d> uv;
    for(std::size_t i = 0; i < batch.size(); ++i)
    {
      const double inf = std::numeric_limits<double>::infinity();
      Border_trial trial{batch[i].first, batch[i].second, mean_value, false, 0, inf, inf};
      if(solved && placed[i])
      {
        assemble_uv(m_patch, solutions[i].border_uv, solutions[i].u, solutions[i].v, uv);
        trial.estimate = m_objective(uv);
        trial.flipped_faces = count_flips(m_patch, uv);
        trial.valid = trial.flipped_faces == 0 && border_curves_are_valid(m_patch, uv);
        if(trial.valid)
          trial.objective = trial.estimate;
      }
      m_trials.push_back(trial);
      result.push_back(trial);
      if(trial.valid && trial.objective < best_objective())
      {
        m_best = static_cast<int>(m_trials.size()) - 1;
        m_best_solution = std::move(solutions[i]);
      }
    }
    return result;
  }

  const std::vector<Border_trial>& trials() const { return m_trials; }
  const Border_family<Patch>& family() const { return m_family; }
  // index of the kept trial, -1 when none is valid
  int best() const { return m_best; }
  double best_objective() const
  {
    return m_best < 0 ? std::numeric_limits<double>::infinity() : m_trials[static_cast<std::size_t>(m_best)].objective;
  }
  Border_solution& best_solution() { return m_best_solution; }
  const Angle_distortion_objective& objective() const { return m_objective; }

private:
  // Every placed border's interior, with one multi-column solve of the interior system
  // (cotangent weights) or of the mean value system.
  bool solve(const std::vector<bool>& placed, std::vector<Border_solution>& solutions, bool mean_value)
  {
    typename Patch::Engine* system = mean_value ? m_patch.mean_value_system() : m_patch.interior_system();
    if(system == nullptr)
      return false;
    const Eigen::Index m = static_cast<Eigen::Index>(m_patch.border().size());
    Eigen::MatrixXd values = Eigen::MatrixXd::Zero(m, 2 * static_cast<Eigen::Index>(solutions.size()));
    for(std::size_t i = 0; i < solutions.size(); ++i)
      if(placed[i])
        for(Eigen::Index k = 0; k < m; ++k)
        {
          values(k, 2 * static_cast<Eigen::Index>(i)) = solutions[i].border_uv[static_cast<std::size_t>(k)].x();
          values(k, 2 * static_cast<Eigen::Index>(i) + 1) = solutions[i].border_uv[static_cast<std::size_t>(k)].y();
        }
    Eigen::MatrixXd rhs, x;
    system->rhs_from_fixed(values, rhs);
    if(system->solve(rhs, x) != OK)
      return false;
    for(std::size_t i = 0; i < solutions.size(); ++i)
    {
      const Eigen::Index c = 2 * static_cast<Eigen::Index>(i);
      solutions[i].u.assign(x.col(c).data(), x.col(c).data() + x.rows());
      solutions[i].v.assign(x.col(c + 1).data(), x.col(c + 1).data() + x.rows());
    }
    return true;
  }

  Patch& m_patch;
  const Border_family<Patch>& m_family;
  Angle_distortion_objective m_objective;
  std::vector<Border_trial> m_trials;
  int m_best = -1;
  Border_solution m_best_solution;
};

// The search along members whose own border (t = own_blend(), see Border_family) gave no
// valid layout: for each, the smallest valid blend t, by `steps` bisection steps on
// (own_blend, 1] (all members of one step in one batch), t = 1 tried last if no smaller t was
// valid. Along a member, the layout moves from
// the member toward a convex border, and the angle distortion grows in practice as the border
// moves away from a better member, so the smallest valid t is the member's best valid blend.
// Returns, per member, the smallest valid t found (or a negative value).
template <class Patch>
std::vector<double> search_smallest_valid_blend(Border_evaluator<Patch>& evaluator,
                                                const std::vector<Border_member>& members,
                                                bool mean_value, int steps = 5)
{
  std::vector<double> invalid(members.size(), 0.), valid(members.size(), -1.);
  for(std::size_t i = 0; i < members.size(); ++i)
    invalid[i] = evaluator.family().own_blend(members[i]);
  std::vector<typename Border_evaluator<Patch>::Request> batch;
  for(int step = 0; step < steps; ++step)
  {
    batch.clear();
    for(std::size_t i = 0; i < members.size(); ++i)
      batch.emplace_back(members[i], 0.5 * (invalid[i] + (valid[i] < 0. ? 1. : valid[i])));
    const std::vector<Border_trial> trials = evaluator.evaluate(batch, mean_value);
    for(std::size_t i = 0; i < members.size(); ++i)
      (trials[i].valid ? valid[i] : invalid[i]) = batch[i].second;
  }
  batch.clear();
  std::vector<std::size_t> last;
  for(std::size_t i = 0; i < members.size(); ++i)
    if(valid[i] < 0.)
    {
      batch.emplace_back(members[i], 1.);
      last.push_back(i);
    }
  if(!batch.empty())
  {
    const std::vector<Border_trial> trials = evaluator.evaluate(batch, mean_value);
    for(std::size_t j = 0; j < last.size(); ++j)
      if(trials[j].valid)
        valid[last[j]] = 1.;
  }
  return valid;
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_BORDER_FAMILY_H
