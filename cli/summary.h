// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// The one-line summary of a run, and the texts that name the border kept and the repair, or
// the charts and the repairs of an atlas (also in the OBJ header and the SVG caption), read
// from the plain data of the run and the library's reports (summary.cpp). No CGAL here but the
// reports' headers.

#ifndef MBP_CLI_SUMMARY_H
#define MBP_CLI_SUMMARY_H

#include "run.h"
#include "text_output.h"

#include <cstddef>
#include <string>

namespace mbp_cli {

/// what the summary says before the border kept: the mesh, the seams, the border and the center
std::string summary_of_mesh(const Run_facts& facts);
/// what the summary says after the solver: the distortion
std::string summary_of_quality(const Quality& quality);

/// the kind of a layout tried: circle, conformal, or measured:<distance>
std::string candidate_kind(const CGAL::Surface_mesh_parameterization::Border_candidate& c,
                           const std::string& distance);

/// the layout kept: "conformal (3 layouts tried)", "measured:poisson t 0.38, mean value
/// interior (9 layouts tried)"
std::string kept_border(const CGAL::Surface_mesh_parameterization::Parameterization_report& report,
                        const std::string& distance);

/// whether the layout was repaired: "repaired 12 flipped faces: blend 0.25, mean value
/// interior", "no repair needed" or "repair off"
std::string repair_text(const CGAL::Surface_mesh_parameterization::Parameterization_report& report, bool enabled);

/// the repairs of the atlas's input that change something, for people: "2 points merged, 1
/// polygon re-oriented, 4 polygons triangulated", or "none"
std::string repair_list(const CGAL::Surface_mesh_parameterization::Soup_repair_report& report);

/// the name of a chart's flattening: disk, seamed or unfolded
const char* flattening_name(CGAL::Surface_mesh_parameterization::Chart_flattening f);

/// the charts' bounds and their extreme figures: "bounds: area spread <= 0.2 (largest 0.18), ...,
/// 12 splits" (a chart of one triangle is kept whatever its compactness)
std::string atlas_bounds_text(const CGAL::Surface_mesh_parameterization::Atlas_report& r);

/// the atlas in a few words: "3 charts, utilization 61.2% (1024 texels, gutter 2)"
std::string atlas_charts_text(const Run_facts& facts);

/// the one-line summary of a successful run (the atlas or the single chart)
std::string summary_line(const Run_facts& facts);

} // namespace mbp_cli

#endif // MBP_CLI_SUMMARY_H
