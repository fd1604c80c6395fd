// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_SEAMS_DISK_CUT_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_SEAMS_DISK_CUT_H

// The cut of an indexed surface into a disk (compute_disk_seams.h), in steps: the shortest
// greedy system of loops or arcs (cut_graph.h), the cones (cone_placement.h) joined to it,
// then pruning and shortening (cut_shortening.h), and the final check that a disk is left.

#include <CGAL/Surface_mesh_parameterization/Disk_seams_report.h>
#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/internal/seams/cone_placement.h>
#include <CGAL/Surface_mesh_parameterization/internal/seams/cut_graph.h>
#include <CGAL/Surface_mesh_parameterization/internal/seams/cut_shortening.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// The longest border loop (3D length), or -1.
inline int longest_border_loop(const Indexed_surface& s)
{
  int best = -1;
  double best_length = -1.;
  for(std::size_t l = 0; l < s.border_loops.size(); ++l)
  {
    const std::vector<int>& loop = s.border_loops[l];
    double length = 0.;
    for(std::size_t k = 0; k < loop.size(); ++k)
      length += (s.points[static_cast<std::size_t>(loop[k])] - s.points[static_cast<std::size_t>(loop[(k + 1) % loop.size()])]).norm();
    if(length > best_length)
    {
      best_length = length;
      best = static_cast<int>(l);
    }
  }
  return best;
}

// Total length of the cut.
inline double cut_length(const Indexed_surface& s, const std::vector<char>& cut)
{
  double length = 0.;
  for(std::size_t e = 0; e < cut.size(); ++e)
    length += cut[e] ? s.edge_lengths[e] : 0.;
  return length;
}

// The greedy system from `root`, pruned and shortened, into `cut` (all zero); returns the
// number of loops or arcs, and the closing edges of the system in `closing` (when not null).
inline int pruned_system_from(const Indexed_surface& s, const Disk_seams_options& options,
                              const std::vector<char>& terminal, int root, std::vector<char>& cut,
                              std::vector<int>* closing, int& shortened)
{
  const int loops = greedy_system_of_cuts(s, root, cut, closing);
  prune_cut(s, terminal, cut);
  shortened = options.shorten ? shorten_cut(s, terminal, 1, options.shortening_passes, cut) : 0;
  return loops;
}

// The greedy system of loops or arcs, pruned and shortened, into `cut` (all zero); returns
// the number of loops or arcs. On a closed surface, the greedy system is the shortest
// system of loops through its root (Erickson and Whittlesey), and the root matters: the
// system is computed from vertex 0, then from one end of each closing edge of that system
// (the point of its loop farthest from the root, where a better root often lies: on a torus
// rooted on the outer equator, the meridian's far point is on the inner equator, the root of
// the shortest system), at most 8 roots; the shortest system is kept.
inline int shortest_system(const Indexed_surface& s, const Disk_seams_options& options,
                           const std::vector<char>& terminal, std::vector<char>& cut, int& shortened)
{
  std::vector<int> closing;
  const int loops = pruned_system_from(s, options, terminal, 0, cut, &closing, shortened);
  if(!s.border_loops.empty())
    return loops;
  double best = cut_length(s, cut);
  std::vector<char> other;
  for(std::size_t k = 0; k < closing.size() && k < 7; ++k)
  {
    other.assign(cut.size(), 0);
    int replaced = 0;
    pruned_system_from(s, options, terminal, s.edge_vertices[static_cast<std::size_t>(closing[k])][0], other,
                       nullptr, replaced);
    const double length = cut_length(s, other);
    if(length < best)
    {
      best = length;
      cut.swap(other);
      shortened = replaced;
    }
  }
  return loops;
}

// What the cut must do on a surface: join the holes or not, how many cones to place, and
// which border vertices it may end on.
struct Cut_plan
{
  bool join = true;             // whether the border loops are joined
  long chi = 1;                 // Euler characteristic of the cut surface: 1 - (holes kept)
  int cones = 0;                // cones to place
  std::vector<char> main_border; // the border vertices the cut may end on
  std::vector<char> avoided;     // the vertices of the holes kept open
};

