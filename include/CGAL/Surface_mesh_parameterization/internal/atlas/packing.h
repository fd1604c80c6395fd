// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_ATLAS_PACKING_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_ATLAS_PACKING_H

// The packing of an atlas: charts, each a triangle set in its own UV plane, become one
// texture atlas in [0,1]^2 (issue 22). Entry point: pack_atlas_charts().
//
// Why a bitmap packer and not libnest2d (measured 2026-11-26 with benchmark/atlas_packing.cpp,
// table in benchmark/README.md, one run on a shared 2-core VM): on xatlas's own charts of the
// 15 meshes of ../shared/data/atlas at resolution 1024 and gutter 2, libnest2d 5.0 (Debian's
// libnest2d-dev: its bottom-left placer on the charts' convex hulls, the same density
// search) packed nothing within 30 s on the 4 meshes of 1120 to 2350 charts and reached a
// median utilization of 0.37 on the 11 others (its no-fit-polygon placer: 0.41 in 30 s on
// 112 charts, 68 s for one trial on 304); this packer: median 0.620 on all 15 (xatlas: 0.603
// in its own non-square atlas, 0.590 in a square) in 0.012 to 0.42 s of processor time
// (median 0.097 s, xatlas's packer alone 0.103 s). libnest2d nests polygons: hulls, one chart
// never in another's concavity; a rasterized packer interlocks charts at texel precision,
// keeps the gutter exactly in texels, and needs no dependency.
//
// 1. One texel density. Each chart is scaled so that its UV area equals its 3D area; one
//    global density then serves all charts: UV area / 3D area is the same for every chart.
// 2. Each chart is turned to its smallest bounding box (min_area_rectangle.h: rotating
//    calipers on the convex hull).
// 3. At a trial density the charts are rasterized conservatively (raster.h; a chart by its
//    border, rasterize_region(): the cells of its triangles at the cost of its border and
//    rows, 0-20% off the packing of small meshes, outputs unchanged), each raster dilated by
//    the gutter, and placed from the largest box down at the first free position
//    of the square (placement.h: the lowest row, then the leftmost column), trying 0 and 90
//    degrees. A chart's own texels stay a gutter away from the square's border. A search
//    starts below the rows where the mask of a chart placed just before, contained in this
//    chart's mask, did not fit (the atlas only fills).
// 4. A trial that places every chart is scaled up about the corner (gutter, gutter) until its
//    farthest point is a gutter away from the border (the gutters only grow). The first trial
//    density comes from the charts' areas and box perimeters; the next from the last trial's
//    fill (its share of rows used, or for a failure its share of the charts' frames placed:
//    area grows as the density squared), kept inside the bracket of the best fit and the
//    smallest failure, else bisection. It stops when the fit fills (1 + tolerance)^-2 of the
//    rows, or the bracket is within the tolerance, or after two failures in a row past the
//    first fit (a failure costs about what a success does: on the 30 meshes of the atlas
//    benchmark this takes up to a third off the packing of a few charts, nefertiti-entire
//    0.024 to 0.016 s, and changes no utilization but moebius's, 0.269 to 0.265, and pig's,
//    0.685 to 0.673), or after max_attempts trials past the first fit; the best scaled-up
//    trial wins.
//
// Guarantees (tested in test_atlas_packing.cpp): every output UV is in [0,1]^2; the triangles
// of two charts are at least `gutter` texels apart, and at least `gutter` texels from the
// border of the square (1 texel = 1 / resolution); a chart is moved by a similarity (uniform
// scale, rotation, translation); UV area / 3D area is equal across non-degenerate charts;
// the output depends only on the input (the clock only feeds the statistics; no threads).
// Above `max_raster_resolution` texels the rasters are coarser (the gutter rounded up in
// their texels): same guarantees. The work buffers are allocated per trial, not per chart or
// texel.
//
// Degenerate charts (zero 3D area or zero UV area: a chart of zero-area faces, a single
// point) are placed too, each in one texel of its own: a chart of zero 3D area and positive
// UV area becomes a point (its UV area is then 0, as its density asks), any other keeps its
// shape scaled into half a texel.

#include <CGAL/Surface_mesh_parameterization/internal/atlas/charts.h>
#include <CGAL/Surface_mesh_parameterization/internal/atlas/min_area_rectangle.h>
#include <CGAL/Surface_mesh_parameterization/internal/atlas/placement.h>
#include <CGAL/Surface_mesh_parameterization/internal/atlas/raster.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/triangle_geometry.h>
#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// A chart to pack: triangles (indices into `uv`) in the chart's own UV plane, and the sum of
// the 3D areas of its faces. A chart without triangles is the set of its UV points.
struct Chart_to_pack
{
  std::vector<Eigen::Vector2d> uv;
  std::vector<Face_indices> triangles;
  double area_3d = 0.;
};

// A chart of charts.h as a chart to pack (three UVs per face, in the order of its faces).
inline Chart_to_pack chart_to_pack(const Atlas_chart& chart)
{
  Chart_to_pack result;
  result.uv.reserve(3 * chart.corners.size());
  result.triangles.reserve(chart.corners.size());
  for(const std::array<Eigen::Vector2d, 3>& corners : chart.corners)
  {
    const int first = int(result.uv.size());
    result.uv.insert(result.uv.end(), corners.begin(), corners.end());
    result.triangles.push_back(Face_indices{{first, first + 1, first + 2}});
  }
  result.area_3d = chart.area_3d;
  return result;
}

