# file: include/CGAL/Surface_mesh_parameterization/internal/atlas/chart_split.h
# tests: test_atlas
# breaks: the seeds past the first two of a split into more parts are not the faces farthest from the seeds so far
s/    seeds.push_back(farthest(seeds, split));/    seeds.push_back(farthest({seeds[0]}, split));/
