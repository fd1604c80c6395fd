// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// Command line of the measured_parameterization program: the options, their parsing and the
// help text (options.cpp). No CGAL here.

#ifndef MBP_CLI_OPTIONS_H
#define MBP_CLI_OPTIONS_H

#include <CGAL/Surface_mesh_parameterization/Atlas_report.h>

#include <cstddef>
#include <string>
#include <vector>

namespace mbp_cli {

enum class Solver { ldlt, cholmod, cholmod_nd };

/// the border the run lays out (`--border=`)
enum class Border { automatic, conformal, conformal_lengths, measured, circle };

/// what the run makes: a packed texture atlas of any polygon soup (`--atlas`, the default), or
/// the single-chart parameterization of a triangle mesh (`--single-chart`, implied by the
/// options of that mode: --border, --center, --distance, --seams, --write-seams, --solver,
/// --no-repair)
enum class Mode { atlas, single_chart };

/// whether this build has CHOLMOD (`MBP_WITH_CHOLMOD`)
bool has_cholmod();
/// the command-line name of a solver: cholmod, cholmod-nd or ldlt
const char* solver_name(Solver s);
/// the command-line name of a border: auto, conformal, measured or circle
const char* border_name(Border b);
/// the name of a mode: atlas or single-chart
const char* mode_name(Mode m);

/// the batch mode (`--batch=FOLDER|LIST|-`, cli/batch.h): many inputs to one output folder
struct Batch_options
{
  std::string source;            // --batch=: a folder, a list file (one path a line), or - (stdin)
  std::string output_dir;        // --output-dir=DIR
  unsigned int jobs = 1;         // --jobs=N: worker processes at once
  unsigned int shard = 1;        // --shard=I/N: the I-th (1-based) ...
  unsigned int shards = 1;       // ... of N slices of the sorted input list
  bool force = false;            // --force: redo the meshes done before

  bool active() const { return !source.empty(); }
};

struct Options
{
  std::string input;        // empty: the built-in default mesh
  std::string output;       // OUTPUT.obj or --output=FILE; empty: <input file stem>_uv.obj in the current directory
  std::string svg;          // empty: no picture
  std::string seams;        // --seams=FILE: a CGAL selection file of seam edges; empty: no seams
                            // (automatic seams when the mesh is not a disk)
  std::string write_seams;  // --write-seams=FILE: the seams used, as a CGAL selection file
  bool json = false;
  bool help = false;
  Mode mode = Mode::atlas;
  unsigned int resolution = 1024;   // --resolution=N: texels per side of the atlas texture
  unsigned int gutter = 2;          // --gutter=N: texels between charts and to the border
  // --max-area-spread, --max-angle-distortion, --min-compactness, --split: the charts' bounds
  // and how a chart that misses them is split (the library's defaults)
  CGAL::Surface_mesh_parameterization::Atlas_options bounds;
  bool repair = true;       // --no-repair turns it off
  Border border = Border::automatic;
  bool fixed_center = false;        // --center=vertex:N
  std::size_t center_vertex = 0;    // N
  std::string center = "poisson";   // poisson, or geodesic:METHOD (when not fixed_center)
  std::string distance = "poisson"; // poisson, a geodesic METHOD, or straightest (default: see parse)
  Solver solver = has_cholmod() ? Solver::cholmod : Solver::ldlt;
  // --threads=N: the BLAS threads of CHOLMOD (0: the BLAS is left alone) and, from 2 on, the
  // package's own threads (CGAL::Parallel_tag)
  unsigned int threads = 1;
  Batch_options batch;

  std::string center_name() const
  {
    return fixed_center ? "vertex:" + std::to_string(center_vertex) : center;
  }
};

/// the geodesic methods, by their command-line names
const std::vector<std::string>& geodesic_methods();
bool is_geodesic_method(const std::string& name);

/// the program's default mesh: a path, or empty when none was configured (default_mesh.cpp)
extern const char* const default_mesh;

/// the help text (`--help`)
std::string usage(const std::string& default_mesh);

/// parses the command line into `o`. Returns an empty string on success, otherwise the
/// message of the first error. `--help` stops the parsing.
std::string parse_options(int argc, char** argv, Options& o);

} // namespace mbp_cli

#endif // MBP_CLI_OPTIONS_H
