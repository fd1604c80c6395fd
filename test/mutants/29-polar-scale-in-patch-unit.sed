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
# file: include/CGAL/Surface_mesh_parameterization/Measured_border_parameterizer_3.h
# tests: test_edges test_measured_border
# breaks: the measured border's record: polar_scale per unit of the patch's normalized length, while border_distances are in the mesh's unit
s|record.polar_scale = polar.scale / patch.length_unit();|record.polar_scale = polar.scale;|
