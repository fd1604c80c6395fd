// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_COMPUTE_ATLAS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_COMPUTE_ATLAS_H

/// \file compute_atlas.h
/// A packed texture atlas of any mesh or polygon soup: `compute_atlas()` and
/// `compute_atlas_of_polygon_soup()`.

#include <CGAL/Surface_mesh_parameterization/Atlas_charts.h>
#include <CGAL/Surface_mesh_parameterization/Atlas_report.h>
#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/internal/atlas/packing.h>
#include <CGAL/Surface_mesh_parameterization/internal/atlas/soup_repair.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Polygon_mesh_processing/polygon_mesh_to_polygon_soup.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <Eigen/Core>

#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

typedef Repaired_soup<Atlas_kernel> Atlas_input;

// The atlas of a repaired soup: its charts, and per face of the repaired mesh its chart and
// the three placed UVs of its corners.
struct Atlas_layout
{
  std::vector<Atlas_chart> charts;
  std::vector<std::size_t> face_chart;                  // per repaired face
  std::vector<std::array<Eigen::Vector2d, 3> > face_uv;  // per repaired face, in [0,1]^2
};

inline Error_code check_atlas_options(const Atlas_options& options)
{
  const bool ok = options.resolution >= 8 && options.resolution <= (1u << 16) &&
                  options.gutter <= options.resolution / 4 && options.max_area_spread >= 0. &&
                  options.max_angle_distortion >= 0. && options.min_compactness >= 0. &&
                  (options.split == SPLIT_BY_NORMALS || options.split == SPLIT_BY_SCALE);
  return ok ? OK : ERROR_WRONG_PARAMETER;
}

// Step 2: the charts of each connected component of the repaired mesh (Atlas_charts.h).
inline std::vector<Atlas_chart> make_charts(const Atlas_input& input, const Atlas_triangles& t,
                                            const Atlas_options& options, std::size_t& splits)
{
  std::vector<std::vector<std::size_t> > components(input.report.components);
  for(std::size_t f = 0; f < input.face_component.size(); ++f)
    components[input.face_component[f]].push_back(f);
  double area = 0.;
  for(const Face_indices& v : t.faces)
    area += 0.5 * (t.points[std::size_t(v[1])] - t.points[std::size_t(v[0])])
                    .cross(t.points[std::size_t(v[2])] - t.points[std::size_t(v[0])]).norm();
  const Chart_bounds bounds{options, 0.5 * std::sqrt(area)};
  std::vector<Atlas_chart> charts;
  splits = 0;
  for(const std::vector<std::size_t>& component : components)
    flatten_face_set(t, component, bounds, charts, splits);
  return charts;
}

// Step 3: the charts packed into the unit square; their placed UVs given to the faces.
inline Error_code pack_charts(const Atlas_options& options, Atlas_layout& layout, double& utilization,
                              double& texel_density)
{
  std::vector<Chart_to_pack> to_pack;
  to_pack.reserve(layout.charts.size());
  for(const Atlas_chart& chart : layout.charts)
    to_pack.push_back(chart_to_pack(chart));
  Atlas_packing_options packing_options;
  packing_options.resolution = int(options.resolution);
  packing_options.gutter = int(options.gutter);
  const Atlas_packing packing = pack_atlas_charts(to_pack, packing_options);
  if(packing.status != OK)
    return packing.status;
  for(std::size_t c = 0; c < layout.charts.size(); ++c)
    for(std::size_t i = 0; i < layout.charts[c].faces.size(); ++i)
    {
      const std::size_t f = layout.charts[c].faces[i];
      layout.face_chart[f] = c;
      for(std::size_t k = 0; k < 3; ++k)
        layout.face_uv[f][k] = packing.uv[c][3 * i + k];
    }
  utilization = packing.utilization;
  texel_density = std::sqrt(packing.statistics.texel_density);
  return OK;
}

// The area-weighted mean of |log(UV area / 3D area)| over all faces after one global scale:
// the area spread of the whole atlas taken as one chart.
inline double atlas_area_spread(const Atlas_triangles& t, const Atlas_layout& layout)
{
  Atlas_chart all;
  all.faces.resize(t.faces.size());
  std::iota(all.faces.begin(), all.faces.end(), std::size_t(0));
  all.corners = layout.face_uv;
  chart_area_figures(t, all);
  return all.area_spread;
}

// The report's charts and totals.
inline void report_charts(const Atlas_triangles& t, const Atlas_layout& layout, Atlas_report& report)
{
  report.charts.clear();
  double weighted = 0., total = 0.;
  for(const Atlas_chart& chart : layout.charts)
  {
    Atlas_chart_report c;
    c.faces = chart.faces.size();
    c.flattening = chart.flattening;
    c.area_3d = chart.area_3d;
    c.area_uv = chart.area_3d * report.texel_density * report.texel_density;
    c.angle_distortion = chart.angle_distortion;
    c.area_spread = chart.area_spread;
    c.compactness = chart.compactness;
    weighted += c.area_3d * c.angle_distortion;
    total += c.area_3d;
    report.charts.push_back(c);
  }
  report.angle_distortion = total > 0. ? weighted / total : 0.;
  report.area_spread = atlas_area_spread(t, layout);
}

