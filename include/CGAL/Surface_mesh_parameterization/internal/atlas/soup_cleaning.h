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

// The first part of the soup stage of the repair of a polygon soup for the atlas
// (soup_repair.h): the input copied into a working soup, duplicate points merged, polygons that
// pass through a point twice simplified, duplicate polygons merged (soup_orientation.h does
// the rest). CGAL's soup functions for these steps do not say what became of each polygon,
// and take seconds on a 1M-face soup; they are written here (each function says which), with
// the bookkeeping that lets every input corner find its face later: the merged point of every
// input corner, the input polygon of every working polygon, which polygon is kept in place of
// a duplicate.

#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/Soup_repair_report.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// A polygon of the working soup, with an id that follows it through the soup functions (the
// merges erase polygons; CGAL's orient_polygon_soup() reverses them in place): a soup's
// polygons only have to be random access containers of point indices, so a vector with one
// more member passes through CGAL's functions unchanged.
struct Soup_polygon : std::vector<std::size_t>
{
  std::size_t id = 0;
};

template <class Point_3>
struct Working_soup
{
  std::vector<Point_3> points;
  std::vector<Soup_polygon> polygons;
  // per working point: the merged point it copies (the orientation adds copies)
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

// Copies the input soup, its counts into the report. ERROR_WRONG_PARAMETER for an index out
// of range, ERROR_NON_FINITE_COORDINATES for a point that is not finite (it cannot be
// ordered, so not even merged).
template <class Point_3, class PointRange, class PolygonRange>
Error_code load_soup(const PointRange& points, const PolygonRange& polygons, Working_soup<Point_3>& soup,
                     Soup_repair_report& report)
{
  report.input_points = static_cast<std::size_t>(std::distance(std::begin(points), std::end(points)));
  report.input_polygons = static_cast<std::size_t>(std::distance(std::begin(polygons), std::end(polygons)));
  soup.polygons.reserve(report.input_polygons);
  soup.corner_offset.assign(1, 0);
  for(const auto& polygon : polygons)
  {
    Soup_polygon copy;
    for(const auto i : polygon)
    {
      if(static_cast<std::size_t>(i) >= report.input_points)
        return ERROR_WRONG_PARAMETER;
      copy.push_back(static_cast<std::size_t>(i));
    }
    copy.id = soup.polygons.size();
    soup.corner_offset.push_back(soup.corner_offset.back() + copy.size());
    soup.polygons.push_back(std::move(copy));
  }
  report.input_corners = soup.corner_offset.back();
  soup.points.resize(report.input_points);
  std::size_t k = 0;
  for(const auto& p : points)
    if(!to_working_point(p, soup.points[k++]))
      return ERROR_NON_FINITE_COORDINATES;
  return OK;
}

// The first of the items equal to each item (itself when none comes before it), among items
// 0..n-1: `hash(i)` a 64-bit hash, equal items having equal hashes; `equal(i, j)`. One sort of
// (hash, item) pairs, no allocation per item.
template <class Hash, class Equal>
std::vector<std::size_t> first_of_equals(std::size_t n, Hash hash, Equal equal)
{
  std::vector<std::pair<std::uint64_t, std::size_t> > keys(n);
  for(std::size_t i = 0; i < n; ++i)
    keys[i] = std::make_pair(hash(i), i);
  std::sort(keys.begin(), keys.end());
  std::vector<std::size_t> first(n);
  std::iota(first.begin(), first.end(), std::size_t(0));
  for(std::size_t run = 0, end = 0; run < n; run = end)
  {
    while(end < n && keys[end].first == keys[run].first)
      ++end;
    for(std::size_t k = run + 1; k < end; ++k)  // items by increasing index: compared with the firsts
      for(std::size_t l = run; l < k; ++l)
        if(first[keys[l].second] == keys[l].second && equal(keys[l].second, keys[k].second))
        {
          first[keys[k].second] = keys[l].second;
          break;
        }
  }
  return first;
}

inline std::uint64_t mix_hash(std::uint64_t seed, std::uint64_t value)
{
  seed ^= value + 0x9e3779b97f4a7c15ULL + (seed << 12) + (seed >> 4);
  return seed * 0xbf58476d1ce4e5b9ULL;
}

// The bits of a coordinate, 0 and -0 alike (they compare equal).
inline std::uint64_t coordinate_bits(double x)
{
  if(x == 0.)
    x = 0.;
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  return bits;
}

// Merges the points of equal coordinates, the first of them kept, in their order, and records
// the merged point of every input corner. What CGAL's merge_duplicate_points_in_polygon_soup()
// does (same points kept, same numbering), written here for time: its std::map of points
// takes 0.6 s on the 500k points of a 1M-face soup, this sort of hashes 0.1 s.
template <class Point_3>
void merge_points(Working_soup<Point_3>& soup, Soup_repair_report& report)
{
  const std::vector<Point_3>& p = soup.points;
  const std::vector<std::size_t> first = first_of_equals(
    p.size(),
    [&p](std::size_t i) {
      return mix_hash(mix_hash(mix_hash(0, coordinate_bits(CGAL::to_double(p[i].x()))), coordinate_bits(CGAL::to_double(p[i].y()))),
                      coordinate_bits(CGAL::to_double(p[i].z())));
    },
    [&p](std::size_t i, std::size_t j) { return p[i] == p[j]; });
  std::vector<std::size_t> merged(p.size());
  std::size_t kept = 0;
  for(std::size_t i = 0; i < p.size(); ++i)
  {
    merged[i] = (first[i] == i) ? kept++ : merged[first[i]];
    soup.points[merged[i]] = soup.points[i];
  }
  report.merged_points = p.size() - kept;
  soup.points.resize(kept);
  soup.corner_point.clear();
  soup.corner_point.reserve(soup.corner_offset.back());
  for(Soup_polygon& polygon : soup.polygons)
    for(std::size_t& i : polygon)
      soup.corner_point.push_back(i = merged[i]);
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

// A polygon read from its smallest point, in the direction of its smaller neighbour: the
// same sequence for polygons with the same points in the same cyclic order, either way.
struct Canonical_polygon
{
  const Soup_polygon* polygon;
  std::size_t start;
  bool forward;

  explicit Canonical_polygon(const Soup_polygon& p) : polygon(&p), start(0), forward(true)
  {
    const std::size_t n = p.size();
    start = std::size_t(std::min_element(p.begin(), p.end()) - p.begin());
    forward = p[(start + 1) % n] < p[(start + n - 1) % n];
  }
  std::size_t size() const { return polygon->size(); }
  std::size_t operator[](std::size_t k) const
  {
    const std::size_t n = polygon->size();
    return (*polygon)[forward ? (start + k) % n : (start + n - k) % n];
  }
};

// Removes the duplicate polygons (the same points in the same cyclic order, either
// orientation: CGAL's definition), the first of each kept, and records for each removed one
// the id of the polygon kept in its place. Written here: CGAL's
// merge_duplicate_polygons_in_polygon_soup() does not say which polygon a removed one
// duplicates, which its corners need, and takes 0.7 s on a 1M-face soup (a copy of every
// polygon, a hash set), this sort of hashes 0.15 s.
template <class Point_3>
void merge_polygons(Working_soup<Point_3>& soup, Soup_repair_report& report)
{
  std::vector<Canonical_polygon> canonical;  // (the polygon at position i has id i here)
  canonical.reserve(soup.polygons.size());
  for(const Soup_polygon& polygon : soup.polygons)
    canonical.emplace_back(polygon);
  const std::vector<std::size_t> first = first_of_equals(
    canonical.size(),
    [&canonical](std::size_t i) {
      std::uint64_t h = canonical[i].size();
      for(std::size_t k = 0; k < canonical[i].size(); ++k)
        h = mix_hash(h, canonical[i][k]);
      return h;
    },
    [&canonical](std::size_t i, std::size_t j) {
      if(canonical[i].size() != canonical[j].size())
        return false;
      for(std::size_t k = 0; k < canonical[i].size(); ++k)
        if(canonical[i][k] != canonical[j][k])
          return false;
      return true;
    });
  std::vector<bool> input_has_duplicate(soup.id_offset.size(), false);
  for(std::size_t id = 0; id < first.size(); ++id)
  {
    soup.id_kept[id] = first[id];
    input_has_duplicate[soup.id_input[id]] = input_has_duplicate[soup.id_input[id]] || first[id] != id;
  }
  report.duplicate_polygons = std::size_t(std::count(input_has_duplicate.begin(), input_has_duplicate.end(), true));
  soup.polygons.erase(std::remove_if(soup.polygons.begin(), soup.polygons.end(),
                                     [&soup](const Soup_polygon& p) { return soup.id_kept[p.id] != p.id; }),
                      soup.polygons.end());
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_ATLAS_SOUP_CLEANING_H
