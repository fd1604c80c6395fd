# file: include/CGAL/Surface_mesh_parameterization/internal/distances/poisson_distance.h
# tests: test_solvers
# breaks: Poisson distance map from sources: right-hand side g_i instead of d_i g_i
s/status = engine->solve_scattered(poisson_right_hand_side(engine->row_sums(), disk.mean_spoke_lengths()), values);/status = engine->solve_scattered(disk.mean_spoke_lengths(), values);/