inline double seconds_between(std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b)
{
  return std::chrono::duration<double>(b - a).count();
}

// Steps 2 and 3 on a repaired soup: charts, packing, report.
inline Error_code lay_out_atlas(const Atlas_input& input, const Atlas_options& options, Atlas_layout& layout,
                                Atlas_report& report)
{
  typedef std::chrono::steady_clock Clock;
  const Clock::time_point start = Clock::now();
  const Atlas_triangles t = repaired_triangles(input);
  layout.charts = make_charts(input, t, options, report.splits);
  report.max_area_spread = options.max_area_spread;
  report.max_angle_distortion = options.max_angle_distortion;
  report.min_compactness = options.min_compactness;
  const Clock::time_point charted = Clock::now();
  layout.face_chart.assign(t.faces.size(), 0);
  layout.face_uv.assign(t.faces.size(), std::array<Eigen::Vector2d, 3>());
  const Error_code packed = pack_charts(options, layout, report.utilization, report.texel_density);
  if(packed != OK)
    return packed;
  report_charts(t, layout, report);
  report.chart_seconds = seconds_between(start, charted);
  report.packing_seconds = seconds_between(charted, Clock::now());
  return OK;
}

// The whole process on a soup: repair, charts, packing. On an error `layout` is empty.
template <class PointRange, class PolygonRange>
Error_code make_atlas(const PointRange& points, const PolygonRange& polygons, const Atlas_options& options,
                      Atlas_input& input, Atlas_layout& layout, Atlas_report& report)
{
  typedef std::chrono::steady_clock Clock;
  const Clock::time_point start = Clock::now();
  report = Atlas_report();
  Error_code status = check_atlas_options(options);
  if(status == OK)
    status = repair_soup_for_atlas(points, polygons, input);
  report.repair = input.report;
  report.repair_seconds = seconds_between(start, Clock::now());
  if(status == OK)
    status = lay_out_atlas(input, options, layout, report);
  if(status != OK)
    layout = Atlas_layout();
  report.total_seconds = seconds_between(start, Clock::now());
  return status;
}

// The UV of corner j of input polygon p.
inline Eigen::Vector2d placed_corner_uv(const Atlas_input& input, const Atlas_layout& layout, std::size_t p,
                                       std::size_t j)
{
  return input_corner_uv(input, p, j, [&layout](std::size_t f, int k) {
    return layout.face_uv[f][std::size_t(k)];
  });
}

// The chart of input polygon p: the chart of the face its first corner takes its UV from.
inline std::size_t input_polygon_chart(const Atlas_input& input, const Atlas_layout& layout, std::size_t p)
{
  return layout.face_chart[std::size_t(face(input.corner(p, 0).from, input.mesh))];
}

} // namespace internal

