// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// The one-line summary of a run, and the texts that name the border kept and the repair (also
// in the OBJ header and the SVG caption), read from the plain data of the run and the
// library's report (summary.cpp). No CGAL here but the report's header.

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

/// the one-line summary of a successful run
std::string summary_line(const Run_facts& facts);

} // namespace mbp_cli

#endif // MBP_CLI_SUMMARY_H
