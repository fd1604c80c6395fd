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
# Behaviour preserved? Compares the command-line program (CMake target
# measured_parameterization_cli) built at REF_COMMIT with the one built from this checkout's
# working tree, on the same meshes and options (issue 21, item 7).
#
#   scripts/compare_outputs.sh [--tolerance=X] [--timeout=S] [--jobs=N] [--out=DIR] REF_COMMIT
#
#  - REF: REF_COMMIT (any name git resolves) is exported with `git archive` into
#    CACHE/ref-<full hash>/src and built there; the build and every REF output are kept, keyed
#    by the full hash (each output also by the program's and the mesh's SHA-1, the arguments
#    and the timeout), so a second run against the same REF neither builds nor runs REF again.
#  - HEAD: the working tree of this checkout AS IT IS (uncommitted and untracked changes
#    included), built incrementally in CACHE/head-<hash of the checkout's path>/build and run
#    again at every call. The summary names HEAD's commit and the number of changed files.
#  - Both are configured with -DMBP_BUILD_TESTS=OFF -DMBP_BUILD_BENCHMARK=OFF -DMBP_BUILD_DOC=OFF
#    and the same MBP_SHARED_MESH_DIR (the program's default mesh), and only the target
#    measured_parameterization_cli is built (found by target name through CMake's file API,
#    wherever its source and its binary are), with --jobs parallel jobs (default 2), which is
#    also the number of runs of the program at a time and of processes of the comparison.
#  - Meshes: the core tier, i.e. every mesh file (.off, .obj, .ply, .stl) of CGAL's data meshes
#    (MBP_CGAL_DATA_ARCHIVE, default Debian's /usr/share/doc/libcgal-dev/data.tar.gz, folder
#    data/meshes, as the top CMakeLists.txt extracts it; here extracted once into
#    CACHE/cgal-data), disks and non-disks, accepted or rejected, and the generated torus
#    examples/data/torus.off; the extended tier, every mesh file of MBP_SHARED_MESH_DIR
#    (default ../shared/data/meshes beside the checkout; skipped with a note when absent).
#  - Option sets, for every mesh: auto (--border=auto), conformal, measured, circle (the
#    --border choices), MBPPP (--border=measured --center=poisson --distance=poisson) and MBPGP
#    (--border=measured --center=geodesic --distance=fast-marching, the geodesic default); every
#    run also has --json and writes out.obj. Two special runs: the program with no INPUT (its
#    default mesh; only --json) and a command-line error (--border=convex, exit status 2).
#  - Every run has a time limit (--timeout, default 120 s; a timeout is its own status).
#  - The comparison (scripts/compare_uv.py; its header says exactly what is compared): per
#    mesh and option set, the exit status and the message class (status, Error_code of the
#    --json error, kinds of the error/warning/note lines of stderr), the 'v' and 'f' lines
#    (count, order, vertex indices), which face corners share a UV (the seams), and the largest
#    UV difference per face corner after the same normalization of both UV sets (each
#    translated and scaled by its own bounding box to [0,1], longest side 1) and raw (relative
#    to REF's bounding box).
#  - Output (--out, default CACHE/report): compare.tsv (one row per mesh and option set,
#    machine-readable), summary.txt (the table printed at the end, with the worst difference),
#    failures.txt; the runs themselves are in CACHE/ref-<hash>/runs and CACHE/head-*/runs.
#
# CACHE is MBP_COMPARE_DIR, default build-compare/ in this checkout (ignored by git: /build*/).
# Environment: MBP_COMPARE_DIR, MBP_SHARED_MESH_DIR, MBP_CGAL_DATA_ARCHIVE, and
# MBP_COMPARE_TOLERANCE (default 1e-10), MBP_COMPARE_TIMEOUT (120), MBP_COMPARE_JOBS (2) as
# defaults of the options.
# Exit status: 0 when every difference is <= the tolerance and no exit status or message class
# changed; 1 otherwise; 2 when the script itself fails (usage, a build).
# Time (2026-11-26, 2 cores shared with other builds, load average 5 to 6): 12 min from an
# empty cache (each build 2 to 2.5 min, 1094 runs 3 to 4 min per side), 3 min when REF is
# cached and HEAD's build up to date. The comparison takes seconds when the OBJs are
# byte-identical, 1 to 3 min when every one must be parsed.
set -euo pipefail

usage() {
  sed -n '/^# Behaviour preserved/,/^# changed; 1 otherwise/p' "$0" | sed 's/^# \{0,1\}//'
}
die() {
  echo "compare_outputs: $*" >&2
  exit 2
}

