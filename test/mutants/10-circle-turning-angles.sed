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
# breaks: the circle's turning angles: 2 pi l_k / L (the next edge only) instead of pi (l_{k-1} + l_k) / L
s/out.circle\[k\] = CGAL_PI \* (out.lengths\[(k + m - 1) % m\] + out.lengths\[k\]) \/ total;/out.circle[k] = CGAL_PI * (2. * out.lengths[k]) \/ total;/
