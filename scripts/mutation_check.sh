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
# Mutation check of the test suite (not part of CI's default run: it builds test suites once
# per mutant). Each mutant is a one-line change of a header, kept as a sed script in
# test/mutants/NN-name.sed with three comment lines:
#     # file: PATH           the header it changes (relative to the repository)
#     # tests: SUITE...      the test suites that should kill it, most likely killer first
#     # breaks: TEXT         what the change breaks
# The script:
#  1. exports the committed tree (git archive HEAD; MBP_MUTATION_SOURCE=worktree copies the
#     working tree's tracked files instead) into a scratch directory outside the repository
#     (the repository's own files are never changed), and configures one Release build there;
#  2. builds and runs every suite the mutants name on the unchanged code (each must pass);
#  3. for each mutant: applies it to the scratch copy (it must change exactly one line),
#     then builds and runs its suites one at a time, core tier only, stopping at the first
#     that fails (a failed check, a crash, a timeout, or a build error: the mutant is
#     killed); restores the header;
#  4. prints the table of killed and surviving mutants (also written to
#     SCRATCH/mutation_table.md).
# Usage: scripts/mutation_check.sh [test/mutants/NN-name.sed ...]   (default: all mutants)
# Environment: MBP_MUTATION_DIR (scratch, default /tmp/mbp-mutation-$USER), MBP_JOBS (make
# jobs, default 2), MBP_MUTATION_TIMEOUT (seconds per suite run, default 900),
# MBP_MUTATION_SOURCE (head | worktree, default head), MBP_MUTATION_KEEP=1 (keep the scratch
# build for a later run, which then recompiles only what changed).
# Exit status: 0 when every mutant was killed, 1 when one survived, 2 on an error (a mutant
# that does not apply, a suite that fails on the unchanged code).
set -uo pipefail

repo="$(cd "$(dirname "$0")/.." && pwd)"
scratch="${MBP_MUTATION_DIR:-/tmp/mbp-mutation-${USER:-user}}"
jobs="${MBP_JOBS:-2}"
timeout_s="${MBP_MUTATION_TIMEOUT:-900}"
source_mode="${MBP_MUTATION_SOURCE:-head}"
src="$scratch/src"
build="$scratch/build"
log="$scratch/log"
table="$scratch/mutation_table.md"

