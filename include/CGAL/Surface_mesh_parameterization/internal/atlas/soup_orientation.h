// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_ATLAS_SOUP_ORIENTATION_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_ATLAS_SOUP_ORIENTATION_H

// The second part of the soup stage of the repair of a polygon soup for the atlas
// (soup_repair.h): the soup oriented consistently, its pinched vertices split into one point
// per fan of polygons, its non-manifold edges and non-orientable pieces cut, so that it is a
// polygon mesh. CGAL's orient_polygon_soup() does it all, but takes 2.4 s on a 1M-face soup
// (a map of edges per point, a set of polygons per point); most soups have no non-manifold
// edge and no non-orientable piece, and are oriented here in 0.3 s (orient_manifold_soup():
// the polygons linked through their edges in a union-find that keeps their relative
// orientation, the fans of every point in another); the others by CGAL (orient_with_cgal()),
// whose visitor tells what it did.

#include <CGAL/Surface_mesh_parameterization/internal/atlas/soup_cleaning.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/union_find.h>
#include <CGAL/Surface_mesh_parameterization/Soup_repair_report.h>

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// What orient_polygon_soup() reports to its visitor, in point indices before its copies.
struct Orientation_record
{
  std::vector<std::size_t> reversed;                            // positions of reversed polygons
  std::vector<std::pair<std::size_t, std::size_t> > copies;     // (point, its new copy)
  std::set<std::pair<std::size_t, std::size_t> > non_manifold_edges;
  std::vector<std::size_t> singular_points;                     // points copied, one entry each
};

// The visitor of orient_polygon_soup(), which copies it: the copies write into one record.
struct Orientation_recorder : Polygon_mesh_processing::Default_orientation_visitor
{
  Orientation_record* record = nullptr;

  explicit Orientation_recorder(Orientation_record& r) : record(&r) {}
  void non_manifold_edge(std::size_t a, std::size_t b, std::size_t)
  {
    record->non_manifold_edges.insert(std::minmax(a, b));
  }
  void non_manifold_vertex(std::size_t v, std::size_t) { record->singular_points.push_back(v); }
  void duplicated_vertex(std::size_t v, std::size_t copy) { record->copies.emplace_back(v, copy); }
  void polygon_orientation_reversed(std::size_t position) { record->reversed.push_back(position); }
};

// The cuts orient_polygon_soup() made through non-orientable pieces, which its visitor does
// not report: edges (in merged points) of exactly two polygons that still run the same way
// after the orientation. Both ends of such a cut are copied points, so only the edges between
// copied points are looked at. The ids of their polygons go to soup.cut_ids.
template <class Point_3>
std::set<std::pair<std::size_t, std::size_t> > orientation_cuts(Working_soup<Point_3>& soup,
                                                                 const Orientation_record& record)
{
  std::vector<bool> copied(soup.points.size(), false);
  for(const auto& copy : record.copies)
    copied[copy.first] = true;
  struct Runs { int count = 0, forward = 0; std::vector<std::size_t> ids; };
  std::map<std::pair<std::size_t, std::size_t>, Runs> runs;
  for(const Soup_polygon& polygon : soup.polygons)
    for(std::size_t j = 0; j < polygon.size(); ++j)
    {
      const std::size_t a = soup.point_origin[polygon[j]];
      const std::size_t b = soup.point_origin[polygon[(j + 1) % polygon.size()]];
      if(!copied[a] || !copied[b])
        continue;
      Runs& r = runs[std::minmax(a, b)];
      ++r.count;
      r.forward += (a < b) ? 1 : 0;
      r.ids.push_back(polygon.id);
    }
  std::set<std::pair<std::size_t, std::size_t> > cuts;
  for(const auto& edge : runs)
    if(edge.second.count == 2 && edge.second.forward != 1)
    {
      cuts.insert(edge.first);
      soup.cut_ids.insert(soup.cut_ids.end(), edge.second.ids.begin(), edge.second.ids.end());
    }
  return cuts;
}

// Counts the copies of points by cause: on a non-manifold edge or at a pinched vertex
// (non-manifold), or only along the cut of a non-orientable piece.
template <class Point_3>
void count_copies(Working_soup<Point_3>& soup, const Orientation_record& record, Soup_repair_report& report)
{
  std::set<std::size_t> on_non_manifold_edge, on_cut;
  for(const auto& edge : record.non_manifold_edges)
    on_non_manifold_edge.insert({edge.first, edge.second});
  for(const auto& edge : orientation_cuts(soup, record))
    on_cut.insert({edge.first, edge.second});
  for(const auto& copy : record.copies)
  {
    const bool non_orientable = on_cut.count(copy.first) != 0 && on_non_manifold_edge.count(copy.first) == 0;
    ++(non_orientable ? report.vertices_split_non_orientable : report.vertices_split_non_manifold);
  }
  for(const std::size_t v : record.singular_points)
    if(on_cut.count(v) == 0 && on_non_manifold_edge.count(v) == 0)
      ++report.pinched_vertices;
  report.non_manifold_edges = record.non_manifold_edges.size();
}

