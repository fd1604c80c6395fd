// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_ATLAS_CHART_SPLIT_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_ATLAS_CHART_SPLIT_H

// The split of a chart that misses the distortion bound (Atlas_options): each face goes to the
// nearest of two or more seeds (a weighted Voronoi split, by Dijkstra's algorithm over the
// faces; seeds past the first two are the faces farthest from the seeds so far). A
// step between two adjacent faces costs the change of a feature plus the distance of their
// centroids over the square root of the chart's area: the angle between their normals
// (Atlas_split SPLIT_BY_NORMALS: the seeds are the two faces farthest apart in this distance,
// so that the cut falls where the surface turns the most between them) or the difference of
// the log area scale of the chart's map (SPLIT_BY_SCALE: the seeds are the faces of the
// smallest and the largest scale, so that the cut falls between the extremes). When the chart
// has sharp edges, its faces are first grouped into smooth patches (joined across edges of
// dihedral angle below 30 degrees) that move together, so that a flat or smooth face of a CAD
// part is never cut. Written here because no library segments a face set this way (CGAL's
// Surface_mesh_segmentation splits by shape diameter, not by a distortion feature).

#include <CGAL/Surface_mesh_parameterization/Atlas_report.h>
#include <CGAL/Surface_mesh_parameterization/internal/atlas/charts.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/union_find.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <numeric>
#include <queue>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// Per face of a subset: its area, centroid, unit normal and split feature (the normal, or in
// x the log area scale of the chart's map).
struct Split_faces
{
  std::vector<double> area;
  std::vector<Eigen::Vector3d> centroid, normal, feature;
};

inline Split_faces split_faces(const Atlas_triangles& t, const std::vector<std::size_t>& faces, const Atlas_chart* map)
{
  Split_faces d;
  d.area.assign(faces.size(), 0.);
  d.centroid.assign(faces.size(), Eigen::Vector3d::Zero());
  d.normal = d.feature = d.centroid;
  for(std::size_t i = 0; i < faces.size(); ++i)
  {
    const Face_indices& v = t.faces[faces[i]];
    const Eigen::Vector3d& a = t.points[std::size_t(v[0])], b = t.points[std::size_t(v[1])], c = t.points[std::size_t(v[2])];
    const Eigen::Vector3d n = (b - a).cross(c - a);
    d.area[i] = 0.5 * n.norm();
    d.centroid[i] = (a + b + c) / 3.;
    if(!(d.area[i] > 0.))
      continue;
    d.normal[i] = n / n.norm();
    d.feature[i] = d.normal[i];
    if(map == nullptr)
      continue;
    const Eigen::Vector2d e = map->corners[i][1] - map->corners[i][0], g = map->corners[i][2] - map->corners[i][0];
    const double uv_area = 0.5 * std::abs(e.x() * g.y() - e.y() * g.x());
    d.feature[i] = Eigen::Vector3d((uv_area > 0.) ? std::log(uv_area / d.area[i]) : 0., 0., 0.);
  }
  return d;
}

// The nodes a split moves whole (smooth patches, or single faces), their adjacency (CSR) and
// their area-weighted mean features and centroids.
struct Split_graph
{
  std::vector<std::size_t> node_of;  // per face of the subset
  std::vector<std::size_t> offsets, adjacent;
  std::vector<Eigen::Vector3d> feature, centroid;
  double length = 1.;                // the unit of the centroids' distances: sqrt(area)
  std::size_t nodes = 0;
};

// The node of each face: its smooth patch when the subset has sharp edges, itself otherwise
// or when its patch holds half the area or more (a patch that big must itself be split, and
// keeping it whole would only peel small patches off it, one split at a time).
inline std::size_t group_into_patches(const std::vector<std::array<int, 3> >& neighbors, const Split_faces& d,
                                      std::vector<std::size_t>& node_of)
{
  const double cos_sharp = std::cos(CGAL_PI / 6.);
  Union_find patches(neighbors.size());
  for(std::size_t f = 0; f < neighbors.size(); ++f)
    for(int g : neighbors[f])
      if(g >= 0 && d.normal[f].dot(d.normal[std::size_t(g)]) >= cos_sharp)
        patches.unite(f, std::size_t(g));
  std::vector<double> patch_area(neighbors.size(), 0.);
  double area = 0.;
  for(std::size_t f = 0; f < neighbors.size(); ++f)
  {
    patch_area[patches.find(f)] += d.area[f];
    area += d.area[f];
  }
  std::vector<std::size_t> root_node(neighbors.size(), neighbors.size());
  std::size_t nodes = 0;
  node_of.assign(neighbors.size(), 0);
  for(std::size_t f = 0; f < neighbors.size(); ++f)
  {
    const std::size_t root = patches.find(f);
    if(patch_area[root] >= 0.5 * area)
    {
      node_of[f] = nodes++;
      continue;
    }
    std::size_t& node = root_node[root];
    if(node == neighbors.size())
      node = nodes++;
    node_of[f] = node;
  }
  return nodes;
}

