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

// The split of a chart that misses the distortion bound (Atlas_options): two regions grown
// from two seeds over the chart's faces, each face to the region that reaches it at the lower
// cost (ties: fewer steps from the seed). The cost is a distance between per-face features:
// the unit normal (Atlas_split SPLIT_BY_NORMALS) or the log of the map's area scale
// (SPLIT_BY_SCALE). When the chart has sharp edges, its faces are first grouped into smooth
// patches (joined across edges of dihedral angle below 30 degrees) that move together, so
// that a flat or smooth face of a CAD part is never cut. Written here because no library
// segments a face set this way (CGAL's Surface_mesh_segmentation splits by shape diameter,
// not by a distortion feature, and not in two).

#include <CGAL/Surface_mesh_parameterization/Atlas_report.h>
#include <CGAL/Surface_mesh_parameterization/internal/atlas/charts.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/union_find.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <queue>
#include <tuple>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// The nodes a split moves whole (smooth patches, or single faces) and their adjacency (CSR).
struct Split_graph
{
  std::vector<std::size_t> node_of;      // per face of the subset
  std::vector<std::size_t> offsets, adjacent;
  std::vector<Eigen::Vector3d> feature;  // per node: the area-weighted mean of its faces'
  std::size_t nodes = 0;
};

// The per-face features of a subset: unit normals, or (x) the log area scale of the chart's map.
inline std::vector<Eigen::Vector3d> face_features(const Atlas_triangles& t, const std::vector<std::size_t>& faces,
                                                  const Atlas_chart* map, std::vector<double>& area)
{
  std::vector<Eigen::Vector3d> feature(faces.size(), Eigen::Vector3d::Zero());
  area.assign(faces.size(), 0.);
  for(std::size_t i = 0; i < faces.size(); ++i)
  {
    const Face_indices& v = t.faces[faces[i]];
    const Eigen::Vector3d n = (t.points[std::size_t(v[1])] - t.points[std::size_t(v[0])])
                                .cross(t.points[std::size_t(v[2])] - t.points[std::size_t(v[0])]);
    area[i] = 0.5 * n.norm();
    if(!(area[i] > 0.))
      continue;
    if(map == nullptr)
    {
      feature[i] = n / n.norm();
      continue;
    }
    const Eigen::Vector2d e = map->corners[i][1] - map->corners[i][0], g = map->corners[i][2] - map->corners[i][0];
    const double uv_area = 0.5 * std::abs(e.x() * g.y() - e.y() * g.x());
    if(uv_area > 0.)
      feature[i].x() = std::log(uv_area / area[i]);
  }
  return feature;
}

