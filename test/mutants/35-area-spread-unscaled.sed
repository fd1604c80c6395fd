# file: include/CGAL/Surface_mesh_parameterization/internal/core/area_spread.h
# tests: test_conformal_border
# breaks: the area spread is not taken after one scale of the UV areas to the 3D total
s/std::abs(std::log(area_uv\[i\] \/ area3\[i\]) + log_scale)/std::abs(std::log(area_uv[i] \/ area3[i]))/