inline Split_graph split_graph(const std::vector<std::array<int, 3> >& neighbors, const Split_faces& d)
{
  Split_graph s;
  s.nodes = group_into_patches(neighbors, d, s.node_of);
  s.feature.assign(s.nodes, Eigen::Vector3d::Zero());
  s.centroid = s.feature;
  std::vector<double> weight(s.nodes, 0.);
  std::vector<std::pair<std::size_t, std::size_t> > links;
  for(std::size_t f = 0; f < neighbors.size(); ++f)
  {
    const std::size_t n = s.node_of[f];
    s.feature[n] += d.area[f] * d.feature[f];
    s.centroid[n] += d.area[f] * d.centroid[f];
    weight[n] += d.area[f];
    for(int g : neighbors[f])
      if(g >= 0 && s.node_of[std::size_t(g)] != n)
        links.emplace_back(n, s.node_of[std::size_t(g)]);
  }
  double area = 0.;
  for(std::size_t n = 0; n < s.nodes; ++n)
    if(weight[n] > 0.)
    {
      s.feature[n] /= weight[n];
      s.centroid[n] /= weight[n];
      area += weight[n];
    }
  s.length = (area > 0.) ? std::sqrt(area) : 1.;
  std::sort(links.begin(), links.end());
  links.erase(std::unique(links.begin(), links.end()), links.end());
  s.offsets.assign(s.nodes + 1, 0);
  for(const auto& l : links)
    ++s.offsets[l.first + 1];
  for(std::size_t n = 0; n < s.nodes; ++n)
    s.offsets[n + 1] += s.offsets[n];
  for(const auto& l : links)
    s.adjacent.push_back(l.second);
  return s;
}

// The cost of a step between adjacent nodes: the change of the feature (the angle between the
// normals, or the difference of log scales) plus the distance of the centroids over sqrt(area).
inline double step_cost(Atlas_split split, const Split_graph& s, std::size_t a, std::size_t b)
{
  const Eigen::Vector3d& fa = s.feature[a];
  const Eigen::Vector3d& fb = s.feature[b];
  const double na = fa.norm(), nb = fb.norm();
  const double change = (split == SPLIT_BY_SCALE) ? std::abs(fa.x() - fb.x())
                        : (na > 0. && nb > 0.)    ? std::acos((std::max)(-1., (std::min)(1., fa.dot(fb) / (na * nb))))
                                                  : 0.;
  return change + (s.centroid[a] - s.centroid[b]).norm() / s.length;
}

// The cost of every step (step_cost()), per entry of `s.adjacent`: computed once, as each
// Dijkstra run of a split crosses every link.
inline std::vector<double> step_costs(Atlas_split split, const Split_graph& s)
{
  std::vector<double> cost(s.adjacent.size());
  for(std::size_t n = 0; n < s.nodes; ++n)
    for(std::size_t i = s.offsets[n]; i < s.offsets[n + 1]; ++i)
      cost[i] = step_cost(split, s, n, s.adjacent[i]);
  return cost;
}

typedef std::pair<double, std::size_t> Split_step;
typedef std::priority_queue<Split_step, std::vector<Split_step>, std::greater<Split_step> > Split_queue;

// Dijkstra's algorithm from the nodes in `queue` (`cost`: step_costs()): lowers `distance`
// (to the nearest seed) and `nearest` (that seed) wherever a path from them is shorter.
inline void relax_seed_distances(const Split_graph& s, const std::vector<double>& cost, Split_queue& queue,
                                 std::vector<double>& distance, std::vector<int>& nearest)
{
  while(!queue.empty())
  {
    const Split_step step = queue.top();
    queue.pop();
    if(step.first > distance[step.second])
      continue;
    for(std::size_t i = s.offsets[step.second]; i < s.offsets[step.second + 1]; ++i)
    {
      const std::size_t next = s.adjacent[i];
      const double d = step.first + cost[i];
      if(d < distance[next])
      {
        distance[next] = d;
        nearest[next] = nearest[step.second];
        queue.emplace(d, next);
      }
    }
  }
}

