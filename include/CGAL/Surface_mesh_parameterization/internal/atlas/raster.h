// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_ATLAS_RASTER_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_ATLAS_RASTER_H

// Bit rasters of the atlas packer (packing.h): one bit per texel, 64 texels per word, the
// bit b of word k of a row is the column 64 k + b. A cell (column i, row j) is the closed
// square [i, i+1] x [j, j+1] of the raster's coordinates (one unit = one texel).
//
// - `rasterize_triangle()` marks every cell whose closed square meets the triangle grown by
//   `raster_epsilon` (a conservative rasterization): every point of the triangle lies in a
//   marked cell, whatever the rounding of its coordinates (errors far below the epsilon).
// - `rasterize_region()` marks the same cells for a set of triangles (the union of
//   `rasterize_triangle()` over them) from its border: the cells of the border edges, the
//   cells whose center has a nonzero winding number, and the triangles that are not surely
//   counterclockwise one by one.
// - `dilate()` grows a raster by g cells in the 8 directions (a square of side 2g+1).
// - `rotate_quarter()` turns a raster by +90 degrees: the cell (i, j) of a raster of height H
//   becomes the cell (H-1-j, i), the image of the point (x, y) is (H - y, x).
//
// The gutter argument of the packer. A chart's cells T, its dilated cells D = dilate(T, g):
// if a placed chart's T never meets another chart's D, two cells of different charts are at
// least g+1 apart in row or column index, so two points of different charts are at least g
// texels apart (in the max norm, hence in the Euclidean norm).

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// How far (in texels) the conservative rasterization grows a triangle.
constexpr double raster_epsilon = 1e-7;

inline int words_for_bits(int bits) { return (bits + 63) / 64; }

// The index of the lowest set bit of a non-zero word.
inline int lowest_bit(std::uint64_t w)
{
#if defined(__GNUC__) || defined(__clang__)
  return __builtin_ctzll(w);
#else
  int b = 0;
  while(!(w & 1u))
  {
    w >>= 1;
    ++b;
  }
  return b;
#endif
}

// The number of leading zero bits of a non-zero word.
inline int leading_zeros(std::uint64_t w)
{
#if defined(__GNUC__) || defined(__clang__)
  return __builtin_clzll(w);
#else
  int b = 0;
  while(!(w >> 63))
  {
    w <<= 1;
    ++b;
  }
  return b;
#endif
}

// A view of a raster stored in a shared word buffer (no allocation per raster).
struct Raster_view
{
  int width = 0;
  int height = 0;
  int words = 0;                   // words per row
  std::uint64_t* bits = nullptr;   // height * words words

  std::uint64_t* row(int r) const { return bits + std::size_t(r) * std::size_t(words); }
  bool test(int x, int y) const { return (row(y)[x >> 6] >> (x & 63)) & 1u; }
  void set(int x, int y) const { row(y)[x >> 6] |= std::uint64_t(1) << (x & 63); }
};

// Sets the bits x0..x1 (inclusive) of a row.
inline void set_span(std::uint64_t* row, int x0, int x1)
{
  const int k0 = x0 >> 6, k1 = x1 >> 6;
  const std::uint64_t first = ~std::uint64_t(0) << (x0 & 63);
  const std::uint64_t last = ~std::uint64_t(0) >> (63 - (x1 & 63));
  if(k0 == k1)
  {
    row[k0] |= first & last;
    return;
  }
  row[k0] |= first;
  for(int k = k0 + 1; k < k1; ++k)
    row[k] = ~std::uint64_t(0);
  row[k1] |= last;
}

// The first column >= x whose bit equals `value`, or `end` when there is none before it.
inline int next_bit(const std::uint64_t* row, int x, int end, bool value)
{
  if(x >= end)
    return end;
  int k = x >> 6;
  const int last_word = (end - 1) >> 6;
  std::uint64_t w = (value ? row[k] : ~row[k]) & (~std::uint64_t(0) << (x & 63));
  while(w == 0)
  {
    if(++k > last_word)
      return end;
    w = value ? row[k] : ~row[k];
  }
  return std::min(end, 64 * k + lowest_bit(w));
}