case "$scratch" in
  "$repo"|"$repo"/*) echo "mutation_check: the scratch directory must be outside the repository" >&2; exit 2 ;;
esac

if [ "$#" -gt 0 ]; then mutants=("$@"); else mutants=("$repo"/test/mutants/*.sed); fi

field() { sed -n "s/^# $2: //p" "$1" | head -n 1; }

# -- 1. scratch copy and configure ------------------------------------------------------------
# The sources are exported afresh, then copied over the previous scratch copy file by file
# where they differ, so that a kept build (MBP_MUTATION_KEEP=1) recompiles only what changed.
mkdir -p "$scratch" "$log"
export_dir="$scratch/export"
rm -rf "$export_dir"
mkdir -p "$export_dir" "$src"
if [ "$source_mode" = worktree ]; then
  (cd "$repo" && git ls-files -z | xargs -0 cp --parents -t "$export_dir")
else
  git -C "$repo" archive --format=tar HEAD | tar -x -C "$export_dir"
fi
(cd "$export_dir" && find . -type f -print0) | while IFS= read -r -d '' f; do
  if ! cmp -s "$export_dir/$f" "$src/$f"; then
    mkdir -p "$(dirname "$src/$f")"
    cp "$export_dir/$f" "$src/$f"
  fi
done
(cd "$src" && find . -type f -print0) | while IFS= read -r -d '' f; do
  [ -e "$export_dir/$f" ] || rm -f "$src/$f"
done
rm -rf "$export_dir"
echo "mutation_check: sources ($source_mode) in $src, build in $build"
cmake -S "$src" -B "$build" -DCMAKE_BUILD_TYPE=Release -DMBP_BUILD_DOC=OFF -DMBP_BUILD_BENCHMARK=OFF \
      -DMBP_BUILD_EXAMPLES=OFF > "$log/configure.txt" 2>&1 || { echo "configure failed: $log/configure.txt" >&2; exit 2; }

# the test executable that holds a suite: the one CTest's entry test_SUITE runs (read from
# the build's CTestTestfile.cmake; test/CMakeLists.txt groups several suites in one executable)
suite_executable() {  # CTest entry
  sed -n "s|^add_test($1 \"\\([^\"]*\\)\".*|\\1|p" "$build/test/CTestTestfile.cmake" | head -n 1
}

# build the executable of one suite, then run the suite's core tier; prints "pass", "fail",
# "crash", "timeout" or "build"
run_suite() {  # CTest entry test_SUITE, log file
  local exe
  exe="$(suite_executable "$1")"
  if [ -z "$exe" ] || ! cmake --build "$build" --target "$(basename "$exe")" -j"$jobs" > "$2.build.txt" 2>&1; then
    echo build
    return
  fi
  # the suite's name in Boost.Test is the entry's name without test_ (test_cli runs the suite
  # cli of test_command_line)
  (cd "$build/test" && timeout "$timeout_s" "$exe" "--run_test=${1#test_}" "--run_test=!@extended" \
     --log_level=error --report_level=short) > "$2.run.txt" 2>&1
  local rc=$?
  # Boost.Test exits with 201 (a failed check) or 200 (an exception); 128 + N is signal N
  if [ $rc -eq 0 ]; then echo pass
  elif [ $rc -eq 124 ]; then echo timeout
  elif [ $rc -gt 128 ] && [ $rc -lt 200 ]; then echo crash
  else echo fail
  fi
}

# -- 2. the unchanged code ----------------------------------------------------------------------
suites=()
for m in "${mutants[@]}"; do
  for s in $(field "$m" tests); do
    case " ${suites[*]-} " in *" $s "*) ;; *) suites+=("$s") ;; esac
  done
done
for s in "${suites[@]}"; do
  result="$(run_suite "$s" "$log/baseline-$s")"
  echo "mutation_check: unchanged code, $s: $result"
  if [ "$result" != pass ]; then
    echo "mutation_check: $s does not pass on the unchanged code (see $log/baseline-$s.*)" >&2
    exit 2
  fi
done

# -- 3. the mutants -------------------------------------------------------------------------------
printf '| mutant | header | what it breaks | result | killed by |\n|---|---|---|---|---|\n' > "$table"
killed=0 survived=0 errors=0
for m in "${mutants[@]}"; do
  name="$(basename "$m" .sed)"
  file="$(field "$m" file)"
  breaks="$(field "$m" breaks)"
  target="$src/$file"
  if [ -z "$file" ] || [ ! -f "$target" ]; then
    echo "mutation_check: $name: no header '$file'" >&2
    printf '| %s | `%s` | %s | **error: no such header** | |\n' "$name" "$file" "$breaks" >> "$table"
    errors=$((errors + 1))
    continue
  fi
  cp -p "$target" "$scratch/original"
  sed -i -f "$m" "$target"
  changed="$(diff "$scratch/original" "$target" | grep -c '^<')"
  if [ "$changed" != 1 ]; then
    echo "mutation_check: $name changes $changed lines of $file (it must change one): not run" >&2
    cp -p "$scratch/original" "$target"
    printf '| %s | `%s` | %s | **error: changes %s lines** | |\n' "$name" "$file" "$breaks" "$changed" >> "$table"
    errors=$((errors + 1))
    continue
  fi
  touch "$target"
  verdict=survived
  by=""
  for s in $(field "$m" tests); do
    result="$(run_suite "$s" "$log/$name-$s")"
    echo "mutation_check: $name, $s: $result"
    if [ "$result" != pass ]; then
      verdict=killed
      by="$s ($result)"
      break
    fi
  done
  cp "$scratch/original" "$target"
  touch "$target"  # newer than the mutant's objects: the next build compiles again
  if [ "$verdict" = killed ]; then killed=$((killed + 1)); else survived=$((survived + 1)); fi
  printf '| %s | `%s` | %s | %s | %s |\n' "$name" "${file#include/CGAL/Surface_mesh_parameterization/}" "$breaks" \
    "$verdict" "$by" >> "$table"
done
printf '\n%d mutants: %d killed, %d survived, %d not run.\n' "${#mutants[@]}" "$killed" "$survived" "$errors" >> "$table"

# -- 4. the table ---------------------------------------------------------------------------------
cat "$table"
if [ "${MBP_MUTATION_KEEP:-0}" != 1 ]; then rm -rf "$build"; fi
if [ "$errors" -gt 0 ]; then exit 2; fi
if [ "$survived" -gt 0 ]; then exit 1; fi
exit 0
