// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// The OBJ output of the measured_parameterization program (obj_writer.h): the atlas, or the
// single chart. No CGAL here.

#include "obj_writer.h"
#include "summary.h"

#include <array>
#include <cstddef>
#include <string>

namespace mbp_cli {

namespace {

// A line of text for a comment of the OBJ file: no line breaks or other control characters.
std::string one_line(std::string s)
{
  for(char& c : s)
    if(static_cast<unsigned char>(c) < 0x20)
      c = '?';
  return s;
}

// the comments at the top: the method, the border kept, the input, the seams, the sizes
void write_header(Buffered_writer& out, const Run_facts& f)
{
  const Options& o = f.options;
  const Uv_layout& layout = f.result.layout;
  const Seams& seams = f.result.seams;
  out << "# UV layout by measured_parameterization: measured boundary parameterization (center: "
      << o.center_name() << ", border distances: " << o.distance << "), discrete conformal interior\n";
  out << "# border: --border=" << border_name(o.border) << ", kept " << kept_border(f.result.report, o.distance)
      << "\n";
  out << "# input: " << one_line(f.generated ? f.mesh_name : o.input) << "\n";
  if(seams.cut)
    out << "# cut along " << seams.edges << " seam edges ("
        << (seams.automatic ? "automatic, " + std::to_string(seams.cones.size()) + " cones" : one_line(o.seams))
        << "): one 'vt' per side of a seam, faces 'f v/vt'\n";
  out << "# " << layout.vertices.size() << " vertices, " << layout.faces.size() << " faces"
      << (layout.has_center ? ", center: input vertex " + std::to_string(layout.center_vertex) + " (0-based)"
                            : std::string())
      << "\n";
}

// The atlas: the input's points ('v', input order), one 'vt' per polygon corner (polygon
// order), the input's polygons in their order as 'f v/vt ...', and 'g chart_K' wherever the
// chart changes between consecutive polygons; a header of comments.
void write_atlas_obj(Buffered_writer& out, const Run_facts& f)
{
  const Atlas_result& a = f.result.atlas;
  const Polygon_soup& soup = a.soup;
  out << "# texture atlas by measured_parameterization: " << atlas_charts_text(f) << "\n";
  out << "# input: " << one_line(f.generated ? f.mesh_name : f.options.input) << "\n";
  out << "# repairs: " << repair_list(a.report.repair) << "\n";
  out << "# " << soup.points.size() << " vertices ('v': the input's points in input order), "
      << soup.number_of_faces() - a.empty_polygons << " polygons, " << a.uv.size()
      << " UVs ('vt': one per polygon corner, in polygon order), " << a.report.charts.size()
      << " charts ('g chart_K')\n";
  if(a.empty_polygons > 0)
    out << "# " << a.empty_polygons << " polygons without vertices left out\n";
  for(const std::array<double, 3>& p : soup.points)
    out << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  for(const std::array<double, 2>& q : a.uv)
    out << "vt " << q[0] << ' ' << q[1] << '\n';
  std::size_t chart = Atlas_result::no_chart;
  for(std::size_t i = 0; i < soup.number_of_faces(); ++i)
  {
    if(soup.face_size(i) == 0)
      continue;
    if(a.polygon_chart[i] != chart)
    {
      chart = a.polygon_chart[i];
      out << "g chart_" << chart << '\n';
    }
    out << 'f';
    for(std::size_t k = soup.face_begin(i); k < soup.face_end[i]; ++k)
      out << ' ' << std::size_t(soup.corners[k]) + 1 << '/' << k + 1;
    out << '\n';
  }
}

} // namespace

void write_obj(Buffered_writer& out, const Run_facts& f)
{
  if(f.options.mode == Mode::atlas)
  {
    write_atlas_obj(out, f);
    return;
  }
  const Uv_layout& layout = f.result.layout;
  write_header(out, f);
  for(const std::array<double, 3>& p : layout.points)
    out << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  for(const std::array<double, 2>& q : layout.uv)
    out << "vt " << q[0] << ' ' << q[1] << '\n';
  for(const std::array<std::size_t, 3>& t : layout.faces)
  {
    out << 'f';
    for(std::size_t u : t)
      out << ' ' << layout.uv_vertex[u] + 1 << '/' << u + 1;
    out << '\n';
  }
}

} // namespace mbp_cli
