// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_BORDERS_BORDER_EVALUATOR_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_BORDERS_BORDER_EVALUATOR_H

// A candidate layout is a border of the family (border_members.h) and an interior: the
// discrete conformal map (two back-substitutions of the disk's factorization of L_II;
// candidates are solved in batches, one multi-column solve per batch) or the mean value map
// (positive weights: one-to-one for a convex border, by Floater's theorem; the disk's mean
// value system, factorized on first use). The evaluator records every candidate and keeps the
// valid one of lowest rank (Distortion_bound::rank(): by the angle distortion alone unless a
// policy sets a finite bound, as Automatic_border does).

#include <CGAL/Surface_mesh_parameterization/Distortion_bound.h>
#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_report.h>
#include <CGAL/Surface_mesh_parameterization/internal/borders/border_members.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/angle_distortion.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/area_spread.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/validity.h>

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// One candidate tried.
struct Border_trial
{
  Border_family member;
  double blend;
  bool mean_value;            // mean value interior (rather than the discrete conformal map)
  bool valid;                 // one-to-one
  std::size_t flipped_faces;  // real faces not positively oriented (0 when there is no layout)
  double objective;           // angle distortion; +infinity when not valid
  double estimate;            // angle distortion of the layout even when not valid (+infinity
                              // when there is no layout: the border could not be built or solved)
  double area_spread;         // area spread of the layout, as `estimate`
  double rank;                // the bound's rank of (estimate, area_spread), as `estimate`
  bool holomorphic = false;   // the holomorphic extension of the border's first coordinate
                              // (evaluate_holomorphic_extension()): the border moved
};

// A layout: border UVs (disk.border() order) and interior UVs (interior_vertices() order).
struct Border_solution
{
  std::vector<Eigen::Vector2d> border_uv;
  std::vector<double> u, v;
};

// UV of every disk vertex from a layout.
template <class Disk>
void assemble_uv(const Disk& disk, const Border_solution& s, std::vector<Eigen::Vector2d>& uv)
{
  uv.assign(disk.number_of_vertices(), Eigen::Vector2d::Zero());
  for(std::size_t k = 0; k < s.border_uv.size(); ++k)
    uv[static_cast<std::size_t>(disk.border()[k])] = s.border_uv[k];
  const std::vector<int>& interior = disk.interior_vertices();
  for(std::size_t r = 0; r < interior.size(); ++r)
    uv[static_cast<std::size_t>(interior[r])] = Eigen::Vector2d(s.u[r], s.v[r]);
}

template <class Disk>
class Border_evaluator
{
public:
  typedef std::pair<Border_family, double> Request;

  Border_evaluator(Disk& disk, const Border_members& members)
    : m_disk(disk), m_members(members), m_objective(disk_angle_distortion(disk)),
      m_area(disk.points(), disk_real_faces(disk))
  { }

  // ranks the layouts evaluated from now on by `bound` (by default: infinite, i.e. by the
  // angle distortion alone)
  void rank_by(const Distortion_bound& bound) { m_bound = bound; }
  // whether a layout is kept and meets the bound
  bool kept_meets_bound() const
  {
    return m_best >= 0 && m_bound.met_by(m_trials[static_cast<std::size_t>(m_best)].objective,
                                         m_trials[static_cast<std::size_t>(m_best)].area_spread);
  }

  // evaluates the requested borders with one interior; returns their trials. Without
  // `estimates` a layout that is not one-to-one is not measured (its estimate, area spread
  // and rank stay infinite, its flipped faces are counted up to one): the searches of the
  // smallest valid blend read only whether a layout is valid.
  std::vector<Border_trial> evaluate(const std::vector<Request>& batch, bool mean_value, bool estimates = true)
  {
    std::vector<Border_solution> solutions(batch.size());
    std::vector<bool> placed(batch.size());
    for(std::size_t i = 0; i < batch.size(); ++i)
      placed[i] = m_members.border(batch[i].first, batch[i].second, solutions[i].border_uv);
    const bool solved = solve(placed, solutions, mean_value);
    std::vector<Border_trial> result;
    for(std::size_t i = 0; i < batch.size(); ++i)
    {
      const Border_trial trial = judge(batch[i], mean_value, solved && placed[i], estimates, solutions[i]);
      m_trials.push_back(trial);
      result.push_back(trial);
      if(trial.valid && trial.rank < best_rank())
      {
        m_best = static_cast<int>(m_trials.size()) - 1;
        m_best_solution = std::move(solutions[i]);
      }
    }
    return result;
  }

  // Boundary First Flattening's holomorphic extension of the kept layout (valid, with the
  // discrete conformal interior): its first coordinate x kept (the harmonic extension of the
  // border's x), the second the harmonic conjugate of x, the y with L y = h on the whole
  // cotangent Laplacian, h_k = (x_{k+1} - x_{k-1}) / 2 on the border loop and 0 elsewhere
  // (the discrete Cauchy-Riemann equations: the normal derivative of y is the tangential
  // derivative of x). Where the border is not exactly the conformal one (its lengths closed
  // by the least change, or blended), this is more conformal than fixing both coordinates on
  // the border: on a locally refined developable disk the mean angle error drops from 0.057 to
  // 0.014 degrees. One back-substitution of the grounded cotangent system (factorized on
  // first use, as for the conformal-length member); the border moves, so the layout is
  // judged as any other, its border tested simple. False when there is no kept layout to
  // extend or the system cannot be solved.
  bool evaluate_holomorphic_extension()
  {
    if(m_best < 0 || m_trials[static_cast<std::size_t>(m_best)].mean_value)
      return false;
    const Border_trial kept = m_trials[static_cast<std::size_t>(m_best)];
    std::vector<Eigen::Vector2d> uv;
    assemble_uv(m_disk, m_best_solution, uv);
    Border_solution conjugate;
    if(!harmonic_conjugate(uv, conjugate))
      return false;
    const bool simple = is_simple_polygon(conjugate.border_uv);
    Border_trial trial = judge({kept.member, kept.blend}, false, simple, true, conjugate);
    trial.holomorphic = true;
    m_trials.push_back(trial);
    if(trial.valid && trial.rank < best_rank())
    {
      m_best = static_cast<int>(m_trials.size()) - 1;
      m_best_solution = std::move(conjugate);
    }
    return true;
  }

