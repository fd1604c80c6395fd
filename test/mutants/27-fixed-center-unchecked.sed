# file: include/CGAL/Surface_mesh_parameterization/Fixed_center.h
# tests: test_robustness
# breaks: Fixed_center: a vertex that is not in the mesh is looked up (out-of-bounds read)
s/if(!disk.contains(m_vertex))/if(m_vertex == boost::graph_traits<TriangleMesh>::null_vertex())/
