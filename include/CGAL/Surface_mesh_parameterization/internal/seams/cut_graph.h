// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_SEAMS_CUT_GRAPH_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_SEAMS_CUT_GRAPH_H

// Cut graphs on an indexed manifold triangle mesh: the edges along which a connected surface is
// cut into a topological disk (compute_disk_seams.h).
//
// A set of cut edges H is kept as one flag per edge ("seam"); the border edges of the mesh
// are always part of the cut and never seams. The surface cut along H is a disk iff its faces
// are connected across the edges that are neither seam nor border, and its Euler
// characteristic is 1 (a connected surface with chi = 1 has genus 0 and one border loop).
//
//   greedy_system_of_cuts()  tree-cotree (Eppstein 2003) with a shortest path tree as the
//                            primal tree: Erickson and Whittlesey's greedy system of loops
//                            ("Greedy optimal homotopy and homology generators", SODA 2005);
//                            on a surface with border, the whole border is the base, which
//                            gives arcs from border to border that also join the border loops
//   prune_cut()              removes dangling trees (vertices of cut degree 1 that are not
//                            terminals)
//   connect_terminals()      joins cones to the cut by shortest paths, nearest first (a
//                            greedy Steiner tree)
//   is_disk_cut()            whether the surface cut along the seams is a disk
//
// The shortening of a cut (shorten_cut()) is in cut_shortening.h.

#include <CGAL/Surface_mesh_parameterization/internal/core/union_find.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
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

// A manifold triangle mesh with dense indices. Edge k of face f joins faces[f][k] and
// faces[f][(k+1)%3]; ring_edges lists the edges around each vertex in rotation order (CSR:
// ring_offsets[v] .. ring_offsets[v+1]).
struct Indexed_surface
{
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<int, 3> > faces;
  std::vector<std::array<int, 3> > face_edges;
  std::vector<std::array<int, 2> > edge_vertices;
  std::vector<std::array<int, 2> > edge_faces;  // -1 on a border side
  std::vector<double> edge_lengths;
  std::vector<int> ring_offsets, ring_edges;
  std::vector<char> border_vertex, border_edge;
  std::vector<std::vector<int> > border_loops;  // vertices of each border loop, in order

  int number_of_vertices() const { return static_cast<int>(points.size()); }
  int number_of_edges() const { return static_cast<int>(edge_vertices.size()); }
  int number_of_faces() const { return static_cast<int>(faces.size()); }
  int other_end(int e, int v) const
  {
    const std::array<int, 2>& ev = edge_vertices[static_cast<std::size_t>(e)];
    return (ev[0] == v) ? ev[1] : ev[0];
  }
  long euler_characteristic() const
  {
    return long(number_of_vertices()) - long(number_of_edges()) + long(number_of_faces());
  }
  int genus() const
  {
    return static_cast<int>((2 - euler_characteristic() - long(border_loops.size())) / 2);
  }
};

// Single- or multi-source Dijkstra on the mesh edges.
struct Shortest_path_tree
{
  std::vector<double> distance;
  std::vector<int> parent_edge;  // -1 at a source or an unreached vertex
};

// A source: a vertex reached at `distance` through `edge` (-1 for a base vertex).
struct Path_source
{
  int vertex;
  double distance;
  int edge;
};

// Vertices to settle, nearest first (ties: smallest index).
typedef std::priority_queue<std::pair<double, int>, std::vector<std::pair<double, int> >,
                            std::greater<std::pair<double, int> > > Path_queue;

// The tree before the first step: every vertex unreached but the sources.
inline void start_shortest_paths(const Indexed_surface& s, const std::vector<Path_source>& sources,
                                 Shortest_path_tree& tree, Path_queue& queue)
{
  const std::size_t n = static_cast<std::size_t>(s.number_of_vertices());
  tree.distance.assign(n, std::numeric_limits<double>::infinity());
  tree.parent_edge.assign(n, -1);
  for(const Path_source& src : sources)
  {
    const std::size_t v = static_cast<std::size_t>(src.vertex);
    if(src.distance < tree.distance[v])
    {
      tree.distance[v] = src.distance;
      tree.parent_edge[v] = src.edge;
      queue.emplace(src.distance, src.vertex);
    }
  }
}