struct Atlas_packing_options
{
  int resolution = 1024;             // texels per side of [0,1]^2
  int gutter = 2;                    // texels between two charts, and to the border, at least
  bool quarter_turns = true;         // whether a chart may also be placed turned by 90 degrees
  double density_tolerance = 0.01;   // relative precision of the search of the density (linear)
  int max_attempts = 8;              // trial densities after the first one that fits
  int max_raster_resolution = 2048;  // the rasters' resolution at most
};

// The similarity that places a chart: uv -> scale * rotation(cos, sin) * uv + translation.
struct Chart_similarity
{
  double scale = 0.;
  double cos_angle = 1.;
  double sin_angle = 0.;
  Eigen::Vector2d translation = Eigen::Vector2d::Zero();
  bool degenerate = false;  // a chart of zero 3D or UV area, placed in one texel

  Eigen::Vector2d apply(const Eigen::Vector2d& p) const
  {
    return scale * Eigen::Vector2d(cos_angle * p.x() - sin_angle * p.y(), sin_angle * p.x() + cos_angle * p.y())
           + translation;
  }
};

struct Atlas_packing_statistics
{
  double seconds = 0.;             // the whole packing
  double raster_seconds = 0.;      // rasterizations (every attempt)
  double placement_seconds = 0.;   // searches of free positions (every attempt)
  int attempts = 0;                // trial densities
  std::size_t charts = 0;
  std::size_t degenerate_charts = 0;
  std::size_t turned_charts = 0;   // placed turned by 90 degrees
  double texel_density = 0.;       // UV area / 3D area of every non-degenerate chart
  double raster_resolution = 0.;   // texels per side of the rasters
  double raster_gutter = 0.;       // the gutter in those texels
};

struct Atlas_packing
{
  Error_code status = OK;  // ERROR_WRONG_PARAMETER, ERROR_NON_FINITE_COORDINATES or OK
  std::vector<Chart_similarity> transforms;       // per chart
  std::vector<std::vector<Eigen::Vector2d> > uv;  // per chart: transforms[c].apply(uv) in [0,1]^2
  double utilization = 0.;  // total UV area of the charts / area of [0,1]^2
  Atlas_packing_statistics statistics;
};

// ---------------------------------------------------------------------------------------
// 1 and 2: a chart scaled to its 3D area and turned to its smallest box

// The sum of the absolute areas of the triangles.
inline double triangle_set_area(const std::vector<Eigen::Vector2d>& uv, const std::vector<Face_indices>& triangles)
{
  double area = 0.;
  for(const Face_indices& t : triangles)
  {
    const Eigen::Vector2d e1 = uv[std::size_t(t[1])] - uv[std::size_t(t[0])];
    const Eigen::Vector2d e2 = uv[std::size_t(t[2])] - uv[std::size_t(t[0])];
    area += 0.5 * std::abs(e1.x() * e2.y() - e1.y() * e2.x());
  }
  return area;
}

// ERROR_WRONG_PARAMETER for a triangle index out of range, ERROR_NON_FINITE_COORDINATES for a
// UV or an area that is not finite (or a negative area), OK otherwise.
inline Error_code check_chart(const Chart_to_pack& chart)
{
  for(const Face_indices& t : chart.triangles)
    for(int v : t)
      if(v < 0 || std::size_t(v) >= chart.uv.size())
        return ERROR_WRONG_PARAMETER;
  for(const Eigen::Vector2d& p : chart.uv)
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()))
      return ERROR_NON_FINITE_COORDINATES;
  return std::isfinite(chart.area_3d) && chart.area_3d >= 0. ? OK : ERROR_NON_FINITE_COORDINATES;
}

// A chart ready to be packed: p -> scale * box.rotate(p) - low puts it in [0, extent].
// Non-degenerate: in units of the square root of 3D area (the density multiplies it);
// degenerate: in texels.
struct Packing_chart
{
  double scale = 0.;
  Min_area_rectangle box;
  Eigen::Vector2d low = Eigen::Vector2d::Zero();
  Eigen::Vector2d extent = Eigen::Vector2d::Zero();
  double area_3d = 0.;
  bool degenerate = false;
  std::vector<int> loose_points;  // the UVs of no triangle (rasterized as points)
  std::vector<std::array<int, 2> > border;  // signed_border_edges() of its triangles
};

// The scale of a chart: its UV area to its 3D area; a degenerate chart: into half a texel,
// or 0 (a point) when its 3D area is 0 and its UV area is not.
inline void chart_scale(const Chart_to_pack& chart, Packing_chart& result)
{
  const double uv_area = triangle_set_area(chart.uv, chart.triangles);
  const double scale = uv_area > 0. ? std::sqrt(chart.area_3d / uv_area) : 0.;
  result.degenerate = !(chart.area_3d > 0. && uv_area > 0. && std::isfinite(scale) && scale > 0.);
  if(!result.degenerate)
    result.scale = scale;
  else if(!(chart.area_3d == 0. && uv_area > 0.) && result.box.width > 0.)
    result.scale = 0.5 / result.box.width;
}

