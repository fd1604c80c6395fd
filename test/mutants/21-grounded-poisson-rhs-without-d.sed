# file: include/CGAL/Surface_mesh_parameterization/internal/core/disk_systems.h
# tests: test_solvers
# breaks: the paper's border distance (grounded spring system): right-hand side g_i instead of d_i g_i
s/f\[i\] = d\[i\] \* g\[i\];/f[i] = g[i];/