/// \ingroup PkgSurfaceMeshParameterizationMeasured
///
/// computes a packed texture atlas of a polygon soup, as CGAL's readers give it
/// (`CGAL::IO::read_polygon_soup()`): every corner of every input polygon gets a UV in
/// \f$ [0,1]^2 \f$, every polygon a chart id.
///
/// The process:
/// 1. the soup is repaired into a triangle mesh whose connected components are oriented
///    manifolds (merged points, duplicate polygons, non-manifold edges and vertices,
///    orientation, non-orientable pieces cut open, polygons triangulated, zero-area triangles
///    set aside; `Soup_repair_report` says what was done), keeping for every input corner the
///    place of the repaired mesh its UV comes from;
/// 2. each connected component becomes one chart when its map is one-to-one (a disk
///    flattened by `Conformal_parameterizer_3` with the automatic border, any other surface
///    cut by `compute_disk_seams()` first) and within the distortion bounds
///    (`Atlas_options::max_area_spread`, `max_angle_distortion`), and is split into parts
///    (`Atlas_split`), recursively, where it is not; a face set that no parameterizer maps
///    one-to-one is unfolded isometrically (`Chart_flattening`);
/// 3. the charts are scaled to one texel density (UV area proportional to 3D area), turned
///    to their smallest bounding box and packed into the unit square by a rasterized packer,
///    `options.gutter` texels apart and from the border at `options.resolution` texels per
///    side.
///
/// Every chart's map is one-to-one (no flipped triangle, no two overlapping); no two charts
/// overlap. A zero-area polygon gets a zero-area UV polygon inside a chart; never a NaN.
///
/// \tparam PointRange a random access range of points with `p[0]`, `p[1]`, `p[2]` convertible
///         to `double` (e.g. `std::vector<Point_3>` of any CGAL kernel, or `std::array<double, 3>`)
/// \tparam PolygonRange a range of polygons, each a range of indices into `points` (any size
///         from 1 up)
/// \param points the points of the soup
/// \param polygons the polygons of the soup
/// \param corner_uvs receives, per input polygon, the UV of each of its corners
/// \param polygon_charts receives the chart id of each input polygon (an index into
///        `report->charts`): the chart of its first corner. A polygon whose triangles fall into
///        two charts has each corner in its own chart's place
/// \param options the resolution and the gutter of the texture (`Atlas_options`)
/// \param report when not null, receives what was repaired, the charts and the packing
/// \return `OK`, `ERROR_EMPTY_MESH` (no polygon with three distinct points and nonzero
///         area), `ERROR_NON_FINITE_COORDINATES` (a point is infinite or NaN),
///         `ERROR_WRONG_PARAMETER` (an index out of range, bad options, or more charts than
///         the square holds with the gutter). On an error the outputs are emptied.
template <class PointRange, class PolygonRange, class Point_2>
Error_code compute_atlas_of_polygon_soup(const PointRange& points, const PolygonRange& polygons,
                                         std::vector<std::vector<Point_2> >& corner_uvs,
                                         std::vector<std::size_t>& polygon_charts,
                                         const Atlas_options& options = Atlas_options(),
                                         Atlas_report* report = nullptr)
{
  internal::Atlas_input input;
  internal::Atlas_layout layout;
  Atlas_report local_report;
  Atlas_report& r = report ? *report : local_report;
  corner_uvs.clear();
  polygon_charts.clear();
  const Error_code status = internal::make_atlas(points, polygons, options, input, layout, r);
  if(status != OK)
    return status;
  corner_uvs.resize(r.repair.input_polygons);
  polygon_charts.resize(r.repair.input_polygons);
  std::size_t p = 0;
  for(const auto& polygon : polygons)
  {
    for(std::size_t j = 0; j < std::size_t(polygon.size()); ++j)
    {
      const Eigen::Vector2d uv = internal::placed_corner_uv(input, layout, p, j);
      corner_uvs[p].push_back(Point_2(uv.x(), uv.y()));
    }
    polygon_charts[p] = internal::input_polygon_chart(input, layout, p);
    ++p;
  }
  return OK;
}

/// \ingroup PkgSurfaceMeshParameterizationMeasured
///
/// computes a packed texture atlas of a face graph (any polygon mesh: faces of any size,
/// several components, non-manifold vertices or misoriented faces are repaired as in
/// `compute_atlas_of_polygon_soup()`, of which this is the face graph's form: input polygon
/// `p` is the `p`-th face of `faces(tm)`, its corners the targets of
/// `halfedges_around_face(halfedge(f, tm), tm)`).
///
/// \tparam HalfedgeUVMap a writable property map from the halfedges of `tm` to a 2D point
///         type: the UV of the corner of `face(h)` at `target(h)` (border halfedges are not
///         written)
/// \tparam FaceChartMap a writable property map from the faces of `tm` to an integer type:
///         the chart id of the face (an index into `report->charts`)
/// \tparam NamedParameters a sequence of named parameters: `vertex_point_map` (default
///         `get(CGAL::vertex_point, tm)`)
/// \return as `compute_atlas_of_polygon_soup()`; on an error nothing is written.
template <class FaceGraph, class HalfedgeUVMap, class FaceChartMap,
          class NamedParameters = parameters::Default_named_parameters>
Error_code compute_atlas(const FaceGraph& tm, HalfedgeUVMap uv_map, FaceChartMap chart_map,
                         const Atlas_options& options = Atlas_options(), Atlas_report* report = nullptr,
                         const NamedParameters& np = parameters::default_values())
{
  typedef typename boost::property_traits<HalfedgeUVMap>::value_type Point_2;
  const auto vpm = parameters::choose_parameter(parameters::get_parameter(np, internal_np::vertex_point),
                                                get_const_property_map(vertex_point, tm));
  std::vector<typename boost::property_traits<decltype(vpm)>::value_type> points;
  std::vector<std::vector<std::size_t> > polygons;
  Polygon_mesh_processing::polygon_mesh_to_polygon_soup(tm, points, polygons, parameters::vertex_point_map(vpm));
  std::vector<std::vector<Point_2> > uvs;
  std::vector<std::size_t> charts;
  const Error_code status = compute_atlas_of_polygon_soup(points, polygons, uvs, charts, options, report);
  if(status != OK)
    return status;
  std::size_t p = 0;
  for(auto f : faces(tm))
  {
    std::size_t j = 0;
    for(auto h : halfedges_around_face(halfedge(f, tm), tm))
      put(uv_map, h, uvs[p][j++]);
    put(chart_map, f, typename boost::property_traits<FaceChartMap>::value_type(charts[p]));
    ++p;
  }
  return OK;
}

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_COMPUTE_ATLAS_H
