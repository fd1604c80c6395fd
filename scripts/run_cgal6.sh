#!/usr/bin/env bash
# Copyright (c) 2026  The measured boundary parameterization authors.
# All rights reserved.
#
# This file is part of the measured boundary parameterization package for CGAL.
#
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Author(s)     : The measured boundary parameterization authors
#
#   bash scripts/run_cgal6.sh [SOURCE [WORK]]
#
# The test suite against CGAL 6: fetches Debian 13's CGAL 6.0 (scripts/fetch_cgal6.sh, into
# WORK/cgal6-prefix), configures SOURCE (default: this checkout) in WORK/cgal6 (default WORK:
# build-ci) with CGAL_DIR pointing into it, builds the tests and the examples with warnings as
# errors (-Werror: a deprecation in CGAL 6 fails), and runs the core tier with CTest (the
# extended tier runs against CGAL 5.5 in scripts/run_tests.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
src="$(cd "${1:-.}" && pwd)"
work="${2:-build-ci}"
mkdir -p "$work"
work="$(cd "$work" && pwd)"
jobs="$(nproc)"

cgal_dir="$(bash scripts/fetch_cgal6.sh "$work/cgal6-prefix" | tail -n 1)"
cmake -S "$src" -B "$work/cgal6" -DCMAKE_BUILD_TYPE=Release "-DCGAL_DIR=$cgal_dir" \
  -DMBP_BUILD_BENCHMARK=OFF -DMBP_BUILD_DOC=OFF "-DCMAKE_CXX_FLAGS=-Werror"
# the package must compile against the unpacked CGAL 6, not the system's CGAL 5.5
include="$(cd "$cgal_dir/../../../.." && pwd)/include"
version="$(sed -n 's/^#define CGAL_VERSION \([0-9.]*\)$/\1/p' "$include/CGAL/version.h")"
case "$version" in
  6.*) echo "run_cgal6: CGAL $version ($include)" ;;
  *) echo "run_cgal6: $include holds CGAL '$version', not CGAL 6" >&2; exit 1 ;;
esac
if ! grep -q -- "-isystem $include" "$work/cgal6/test/CMakeFiles/test_distance_maps.dir/flags.make"; then
  echo "run_cgal6: the build does not use CGAL 6's headers ($include)" >&2
  exit 1
fi
cmake --build "$work/cgal6" -j"$jobs"
ctest --test-dir "$work/cgal6" --output-on-failure -j"$jobs" -LE extended
