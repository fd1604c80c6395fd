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
# CI's CGAL 6 step (.ci/run, after the README's test command): a CGAL 6 user's default build.
# Fetches Debian 13's CGAL 6.0 (scripts/fetch_cgal6.sh, into WORK/cgal6-prefix), configures
# SOURCE (default: this checkout) in WORK/cgal6 (default WORK: build-ci) in the default
# configuration (every option at its default but two: the precompiled headers off, so that
# every source must include what it uses; the tests and the examples at the build type's -O3,
# not -O1: at -O1 GCC 12 warns -Wmaybe-uninitialized about the default value T() of CGAL 6's
# get(dynamic_vertex_property_t<Point_2>, mesh), a Point_2 whose coordinates are left
# uninitialized by design, which -Werror would turn into a failure) with CGAL_DIR pointing into it and warnings as errors (-Werror: a
# deprecation in CGAL 6 fails), builds every default target (the library's tests, the
# examples, the command-line program and the benchmarks: a header that CGAL 5.5 pulled in
# transitively and CGAL 6 does not fails here), and runs the core tier with CTest
# (the extended tier runs against CGAL 5.5 in scripts/run_tests.sh; the Doxygen check, which
# does not depend on CGAL, too). Prints the time of each part.
set -euo pipefail
cd "$(dirname "$0")/.."
src="$(cd "${1:-.}" && pwd)"
work="${2:-build-ci}"
mkdir -p "$work"
work="$(cd "$work" && pwd)"
jobs="$(nproc)"
start=$(date +%s)
elapsed() { echo "$(( $(date +%s) - start )) s"; }

cgal_dir="$(bash scripts/fetch_cgal6.sh "$work/cgal6-prefix" | tail -n 1)"
# the default configuration, whatever an earlier run left in the cache (the objects are kept)
rm -f "$work/cgal6/CMakeCache.txt"
cmake -S "$src" -B "$work/cgal6" -DCMAKE_BUILD_TYPE=Release "-DCGAL_DIR=$cgal_dir" \
  "-DCMAKE_CXX_FLAGS=-Werror" -DMBP_PRECOMPILED_HEADERS=OFF -DMBP_TEST_OPTIMIZATION=
# the package must compile against the unpacked CGAL 6, not the system's CGAL 5.5
include="$(cd "$cgal_dir/../../../.." && pwd)/include"
version="$(sed -n 's/^#define CGAL_VERSION \([0-9.]*\)$/\1/p' "$include/CGAL/version.h")"
case "$version" in
  6.*) echo "run_cgal6: CGAL $version ($include)" ;;
  *) echo "run_cgal6: $include holds CGAL '$version', not CGAL 6" >&2; exit 1 ;;
esac
if ! grep -q -- "-isystem $include" "$work/cgal6/test/CMakeFiles/test_distances.dir/flags.make"; then
  echo "run_cgal6: the build does not use CGAL 6's headers ($include)" >&2
  exit 1
fi
echo "run_cgal6: configured ($(elapsed))"
cmake --build "$work/cgal6" -j"$jobs"
echo "run_cgal6: every default target built against CGAL $version ($(elapsed))"
ctest --test-dir "$work/cgal6" --output-on-failure -j"$jobs" -LE "extended|doc"
echo "run_cgal6: core tier passed against CGAL $version ($(elapsed))"