  const std::vector<Border_trial>& trials() const { return m_trials; }
  const Border_members& members() const { return m_members; }
  // index of the kept trial, -1 when none is valid
  int best() const { return m_best; }
  // the rank of the kept trial, +infinity when none is valid
  double best_rank() const
  {
    return m_best < 0 ? std::numeric_limits<double>::infinity() : m_trials[static_cast<std::size_t>(m_best)].rank;
  }
  const Border_solution& best_solution() const { return m_best_solution; }

private:
  Border_trial judge(const Request& request, bool mean_value, bool laid_out, bool estimates,
                     const Border_solution& solution)
  {
    const double inf = std::numeric_limits<double>::infinity();
    Border_trial trial{request.first, request.second, mean_value, false, 0, inf, inf, inf, inf};
    if(!laid_out)
      return trial;
    std::vector<Eigen::Vector2d> uv;
    assemble_uv(m_disk, solution, uv);
    trial.flipped_faces = count_flips(m_disk.faces_indices(), m_disk.number_of_real_faces(), uv,
                                      estimates ? std::size_t(-1) : std::size_t(1));
    trial.valid = trial.flipped_faces == 0 && border_curves_are_valid(m_disk, uv);
    if(!trial.valid && !estimates)
      return trial;
    trial.estimate = m_objective(uv);
    trial.area_spread = m_area(uv);
    trial.rank = m_bound.rank(trial.estimate, trial.area_spread);
    if(trial.valid)
      trial.objective = trial.estimate;
    return trial;
  }

  // The layout (x, y) of evaluate_holomorphic_extension() from the layout `uv`: y scaled by
  // -1 when needed so that the border keeps its orientation, shifted so that its border
  // keeps its mean.
  bool harmonic_conjugate(const std::vector<Eigen::Vector2d>& uv, Border_solution& result)
  {
    const std::vector<int>& border = m_disk.border();
    const std::size_t m = border.size();
    std::vector<double> h(uv.size(), 0.), y;
    for(std::size_t k = 0; k < m; ++k)
      h[static_cast<std::size_t>(border[k])] = 0.5 * (uv[static_cast<std::size_t>(border[(k + 1) % m])].x() -
                                                       uv[static_cast<std::size_t>(border[(k + m - 1) % m])].x());
    if(m < 3 || m_disk.solve_cotangent_poisson(h, y) != OK || y.size() != uv.size())
      return false;
    std::vector<Eigen::Vector2d> xy(uv.size());
    for(std::size_t i = 0; i < uv.size(); ++i)
      xy[i] = Eigen::Vector2d(uv[i].x(), y[i]);
    const double before = signed_double_area(border, uv), after = signed_double_area(border, xy);
    if(!std::isfinite(after) || after == 0.)
      return false;
    const double sign = ((before > 0.) == (after > 0.)) ? 1. : -1.;
    double shift = 0.;
    for(int i : border)
      shift += uv[static_cast<std::size_t>(i)].y() - sign * y[static_cast<std::size_t>(i)];
    shift /= double(m);
    for(Eigen::Vector2d& p : xy)
      p.y() = sign * p.y() + shift;
    for(int i : border)
      result.border_uv.push_back(xy[static_cast<std::size_t>(i)]);
    for(int i : m_disk.interior_vertices())
    {
      result.u.push_back(xy[static_cast<std::size_t>(i)].x());
      result.v.push_back(xy[static_cast<std::size_t>(i)].y());
      if(!std::isfinite(result.v.back()))
        return false;
    }
    return true;
  }

  // Every placed border's interior, with one multi-column solve of the interior system
  // (cotangent weights) or of the mean value system.
  bool solve(const std::vector<bool>& placed, std::vector<Border_solution>& solutions, bool mean_value)
  {
    typename Disk::Engine* system = mean_value ? m_disk.systems().mean_value() : m_disk.systems().interior();
    if(system == nullptr)
      return false;
    const Eigen::Index m = static_cast<Eigen::Index>(m_disk.border().size());
    Eigen::MatrixXd values = Eigen::MatrixXd::Zero(m, 2 * static_cast<Eigen::Index>(solutions.size()));
    for(std::size_t i = 0; i < solutions.size(); ++i)
      for(Eigen::Index k = 0; placed[i] && k < m; ++k)
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

  Disk& m_disk;
  const Border_members& m_members;
  Angle_distortion m_objective;
  Area_spread m_area;
  Distortion_bound m_bound{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  std::vector<Border_trial> m_trials;
  int m_best = -1;
  Border_solution m_best_solution;
};

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_BORDERS_BORDER_EVALUATOR_H
