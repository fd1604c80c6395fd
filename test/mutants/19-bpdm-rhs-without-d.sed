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
# file: include/CGAL/Surface_mesh_parameterization/internal/distances/poisson_distance.h
# tests: test_distance_maps
# breaks: boundary Poisson distance map: right-hand side g_i instead of d_i g_i
s/system->solve_scattered(poisson_right_hand_side(disk.cotangent_row_sums(), disk.mean_spoke_lengths()), values)/system->solve_scattered(disk.mean_spoke_lengths(), values)/