// Adds the seed `seed` (the index-th) to the distances to the nearest seed: only the nodes it
// brings nearer are visited.
inline void add_seed(const Split_graph& s, const std::vector<double>& cost, std::size_t seed, int index,
                     std::vector<double>& distance, std::vector<int>& nearest)
{
  if(nearest[seed] >= 0 && !(distance[seed] > 0.))
    return;  // a seed already
  Split_queue queue;
  distance[seed] = 0.;
  nearest[seed] = index;
  queue.emplace(0., seed);
  relax_seed_distances(s, cost, queue, distance, nearest);
}

// Dijkstra's algorithm from `seeds`: the distance of each node to the nearest seed, and which
// seed that is (`nearest`).
inline std::vector<double> seed_distances(const Split_graph& s, const std::vector<double>& cost,
                                          const std::vector<std::size_t>& seeds, std::vector<int>& nearest)
{
  std::vector<double> distance(s.nodes, std::numeric_limits<double>::infinity());
  nearest.assign(s.nodes, -1);
  for(std::size_t i = 0; i < seeds.size(); ++i)
    add_seed(s, cost, seeds[i], int(i), distance, nearest);
  return distance;
}

// The seeds of a split into `count` (>= 2) parts: the nodes of the smallest and the largest
// scale, or (normals) the node farthest from any node; then, while fewer than `count`, the
// node farthest from the seeds so far (each added with add_seed(): it visits only the nodes it
// takes), so that the first two are far apart. `nearest` gets each node's seed.
inline std::vector<std::size_t> split_seeds(Atlas_split split, const Split_graph& s, std::size_t count,
                                            std::vector<int>& nearest)
{
  auto farthest = [](const std::vector<double>& d) { return std::size_t(std::max_element(d.begin(), d.end()) - d.begin()); };
  std::vector<std::size_t> seeds;
  if(split == SPLIT_BY_SCALE)
  {
    auto by_scale = [&s](std::size_t a, std::size_t b) { return s.feature[a].x() < s.feature[b].x(); };
    std::vector<std::size_t> order(s.nodes);
    std::iota(order.begin(), order.end(), std::size_t(0));
    const auto extremes = std::minmax_element(order.begin(), order.end(), by_scale);
    if(*extremes.first != *extremes.second)
      seeds = {*extremes.first, *extremes.second};
  }
  const std::vector<double> cost = step_costs(seeds.empty() ? SPLIT_BY_NORMALS : split, s);
  if(seeds.empty())
    seeds.push_back(farthest(seed_distances(s, cost, {0}, nearest)));
  std::vector<double> distance = seed_distances(s, cost, seeds, nearest);
  while(seeds.size() < (std::min)(count, s.nodes))
  {
    seeds.push_back(farthest(distance));
    add_seed(s, cost, seeds.back(), int(seeds.size() - 1), distance, nearest);
  }
  return seeds;
}

// The parts (0 to count - 1, per face) of the split of a connected face subset that misses
// the bound, each face with its nearest seed (split_seeds()); `map` is its one-to-one map
// (SPLIT_BY_SCALE), or null when it has none (the normals are used then). Input polygons are
// kept whole (parts_keeping_polygons()).
inline std::vector<int> split_sides(const Atlas_triangles& t, const std::vector<std::size_t>& faces,
                                    const std::vector<std::array<int, 3> >& neighbors, Atlas_split split,
                                    const Atlas_chart* map, std::size_t count = 2)
{
  if(map == nullptr)
    split = SPLIT_BY_NORMALS;
  const Split_faces d = split_faces(t, faces, split == SPLIT_BY_SCALE ? map : nullptr);
  const Split_graph s = split_graph(neighbors, d);
  std::vector<int> node_side;
  split_seeds(split, s, count, node_side);
  std::vector<int> side(faces.size());
  for(std::size_t i = 0; i < faces.size(); ++i)
    side[i] = std::max(node_side[s.node_of[i]], 0);
  return parts_keeping_polygons(t, faces, side);
}

