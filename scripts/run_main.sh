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
# The main job: installs what is missing, builds in Release (build/), and flattens the
# default mesh with the command-line program, writing build/measured_parameterization.obj
# and build/measured_parameterization.svg and printing the one-line summary.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)" --target measured_parameterization_cli
build/cli/measured_parameterization \
  --output=build/measured_parameterization.obj \
  --svg=build/measured_parameterization.svg
