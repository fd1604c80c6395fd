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
// texture atlas in [0,1]^2.
//
// 1. One texel density. Each chart is scaled so that its UV area equals its 3D area, then
//    one global scale serves all charts: UV area / 3D area is the same for every chart.
// 2. Each chart is turned to its smallest bounding box (min_area_rectangle.h).
// 3. The charts are rasterized conservatively at the texel resolution (raster.h), each
//    raster dilated by the gutter, and placed from the largest down at the first free
//    position of the square atlas (placement.h), trying 0 and 90 degrees: the position with
//    the lowest bottom row, then the leftmost, wins.
// 4. The global scale is the largest for which every chart finds a place: the first tries
//    descend from the area bound (all of the square used) by a factor 0.9 until the packing
//    succeeds, then a bisection narrows [succeeded, failed] to `scale_tolerance`.
//
// Guarantees (tested in test_atlas_packing.cpp): every output UV is in [0,1]^2; the triangles
// of two charts are at least `gutter` texels apart (1 texel = 1 / resolution); a chart is
// moved by a similarity (uniform scale, rotation, translation); UV area / 3D area is equal
// across non-degenerate charts; the output depends only on the input (no clock, no threads).
//
// Degenerate charts (zero 3D area or zero UV area: a chart of zero-area faces, a single
// point) are placed too, each in one texel of its own: a chart of zero 3D area and positive
// UV area becomes a point (its UV area is then 0, as its density asks), any other keeps its
// shape scaled into half a texel.
//
// Measured against libnest2d (benchmark/atlas_packing.cpp, benchmark/README.md): on the
// charts of xatlas for the 15 meshes of ../shared/data/atlas this packer fills more of the
// square in less time, so it is the package's packer.

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

// One chart: a triangle set in its own UV plane, and the sum of its triangles' 3D areas.
struct Atlas_chart
{
  std::vector<Eigen::Vector2d> uv;
  std::vector<Face_indices> triangles;  // indices into uv
  double area_3d = 0.;
};

struct Atlas_packing_options
{
  int resolution = 1024;          // texels per side of [0,1]^2
  int gutter = 2;                 // texels between the triangles of two charts, at least
  double scale_tolerance = 0.005; // relative precision of the largest global scale
  bool quarter_turns = true;      // whether a chart may also be placed turned by 90 degrees
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
  int attempts = 0;                // global scales tried
  std::size_t charts = 0;
  std::size_t degenerate_charts = 0;
  std::size_t turned_charts = 0;   // placed turned by 90 degrees
  double texel_density = 0.;       // UV area / 3D area of every non-degenerate chart
  double area_bound_ratio = 0.;    // global scale / its bound (all of the square used)
};

