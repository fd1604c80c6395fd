// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// The SVG output of the measured_parameterization program (svg_writer.h). No CGAL here.

#include "svg_writer.h"

#include "summary.h"
#include "svg_layout.h"
#include "text_output.h"

#include <limits>

namespace mbp_cli {

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

} // namespace

std::string svg_picture(const Run_facts& f)
{
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
