# file: include/CGAL/Surface_mesh_parameterization/Distortion_bound.h
# tests: test_conformal_border
# breaks: outside the bound angle and area are added, not multiplied (a little area can buy much angle)
s/ratio(angle, max_angle_distortion) \* ratio(area, max_area_spread)/ratio(angle, max_angle_distortion) + ratio(area, max_area_spread)/
