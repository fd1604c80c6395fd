# file: include/CGAL/Surface_mesh_parameterization/Conformal_parameterizer_3.h
# tests: test_concurrency
# breaks: concurrency: a Sequential_tag call lets the patch's multi-column solves use a second thread
s/Disk disk(m_traits, internal::Is_parallel<Concurrency_tag>::value);/Disk disk(m_traits, true);/
