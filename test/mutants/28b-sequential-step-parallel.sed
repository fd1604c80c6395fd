# file: include/CGAL/Surface_mesh_parameterization/Conformal_parameterizer_3.h
# tests: test_concurrency
# breaks: a Sequential_tag call of the complete parameterizer gives its border step a parallel flag (the distance preparation in a second thread)
s/internal::Border_step<Disk> step(disk, r, internal::Is_parallel<Concurrency_tag>::value, true);/internal::Border_step<Disk> step(disk, r, true, true);/
