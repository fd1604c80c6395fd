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
//   shorten_cut()            replaces each path of the cut between two branch points by the
//                            shortest path between the same points on the same sides, when
//                            shorter, and keeps it only if the cut is still a disk

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

// Runs Dijkstra from the sources. `usable(e)` says whether an edge may be walked, `relay(v)`
// whether a settled vertex is expanded; `settle(v, d)` is called for every settled vertex
// and returns true to stop. Ties are broken by vertex index (deterministic).
template <class Usable, class Relay, class Settle>
void shortest_paths(const Indexed_surface& s, const std::vector<Path_source>& sources,
                    const Usable& usable, const Relay& relay, const Settle& settle,
                    Shortest_path_tree& tree)
{
  typedef std::pair<double, int> Item;
  const std::size_t n = static_cast<std::size_t>(s.number_of_vertices());
  tree.distance.assign(n, std::numeric_limits<double>::infinity());
  tree.parent_edge.assign(n, -1);
  std::vector<char> settled(n, 0);
  std::priority_queue<Item, std::vector<Item>, std::greater<Item> > queue;
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
  while(!queue.empty())
  {
    const Item top = queue.top();
    queue.pop();
    const std::size_t v = static_cast<std::size_t>(top.second);
    if(settled[v] || top.first > tree.distance[v])
      continue;
    settled[v] = 1;
    if(settle(top.second, top.first))
      return;
    if(!relay(top.second))
      continue;
    for(int k = s.ring_offsets[v]; k < s.ring_offsets[v + 1]; ++k)
    {
      const int e = s.ring_edges[static_cast<std::size_t>(k)];
      if(!usable(e))
        continue;
      const std::size_t w = static_cast<std::size_t>(s.other_end(e, top.second));
      const double d = top.first + s.edge_lengths[static_cast<std::size_t>(e)];
      if(!settled[w] && d < tree.distance[w])
      {
        tree.distance[w] = d;
        tree.parent_edge[w] = e;
        queue.emplace(d, static_cast<int>(w));
      }
    }
  }
}

// Marks the tree path from v up to its source.
inline void mark_tree_path(const Indexed_surface& s, const Shortest_path_tree& tree, int v,
                           std::vector<char>& cut)
{
  while(tree.parent_edge[static_cast<std::size_t>(v)] >= 0)
  {
    const int e = tree.parent_edge[static_cast<std::size_t>(v)];
    cut[static_cast<std::size_t>(e)] = 1;
    v = s.other_end(e, v);
  }
}

// Union-find with path halving.
class Disjoint_sets
{
public:
  explicit Disjoint_sets(std::size_t n) : m_parent(n) { std::iota(m_parent.begin(), m_parent.end(), std::size_t(0)); }
  std::size_t find(std::size_t i)
  {
    while(m_parent[i] != i)
      i = m_parent[i] = m_parent[m_parent[i]];
    return i;
  }
  bool unite(std::size_t a, std::size_t b)
  {
    a = find(a);
    b = find(b);
    if(a == b)
      return false;
    m_parent[(std::max)(a, b)] = (std::min)(a, b);
    return true;
  }

private:
  std::vector<std::size_t> m_parent;
};

