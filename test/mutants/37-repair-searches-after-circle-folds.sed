# file: include/CGAL/Surface_mesh_parameterization/internal/borders/border_search.h
# tests: test_method
# breaks: the repair searches the mean value blends of every member even when the circle's own mean value map folds (rounding), the time of a failed repair on a large atlas chart
s/  if(!search.empty() \&\& !circle_folds)/  if(!search.empty())/
