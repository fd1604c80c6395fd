# file: include/CGAL/Surface_mesh_parameterization/internal/borders/border_search.h
# tests: test_conformal_border
# breaks: the automatic border tries the conformal-length member only when the conformal layout folds, not when its polygon overlaps itself
s/(folds || evaluator.members().own_blend(CONFORMAL) > 0.)/(folds)/