// Extends [lo, hi] by the part of the segment pq inside the slab y0 <= y <= y1.
inline void clip_edge_to_slab(double px, double py, double qx, double qy, double y0, double y1,
                              double& lo, double& hi)
{
  if(py > qy)
  {
    std::swap(px, qx);
    std::swap(py, qy);
  }
  if(qy < y0 || py > y1)
    return;
  double xa = px, xb = qx;
  if(qy > py)
  {
    const double slope = (qx - px) / (qy - py);
    xa = px + (std::max(py, y0) - py) * slope;
    xb = px + (std::min(qy, y1) - py) * slope;
  }
  lo = std::min(lo, std::min(xa, xb));
  hi = std::max(hi, std::max(xa, xb));
}

// Marks the cells of `raster` that the triangle (a, b, c) meets (grown by raster_epsilon);
// cells outside the raster are ignored.
inline void rasterize_triangle(const Raster_view& raster, const double* a, const double* b, const double* c)
{
  const double e = raster_epsilon;
  const double ymin = std::min(a[1], std::min(b[1], c[1])), ymax = std::max(a[1], std::max(b[1], c[1]));
  const double xmin = std::min(a[0], std::min(b[0], c[0])), xmax = std::max(a[0], std::max(b[0], c[0]));
  const int r0 = std::max(0, int(std::floor(ymin - e))), r1 = std::min(raster.height - 1, int(std::floor(ymax + e)));
  const int c0 = std::max(0, int(std::floor(xmin - e))), c1 = std::min(raster.width - 1, int(std::floor(xmax + e)));
  if(r0 > r1 || c0 > c1)
    return;
  if(r0 == r1 || c0 == c1)  // one row or one column: the bounding box is exact
  {
    for(int r = r0; r <= r1; ++r)
      set_span(raster.row(r), c0, c1);
    return;
  }
  for(int r = r0; r <= r1; ++r)
  {
    const double y0 = std::max(double(r) - e, ymin), y1 = std::min(double(r + 1) + e, ymax);
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    clip_edge_to_slab(a[0], a[1], b[0], b[1], y0, y1, lo, hi);
    clip_edge_to_slab(b[0], b[1], c[0], c[1], y0, y1, lo, hi);
    clip_edge_to_slab(c[0], c[1], a[0], a[1], y0, y1, lo, hi);
    if(lo > hi)
      continue;
    const int x0 = std::max(c0, int(std::floor(lo - e))), x1 = std::min(c1, int(std::floor(hi + e)));
    if(x0 <= x1)
      set_span(raster.row(r), x0, x1);
  }
}

// The border of a triangle set (corners indexing points): each edge whose net count over the
// triangles is not zero (a -> b counts +1 and b -> a counts -1), repeated |count| times in the
// direction of its sign. With every triangle counterclockwise the border is the boundary of
// the set's union, the outer loops counterclockwise and the holes clockwise.
template <class Triangles>
std::vector<std::array<int, 2> > signed_border_edges(const Triangles& triangles)
{
  std::vector<std::pair<std::pair<int, int>, int> > edges;  // ((smaller, larger), +1 or -1)
  for(const auto& t : triangles)
    for(int k = 0; k < 3; ++k)
    {
      const int a = int(t[std::size_t(k)]), b = int(t[std::size_t((k + 1) % 3)]);
      if(a != b)
        edges.push_back({std::minmax(a, b), a < b ? 1 : -1});
    }
  std::sort(edges.begin(), edges.end());
  std::vector<std::array<int, 2> > border;
  for(std::size_t i = 0, j = 0; i < edges.size(); i = j)
  {
    int count = 0;
    for(j = i; j < edges.size() && edges[j].first == edges[i].first; ++j)
      count += edges[j].second;
    for(; count > 0; --count)
      border.push_back({{edges[i].first.first, edges[i].first.second}});
    for(; count < 0; ++count)
      border.push_back({{edges[i].first.second, edges[i].first.first}});
  }
  return border;
}

