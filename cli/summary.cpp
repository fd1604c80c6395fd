// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// The one-line summary of a run and the texts of the border kept and the repair, or of the
// atlas (summary.h). No CGAL here but the library's reports.

#include "summary.h"

namespace mbp_cli {

namespace SMP = CGAL::Surface_mesh_parameterization;

std::string summary_of_mesh(const Run_facts& f)
{
  const Uv_layout& layout = f.result.layout;
  const Seams& seams = f.result.seams;
  std::string s = f.mesh_name + ": V " + std::to_string(layout.vertices.size()) + ", F " +
                  std::to_string(layout.faces.size());
  if(seams.cut)
    s += std::string(seams.automatic ? " | automatic seams " : " | seams ") + std::to_string(seams.edges) +
         " edges, " + (seams.automatic ? std::to_string(seams.cones.size()) + " cones, " : std::string()) +
         std::to_string(layout.uv.size()) + " UVs";
  s += " | border " + std::to_string(f.result.border_vertices) + " vertices, length " +
       rounded(f.result.border_length);
  if(layout.has_center)
    s += " | center " + std::to_string(layout.center_vertex) + " (" + f.options.center_name() + ")" +
         " | distances " + f.options.distance;
  return s;
}

std::string summary_of_quality(const Quality& q)
{
  return " | angle distortion " + rounded(q.angle_distortion) + ", L2 stretch " + rounded(q.l2_stretch) +
         ", quasi-conformal mean " + rounded(q.quasi_conformal_mean) + ", flipped faces " +
         std::to_string(q.flipped_faces);
}

std::string candidate_kind(const SMP::Border_candidate& c, const std::string& distance)
{
  return c.family == SMP::CIRCLE              ? std::string("circle")
         : c.family == SMP::CONFORMAL         ? std::string("conformal")
         : c.family == SMP::CONFORMAL_LENGTHS ? std::string("conformal-lengths")
                                              : "measured:" + distance;
}

std::string kept_border(const SMP::Parameterization_report& report, const std::string& distance)
{
  const std::size_t n = report.border_candidates.size();
  const std::string tried = " (" + std::to_string(n) + (n == 1 ? " layout" : " layouts") + " tried)";
  if(report.chosen_candidate < 0)
    return "none valid" + tried;
  const SMP::Border_candidate& c = report.border_candidates[static_cast<std::size_t>(report.chosen_candidate)];
  const std::string kind = candidate_kind(c, distance);
  return kind + (kind == "circle" || c.blend == 0. ? std::string() : " t " + rounded(c.blend, 3)) +
         (c.mean_value_interior ? ", mean value interior" : "") +
         (c.holomorphic_extension ? ", holomorphic extension" : "") + tried;
}

std::string repair_text(const SMP::Parameterization_report& report, bool enabled)
{
  if(report.repaired)
    return "repaired " + std::to_string(report.flipped_faces_before_repair) + " flipped faces: blend " +
           rounded(report.blend, 3) + (report.mean_value_interior ? ", mean value interior" : "");
  return enabled ? "no repair needed" : "repair off";
}

namespace {

// "1 polygon", "2 polygons"
std::string counted(std::size_t n, const std::string& noun)
{
  return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
}

// the one-line summary of an atlas
std::string atlas_summary_line(const Run_facts& f)
{
  const Options& o = f.options;
  const Atlas_result& a = f.result.atlas;
  const SMP::Atlas_report& r = a.report;
  return f.mesh_name + ": " + counted(a.soup.points.size(), "point") + ", " +
         counted(a.soup.number_of_faces(), "polygon") + " | " + atlas_charts_text(f) + " | repairs: " +
         repair_list(r.repair) + " | area spread " + rounded(r.area_spread) + ", angle distortion " +
         rounded(r.angle_distortion) + " | " + atlas_bounds_text(r) + " | seconds: repair " + rounded(r.repair_seconds, 3) + ", charts " +
         rounded(r.chart_seconds, 3) + ", packing " + rounded(r.packing_seconds, 3) + ", total " +
         rounded(r.total_seconds, 3) + " | wrote " + o.output + (o.svg.empty() ? std::string() : ", " + o.svg) + "\n";
}

} // namespace

std::string repair_list(const SMP::Soup_repair_report& r)
{
  struct Repair
  {
    std::size_t count;
    const char *one, *many;  // the text after the count
  };
  const Repair repairs[] = {
    {r.merged_points, "point merged", "points merged"},
    {r.duplicate_polygons, "duplicate polygon", "duplicate polygons"},
    {r.degenerate_polygons, "degenerate polygon", "degenerate polygons"},
    {r.polygons_with_repeated_points, "polygon with a repeated point", "polygons with a repeated point"},
    {r.non_manifold_edges, "non-manifold edge", "non-manifold edges"},
    {r.pinched_vertices, "pinched vertex", "pinched vertices"},
    {r.non_orientable_components, "non-orientable piece cut", "non-orientable pieces cut"},
    {r.reoriented_polygons, "polygon re-oriented", "polygons re-oriented"},
    {r.detached_polygons, "polygon detached", "polygons detached"},
    {r.triangulated_polygons, "polygon triangulated", "polygons triangulated"},
    {r.zero_area_triangles, "triangle of zero area", "triangles of zero area"}};
  std::string s;
  for(const Repair& repair : repairs)
    if(repair.count > 0)
      s += (s.empty() ? "" : ", ") + std::to_string(repair.count) + " " + (repair.count == 1 ? repair.one : repair.many);
  return s.empty() ? std::string("none") : s;
}

const char* flattening_name(SMP::Chart_flattening f)
{
  return f == SMP::DISK_CHART ? "disk" : f == SMP::SEAMED_CHART ? "seamed" : "unfolded";
}

std::string atlas_bounds_text(const SMP::Atlas_report& r)
{
  double spread = 0., angle = 0., compactness = r.charts.empty() ? 0. : 1.;
  for(const SMP::Atlas_chart_report& c : r.charts)
  {
    spread = (std::max)(spread, c.area_spread);
    angle = (std::max)(angle, c.angle_distortion);
    compactness = (std::min)(compactness, c.compactness);
  }
  return "bounds: area spread <= " + rounded(r.max_area_spread) + " (largest " + rounded(spread, 3) +
         "), angle distortion <= " + rounded(r.max_angle_distortion) + " (largest " + rounded(angle, 3) +
         "), compactness >= " + rounded(r.min_compactness) + " (smallest " + rounded(compactness, 3) + "), " +
         counted(r.splits, "split");
}

std::string atlas_charts_text(const Run_facts& f)
{
  const SMP::Atlas_report& r = f.result.atlas.report;
  return counted(r.charts.size(), "chart") + ", utilization " + rounded(100. * r.utilization, 3) + "% (" +
         std::to_string(f.options.resolution) + " texels, gutter " + std::to_string(f.options.gutter) + ")";
}

std::string summary_line(const Run_facts& f)
{
  if(f.options.mode == Mode::atlas)
    return atlas_summary_line(f);
  const Options& o = f.options;
  const SMP::Parameterization_report& r = f.result.report;
  return summary_of_mesh(f) + " | border " + border_name(o.border) + ": " + kept_border(r, o.distance) +
         " | seconds: preparation " + rounded(r.preparation_seconds, 3) + ", center " +
         rounded(r.center_seconds, 3) + ", distances " + rounded(r.distance_seconds, 3) + ", border map " +
         rounded(r.border_map_seconds, 3) + ", conformal border " + rounded(r.conformal_border_seconds, 3) +
         (o.border == Border::conformal_lengths ? ", conformal lengths " + rounded(r.conformal_length_seconds, 3)
                                                : std::string()) +
         ", layouts " + rounded(r.interior_seconds, 3) + ", total " + rounded(r.total_seconds, 3) + " | " +
         solver_name(o.solver) + ": " + std::to_string(r.statistics.factorizations) + " factorizations, " +
         std::to_string(r.statistics.back_substitutions) + " back-substitutions" +
         summary_of_quality(f.result.quality) + " | " + repair_text(r, o.repair) + " | wrote " + o.output +
         (o.svg.empty() ? std::string() : ", " + o.svg) + "\n";
}

} // namespace mbp_cli
