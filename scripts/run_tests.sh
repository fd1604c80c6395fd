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
# The test command of the README and of CI (.ci/run). Installs what is missing, then:
#  1. a user's clone: the tracked files of this checkout (as they are in the working tree) are
#     mirrored into build-ci/main, a folder with nothing beside it (no ../shared), built there
#     in Release (everything) and tested by CTest: the core tier must pass, the extended tier
#     is reported as skipped. This is exactly what a fresh clone gets;
#  2. the extended tier, when the project's meshes are there (../shared/data/meshes beside this
#     checkout, or MBP_SHARED_MESH_DIR): the extended tests of the same build, run with them;
#  3. CGAL 6 (scripts/run_cgal6.sh): Debian 13's CGAL 6.0 unpacked into build-ci, the tests
#     and examples built against it (warnings are errors) and the core tier run;
#  4. the hardening checks (scripts/run_hardening.sh): sanitizer build and tests, fuzzing.
# MBP_CI_DIR changes build-ci; MBP_SKIP_CGAL6=1 and MBP_SKIP_HARDENING=1 skip steps 3 and 4.
# Prints the time of every step; exits non-zero when any step or any test fails.
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

bash scripts/setup.sh
step "setup"

# -- 1. a user's clone -------------------------------------------------------------------------
clone="$ci/main"
bash scripts/mirror_checkout.sh "$clone"
cmake -S "$clone" -B "$clone/build" -DCMAKE_BUILD_TYPE=Release
cmake --build "$clone/build" -j"$jobs"
step "user's clone: build"
env -u MBP_SHARED_MESH_DIR ctest --test-dir "$clone/build" --output-on-failure -j"$jobs" | tee "$ci/ctest-user.log"
skipped=$(grep -c "\*\*\*Skipped" "$ci/ctest-user.log" || true)
extended=$(ctest --test-dir "$clone/build" -N -L extended | sed -n 's/^Total Tests: //p')
if [ "$skipped" != "$extended" ]; then
  echo "run_tests: the user's clone reported $skipped skipped tests, not the $extended of the extended tier" >&2
  exit 1
fi
step "user's clone: core tier passed, $skipped extended tests skipped"

# -- 2. the extended tier ----------------------------------------------------------------------
if [ -f "$shared/PROVENANCE.md" ]; then
  shared="$(cd "$shared" && pwd)"
  MBP_SHARED_MESH_DIR="$shared" ctest --test-dir "$clone/build" --output-on-failure -j"$jobs" -L extended
  step "extended tier passed ($shared)"
else
  echo "run_tests: no project meshes at $shared: the extended tier is not run"
fi

# -- 3. CGAL 6 ---------------------------------------------------------------------------------
if [ "${MBP_SKIP_CGAL6:-0}" != 1 ]; then
  bash scripts/run_cgal6.sh "$clone" "$ci"
  step "CGAL 6"
fi

# -- 4. hardening ------------------------------------------------------------------------------
if [ "${MBP_SKIP_HARDENING:-0}" != 1 ]; then
  bash scripts/run_hardening.sh
  step "hardening"
fi
echo "run_tests: all passed ($(( $(date +%s) - start )) s)"