// Whether the triangle (a, b, c) is counterclockwise for certain: its doubled area, computed
// in double, above the bound of that computation's rounding.
inline bool surely_counterclockwise(const double* a, const double* b, const double* c)
{
  const double ux = b[0] - a[0], uy = b[1] - a[1], vx = c[0] - a[0], vy = c[1] - a[1];
  return ux * vy - uy * vx > 1e-14 * (std::abs(ux) + std::abs(uy)) * (std::abs(vx) + std::abs(vy));
}

// A crossing of a border edge with the center line y = row + 1/2 of a row.
struct Row_crossing
{
  double x;
  int direction;  // +1 upward, -1 downward
  bool operator<(const Row_crossing& o) const { return x < o.x; }
};

// Work space of rasterize_region(): the crossings bucketed by row (those of row r in
// crossings[start[r], start[r + 1])).
struct Row_crossings
{
  std::vector<int> start;
  std::vector<Row_crossing> crossings;
};

// The rows [r0, r1) whose center line y = r + 1/2 a border edge from a to b crosses
// (low <= r + 1/2 < high), clamped to the raster; empty for a horizontal edge.
inline std::array<int, 2> crossed_rows(const Raster_view& raster, const double* a, const double* b)
{
  if(!(a[1] != b[1]))
    return {{0, 0}};
  const double low = std::min(a[1], b[1]), high = std::max(a[1], b[1]);
  return {{std::max(0, int(std::ceil(low - 0.5))), std::min(raster.height, int(std::ceil(high - 0.5)))}};
}

// The crossings of the border edges with the rows' center lines, bucketed by row (a counting
// sort: a global sort of the crossings cost as much as the triangles saved), each row's
// sorted by x.
inline void bucket_crossings(const Raster_view& raster, const std::vector<std::array<int, 2> >& border,
                             const double* points, Row_crossings& rows)
{
  auto p = [points](int i) { return points + 2 * std::size_t(i); };
  rows.start.assign(std::size_t(raster.height) + 1, 0);
  for(const std::array<int, 2>& e : border)
  {
    const std::array<int, 2> r = crossed_rows(raster, p(e[0]), p(e[1]));
    for(int row = r[0]; row < r[1]; ++row)
      ++rows.start[std::size_t(row) + 1];
  }
  for(std::size_t row = 0; row < std::size_t(raster.height); ++row)
    rows.start[row + 1] += rows.start[row];
  rows.crossings.resize(std::size_t(rows.start.back()));
  std::vector<int>& next = rows.start;  // filled from each row's start, shifted back below
  for(const std::array<int, 2>& e : border)
  {
    const double *a = p(e[0]), *b = p(e[1]);
    const std::array<int, 2> r = crossed_rows(raster, a, b);
    const double *low = a[1] < b[1] ? a : b, *high = a[1] < b[1] ? b : a;
    const double slope = r[0] < r[1] ? (high[0] - low[0]) / (high[1] - low[1]) : 0.;
    for(int row = r[0]; row < r[1]; ++row)
      rows.crossings[std::size_t(next[std::size_t(row)]++)] =
        Row_crossing{low[0] + (double(row) + 0.5 - low[1]) * slope, a[1] < b[1] ? 1 : -1};
  }
  for(std::size_t row = std::size_t(raster.height); row > 0; --row)
    next[row] = next[row - 1];
  next[0] = 0;
  for(std::size_t row = 0; row < std::size_t(raster.height); ++row)
    std::sort(rows.crossings.begin() + rows.start[row], rows.crossings.begin() + rows.start[row + 1]);
}

