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
# breaks: disk check: a vertex pinched between two fans is accepted
s/if(around != corners\[i\] || gaps > 1)/if(around != corners[i] || gaps > 2)/