// Relaxes the usable edges of the settled vertex v, at distance d.
template <class Usable>
void relax_edges(const Indexed_surface& s, int v, double d, const Usable& usable, const std::vector<char>& settled,
                 Shortest_path_tree& tree, Path_queue& queue)
{
  const std::size_t i = static_cast<std::size_t>(v);
  for(int k = s.ring_offsets[i]; k < s.ring_offsets[i + 1]; ++k)
  {
    const int e = s.ring_edges[static_cast<std::size_t>(k)];
    if(!usable(e))
      continue;
    const std::size_t w = static_cast<std::size_t>(s.other_end(e, v));
    const double dw = d + s.edge_lengths[static_cast<std::size_t>(e)];
    if(!settled[w] && dw < tree.distance[w])
    {
      tree.distance[w] = dw;
      tree.parent_edge[w] = e;
      queue.emplace(dw, static_cast<int>(w));
    }
  }
}

// Runs Dijkstra from the sources. `usable(e)` says whether an edge may be walked, `relay(v)`
// whether a settled vertex is expanded; `settle(v, d)` is called for every settled vertex
// and returns true to stop. Ties are broken by vertex index (deterministic).
template <class Usable, class Relay, class Settle>
void shortest_paths(const Indexed_surface& s, const std::vector<Path_source>& sources,
                    const Usable& usable, const Relay& relay, const Settle& settle,
                    Shortest_path_tree& tree)
{
  Path_queue queue;
  start_shortest_paths(s, sources, tree, queue);
  std::vector<char> settled(tree.distance.size(), 0);
  while(!queue.empty())
  {
    const std::pair<double, int> top = queue.top();
    queue.pop();
    const std::size_t v = static_cast<std::size_t>(top.second);
    if(settled[v] || top.first > tree.distance[v])
      continue;
    settled[v] = 1;
    if(settle(top.second, top.first))
      return;
    if(relay(top.second))
      relax_edges(s, top.second, top.first, usable, settled, tree, queue);
  }
}

// Marks the tree path from v up to its source in `cut`, and its vertices but the source in
// `on_path` (when not null).
inline void mark_tree_path(const Indexed_surface& s, const Shortest_path_tree& tree, int v,
                           std::vector<char>& cut, std::vector<char>* on_path = nullptr)
{
  while(tree.parent_edge[static_cast<std::size_t>(v)] >= 0)
  {
    const int e = tree.parent_edge[static_cast<std::size_t>(v)];
    cut[static_cast<std::size_t>(e)] = 1;
    if(on_path)
      (*on_path)[static_cast<std::size_t>(v)] = 1;
    v = s.other_end(e, v);
  }
}

// The shortest path tree of the greedy system: from the whole border (with border), or from
// `root` (closed surface), over the interior edges.
inline void system_tree(const Indexed_surface& s, int root, Shortest_path_tree& tree)
{
  std::vector<Path_source> sources;
  if(!s.border_loops.empty())
  {
    for(int v = 0; v < s.number_of_vertices(); ++v)
      if(s.border_vertex[static_cast<std::size_t>(v)])
        sources.push_back({v, 0., -1});
  }
  else
    sources.push_back({root, 0., -1});
  shortest_paths(
    s, sources, [&s](int e) { return !s.border_edge[static_cast<std::size_t>(e)]; },
    [](int) { return true; }, [](int, double) { return false; }, tree);
}

// The dual edges of the greedy system (the interior edges not in the tree) with the length
// d(u) + |uv| + d(v) of the loop or arc each closes with the tree, heaviest first (ties by
// edge index).
inline std::vector<std::pair<double, int> > weighted_dual_edges(const Indexed_surface& s,
                                                                const Shortest_path_tree& tree)
{
  std::vector<char> in_tree(static_cast<std::size_t>(s.number_of_edges()), 0);
  for(int e : tree.parent_edge)
    if(e >= 0)
      in_tree[static_cast<std::size_t>(e)] = 1;
  std::vector<std::pair<double, int> > dual;
  for(int e = 0; e < s.number_of_edges(); ++e)
  {
    const std::size_t i = static_cast<std::size_t>(e);
    if(in_tree[i] || s.border_edge[i])
      continue;
    const std::array<int, 2>& ev = s.edge_vertices[i];
    dual.emplace_back(tree.distance[static_cast<std::size_t>(ev[0])] + s.edge_lengths[i] +
                        tree.distance[static_cast<std::size_t>(ev[1])], e);
  }
  std::sort(dual.begin(), dual.end(), [](const std::pair<double, int>& a, const std::pair<double, int>& b) {
    return a.first > b.first || (a.first == b.first && a.second < b.second);
  });
  return dual;
}

