// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_SEAMS_CUT_SHORTENING_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_SEAMS_CUT_SHORTENING_H

// The shortening of a cut graph (cut_graph.h): shorten_cut() replaces each path of the cut
// between two branch points (a segment) by the shortest path between the same points that
// leaves and enters them on the same sides and meets the rest of the cut nowhere else, when
// it is shorter, and keeps it only if the cut is still a disk.

#include <CGAL/Surface_mesh_parameterization/internal/seams/cut_graph.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// A path of seam edges between two nodes of the cut (vertices that are not of cut degree 2,
// lie on the border, or are terminals): vertices.front() and vertices.back() are the nodes.
struct Cut_segment
{
  std::vector<int> vertices;
  std::vector<int> edges;
};

// The seam edge of `v` other than `e` (the last one in rotation order), or -1.
inline int other_seam_edge(const Indexed_surface& s, const std::vector<char>& cut, int v, int e)
{
  int other = -1;
  for(int j = s.ring_offsets[static_cast<std::size_t>(v)]; j < s.ring_offsets[static_cast<std::size_t>(v) + 1]; ++j)
  {
    const int f = s.ring_edges[static_cast<std::size_t>(j)];
    if(cut[static_cast<std::size_t>(f)] && f != e)
      other = f;
  }
  return other;
}

