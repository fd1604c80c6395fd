// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// The OBJ output of the measured_parameterization program (obj_writer.cpp), with a header of
// comments. The atlas: the input's points ('v', all of them, in input order), one UV per
// polygon corner ('vt', in polygon order), the input's polygons in their order ('f v/vt ...')
// and a group 'g chart_K' wherever the chart changes. A single chart: the input vertices that
// are in a face ('v'), the UVs ('vt': one per vertex, or one per side of a seam), the faces
// 'f v/vt'. No CGAL here.

#ifndef MBP_CLI_OBJ_WRITER_H
#define MBP_CLI_OBJ_WRITER_H

#include "file_output.h"
#include "run.h"

namespace mbp_cli {

/// writes the OBJ file of the run into `out`
void write_obj(Buffered_writer& out, const Run_facts& facts);

} // namespace mbp_cli

#endif // MBP_CLI_OBJ_WRITER_H
