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
# file: include/CGAL/Surface_mesh_parameterization/measure_quality.h
# tests: test_edges
# breaks: measure_quality: the 3D positions are not scaled by a power of two (figures wrong at extreme scales)
s/exponent3 = largest_exponent(p);/exponent3 = 0;/