// The border of a chart's triangles (signed_border_edges()), the UVs of equal coordinates
// taken as one vertex (chart_to_pack() gives each face its own three).
inline std::vector<std::array<int, 2> > chart_border(const Chart_to_pack& chart)
{
  std::vector<int> order(chart.uv.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&chart](int a, int b) {
    const Eigen::Vector2d &p = chart.uv[std::size_t(a)], &q = chart.uv[std::size_t(b)];
    return p.x() != q.x() ? p.x() < q.x() : p.y() != q.y() ? p.y() < q.y() : a < b;
  });
  std::vector<int> same(chart.uv.size());
  for(std::size_t i = 0; i < order.size(); ++i)
  {
    const std::size_t v = std::size_t(order[i]);
    same[v] = (i > 0 && chart.uv[v] == chart.uv[std::size_t(order[i - 1])]) ? same[std::size_t(order[i - 1])] : int(v);
  }
  std::vector<Face_indices> welded(chart.triangles.size());
  for(std::size_t f = 0; f < welded.size(); ++f)
    for(std::size_t k = 0; k < 3; ++k)
      welded[f][k] = same[std::size_t(chart.triangles[f][k])];
  return signed_border_edges(welded);
}

inline Packing_chart normalize_chart(const Chart_to_pack& chart)
{
  Packing_chart result;
  result.box = min_area_rectangle(chart.uv);
  result.area_3d = chart.area_3d;
  chart_scale(chart, result);
  Eigen::Vector2d high(-HUGE_VAL, -HUGE_VAL);
  result.low = Eigen::Vector2d(HUGE_VAL, HUGE_VAL);
  for(const Eigen::Vector2d& p : chart.uv)
  {
    const Eigen::Vector2d q = result.scale * result.box.rotate(p);
    result.low = result.low.cwiseMin(q);
    high = high.cwiseMax(q);
  }
  if(chart.uv.empty())
    result.low = high = Eigen::Vector2d::Zero();
  result.extent = high - result.low;
  std::vector<bool> used(chart.uv.size(), false);
  for(const Face_indices& t : chart.triangles)
    used[std::size_t(t[0])] = used[std::size_t(t[1])] = used[std::size_t(t[2])] = true;
  for(std::size_t v = 0; v < used.size(); ++v)
    if(!used[v])
      result.loose_points.push_back(int(v));
  result.border = chart_border(chart);
  return result;
}

// ---------------------------------------------------------------------------------------
// 3: the rasters of the charts at one density

// How far (in texels) a chart's lower corner lies inside its first cell: more than the
// rasterization's epsilon, so that a point chart occupies one cell.
constexpr double frame_inset = 1e-6;

// Bands of the masks: at most 2^4 rows (placement.h).
constexpr int mask_band_level = 4;

// The rasters' resolution and gutter, and what a trial density decides.
struct Raster_setup
{
  int resolution = 0;
  int gutter = 0;
  bool quarter_turns = true;
};

// A chart's frame at one density: its cells T span `cells` texels; the frame is cells + 2
// gutter on each side. Turned by q quarters: `cells_words[q]` and `mask_words[q]`, the
// offsets of T and D in the workspace's pool; runs and bands of D in the workspace's lists.
struct Chart_frame
{
  double texels_per_unit = 0.;
  std::array<int, 2> cells{{0, 0}};
  std::array<std::size_t, 2> cells_words{{0, 0}};
  std::array<std::size_t, 2> mask_words{{0, 0}};
  std::array<std::size_t, 2> runs{{0, 0}};
  std::array<int, 2> run_count{{0, 0}};
  std::array<std::size_t, 2> bands{{0, 0}};
  std::array<int, 2> band_count{{0, 0}};
};

// Where a chart is placed: its frame origin in atlas texels, and its quarter turn.
struct Chart_placement
{
  int x = 0;
  int y = 0;
  int quarter = 0;
};

// The buffers of the packer, reused by every attempt (no allocation per chart or per texel).
struct Packing_workspace
{
  std::vector<Chart_frame> frames;
  std::vector<std::uint64_t> pool;
  std::vector<Mask_run> runs;
  std::vector<Mask_band> bands;
  std::vector<int> run_begin, run_end;
  std::vector<double> points;
  Row_crossings crossings;
  std::vector<Chart_placement> placements;
  std::vector<std::array<int, 2> > reach;  // per chart and quarter: the rows above it do not fit its mask
  std::vector<int> lifetimes, summary_lifetimes;
  Atlas_occupancy occupancy;
  double placed_area = 0.;  // the frames' areas of the charts placed by the last attempt
};

// The frame width and height of a chart turned by `quarter` quarters.
inline std::array<int, 2> frame_size(const Chart_frame& frame, int quarter, int gutter)
{
  const int w = frame.cells[0] + 2 * gutter, h = frame.cells[1] + 2 * gutter;
  return quarter == 0 ? std::array<int, 2>{{w, h}} : std::array<int, 2>{{h, w}};
}

