# file: include/CGAL/Surface_mesh_parameterization/internal/core/laplacian.h
# tests: test_solvers
# breaks: mean value weights: tan(alpha / 4) instead of tan(alpha / 2)
s/return std::tan(0.5 \* alpha) \/ u.norm();/return std::tan(0.25 * alpha) \/ u.norm();/
