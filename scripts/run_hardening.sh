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
# CI's hardening step (.ci/run, after the README's test command and the CGAL 6 step; can be
# run alone):
#  1. the test suite, the examples and the command-line program built with Clang, AddressSanitizer and
#     UndefinedBehaviorSanitizer (-O1, every finding fatal) in build-asan/, and the core tier of
#     the tests run by CTest (MBP_HARDENING_EXTENDED=1: the extended tier too);
#  2. the libFuzzer target over the command-line program's input path (test/fuzz), run for
#     at most MBP_FUZZ_SECONDS (default 180; MBP_FUZZ_RUNS runs, default 100000) on a scratch copy of the seed corpus (test/fuzz/corpus is
#     not modified). A crash, a sanitizer finding, a leak, a timeout or an out-of-memory is a
#     failure; the input that caused it is kept in build-asan/fuzz-artifacts/.
# Exits non-zero when any step fails. Needs clang and libclang-rt-14-dev (installed here by
# scripts/setup.sh --hardening).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh --hardening

build=build-asan
fuzz_seconds="${MBP_FUZZ_SECONDS:-180}"
jobs="$(nproc)"
start=$(date +%s)
elapsed() { echo "$(( $(date +%s) - start )) s"; }

export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:strict_string_checks=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"

# -- 1. sanitizer build and tests ------------------------------------------------------------
# -O1 keeps the instrumented build and the tests fast; assertions stay on (no NDEBUG). No
# precompiled headers: every translation unit is instrumented from its own sources.
# The benchmarks are not built (measurement programs: the CGAL 6 step builds them); the
# examples and the command-line program are (test_cli runs it).
echo "hardening: ASan+UBSan build in $build"
cmake -S . -B "$build" \
  -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -gline-tables-only" \
  -DMBP_SANITIZERS=address,undefined \
  -DMBP_BUILD_TESTS=ON -DMBP_BUILD_EXAMPLES=ON -DMBP_BUILD_BENCHMARK=OFF \
  -DMBP_BUILD_FUZZERS=ON -DMBP_PRECOMPILED_HEADERS=OFF
cmake --build "$build" -j"$jobs"
echo "hardening: build done ($(elapsed))"
# a test slower than 15 min under the sanitizers is reported as a failure (a hang). The core
# tier only (generated meshes and CGAL's data meshes: every code path of the package); the
# extended tier runs in Release (scripts/run_tests.sh). MBP_HARDENING_EXTENDED=1 adds it here.
tiers=(-LE extended)
if [ "${MBP_HARDENING_EXTENDED:-0}" = 1 ]; then tiers=(); fi
ctest --test-dir "$build" --output-on-failure -j"$jobs" --timeout 900 "${tiers[@]}"
echo "hardening: sanitizer tests passed ($(elapsed))"

# -- 2. bounded fuzzing ----------------------------------------------------------------------
if [ "$fuzz_seconds" -le 0 ]; then
  echo "hardening: fuzzing skipped (MBP_FUZZ_SECONDS=$fuzz_seconds; the corpus ran in CTest)"
  exit 0
fi
fuzzer="$build/test/fuzz/fuzz_mesh_input"
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT
cp test/fuzz/corpus/* "$scratch/"
artifacts="$build/fuzz-artifacts/"
mkdir -p "$artifacts"
echo "hardening: fuzzing for $fuzz_seconds s on a copy of test/fuzz/corpus"
# one worker (the machine is shared); inputs up to 8 KiB; an input slower than 30 s is a hang
# A fixed seed and a fixed number of runs (about a minute here) make the run reproducible: the
# same sources give the same inputs, so a CI result can be replayed; MBP_FUZZ_SEED and
# MBP_FUZZ_RUNS explore further. MBP_FUZZ_SECONDS caps the time.
if ! "$fuzzer" -seed="${MBP_FUZZ_SEED:-1}" -runs="${MBP_FUZZ_RUNS:-100000}" -max_total_time="$fuzz_seconds" -timeout=30 -rss_limit_mb=2048 -max_len=8192 \
                -print_final_stats=1 -artifact_prefix="$artifacts" "$scratch" 2> "$build/fuzz.log"; then
  tail -n 60 "$build/fuzz.log"
  echo "hardening: FAILED: the fuzzer found a crash; reproducer(s) in $artifacts:" >&2
  ls -l "$artifacts" >&2
  exit 1
fi
grep -E "^stat::number_of_executed_units|^stat::peak_rss_mb|^#[0-9]+.*DONE" "$build/fuzz.log" || true
echo "hardening: fuzzing found nothing ($(elapsed) in all)"