// The raster of a chart's cells (`mask` false) or of its dilated cells (`mask` true).
inline Raster_view frame_raster(Packing_workspace& ws, const Chart_frame& frame, int quarter, bool mask, int gutter)
{
  const std::array<int, 2> size = frame_size(frame, quarter, gutter);
  const std::size_t offset = mask ? frame.mask_words[std::size_t(quarter)] : frame.cells_words[std::size_t(quarter)];
  return Raster_view{size[0], size[1], words_for_bits(size[0]), ws.pool.data() + offset};
}

// A point of a chart in its unturned frame (texels).
inline Eigen::Vector2d frame_point(const Packing_chart& chart, const Chart_frame& frame, const Eigen::Vector2d& p,
                                   int gutter)
{
  const Eigen::Vector2d q = chart.scale * chart.box.rotate(p);
  return frame.texels_per_unit * (q - chart.low) + Eigen::Vector2d::Constant(double(gutter) + frame_inset);
}

// The number of cells that a chart's extent spans in its frame.
inline int cell_count(double texels, int gutter)
{
  const double last = std::floor(double(gutter) + frame_inset + texels + raster_epsilon);
  return int(last) - gutter + 1;
}

// Sizes the frames of the charts (degenerate ones in texels) at the density `texels_per_unit`.
// False when a frame is larger than the atlas.
inline bool size_frames(const std::vector<Packing_chart>& charts, double texels_per_unit, const Raster_setup& setup,
                        Packing_workspace& ws)
{
  ws.frames.resize(charts.size());
  for(std::size_t c = 0; c < charts.size(); ++c)
  {
    Chart_frame& frame = ws.frames[c];
    frame.texels_per_unit = charts[c].degenerate ? 1. : texels_per_unit;
    const double span = std::max(charts[c].extent.x(), charts[c].extent.y()) * frame.texels_per_unit;
    if(!(span < double(setup.resolution)))
      return false;
    for(int axis = 0; axis < 2; ++axis)
      frame.cells[std::size_t(axis)] = cell_count(frame.texels_per_unit * charts[c].extent[axis], setup.gutter);
    if(std::max(frame.cells[0], frame.cells[1]) + 2 * setup.gutter > setup.resolution)
      return false;
  }
  return true;
}

// Lays out the rasters of the sized frames in the pool (cleared).
inline void layout_rasters(const Raster_setup& setup, Packing_workspace& ws)
{
  std::size_t words = 0;
  for(Chart_frame& frame : ws.frames)
    for(int quarter = 0; quarter < 2; ++quarter)
    {
      const std::array<int, 2> size = frame_size(frame, quarter, setup.gutter);
      const std::size_t raster_words = std::size_t(size[1]) * std::size_t(words_for_bits(size[0]));
      frame.cells_words[std::size_t(quarter)] = words;
      frame.mask_words[std::size_t(quarter)] = words + raster_words;
      words += 2 * raster_words;
    }
  ws.pool.assign(words, 0);
  ws.runs.clear();
  ws.bands.clear();
}

// The runs and bands of a chart's dilated raster turned by `quarter`.
inline void compute_mask(Chart_frame& frame, int quarter, const Raster_view& mask, Packing_workspace& ws)
{
  const std::size_t q = std::size_t(quarter);
  frame.runs[q] = ws.runs.size();
  compute_mask_runs(mask, ws.runs);
  frame.run_count[q] = int(ws.runs.size() - frame.runs[q]);
  frame.bands[q] = ws.bands.size();
  compute_mask_bands(mask, mask_band_level, ws.bands, ws.run_begin, ws.run_end);
  frame.band_count[q] = int(ws.bands.size() - frame.bands[q]);
}

// Marks the cells of a chart's triangles (rasterize_region(): by its border) and loose
// points, given by their frame points.
inline void rasterize_points(const Raster_view& cells, const Chart_to_pack& input, const Packing_chart& chart,
                             const double* points, Row_crossings& rows)
{
  rasterize_region(cells, chart.border, input.triangles, points, rows);
  for(int v : chart.loose_points)  // a triangle's raster covers its corners
    rasterize_triangle(cells, points + 2 * v, points + 2 * v, points + 2 * v);
}

// The cells T of a chart turned by a quarter: its turned points rasterized (as cheap as the
// first raster) when it has few triangles for its cells, else the first raster turned (one
// step per cell).
inline void rasterize_turned(const Chart_to_pack& input, const Packing_chart& chart, const Chart_frame& frame,
                             const Raster_setup& setup, Packing_workspace& ws)
{
  const Raster_view cells = frame_raster(ws, frame, 0, false, setup.gutter);
  const Raster_view turned = frame_raster(ws, frame, 1, false, setup.gutter);
  if(32. * double(input.triangles.size()) > double(frame.cells[0]) * double(frame.cells[1]))
  {
    rotate_quarter(cells, turned);
    return;
  }
  const double height = double(cells.height);  // (x, y) -> (height - y, x)
  for(std::size_t v = 0; v < input.uv.size(); ++v)
  {
    const double x = ws.points[2 * v];
    ws.points[2 * v] = height - ws.points[2 * v + 1];
    ws.points[2 * v + 1] = x;
  }
  rasterize_points(turned, input, chart, ws.points.data(), ws.crossings);
}

