# file: include/CGAL/Surface_mesh_parameterization/internal/core/laplacian.h
# tests: test_solvers
# breaks: spring exponent: the weights are |x_i - x_j|^-1 whatever r
s/return std::pow(l, -exponent) \*/return std::pow(l, -1.) */
