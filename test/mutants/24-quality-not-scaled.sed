# file: include/CGAL/Surface_mesh_parameterization/measure_quality.h
# tests: test_scale_invariance
# breaks: measure_quality: the 3D positions are not scaled by a power of two (figures wrong at extreme scales)
s/exponent3 = largest_exponent(p);/exponent3 = 0;/