// Groups the faces into smooth patches (one node per face when there is one patch) and
// gives each node the area-weighted mean feature of its faces.
inline Split_graph split_graph(const std::vector<std::array<int, 3> >& neighbors, const std::vector<Eigen::Vector3d>& normal,
                               const std::vector<Eigen::Vector3d>& feature, const std::vector<double>& area)
{
  const double cos_sharp = std::cos(CGAL_PI / 6.);
  Union_find patches(neighbors.size());
  for(std::size_t f = 0; f < neighbors.size(); ++f)
    for(int g : neighbors[f])
      if(g >= 0 && normal[f].dot(normal[std::size_t(g)]) >= cos_sharp)
        patches.unite(f, std::size_t(g));
  Split_graph s;
  s.node_of.assign(neighbors.size(), neighbors.size());
  std::vector<std::size_t> root_node(neighbors.size(), neighbors.size());
  for(std::size_t f = 0; f < neighbors.size(); ++f)
  {
    std::size_t& node = root_node[patches.find(f)];
    if(node == neighbors.size())
      node = s.nodes++;
    s.node_of[f] = node;
  }
  if(s.nodes == 1)  // one smooth patch: its faces move one by one
  {
    s.nodes = neighbors.size();
    for(std::size_t f = 0; f < neighbors.size(); ++f)
      s.node_of[f] = f;
  }
  s.feature.assign(s.nodes, Eigen::Vector3d::Zero());
  std::vector<double> weight(s.nodes, 0.);
  std::vector<std::pair<std::size_t, std::size_t> > links;
  for(std::size_t f = 0; f < neighbors.size(); ++f)
  {
    s.feature[s.node_of[f]] += area[f] * feature[f];
    weight[s.node_of[f]] += area[f];
    for(int g : neighbors[f])
      if(g >= 0 && s.node_of[std::size_t(g)] != s.node_of[f])
        links.emplace_back(s.node_of[f], s.node_of[std::size_t(g)]);
  }
  for(std::size_t n = 0; n < s.nodes; ++n)
    if(weight[n] > 0.)
      s.feature[n] /= weight[n];
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

// The distance between two features: 1 - cos of the angle between normals, or the difference
// of log scales.
inline double feature_distance(Atlas_split split, const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  if(split == SPLIT_BY_SCALE)
    return std::abs(a.x() - b.x());
  const double na = a.norm(), nb = b.norm();
  return (na > 0. && nb > 0.) ? 1. - a.dot(b) / (na * nb) : 1.;
}

// The node farthest (by feature) from `from`; ties to the lowest index.
inline std::size_t farthest_node(Atlas_split split, const Split_graph& s, const Eigen::Vector3d& from)
{
  std::size_t best = 0;
  for(std::size_t n = 1; n < s.nodes; ++n)
    if(feature_distance(split, s.feature[n], from) > feature_distance(split, s.feature[best], from))
      best = n;
  return best;
}

// The side (0 or 1) of each node: two regions grown from seeds a and b, best first.
inline std::vector<int> grow_two_regions(Atlas_split split, const Split_graph& s, std::size_t a, std::size_t b)
{
  typedef std::tuple<double, std::size_t, std::size_t, int> Step;  // cost, steps, node, side
  std::priority_queue<Step, std::vector<Step>, std::greater<Step> > queue;
  std::vector<int> side(s.nodes, -1);
  queue.emplace(0., 0, a, 0);
  queue.emplace(0., 0, b, 1);
  const std::array<std::size_t, 2> seed = {{a, b}};
  while(!queue.empty())
  {
    const Step step = queue.top();
    queue.pop();
    const std::size_t node = std::get<2>(step);
    const int region = std::get<3>(step);
    if(side[node] >= 0)
      continue;
    side[node] = region;
    for(std::size_t i = s.offsets[node]; i < s.offsets[node + 1]; ++i)
      if(side[s.adjacent[i]] < 0)
        queue.emplace(feature_distance(split, s.feature[s.adjacent[i]], s.feature[seed[std::size_t(region)]]),
                      std::get<1>(step) + 1, s.adjacent[i], region);
  }
  return side;
}

// The seeds: the node farthest from the mean feature and the node farthest from it; when all
// features agree, the node farthest in steps.
inline std::array<std::size_t, 2> split_seeds(Atlas_split split, const Split_graph& s)
{
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for(const Eigen::Vector3d& f : s.feature)
    mean += f / double(s.nodes);
  const std::size_t a = farthest_node(split, s, mean);
  std::size_t b = farthest_node(split, s, s.feature[a]);
  if(feature_distance(split, s.feature[b], s.feature[a]) <= 0.)  // the last node reached breadth first
  {
    std::vector<std::size_t> queue(1, a);
    std::vector<char> seen(s.nodes, 0);
    seen[a] = 1;
    for(std::size_t q = 0; q < queue.size(); ++q)
      for(std::size_t i = s.offsets[queue[q]]; i < s.offsets[queue[q] + 1]; ++i)
        if(!seen[s.adjacent[i]])
        {
          seen[s.adjacent[i]] = 1;
          queue.push_back(s.adjacent[i]);
        }
    b = queue.back();
  }
  return {{a, b}};
}

// A connected face subset that misses the bound split in two; `map` is its one-to-one map
// (SPLIT_BY_SCALE), or null when it has none (the normals are used then). Input polygons are
// kept whole (parts_keeping_polygons()); the caller splits each part into its components.
inline std::array<std::vector<std::size_t>, 2> split_for_bound(const Atlas_triangles& t, const std::vector<std::size_t>& faces,
                                                              Atlas_split split, const Atlas_chart* map)
{
  if(map == nullptr)
    split = SPLIT_BY_NORMALS;
  std::vector<double> area;
  const std::vector<Eigen::Vector3d> normal = face_features(t, faces, nullptr, area);
  const std::vector<Eigen::Vector3d> feature = (split == SPLIT_BY_SCALE) ? face_features(t, faces, map, area) : normal;
  const Split_graph s = split_graph(subset_neighbors(t, faces), normal, feature, area);
  const std::array<std::size_t, 2> seed = split_seeds(split, s);
  const std::vector<int> node_side = grow_two_regions(split, s, seed[0], seed[1]);
  std::vector<int> side(faces.size());
  for(std::size_t i = 0; i < faces.size(); ++i)
    side[i] = std::max(node_side[s.node_of[i]], 0);
  const std::vector<int> part = parts_keeping_polygons(t, faces, side);
  std::array<std::vector<std::size_t>, 2> parts;
  for(std::size_t i = 0; i < faces.size(); ++i)
    parts[std::size_t(part[i])].push_back(faces[i]);
  return parts;
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_ATLAS_CHART_SPLIT_H