tolerance="${MBP_COMPARE_TOLERANCE:-1e-10}"
run_timeout="${MBP_COMPARE_TIMEOUT:-120}"
jobs="${MBP_COMPARE_JOBS:-2}"
out=""
ref=""
while [ $# -gt 0 ]; do
  case "$1" in
    --tolerance=*) tolerance="${1#*=}" ;;
    --timeout=*) run_timeout="${1#*=}" ;;
    --jobs=*) jobs="${1#*=}" ;;
    --out=*) out="${1#*=}" ;;
    --tolerance|--timeout|--jobs|--out)
      [ $# -ge 2 ] || die "option $1 needs a value"
      case "$1" in
        --tolerance) tolerance="$2" ;; --timeout) run_timeout="$2" ;; --jobs) jobs="$2" ;; --out) out="$2" ;;
      esac
      shift ;;
    -h|--help) usage; exit 0 ;;
    -*) die "unknown option $1 (see --help)" ;;
    *) [ -z "$ref" ] || die "one REF_COMMIT only (see --help)"; ref="$1" ;;
  esac
  shift
done
[ -n "$ref" ] || { usage >&2; exit 2; }
python3 -c "import sys; x = float(sys.argv[1]); assert x >= 0" "$tolerance" 2>/dev/null ||
  die "bad tolerance '$tolerance'"
[[ "$run_timeout" =~ ^[0-9]+$ ]] && [ "$run_timeout" -gt 0 ] || die "bad timeout '$run_timeout'"
[[ "$jobs" =~ ^[0-9]+$ ]] && [ "$jobs" -gt 0 ] || die "bad --jobs '$jobs'"

cd "$(dirname "$0")/.."
source="$PWD"
scripts="$source/scripts"
start=$(date +%s)
ref_hash=$(git rev-parse --verify --quiet "$ref^{commit}") || die "'$ref' is not a commit of $source"
head_hash=$(git rev-parse HEAD)
changed_files=$(git status --porcelain | wc -l)

cache="${MBP_COMPARE_DIR:-$source/build-compare}"
mkdir -p "$cache"
cache="$(cd "$cache" && pwd)"
out="${out:-$cache/report}"
mkdir -p "$out"
out="$(cd "$out" && pwd)"
shared="${MBP_SHARED_MESH_DIR:-$source/../shared/data/meshes}"
if [ -d "$shared" ]; then shared="$(cd "$shared" && pwd)"; fi
archive="${MBP_CGAL_DATA_ARCHIVE:-/usr/share/doc/libcgal-dev/data.tar.gz}"

elapsed() { echo "$(( $(date +%s) - start )) s"; }
say() { echo "compare_outputs: $* ($(elapsed))"; }

# -- builds ------------------------------------------------------------------------------------
# configure_and_build SOURCE BUILD LOG: configures SOURCE in BUILD, builds the target
# measured_parameterization_cli and prints the path of its binary (CMake's file API).
configure_and_build() {
  local src="$1" build="$2" log="$3"
  mkdir -p "$build/.cmake/api/v1/query"
  touch "$build/.cmake/api/v1/query/codemodel-v2"
  if ! { cmake -S "$src" -B "$build" -DCMAKE_BUILD_TYPE=Release -DMBP_BUILD_TESTS=OFF \
           -DMBP_BUILD_BENCHMARK=OFF -DMBP_BUILD_DOC=OFF -DMBP_SHARED_MESH_DIR="$shared" \
           -DMBP_CGAL_DATA_ARCHIVE="$archive" &&
         cmake --build "$build" --target measured_parameterization_cli -j"$jobs"; } > "$log" 2>&1; then
    tail -n 40 "$log" >&2
    die "the build of $src failed (log: $log)"
  fi
  python3 - "$build" <<'EOF'
import glob, json, os, sys
build = sys.argv[1]
reply = os.path.join(build, ".cmake", "api", "v1", "reply")
index = json.load(open(sorted(glob.glob(os.path.join(reply, "index-*.json")))[-1]))
codemodel = json.load(open(os.path.join(reply, index["reply"]["codemodel-v2"]["jsonFile"])))
for target in codemodel["configurations"][0]["targets"]:
    if target["name"] == "measured_parameterization_cli":
        t = json.load(open(os.path.join(reply, target["jsonFile"])))
        path = t["artifacts"][0]["path"]
        print(path if os.path.isabs(path) else os.path.join(build, path))
        sys.exit(0)
sys.exit("no target measured_parameterization_cli in " + build)
EOF
}

# REF: exported and built once per commit
ref_dir="$cache/ref-$ref_hash"
mkdir -p "$ref_dir"
exec 8> "$ref_dir/lock"
flock 8 || die "cannot lock $ref_dir"
ref_config="MBP_SHARED_MESH_DIR=$shared MBP_CGAL_DATA_ARCHIVE=$archive"
if [ -f "$ref_dir/binary" ] && [ -x "$(cat "$ref_dir/binary")" ] &&
   [ "$(cat "$ref_dir/config" 2>/dev/null)" = "$ref_config" ]; then
  ref_bin="$(cat "$ref_dir/binary")"
  say "REF $ref_hash: cached build $ref_bin"
