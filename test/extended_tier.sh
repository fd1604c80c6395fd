#!/bin/sh
# Copyright (c) 2026  The measured boundary parameterization authors.
# All rights reserved.
#
# This file is part of the measured boundary parameterization package for CGAL.
#
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Author(s)     : The measured boundary parameterization authors
#
# extended_tier.sh MESH_DIR PROGRAM [ARGS...]
#
# Runs PROGRAM ARGS, a test of the extended tier, when the project's meshes are there: in
# MESH_DIR (the configured MBP_SHARED_MESH_DIR), or in the folder named by the environment
# variable MBP_SHARED_MESH_DIR, which takes precedence (then every argument equal to MESH_DIR
# is replaced by it). Without them it exits 77, which CTest reports as skipped
# (SKIP_RETURN_CODE, set by mbp_add_extended_test() in the top CMakeLists.txt).
configured="$1"
shift
dir="${MBP_SHARED_MESH_DIR:-$configured}"
if [ ! -f "$dir/PROVENANCE.md" ]; then
  echo "extended tier skipped: the project's meshes are not in '$dir' (MBP_SHARED_MESH_DIR)"
  exit 77
fi
export MBP_SHARED_MESH_DIR="$dir"
program="$1"
shift
for arg in "$@"; do
  shift
  if [ "$arg" = "$configured" ]; then set -- "$@" "$dir"; else set -- "$@" "$arg"; fi
done
exec "$program" "$@"
