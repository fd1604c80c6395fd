// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// The default mesh of a build of the measured_parameterization program (MBP_DEFAULT_MESH of
// its CMake target): the only file that differs between the program and its variant for
// test_cli.

#include "options.h"

#ifndef MBP_DEFAULT_MESH
#define MBP_DEFAULT_MESH ""
#endif

namespace mbp_cli {

const char* const default_mesh = MBP_DEFAULT_MESH;

} // namespace mbp_cli
