// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// The sections of the JSON output that read plain data (json_output.h). No CGAL here.

#include "json_output.h"

namespace mbp_cli {

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

void write_command_line(Json_writer& j, const Run_facts& f)
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
  j.member("solver", solver_name(o.solver));
  j.member("center_locator", o.fixed_center ? std::string("vertex") : o.center);
  j.member("border_distance", o.distance);
}

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
     .member("convex", f.result.border_convex)
     .end_object();
  write_center(j, layout);
}

void write_io_times(Json_writer& j, const Run_facts& f)
{
  j.begin_object("io_times")
     .member("read", f.read_seconds)
     .member("quality", f.result.quality_seconds)
     .member("write", f.write_seconds)
     .end_object();
}

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

} // namespace mbp_cli
