// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_ATLAS_SOUP_CLEANING_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_ATLAS_SOUP_CLEANING_H

// The soup stage of the repair of a polygon soup for the atlas (soup_repair.h): the input
// copied into a working soup, duplicate points merged (CGAL), polygons that pass through a
// point twice simplified, duplicate polygons merged (CGAL), and the soup oriented with its
// non-manifold edges, pinched vertices and non-orientable pieces cut (CGAL). Around CGAL's
// functions, the bookkeeping that lets every input corner find its face later: the merged
// point of every input corner, the input polygon of every working polygon, the merged point
// of every point copy, and which polygons were reversed.

#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/Soup_repair_report.h>

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <numeric>
#include <set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// A polygon of the working soup, with an id that follows it through CGAL's soup functions.
// merge_duplicate_polygons_in_polygon_soup() moves polygons around and erases the
// duplicates without saying which; a soup's polygons only have to be random access
// containers of point indices, so a vector with one more member passes through unchanged.
struct Soup_polygon : std::vector<std::size_t>
{
  std::size_t id = 0;
};

template <class Point_3>
struct Working_soup
{
  std::vector<Point_3> points;
  std::vector<Soup_polygon> polygons;
  // per working point: the merged point it copies (orient_polygon_soup() adds copies)
  std::vector<std::size_t> point_origin;
  // per input polygon p: its corners [corner_offset[p], corner_offset[p+1]) and its working
  // polygons, by id, [id_offset[p], id_offset[p+1]) (none when degenerate, several when split)
  std::vector<std::size_t> corner_offset, id_offset;
  // per input corner: its merged point
  std::vector<std::size_t> corner_point;
  // per id: the input polygon, whether the polygon is reversed, the id kept in its place
  // (itself, or the polygon it duplicates)
  std::vector<std::size_t> id_input, id_kept;
  std::vector<bool> id_reversed;
  // the ids of the polygons along the cuts of non-orientable pieces
  std::vector<std::size_t> cut_ids;
};

// The input point as a point of the working soup (any point with three coordinates p[0],
// p[1], p[2] convertible to double: CGAL's points, std::array); false when not finite.
template <class Point_3, class InputPoint>
bool to_working_point(const InputPoint& p, Point_3& q)
{
  const double x = CGAL::to_double(p[0]), y = CGAL::to_double(p[1]), z = CGAL::to_double(p[2]);
  q = Point_3(x, y, z);
  return std::isfinite(x) && std::isfinite(y) && std::isfinite(z);
}

// Copies the input soup. ERROR_NON_FINITE_COORDINATES for a point that is not finite (it
// cannot be ordered, so not even merged), ERROR_WRONG_PARAMETER for an index out of range.
template <class Point_3, class PointRange, class PolygonRange>
Error_code load_soup(const PointRange& points, const PolygonRange& polygons, Working_soup<Point_3>& soup,
                     Soup_repair_report& report)
{
  for(const auto& p : points)
  {
    soup.points.emplace_back();
    if(!to_working_point(p, soup.points.back()))
      return ERROR_NON_FINITE_COORDINATES;
  }
  soup.corner_offset.assign(1, 0);
  for(const auto& polygon : polygons)
  {
    Soup_polygon copy;
    for(const auto i : polygon)
    {
      if(static_cast<std::size_t>(i) >= soup.points.size())
        return ERROR_WRONG_PARAMETER;
      copy.push_back(static_cast<std::size_t>(i));
    }
    copy.id = soup.polygons.size();
    soup.corner_offset.push_back(soup.corner_offset.back() + copy.size());
    soup.polygons.push_back(std::move(copy));
  }
  report.input_points = soup.points.size();
  report.input_polygons = soup.polygons.size();
  report.input_corners = soup.corner_offset.back();
  return OK;
}

// Merges the points of equal coordinates (CGAL), and records the merged point of every input
// corner: the function keeps the polygons in their order, with their sizes.
template <class Point_3>
void merge_points(Working_soup<Point_3>& soup, Soup_repair_report& report)
{
  report.merged_points = Polygon_mesh_processing::merge_duplicate_points_in_polygon_soup(soup.points,
                                                                                         soup.polygons);
  soup.corner_point.clear();
  soup.corner_point.reserve(soup.corner_offset.back());
  for(const Soup_polygon& polygon : soup.polygons)
    soup.corner_point.insert(soup.corner_point.end(), polygon.begin(), polygon.end());
  soup.point_origin.resize(soup.points.size());
  std::iota(soup.point_origin.begin(), soup.point_origin.end(), std::size_t(0));
}

// Whether a polygon passes through a point twice.
inline bool has_repeated_point(const std::vector<std::size_t>& polygon)
{
  if(polygon.size() <= 16)
  {
    for(std::size_t i = 0; i < polygon.size(); ++i)
      if(std::find(polygon.begin() + i + 1, polygon.end(), polygon[i]) != polygon.end())
        return true;
    return false;
  }
  std::vector<std::size_t> sorted(polygon);
  std::sort(sorted.begin(), sorted.end());
  return std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end();
}

