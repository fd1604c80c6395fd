# file: include/CGAL/Surface_mesh_parameterization/internal/atlas/chart_split.h
# tests: test_atlas
# breaks: a chart that misses only the compactness is cut near the low end of its box instead of the middle (a sliver and the rest), so a long strip is peeled a little at a time
s/> 1\.5 \* (low + high);/> 3. * low + 1e-9 * (high - low);/
