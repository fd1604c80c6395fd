# file: include/CGAL/Surface_mesh_parameterization/internal/borders/border_reports.h
# tests: test_scale_invariance
# breaks: the measured border's record: polar_scale per unit of the patch's normalized length, while border_distances are in the mesh's unit
s|report.polar_scale = member.polar.scale / disk.length_unit();|report.polar_scale = member.polar.scale;|
