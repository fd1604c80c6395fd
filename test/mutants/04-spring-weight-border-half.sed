# file: include/CGAL/Surface_mesh_parameterization/internal/core/laplacian.h
# tests: test_solvers
# breaks: spring weights: a border edge (one face) gets half its weight |x_i - x_j|^-r
s/std::pow(l, -exponent) \* edge_share((\*single_edges)\[f\], 3 - a - b);/std::pow(l, -exponent) * 0.5;/
