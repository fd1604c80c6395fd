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
# file: include/CGAL/Surface_mesh_parameterization/Parameterization_patch_3.h
# tests: test_edges test_conformal
# breaks: the paper's border distance (grounded spring system): right-hand side g_i instead of d_i g_i
s/const double b = (i == source) ? 0. : d\[i\] \* g\[i\];/const double b = (i == source) ? 0. : g[i];/
