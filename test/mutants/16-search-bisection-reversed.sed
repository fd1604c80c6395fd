# file: include/CGAL/Surface_mesh_parameterization/internal/borders/border_search.h
# tests: test_border_search
# breaks: the automatic border's search: a valid blend moves the lower end of the bracket up (bisection the wrong way)
s/(trials\[i\].valid ? valid\[i\] : invalid\[i\]) = batch\[i\].second;/(trials[i].valid ? invalid[i] : valid[i]) = batch[i].second;/
