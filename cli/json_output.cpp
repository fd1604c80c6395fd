// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// The JSON output (json_output.h): the document of a failed run, and the sections of the
// document of a successful run, an atlas or a single chart. No CGAL here but the library's
// reports.

#include "json_output.h"
#include "summary.h"
#include "text_output.h"

#include <cstddef>

namespace mbp_cli {

namespace SMP = CGAL::Surface_mesh_parameterization;

namespace {

// seams, seam_edges, automatic_seams
void write_seams(Json_writer& j, const Run_facts& f)
{
  const Seams& s = f.result.seams;
  if(s.cut && !s.automatic)
    j.member("seams", f.options.seams);
  else
    j.null_member("seams");
  j.member("seam_edges", s.edges);
  if(!s.automatic)
  {
    j.null_member("automatic_seams");
    return;
  }
  j.begin_object("automatic_seams").member("seam_edges", s.edges).member("cones", s.cones.size());
  j.begin_array("cone_vertices");
  for(std::size_t v : s.cones)
    j.element(double(v));
  j.end_array();
  j.member("length", s.length)
     .member("genus", s.genus)
     .member("border_loops", s.border_loops)
     .member("loops", s.loops)
     .member("seconds", s.seconds)
     .end_object();
}

// center: its input vertex, point and UV, or null
void write_center(Json_writer& j, const Uv_layout& layout)
{
  if(!layout.has_center)
  {
    j.null_member("center");
    return;
  }
  const std::array<double, 3>& p = layout.center_point;
  const std::array<double, 2>& uv = layout.uv[layout.center];
  j.begin_object("center").member("index", layout.center_vertex);
  j.begin_array("point").element(p[0]).element(p[1]).element(p[2]).end_array();
  j.begin_array("uv").element(uv[0]).element(uv[1]).end_array();
  j.end_object();
}

// input, generated_mesh, mesh, output, svg: the files of the run (both modes)
void write_files(Json_writer& j, const Run_facts& f)
{
  const Options& o = f.options;
  if(f.generated)
    j.null_member("input");
  else
    j.member("input", o.input);
  j.member("generated_mesh", f.generated);
  j.member("mesh", f.mesh_name);
  j.member("output", o.output);
  if(o.svg.empty())
    j.null_member("svg");
  else
    j.member("svg", o.svg);
}

// the members from the command line: input, generated_mesh, mesh, output, svg, solver,
// center_locator, border_distance
void write_command_line(Json_writer& j, const Run_facts& f)
{
  const Options& o = f.options;
  write_files(j, f);
  j.member("solver", solver_name(o.solver));
  j.member("center_locator", o.fixed_center ? std::string("vertex") : o.center);
  j.member("border_distance", o.distance);
}

// the members on the mesh and its layout: vertices, faces, isolated_vertices, seams,
// seam_edges, automatic_seams, uvs, border, center
void write_mesh(Json_writer& j, const Run_facts& f)
{
  const Uv_layout& layout = f.result.layout;
  j.member("vertices", layout.vertices.size());
  j.member("faces", layout.faces.size());
  j.member("isolated_vertices", f.result.input_vertices - layout.vertices.size());
  write_seams(j, f);
  j.member("uvs", layout.uv.size());
  j.begin_object("border")
     .member("vertices", f.result.border_vertices)
     .member("length", f.result.border_length)
     .member("convex", f.result.report.border_convex)
     .end_object();
  write_center(j, layout);
}

// the times measured by the program: io_times
void write_io_times(Json_writer& j, const Run_facts& f)
{
  j.begin_object("io_times")
     .member("read", f.read_seconds)
     .member("quality", f.result.quality_seconds)
     .member("write", f.write_seconds)
     .end_object();
}

// the distortion: quality
void write_quality(Json_writer& j, const Quality& q)
{
  j.begin_object("quality")
     .member("angle_distortion", q.angle_distortion)
     .member("angle_distortion_per_corner", q.angle_distortion_per_corner)
     .member("l2_stretch", q.l2_stretch)
     .member("linf_stretch", q.linf_stretch)
     .member("quasi_conformal_mean", q.quasi_conformal_mean)
     .member("quasi_conformal_max", q.quasi_conformal_max)
     .member("area_distortion_mean", q.area_distortion_mean)
     .member("area_distortion_max", q.area_distortion_max)
     .member("flipped_faces", q.flipped_faces)
     .end_object();
}

// the layouts tried and the one kept: border_choice
void write_border_choice(Json_writer& j, const Run_facts& f)
{
  const SMP::Parameterization_report& r = f.result.report;
  j.begin_object("border_choice").member("mode", border_name(f.options.border));
  // a candidate's members (its figures null when it is not valid)
  const auto candidate = [&](const SMP::Border_candidate& c) -> Json_writer& {
    return j.member("kind", candidate_kind(c, f.options.distance))
      .member("blend", c.blend)
      .member("mean_value_interior", c.mean_value_interior)
      .member("holomorphic_extension", c.holomorphic_extension)
      .member("valid", c.valid)
      .member("angle_distortion", c.objective)
      .member("area_spread", c.area_spread);
  };
  if(r.chosen_candidate >= 0)
  {
    j.begin_object("chosen").member("index", r.chosen_candidate);
    candidate(r.border_candidates[static_cast<std::size_t>(r.chosen_candidate)]).end_object();
  }
  else
    j.null_member("chosen");
  j.begin_array("candidates", false);
  for(const SMP::Border_candidate& c : r.border_candidates)
  {
    j.begin_object();
    candidate(c).end_object();
  }
  j.end_array();
  j.end_object();
}

// the stages of the parameterization: times
void write_times(Json_writer& j, const SMP::Parameterization_report& r)
{
  j.begin_object("times")
     .member("preparation", r.preparation_seconds)
     .member("center", r.center_seconds)
     .member("distances", r.distance_seconds)
     .member("border_map", r.border_map_seconds)
     .member("conformal_border", r.conformal_border_seconds)
     .member("conformal_lengths", r.conformal_length_seconds)  // --border=conformal-lengths
     .member("interior", r.interior_seconds)  // every layout tried before repair
     .member("output", r.output_seconds)
     .member("total", r.total_seconds)
     .end_object();
}

// the repair (`enabled`: not --no-repair): repair
void write_repair(Json_writer& j, const SMP::Parameterization_report& r, bool enabled)
{
  j.begin_object("repair")
     .member("enabled", enabled)
     .member("flipped_faces_before", r.flipped_faces_before_repair)
     .member("repaired", r.repaired)
     .member("blend", r.blend)
     .member("interior", r.mean_value_interior ? "mean value coordinates" : "discrete conformal")
     .member("candidates", r.repair_candidates)
     .member("seconds", r.repair_seconds)
     .end_object();
}

// the solver's work: statistics
void write_statistics(Json_writer& j, const SMP::Solver_statistics& s)
{
  j.begin_object("statistics")
     .member("factorizations", s.factorizations)
     .member("back_substitutions", s.back_substitutions)
     .member("factorization_seconds", s.factorization_seconds)
     .member("back_substitution_seconds", s.back_substitution_seconds)
     .end_object();
}

// ---------------------------------------------------------------------------- the atlas

// the repairs of the input: repair (every count of the library's Soup_repair_report)
void write_soup_repair(Json_writer& j, const SMP::Soup_repair_report& r)
{
  j.begin_object("repair")
     .member("input_points", r.input_points)
     .member("input_polygons", r.input_polygons)
     .member("input_corners", r.input_corners)
     .member("merged_points", r.merged_points)
     .member("degenerate_polygons", r.degenerate_polygons)
     .member("polygons_with_repeated_points", r.polygons_with_repeated_points)
     .member("duplicate_polygons", r.duplicate_polygons)
     .member("non_manifold_edges", r.non_manifold_edges)
     .member("pinched_vertices", r.pinched_vertices)
     .member("non_orientable_components", r.non_orientable_components)
     .member("vertices_split_non_manifold", r.vertices_split_non_manifold)
     .member("vertices_split_non_orientable", r.vertices_split_non_orientable)
     .member("reoriented_polygons", r.reoriented_polygons)
     .member("detached_polygons", r.detached_polygons)
     .member("triangulated_polygons", r.triangulated_polygons)
     .member("triangles_from_polygons", r.triangles_from_polygons)
     .member("zero_area_triangles", r.zero_area_triangles)
     .member("vertices_split_after_removal", r.vertices_split_after_removal)
     .member("vertices", r.vertices)
     .member("faces", r.faces)
     .member("components", r.components)
     .member("collapsed_corners", r.collapsed_corners)
     .member("isolated_corners", r.isolated_corners)
     .end_object();
}

// the charts: chart_count, and charts, one object per chart (by chart id)
void write_charts(Json_writer& j, const SMP::Atlas_report& r)
{
  j.member("chart_count", r.charts.size());
  j.begin_array("charts", false);
  for(const SMP::Atlas_chart_report& c : r.charts)
    j.begin_object()
       .member("faces", c.faces)
       .member("flattening", flattening_name(c.flattening))
       .member("area_3d", c.area_3d)
       .member("area_uv", c.area_uv)
       .member("angle_distortion", c.angle_distortion)
       .member("area_spread", c.area_spread)
       .member("compactness", c.compactness)
       .end_object();
  j.end_array();
}

// the document of an atlas
std::string json_atlas_document(const Run_facts& f)
{
  const Options& o = f.options;
  const Atlas_result& a = f.result.atlas;
  const SMP::Atlas_report& r = a.report;
  Json_writer j;
  j.begin_object();
  j.member("mode", mode_name(o.mode));
  write_files(j, f);
  j.member("resolution", std::size_t(o.resolution));
  j.member("gutter", std::size_t(o.gutter));
  j.begin_object("bounds")
     .member("max_area_spread", r.max_area_spread)
     .member("max_angle_distortion", r.max_angle_distortion)
     .member("min_compactness", r.min_compactness)
     .member("split", o.bounds.split == SMP::SPLIT_BY_SCALE ? "scale" : "normals")
     .end_object();
  j.member("splits", r.splits);
  j.member("points", a.soup.points.size());
  j.member("polygons", a.soup.number_of_faces());
  j.member("corners", a.soup.corners.size());
  j.member("empty_polygons", a.empty_polygons);
  write_soup_repair(j, r.repair);
  write_charts(j, r);
  j.member("utilization", r.utilization);
  j.member("texel_density", r.texel_density);
  j.member("angle_distortion", r.angle_distortion);
  j.member("area_spread", r.area_spread);
  j.begin_object("times")
     .member("read", f.read_seconds)
     .member("repair", r.repair_seconds)
     .member("charts", r.chart_seconds)
     .member("packing", r.packing_seconds)
     .member("total", r.total_seconds)
     .member("write", f.write_seconds)
     .end_object();
  j.end_object();
  return j.text();
}

} // namespace

std::string json_failure(const std::string& message, int status, int error_code)
{
  Json_writer j;
  j.begin_object().member("error", message).member("code", status);
  if(error_code == 0)
    j.null_member("error_code");
  else
    j.member("error_code", error_code);
  j.end_object();
  return j.text();
}

std::string json_document(const Run_facts& f)
{
  if(f.options.mode == Mode::atlas)
    return json_atlas_document(f);
  const SMP::Parameterization_report& r = f.result.report;
  Json_writer j;
  j.begin_object();
  j.member("mode", mode_name(f.options.mode));
  write_command_line(j, f);
  write_border_choice(j, f);
  write_mesh(j, f);
  write_times(j, r);
  write_io_times(j, f);
  write_repair(j, r, f.options.repair);
  write_statistics(j, r.statistics);
  write_quality(j, f.result.quality);
  j.end_object();
  return j.text();
}

} // namespace mbp_cli
