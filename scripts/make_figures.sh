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
# Regenerates the documentation figures in doc/Surface_mesh_parameterization/fig/:
# configures and builds the figure program (doc/figures/make_figures.cpp) in build-fig/,
# runs it on the project's meshes (../shared/data/meshes, or MESH_DIR), and turns each
# composite SVG into a PNG with rsvg-convert. figures.md there lists every figure with its
# numbers.
#
#   scripts/make_figures.sh [MESH_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
mesh_dir="${1:-../shared/data/meshes}"
fig_dir="doc/Surface_mesh_parameterization/fig"
build_dir="build-fig"
work_dir="$build_dir/figures"
zoom=1.5          # the 3D views are rendered for this zoom
if ! command -v rsvg-convert > /dev/null; then
  echo "error: rsvg-convert is needed (Debian: apt-get install librsvg2-bin)" >&2
  exit 1
fi
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DMBP_BUILD_FIGURES=ON \
  -DMBP_BUILD_TESTS=OFF -DMBP_BUILD_EXAMPLES=OFF -DMBP_BUILD_BENCHMARK=OFF -DMBP_BUILD_DOC=OFF > /dev/null
cmake --build "$build_dir" -j2 --target make_figures
rm -rf "$work_dir"
"$build_dir/doc/figures/make_figures" "$mesh_dir" "$fig_dir" "$work_dir" --zoom="$zoom"
for svg in "$work_dir"/*.svg; do
  name="$(basename "${svg%.svg}")"
  z="$zoom"
  # Fig. 9 holds twenty panels, four of them a 62k-face layout: a lower resolution keeps the file small
  if [ "$name" = fig9_domains ]; then z=1.0; fi
  rsvg-convert --zoom="$z" "$svg" -o "$fig_dir/$name.png"
  echo "wrote $fig_dir/$name.png ($(( $(stat -c %s "$fig_dir/$name.png") / 1024 )) KiB)"
done
