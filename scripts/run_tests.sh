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
# Installs what is missing, builds everything in Release, and runs all tests (CTest).
# Exits non-zero when any step or any test fails.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)"
ctest --test-dir build --output-on-failure
# Sanitizer build and tests, and a bounded fuzzing run (scripts/run_hardening.sh).
bash scripts/run_hardening.sh
