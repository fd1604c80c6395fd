# file: include/CGAL/Surface_mesh_parameterization/internal/distances/fast_marching.h
# tests: test_fast_marching
# breaks: fast marching: the obtuse branch is taken for a right angle rounded below 90 degrees (no tolerance)
s/return eb.x() < -obtuse_tolerance() \* eb.norm();/return eb.x() < 0.;/
