# file: include/CGAL/Surface_mesh_parameterization/main_border.h
# tests: test_robustness
# breaks: main_border(): no tie rule (rounding picks among loops of equal length)
s/const bool tied = std::abs(l.length - best->length) <= 1e-9 \* longer;/const bool tied = (longer < 0.);/
