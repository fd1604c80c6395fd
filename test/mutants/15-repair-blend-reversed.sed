# file: include/CGAL/Surface_mesh_parameterization/internal/borders/border_members.h
# tests: test_border_search test_validity
# breaks: the measured border's blend toward the circle: the angles move the wrong way (t = 1 keeps the measured angles)
s/a\[k\] = (1. - t) \* angles\[k\] + t \* circle\[k\];/a[k] = t * angles[k] + (1. - t) * circle[k];/
