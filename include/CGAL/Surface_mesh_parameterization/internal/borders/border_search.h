// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_BORDERS_BORDER_SEARCH_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_BORDERS_BORDER_SEARCH_H

// The choice among the candidates of the border family, written once for every border
// policy: the layout of one member (the circular, conformal and measured borders), the
// automatic search over the members, and the repair by blending toward a convex border.

#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_report.h>
#include <CGAL/Surface_mesh_parameterization/internal/borders/border_evaluator.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// Bisection steps of the search for the smallest valid blend along a member.
constexpr int valid_blend_bisection_steps = 5;

// The search along members whose own border (t = own_blend()) gave no valid layout: for each,
// the smallest valid blend t, by bisection on (own_blend, 1] (all members of one step in one
// batch), t = 1 tried last if no smaller t was valid. Along a member the layout moves toward
// a convex border, and the angle distortion grows in practice as the border moves away from a
// better member, so the smallest valid t is the member's best valid blend.
template <class Evaluator>
void search_smallest_valid_blend(Evaluator& evaluator, const std::vector<Border_family>& members, bool mean_value)
{
  std::vector<double> invalid(members.size(), 0.), valid(members.size(), -1.);
  for(std::size_t i = 0; i < members.size(); ++i)
    invalid[i] = evaluator.members().own_blend(members[i]);
  std::vector<typename Evaluator::Request> batch;
  for(int step = 0; step < valid_blend_bisection_steps; ++step)
  {
    batch.clear();
    for(std::size_t i = 0; i < members.size(); ++i)
      batch.emplace_back(members[i], 0.5 * (invalid[i] + (valid[i] < 0. ? 1. : valid[i])));
    const std::vector<Border_trial> trials = evaluator.evaluate(batch, mean_value, false);
    for(std::size_t i = 0; i < members.size(); ++i)
      (trials[i].valid ? valid[i] : invalid[i]) = batch[i].second;
  }
  batch.clear();
  for(std::size_t i = 0; i < members.size(); ++i)
    if(valid[i] < 0.)
      batch.emplace_back(members[i], 1.);
  if(!batch.empty())
    evaluator.evaluate(batch, mean_value, false);
}

// The layout of one member's own border; `repairable` gets the member.
template <class Evaluator>
void evaluate_member(Evaluator& evaluator, Border_family member, Parameterization_report& report,
                     std::vector<Border_family>& repairable)
{
  const Border_trial trial = evaluator.evaluate({{member, evaluator.members().own_blend(member)}}, false).front();
  report.valid_before_repair = trial.valid;
  report.flipped_faces_before_repair = trial.flipped_faces;
  repairable.push_back(member);
}

// The candidates of a border policy: its own search, or the layout of its one member.
template <class Policy, class Step, class Evaluator>
Error_code choose_border(const Policy& policy, Step& step, Evaluator& evaluator)
{
  if constexpr(Policy::searches)
    return policy.choose(step, evaluator);
  else
  {
    evaluate_member(evaluator, Policy::member, step.report, step.repairable);
    return OK;
  }
}