// Rasterizes one chart's triangles and loose points (cells T), turned too, then its dilated
// rasters and their runs and bands.
inline void rasterize_chart(const Chart_to_pack& input, const Packing_chart& chart, Chart_frame& frame,
                            const Raster_setup& setup, Packing_workspace& ws)
{
  ws.points.resize(2 * input.uv.size());
  for(std::size_t v = 0; v < input.uv.size(); ++v)
  {
    const Eigen::Vector2d p = frame_point(chart, frame, input.uv[v], setup.gutter);
    ws.points[2 * v] = p.x();
    ws.points[2 * v + 1] = p.y();
  }
  rasterize_points(frame_raster(ws, frame, 0, false, setup.gutter), input, chart, ws.points.data(), ws.crossings);
  if(setup.quarter_turns)
    rasterize_turned(input, chart, frame, setup, ws);
  for(int quarter = 0; quarter < (setup.quarter_turns ? 2 : 1); ++quarter)
  {
    const Raster_view mask = frame_raster(ws, frame, quarter, true, setup.gutter);
    dilate(frame_raster(ws, frame, quarter, false, setup.gutter), mask, setup.gutter);
    compute_mask(frame, quarter, mask, ws);
  }
}

// ---------------------------------------------------------------------------------------
// 3 (continued): the placement of the rasters

// Whether the dilated raster of the chart `a` turned by `qa` is a subset of that of `b`
// turned by `qb` (of the same size).
inline bool mask_contained(const Packing_workspace& ws, std::size_t a, int qa, std::size_t b, int qb, int gutter)
{
  const std::array<int, 2> size = frame_size(ws.frames[a], qa, gutter);
  if(size != frame_size(ws.frames[b], qb, gutter))
    return false;
  const std::uint64_t* p = ws.pool.data() + ws.frames[a].mask_words[std::size_t(qa)];
  const std::uint64_t* q = ws.pool.data() + ws.frames[b].mask_words[std::size_t(qb)];
  const std::size_t words = std::size_t(size[1]) * std::size_t(words_for_bits(size[0]));
  for(std::size_t k = 0; k < words; ++k)
    if((p[k] & ~q[k]) != 0)
      return false;
  return true;
}

// The first row where the chart `c` turned by `quarter` may fit: the reach of the searches
// of the last charts placed (at most 32, `done` of them) whose mask its mask contains.
inline int known_unfit_rows(const Packing_workspace& ws, const std::vector<std::size_t>& order, std::size_t done,
                            std::size_t c, int quarter, const Raster_setup& setup)
{
  int y = 0;
  for(std::size_t i = done; i-- > 0 && done - i <= 32;)
    for(int q = 0; q < (setup.quarter_turns ? 2 : 1); ++q)
      if(ws.reach[order[i]][std::size_t(q)] > y && mask_contained(ws, order[i], q, c, quarter, setup.gutter))
        y = ws.reach[order[i]][std::size_t(q)];
  return y;
}

// The first position of the chart `c` (the done-th of `order`) turned by `quarter` whose
// frame's bottom row is above `bottom` (or at `bottom` and left of `left`); x = -1 when there
// is none.
inline Frame_position find_position(Packing_workspace& ws, const std::vector<std::size_t>& order, std::size_t done,
                                    int quarter, int bottom, int left, const Raster_setup& setup)
{
  const std::size_t c = order[done], q = std::size_t(quarter);
  const Chart_frame& frame = ws.frames[c];
  const std::array<int, 2> size = frame_size(frame, quarter, setup.gutter);
  const Chart_mask mask{ws.runs.data() + frame.runs[q], frame.run_count[q], ws.bands.data() + frame.bands[q],
                        frame.band_count[q]};
  const int y_max = std::min(setup.resolution, bottom) - size[1];
  const int start = known_unfit_rows(ws, order, done, c, quarter, setup);
  const Frame_position found = ws.occupancy.find(mask, setup.resolution - size[0], y_max, start, ws.reach[c][q]);
  if(found.x >= 0 && found.y + size[1] == bottom && found.x >= left)
    return Frame_position();
  return found;
}

// Starts the occupancy's windows (placement.h) with their lifetimes: a level (k, m) is read
// by the search of the i-th chart of `order` (i charts placed) when one of its masks has a
// band (windows and summaries) or a run (windows) of that level.
inline void start_occupancy(const std::vector<std::size_t>& order, const Raster_setup& setup, Packing_workspace& ws)
{
  Atlas_occupancy& o = ws.occupancy;
  o.reset(setup.resolution, mask_band_level);
  ws.lifetimes.assign(o.table_count(), 0);
  ws.summary_lifetimes.assign(o.table_count(), 0);
  for(std::size_t i = 0; i < order.size(); ++i)
    for(std::size_t q = 0; q < (setup.quarter_turns ? 2u : 1u); ++q)
    {
      const Chart_frame& f = ws.frames[order[i]];
      for(int b = 0; b < f.band_count[q]; ++b)
      {
        const Mask_band& band = ws.bands[f.bands[q] + std::size_t(b)];
        ws.lifetimes[o.table(band.level, band.row_level)] = int(i) + 1;
        ws.summary_lifetimes[o.table(band.level, band.row_level)] = int(i) + 1;
      }
      for(int r = 0; r < f.run_count[q]; ++r)
        ws.lifetimes[o.table(ws.runs[f.runs[q] + std::size_t(r)].level, 0)] = int(i) + 1;
    }
  o.start(ws.lifetimes, ws.summary_lifetimes);
}

