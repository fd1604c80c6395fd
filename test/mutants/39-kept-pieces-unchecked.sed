# file: include/CGAL/Surface_mesh_parameterization/Atlas_charts.h
# tests: test_atlas
# breaks: a piece of a split chart keeps the chart's map without its own distortion checked against the bounds
s/    if(!within_distortion_bounds(piece, bounds) || !chart_border_is_clear(t, piece))/    if(!chart_border_is_clear(t, piece))/
