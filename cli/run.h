// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// The run of the measured_parameterization program behind an interface without CGAL, by
// run.cpp, the only file that calls the library. In the atlas mode (the default) the file is
// read as a polygon soup and the library repairs it, makes its charts and packs them; in the
// single-chart mode the mesh is read, checked, cut along seams when it is not a disk,
// parameterized, and its distortion measured. What the run gives the writers (OBJ, SVG, JSON,
// summary) is plain data, and the library's reports, `Atlas_report` and
// `Parameterization_report` (plain structs: their headers hold no CGAL code but the error
// codes).

#ifndef MBP_CLI_RUN_H
#define MBP_CLI_RUN_H

#include "mesh_reader.h"
#include "options.h"

#include <CGAL/Surface_mesh_parameterization/Atlas_report.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_report.h>

#include <array>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace mbp_cli {

/// A failure of the run: the message (it names the input) and the library's `Error_code`
/// (0, the library's `OK`, for a failure that has none, such as an unreadable file).
struct Run_error
{
  std::string message;
  int error_code = 0;

  bool failed() const { return !message.empty(); }
};

/// A parameterized mesh in the numbering of the output files, the same for a mesh and for a
/// mesh cut along seams. The 'v' lines are the input vertices that are in a face; the 'vt'
/// lines the UVs: one per vertex, or, for a seam mesh, one per seam mesh vertex (a vertex on
/// a seam has one per side).
struct Uv_layout
{
  std::vector<std::size_t> vertices;                   // per 'v': its input vertex, increasing
  std::vector<std::array<double, 3> > points;          // per 'v': its input point
  std::vector<std::size_t> uv_vertex;                  // per 'vt': its 'v' (0-based)
  std::vector<std::array<double, 2> > uv;              // per 'vt'
  std::vector<std::array<std::size_t, 3> > faces;      // per face, in input order: 'vt' indices (0-based)
  std::vector<double> face_angle_distortion;           // per face
  std::vector<bool> face_flipped;                      // per face: UV area <= 0
  std::vector<std::size_t> border;                     // the longest border loop: 'vt' indices
  std::vector<std::array<std::size_t, 2> > seam_sides; // both sides of every seam edge: 'vt' index pairs
  bool has_center = false;                             // --border=conformal and circle locate no center
  std::size_t center = 0;                              // 'vt' index of the center
  std::size_t center_vertex = 0;                       // input vertex of the center
  std::array<double, 3> center_point = {0., 0., 0.};   // its input point
};

/// The distortion figures of the layout (the library's `Parameterization_quality`).
struct Quality
{
  double angle_distortion = 0., angle_distortion_per_corner = 0.;
  double l2_stretch = 1., linf_stretch = 1.;
  double quasi_conformal_mean = 1., quasi_conformal_max = 1.;
  double area_distortion_mean = 0., area_distortion_max = 0.;
  std::size_t flipped_faces = 0, number_of_faces = 0;
};

/// The seams the mesh was cut along: those of --seams, or automatic seams (the library's
/// `Disk_seams_report`).
struct Seams
{
  bool cut = false;                   // whether the mesh was cut (it is not a disk, or --seams)
  bool automatic = false;             // automatic seams (compute_disk_seams), not --seams
  std::size_t edges = 0;              // seam edges
  std::vector<std::size_t> cones;     // automatic seams: the cone vertices (input vertices)
  double length = 0.;                 // automatic seams: 3D length
  int genus = 0, loops = 0;
  std::size_t border_loops = 0;
  double seconds = 0.;
  std::string selection;              // with --write-seams: the text of the selection file
};

/// The atlas of the input (`--atlas`), in the input's numbering: its points and polygons as
/// read, the UV of every polygon corner and the chart of every polygon (the library's
/// `compute_atlas_of_polygon_soup()`).
struct Atlas_result
{
  static constexpr std::size_t no_chart = std::size_t(-1);

  Polygon_soup soup;                               // the input: 'v' lines, and the polygons in their order
  std::vector<std::array<double, 2> > uv;          // per corner of the soup ('vt'), in [0,1]^2
  std::vector<std::size_t> polygon_chart;          // per polygon: its chart (no_chart: a polygon without corners)
  /// per polygon: |log(UV area / (3D area * texel_density^2))|, its area distortion after the
  /// one scale of the atlas (0 when either area is 0)
  std::vector<double> polygon_area_distortion;
  std::size_t empty_polygons = 0;                  // polygons without corners: not given to the library
  /// the library's report; its lengths and areas in the input's unit
  CGAL::Surface_mesh_parameterization::Atlas_report report;
};

/// What the run gives the writers.
struct Run_result
{
  Atlas_result atlas;                 // --atlas; the members below are those of --single-chart
  Uv_layout layout;
  Quality quality;
  double quality_seconds = 0.;        // time of the distortion measures
  Seams seams;
  std::size_t input_vertices = 0;     // vertices of the input, in a face or not
  std::size_t border_vertices = 0;    // of the longest border loop (a seam counts on both sides)
  double border_length = 0.;          // its 3D length
  /// the library's report of the parameterization (its `border_convex`: whether the kept
  /// border polygon is strictly convex)
  CGAL::Surface_mesh_parameterization::Parameterization_report report;
};

/// What the writers know of a run: the command line, the input, the result, and the times
/// the program measured around the run.
struct Run_facts
{
  Run_facts(const Options& options, const Run_result& result) : options(options), result(result) { }

  const Options& options;
  const Run_result& result;
  bool generated = false;             // the generated curved disk, not a file
  std::string mesh_name;              // the input file's name, or "curved disk (generated)"
  double read_seconds = 0., write_seconds = 0.;
};

/// One run: a mesh or a polygon soup (read from a file, or generated), then its atlas or its
/// parameterization.
class Run
{
public:
  Run();
  ~Run();
  Run(const Run&) = delete;
  Run& operator=(const Run&) = delete;

  /// makes the mesh the generated curved disk; returns its numbers of vertices and faces
  std::array<std::size_t, 2> generate_curved_disk();
  /// reads the file `path` (.off, .obj, .ply or .stl): for the atlas the polygon soup as it
  /// is, for a single chart the mesh
  Run_error read(const std::string& path, Mode mode);
  /// the atlas: the library repairs the soup, makes its charts and packs them; a single chart:
  /// checks the mesh, cuts it along seams when it is not a disk (those of --seams, or automatic
  /// ones), parameterizes it and measures the distortion
  Run_error parameterize(const Options& options);
  /// the result of `parameterize()`
  const Run_result& result() const;

private:
  struct Impl;
  std::unique_ptr<Impl> m;
};

} // namespace mbp_cli

#endif // MBP_CLI_RUN_H
