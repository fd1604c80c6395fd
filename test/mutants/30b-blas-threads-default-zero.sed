# file: include/CGAL/Surface_mesh_parameterization/Cholmod_supernodal_cholesky_traits.h
# tests: test_concurrency
# breaks: BLAS threads: the CHOLMOD traits' default leaves the BLAS alone instead of one thread
s/explicit Cholmod_supernodal_cholesky_traits(Ordering ordering = AMD, int blas_threads = 1)/explicit Cholmod_supernodal_cholesky_traits(Ordering ordering = AMD, int blas_threads = 0)/
