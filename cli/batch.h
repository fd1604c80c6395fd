// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// The batch mode of the measured_parameterization program (--batch=FOLDER|LIST|-): many
// inputs to one output folder, each mesh in a worker process that is this program run on that
// one mesh with --json (batch.cpp). No CGAL here.
//
// - The inputs: the .off, .obj, .ply and .stl files of a folder, or the lines of a list file
//   (relative paths: relative to the list's folder) or of stdin; sorted, duplicates removed.
//   --shard=I/N keeps the inputs K (from 0, in that order) with K mod N = I - 1, so that N
//   machines split a data set without talking to each other.
// - The outputs: DIR/<stem>_uv.obj (DIR/<file name>_uv.obj for inputs sharing a stem),
//   written by the worker as a run of one mesh writes them (all or nothing).
// - The report: DIR/report.jsonl (DIR/report-shard-I-of-N.jsonl), one JSON object a line per
//   mesh: {"input", "status" ("OK" or "FAILED"), "outputs", "message", "seconds", "figures"
//   (the worker's --json document, or null)}. A line is appended when its mesh ends (a batch
//   that is interrupted keeps what it did); at the end the file is rewritten with the last
//   line of each mesh, in the order of the input list.
// - Resuming: a mesh whose last report line says OK and whose outputs exist is skipped, unless
//   --force. A failed mesh (an error, a worker killed by a signal) never stops the batch.
// - --jobs=N workers at once, each given the command line's --threads (default 1).

#ifndef MBP_CLI_BATCH_H
#define MBP_CLI_BATCH_H

#include "options.h"

namespace mbp_cli {

/// runs the batch of `options.batch` (`argv`: the command line, whose options of a mode are
/// passed on to the workers). Returns the exit status: 0 when every mesh is done, 1 when one
/// failed or the report cannot be written, 2 when the inputs or the output folder are wrong.
int run_batch(const Options& options, int argc, char** argv);

} // namespace mbp_cli

#endif // MBP_CLI_BATCH_H
