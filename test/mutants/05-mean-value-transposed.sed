# file: include/CGAL/Surface_mesh_parameterization/internal/core/laplacian.h
# tests: test_solvers
# breaks: Laplacian assembly: a non-symmetric Laplacian (mean value weights) is assembled transposed
s/if constexpr(!Weight::symmetric)/if constexpr(false)/
