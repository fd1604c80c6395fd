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
# breaks: scale normalization: lengths reported to users stay in the patch's unit (not multiplied back)
s/m_length_unit = std::ldexp(1., exponent);/m_length_unit = 1.;/
