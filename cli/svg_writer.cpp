// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// The SVG output of the measured_parameterization program (svg_writer.h): the atlas, or the
// single chart. No CGAL here.

#include "svg_writer.h"

#include "summary.h"
#include "svg_layout.h"
#include "text_output.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <tuple>
#include <utility>
#include <vector>

namespace mbp_cli {

namespace SMP = CGAL::Surface_mesh_parameterization;

namespace {

// "1234 vertices, 2400 faces, 288 automatic seam edges (8 cones, 14113 UVs), border of 576
// vertices, center: poisson center, fast-marching distances"
std::string caption_of_mesh(const Run_facts& f)
{
  const Uv_layout& layout = f.result.layout;
  const Seams& seams = f.result.seams;
  std::string s = std::to_string(layout.vertices.size()) + " vertices, " + std::to_string(layout.faces.size()) +
                  " faces, ";
  if(seams.cut)
    s += std::to_string(seams.edges) +
         (seams.automatic ? " automatic seam edges (" + std::to_string(seams.cones.size()) + " cones, "
                          : std::string(" seam edges (")) +
         std::to_string(layout.uv.size()) + " UVs), ";
  return s + "border of " + std::to_string(f.result.border_vertices) + " vertices, center: " +
         f.options.center_name() + " center, " + f.options.distance + " distances";
}

std::string caption_of_quality(const Quality& q)
{
  return "angle distortion " + rounded(q.angle_distortion) + ",  L2 stretch " + rounded(q.l2_stretch) +
         ",  quasi-conformal mean " + rounded(q.quasi_conformal_mean) + ",  flipped faces " +
         std::to_string(q.flipped_faces);
}

// The outlines of the charts: the edges of their polygons that no other polygon of the same
// chart has with the same UVs (either direction), as corner pairs; edges of zero length left
// out. By a sort of the edges on (chart, UV of one end, UV of the other).
std::vector<std::array<std::size_t, 2> > chart_outlines(const Atlas_result& a)
{
  const Polygon_soup& soup = a.soup;
  struct Edge
  {
    std::size_t chart, from, to;  // corners; `from` has the smaller UV
  };
  std::vector<Edge> edges;
  edges.reserve(a.uv.size());
  for(std::size_t i = 0; i < soup.number_of_faces(); ++i)
  {
    const std::size_t begin = soup.face_begin(i), n = soup.face_size(i);
    for(std::size_t k = 0; k < n && n > 1; ++k)
    {
      std::size_t from = begin + k, to = begin + (k + 1) % n;
      if(a.uv[from] == a.uv[to])
        continue;
      if(a.uv[to] < a.uv[from])
        std::swap(from, to);
      edges.push_back({a.polygon_chart[i], from, to});
    }
  }
  auto key = [&a](const Edge& e) { return std::make_tuple(e.chart, a.uv[e.from], a.uv[e.to]); };
  std::sort(edges.begin(), edges.end(), [&key](const Edge& x, const Edge& y) { return key(x) < key(y); });
  std::vector<std::array<std::size_t, 2> > outlines;
  for(std::size_t e = 0, next = 0; e < edges.size(); e = next)
  {
    for(next = e + 1; next < edges.size() && key(edges[next]) == key(edges[e]);)
      ++next;
    if(next == e + 1)
      outlines.push_back({edges[e].from, edges[e].to});
  }
  return outlines;
}

// Per polygon, its chart's distortion against the bounds: the larger of the chart's area
// spread and angle distortion, each over its bound (an infinite bound counts 0), at most 1
// within the bounds (a lone triangle may exceed them); empty when both bounds are infinite.
std::vector<double> chart_bound_ratios(const Atlas_result& a)
{
  const SMP::Atlas_report& r = a.report;
  const auto over = [](double value, double bound) { return bound < HUGE_VAL && bound > 0. ? value / bound : 0.; };
  if(!(r.max_area_spread < HUGE_VAL) && !(r.max_angle_distortion < HUGE_VAL))
    return {};
  std::vector<double> ratios(a.polygon_chart.size(), 0.);
  for(std::size_t i = 0; i < ratios.size(); ++i)
    if(a.polygon_chart[i] < r.charts.size())
    {
      const SMP::Atlas_chart_report& c = r.charts[a.polygon_chart[i]];
      ratios[i] = (std::max)(over(c.area_spread, r.max_area_spread), over(c.angle_distortion, r.max_angle_distortion));
    }
  return ratios;
}

// The picture of an atlas: the unit square framed, the input's polygons at their UVs colored
// by their chart's distortion against the bounds (by their own area distortion when the bounds
// are lifted), the charts outlined, the caption and the legend.
std::string atlas_picture(const Run_facts& f)
{
  const Atlas_result& a = f.result.atlas;
  const SMP::Atlas_report& r = a.report;
  Svg_layout picture;
  picture.uv = a.uv;
  for(std::size_t i = 0; i < a.soup.number_of_faces(); ++i)
    picture.polygon_end.push_back(a.soup.face_end[i]);
  picture.face_angle_distortion = chart_bound_ratios(a);
  if(picture.face_angle_distortion.empty())
  {
    picture.face_angle_distortion = a.polygon_area_distortion;
    picture.color_title = "area distortion per polygon";
    picture.color_note = "|log(UV area / 3D area)|, log scale";
  }
  else
  {
    picture.color_lo = 0.01;  // a fixed range, up to the bounds
    picture.color_hi = 1.;
    picture.color_title = "distortion per chart against the bounds";
    picture.color_note = "max(area spread, angle distortion) / bound, log scale";
  }
  picture.face_flipped.assign(a.soup.number_of_faces(), false);
  picture.outlines = chart_outlines(a);
  picture.unit_square = true;
  picture.layout_marks = false;
  picture.center = picture.uv.size();  // none
  picture.frame_label = "texture (" + std::to_string(f.options.resolution) + " texels)";
  picture.outline_label = "chart outlines (" + std::to_string(r.charts.size()) + ")";
  picture.title = f.mesh_name;
  picture.caption.push_back(std::to_string(a.soup.points.size()) + " points, " +
                            std::to_string(a.soup.number_of_faces()) + " polygons: " + atlas_charts_text(f));
  picture.caption.push_back("repairs: " + repair_list(r.repair));
  picture.caption.push_back("area spread " + rounded(r.area_spread) + " (after one scale of the atlas),  angle distortion " +
                            rounded(r.angle_distortion));
  picture.caption.push_back(atlas_bounds_text(r));
  return svg_document(picture);
}

} // namespace

std::string svg_picture(const Run_facts& f)
{
  if(f.options.mode == Mode::atlas)
    return atlas_picture(f);
  const Uv_layout& layout = f.result.layout;
  const Options& o = f.options;
  Svg_layout picture;
  picture.uv = layout.uv;
  picture.faces = layout.faces;
  picture.face_angle_distortion = layout.face_angle_distortion;
  picture.face_flipped = layout.face_flipped;
  picture.border = layout.border;
  if(f.result.seams.cut)  // both sides of each seam edge
  {
    picture.seams = layout.seam_sides;
    picture.seam_edges = f.result.seams.edges;
  }
  picture.center = layout.has_center ? layout.center : std::numeric_limits<std::size_t>::max();
  picture.center_label = "center (vertex " + std::to_string(layout.center_vertex) + ")";
  picture.title = f.mesh_name;
  picture.caption.push_back(caption_of_mesh(f));
  picture.caption.push_back(caption_of_quality(f.result.quality));
  picture.caption.push_back("border " + std::string(border_name(o.border)) + ": kept " +
                            kept_border(f.result.report, o.distance) + ",  " + repair_text(f.result.report, o.repair));
  return svg_document(picture);
}

} // namespace mbp_cli
