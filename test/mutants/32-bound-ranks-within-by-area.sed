# file: include/CGAL/Surface_mesh_parameterization/Distortion_bound.h
# tests: test_conformal_border
# breaks: within the bound the layouts are ranked by area spread, not by angle distortion (not conformal where they can be)
s/      return angle \/ (1\. + angle);/      return area \/ (1. + area);/
