// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// The parts of the one-line summary that read plain data (summary.h). No CGAL here.

#include "summary.h"

namespace mbp_cli {

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

} // namespace mbp_cli
