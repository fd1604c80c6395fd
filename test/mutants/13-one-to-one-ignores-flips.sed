# file: include/CGAL/Surface_mesh_parameterization/internal/core/validity.h
# tests: test_validity
# breaks: the one-to-one test: a flipped face is not counted
s/exact_point(uv\[static_cast<std::size_t>(t\[2\])\])) != CGAL::LEFT_TURN)/exact_point(uv[static_cast<std::size_t>(t[2])])) != CGAL::LEFT_TURN \&\& false)/