// The greedy system of loops (closed surface, based at `root`) or of arcs (surface with
// border, based at the whole border): marks its edges in `cut` and returns the number of
// loops or arcs, 2g on a closed surface and 2g + b - 1 with b border loops.
//
// T is the shortest path tree (forest, with border) from the base; C* the maximum spanning
// tree of the dual graph (faces joined across the interior edges not in T), where the weight
// of an edge uv is the length d(u) + |uv| + d(v) of the loop or arc that it closes with T;
// every interior edge in neither (a closing edge, listed in `closing_edges`) gives one loop or
// arc (Eppstein's tree-cotree
// decomposition; with this T and C*, Erickson and Whittlesey's greedy generators). With a
// border, the count is that of the surface whose border vertices are contracted to one vertex
// and whose border edges are dropped: T has V_int edges, C* has F - 1, and the
// E_int - V_int - F + 1 = 1 - chi = 2g + b - 1 others are the arcs. The surface minus T, the
// arcs and the border is the union of the faces glued across C*: an open disk.
inline int greedy_system_of_cuts(const Indexed_surface& s, int root, std::vector<char>& cut,
                                 std::vector<int>* closing_edges = nullptr)
{
  const bool with_border = !s.border_loops.empty();
  std::vector<Path_source> sources;
  if(with_border)
  {
    for(int v = 0; v < s.number_of_vertices(); ++v)
      if(s.border_vertex[static_cast<std::size_t>(v)])
        sources.push_back({v, 0., -1});
  }
  else
    sources.push_back({root, 0., -1});
  Shortest_path_tree tree;
  shortest_paths(
    s, sources, [&s](int e) { return !s.border_edge[static_cast<std::size_t>(e)]; },
    [](int) { return true; }, [](int, double) { return false; }, tree);

  std::vector<char> in_tree(static_cast<std::size_t>(s.number_of_edges()), 0);
  for(int e : tree.parent_edge)
    if(e >= 0)
      in_tree[static_cast<std::size_t>(e)] = 1;

  // the dual edges, heaviest first (ties by edge index)
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
  Disjoint_sets faces(static_cast<std::size_t>(s.number_of_faces()));
  int loops = 0;
  for(const std::pair<double, int>& d : dual)
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
  while(left > 0)
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
    if(reached < 0)
      return false;
    waiting[static_cast<std::size_t>(reached)] = 0;
    --left;
    for(int v = reached; tree.parent_edge[static_cast<std::size_t>(v)] >= 0;)
    {
      const int e = tree.parent_edge[static_cast<std::size_t>(v)];
      cut[static_cast<std::size_t>(e)] = 1;
      connected[static_cast<std::size_t>(v)] = 1;
      v = s.other_end(e, v);
    }
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
  Disjoint_sets pieces(static_cast<std::size_t>(s.number_of_faces()));
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

// A path of seam edges between two nodes of the cut (vertices that are not of cut degree 2,
// lie on the border, or are terminals): vertices.front() and vertices.back() are the nodes.
struct Cut_segment
{
  std::vector<int> vertices;
  std::vector<int> edges;
};

inline std::vector<Cut_segment> cut_segments(const Indexed_surface& s, const std::vector<char>& cut,
                                             const std::vector<char>& terminal)
{
  const std::vector<int> degree = seam_degrees(s, cut);
  auto is_node = [&](int v) {
    const std::size_t i = static_cast<std::size_t>(v);
    return degree[i] != 2 || s.border_vertex[i] || terminal[i];
  };
  std::vector<char> walked(static_cast<std::size_t>(s.number_of_edges()), 0);
  std::vector<Cut_segment> segments;
  for(int a = 0; a < s.number_of_vertices(); ++a)
  {
    if(degree[static_cast<std::size_t>(a)] == 0 || !is_node(a))
      continue;
    for(int k = s.ring_offsets[static_cast<std::size_t>(a)]; k < s.ring_offsets[static_cast<std::size_t>(a) + 1]; ++k)
    {
      int e = s.ring_edges[static_cast<std::size_t>(k)];
      if(!cut[static_cast<std::size_t>(e)] || walked[static_cast<std::size_t>(e)])
        continue;
      Cut_segment segment;
      segment.vertices.push_back(a);
      int v = a;
      while(true)
      {
        walked[static_cast<std::size_t>(e)] = 1;
        segment.edges.push_back(e);
        v = s.other_end(e, v);
        segment.vertices.push_back(v);
        if(is_node(v))
          break;
        int next = -1;  // the other seam edge of v
        for(int j = s.ring_offsets[static_cast<std::size_t>(v)]; j < s.ring_offsets[static_cast<std::size_t>(v) + 1]; ++j)
        {
          const int f = s.ring_edges[static_cast<std::size_t>(j)];
          if(cut[static_cast<std::size_t>(f)] && f != e)
            next = f;
        }
        e = next;
      }
      segments.push_back(std::move(segment));
    }
  }
  return segments;
}

// The edges around `v` in the two wedges beside edge `e` (between the nearest cut or border
// edges before and after it in the rotation, `e` included), flagged in `flags`. Returns false
// when `v` has no other cut or border edge (then every edge of `v` is flagged).
inline bool flag_wedges_beside(const Indexed_surface& s, const std::vector<char>& cut, int v, int e,
                               std::vector<char>& flags, std::vector<int>& flagged)
{
  const std::size_t i = static_cast<std::size_t>(v);
  const int begin = s.ring_offsets[i], size = s.ring_offsets[i + 1] - begin;
  auto edge_at = [&](int k) { return s.ring_edges[static_cast<std::size_t>(begin + ((k % size) + size) % size)]; };
  auto is_cut = [&](int f) { return cut[static_cast<std::size_t>(f)] || s.border_edge[static_cast<std::size_t>(f)]; };
  int position = 0;
  while(edge_at(position) != e)
    ++position;
  bool bounded = false;
  for(int step : {1, -1})
    for(int k = 0; k < size; ++k)
    {
      const int f = edge_at(position + step * k);
      if(k > 0 && is_cut(f))
      {
        bounded = true;
        break;
      }
      if(!flags[static_cast<std::size_t>(f)])
      {
        flags[static_cast<std::size_t>(f)] = 1;
        flagged.push_back(f);
      }
    }
  return bounded;
}

// Tries to replace the segment by a shorter path between its nodes, leaving each node in the
// wedges beside the segment's end edges and avoiding every other vertex of the cut and of the
// border; keeps the new path only if the cut is still a disk. Returns whether it did.
inline bool shorten_segment(const Indexed_surface& s, const Cut_segment& segment, long chi, std::vector<char>& cut)
{
  const int a = segment.vertices.front(), b = segment.vertices.back();
  double old_length = 0.;
  for(int e : segment.edges)
  {
    old_length += s.edge_lengths[static_cast<std::size_t>(e)];
    cut[static_cast<std::size_t>(e)] = 0;
  }
  auto restore = [&]() {
    for(int e : segment.edges)
      cut[static_cast<std::size_t>(e)] = 1;
    return false;
  };
  const std::vector<int> degree = seam_degrees(s, cut);
  auto blocked = [&](int v) {
    const std::size_t i = static_cast<std::size_t>(v);
    return v == a || v == b || degree[i] > 0 || s.border_vertex[i];
  };
  std::vector<char> start(static_cast<std::size_t>(s.number_of_edges()), 0), end(start);
  std::vector<int> start_edges, end_edges;
  const bool a_bounded = flag_wedges_beside(s, cut, a, segment.edges.front(), start, start_edges);
  const bool b_bounded = flag_wedges_beside(s, cut, b, segment.edges.back(), end, end_edges);
  if(a == b)
  {
    if(!a_bounded || !b_bounded)
      return restore();
    for(int e : start_edges)
      if(end[static_cast<std::size_t>(e)])
        return restore();  // the wedges overlap: no side to keep
  }

  double best = old_length * (1. - 1e-9);
  int best_last = -1;  // the last edge of the best path (into b)
  std::vector<Path_source> sources;
  for(int e : start_edges)
  {
    const int m = s.other_end(e, a);
    const double l = s.edge_lengths[static_cast<std::size_t>(e)];
    if(m == b && end[static_cast<std::size_t>(e)] && a != b && l < best)
    {
      best = l;
      best_last = e;
    }
    else if(!blocked(m))
      sources.push_back({m, l, e});
  }
  Shortest_path_tree tree;
  shortest_paths(
    s, sources, [&s, &cut](int e) { return !cut[static_cast<std::size_t>(e)] && !s.border_edge[static_cast<std::size_t>(e)]; },
    [&](int v) { return !blocked(v); },
    [&](int v, double d) {
      if(d >= best)
        return true;
      if(blocked(v))
        return false;
      const std::size_t i = static_cast<std::size_t>(v);
      for(int k = s.ring_offsets[i]; k < s.ring_offsets[i + 1]; ++k)
      {
        const int e = s.ring_edges[static_cast<std::size_t>(k)];
        if(end[static_cast<std::size_t>(e)] && s.other_end(e, v) == b &&
           e != tree.parent_edge[i] && d + s.edge_lengths[static_cast<std::size_t>(e)] < best)
        {
          best = d + s.edge_lengths[static_cast<std::size_t>(e)];
          best_last = e;
        }
      }
      return false;
    },
    tree);
  if(best_last < 0)
    return restore();

  std::vector<int> path(1, best_last);
  for(int v = s.other_end(best_last, b); v != a;)
  {
    const int e = tree.parent_edge[static_cast<std::size_t>(v)];
    path.push_back(e);
    v = s.other_end(e, v);
  }
  for(int e : path)
    cut[static_cast<std::size_t>(e)] = 1;
  if(is_disk_cut(s, cut, chi))
    return true;
  for(int e : path)
    cut[static_cast<std::size_t>(e)] = 0;
  return restore();
}

// Shortens the segments of the cut, pass after pass, until no segment gets shorter or after
// `max_passes` passes; `chi` as for is_disk_cut(). Returns the number of replacements.
inline int shorten_cut(const Indexed_surface& s, const std::vector<char>& terminal, long chi, int max_passes,
                       std::vector<char>& cut)
{
  int replaced = 0;
  for(int pass = 0; pass < max_passes; ++pass)
  {
    int this_pass = 0;
    for(const Cut_segment& segment : cut_segments(s, cut, terminal))
      if(shorten_segment(s, segment, chi, cut))
        ++this_pass;
    replaced += this_pass;
    if(this_pass == 0)
      break;
  }
  return replaced;
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_SEAMS_CUT_GRAPH_H