else
  if [ ! -f "$ref_dir/src/.exported" ]; then
    rm -rf "$ref_dir/src"
    mkdir -p "$ref_dir/src"
    git archive --format=tar "$ref_hash" | tar -x -C "$ref_dir/src"
    touch "$ref_dir/src/.exported"
  fi
  say "REF $ref_hash: building (log: $ref_dir/build.log)"
  ref_bin="$(configure_and_build "$ref_dir/src" "$ref_dir/build" "$ref_dir/build.log")"
  echo "$ref_bin" > "$ref_dir/binary"
  echo "$ref_config" > "$ref_dir/config"
  say "REF built: $ref_bin"
fi

# HEAD: the working tree, built incrementally
head_dir="$cache/head-$(printf '%s' "$source" | sha1sum | cut -c1-12)"
mkdir -p "$head_dir"
exec 9> "$head_dir/lock"
flock 9 || die "cannot lock $head_dir"
say "HEAD (working tree of $source at $head_hash, $changed_files changed files): building (log: $head_dir/build.log)"
head_bin="$(configure_and_build "$source" "$head_dir/build" "$head_dir/build.log")"
say "HEAD built: $head_bin"

# -- meshes ------------------------------------------------------------------------------------
cgal_dir="$cache/cgal-data/data/meshes"
if [ ! -f "$cache/cgal-data/.extracted" ]; then
  [ -f "$archive" ] || die "CGAL's data meshes not found: $archive (Debian package libcgal-demo)"
  rm -rf "$cache/cgal-data"
  mkdir -p "$cache/cgal-data"
  tar -xzf "$archive" -C "$cache/cgal-data" --wildcards 'data/meshes/*'
  touch "$cache/cgal-data/.extracted"
fi

# mesh_files DIR: the mesh files of DIR, one a line, sorted byte-wise
mesh_files() {
  find "$1" -maxdepth 1 -type f \( -iname '*.off' -o -iname '*.obj' -o -iname '*.ply' -o -iname '*.stl' \) \
    -printf '%f\n' | LC_ALL=C sort
}

meshes=()   # "tier<TAB>path"
while IFS= read -r name; do meshes+=("core	$cgal_dir/$name"); done < <(mesh_files "$cgal_dir")
if [ -f "$source/examples/data/torus.off" ]; then
  meshes+=("generated	$source/examples/data/torus.off")
fi
if [ -d "$shared" ]; then
  while IFS= read -r name; do meshes+=("shared	$shared/$name"); done < <(mesh_files "$shared")
else
  echo "compare_outputs: no project meshes at $shared (MBP_SHARED_MESH_DIR): the extended tier is not compared" >&2
fi

option_names=(auto conformal measured circle MBPPP MBPGP)
option_args=("--border=auto" "--border=conformal" "--border=measured" "--border=circle"
             "--border=measured --center=poisson --distance=poisson"
             "--border=measured --center=geodesic --distance=fast-marching")

# the cases, one a line, tab-separated: id, tier, mesh, option set, the arguments after INPUT
# (no spaces inside one), INPUT ('-' for none: read splits on tabs but skips empty fields), the
# OBJ's name, REF's and HEAD's run folders
cases="$out/cases.tsv"
: > "$cases"
add_case() {  # ID TIER MESH OPTIONS ARGS INPUT OBJ
  printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$1" "$2" "$3" "$4" "$5" "$6" "$7" \
    "$ref_dir/runs/$1" "$head_dir/runs/$1" >> "$cases"
}
for entry in "${meshes[@]}"; do
  tier="${entry%%	*}"
  path="${entry#*	}"
  name="$(basename "$path")"
  for k in "${!option_names[@]}"; do
    add_case "$tier/$name/${option_names[$k]}" "$tier" "$name" "${option_names[$k]}" \
      "out.obj --json ${option_args[$k]}" "$path" out.obj
  done
done
add_case "cli/no-input/default" cli "(no INPUT: the default mesh)" default "--json" - "*_uv.obj"
usage_mesh="$cgal_dir/nefertiti.off"
add_case "cli/bad-option/border-convex" cli "(command-line error)" "--border=convex" \
  "out.obj --json --border=convex" "$usage_mesh" out.obj

# -- runs --------------------------------------------------------------------------------------
file_sha() { sha1sum "$1" | cut -c1-40; }

