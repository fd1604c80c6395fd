# file: include/CGAL/Surface_mesh_parameterization/internal/borders/conformal_border.h
# tests: test_border_search
# breaks: conformal border blend: t weighs the conformal turning angles and 1 - t the circle's
s/k\[i\] = (1. - t) \* data.turning\[i\] + t \* data.circle\[i\];/k[i] = t * data.turning[i] + (1. - t) * data.circle[i];/
