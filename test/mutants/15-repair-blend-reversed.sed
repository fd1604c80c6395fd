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
# file: include/CGAL/Surface_mesh_parameterization/internal/border_search.h
# tests: test_validity test_conformal test_edges
# breaks: the measured border's blend toward the circle: the angles move the wrong way (t = 1 keeps the measured angles)
s/a\[k\] = (1. - t) \* angles\[k\] + t \* circle\[k\];/a[k] = t * angles[k] + (1. - t) * circle[k];/
