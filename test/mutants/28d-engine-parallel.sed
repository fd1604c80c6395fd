# file: include/CGAL/Surface_mesh_parameterization/internal/core/disk_systems.h
# tests: test_concurrency
# breaks: every engine of a disk is built parallel whatever the concurrency tag
s/e->set_parallel(m_parallel);/e->set_parallel(true);/
