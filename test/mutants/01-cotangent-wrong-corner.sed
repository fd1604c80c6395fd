# file: include/CGAL/Surface_mesh_parameterization/internal/core/laplacian.h
# tests: test_border_search test_solvers test_robustness test_scale_invariance
# breaks: cotangent weights: the edge (a, b) of a face takes the half cotangent of the angle at corner a instead of the corner opposite the edge
s/return (\*half_cotangents)\[f\]\[static_cast<std::size_t>(3 - a - b)\];/return (*half_cotangents)[f][static_cast<std::size_t>(a)];/
