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
# breaks: spring exponent: the weights are |x_i - x_j|^-1 whatever r
s/return std::pow(l, -exponent) \*/return std::pow(l, -1.) */