// Orients the soup (CGAL), which also copies points to cut non-manifold edges, pinched
// vertices and non-orientable pieces; records the reversed polygons and the copies.
template <class Point_3>
void orient_with_cgal(Working_soup<Point_3>& soup, Soup_repair_report& report)
{
  Orientation_record record;
  Polygon_mesh_processing::orient_polygon_soup(soup.points, soup.polygons,
                                               parameters::visitor(Orientation_recorder(record)));
  for(const std::size_t position : record.reversed)
    soup.id_reversed[soup.polygons[position].id] = !soup.id_reversed[soup.polygons[position].id];
  soup.point_origin.resize(soup.points.size());
  for(const auto& copy : record.copies)
    soup.point_origin[copy.second] = soup.point_origin[copy.first];
  count_copies(soup, record, report);
}

// Items in sets with a parity each, relative to the root of its set (the smallest item): the
// polygons of a piece, parity 1 for those to reverse so that they turn as the first one does.
struct Parity_union_find
{
  std::vector<std::size_t> parent;
  std::vector<unsigned char> parity;  // of an item relative to its parent

  explicit Parity_union_find(std::size_t n) : parent(n), parity(n, 0)
  {
    std::iota(parent.begin(), parent.end(), std::size_t(0));
  }
  std::size_t find(std::size_t x, unsigned char& p)
  {
    std::size_t root = x;
    p = 0;
    for(; parent[root] != root; root = parent[root])
      p ^= parity[root];
    for(unsigned char q = p; parent[x] != root && x != root;)  // the path, attached to the root
    {
      const std::size_t up = parent[x];
      const unsigned char q_up = q ^ parity[x];
      parent[x] = root;
      parity[x] = q;
      x = up;
      q = q_up;
    }
    return root;
  }
  // Requires parity(a) ^ parity(b) == d; false when their sets already say otherwise.
  bool unite(std::size_t a, std::size_t b, unsigned char d)
  {
    unsigned char pa, pb;
    const std::size_t ra = find(a, pa), rb = find(b, pb);
    if(ra == rb)
      return (pa ^ pb) == d;
    parent[(std::max)(ra, rb)] = (std::min)(ra, rb);
    parity[(std::max)(ra, rb)] = pa ^ pb ^ d;
    return true;
  }
};

// The corners of the working soup in one numbering, polygon after polygon.
struct Soup_corners
{
  std::vector<std::size_t> polygon_start;   // per polygon position, and the total at the end
  std::vector<std::size_t> corner_polygon;  // per corner: its polygon's position

  template <class Polygons>
  explicit Soup_corners(const Polygons& polygons)
  {
    polygon_start.reserve(polygons.size() + 1);
    polygon_start.push_back(0);
    for(const auto& polygon : polygons)
      polygon_start.push_back(polygon_start.back() + polygon.size());
    corner_polygon.resize(polygon_start.back());
    for(std::size_t q = 0; q < polygons.size(); ++q)
      std::fill(corner_polygon.begin() + polygon_start[q], corner_polygon.begin() + polygon_start[q + 1], q);
  }
  std::size_t next(std::size_t c) const
  {
    return c + 1 == polygon_start[corner_polygon[c] + 1] ? polygon_start[corner_polygon[c]] : c + 1;
  }
};

// The edge from a corner to the next corner of its polygon, filed under its smaller end.
struct Soup_edge
{
  std::size_t other;   // the larger end
  std::size_t corner;  // the corner it starts from
  bool forward;        // whether it starts from the smaller end
  bool operator<(const Soup_edge& e) const { return other < e.other; }
};

// Calls f(corner, a, b) for the edge from every corner (point a) to the next (point b).
template <class Point_3, class F>
void for_each_edge(const Working_soup<Point_3>& soup, const Soup_corners& c, F f)
{
  for(std::size_t q = 0; q < soup.polygons.size(); ++q)
    for(std::size_t j = 0, n = soup.polygons[q].size(); j < n; ++j)
      f(c.polygon_start[q] + j, soup.polygons[q][j], soup.polygons[q][(j + 1) % n]);
}

// The edges of the soup filed under their smaller ends (a counting sort): edges[start[a] ..
// start[a + 1]) those of point a, in the order of their larger ends.
template <class Point_3>
void file_edges(const Working_soup<Point_3>& soup, const Soup_corners& c, std::vector<std::size_t>& start,
                std::vector<Soup_edge>& edges)
{
  start.assign(soup.points.size() + 1, 0);
  for_each_edge(soup, c, [&start](std::size_t, std::size_t a, std::size_t b) { ++start[1 + (std::min)(a, b)]; });
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<std::size_t> cursor(start.begin(), start.end() - 1);
  edges.resize(c.corner_polygon.size());
  for_each_edge(soup, c, [&](std::size_t corner, std::size_t a, std::size_t b) {
    edges[cursor[(std::min)(a, b)]++] = Soup_edge{(std::max)(a, b), corner, a < b};
  });
  for(std::size_t a = 0; a + 1 < start.size(); ++a)
    std::sort(edges.begin() + start[a], edges.begin() + start[a + 1]);
}

