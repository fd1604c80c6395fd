// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// The SVG output of the measured_parameterization program (--svg, svg_writer.cpp): the
// picture of svg_layout.h of the run's atlas or layout, with its caption. No CGAL here.

#ifndef MBP_CLI_SVG_WRITER_H
#define MBP_CLI_SVG_WRITER_H

#include "run.h"

#include <string>

namespace mbp_cli {

/// the SVG document of the run
std::string svg_picture(const Run_facts& facts);

} // namespace mbp_cli

#endif // MBP_CLI_SVG_WRITER_H