// On a closed surface of genus 0, the default cone count and at least 2; on a genus-0
// surface whose holes stay open, the cut ends on the longest border only.
inline Cut_plan plan_cut(const Indexed_surface& s, const Disk_seams_options& options)
{
  const std::size_t n = static_cast<std::size_t>(s.number_of_vertices()), b = s.border_loops.size();
  const int genus = s.genus();
  const bool closed_sphere = (b == 0 && genus == 0);
  Cut_plan plan;
  plan.join = options.join_holes || genus > 0;
  plan.chi = 1 - (plan.join ? 0 : (b >= 2 ? long(b) - 1 : 0));
  const int count = (options.number_of_cones >= 0) ? options.number_of_cones
                    : closed_sphere ? (std::min)(Disk_seams_options::default_number_of_cones, static_cast<int>(n / 16))
                                    : 0;
  plan.cones = closed_sphere ? (std::max)(count, 2) : count;
  plan.main_border.assign(n, 0);
  plan.avoided.assign(n, 0);
  const int main_loop = longest_border_loop(s);
  for(std::size_t l = 0; l < b; ++l)
    for(int v : s.border_loops[l])
      (plan.join || static_cast<int>(l) == main_loop ? plan.main_border : plan.avoided)[static_cast<std::size_t>(v)] = 1;
  return plan;
}

// The vertices of the cut and of the border: D of the cone placement.
inline std::vector<char> cut_and_border_vertices(const Indexed_surface& s, const std::vector<char>& cut)
{
  std::vector<char> fixed(s.border_vertex.begin(), s.border_vertex.end());
  for(int e = 0; e < s.number_of_edges(); ++e)
    if(cut[static_cast<std::size_t>(e)])
      for(int v : s.edge_vertices[static_cast<std::size_t>(e)])
        fixed[static_cast<std::size_t>(v)] = 1;
  return fixed;
}

// Joins the cones to the cut, or to the main border, by shortest paths avoiding the holes
// kept open (on a closed genus-0 surface, from the first cone), then prunes the cut.
inline bool join_cones(const Indexed_surface& s, const Cut_plan& plan, const std::vector<char>& fixed,
                       const std::vector<int>& cones, std::vector<char>& terminal, std::vector<char>& cut)
{
  std::vector<char> connected(fixed.size(), 0);
  for(std::size_t v = 0; v < fixed.size(); ++v)
    connected[v] = (fixed[v] && !plan.avoided[v]) || plan.main_border[v];
  if(!cones.empty() && std::find(connected.begin(), connected.end(), char(1)) == connected.end())
    connected[static_cast<std::size_t>(cones.front())] = 1;  // closed genus 0: start at a cone
  for(int c : cones)
    terminal[static_cast<std::size_t>(c)] = 1;
  if(!connect_terminals(s, cones, plan.avoided, connected, cut))
    return false;
  prune_cut(s, terminal, cut);
  return true;
}

// Places the cones of the plan off the cut and the border, and joins them to the cut.
template <class SolverTraits>
Disk_seams_problem add_cones(const Indexed_surface& s, const Cut_plan& plan, std::vector<char>& cut,
                             std::vector<int>& cones, std::vector<char>& terminal, Disk_seams_report& report)
{
  const std::vector<char> fixed = cut_and_border_vertices(s, cut);
  Cone_placement<SolverTraits> placement(s, fixed);
  const Error_code status = placement.place(plan.cones, cones);
  report.statistics = placement.statistics();
  if(status == ERROR_DEGENERATE_FACE)
    return ZERO_AREA_FACE;
  if(status != OK)
    return SOLVER_FAILURE;
  return join_cones(s, plan, fixed, cones, terminal, cut) ? NO_PROBLEM : CUT_NOT_A_DISK;
}

// The cut on the indexed surface: the greedy system of loops or arcs, the cones joined to it,
// pruned and shortened. `cut` gets one flag per edge, `cones` the cone vertices.
template <class SolverTraits>
Disk_seams_problem cut_to_disk(const Indexed_surface& s, const Disk_seams_options& options,
                               std::vector<char>& cut, std::vector<int>& cones, Disk_seams_report& report)
{
  const Cut_plan plan = plan_cut(s, options);
  const bool several_borders = s.border_loops.size() >= 2;
  std::vector<char> terminal(static_cast<std::size_t>(s.number_of_vertices()), 0);
  cut.assign(static_cast<std::size_t>(s.number_of_edges()), 0);
  if(s.genus() > 0 || (plan.join && several_borders))
    report.number_of_loops = shortest_system(s, options, terminal, cut, report.shortened_paths);
  if(plan.cones > 0)
  {
    const Disk_seams_problem problem = add_cones<SolverTraits>(s, plan, cut, cones, terminal, report);
    if(problem != NO_PROBLEM)
      return problem;
  }
  if(options.shorten && !cones.empty())
    report.shortened_paths += shorten_cut(s, terminal, plan.chi, options.shortening_passes, cut);
  report.holes_joined = plan.join && several_borders;
  return is_disk_cut(s, cut, plan.chi) ? NO_PROBLEM : CUT_NOT_A_DISK;
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_SEAMS_DISK_CUT_H
