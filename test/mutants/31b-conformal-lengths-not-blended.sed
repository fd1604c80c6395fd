# file: include/CGAL/Surface_mesh_parameterization/internal/borders/conformal_border.h
# tests: test_conformal_border
# breaks: the conformal-length member's scale factors do not grow with the blend (t = 0 is not the conformal border)
s/out\[k\] = lengths\[k\] \* std::exp(-0.5 \* t \* /out[k] = lengths[k] * std::exp(-0.5 * /
