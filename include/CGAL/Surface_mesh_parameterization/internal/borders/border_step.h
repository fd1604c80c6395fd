// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_BORDERS_BORDER_STEP_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_BORDERS_BORDER_STEP_H

// What a border policy works on during one call (the protocol between the border policies and
// the parameterizers, see the concept BorderPolicy): the disk, the members built so far, the
// report, and the call's options. A policy's build() adds its members; its choose() evaluates
// candidates with an evaluator (border_evaluator.h) and names the members a repair may blend.

#include <CGAL/Surface_mesh_parameterization/Parameterization_report.h>
#include <CGAL/Surface_mesh_parameterization/internal/borders/border_members.h>

#include <Eigen/Core>

#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

template <class Disk_>
struct Border_step
{
  typedef Disk_ Disk;

  Border_step(Disk& d, Parameterization_report& r, bool parallel_, bool factorize_interior_)
    : disk(d), members(d), report(r), parallel(parallel_), factorize_interior(factorize_interior_)
  { }

  Disk& disk;
  Border_members members;
  Parameterization_report& report;
  bool parallel;            // whether the policies may start a second thread (Parallel_tag)
  bool factorize_interior;  // whether L_II will be needed (the complete parameterizer)
  std::vector<Border_family> repairable;  // set by choose(): the members a repair may blend
};

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_BORDERS_BORDER_STEP_H
