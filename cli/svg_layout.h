// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// An SVG picture of a UV layout: faces colored by their angle distortion (log scale, with a
// legend), flipped faces in red and circled, the border as a closed polyline, the seams of a
// cut mesh over it (both sides of each), the center marked, and a caption. Or, for an atlas,
// polygons colored by another distortion in the framed unit square, the charts outlined.
// The picture is widened where a caption line or a legend entry would not fit in it. No CGAL
// here.
//
// Size: coordinates are integers in units of 1e-4 of the UV square (UV positions rounded to
// 4 decimals), faces of one color share one path element, and each face is written as
// "M x y l dx dy dx dy z": about 25 bytes a face, 2.5 MB for 100k faces.

#ifndef MBP_CLI_SVG_LAYOUT_H
#define MBP_CLI_SVG_LAYOUT_H

#include "text_output.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>
#include <vector>

namespace mbp_cli {

struct Svg_layout
{
  std::vector<std::array<double, 2> > uv;                 // per vertex, finite
  std::vector<std::array<std::size_t, 3> > faces;         // vertex indices, counterclockwise in UV when not flipped
  std::vector<double> face_angle_distortion;              // per face, >= 0
  std::vector<bool> face_flipped;                         // per face: UV area <= 0
  std::vector<std::size_t> border;                        // vertex indices along the border loop
  std::vector<std::array<std::size_t, 2> > seams;         // seam edges as vertex index pairs, one per side
  std::size_t seam_edges = 0;                             // seam edges of the mesh (for the legend)
  std::size_t center = 0;                                 // vertex index of the center
  std::string center_label;                               // e.g. "center (vertex 12)"
  std::string title;                                      // first caption line (mesh name)
  std::vector<std::string> caption;                       // further caption lines
  // Color range of the angle distortion: when 0 < color_lo < color_hi, this fixed range
  // (e.g. shared by several pictures to compare); otherwise the 2nd and 98th percentiles.
  double color_lo = 0., color_hi = 0.;
  bool legend = true;                                     // the color bar and marks on the right
  bool center_text = true;                                // the center's label beside its marker
  int wireframe = -1;                                     // mesh edges: 1 drawn, 0 not, -1 when they are long enough
  double mark_scale = 1.;                                 // scales the border line and the center marker of the
                                                          // layout (for a picture shown smaller than its nominal size)
  // Polygons instead of triangles: when not empty, `faces` is not used, polygon i is drawn
  // through uv[polygon_end[i - 1]], ..., uv[polygon_end[i] - 1] (polygon_end[-1] = 0), and
  // face_angle_distortion and face_flipped are per polygon.
  std::vector<std::size_t> polygon_end;
  std::vector<std::array<std::size_t, 2> > outlines;      // chart outlines: uv index pairs, drawn over the faces
  std::string outline_label;                              // their legend entry, e.g. "chart outlines (12 charts)"
  bool unit_square = false;                               // draw [0,1]^2, framed, rather than the layout's bounding box
  std::string frame_label;                                // the frame's legend entry (with unit_square)
  std::string color_title = "angle distortion per face";  // the color bar's title and note
  std::string color_note = "(mean of its 3 corners, log scale)";
  bool layout_marks = true;                               // the legend's flipped faces, border and center entries
};

namespace detail {

inline std::string xml_escaped(const std::string& s)
{
  std::string e;
  for(char c : s)
  {
    switch(c)
    {
    case '&': e += "&amp;"; break;
    case '<': e += "&lt;"; break;
    case '>': e += "&gt;"; break;
    case '"': e += "&quot;"; break;
    default:
      // control characters are not allowed in XML 1.0
      e += (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n') ? '?' : c;
    }
  }
  return e;
}

// Viridis (perceptually uniform, readable in grey scale), t in [0, 1].
inline std::string viridis(double t)
{
  static const double stops[9][3] = {
    {0x44, 0x01, 0x54}, {0x47, 0x2d, 0x7b}, {0x3b, 0x52, 0x8b}, {0x2c, 0x72, 0x8e}, {0x21, 0x91, 0x8c},
    {0x28, 0xae, 0x80}, {0x5e, 0xc9, 0x62}, {0xad, 0xdc, 0x30}, {0xfd, 0xe7, 0x25}};
  t = std::clamp(t, 0., 1.) * 8.;
  const int i = (std::min)(int(t), 7);
  const double s = t - i;
  char hex[8];
  std::snprintf(hex, sizeof(hex), "#%02x%02x%02x",
                unsigned(std::lround(stops[i][0] + s * (stops[i + 1][0] - stops[i][0]))),
                unsigned(std::lround(stops[i][1] + s * (stops[i + 1][1] - stops[i][1]))),
                unsigned(std::lround(stops[i][2] + s * (stops[i + 1][2] - stops[i][2]))));
  return hex;
}

// Appends integer `n` to a path: a space separates it from a previous number unless its
// minus sign does, or the previous character is a command letter.
inline void append_coordinate(std::string& d, long n)
{
  if(!d.empty() && n >= 0 && !std::isalpha(static_cast<unsigned char>(d.back())))
    d += ' ';
  d += std::to_string(n);
}

// Value of a legend tick, short: 0.001, 0.25, 3e-05.
inline std::string tick_text(double x)
{
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.2g", x);
  return buffer;
}

// The width of `text` in SVG units at `font_size`, estimated from its characters at or above
// their advance in DejaVu Sans, the widest of the fonts the document names (narrow letters and
// punctuation 0.4 em, wide letters and capitals 0.9 em, the others 0.64 em; bold 10% more):
// for keeping every label inside the picture.
inline long text_width(const std::string& text, long font_size, bool bold = false)
{
  static const std::string narrow = "fijlrt .,:;'|!()[]/-", wide = "mwMW@%";
  double em = 0.;
  for(char c : text)
  {
    const unsigned char u = static_cast<unsigned char>(c);
    if((u & 0xc0) == 0x80)  // a continuation byte of UTF-8: its character is counted once
      continue;
    em += narrow.find(c) != std::string::npos ? 0.4 : (wide.find(c) != std::string::npos || std::isupper(u)) ? 0.9 : 0.64;
  }
  return long(std::ceil(em * double(font_size) * (bold ? 1.1 : 1.)));
}

// The drawing of a layout: its frame (SVG units, positions), its color scale, then the
// parts of the document in order.
class Svg_drawing
{
public:
  static constexpr double unit = 1e4;                // SVG units per UV unit
  static constexpr long pad = 300, line = 300;       // 10 SVG units = 1 pixel at the nominal size
  static constexpr long legend_width = 3400, bar_width = 400, bar_height = 5000;
  static constexpr int bins = 32;
  static constexpr std::size_t max_markers = 1000;   // more flipped faces are not circled: the circles would hide the layout

  explicit Svg_drawing(const Svg_layout& layout) : m_layout(layout)
  {
    place();
    scale_colors();
    trace_faces();
  }

  std::string document()
  {
    m_s.reserve(64 * m_layout.faces.size() + 8192);
    write_head();
    write_faces();
    write_frame_and_outlines();
    write_border_and_seams();
    // Circles around the flipped faces (which may be too small to see), unless there are too
    // many of them.
    if(m_flipped <= max_markers && !m_markers.empty())
      m_s += "<g fill=\"none\" stroke=\"#ff1a1a\" stroke-width=\"25\">" + m_markers + "</g>\n";
    write_center();
    if(m_layout.legend)
    {
      write_color_bar();
      write_marks();
    }
    m_s += "</svg>\n";
    return m_s;
  }

private:
  // Bounding box of the layout, and where everything goes.
  void place()
  {
    const Svg_layout& layout = m_layout;
    double umin = 0., umax = 1., vmin = 0., vmax = 1.;
    if(!layout.uv.empty() && !layout.unit_square)
    {
      umin = umax = layout.uv[0][0];
      vmin = vmax = layout.uv[0][1];
    }
    for(const auto& p : layout.uv)  // the unit square, or the layout's bounding box
    {
      umin = (std::min)(umin, p[0]); umax = (std::max)(umax, p[0]);
      vmin = (std::min)(vmin, p[1]); vmax = (std::max)(vmax, p[1]);
    }
    m_w = (std::max)(1L, std::lround((umax - umin) * unit));
    const long h = (std::max)(1L, std::lround((vmax - vmin) * unit));
    const bool has_caption = !layout.title.empty() || !layout.caption.empty();
    const long caption_height = has_caption ? pad + line * long(1 + layout.caption.size()) + pad / 2 : pad;
    m_x0 = pad;
    m_y0 = caption_height;
    m_frame = {m_x0 + std::lround((0. - umin) * unit), m_y0 + std::lround((vmax - 1.) * unit)};
    // UV -> SVG, v upwards
    m_xy.resize(layout.uv.size());
    for(std::size_t i = 0; i < m_xy.size(); ++i)
      m_xy[i] = {m_x0 + std::lround((layout.uv[i][0] - umin) * unit), m_y0 + std::lround((vmax - layout.uv[i][1]) * unit)};

    m_legend_x = m_x0 + m_w + pad;
    const long legend_height = 2 * line + bar_height + 5 * line;
    m_width = layout.legend ? m_legend_x + (std::max)(legend_width, widest_legend_entry() + pad) : m_x0 + m_w + pad;
    m_height = m_y0 + (layout.legend ? (std::max)(h, legend_height) : h) + pad;
    // the caption inside the picture
    if(!layout.title.empty())
      m_width = (std::max)(m_width, 2 * pad + text_width(layout.title, 260, true));
    for(const std::string& c : layout.caption)
      m_width = (std::max)(m_width, 2 * pad + text_width(c, 210));
  }

  // The width the legend's texts take right of its left edge (the tick labels excepted:
  // numbers of a few characters).
  long widest_legend_entry() const
  {
    const Svg_layout& layout = m_layout;
    long w = (std::max)(text_width(layout.color_title, 210), text_width(layout.color_note, 170));
    std::vector<std::string> entries;
    if(layout.layout_marks)
      entries = {"flipped faces: " + std::to_string(layout.faces.size()), "(too many to circle)",
                 "border (" + std::to_string(layout.border.size()) + " vertices)", "center"};
    else
      entries = {layout.frame_label};
    if(!layout.seams.empty())
      entries.push_back("seams (" + std::to_string(layout.seam_edges) + " edges, both sides)");
    if(!layout.outline_label.empty())
      entries.push_back(layout.outline_label);
    for(const std::string& e : entries)
      w = (std::max)(w, 520 + text_width(e, 190));
    return w;
  }

  // Color scale: log10 of the per-face angle distortion between its 2nd and 98th percentiles
  // over the faces with a positive value (robust to a few extreme faces); values beyond the
  // ends get the end colors.
  void scale_colors()
  {
    std::vector<double> positive;
    for(double a : m_layout.face_angle_distortion)
      if(a > 0. && std::isfinite(a))
        positive.push_back(a);
    m_has_positive = !positive.empty();
    if(m_layout.color_lo > 0. && m_layout.color_hi > m_layout.color_lo)
    {
      m_lo = m_layout.color_lo;
      m_hi = m_layout.color_hi;
    }
    else if(!positive.empty())
    {
      std::sort(positive.begin(), positive.end());
      m_lo = positive[std::size_t(0.02 * double(positive.size() - 1))];
      m_hi = positive[std::size_t(0.98 * double(positive.size() - 1))];
      if(!(m_hi > m_lo))
        m_hi = m_lo * 10.;
    }
    m_log_lo = (m_lo > 0.) ? std::log10(m_lo) : 0.;
    m_log_hi = (m_hi > 0.) ? std::log10(m_hi) : 1.;
  }

  int bin_of(double a) const
  {
    if(!(a > m_lo))
      return 0;
    if(!std::isfinite(a) || a >= m_hi)
      return bins - 1;
    const double t = (std::log10(a) - m_log_lo) / (m_log_hi - m_log_lo);
    return std::clamp(int(t * bins), 0, bins - 1);
  }

  static std::string bin_color(int b) { return viridis((b + 0.5) / bins); }

  // Faces per bin, flipped faces apart.
  void trace_faces()
  {
    const Svg_layout& layout = m_layout;
    m_paths.resize(static_cast<std::size_t>(bins));
    double edge_sum = 0.;
    const bool polygons = !layout.polygon_end.empty();
    const std::size_t n = polygons ? layout.polygon_end.size() : layout.faces.size();
    std::vector<std::size_t> corners;
    for(std::size_t f = 0; f < n; ++f)
    {
      corners.clear();
      if(polygons)
        for(std::size_t k = (f == 0 ? 0 : layout.polygon_end[f - 1]); k < layout.polygon_end[f]; ++k)
          corners.push_back(k);
      else
        corners.assign(layout.faces[f].begin(), layout.faces[f].end());
      if(corners.empty())
        continue;
      const bool is_flipped = layout.face_flipped[f];
      std::string& d = is_flipped ? m_flipped_path : m_paths[std::size_t(bin_of(layout.face_angle_distortion[f]))];
      const auto& a = m_xy[corners[0]];
      d += 'M';
      append_coordinate(d, a[0]); append_coordinate(d, a[1]);
      d += 'l';
      std::array<long, 2> sum = a;
      for(std::size_t k = 1; k < corners.size(); ++k)
      {
        const auto &p = m_xy[corners[k - 1]], &q = m_xy[corners[k]];
        append_coordinate(d, q[0] - p[0]); append_coordinate(d, q[1] - p[1]);
        sum = {sum[0] + q[0], sum[1] + q[1]};
      }
      d += 'z';
      if(corners.size() > 1)
        edge_sum += std::hypot(double(m_xy[corners[1]][0] - a[0]), double(m_xy[corners[1]][1] - a[1]));
      if(is_flipped && ++m_flipped <= max_markers)
        m_markers += "<circle cx=\"" + std::to_string(sum[0] / long(corners.size())) + "\" cy=\"" +
                     std::to_string(sum[1] / long(corners.size())) + "\" r=\"120\"/>";
    }
    // Draw the mesh edges when they are at least 6 pixels long on average; otherwise stroke
    // each face with its own color to hide the hairline seams of anti-aliasing.
    m_wireframe = (layout.wireframe >= 0) ? layout.wireframe > 0 : n > 0 && edge_sum / double(n) >= 60.;
    m_border_width = std::lround(22. * layout.mark_scale);
  }

  // The document's head and the caption.
  void write_head()
  {
    std::string& s = m_s;
    s += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    s += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(m_width / 10) + "\" height=\"" +
         std::to_string(m_height / 10) + "\" viewBox=\"0 0 " + std::to_string(m_width) + " " +
         std::to_string(m_height) + "\" font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\">\n";
    s += "<title>" + xml_escaped(m_layout.title) + ": UV layout</title>\n";
    s += "<rect width=\"" + std::to_string(m_width) + "\" height=\"" + std::to_string(m_height) +
         "\" fill=\"#ffffff\"/>\n";
    s += "<text x=\"" + std::to_string(pad) + "\" y=\"" + std::to_string(pad + line - 60) +
         "\" font-size=\"260\" font-weight=\"bold\">" + xml_escaped(m_layout.title) + "</text>\n";
    for(std::size_t i = 0; i < m_layout.caption.size(); ++i)
      s += "<text x=\"" + std::to_string(pad) + "\" y=\"" + std::to_string(pad + line * long(i + 2) - 60) +
           "\" font-size=\"210\">" + xml_escaped(m_layout.caption[i]) + "</text>\n";
  }

  void write_faces()
  {
    std::string& s = m_s;
    s += "<g stroke-linejoin=\"round\"";
    s += m_wireframe ? " stroke=\"#000000\" stroke-opacity=\"0.25\" stroke-width=\"5\">\n" : " stroke-width=\"6\">\n";
    for(int b = 0; b < bins; ++b)
      if(!m_paths[std::size_t(b)].empty())
      {
        s += "<path fill=\"" + bin_color(b) + "\"";
        if(!m_wireframe)
          s += " stroke=\"" + bin_color(b) + "\"";
        s += " d=\"" + m_paths[std::size_t(b)] + "\"/>\n";
      }
    s += "</g>\n";
    if(!m_flipped_path.empty())
    {
      s += "<path fill=\"#ff1a1a\" stroke=\"#000000\" stroke-width=\"10\" stroke-linejoin=\"round\" d=\"" +
           m_flipped_path + "\"/>\n";
    }
  }

  // The frame of the unit square, and the chart outlines.
  void write_frame_and_outlines()
  {
    std::string& s = m_s;
    if(m_layout.unit_square)
      s += "<rect x=\"" + std::to_string(m_frame[0]) + "\" y=\"" + std::to_string(m_frame[1]) + "\" width=\"" +
           std::to_string(std::lround(unit)) + "\" height=\"" + std::to_string(std::lround(unit)) +
           "\" fill=\"none\" stroke=\"#888888\" stroke-width=\"12\"/>\n";
    if(m_layout.outlines.empty())
      return;
    s += "<path fill=\"none\" stroke=\"#000000\" stroke-width=\"" + std::to_string(outline_width()) +
         "\" stroke-linecap=\"round\" d=\"";
    for(const std::array<std::size_t, 2>& e : m_layout.outlines)
    {
      const auto &p = m_xy[e[0]], &q = m_xy[e[1]];
      s += "M" + std::to_string(p[0]) + " " + std::to_string(p[1]) + "L" + std::to_string(q[0]) + " " +
           std::to_string(q[1]);
    }
    s += "\"/>\n";
  }

  long outline_width() const { return std::lround(12. * m_layout.mark_scale); }

  // The border, a closed polyline, and the seams: on the border, both sides of every seam
  // edge, in orange.
  void write_border_and_seams()
  {
    std::string& s = m_s;
    if(!m_layout.border.empty())
    {
      s += "<polygon fill=\"none\" stroke=\"#000000\" stroke-width=\"" + std::to_string(m_border_width) +
           "\" stroke-linejoin=\"round\" points=\"";
      for(std::size_t k = 0; k < m_layout.border.size(); ++k)
      {
        const auto& p = m_xy[m_layout.border[k]];
        if(k > 0)
          s += ' ';
        s += std::to_string(p[0]) + "," + std::to_string(p[1]);
      }
      s += "\"/>\n";
    }
    if(!m_layout.seams.empty())
    {
      s += "<path fill=\"none\" stroke=\"#e66100\" stroke-width=\"" + std::to_string(2 * m_border_width) +
           "\" stroke-linecap=\"round\" d=\"";
      for(const std::array<std::size_t, 2>& e : m_layout.seams)
      {
        const auto &p = m_xy[e[0]], &q = m_xy[e[1]];
        s += "M" + std::to_string(p[0]) + " " + std::to_string(p[1]) + "L" + std::to_string(q[0]) + " " +
             std::to_string(q[1]);
      }
      s += "\"/>\n";
    }
  }

  // A target at (cx, cy).
  static std::string center_marker(long cx, long cy, double scale)
  {
    const std::string x = std::to_string(cx), y = std::to_string(cy);
    const long r = std::lround(110. * scale), arm = std::lround(190. * scale), sw = std::lround(25. * scale);
    return "<circle cx=\"" + x + "\" cy=\"" + y + "\" r=\"" + std::to_string(r) +
           "\" fill=\"#ffffff\" stroke=\"#000000\" stroke-width=\"" + std::to_string(sw) + "\"/>"
           "<path d=\"M" + std::to_string(cx - arm) + " " + y + "h" + std::to_string(2 * arm) + "M" + x + " " +
           std::to_string(cy - arm) + "v" + std::to_string(2 * arm) + "\" stroke=\"#000000\" stroke-width=\"" +
           std::to_string(sw) + "\"/>";
  }

  // The center: a target, and its label on a white box.
  void write_center()
  {
    if(m_layout.center >= m_xy.size())
      return;
    const auto& c = m_xy[m_layout.center];
    m_s += center_marker(c[0], c[1], m_layout.mark_scale) + "\n";
    if(!m_layout.center_text)
      return;
    // on a translucent white box (width estimated from the number of characters), above
    // right of the marker, or left / below when it would leave the drawing
    const long label_width = long(115 * m_layout.center_label.size()) + 120;
    const long box_x = (c[0] + 180 + label_width <= m_x0 + m_w) ? c[0] + 180 : c[0] - 180 - label_width;
    const long box_y = (c[1] - 340 >= m_y0) ? c[1] - 340 : c[1] + 50;
    m_s += "<rect x=\"" + std::to_string(box_x) + "\" y=\"" + std::to_string(box_y) + "\" width=\"" +
           std::to_string(label_width) + "\" height=\"290\" rx=\"40\" fill=\"#ffffff\" fill-opacity=\"0.8\"/>";
    m_s += "<text x=\"" + std::to_string(box_x + 60) + "\" y=\"" + std::to_string(box_y + 215) +
           "\" font-size=\"210\">" + xml_escaped(m_layout.center_label) + "</text>\n";
  }

  // Legend: the color bar, high values on top, with ticks at the powers of ten inside the
  // range and at both ends.
  void write_color_bar()
  {
    std::string& s = m_s;
    long y = m_y0;
    s += "<text x=\"" + std::to_string(m_legend_x) + "\" y=\"" + std::to_string(y + 200) + "\" font-size=\"210\">" +
         xml_escaped(m_layout.color_title) + "</text>\n";
    s += "<text x=\"" + std::to_string(m_legend_x) + "\" y=\"" + std::to_string(y + 200 + line - 40) +
         "\" font-size=\"170\" fill=\"#444444\">" + xml_escaped(m_layout.color_note) + "</text>\n";
    y += 2 * line + 100;
    const long bar_top = y;
    for(int b = 0; b < bins; ++b)
    {
      const long top = bar_top + bar_height * (bins - 1 - b) / bins, bottom = bar_top + bar_height * (bins - b) / bins;
      s += "<rect x=\"" + std::to_string(m_legend_x) + "\" y=\"" + std::to_string(top) + "\" width=\"" +
           std::to_string(bar_width) + "\" height=\"" + std::to_string(bottom - top + 1) + "\" fill=\"" +
           bin_color(b) + "\"/>";
    }
    s += "\n<rect x=\"" + std::to_string(m_legend_x) + "\" y=\"" + std::to_string(bar_top) + "\" width=\"" +
         std::to_string(bar_width) + "\" height=\"" + std::to_string(bar_height) +
         "\" fill=\"none\" stroke=\"#000000\" stroke-width=\"10\"/>\n";
    if(!m_has_positive)
      tick(bar_top, 0.5, "0 (all faces)");
    else
      write_ticks(bar_top);
  }

  // a tick of the color bar at `t` (0 at the bottom, 1 at the top)
  void tick(long bar_top, double t, const std::string& text)
  {
    const long ty = bar_top + std::lround((1. - t) * bar_height);
    m_s += "<path d=\"M" + std::to_string(m_legend_x + bar_width) + " " + std::to_string(ty) +
           "h80\" stroke=\"#000000\" stroke-width=\"10\"/>";
    m_s += "<text x=\"" + std::to_string(m_legend_x + bar_width + 120) + "\" y=\"" + std::to_string(ty + 70) +
           "\" font-size=\"190\">" + xml_escaped(text) + "</text>\n";
  }

  void write_ticks(long bar_top)
  {
    tick(bar_top, 1., "\xe2\x89\xa5 " + tick_text(m_hi));  // >=
    tick(bar_top, 0., "\xe2\x89\xa4 " + tick_text(m_lo));  // <=
    // powers of ten, and also 2 and 5 times them when the range spans less than two decades
    const double min_gap = 350. / double(bar_height);     // keep labels apart
    const bool fine = m_log_hi - m_log_lo < 2.;
    double last = -1.;
    for(int e = int(std::floor(m_log_lo)); e <= int(std::ceil(m_log_hi)); ++e)
      for(double m : {1., 2., 5.})
      {
        if(m != 1. && !fine)
          continue;
        const double t = (std::log10(m) + e - m_log_lo) / (m_log_hi - m_log_lo);
        if(t > min_gap && t < 1. - min_gap && t > last + min_gap)
        {
          tick(bar_top, t, tick_text(m * std::pow(10., e)));
          last = t;
        }
      }
  }

  void legend_text(long ty, const std::string& text)
  {
    m_s += "<text x=\"" + std::to_string(m_legend_x + 520) + "\" y=\"" + std::to_string(ty + 70) +
           "\" font-size=\"190\">" + xml_escaped(text) + "</text>\n";
  }

  // Legend: the other marks.
  void write_marks()
  {
    if(!m_layout.layout_marks)
    {
      write_atlas_marks();
      return;
    }
    std::string& s = m_s;
    const long legend_x = m_legend_x;
    long y = m_y0 + 2 * line + 100 + bar_height + line + 50;
    s += "<rect x=\"" + std::to_string(legend_x + 60) + "\" y=\"" + std::to_string(y - 100) +
         "\" width=\"280\" height=\"200\" fill=\"#ff1a1a\" stroke=\"#000000\" stroke-width=\"10\"/>"
         "<circle cx=\"" + std::to_string(legend_x + 200) + "\" cy=\"" + std::to_string(y) +
         "\" r=\"170\" fill=\"none\" stroke=\"#ff1a1a\" stroke-width=\"25\"/>\n";
    legend_text(y, "flipped faces: " + std::to_string(m_flipped));
    if(m_flipped > max_markers)
    {
      s += "<text x=\"" + std::to_string(legend_x + 520) + "\" y=\"" + std::to_string(y + 270) +
           "\" font-size=\"170\" fill=\"#444444\">(too many to circle)</text>\n";
      y += 200;
    }
    y += line + 100;
    s += "<path d=\"M" + std::to_string(legend_x) + " " + std::to_string(y) +
         "h400\" stroke=\"#000000\" stroke-width=\"22\"/>\n";
    legend_text(y, "border (" + std::to_string(m_layout.border.size()) + " vertices)");
    if(!m_layout.seams.empty())
    {
      y += line + 100;
      s += "<path d=\"M" + std::to_string(legend_x) + " " + std::to_string(y) +
           "h400\" stroke=\"#e66100\" stroke-width=\"44\" stroke-linecap=\"round\"/>\n";
      legend_text(y, "seams (" + std::to_string(m_layout.seam_edges) + " edges, both sides)");
    }
    y += line + 100;
    s += center_marker(legend_x + 200, y, 1.) + "\n";
    legend_text(y, "center");
  }

  // Legend of an atlas: the frame and the chart outlines.
  void write_atlas_marks()
  {
    long y = m_y0 + 2 * line + 100 + bar_height + line + 50;
    if(m_layout.unit_square)
    {
      m_s += "<rect x=\"" + std::to_string(m_legend_x + 60) + "\" y=\"" + std::to_string(y - 100) +
             "\" width=\"280\" height=\"200\" fill=\"none\" stroke=\"#888888\" stroke-width=\"12\"/>\n";
      legend_text(y, m_layout.frame_label);
      y += line + 100;
    }
    if(!m_layout.outline_label.empty())
    {
      m_s += "<path d=\"M" + std::to_string(m_legend_x) + " " + std::to_string(y) + "h400\" stroke=\"#000000\" stroke-width=\"" +
             std::to_string(outline_width()) + "\"/>\n";
      legend_text(y, m_layout.outline_label);
    }
  }

  const Svg_layout& m_layout;
  std::array<long, 2> m_frame = {0, 0};      // the top left corner of the unit square
  std::vector<std::array<long, 2> > m_xy;    // per UV: its SVG position
  long m_w = 0, m_x0 = 0, m_y0 = 0;          // width and top left corner of the layout
  long m_legend_x = 0, m_width = 0, m_height = 0;
  double m_lo = 0., m_hi = 0., m_log_lo = 0., m_log_hi = 1.;
  bool m_has_positive = false;               // some face has a positive angle distortion
  std::vector<std::string> m_paths;          // per color bin: the path of its faces
  std::string m_flipped_path, m_markers;
  std::size_t m_flipped = 0;
  bool m_wireframe = false;
  long m_border_width = 0;
  std::string m_s;
};

} // namespace detail

/// the SVG document of `layout`.
inline std::string svg_document(const Svg_layout& layout)
{
  return detail::Svg_drawing(layout).document();
}

} // namespace mbp_cli

#endif // MBP_CLI_SVG_LAYOUT_H
