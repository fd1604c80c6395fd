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
# file: include/CGAL/Surface_mesh_parameterization/Fixed_center.h
# tests: test_edges
# breaks: Fixed_center: a vertex that is not in the mesh is looked up (out-of-bounds read)
s/if(!patch.contains(m_vertex))/if(m_vertex == boost::graph_traits<TriangleMesh>::null_vertex())/
