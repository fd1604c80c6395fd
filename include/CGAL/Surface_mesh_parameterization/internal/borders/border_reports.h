// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_BORDERS_BORDER_REPORTS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_BORDERS_BORDER_REPORTS_H

// What the border steps tell the report, in the mesh's unit of length.

#include <CGAL/Surface_mesh_parameterization/Parameterization_report.h>
#include <CGAL/Surface_mesh_parameterization/internal/borders/conformal_border.h>
#include <CGAL/Surface_mesh_parameterization/internal/borders/measured_member.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/validity.h>

#include <Eigen/Core>

#include <array>
#include <chrono>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

inline std::vector<double> scaled(std::vector<double> values, double factor)
{
  for(double& x : values)
    x *= factor;
  return values;
}

// The conformal border's data and its smallest simple blend.
inline void report_conformal(const Conformal_border_data& data, const std::vector<double>& closed, double blend,
                             double length_unit, Parameterization_report& report)
{
  report.edge_lengths = scaled(data.lengths, length_unit);
  report.closed_lengths = scaled(closed, length_unit);
  report.geodesic_curvatures = data.curvature;
  report.corrections = data.correction;
  report.turning_angles = data.turning;
  report.conformal_blend = blend;
}

// A conformal member built by `add` (a call of Border_members::add_conformal or
// add_conformal_lengths with the disk, the polygon and the closed lengths), reported with the
// member's own blend unless `reported` is false; `seconds` gets the time it took.
template <class Step, class Add>
Error_code build_conformal_member(Step& step, Border_family member, Add add, double& seconds, bool reported = true)
{
  const std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  std::vector<Eigen::Vector2d> polygon;
  std::vector<double> closed;
  const Error_code status = add(step.disk, polygon, closed);
  if(status == OK && reported)
    report_conformal(step.members.conformal(), closed, step.members.own_blend(member), step.disk.length_unit(),
                     step.report);
  seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return status;
}

// The conformal-length member (the conformal member built first), with its time and scale
// factors in the report; `reported`: whether the report gives its own blend and closed lengths
// (the policy's own member) or keeps the conformal border's (a member of the automatic search).
template <class Step>
Error_code build_conformal_length_member(Step& step, bool reported)
{
  const Error_code status = build_conformal_member(
    step, CONFORMAL_LENGTHS,
    [&step](auto& disk, auto& polygon, auto& closed) { return step.members.add_conformal_lengths(disk, polygon, closed); },
    step.report.conformal_length_seconds, reported);
  if(status == OK)
    step.report.scale_factors = step.members.scale_factors();
  return status;
}

// The center (by its position in vertices(mesh)), the distances and the polar map.
template <class Disk>
void report_measured(const Disk& disk, const Measured_member& member, Parameterization_report& report)
{
  report.has_center = member.located;
  if(member.located)
    report.center = disk.position_in_mesh(member.center);
  report.border_distances = scaled(member.distances, disk.length_unit());
  if(member.polar.angles.empty())
    return;  // no polar map: a step failed
  report.border_angles = member.polar.angles;
  report.polar_origin = {{member.polar.origin.x(), member.polar.origin.y()}};
  report.polar_scale = member.polar.scale / disk.length_unit();  // per unit of the mesh's length
}

// The border polygon of the result.
inline void report_border(const std::vector<Eigen::Vector2d>& uv, Parameterization_report& report)
{
  report.border_uv.resize(uv.size());
  for(std::size_t k = 0; k < uv.size(); ++k)
    report.border_uv[k] = {{uv[k].x(), uv[k].y()}};
  report.border_convex = is_strictly_convex_clockwise(uv);
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_BORDERS_BORDER_REPORTS_H