// The greedy system of loops (closed surface, based at `root`) or of arcs (surface with
// border, based at the whole border): marks its edges in `cut` and returns the number of
// loops or arcs, 2g on a closed surface and 2g + b - 1 with b border loops.
//
// T is the shortest path tree (forest, with border) from the base; C* the maximum spanning
// tree of the dual graph (faces joined across the interior edges not in T), where the weight
// of an edge uv is the length d(u) + |uv| + d(v) of the loop or arc that it closes with T;
// every interior edge in neither (a closing edge, listed in `closing_edges`) gives one loop or
// arc (Eppstein's tree-cotree decomposition; with this T and C*, Erickson and Whittlesey's
// greedy generators). With a border, the count is that of the surface whose border vertices
// are contracted to one vertex and whose border edges are dropped: T has V_int edges, C* has
// F - 1, and the E_int - V_int - F + 1 = 1 - chi = 2g + b - 1 others are the arcs. The surface
// minus T, the arcs and the border is the union of the faces glued across C*: an open disk.
inline int greedy_system_of_cuts(const Indexed_surface& s, int root, std::vector<char>& cut,
                                 std::vector<int>* closing_edges = nullptr)
{
  Shortest_path_tree tree;
  system_tree(s, root, tree);
  Union_find faces(static_cast<std::size_t>(s.number_of_faces()));
  int loops = 0;
  for(const std::pair<double, int>& d : weighted_dual_edges(s, tree))
  {
    const std::array<int, 2>& ef = s.edge_faces[static_cast<std::size_t>(d.second)];
    if(faces.unite(static_cast<std::size_t>(ef[0]), static_cast<std::size_t>(ef[1])))
      continue;  // a cotree edge
    ++loops;
    if(closing_edges)
      closing_edges->push_back(d.second);
    cut[static_cast<std::size_t>(d.second)] = 1;
    const std::array<int, 2>& ev = s.edge_vertices[static_cast<std::size_t>(d.second)];
    mark_tree_path(s, tree, ev[0], cut);
    mark_tree_path(s, tree, ev[1], cut);
  }
  return loops;
}

// Number of seam edges at every vertex.
inline std::vector<int> seam_degrees(const Indexed_surface& s, const std::vector<char>& cut)
{
  std::vector<int> degree(static_cast<std::size_t>(s.number_of_vertices()), 0);
  for(int e = 0; e < s.number_of_edges(); ++e)
    if(cut[static_cast<std::size_t>(e)])
      for(int v : s.edge_vertices[static_cast<std::size_t>(e)])
        ++degree[static_cast<std::size_t>(v)];
  return degree;
}

// Removes dangling trees: repeatedly unmarks the seam edge at a vertex that has exactly one
// seam edge, is not on the border and is not a terminal.
inline void prune_cut(const Indexed_surface& s, const std::vector<char>& terminal, std::vector<char>& cut)
{
  std::vector<int> degree = seam_degrees(s, cut);
  std::vector<int> stack;
  auto dangling = [&](int v) {
    const std::size_t i = static_cast<std::size_t>(v);
    return degree[i] == 1 && !s.border_vertex[i] && !terminal[i];
  };
  for(int v = 0; v < s.number_of_vertices(); ++v)
    if(dangling(v))
      stack.push_back(v);
  while(!stack.empty())
  {
    const int v = stack.back();
    stack.pop_back();
    if(!dangling(v))
      continue;
    const std::size_t i = static_cast<std::size_t>(v);
    for(int k = s.ring_offsets[i]; k < s.ring_offsets[i + 1]; ++k)
    {
      const int e = s.ring_edges[static_cast<std::size_t>(k)];
      if(!cut[static_cast<std::size_t>(e)])
        continue;
      cut[static_cast<std::size_t>(e)] = 0;
      const int w = s.other_end(e, v);
      --degree[i];
      --degree[static_cast<std::size_t>(w)];
      if(dangling(w))
        stack.push_back(w);
      break;
    }
  }
}

