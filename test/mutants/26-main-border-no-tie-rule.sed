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
# file: include/CGAL/Surface_mesh_parameterization/main_border.h
# tests: test_edges
# breaks: main_border(): no tie rule (rounding picks among loops of equal length)
s/const bool tied = std::abs(l.length - best->length) <= 1e-9 \* longer;/const bool tied = (longer < 0.);/