// Links the two polygons of an edge (e, f): in `polygons`, reversed one relative to the other
// when they run the edge the same way; in `corners`, their corners at each end. False when the
// links contradict (a non-orientable piece).
inline bool link_edge(const Soup_edge& e, const Soup_edge& f, const Soup_corners& c, Parity_union_find& polygons,
                      Union_find& corners)
{
  auto at_smaller = [&c](const Soup_edge& g) { return g.forward ? g.corner : c.next(g.corner); };
  auto at_larger = [&c](const Soup_edge& g) { return g.forward ? c.next(g.corner) : g.corner; };
  corners.unite(at_smaller(e), at_smaller(f));
  corners.unite(at_larger(e), at_larger(f));
  return polygons.unite(c.corner_polygon[e.corner], c.corner_polygon[f.corner], e.forward == f.forward ? 1 : 0);
}

// Links the polygons through their edges (link_edge()). False at an edge of three polygons or
// more, or in a non-orientable piece.
template <class Point_3>
bool link_polygons(const Working_soup<Point_3>& soup, const Soup_corners& c, Parity_union_find& polygons,
                   Union_find& corners)
{
  std::vector<std::size_t> start;
  std::vector<Soup_edge> edges;
  file_edges(soup, c, start, edges);
  for(std::size_t a = 0; a + 1 < start.size(); ++a)
    for(std::size_t run = start[a], end = run; run < start[a + 1]; run = end)
    {
      while(end < start[a + 1] && edges[end].other == edges[run].other)
        ++end;
      if(end - run > 2 || (end - run == 2 && !link_edge(edges[run], edges[run + 1], c, polygons, corners)))
        return false;
    }
  return true;
}

// Gives every fan of polygons around a point (a set of `corners`) a point of its own: the
// first fan keeps the point, the others get copies (CGAL would split them the same way).
template <class Point_3>
void split_fans(Working_soup<Point_3>& soup, const Soup_corners& c, Union_find& corners, Soup_repair_report& report)
{
  const std::size_t none = (std::numeric_limits<std::size_t>::max)();
  std::vector<std::size_t> fan_point(c.corner_polygon.size(), none);  // per fan (its root corner)
  std::vector<bool> has_fan(soup.points.size(), false), pinched(soup.points.size(), false);
  for(std::size_t q = 0; q < soup.polygons.size(); ++q)
    for(std::size_t j = 0; j < soup.polygons[q].size(); ++j)
    {
      std::size_t& point = soup.polygons[q][j];
      const std::size_t fan = corners.find(c.polygon_start[q] + j);
      if(fan_point[fan] == none && !has_fan[point])
      {
        has_fan[point] = true;
        fan_point[fan] = point;
      }
      else if(fan_point[fan] == none)
      {
        const Point_3 copy = soup.points[point];
        soup.points.push_back(copy);
        soup.point_origin.push_back(soup.point_origin[point]);
        fan_point[fan] = soup.points.size() - 1;
        ++report.vertices_split_non_manifold;
        report.pinched_vertices += pinched[point] ? 0 : 1;
        pinched[point] = true;
      }
      point = fan_point[fan];
    }
}

// Orients a soup whose edges have at most two polygons each and whose pieces are orientable
// (else false, the soup untouched): each piece turned as its first polygon, the pinched
// points split.
template <class Point_3>
bool orient_manifold_soup(Working_soup<Point_3>& soup, Soup_repair_report& report)
{
  const Soup_corners c(soup.polygons);
  Parity_union_find polygons(soup.polygons.size());
  Union_find corners(c.corner_polygon.size());
  if(!link_polygons(soup, c, polygons, corners))
    return false;
  split_fans(soup, c, corners, report);
  for(std::size_t q = 0; q < soup.polygons.size(); ++q)
  {
    unsigned char reversed;
    polygons.find(q, reversed);
    if(reversed)
    {
      std::reverse(soup.polygons[q].begin(), soup.polygons[q].end());
      soup.id_reversed[soup.polygons[q].id] = !soup.id_reversed[soup.polygons[q].id];
    }
  }
  return true;
}

// The soup oriented, a polygon mesh: by orient_manifold_soup() when it can, else by CGAL.
template <class Point_3>
void orient_soup(Working_soup<Point_3>& soup, Soup_repair_report& report)
{
  if(!orient_manifold_soup(soup, report))
    orient_with_cgal(soup, report);
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_ATLAS_SOUP_ORIENTATION_H
