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
# file: include/CGAL/Surface_mesh_parameterization/internal/border_family.h
# tests: test_edges test_conformal
# breaks: the automatic border's search: a valid blend moves the lower end of the bracket up (bisection the wrong way)
s/(trials\[i\].valid ? valid\[i\] : invalid\[i\]) = batch\[i\].second;/(trials[i].valid ? invalid[i] : valid[i]) = batch[i].second;/
