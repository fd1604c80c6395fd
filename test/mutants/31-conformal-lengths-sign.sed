# file: include/CGAL/Surface_mesh_parameterization/internal/borders/conformal_border.h
# tests: test_conformal_border
# breaks: the conformal-length member scales the lengths by exp(+t u) (METHOD.md section 8: the family diverges)
s/out\[k\] = lengths\[k\] \* std::exp(-0.5 \* t \* /out[k] = lengths[k] * std::exp(0.5 * t * /
