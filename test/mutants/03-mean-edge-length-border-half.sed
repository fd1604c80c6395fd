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
# file: include/CGAL/Surface_mesh_parameterization/internal/laplacian.h
# tests: test_edges
# breaks: g_i: a border edge (one face) is counted with weight 1/2 instead of once
s/const double share = edge_share(single_edges\[f\], k);/const double share = 0.5;/
