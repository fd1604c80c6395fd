# file: include/CGAL/Surface_mesh_parameterization/internal/core/checked_disk.h
# tests: test_robustness
# breaks: disk check: a vertex pinched between two fans is accepted
s/if(around != corners\[i\] || gaps > 1)/if(around != corners[i] || gaps > 2)/
