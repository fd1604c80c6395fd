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
# file: include/CGAL/Surface_mesh_parameterization/internal/distances/center_selection.h
# tests: test_distance_maps test_measured_border
# breaks: the center's tie rule: only values exactly equal to the maximum are tied (rounding picks the center)
s/const double threshold = best - center_tie_tolerance \* std::abs(best);/const double threshold = best;/
