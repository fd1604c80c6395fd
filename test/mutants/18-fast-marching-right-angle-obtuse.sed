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
# file: include/CGAL/Surface_mesh_parameterization/internal/fast_marching.h
# tests: test_edges test_fast_marching
# breaks: fast marching: the obtuse branch is taken for a right angle rounded below 90 degrees (no tolerance)
s/return eb.x() < -obtuse_tolerance() \* eb.norm();/return eb.x() < 0.;/
