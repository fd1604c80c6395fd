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
# Installs what this package needs on Debian 12 (bookworm) and nothing that is already there.
# Used by the README commands and by .ci/run. Runs apt-get through sudo when not root.
#
#   bash scripts/setup.sh              # library, tests, examples, command line, benchmarks
#   bash scripts/setup.sh --hardening  # and Clang's sanitizers and libFuzzer (scripts/run_hardening.sh)
#
set -euo pipefail

packages=(
  g++ make cmake pkg-config
  libcgal-dev            # CGAL >= 5.5 (header-only)
  libcgal-demo           # CGAL's data meshes (/usr/share/doc/libcgal-dev/data.tar.gz), test fallback
  libeigen3-dev          # Eigen 3.4
  libgmp-dev libmpfr-dev # CGAL's exact number types
  libboost-dev libboost-graph-dev libboost-test-dev
  libsuitesparse-dev     # CHOLMOD's supernodal Cholesky (optional solver)
  libopenblas-dev        # a multithreaded BLAS for CHOLMOD
  doxygen                # the HTML reference manual (doc/)
  librsvg2-bin           # rsvg-convert: the manual's SVG figures to PNG
)
if [ "${1:-}" = --hardening ]; then
  packages+=(clang libclang-rt-14-dev)  # the libFuzzer target and the sanitizer build (clang 14)
fi

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${db:Status-Status}' "$p" 2>/dev/null || true)
  [ "$status" = "installed" ] || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all dependencies already installed"
  exit 0
fi

echo "setup: installing ${missing[*]}"
if [ "$(id -u)" -eq 0 ]; then SUDO=(); else SUDO=(sudo); fi
export DEBIAN_FRONTEND=noninteractive
"${SUDO[@]}" apt-get update -qq
"${SUDO[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
echo "setup: done"
