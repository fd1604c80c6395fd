# file: include/CGAL/Surface_mesh_parameterization/Border_parameterizer_3.h
# tests: test_concurrency
# breaks: a Sequential_tag call of the drop-in border parameterizer builds a parallel disk (threads in its multi-column solves)
s/const bool parallel = internal::Is_parallel<ConcurrencyTag_>::value;/const bool parallel = true;/