// The pieces of a closed polygon of at least 3 distinct points: the polygon without its
// repeated consecutive points, split where it passes through a point again (the two loops
// that meet there, each split again). Written here because CGAL 5.5's equivalents,
// simplify_polygons_in_polygon_soup() and split_pinched_polygons_in_polygon_soup(), are
// undocumented (namespace internal) and do not say which polygon a piece comes from.
inline void split_at_repeated_points(std::vector<std::size_t> polygon, std::vector<std::vector<std::size_t> >& pieces)
{
  polygon.erase(std::unique(polygon.begin(), polygon.end()), polygon.end());
  while(polygon.size() > 1 && polygon.front() == polygon.back())
    polygon.pop_back();
  if(!has_repeated_point(polygon))
  {
    if(polygon.size() >= 3)
      pieces.push_back(polygon);
    return;
  }
  for(std::size_t i = 0; i < polygon.size(); ++i)
    for(std::size_t j = i + 1; j < polygon.size(); ++j)
      if(polygon[i] == polygon[j])
      {
        split_at_repeated_points(std::vector<std::size_t>(polygon.begin() + i, polygon.begin() + j), pieces);
        std::vector<std::size_t> rest(polygon.begin() + j, polygon.end());
        rest.insert(rest.end(), polygon.begin(), polygon.begin() + i);
        split_at_repeated_points(rest, pieces);
        return;
      }
}

// Replaces every polygon by its pieces (split_at_repeated_points()), numbered in input order:
// a polygon with no piece is degenerate (fewer than 3 distinct points).
template <class Point_3>
void simplify_polygons(Working_soup<Point_3>& soup, Soup_repair_report& report)
{
  std::vector<Soup_polygon> simple;
  simple.reserve(soup.polygons.size());
  std::vector<std::vector<std::size_t> > pieces;
  soup.id_offset.assign(1, 0);
  for(std::size_t p = 0; p < soup.polygons.size(); ++p)
  {
    pieces.clear();
    const std::size_t size = soup.polygons[p].size();
    if(size >= 3 && !has_repeated_point(soup.polygons[p]))
      pieces.push_back(std::move(soup.polygons[p]));  // the usual case, not copied
    else
      split_at_repeated_points(soup.polygons[p], pieces);
    if(pieces.empty())
      ++report.degenerate_polygons;
    else if(pieces.size() > 1 || pieces.front().size() != size)
      ++report.polygons_with_repeated_points;
    for(std::vector<std::size_t>& piece : pieces)
    {
      simple.emplace_back();
      simple.back().swap(piece);
      simple.back().id = soup.id_input.size();
      soup.id_input.push_back(p);
    }
    soup.id_offset.push_back(simple.size());
  }
  soup.polygons.swap(simple);
  soup.id_kept.resize(soup.id_input.size());
  std::iota(soup.id_kept.begin(), soup.id_kept.end(), std::size_t(0));
  soup.id_reversed.assign(soup.id_input.size(), false);
}

// The points of the polygon of `id` in increasing order (`flat`, `offset`: the polygons by id).
inline std::vector<std::size_t> point_set(const std::vector<std::size_t>& flat, const std::vector<std::size_t>& offset,
                                          std::size_t id)
{
  std::vector<std::size_t> points(flat.begin() + offset[id], flat.begin() + offset[id + 1]);
  std::sort(points.begin(), points.end());
  return points;
}

// Removes the duplicate polygons (CGAL: same points in the same cyclic order, either
// orientation), and records for each removed one the id of a polygon kept with the same
// points, which CGAL does not report (it erases them): their points are copied before.
template <class Point_3>
void merge_polygons(Working_soup<Point_3>& soup, Soup_repair_report& report)
{
  std::vector<std::size_t> flat, offset(1, 0);  // the polygons, in id order (simplify_polygons())
  for(const Soup_polygon& polygon : soup.polygons)
  {
    flat.insert(flat.end(), polygon.begin(), polygon.end());
    offset.push_back(flat.size());
  }
  if(Polygon_mesh_processing::merge_duplicate_polygons_in_polygon_soup(soup.points, soup.polygons) == 0)
    return;
  std::vector<bool> is_kept(soup.id_input.size(), false);
  for(const Soup_polygon& polygon : soup.polygons)
    is_kept[polygon.id] = true;
  std::map<std::vector<std::size_t>, std::vector<std::size_t> > removed;  // by their points
  std::set<std::size_t> inputs;
  for(std::size_t id = 0; id < is_kept.size(); ++id)
    if(!is_kept[id])
    {
      removed[point_set(flat, offset, id)].push_back(id);
      inputs.insert(soup.id_input[id]);
    }
  for(const Soup_polygon& polygon : soup.polygons)
  {
    const auto duplicates = removed.find(point_set(flat, offset, polygon.id));
    if(duplicates != removed.end())
      for(const std::size_t id : duplicates->second)
        soup.id_kept[id] = polygon.id;
  }
  report.duplicate_polygons = inputs.size();
}

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
void orient_soup(Working_soup<Point_3>& soup, Soup_repair_report& report)
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

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_ATLAS_SOUP_CLEANING_H
