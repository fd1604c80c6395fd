# file: include/CGAL/Surface_mesh_parameterization/internal/core/checked_disk.h
# tests: test_scale_invariance
# breaks: scale normalization: positions are not divided by a power of two (squares under- and overflow at extreme scales)
s/const int exponent = std::ilogb(largest);/const int exponent = 0;/
