# file: include/CGAL/Surface_mesh_parameterization/internal/core/laplacian.h
# tests: test_solvers
# breaks: g_i: a border edge (one face) is counted with weight 1/2 instead of once
s/const double share = edge_share(single_edges\[f\], k);/const double share = 0.5;/
