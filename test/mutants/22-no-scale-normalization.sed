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
# file: include/CGAL/Surface_mesh_parameterization/internal/checked_disk.h
# tests: test_edges
# breaks: scale normalization: positions are not divided by a power of two (squares under- and overflow at extreme scales)
s/const int exponent = std::ilogb(largest);/const int exponent = 0;/
