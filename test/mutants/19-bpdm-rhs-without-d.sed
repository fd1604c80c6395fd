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
# file: include/CGAL/Surface_mesh_parameterization/internal/poisson_distance.h
# tests: test_distance_maps test_edges
# breaks: boundary Poisson distance map: right-hand side g_i instead of d_i g_i
/boundary_poisson_distance(Patch/,/return OK;/ s/rhs\[r\] = d\[i\] \* g\[i\];/rhs[r] = g[i];/
