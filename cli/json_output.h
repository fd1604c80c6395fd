// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// The JSON output of the measured_parameterization program (--json), the one serializer of
// both documents: a failed run, and a successful run, whose sections read the plain data of
// the run and the library's report (json_output.cpp). No CGAL here but the report's header.

#ifndef MBP_CLI_JSON_OUTPUT_H
#define MBP_CLI_JSON_OUTPUT_H

#include "run.h"

#include <string>

namespace mbp_cli {

/// the document of a failed run, {"error": MESSAGE, "code": STATUS, "error_code": N}: STATUS is
/// the exit status (1: the input cannot be parameterized or an output cannot be written; 2: a
/// command-line error), N the library's `Error_code` when the failure is one (null otherwise,
/// `error_code` 0)
std::string json_failure(const std::string& message, int status, int error_code);

/// the document of a successful run: "mode" ("atlas" or "single-chart") first, then for the
/// atlas the input, the repairs, the charts, the utilization, the distortion and the times;
/// for a single chart the border, the mesh, the times, the solver's work and the distortion
std::string json_document(const Run_facts& facts);

} // namespace mbp_cli

#endif // MBP_CLI_JSON_OUTPUT_H
