# file: include/CGAL/Surface_mesh_parameterization/Atlas_charts.h
# tests: test_atlas
# breaks: a chart far over the bounds is split in two, not into 1 + ceil(log2 r) parts
s/  const double parts = 1. + std::ceil(std::log2(over));/  const double parts = 2.;/
