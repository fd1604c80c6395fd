# file: include/CGAL/Surface_mesh_parameterization/internal/atlas/charts.h
# tests: test_atlas
# breaks: a chart's border may come within a rounding of itself (a T-junction's crack), which the packing can round into an overlap
s/constexpr double chart_clearance = 1e-10;/constexpr double chart_clearance = 0.;/