// Marks the cells of `raster` that a triangle set meets (grown by raster_epsilon), the cells
// rasterize_triangle() marks for each triangle, by its border (signed_border_edges()): the
// cells each border edge meets, then the cells whose center has a nonzero winding number of
// the border, and each triangle that is not surely counterclockwise on its own. The same cells:
// a cell that meets no border edge has its center half a cell or more away from the border,
// far beyond the rounding of the crossings, and its center is in the union of the triangles
// exactly when its winding number (the sum over the triangles that hold it of +1 if
// counterclockwise, -1 if not) is not zero or a triangle that is not counterclockwise holds
// it. Its cost is the border's and the rows', where rasterize_triangle() of every triangle
// costs a chart's area in triangles (a chart of thousands of triangles: most of a packing
// trial). `rows` is work space.
template <class Triangles>
void rasterize_region(const Raster_view& raster, const std::vector<std::array<int, 2> >& border,
                      const Triangles& triangles, const double* points, Row_crossings& rows)
{
  auto p = [points](int i) { return points + 2 * std::size_t(i); };
  for(const auto& t : triangles)
    if(!surely_counterclockwise(p(int(t[0])), p(int(t[1])), p(int(t[2]))))
      rasterize_triangle(raster, p(int(t[0])), p(int(t[1])), p(int(t[2])));
  for(const std::array<int, 2>& e : border)
    rasterize_triangle(raster, p(e[0]), p(e[1]), p(e[1]));
  bucket_crossings(raster, border, points, rows);
  for(int row = 0; row < raster.height; ++row)
  {
    int winding = 0;
    for(int i = rows.start[std::size_t(row)]; i + 1 < rows.start[std::size_t(row) + 1]; ++i)
    {
      const Row_crossing &c = rows.crossings[std::size_t(i)], &d = rows.crossings[std::size_t(i) + 1];
      winding += c.direction;
      const int c0 = std::max(0, int(std::floor(c.x - 0.5)) + 1);
      const int c1 = std::min(raster.width - 1, int(std::ceil(d.x - 0.5)) - 1);
      if(winding != 0 && c0 <= c1)
        set_span(raster.row(row), c0, c1);
    }
  }
}

// One step of the horizontal dilation of a row: every set bit also sets its two neighbours.
inline void dilate_row_once(std::uint64_t* row, int words)
{
  std::uint64_t carry_in = 0;  // the bit 63 of the previous word, before this step
  for(int k = 0; k < words; ++k)
  {
    const std::uint64_t w = row[k];
    const std::uint64_t next = k + 1 < words ? row[k + 1] : 0;
    row[k] = w | (w << 1) | (carry_in >> 63) | (w >> 1) | (next << 63);
    carry_in = w;
  }
}

// One step of the vertical dilation of a raster: every set bit also sets the bits above and
// below it.
inline void dilate_columns_once(const Raster_view& raster)
{
  for(int k = 0; k < raster.words; ++k)
  {
    std::uint64_t previous = 0;  // the row above, before this step
    for(int r = 0; r < raster.height; ++r)
    {
      std::uint64_t& w = raster.row(r)[k];
      const std::uint64_t original = w;
      w |= previous | (r + 1 < raster.height ? raster.row(r + 1)[k] : 0);
      previous = original;
    }
  }
}

// `out` (same size as `in`) = `in` dilated by g cells; bits beyond the width are cleared.
inline void dilate(const Raster_view& in, const Raster_view& out, int g)
{
  std::copy(in.bits, in.bits + std::size_t(in.height) * std::size_t(in.words), out.bits);
  const int tail = in.width & 63;
  for(int r = 0; r < in.height; ++r)
  {
    std::uint64_t* row = out.row(r);
    for(int s = 0; s < g; ++s)
      dilate_row_once(row, in.words);
    if(tail != 0)
      row[in.words - 1] &= ~(~std::uint64_t(0) << tail);
  }
  for(int s = 0; s < g; ++s)
    dilate_columns_once(out);
}

// `out` (width in.height, height in.width, cleared) = `in` turned by +90 degrees.
inline void rotate_quarter(const Raster_view& in, const Raster_view& out)
{
  for(int j = 0; j < in.height; ++j)
  {
    const std::uint64_t* row = in.row(j);
    for(int i = next_bit(row, 0, in.width, true); i < in.width; i = next_bit(row, i + 1, in.width, true))
      out.set(in.height - 1 - j, i);
  }
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_ATLAS_RASTER_H