// The segment that leaves node `a` by the seam edge `e`, walked up to the next node.
template <class IsNode>
Cut_segment walk_segment(const Indexed_surface& s, const std::vector<char>& cut, const IsNode& is_node, int a,
                         int e, std::vector<char>& walked)
{
  Cut_segment segment;
  segment.vertices.push_back(a);
  for(int v = a;; e = other_seam_edge(s, cut, v, e))
  {
    walked[static_cast<std::size_t>(e)] = 1;
    segment.edges.push_back(e);
    v = s.other_end(e, v);
    segment.vertices.push_back(v);
    if(is_node(v))
      return segment;
  }
}

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
    const std::size_t i = static_cast<std::size_t>(a);
    if(degree[i] == 0 || !is_node(a))
      continue;
    for(int k = s.ring_offsets[i]; k < s.ring_offsets[i + 1]; ++k)
    {
      const int e = s.ring_edges[static_cast<std::size_t>(k)];
      if(cut[static_cast<std::size_t>(e)] && !walked[static_cast<std::size_t>(e)])
        segments.push_back(walk_segment(s, cut, is_node, a, e, walked));
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

// The edges by which a replacement of a segment (lifted from the cut) may leave its first
// node `a` (`start`) and enter its last node `b` (`end`): those in the wedges beside the
// segment's end edges.
struct Segment_ends
{
  int a = -1, b = -1;
  std::vector<char> start, end;  // one flag per edge
  std::vector<int> start_edges, end_edges;
};

// The ends of the segment; false when a replacement would have no side to keep (a closed
// segment whose node has no other cut edge, or whose wedges overlap).
inline bool segment_ends(const Indexed_surface& s, const std::vector<char>& cut, const Cut_segment& segment,
                         Segment_ends& ends)
{
  ends.a = segment.vertices.front();
  ends.b = segment.vertices.back();
  ends.start.assign(static_cast<std::size_t>(s.number_of_edges()), 0);
  ends.end = ends.start;
  const bool a_bounded = flag_wedges_beside(s, cut, ends.a, segment.edges.front(), ends.start, ends.start_edges);
  const bool b_bounded = flag_wedges_beside(s, cut, ends.b, segment.edges.back(), ends.end, ends.end_edges);
  if(ends.a != ends.b)
    return true;
  if(!a_bounded || !b_bounded)
    return false;
  for(int e : ends.start_edges)
    if(ends.end[static_cast<std::size_t>(e)])
      return false;  // the wedges overlap: no side to keep
  return true;
}

// The best replacement found so far: its length and its last edge (into b; -1: none).
struct Replacement
{
  double length;
  int last = -1;
};

// Closes a replacement from the settled vertex v (at distance d from a) by an end edge into
// b, when that is shorter than the best so far.
inline void close_replacement_at(const Indexed_surface& s, const Segment_ends& ends, const Shortest_path_tree& tree,
                                 int v, double d, Replacement& best)
{
  const std::size_t i = static_cast<std::size_t>(v);
  for(int k = s.ring_offsets[i]; k < s.ring_offsets[i + 1]; ++k)
  {
    const int e = s.ring_edges[static_cast<std::size_t>(k)];
    const double length = d + s.edge_lengths[static_cast<std::size_t>(e)];
    if(ends.end[static_cast<std::size_t>(e)] && s.other_end(e, v) == ends.b && e != tree.parent_edge[i] &&
       length < best.length)
      best = {length, e};
  }
}

// The shortest replacement of the lifted segment that is shorter than `best.length`: a path
// from a to b that leaves a and enters b by their end edges and avoids every other vertex of
// the cut and of the border. Its edges are `best.last` and the path of `tree` to a.
inline void shortest_replacement(const Indexed_surface& s, const std::vector<char>& cut, const Segment_ends& ends,
                                 Replacement& best, Shortest_path_tree& tree)
{
  const int a = ends.a, b = ends.b;
  const std::vector<int> degree = seam_degrees(s, cut);
  auto blocked = [&](int v) {
    return v == a || v == b || degree[static_cast<std::size_t>(v)] > 0 || s.border_vertex[static_cast<std::size_t>(v)];
  };
  std::vector<Path_source> sources;
  for(int e : ends.start_edges)
  {
    const int m = s.other_end(e, a);
    const double l = s.edge_lengths[static_cast<std::size_t>(e)];
    if(m == b && ends.end[static_cast<std::size_t>(e)] && a != b && l < best.length)
      best = {l, e};
    else if(!blocked(m))
      sources.push_back({m, l, e});
  }
  shortest_paths(
    s, sources, [&s, &cut](int e) { return !cut[static_cast<std::size_t>(e)] && !s.border_edge[static_cast<std::size_t>(e)]; },
    [&](int v) { return !blocked(v); },
    [&](int v, double d) {
      if(d >= best.length)
        return true;
      if(!blocked(v))
        close_replacement_at(s, ends, tree, v, d, best);
      return false;
    },
    tree);
}

// The edges of the replacement, from b back to a.
inline std::vector<int> replacement_path(const Indexed_surface& s, const Shortest_path_tree& tree,
                                         const Segment_ends& ends, int last)
{
  std::vector<int> path(1, last);
  for(int v = s.other_end(last, ends.b); v != ends.a;)
  {
    const int e = tree.parent_edge[static_cast<std::size_t>(v)];
    path.push_back(e);
    v = s.other_end(e, v);
  }
  return path;
}

// Tries to replace the segment by a shorter path between its nodes (shortest_replacement());
// keeps the new path only if the cut is still a disk. Returns whether it did.
inline bool shorten_segment(const Indexed_surface& s, const Cut_segment& segment, long chi, std::vector<char>& cut)
{
  Replacement best{0.};
  for(int e : segment.edges)
  {
    best.length += s.edge_lengths[static_cast<std::size_t>(e)];
    cut[static_cast<std::size_t>(e)] = 0;
  }
  best.length *= 1. - 1e-9;
  Segment_ends ends;
  Shortest_path_tree tree;
  if(segment_ends(s, cut, segment, ends))
    shortest_replacement(s, cut, ends, best, tree);
  if(best.last >= 0)
  {
    const std::vector<int> path = replacement_path(s, tree, ends, best.last);
    for(int e : path)
      cut[static_cast<std::size_t>(e)] = 1;
    if(is_disk_cut(s, cut, chi))
      return true;
    for(int e : path)
      cut[static_cast<std::size_t>(e)] = 0;
  }
  for(int e : segment.edges)
    cut[static_cast<std::size_t>(e)] = 1;
  return false;
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

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_SEAMS_CUT_SHORTENING_H