// Places the charts in `order`; false when one finds no place (ws.placed_area: the frames'
// area of those placed).
inline bool place_charts(const std::vector<std::size_t>& order, const Raster_setup& setup, Packing_workspace& ws)
{
  start_occupancy(order, setup, ws);
  ws.placements.assign(ws.frames.size(), Chart_placement());
  ws.reach.assign(ws.frames.size(), std::array<int, 2>{{0, 0}});
  ws.placed_area = 0.;
  for(std::size_t done = 0; done < order.size(); ++done)
  {
    const std::size_t c = order[done];
    const Chart_frame& frame = ws.frames[c];
    Chart_placement best;
    int bottom = setup.resolution + 1, left = 0;
    for(int quarter = 0; quarter < (setup.quarter_turns ? 2 : 1); ++quarter)
    {
      const Frame_position p = find_position(ws, order, done, quarter, bottom, left, setup);
      if(p.x < 0)
        continue;
      best = Chart_placement{p.x, p.y, quarter};
      bottom = p.y + frame_size(frame, quarter, setup.gutter)[1];
      left = p.x;
    }
    if(bottom > setup.resolution)
      return false;
    ws.placements[c] = best;
    ws.occupancy.place(frame_raster(ws, frame, best.quarter, false, setup.gutter), best.x, best.y);
    ws.placed_area += double(frame.cells[0] + setup.gutter) * double(frame.cells[1] + setup.gutter);
  }
  return true;
}

// ---------------------------------------------------------------------------------------
// 4: the search of the density

typedef std::chrono::steady_clock Packing_clock;

inline double seconds_since(Packing_clock::time_point start)
{
  return std::chrono::duration<double>(Packing_clock::now() - start).count();
}

