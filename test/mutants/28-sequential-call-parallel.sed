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
# tests: test_edges
# breaks: concurrency: a Sequential_tag call lets the patch's multi-column solves use a second thread
s/patch.set_parallel(internal::Is_parallel<Concurrency_tag>::value);/patch.set_parallel(true);/