// The automatic border's search, its layouts ranked by the policy's bound (the caller's
// Evaluator::rank_by()):
// 1. the circle and the conformal border (at its own blend), in one batch;
// 2. when the conformal polygon is not simple (own blend > 0) or its layout not one-to-one:
//    the conformal-length member (`add_lengths()`);
// 3. only when the conformal layout is not one-to-one: the measured member (`add_measured()`).
//    Both return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM for a fatal failure and any other failure
//    to leave the member out;
// 4. for each member whose own layout is not one-to-one but ranks (as if it were) before the
//    best valid one so far, the smallest valid blend;
// 5. when the kept layout meets the bound (and `holomorphic_extension`), its holomorphic
//    extension (Border_evaluator::evaluate_holomorphic_extension(): one more factorization),
//    kept when it is one-to-one and ranks before. Only there: a layout beyond the bound is
//    split or repaired by the caller, and an atlas flattens many of those.
// `repairable` gets the members in the order of their own layouts' ranks.
template <class Evaluator, class AddMeasured, class AddLengths>
Error_code automatic_search(Evaluator& evaluator, const AddMeasured& add_measured, const AddLengths& add_lengths,
                            Parameterization_report& report, std::vector<Border_family>& repairable,
                            bool holomorphic_extension = true)
{
  std::vector<typename Evaluator::Request> batch(1, {CIRCLE, 1.});
  const bool conformal = evaluator.members().has(CONFORMAL);
  if(conformal)
    batch.emplace_back(CONFORMAL, evaluator.members().own_blend(CONFORMAL));
  std::vector<Border_trial> own = evaluator.evaluate(batch, false);
  const auto add = [&](const auto& build, Border_family member) {
    const Error_code status = build();
    if(status == OK)
      own.push_back(evaluator.evaluate({{member, evaluator.members().own_blend(member)}}, false).front());
    return status == ERROR_CANNOT_SOLVE_LINEAR_SYSTEM ? status : OK;
  };
  const bool folds = !own.back().valid;  // no valid conformal layout
  if(conformal && (folds || evaluator.members().own_blend(CONFORMAL) > 0.) && add(add_lengths, CONFORMAL_LENGTHS) != OK)
    return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
  if(folds && add(add_measured, MEASURED) != OK)
    return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
  bool first = true;
  for(const Border_trial& t : own)
    if(std::isfinite(t.estimate))
    {
      report.flipped_faces_before_repair =
        first ? t.flipped_faces : (std::min)(report.flipped_faces_before_repair, t.flipped_faces);
      first = false;
    }
  std::vector<Border_family> search;
  for(const Border_trial& t : own)
    if(!t.valid && t.member != CIRCLE && t.rank < evaluator.best_rank())
      search.push_back(t.member);
  if(!search.empty())
    search_smallest_valid_blend(evaluator, search, false);
  if(holomorphic_extension && evaluator.kept_meets_bound())
    evaluator.evaluate_holomorphic_extension();
  report.valid_before_repair = evaluator.best() >= 0;
  std::stable_sort(own.begin(), own.end(), [](const Border_trial& a, const Border_trial& b) { return a.rank < b.rank; });
  for(const Border_trial& t : own)
    repairable.push_back(t.member);
  return OK;
}

// The repair (blend toward the circle): along each member, the smallest valid blend with the
// discrete conformal interior (unless a search did it already), then with the mean value
// interior; the evaluator keeps the best. When the circle is a member and its mean value map
// folds (Floater's theorem makes it one-to-one: only rounding on a badly shaped disk defeats
// it), the other members' blends toward convex borders are not searched: they fail the same
// way, and on a large atlas chart that search cost most of the time of its failed repair.
template <class Evaluator>
void repair_by_blending(Evaluator& evaluator, const std::vector<Border_family>& members, bool conformal_search)
{
  std::vector<Border_family> blendable;
  for(Border_family m : members)
    if(m != CIRCLE)
      blendable.push_back(m);
  if(conformal_search && !blendable.empty())
    search_smallest_valid_blend(evaluator, blendable, false);
  std::vector<typename Evaluator::Request> batch;
  for(Border_family m : members)
    batch.emplace_back(m, evaluator.members().own_blend(m));
  const std::vector<Border_trial> own = evaluator.evaluate(batch, true, false);
  std::vector<Border_family> search;
  bool circle_folds = false;
  for(const Border_trial& t : own)
    if(t.valid)
      continue;
    else if(t.member == CIRCLE)
      circle_folds = true;
    else
      search.push_back(t.member);
  if(!search.empty() && !circle_folds)
    search_smallest_valid_blend(evaluator, search, true);
}

// The report's account of the choice: every candidate, the kept one.
template <class Evaluator>
Error_code report_choice(const Evaluator& evaluator, bool searched, Parameterization_report& report)
{
  for(const Border_trial& t : evaluator.trials())
    report.border_candidates.push_back(Border_candidate{t.member, t.blend, t.mean_value, t.valid, t.objective,
                                                         t.valid ? t.area_spread : t.objective, t.holomorphic});
  report.chosen_candidate = evaluator.best();
  if(evaluator.best() < 0)
    return ERROR_NO_1_TO_1_MAPPING;
  const Border_candidate& kept = report.border_candidates[static_cast<std::size_t>(evaluator.best())];
  report.kept_border = kept.family;
  report.blend = kept.blend;
  report.mean_value_interior = kept.mean_value_interior;
  report.holomorphic_extension = kept.holomorphic_extension;
  report.repaired = kept.mean_value_interior ||
                    (!searched && kept.blend > evaluator.members().own_blend(kept.family));
  return OK;
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_BORDERS_BORDER_SEARCH_H