// The charts from the largest box down (degenerate charts last), ties by index.
inline std::vector<std::size_t> packing_order(const std::vector<Packing_chart>& charts)
{
  std::vector<std::size_t> order(charts.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  const auto key = [&charts](std::size_t c) {
    return charts[c].degenerate ? -1. : charts[c].extent.x() * charts[c].extent.y();
  };
  std::stable_sort(order.begin(), order.end(), [&key](std::size_t a, std::size_t b) { return key(a) > key(b); });
  return order;
}

// The packer's input at one density, and the charts' order.
struct Packing_problem
{
  const std::vector<Chart_to_pack>& input;
  const std::vector<Packing_chart>& charts;
  std::vector<std::size_t> order;
  Raster_setup setup;
};

// One attempt: rasterizes and places every chart at the density `texels_per_unit`.
inline bool try_density(const Packing_problem& problem, double texels_per_unit, Packing_workspace& ws,
                        Atlas_packing_statistics& stats)
{
  ++stats.attempts;
  Packing_clock::time_point start = Packing_clock::now();
  ws.placed_area = 0.;
  const bool sized = size_frames(problem.charts, texels_per_unit, problem.setup, ws);
  if(sized)
  {
    layout_rasters(problem.setup, ws);
    for(std::size_t c = 0; c < problem.charts.size(); ++c)
      rasterize_chart(problem.input[c], problem.charts[c], ws.frames[c], problem.setup, ws);
  }
  stats.raster_seconds += seconds_since(start);
  if(!sized)
    return false;
  start = Packing_clock::now();
  const bool placed = place_charts(problem.order, problem.setup, ws);
  stats.placement_seconds += seconds_since(start);
  return placed;
}

// The frames' total area at the density d (texels): each chart's cells and one gutter.
inline double frames_area(const Packing_problem& problem, double d)
{
  const double g = double(problem.setup.gutter) + 1.;
  double area = 0.;
  for(const Packing_chart& c : problem.charts)
    area += c.degenerate ? g * g : (c.extent.x() * d + g) * (c.extent.y() * d + g);
  return area;
}

// The density at which the charts' areas, each grown by a band of half a gutter and half a
// texel along its box's perimeter, are `share` of the atlas (0 when even tiny charts exceed
// it): a root of a quadratic in d. On xatlas's charts, the packed density makes this share
// 0.96 to 1.06 for the meshes of hundreds of charts (benchmark/atlas_packing.cpp), less for
// a few large charts.
inline double density_for_share(const Packing_problem& problem, double share)
{
  const double g = 0.5 * double(problem.setup.gutter) + 0.5;
  double a = 0., b = 0., c = 0.;
  for(const Packing_chart& chart : problem.charts)
  {
    a += chart.degenerate ? 0. : chart.area_3d;
    b += chart.degenerate ? 0. : 4. * g * (chart.extent.x() + chart.extent.y());
    c += chart.degenerate ? 4. * (g + 0.5) * (g + 0.5) : 16. * g * g;
  }
  const double r = double(problem.setup.resolution), rest = share * r * r - c;
  if(!(a > 0.) || !(rest > 0.))
    return 0.;
  return 2. * rest / (b + std::sqrt(b * b + 4. * a * rest));
}

// The largest density at which the largest chart's frame fits in the atlas.
inline double largest_density(const Packing_problem& problem)
{
  double extent = 0.;
  for(const Packing_chart& c : problem.charts)
    if(!c.degenerate)
      extent = std::max(extent, c.extent.maxCoeff());
  const double room = double(problem.setup.resolution - 2 * problem.setup.gutter - 2);
  return extent > 0. && room > 0. ? room / extent : HUGE_VAL;
}

// The scale factor >= 1 about (gutter, gutter) that brings the placed charts' farthest point
// a gutter away from the atlas's border.
inline double growth_factor(const Packing_problem& problem, const Packing_workspace& ws)
{
  const Raster_setup& s = problem.setup;
  double far = double(s.gutter);
  for(std::size_t c = 0; c < problem.charts.size(); ++c)
  {
    const Chart_frame& frame = ws.frames[c];
    const Chart_placement& p = ws.placements[c];
    const std::array<int, 2> size = frame_size(frame, p.quarter, s.gutter);
    far = std::max(far, double(std::max(p.x + size[0], p.y + size[1]) - s.gutter));
  }
  return far > double(s.gutter) ? std::max(1., double(s.resolution - 2 * s.gutter) / (far - double(s.gutter))) : 1.;
}

// The best attempt so far: its trial density, its growth and placements.
struct Packing_trial
{
  double density = 0.;
  double growth = 1.;
  std::vector<Chart_placement> placements;
  double result() const { return density * growth; }
};

// The next trial density after `last`, which filled `fill` of the atlas (a success: the
// share of rows used; a failure: the frames' area / the area of those placed, above 1): the
// area grows as the square of the density, so fill 1 is expected at last / sqrt(fill). It is
// kept inside the bracket (`fit`: the best result, 0 when none; `no_fit`: the smallest
// failure, HUGE_VAL when none), away from its ends, else the bracket is bisected.
inline double next_density(double last, double fill, double fit, double no_fit, double tolerance)
{
  const double guess = last / std::sqrt(std::max(fill, 1e-6)) * (fill > 1. ? 0.99 : 1.);
  const double low = fit * (1. + 2. * tolerance), high = no_fit / (1. + tolerance);
  if(fit == 0.)
    return std::min(guess, last * 0.95);
  if(no_fit == HUGE_VAL)
    return std::max(guess, low);
  return guess >= low && guess <= high ? guess : std::sqrt(fit * no_fit);
}

// The share of the atlas's rows that the placed charts use (a success), or the frames' area
// / the area of those placed (a failure).
inline double atlas_fill(const Packing_problem& problem, double d, bool fits, const Packing_workspace& ws)
{
  if(!fits)
    return frames_area(problem, d) / std::max(ws.placed_area, 1.);
  int used = 0;
  for(std::size_t c = 0; c < problem.charts.size(); ++c)
    used = std::max(used, ws.placements[c].y + frame_size(ws.frames[c], ws.placements[c].quarter, problem.setup.gutter)[1]);
  return double(used) / double(problem.setup.resolution);
}

// The density at which every chart is smaller than a thousandth of a texel.
inline double smallest_density(const Packing_problem& problem)
{
  double extent = 0.;
  for(const Packing_chart& c : problem.charts)
    if(!c.degenerate)
      extent = std::max(extent, c.extent.maxCoeff());
  return extent > 0. ? 1e-3 / extent : 1.;
}

// The largest density (texels per unit) found at which the charts pack, grown; the trial in
// `best`. 0 when none does (more charts than the atlas holds with this gutter).
inline double search_density(const Packing_problem& problem, const Atlas_packing_options& options,
                             Packing_workspace& ws, Packing_trial& best, Atlas_packing_statistics& stats)
{
  const double smallest = smallest_density(problem), largest = largest_density(problem);
  double d = std::min(largest, std::max(smallest, density_for_share(problem, 0.97))), no_fit = HUGE_VAL;
  for(int after_fit = 0, failures = 0;;)  // trials past the first fit, failures in a row past it
  {
    const bool fits = try_density(problem, d, ws, stats);
    const double growth = fits ? growth_factor(problem, ws) : 1.;
    if(fits && d * growth > best.result())
      best = Packing_trial{d, growth, ws.placements};
    if(!fits)
      no_fit = std::min(no_fit, d);
    const double fill = atlas_fill(problem, d, fits, ws), tolerance = 1. + options.density_tolerance;
    after_fit += best.density > 0. ? 1 : 0;
    failures = (fits || best.density == 0.) ? 0 : failures + 1;
    const bool done = no_fit <= best.result() * tolerance || (fits && fill * tolerance * tolerance >= 1.)
                      || (fits && d >= largest) || after_fit > options.max_attempts || failures >= 2;
    if((best.density > 0. && done) || (best.density == 0. && (d <= smallest || stats.attempts >= 64)))
      break;
    d = std::min(largest, std::max(smallest, next_density(d, fill, best.result(), no_fit, options.density_tolerance)));
  }
  return best.result();
}

// ---------------------------------------------------------------------------------------
// The output

// The similarity of a placed chart: the frame point of the rasterization, turned, moved to
// the placement, grown about (gutter, gutter), divided by the resolution.
inline Chart_similarity chart_similarity(const Packing_chart& chart, const Chart_frame& frame,
                                         const Chart_placement& placement, double growth, const Raster_setup& s)
{
  const double resolution = double(s.resolution), g = double(s.gutter);
  const double height = double(frame_size(frame, 0, s.gutter)[1]);
  const Eigen::Vector2d zero = frame_point(chart, frame, Eigen::Vector2d::Zero(), s.gutter);
  const Eigen::Vector2d turned = placement.quarter == 0 ? zero : Eigen::Vector2d(height - zero.y(), zero.x());
  const Eigen::Vector2d origin(double(placement.x), double(placement.y));
  Chart_similarity t;
  t.degenerate = chart.degenerate;
  t.scale = growth * frame.texels_per_unit * chart.scale / resolution;
  t.cos_angle = placement.quarter == 0 ? chart.box.cos_angle : -chart.box.sin_angle;
  t.sin_angle = placement.quarter == 0 ? chart.box.sin_angle : chart.box.cos_angle;
  t.translation = (Eigen::Vector2d::Constant(g) + growth * (turned + origin - Eigen::Vector2d::Constant(g))) / resolution;
  return t;
}

// Writes the placed charts, their similarities, the utilization and the counters.
inline void finish_packing(const Packing_problem& problem, const Packing_trial& trial, const Packing_workspace& ws,
                           Atlas_packing& result)
{
  result.transforms.resize(problem.input.size());
  result.uv.resize(problem.input.size());
  for(std::size_t c = 0; c < problem.input.size(); ++c)
  {
    const Chart_similarity& t = result.transforms[c] =
        chart_similarity(problem.charts[c], ws.frames[c], trial.placements[c], trial.growth, problem.setup);
    result.uv[c].resize(problem.input[c].uv.size());
    for(std::size_t v = 0; v < problem.input[c].uv.size(); ++v)
      result.uv[c][v] = t.apply(problem.input[c].uv[v]).cwiseMax(Eigen::Vector2d::Zero()).cwiseMin(Eigen::Vector2d::Ones());
    result.utilization += triangle_set_area(result.uv[c], problem.input[c].triangles);
    result.statistics.degenerate_charts += problem.charts[c].degenerate ? 1 : 0;
    result.statistics.turned_charts += trial.placements[c].quarter != 0 ? 1 : 0;
  }
  const double texel = trial.result() / double(problem.setup.resolution);
  result.statistics.texel_density = texel * texel;
}

// The rasters' resolution and gutter for the options: at most max_raster_resolution texels,
// the gutter rounded up so that it is at least `gutter` / `resolution` in UV units.
inline Raster_setup raster_setup(const Atlas_packing_options& options)
{
  Raster_setup s;
  s.resolution = std::min(options.resolution,
                          std::min(Atlas_occupancy::max_size, std::max(16, options.max_raster_resolution)));
  const long long g = (static_cast<long long>(options.gutter) * s.resolution + options.resolution - 1) / options.resolution;
  s.gutter = int(g);
  s.quarter_turns = options.quarter_turns;
  return s;
}

inline Error_code check_packing_input(const std::vector<Chart_to_pack>& charts, const Atlas_packing_options& options)
{
  if(options.resolution < 1 || options.gutter < 0 || options.gutter > options.resolution
     || !(options.density_tolerance > 0.) || options.max_attempts < 0)
    return ERROR_WRONG_PARAMETER;
  for(const Chart_to_pack& chart : charts)
    if(check_chart(chart) != OK)
      return check_chart(chart);
  return OK;
}

/// Packs charts into the unit square [0,1]^2 as one texture atlas (see the top of this file):
/// every chart is moved by a similarity (returned per chart, with its placed UVs) so that all
/// charts share one texel density (UV area / 3D area), sit without overlap at least
/// `options.gutter` texels apart and from the border at `options.resolution` texels per side,
/// and fill as much of the square as the packer finds (`utilization`: UV area / 1).
/// Deterministic; independent of any mesh type.
/// \return status OK, ERROR_WRONG_PARAMETER (bad option, triangle index out of range, more
/// charts than the square holds with this gutter), or ERROR_NON_FINITE_COORDINATES.
inline Atlas_packing pack_atlas_charts(const std::vector<Chart_to_pack>& charts,
                                       const Atlas_packing_options& options = Atlas_packing_options())
{
  const Packing_clock::time_point start = Packing_clock::now();
  Atlas_packing result;
  result.statistics.charts = charts.size();
  result.status = check_packing_input(charts, options);
  if(result.status != OK || charts.empty())
    return result;
  std::vector<Packing_chart> normalized;
  normalized.reserve(charts.size());
  for(const Chart_to_pack& chart : charts)
    normalized.push_back(normalize_chart(chart));
  Packing_problem problem{charts, normalized, packing_order(normalized), raster_setup(options)};
  result.statistics.raster_resolution = problem.setup.resolution;
  result.statistics.raster_gutter = problem.setup.gutter;
  Packing_workspace ws;
  Packing_trial best;
  if(search_density(problem, options, ws, best, result.statistics) > 0.)
  {
    size_frames(problem.charts, best.density, problem.setup, ws);
    finish_packing(problem, best, ws, result);
  }
  else
    result.status = ERROR_WRONG_PARAMETER;  // more charts than the atlas holds with this gutter
  result.statistics.seconds = seconds_since(start);
  return result;
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_ATLAS_PACKING_H
