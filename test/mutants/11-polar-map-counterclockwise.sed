# Copyright (c) 2026  The measured boundary parameterization authors.
# All rights reserved.
#
# This file is part of the measured boundary parameterization package for CGAL.
#
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Author(s)     : The measured boundary parameterization authors
#
# A one-line mutant for scripts/mutation_check.sh (sed script).
# file: include/CGAL/Surface_mesh_parameterization/internal/borders/polar_map.h
# tests: test_measured_border test_scale_invariance
# breaks: polar map orientation: border vertex k at angle +phi_k (counterclockwise) instead of -phi_k
s/radii\[k\] \* std::sin(-angles\[k\])/radii[k] * std::sin(angles[k])/
