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
# The README's test command: what a user runs to know that the package works on their
# machine. CI (.ci/run) runs it first, then the CGAL 6 step (scripts/run_cgal6.sh) and the
# hardening step (scripts/run_hardening.sh), which this command does not run.
#  1. setup: installs what is missing (scripts/setup.sh);
#  2. a user's clone: the tracked files of this checkout (as they are in the working tree) are
#     mirrored into build-ci/main, a folder with nothing beside it (no ../shared), configured
#     in Release and built there: the library's tests, the examples and the command-line
#     program (the benchmarks are not built: they are measurement programs, no test runs them;
#     the CGAL 6 step of CI builds them with every other default target);
#  3. the core tier: every CTest entry of that build; the core tier must pass and the extended
#     tier be reported as skipped, one skipped entry per extended entry, as in a fresh clone;
#  4. the extended tier, when the project's meshes are there (../shared/data/meshes beside this
#     checkout, or MBP_SHARED_MESH_DIR): the extended entries of the same build, run with them;
#     otherwise reported as not run.
# MBP_CI_DIR changes build-ci. Prints the time of every step; exits non-zero when any step or
# any test fails.
set -euo pipefail
cd "$(dirname "$0")/.."
source=$PWD
ci="${MBP_CI_DIR:-build-ci}"
mkdir -p "$ci"
ci="$(cd "$ci" && pwd)"
shared="${MBP_SHARED_MESH_DIR:-$source/../shared/data/meshes}"
jobs="$(nproc)"
start=$(date +%s)
step_start=$start
step() {
  local now
  now=$(date +%s)
  echo "run_tests: $1 ($(( now - step_start )) s; $(( now - start )) s in all)"
  step_start=$now
}

# -- 1. setup ----------------------------------------------------------------------------------
bash scripts/setup.sh
step "setup"

# -- 2. a user's clone: the build --------------------------------------------------------------
clone="$ci/main"
bash scripts/mirror_checkout.sh "$clone"
cmake -S "$clone" -B "$clone/build" -DCMAKE_BUILD_TYPE=Release -DMBP_BUILD_BENCHMARK=OFF
cmake --build "$clone/build" -j"$jobs"
step "build (tests, examples, command line)"

# -- 3. the core tier, the extended tier skipped -----------------------------------------------
env -u MBP_SHARED_MESH_DIR ctest --test-dir "$clone/build" --output-on-failure -j"$jobs" | tee "$ci/ctest-user.log"
skipped=$(grep -c "\*\*\*Skipped" "$ci/ctest-user.log" || true)
extended=$(ctest --test-dir "$clone/build" -N -L extended | sed -n 's/^Total Tests: //p')
core=$(ctest --test-dir "$clone/build" -N -LE extended | sed -n 's/^Total Tests: //p')
if [ "$skipped" != "$extended" ]; then
  echo "run_tests: the user's clone reported $skipped skipped tests, not the $extended of the extended tier" >&2
  exit 1
fi
step "core tier: $core tests passed, the $extended extended tests skipped"

# -- 4. the extended tier ----------------------------------------------------------------------
if [ -f "$shared/PROVENANCE.md" ]; then
  shared="$(cd "$shared" && pwd)"
  MBP_SHARED_MESH_DIR="$shared" ctest --test-dir "$clone/build" --output-on-failure -j"$jobs" -L extended
  step "extended tier: $extended tests passed ($shared)"
  ran_extended=$extended
else
  echo "run_tests: no project meshes at $shared: the extended tier is not run"
  ran_extended=0
fi
echo "run_tests: all passed in $(( $(date +%s) - start )) s"
echo "run_tests: $(( core + ran_extended )) passed, 0 failed, $(( extended - ran_extended )) skipped"
