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
# file: include/CGAL/Surface_mesh_parameterization/internal/borders/polar_map.h
# tests: test_measured_border test_conformal test_scale_invariance
# breaks: CGAL's placement: the shorter side of the bounding box spans [0,1] instead of the longer one
s/const double extent = (std::max)(hi.x() - lo.x(), hi.y() - lo.y());/const double extent = (std::min)(hi.x() - lo.x(), hi.y() - lo.y());/