// The two parts of that split (split_sides()); the caller splits each into its components.
inline std::array<std::vector<std::size_t>, 2> split_for_bound(const Atlas_triangles& t, const std::vector<std::size_t>& faces,
                                                              const std::vector<std::array<int, 3> >& neighbors,
                                                              Atlas_split split, const Atlas_chart* map)
{
  const std::vector<int> side = split_sides(t, faces, neighbors, split, map);
  std::array<std::vector<std::size_t>, 2> parts;
  for(std::size_t i = 0; i < faces.size(); ++i)
    parts[std::size_t(side[i])].push_back(faces[i]);
  return parts;
}

// Whether face i of a chart and its neighbor g across the edge opposite corner k of i
// (subset_neighbors()) give that edge's two ends the same UVs: the edge is no seam of the map.
inline bool shares_uv_edge(const Atlas_triangles& t, const Atlas_chart& chart, std::size_t i, int k, std::size_t g)
{
  const Face_indices& vi = t.faces[chart.faces[i]];
  const Face_indices& vg = t.faces[chart.faces[g]];
  for(int e : {(k + 1) % 3, (k + 2) % 3})
  {
    const std::size_t kg = std::size_t(std::find(vg.begin(), vg.end(), vi[std::size_t(e)]) - vg.begin());
    if(kg == 3 || chart.corners[g][kg] != chart.corners[i][std::size_t(e)])
      return false;
  }
  return true;
}

// The UV islands of a chart within each part (`part`: per face): faces of one part joined
// across the edges (`neighbors`: subset_neighbors() of the chart's faces) whose two ends have
// the same UVs on both sides; each island a chart that keeps its faces' UVs, in the order of
// their first faces; `island_part`, when given, gets the part of each island.
inline std::vector<Atlas_chart> uv_islands(const Atlas_triangles& t, const Atlas_chart& chart, const std::vector<int>& part,
                                           const std::vector<std::array<int, 3> >& neighbors,
                                           std::vector<int>* island_part = nullptr)
{
  Union_find islands(chart.faces.size());
  for(std::size_t i = 0; i < chart.faces.size(); ++i)
    for(int k = 0; k < 3; ++k)
    {
      const int g = neighbors[i][std::size_t(k)];
      if(g > int(i) && part[i] == part[std::size_t(g)] && shares_uv_edge(t, chart, i, k, std::size_t(g)))
        islands.unite(i, std::size_t(g));
    }
  std::vector<std::size_t> piece_of(chart.faces.size(), chart.faces.size());
  std::vector<Atlas_chart> pieces;
  for(std::size_t i = 0; i < chart.faces.size(); ++i)
  {
    std::size_t& piece = piece_of[islands.find(i)];
    if(piece == chart.faces.size())
    {
      piece = pieces.size();
      pieces.emplace_back();
      pieces.back().flattening = chart.flattening;
      if(island_part != nullptr)
        island_part->push_back(part[i]);
    }
    pieces[piece].faces.push_back(chart.faces[i]);
    pieces[piece].corners.push_back(chart.corners[i]);
  }
  return pieces;
}

// A one-to-one chart cut across the longer side of its smallest bounding box (`chart.box`,
// chart_compactness()), at the box's middle (each face goes to the side of its UV centroid;
// input polygons are kept whole), each piece one UV island (its faces joined across the edges
// whose two ends keep their UVs). A piece keeps its faces' UVs: a part of a one-to-one map is
// one-to-one with the same distortion, so nothing is flattened again, and a long strip becomes
// two of half its length. Two pieces at least for a chart of two faces or more
// (parts_keeping_polygons()).
inline std::vector<Atlas_chart> cut_across(const Atlas_triangles& t, const Atlas_chart& chart)
{
  double low = HUGE_VAL, high = -HUGE_VAL;
  for(const std::array<Eigen::Vector2d, 3>& c : chart.corners)
    for(const Eigen::Vector2d& p : c)
    {
      low = (std::min)(low, chart.box.rotate(p).x());
      high = (std::max)(high, chart.box.rotate(p).x());
    }
  std::vector<int> side(chart.faces.size());
  for(std::size_t i = 0; i < chart.faces.size(); ++i)
    side[i] = chart.box.rotate(chart.corners[i][0] + chart.corners[i][1] + chart.corners[i][2]).x() > 1.5 * (low + high);
  return uv_islands(t, chart, parts_keeping_polygons(t, chart.faces, side), subset_neighbors(t, chart.faces));
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_ATLAS_CHART_SPLIT_H
