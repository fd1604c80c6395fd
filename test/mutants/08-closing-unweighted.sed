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
# file: include/CGAL/Surface_mesh_parameterization/internal/borders/conformal_border.h
# tests: test_conformal_border test_border_search
# breaks: conformal border, closing step: T N^-1 T^T assembled without the weights l (the polygon no longer closes with the smallest change)
s/    a += l \* x \* x;/    a += x * x;/