// The nearest vertex flagged in `waiting` from the vertices flagged in `connected`, by a
// shortest path over interior edges through no vertex flagged in `avoided` (the path in
// `tree`); -1 when none can be reached.
inline int nearest_waiting_vertex(const Indexed_surface& s, const std::vector<char>& waiting,
                                  const std::vector<char>& avoided, const std::vector<char>& connected,
                                  Shortest_path_tree& tree)
{
  std::vector<Path_source> sources;
  for(int v = 0; v < s.number_of_vertices(); ++v)
    if(connected[static_cast<std::size_t>(v)])
      sources.push_back({v, 0., -1});
  int reached = -1;
  shortest_paths(
    s, sources,
    [&s, &avoided](int e) {
      const std::array<int, 2>& ev = s.edge_vertices[static_cast<std::size_t>(e)];
      return !s.border_edge[static_cast<std::size_t>(e)] && !avoided[static_cast<std::size_t>(ev[0])] &&
             !avoided[static_cast<std::size_t>(ev[1])];
    },
    [](int) { return true; },
    [&](int v, double) {
      if(!waiting[static_cast<std::size_t>(v)])
        return false;
      reached = v;
      return true;
    },
    tree);
  return reached;
}

// Joins every terminal to the cut, the nearest first, by a shortest path over interior edges
// from the vertices already connected (`connected`: the vertices of the cut and of the
// border; updated), through no vertex flagged in `avoided`. Returns false when a terminal
// cannot be reached.
inline bool connect_terminals(const Indexed_surface& s, const std::vector<int>& terminals,
                              const std::vector<char>& avoided, std::vector<char>& connected,
                              std::vector<char>& cut)
{
  std::vector<char> waiting(static_cast<std::size_t>(s.number_of_vertices()), 0);
  std::size_t left = 0;
  for(int t : terminals)
    if(!connected[static_cast<std::size_t>(t)] && !waiting[static_cast<std::size_t>(t)])
    {
      waiting[static_cast<std::size_t>(t)] = 1;
      ++left;
    }
  Shortest_path_tree tree;
  for(; left > 0; --left)
  {
    const int reached = nearest_waiting_vertex(s, waiting, avoided, connected, tree);
    if(reached < 0)
      return false;
    waiting[static_cast<std::size_t>(reached)] = 0;
    mark_tree_path(s, tree, reached, cut, &connected);
    connected[static_cast<std::size_t>(reached)] = 1;
  }
  return true;
}

// Whether the surface cut along the seams (and its border) is a topological disk: its faces
// are connected across the edges that are neither seam nor border, and its Euler
// characteristic is 1 (or `chi`: 1 - h for a disk with h holes). A vertex becomes as many
// vertices as it has wedges between cut edges.
inline bool is_disk_cut(const Indexed_surface& s, const std::vector<char>& cut, long chi = 1)
{
  if(s.faces.empty())
    return false;
  Union_find pieces(static_cast<std::size_t>(s.number_of_faces()));
  long seams = 0, components = s.number_of_faces();
  for(int e = 0; e < s.number_of_edges(); ++e)
  {
    const std::size_t i = static_cast<std::size_t>(e);
    if(cut[i])
      ++seams;
    else if(!s.border_edge[i] &&
            pieces.unite(static_cast<std::size_t>(s.edge_faces[i][0]), static_cast<std::size_t>(s.edge_faces[i][1])))
      --components;
  }
  if(components != 1)
    return false;
  const std::vector<int> degree = seam_degrees(s, cut);
  long vertices = 0;
  for(int v = 0; v < s.number_of_vertices(); ++v)
  {
    const int d = degree[static_cast<std::size_t>(v)];
    vertices += s.border_vertex[static_cast<std::size_t>(v)] ? 1 + d : (std::max)(1, d);
  }
  return vertices - (long(s.number_of_edges()) + seams) + long(s.number_of_faces()) == chi;
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_SEAMS_CUT_GRAPH_H
