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
# file: include/CGAL/Surface_mesh_parameterization/internal/conformal_border.h
# tests: test_edges test_conformal_border
# breaks: conformal border blend: t weighs the conformal turning angles and 1 - t the circle's
s/k\[i\] = (1. - t) \* data.turning\[i\] + t \* data.circle\[i\];/k[i] = t * data.turning[i] + (1. - t) * data.circle[i];/