# run_in FOLDER COMMAND...: runs COMMAND in FOLDER (emptied first) under the time limit: its
# stdout, stderr, exit status (rc) and wall time (seconds) in FOLDER
run_in() {
  local folder="$1" rc t0 t1
  shift
  rm -rf "$folder"
  mkdir -p "$folder"
  t0=${EPOCHREALTIME/[.,]/}
  if (cd "$folder" && exec timeout --kill-after=10 "$run_timeout" "$@" > stdout 2> stderr); then rc=0; else rc=$?; fi
  t1=${EPOCHREALTIME/[.,]/}
  echo "$rc" > "$folder/rc"
  printf '%d.%06d\n' $(( (t1 - t0) / 1000000 )) $(( (t1 - t0) % 1000000 )) > "$folder/seconds"
}

# the SHA-1 of every input (in the keys of the cached REF runs)
declare -A mesh_sha
while IFS=$'\t' read -r _ _ _ _ _ input _; do
  if [ "$input" != - ] && [ -z "${mesh_sha[$input]+x}" ]; then mesh_sha[$input]=$(file_sha "$input"); fi
done < "$cases"

# run_worker BINARY SIDE_DIR CACHED W: runs the cases W, W + jobs, W + 2 jobs... of the list and
# writes how many it ran and reused into SIDE_DIR/worker-W; with CACHED=1 a case whose folder
# holds the same key (binary, mesh, arguments, timeout) is not run again
run_worker() {
  local bin="$1" side="$2" cached="$3" w="$4" bin_sha i=0 n=0 reused=0
  local id tier mesh options args input obj refd headd folder key stored sha argv rest
  bin_sha=$(file_sha "$bin")
  while IFS=$'\t' read -r id tier mesh options args input obj refd headd; do
    i=$(( i + 1 ))
    [ $(( (i - 1) % jobs )) -eq "$w" ] || continue
    folder="$side/runs/$id"
    sha="-"
    if [ "$input" != - ]; then sha="${mesh_sha[$input]}"; fi
    key="$bin_sha $sha $run_timeout $args"
    stored=""
    if [ "$cached" = 1 ] && [ -f "$folder/key" ]; then read -r stored < "$folder/key" || true; fi
    if [ "$stored" = "$key" ]; then
      reused=$(( reused + 1 ))
      continue
    fi
    argv=()
    if [ "$input" != - ]; then argv=("$input"); fi
    read -r -a rest <<< "$args"
    run_in "$folder" "$bin" "${argv[@]}" "${rest[@]}"
    echo "$key" > "$folder/key"
    n=$(( n + 1 ))
  done < "$cases"
  echo "$n $reused" > "$side/worker-$w"
}

# run_side LABEL BINARY SIDE_DIR CACHED: every case, by --jobs workers
run_side() {
  local label="$1" bin="$2" side="$3" cached="$4" t0 w pids=() n=0 reused=0 a b
  t0=$(date +%s)
  for (( w = 0; w < jobs; ++w )); do
    rm -f "$side/worker-$w"
    run_worker "$bin" "$side" "$cached" "$w" &
    pids+=($!)
  done
  for w in "${!pids[@]}"; do
    wait "${pids[$w]}" || die "$label: worker $w failed"
    read -r a b < "$side/worker-$w"
    n=$(( n + a ))
    reused=$(( reused + b ))
  done
  echo "$label: $n runs, $reused reused from the cache, $(( $(date +%s) - t0 )) s ($jobs at a time)" >> "$out/timing.txt"
  say "$label: $n runs, $reused reused from the cache ($(( $(date +%s) - t0 )) s, $jobs at a time)"
}

: > "$out/timing.txt"
ncases=$(wc -l < "$cases")
say "$ncases cases: ${#meshes[@]} meshes x ${#option_names[@]} option sets, and 2 special runs"
run_side REF "$ref_bin" "$ref_dir" 1
run_side HEAD "$head_bin" "$head_dir" 0  # every case folder is emptied before its run

# -- comparison --------------------------------------------------------------------------------
{
  echo "compare_outputs: REF  $ref_hash ($(git log -1 --format=%s "$ref_hash" | cut -c1-80))"
  echo "                 HEAD the working tree of $source: commit $head_hash, $changed_files files changed or untracked (git status --porcelain)"
  echo "                 meshes: core $cgal_dir; extended $shared"
  echo "                 tolerance $tolerance, timeout $run_timeout s per run"
  sed 's/^/                 /' "$out/timing.txt"
} > "$out/header.txt"
set +e
python3 "$scripts/compare_uv.py" --cases "$cases" --tolerance "$tolerance" --out "$out" --header "$out/header.txt" \
  --jobs "$jobs"
status=$?
set -e
[ "$status" -le 1 ] || die "the comparison failed (scripts/compare_uv.py, status $status)"
say "done: $out/compare.tsv"
exit "$status"
