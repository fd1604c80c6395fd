# file: include/CGAL/Surface_mesh_parameterization/internal/borders/conformal_border.h
# tests: test_border_search
# breaks: the circle's turning angles: 2 pi l_k / L (the next edge only) instead of pi (l_{k-1} + l_k) / L
s/out.circle\[k\] = CGAL_PI \* (out.lengths\[(k + m - 1) % m\] + out.lengths\[k\]) \/ total;/out.circle[k] = CGAL_PI * (2. * out.lengths[k]) \/ total;/
