# file: include/CGAL/Surface_mesh_parameterization/internal/core/checked_disk.h
# tests: test_scale_invariance
# breaks: scale normalization: lengths reported to users stay in the patch's unit (not multiplied back)
s/m_length_unit = std::ldexp(1., exponent);/m_length_unit = 1.;/