struct Atlas_packing
{
  Error_code status = OK;  // ERROR_WRONG_PARAMETER, ERROR_NON_FINITE_COORDINATES or OK
  std::vector<Chart_similarity> transforms;  // per chart
  std::vector<std::vector<Eigen::Vector2d> > uv;  // per chart: the placed UVs
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
inline Error_code check_chart(const Atlas_chart& chart)
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
// Non-degenerate: in units of the square root of 3D area (the global scale multiplies it);
// degenerate: in texels.
struct Packing_chart
{
  double scale = 0.;
  Min_area_rectangle box;
  Eigen::Vector2d low = Eigen::Vector2d::Zero();
  Eigen::Vector2d extent = Eigen::Vector2d::Zero();
  double area_3d = 0.;
  bool degenerate = false;
};

inline Packing_chart normalize_chart(const Atlas_chart& chart)
{
  Packing_chart result;
  result.box = min_area_rectangle(chart.uv);
  result.area_3d = chart.area_3d;
  const double uv_area = triangle_set_area(chart.uv, chart.triangles);
  const double scale = uv_area > 0. ? std::sqrt(chart.area_3d / uv_area) : 0.;
  result.degenerate = !(chart.area_3d > 0. && uv_area > 0. && std::isfinite(scale) && scale > 0.);
  if(!result.degenerate)
    result.scale = scale;
  else if(!(chart.area_3d == 0. && uv_area > 0.) && result.box.width > 0.)
    result.scale = 0.5 / result.box.width;  // into half a texel
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
  return result;
}

// ---------------------------------------------------------------------------------------
// 3: the rasters of the charts at one global scale

// How far (in texels) a chart's lower corner lies inside its first cell: more than the
// rasterization's epsilon, so that a point chart occupies one cell.
constexpr double frame_inset = 1e-6;

// A chart's frame at one global scale: its cells T span `cells` texels; the frame is
// cells + 2 gutter on each side. Turned by q quarters: `cells_words[q]` and `mask_words[q]`,
// the offsets of T and D in the workspace's pool; `runs[q]`, `run_count[q]`: D's runs in the
// workspace's runs; `rows[q]`: the longest run of each row of D in its row_longest.
struct Chart_frame
{
  double texels_per_unit = 0.;
  std::array<int, 2> cells{{0, 0}};
  std::array<std::size_t, 2> cells_words{{0, 0}};
  std::array<std::size_t, 2> mask_words{{0, 0}};
  std::array<std::size_t, 2> runs{{0, 0}};
  std::array<int, 2> run_count{{0, 0}};
  std::array<std::size_t, 2> rows{{0, 0}};
};

// Where a chart is placed: its frame origin in padded atlas coordinates, and its quarter turn.
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
  std::vector<int> row_longest;
  std::vector<double> points;
  std::vector<Chart_placement> placements;
  Atlas_occupancy occupancy;
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

// Sizes the frames at the global scale `texels_per_unit` and lays out the pool; false when a
// chart does not fit in the atlas.
inline bool layout_frames(const std::vector<Packing_chart>& charts, double texels_per_unit,
                          const Atlas_packing_options& options, Packing_workspace& ws)
{
  ws.frames.resize(charts.size());
  std::size_t words = 0, rows = 0;
  for(std::size_t c = 0; c < charts.size(); ++c)
  {
    Chart_frame& frame = ws.frames[c];
    frame.texels_per_unit = charts[c].degenerate ? 1. : texels_per_unit;
    const double span = std::max(charts[c].extent.x(), charts[c].extent.y()) * frame.texels_per_unit;
    if(!(span < double(options.resolution)))
      return false;
    for(int axis = 0; axis < 2; ++axis)
      frame.cells[std::size_t(axis)] = cell_count(frame.texels_per_unit * charts[c].extent[axis], options.gutter);
    if(std::max(frame.cells[0], frame.cells[1]) > options.resolution)
      return false;
    for(int quarter = 0; quarter < 2; ++quarter)
    {
      const std::array<int, 2> size = frame_size(frame, quarter, options.gutter);
      const std::size_t raster_words = std::size_t(size[1]) * std::size_t(words_for_bits(size[0]));
      frame.cells_words[std::size_t(quarter)] = words;
      frame.mask_words[std::size_t(quarter)] = words + raster_words;
      frame.rows[std::size_t(quarter)] = rows;
      words += 2 * raster_words;
      rows += std::size_t(size[1]);
    }
  }
  ws.pool.assign(words, 0);
  ws.row_longest.assign(rows, 0);
  ws.runs.clear();
  return true;
}

// Rasterizes one chart's triangles and vertices (cells T), then its dilated, turned rasters
// and the row runs of the masks.
inline void rasterize_chart(const Atlas_chart& input, const Packing_chart& chart, Chart_frame& frame,
                            int gutter, Packing_workspace& ws)
{
  ws.points.resize(2 * input.uv.size());
  for(std::size_t v = 0; v < input.uv.size(); ++v)
  {
    const Eigen::Vector2d p = frame_point(chart, frame, input.uv[v], gutter);
    ws.points[2 * v] = p.x();
    ws.points[2 * v + 1] = p.y();
  }
  const Raster_view cells = frame_raster(ws, frame, 0, false, gutter);
  const double* points = ws.points.data();
  for(const Face_indices& t : input.triangles)
    rasterize_triangle(cells, points + 2 * t[0], points + 2 * t[1], points + 2 * t[2]);
  for(std::size_t v = 0; v < input.uv.size(); ++v)
    rasterize_triangle(cells, points + 2 * v, points + 2 * v, points + 2 * v);
  const Raster_view turned = frame_raster(ws, frame, 1, false, gutter);
  rotate_quarter(cells, turned);
  for(int quarter = 0; quarter < 2; ++quarter)
  {
    const Raster_view mask = frame_raster(ws, frame, quarter, true, gutter);
    dilate(quarter == 0 ? cells : turned, mask, gutter);
    frame.runs[std::size_t(quarter)] = ws.runs.size();
    compute_mask_runs(mask, ws.runs, ws.row_longest.data() + frame.rows[std::size_t(quarter)]);
    frame.run_count[std::size_t(quarter)] = int(ws.runs.size() - frame.runs[std::size_t(quarter)]);
  }
}

// ---------------------------------------------------------------------------------------
// 3 (continued): the placement of the rasters

// The first position of a chart turned by `quarter` whose bottom row is above `bottom` (or
// at `bottom` and left of `left`); x = -1 when there is none.
inline Frame_position find_position(const Packing_workspace& ws, const Chart_frame& frame, int quarter, int bottom,
                                    int left, const Atlas_packing_options& options)
{
  const std::size_t q = std::size_t(quarter);
  const int height = frame_size(frame, quarter, options.gutter)[1];
  Mask_runs mask{ws.runs.data() + frame.runs[q], frame.run_count[q], ws.row_longest.data() + frame.rows[q], 0};
  mask.shortest = *std::min_element(mask.row_longest, mask.row_longest + height);
  const std::array<int, 2> cells = quarter == 0 ? frame.cells : std::array<int, 2>{{frame.cells[1], frame.cells[0]}};
  const int y_max = std::min(options.resolution - cells[1], bottom - height);
  const Frame_position found = ws.occupancy.find(mask, height, options.resolution - cells[0], y_max);
  if(found.x >= 0 && found.y + height == bottom && found.x >= left)
    return Frame_position();
  return found;
}

// Places the charts in `order`; false when one finds no place.
inline bool place_charts(const std::vector<std::size_t>& order, const Atlas_packing_options& options,
                         Packing_workspace& ws)
{
  ws.occupancy.reset(options.resolution + 2 * options.gutter);
  ws.placements.assign(ws.frames.size(), Chart_placement());
  for(std::size_t c : order)
  {
    const Chart_frame& frame = ws.frames[c];
    Chart_placement best;
    int bottom = options.resolution + 2 * options.gutter + 1, left = 0;
    for(int quarter = 0; quarter < (options.quarter_turns ? 2 : 1); ++quarter)
    {
      const Frame_position p = find_position(ws, frame, quarter, bottom, left, options);
      if(p.x < 0)
        continue;
      best = Chart_placement{p.x, p.y, quarter};
      bottom = p.y + frame_size(frame, quarter, options.gutter)[1];
      left = p.x;
    }
    if(bottom > options.resolution + 2 * options.gutter)
      return false;
    ws.placements[c] = best;
    ws.occupancy.place(frame_raster(ws, frame, best.quarter, false, options.gutter), best.x, best.y);
  }
  return true;
}

// ---------------------------------------------------------------------------------------
// 4: the search of the global scale

typedef std::chrono::steady_clock Packing_clock;

inline double seconds_since(Packing_clock::time_point start)
{
  return std::chrono::duration<double>(Packing_clock::now() - start).count();
}

// One attempt: rasterizes and places every chart at the global scale `texels_per_unit`.
inline bool try_scale(const std::vector<Atlas_chart>& input, const std::vector<Packing_chart>& charts,
                      const std::vector<std::size_t>& order, double texels_per_unit,
                      const Atlas_packing_options& options, Packing_workspace& ws, Atlas_packing_statistics& stats)
{
  ++stats.attempts;
  Packing_clock::time_point start = Packing_clock::now();
  const bool sized = layout_frames(charts, texels_per_unit, options, ws);
  if(sized)
    for(std::size_t c = 0; c < charts.size(); ++c)
      rasterize_chart(input[c], charts[c], ws.frames[c], options.gutter, ws);
  stats.raster_seconds += seconds_since(start);
  if(!sized)
    return false;
  start = Packing_clock::now();
  const bool placed = place_charts(order, options, ws);
  stats.placement_seconds += seconds_since(start);
  return placed;
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

// The largest global scale (texels per unit) at which the charts pack, within the tolerance;
// its placements are left in `best`. 0 when none does.
inline double search_scale(const std::vector<Atlas_chart>& input, const std::vector<Packing_chart>& charts,
                           const Atlas_packing_options& options, Packing_workspace& ws,
                           std::vector<Chart_placement>& best, Atlas_packing_statistics& stats)
{
  const std::vector<std::size_t> order = packing_order(charts);
  double area = 0., extent = 0.;
  for(const Packing_chart& c : charts)
    if(!c.degenerate)
    {
      area += c.area_3d;
      extent = std::max(extent, std::max(c.extent.x(), c.extent.y()));
    }
  const double bound = area > 0. ? double(options.resolution) / std::sqrt(area) : 1.;
  const double smallest = extent > 0. ? 1e-3 / extent : bound;  // every chart in one texel
  double high = bound, low = 0.;
  for(int step = 0; low == 0. && step <= 21; ++step)  // bound * 0.9^k down to 0.11 bound, then `smallest`
  {
    const double scale = step < 21 ? bound * std::pow(0.9, step) : smallest;
    if(scale < smallest && step < 21)
      continue;
    if(try_scale(input, charts, order, scale, options, ws, stats))
      low = scale;
    else
      high = scale;
  }
  if(low == 0.)
    return 0.;
  best = ws.placements;
  while(high > low * (1. + options.scale_tolerance))
  {
    const double scale = std::sqrt(low * high);
    if(try_scale(input, charts, order, scale, options, ws, stats))
    {
      low = scale;
      best = ws.placements;
    }
    else
      high = scale;
  }
  stats.area_bound_ratio = low / bound;
  return low;
}

// ---------------------------------------------------------------------------------------
// The output

// The similarity of a placed chart, and its UVs: the frame points of the rasterization,
// turned, moved to the placement and divided by the resolution.
inline void place_chart_output(const Atlas_chart& input, const Packing_chart& chart, const Chart_frame& frame,
                               const Chart_placement& placement, const Atlas_packing_options& options,
                               Chart_similarity& transform, std::vector<Eigen::Vector2d>& uv)
{
  const double resolution = double(options.resolution);
  const double height = double(frame_size(frame, 0, options.gutter)[1]);
  const Eigen::Vector2d origin(double(placement.x - options.gutter), double(placement.y - options.gutter));
  const auto turn = [&](const Eigen::Vector2d& p) {
    return placement.quarter == 0 ? p : Eigen::Vector2d(height - p.y(), p.x());
  };
  uv.resize(input.uv.size());
  for(std::size_t v = 0; v < input.uv.size(); ++v)
  {
    const Eigen::Vector2d p = (turn(frame_point(chart, frame, input.uv[v], options.gutter)) + origin) / resolution;
    uv[v] = p.cwiseMax(Eigen::Vector2d::Zero()).cwiseMin(Eigen::Vector2d::Ones());
  }
  transform.degenerate = chart.degenerate;
  transform.scale = frame.texels_per_unit * chart.scale / resolution;
  transform.cos_angle = placement.quarter == 0 ? chart.box.cos_angle : -chart.box.sin_angle;
  transform.sin_angle = placement.quarter == 0 ? chart.box.sin_angle : chart.box.cos_angle;
  const Eigen::Vector2d zero = frame_point(chart, frame, Eigen::Vector2d::Zero(), options.gutter);
  transform.translation = (turn(zero) + origin) / resolution;
}

// Writes the placed charts, their similarities, the utilization and the counters.
inline void finish_packing(const std::vector<Atlas_chart>& input, const std::vector<Packing_chart>& charts,
                           const std::vector<Chart_placement>& placements, double texels_per_unit,
                           const Atlas_packing_options& options, const Packing_workspace& ws, Atlas_packing& result)
{
  result.transforms.resize(input.size());
  result.uv.resize(input.size());
  for(std::size_t c = 0; c < input.size(); ++c)
  {
    place_chart_output(input[c], charts[c], ws.frames[c], placements[c], options, result.transforms[c], result.uv[c]);
    result.utilization += triangle_set_area(result.uv[c], input[c].triangles);
    result.statistics.degenerate_charts += charts[c].degenerate ? 1 : 0;
    result.statistics.turned_charts += placements[c].quarter != 0 ? 1 : 0;
  }
  const double texel = texels_per_unit / double(options.resolution);
  result.statistics.texel_density = texel * texel;
}

// Packs the charts into [0,1]^2 (see the top of this file).
inline Atlas_packing pack_atlas_charts(const std::vector<Atlas_chart>& charts,
                                       const Atlas_packing_options& options = Atlas_packing_options())
{
  const Packing_clock::time_point start = Packing_clock::now();
  Atlas_packing result;
  result.statistics.charts = charts.size();
  if(options.resolution < 1 || options.gutter < 0 || options.resolution > (1 << 20)
     || !(options.scale_tolerance > 0.))
    result.status = ERROR_WRONG_PARAMETER;
  for(std::size_t c = 0; c < charts.size() && result.status == OK; ++c)
    result.status = check_chart(charts[c]);
  if(result.status != OK)
    return result;
  std::vector<Packing_chart> normalized;
  normalized.reserve(charts.size());
  for(const Atlas_chart& chart : charts)
    normalized.push_back(normalize_chart(chart));
  Packing_workspace ws;
  std::vector<Chart_placement> placements;
  const double scale = search_scale(charts, normalized, options, ws, placements, result.statistics);
  if(!(scale > 0.))
  {
    result.status = ERROR_WRONG_PARAMETER;  // more charts than the atlas holds with this gutter
    result.statistics.seconds = seconds_since(start);
    return result;
  }
  layout_frames(normalized, scale, options, ws);
  finish_packing(charts, normalized, placements, scale, options, ws, result);
  result.statistics.seconds = seconds_since(start);
  return result;
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_ATLAS_PACKING_H
