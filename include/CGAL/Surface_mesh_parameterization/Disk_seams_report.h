// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_DISK_SEAMS_REPORT_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_DISK_SEAMS_REPORT_H

/// \file Disk_seams_report.h
/// The options and the report of `compute_disk_seams()` (compute_disk_seams.h).

#include <CGAL/Surface_mesh_parameterization/Parameterization_report.h>

#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgSurfaceMeshParameterizationMeasured
/// Options of `compute_disk_seams()`.
struct Disk_seams_options
{
  /// The number of cones on a closed surface of genus 0 when `number_of_cones` is negative.
  /// Chosen by measurement (`seam_comparison --sweep`, `benchmark/README.md`): on the closed
  /// meshes of genus 0 of the project, flattened with the conformal border, the median
  /// deviation of the log area ratios falls from 1.35 (2 cones) to 0.78 (4) and 0.39 (8),
  /// then only to 0.30 with 16 cones, for 15 to 30% more seam length; 8 is the smallest count
  /// within 1.3 times the 16-cone figure, and the angle distortion is below 0.05 on all three.
  static constexpr int default_number_of_cones = 8;

  /// Cones to place: the cut passes through that many vertices where the conformal scale
  /// factor is most extreme (see `compute_disk_seams()`). Negative (the default): automatic,
  /// `default_number_of_cones` on a closed surface of genus 0 (but no more than one vertex in
  /// 16, so that a small mesh keeps interior vertices: an octahedron gets 2) and none
  /// otherwise. A closed surface of genus 0 gets at least 2, the fewest a cut can end at.
  int number_of_cones = -1;
  /// Whether the cut joins every border loop (`true`, the default), or, on a surface of
  /// genus 0, leaves the holes (the border loops other than the longest) open for the
  /// parameterizer's virtual hole filling. A surface with handles always gets its holes
  /// joined: its loops need the border to end on.
  bool join_holes = true;
  /// Whether each path of the cut between two branch points is replaced by a shorter path
  /// between the same points, on the same sides, when the cut stays a disk (default `true`).
  bool shorten = true;
  /// The most passes of shortening over all paths (default 3).
  int shortening_passes = 3;
};

/// \ingroup PkgSurfaceMeshParameterizationMeasured
/// What made `compute_disk_seams()` fail, or `NO_PROBLEM`.
enum Disk_seams_problem
{
  /// success
  NO_PROBLEM,
  /// the mesh has no face
  EMPTY_INPUT_MESH,
  /// a face is not a triangle (`problem_face` in the report)
  FACE_NOT_A_TRIANGLE,
  /// a vertex has two or more fans of faces, or an edge has no face (`problem_vertex`)
  NON_MANIFOLD_VERTEX,
  /// the faces form several connected components (`number_of_components`)
  SEVERAL_COMPONENTS,
  /// a vertex coordinate is infinite or NaN (`problem_vertex`)
  NON_FINITE_COORDINATE,
  /// a face has zero area, so the cone placement has no cotangent weights (`problem_face`)
  ZERO_AREA_FACE,
  /// the sparse solver of the cone placement failed
  SOLVER_FAILURE,
  /// the cut does not leave a disk (an internal failure; it should not happen)
  CUT_NOT_A_DISK
};

/// \ingroup PkgSurfaceMeshParameterizationMeasured
/// the message of a `Disk_seams_problem`, naming the problem.
inline const char* disk_seams_problem_message(Disk_seams_problem problem)
{
  switch(problem)
  {
  case NO_PROBLEM:            return "no problem";
  case EMPTY_INPUT_MESH:      return "the mesh has no face";
  case FACE_NOT_A_TRIANGLE:   return "the mesh has a face that is not a triangle";
  case NON_MANIFOLD_VERTEX:   return "the mesh is not a manifold: a vertex joins two or more fans of faces";
  case SEVERAL_COMPONENTS:    return "the mesh has several connected components; cut each one separately";
  case NON_FINITE_COORDINATE: return "the mesh has a non-finite vertex coordinate";
  case ZERO_AREA_FACE:        return "the mesh has a face of zero area (the cone placement needs cotangent weights)";
  case SOLVER_FAILURE:        return "the sparse solver of the cone placement failed";
  case CUT_NOT_A_DISK:        return "internal error: the cut does not leave a disk";
  }
  return "unknown problem";
}

/// \ingroup PkgSurfaceMeshParameterizationMeasured
///
/// The report of one call of `compute_disk_seams()`: pass a pointer to one as its optional
/// `report` argument. Lengths are in the mesh's unit. Vertices are named by their position in
/// the range `vertices(tm)` and faces by their position in `faces(tm)` (for a
/// `CGAL::Surface_mesh` without removed elements, `Mesh::Vertex_index(report.cones[k])`).
struct Disk_seams_report
{
  /// the value of `problem_vertex` and `problem_face` when there is no such element
  static constexpr std::size_t no_element = (std::numeric_limits<std::size_t>::max)();

  /// `NO_PROBLEM`, or what failed
  Disk_seams_problem problem = NO_PROBLEM;
  /// the offending vertex, by its position in `vertices(tm)` (`NON_MANIFOLD_VERTEX`,
  /// `NON_FINITE_COORDINATE`), otherwise `no_element`
  std::size_t problem_vertex = no_element;
  /// the offending face, by its position in `faces(tm)` (`FACE_NOT_A_TRIANGLE`,
  /// `ZERO_AREA_FACE`), otherwise `no_element`
  std::size_t problem_face = no_element;
  /// connected components of the faces
  std::size_t number_of_components = 0;
  /// genus of the mesh
  int genus = 0;
  /// border loops of the mesh
  std::size_t number_of_border_loops = 0;
  /// loops (closed surface: 2g) or arcs (with border: 2g + b - 1) of the greedy system
  int number_of_loops = 0;
  /// seam edges written
  std::size_t number_of_seam_edges = 0;
  /// total 3D length of the seam edges
  double seam_length = 0.;
  /// the cones, by their position in `vertices(tm)`, in the order they were placed
  std::vector<std::size_t> cones;
  /// whether the border loops were joined by the cut (see `Disk_seams_options::join_holes`)
  bool holes_joined = false;
  /// cut paths replaced by shorter ones
  int shortened_paths = 0;
  /// factorizations and back-substitutions of the cone placement
  Solver_statistics statistics;
  /// time of the call (wall clock, seconds)
  double seconds = 0.;
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_DISK_SEAMS_REPORT_H
