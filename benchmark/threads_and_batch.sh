#!/bin/bash
# Copyright (c) 2026  The measured boundary parameterization authors.
# All rights reserved.
#
# This file is part of the measured boundary parameterization package for CGAL.
#
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Author(s)     : The measured boundary parameterization authors
#
# BLAS threads and batches (issue 24), measured with the command-line program; builds nothing:
#
#   bash benchmark/threads_and_batch.sh CLI [WORK_DIR] [BASELINE_CLI]
#
# CLI: the program (build/cli/measured_parameterization); WORK_DIR: scratch (default: a new
# temporary folder; the 714k-vertex disk is kept there between runs); BASELINE_CLI: optionally
# the program of an earlier commit (without --threads), timed as "today's default".
#
# 1. The 714k-vertex disk (bimba_i.obj of ../shared/data/meshes refined twice by
#    scripts/refine_mesh.py), --single-chart --solver=cholmod: idle, and beside a busy load
#    of two spinning processes that this script starts and stops (each bounded by `timeout`),
#    with --threads=0 (the BLAS left alone: OpenBLAS's default, a thread per core) against
#    --threads=1 (the default) and --threads=2. Targets: busy <= 2x idle; idle --threads=1 no
#    more than 15% slower than the BLAS's default.
# 2. A batch of every mesh of ../shared/data/meshes and ../shared/data/atlas (the atlas, the
#    program's default mode) with --jobs=1 and --jobs=2: meshes per second. Target: --jobs=2
#    >= 1.8x --jobs=1.
# 3. --shard=1/3, 2/3, 3/3: the union of their outputs against the unsharded run, with cmp.
#    Target: byte-identical.
# The machine's load (uptime) is printed before each part: say it with the figures.
# Environment: REPEATS, BUSY_REPEATS (runs per configuration), BUSY_THREADS (spinning
# processes, default 2), PARTS (default "1 2 3"), CONFIGS (default "--threads=0 --threads=1
# --threads=2").
set -u
if [ $# -lt 1 ] || [ ! -x "$1" ]; then
  echo "usage: bash benchmark/threads_and_batch.sh CLI [WORK_DIR] [BASELINE_CLI]" >&2
  exit 2
fi
CLI=$(realpath "$1")
WORK=${2:-$(mktemp -d /tmp/mbp-threads-batch.XXXXXX)}
BASELINE=${3:-}
HERE=$(cd "$(dirname "$0")/.." && pwd)
DATA=${MBP_SHARED_DATA_DIR:-$HERE/../shared/data}
REPEATS=${REPEATS:-3}
BUSY_REPEATS=${BUSY_REPEATS:-2}
BUSY_THREADS=${BUSY_THREADS:-2}   # the spinning processes of the busy load
PARTS=${PARTS:-"1 2 3"}           # the parts to run
CONFIGS=${CONFIGS:-"--threads=0 --threads=1 --threads=2"}
mkdir -p "$WORK"
cd "$WORK" || exit 2

now() { date +%s.%N; }
elapsed() { echo "$2 - $1" | bc -l | xargs printf "%.2f"; }

# the busy load: two processes spinning, each stopped by timeout after $1 seconds at most
BUSY_PIDS=()
start_busy() {
  for _ in $(seq "$BUSY_THREADS"); do
    timeout "$1" sh -c 'while :; do :; done' &
    BUSY_PIDS+=($!)
  done
  sleep 1
}
stop_busy() {
  for pid in "${BUSY_PIDS[@]}"; do kill "$pid" 2>/dev/null; wait "$pid" 2>/dev/null; done
  BUSY_PIDS=()
}
trap stop_busy EXIT

# one timed run of the 714k disk: PROGRAM ARGS...; prints the seconds
time_disk() {
  local t0 t1
  t0=$(now)
  "$@" "$DISK" disk_uv.obj --single-chart --solver=cholmod > run.log 2>&1 || { echo "failed: $*" >&2; cat run.log >&2; }
  t1=$(now)
  elapsed "$t0" "$t1"
}

# the median of the arguments
median() { printf "%s\n" "$@" | sort -g | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2}'; }

# --- 1. the 714k-vertex disk ------------------------------------------------------------------
part1() {
DISK=$WORK/bimba_714k.obj
if [ ! -s "$DISK" ]; then
  echo "making the 714k-vertex disk: refine_mesh.py bimba_i.obj 2" >&2
  python3 "$HERE/scripts/refine_mesh.py" "$DATA/meshes/bimba_i.obj" 2 "$DISK" >&2 || exit 1
fi
echo "## 714k-vertex disk, --single-chart --solver=cholmod, busy load: $BUSY_THREADS spinning processes"
echo "load before: $(uptime)"
echo
echo "| run | idle (s, each) | idle median | busy (s, each) | busy median | busy / idle |"
echo "|---|---|---|---|---|---|"
read -r -a configs <<< "$CONFIGS"
[ -n "$BASELINE" ] && configs=("baseline" "${configs[@]}")
for config in "${configs[@]}"; do
  if [ "$config" = baseline ]; then cmd=("$BASELINE"); else cmd=("$CLI" "$config"); fi
  idle=(); busy=()
  for _ in $(seq "$REPEATS"); do idle+=("$(time_disk "${cmd[@]}")"); done
  for _ in $(seq "$BUSY_REPEATS"); do
    start_busy 150
    busy+=("$(time_disk "${cmd[@]}")")
    stop_busy
  done
  mi=$(median "${idle[@]}"); mb=$(median "${busy[@]}")
  echo "| $config | ${idle[*]} | $mi | ${busy[*]} | $mb | $(echo "$mb / $mi" | bc -l | xargs printf "%.2f") |"
done
echo
echo "load after: $(uptime)"
}

# --- 2. batch throughput ------------------------------------------------------------------------
part2() {
find "$DATA/meshes" "$DATA/atlas" -maxdepth 1 -type f \
  \( -iname '*.off' -o -iname '*.obj' -o -iname '*.ply' -o -iname '*.stl' \) | sort > all_meshes.txt
count=$(wc -l < all_meshes.txt)
echo
echo "## batch of $count meshes (../shared/data/meshes and ../shared/data/atlas, the atlas)"
echo "load before: $(uptime)"
echo
echo "| jobs | seconds | meshes/s | done | failed |"
echo "|---|---|---|---|---|"
declare -A rate
for jobs in 1 2; do
  rm -rf "batch_j$jobs"
  t0=$(now)
  "$CLI" --batch=all_meshes.txt --output-dir="batch_j$jobs" --jobs=$jobs > "batch_j$jobs.log" 2> "batch_j$jobs.err"
  t1=$(now)
  s=$(elapsed "$t0" "$t1")
  rate[$jobs]=$(echo "$count / $s" | bc -l | xargs printf "%.3f")
  ok=$(grep -c '"status":"OK"' "batch_j$jobs/report.jsonl")
  failed=$(grep -c '"status":"FAILED"' "batch_j$jobs/report.jsonl")
  echo "| $jobs | $s | ${rate[$jobs]} | $ok | $failed |"
done
echo
echo "--jobs=2 / --jobs=1: $(echo "${rate[2]} / ${rate[1]}" | bc -l | xargs printf "%.2f")x meshes/s"
echo "load after: $(uptime)"
}

# --- 3. shards --------------------------------------------------------------------------------
part3() {
[ -f batch_j1/report.jsonl ] || { echo "part 3 needs the --jobs=1 run of part 2" >&2; return 1; }
echo
echo "## shards 1/3, 2/3, 3/3 against the unsharded --jobs=1 run"
rm -rf shards && mkdir shards
for i in 1 2 3; do
  "$CLI" --batch=all_meshes.txt --output-dir=shards --shard=$i/3 --jobs=2 > "shard$i.log" 2>&1
done
same=0; different=0; missing=0
for f in batch_j1/*_uv.obj; do
  g=shards/$(basename "$f")
  if [ ! -f "$g" ]; then missing=$((missing + 1)); elif cmp -s "$f" "$g"; then same=$((same + 1)); else different=$((different + 1)); fi
done
extra=$(comm -13 <(cd batch_j1 && ls *_uv.obj | sort) <(cd shards && ls *_uv.obj | sort) | wc -l)
echo "outputs: $same byte-identical, $different different, $missing missing from the shards, $extra only in the shards"
}

for part in $PARTS; do "part$part"; done
