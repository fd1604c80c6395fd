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
# file: include/CGAL/Surface_mesh_parameterization/internal/laplacian.h
# tests: test_edges test_distance_maps test_conformal
# breaks: cotangent weights: the edge (a, b) of a face takes the half cotangent of the angle at corner a instead of the corner opposite the edge
s/return (\*half_cotangents)\[f\]\[static_cast<std::size_t>(3 - a - b)\];/return (*half_cotangents)[f][static_cast<std::size_t>(a)];/
