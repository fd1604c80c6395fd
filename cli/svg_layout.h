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
// cut mesh over it (both sides of each), the center marked, and a caption. No CGAL here.
//
// Size: coordinates are integers in units of 1e-4 of the UV square (UV positions rounded to
// 4 decimals), faces of one color share one path element, and each face is written as
// "M x y l dx dy dx dy z": about 25 bytes a face, 2.5 MB for 100k faces.

#ifndef MBP_CLI_SVG_LAYOUT_H
#define MBP_CLI_SVG_LAYOUT_H

#include "text_output.h"

#include <algorithm>
#include <array>
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

} // namespace detail

/// the SVG document of `layout`.
inline std::string svg_document(const Svg_layout& layout)
{
  using detail::append_coordinate;
  using detail::xml_escaped;
  const double unit = 1e4;                // SVG units per UV unit
  const long pad = 300, line = 300;       // 10 SVG units = 1 pixel at the nominal size
  const long legend_width = 3400, bar_width = 400, bar_height = 5000;
  const int bins = 32;
  const std::size_t max_markers = 1000;   // more flipped faces are not circled: the circles would hide the layout

  // Bounding box of the layout.
  double umin = 0., umax = 1., vmin = 0., vmax = 1.;
  if(!layout.uv.empty())
  {
    umin = umax = layout.uv[0][0];
    vmin = vmax = layout.uv[0][1];
    for(const auto& p : layout.uv)
    {
      umin = (std::min)(umin, p[0]); umax = (std::max)(umax, p[0]);
      vmin = (std::min)(vmin, p[1]); vmax = (std::max)(vmax, p[1]);
    }
  }
  const long w = (std::max)(1L, std::lround((umax - umin) * unit));
  const long h = (std::max)(1L, std::lround((vmax - vmin) * unit));
  const bool has_caption = !layout.title.empty() || !layout.caption.empty();
  const long caption_height = has_caption ? pad + line * long(1 + layout.caption.size()) + pad / 2 : pad;
  const long x0 = pad, y0 = caption_height;
  // UV -> SVG, v upwards
  std::vector<std::array<long, 2> > xy(layout.uv.size());
  for(std::size_t i = 0; i < xy.size(); ++i)
    xy[i] = {x0 + std::lround((layout.uv[i][0] - umin) * unit), y0 + std::lround((vmax - layout.uv[i][1]) * unit)};

  const long legend_x = x0 + w + pad;
  const long legend_height = 2 * line + bar_height + 5 * line;
  const long width = layout.legend ? legend_x + legend_width : x0 + w + pad;
  const long height = y0 + (layout.legend ? (std::max)(h, legend_height) : h) + pad;

  // Color scale: log10 of the per-face angle distortion between its 2nd and 98th percentiles
  // over the faces with a positive value (robust to a few extreme faces); values beyond the
  // ends get the end colors.
  std::vector<double> positive;
  for(double a : layout.face_angle_distortion)
    if(a > 0. && std::isfinite(a))
      positive.push_back(a);
  double lo = 0., hi = 0.;
  if(layout.color_lo > 0. && layout.color_hi > layout.color_lo)
  {
    lo = layout.color_lo;
    hi = layout.color_hi;
  }
  else if(!positive.empty())
  {
    std::sort(positive.begin(), positive.end());
    lo = positive[std::size_t(0.02 * double(positive.size() - 1))];
    hi = positive[std::size_t(0.98 * double(positive.size() - 1))];
    if(!(hi > lo))
      hi = lo * 10.;
  }
  const double log_lo = (lo > 0.) ? std::log10(lo) : 0., log_hi = (hi > 0.) ? std::log10(hi) : 1.;
  auto bin_of = [&](double a) {
    if(!(a > lo))
      return 0;
    if(!std::isfinite(a) || a >= hi)
      return bins - 1;
    const double t = (std::log10(a) - log_lo) / (log_hi - log_lo);
    return std::clamp(int(t * bins), 0, bins - 1);
  };
  auto bin_color = [&](int b) { return detail::viridis((b + 0.5) / bins); };

  // Faces per bin, flipped faces apart.
  std::vector<std::string> paths(static_cast<std::size_t>(bins));
  std::string flipped_path, markers;
  std::size_t flipped = 0;
  double edge_sum = 0.;
  for(std::size_t f = 0; f < layout.faces.size(); ++f)
  {
    const auto& t = layout.faces[f];
    const auto &a = xy[t[0]], &b = xy[t[1]], &c = xy[t[2]];
    const bool is_flipped = layout.face_flipped[f];
    std::string& d = is_flipped ? flipped_path : paths[std::size_t(bin_of(layout.face_angle_distortion[f]))];
    d += 'M';
    append_coordinate(d, a[0]); append_coordinate(d, a[1]);
    d += 'l';
    append_coordinate(d, b[0] - a[0]); append_coordinate(d, b[1] - a[1]);
    append_coordinate(d, c[0] - b[0]); append_coordinate(d, c[1] - b[1]);
    d += 'z';
    edge_sum += std::hypot(double(b[0] - a[0]), double(b[1] - a[1]));
    if(is_flipped && ++flipped <= max_markers)
      markers += "<circle cx=\"" + std::to_string((a[0] + b[0] + c[0]) / 3) + "\" cy=\"" +
                 std::to_string((a[1] + b[1] + c[1]) / 3) + "\" r=\"120\"/>";
  }
  // Draw the mesh edges when they are at least 6 pixels long on average; otherwise stroke
  // each face with its own color to hide the hairline seams of anti-aliasing.
  const bool wireframe = (layout.wireframe >= 0) ? layout.wireframe > 0
                                                 : !layout.faces.empty() && edge_sum / double(layout.faces.size()) >= 60.;
  const long border_width = std::lround(22. * layout.mark_scale);

  std::string s;
  s.reserve(64 * layout.faces.size() + 8192);
  s += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  s += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(width / 10) + "\" height=\"" +
       std::to_string(height / 10) + "\" viewBox=\"0 0 " + std::to_string(width) + " " + std::to_string(height) +
       "\" font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\">\n";
  s += "<title>" + xml_escaped(layout.title) + ": UV layout</title>\n";
  s += "<rect width=\"" + std::to_string(width) + "\" height=\"" + std::to_string(height) + "\" fill=\"#ffffff\"/>\n";

  // Caption.
  s += "<text x=\"" + std::to_string(pad) + "\" y=\"" + std::to_string(pad + line - 60) +
       "\" font-size=\"260\" font-weight=\"bold\">" + xml_escaped(layout.title) + "</text>\n";
  for(std::size_t i = 0; i < layout.caption.size(); ++i)
    s += "<text x=\"" + std::to_string(pad) + "\" y=\"" + std::to_string(pad + line * long(i + 2) - 60) +
         "\" font-size=\"210\">" + xml_escaped(layout.caption[i]) + "</text>\n";

  // Faces.
  s += "<g stroke-linejoin=\"round\"";
  s += wireframe ? " stroke=\"#000000\" stroke-opacity=\"0.25\" stroke-width=\"5\">\n" : " stroke-width=\"6\">\n";
  for(int b = 0; b < bins; ++b)
    if(!paths[std::size_t(b)].empty())
    {
      s += "<path fill=\"" + bin_color(b) + "\"";
      if(!wireframe)
        s += " stroke=\"" + bin_color(b) + "\"";
      s += " d=\"" + paths[std::size_t(b)] + "\"/>\n";
    }
  s += "</g>\n";
  if(!flipped_path.empty())
  {
    s += "<path fill=\"#ff1a1a\" stroke=\"#000000\" stroke-width=\"10\" stroke-linejoin=\"round\" d=\"" +
         flipped_path + "\"/>\n";
  }

  // Border: a closed polyline.
  if(!layout.border.empty())
  {
    s += "<polygon fill=\"none\" stroke=\"#000000\" stroke-width=\"" + std::to_string(border_width) + "\" stroke-linejoin=\"round\" points=\"";
    for(std::size_t k = 0; k < layout.border.size(); ++k)
    {
      const auto& p = xy[layout.border[k]];
      if(k > 0)
        s += ' ';
      s += std::to_string(p[0]) + "," + std::to_string(p[1]);
    }
    s += "\"/>\n";
  }

  // Seams: on the border, both sides of every seam edge, in orange.
  if(!layout.seams.empty())
  {
    s += "<path fill=\"none\" stroke=\"#e66100\" stroke-width=\"" + std::to_string(2 * border_width) +
         "\" stroke-linecap=\"round\" d=\"";
    for(const std::array<std::size_t, 2>& e : layout.seams)
    {
      const auto &p = xy[e[0]], &q = xy[e[1]];
      s += "M" + std::to_string(p[0]) + " " + std::to_string(p[1]) + "L" + std::to_string(q[0]) + " " +
           std::to_string(q[1]);
    }
    s += "\"/>\n";
  }

  // Circles around the flipped faces (which may be too small to see), unless there are too
  // many of them.
  if(flipped <= max_markers && !markers.empty())
    s += "<g fill=\"none\" stroke=\"#ff1a1a\" stroke-width=\"25\">" + markers + "</g>\n";

  // Center: a target, and its label on a white box.
  auto center_marker = [](long cx, long cy, double scale) {
    const std::string x = std::to_string(cx), y = std::to_string(cy);
    const long r = std::lround(110. * scale), arm = std::lround(190. * scale), sw = std::lround(25. * scale);
    return "<circle cx=\"" + x + "\" cy=\"" + y + "\" r=\"" + std::to_string(r) +
           "\" fill=\"#ffffff\" stroke=\"#000000\" stroke-width=\"" + std::to_string(sw) + "\"/>"
           "<path d=\"M" + std::to_string(cx - arm) + " " + y + "h" + std::to_string(2 * arm) + "M" + x + " " +
           std::to_string(cy - arm) + "v" + std::to_string(2 * arm) + "\" stroke=\"#000000\" stroke-width=\"" +
           std::to_string(sw) + "\"/>";
  };
  if(layout.center < xy.size())
  {
    const auto& c = xy[layout.center];
    s += center_marker(c[0], c[1], layout.mark_scale) + "\n";
  }
  if(layout.center < xy.size() && layout.center_text)
  {
    const auto& c = xy[layout.center];
    // on a translucent white box (width estimated from the number of characters), above
    // right of the marker, or left / below when it would leave the drawing
    const long label_width = long(115 * layout.center_label.size()) + 120;
    const long box_x = (c[0] + 180 + label_width <= x0 + w) ? c[0] + 180 : c[0] - 180 - label_width;
    const long box_y = (c[1] - 340 >= y0) ? c[1] - 340 : c[1] + 50;
    s += "<rect x=\"" + std::to_string(box_x) + "\" y=\"" + std::to_string(box_y) + "\" width=\"" +
         std::to_string(label_width) + "\" height=\"290\" rx=\"40\" fill=\"#ffffff\" fill-opacity=\"0.8\"/>";
    s += "<text x=\"" + std::to_string(box_x + 60) + "\" y=\"" + std::to_string(box_y + 215) +
         "\" font-size=\"210\">" + xml_escaped(layout.center_label) + "</text>\n";
  }

  if(!layout.legend)
  {
    s += "</svg>\n";
    return s;
  }

  // Legend: the color bar, high values on top, with ticks at the powers of ten inside the
  // range and at both ends.
  long y = y0;
  s += "<text x=\"" + std::to_string(legend_x) + "\" y=\"" + std::to_string(y + 200) +
       "\" font-size=\"210\">angle distortion per face</text>\n";
  s += "<text x=\"" + std::to_string(legend_x) + "\" y=\"" + std::to_string(y + 200 + line - 40) +
       "\" font-size=\"170\" fill=\"#444444\">(mean of its 3 corners, log scale)</text>\n";
  y += 2 * line + 100;
  const long bar_top = y;
  for(int b = 0; b < bins; ++b)
  {
    const long top = bar_top + bar_height * (bins - 1 - b) / bins, bottom = bar_top + bar_height * (bins - b) / bins;
    s += "<rect x=\"" + std::to_string(legend_x) + "\" y=\"" + std::to_string(top) + "\" width=\"" +
         std::to_string(bar_width) + "\" height=\"" + std::to_string(bottom - top + 1) + "\" fill=\"" + bin_color(b) + "\"/>";
  }
  s += "\n<rect x=\"" + std::to_string(legend_x) + "\" y=\"" + std::to_string(bar_top) + "\" width=\"" +
       std::to_string(bar_width) + "\" height=\"" + std::to_string(bar_height) +
       "\" fill=\"none\" stroke=\"#000000\" stroke-width=\"10\"/>\n";
  auto tick = [&](double t, const std::string& text) {
    const long ty = bar_top + std::lround((1. - t) * bar_height);
    s += "<path d=\"M" + std::to_string(legend_x + bar_width) + " " + std::to_string(ty) + "h80\" stroke=\"#000000\" stroke-width=\"10\"/>";
    s += "<text x=\"" + std::to_string(legend_x + bar_width + 120) + "\" y=\"" + std::to_string(ty + 70) +
         "\" font-size=\"190\">" + xml_escaped(text) + "</text>\n";
  };
  if(positive.empty())
    tick(0.5, "0 (all faces)");
  else
  {
    tick(1., "\xe2\x89\xa5 " + detail::tick_text(hi));  // >=
    tick(0., "\xe2\x89\xa4 " + detail::tick_text(lo));  // <=
    // powers of ten, and also 2 and 5 times them when the range spans less than two decades
    const double min_gap = 350. / double(bar_height);     // keep labels apart
    const bool fine = log_hi - log_lo < 2.;
    double last = -1.;
    for(int e = int(std::floor(log_lo)); e <= int(std::ceil(log_hi)); ++e)
      for(double m : {1., 2., 5.})
      {
        if(m != 1. && !fine)
          continue;
        const double t = (std::log10(m) + e - log_lo) / (log_hi - log_lo);
        if(t > min_gap && t < 1. - min_gap && t > last + min_gap)
        {
          tick(t, detail::tick_text(m * std::pow(10., e)));
          last = t;
        }
      }
  }
  y = bar_top + bar_height + line + 50;

  // Legend: the other marks.
  auto legend_text = [&](long ty, const std::string& text) {
    s += "<text x=\"" + std::to_string(legend_x + 520) + "\" y=\"" + std::to_string(ty + 70) +
         "\" font-size=\"190\">" + xml_escaped(text) + "</text>\n";
  };
  s += "<rect x=\"" + std::to_string(legend_x + 60) + "\" y=\"" + std::to_string(y - 100) +
       "\" width=\"280\" height=\"200\" fill=\"#ff1a1a\" stroke=\"#000000\" stroke-width=\"10\"/>"
       "<circle cx=\"" + std::to_string(legend_x + 200) + "\" cy=\"" + std::to_string(y) +
       "\" r=\"170\" fill=\"none\" stroke=\"#ff1a1a\" stroke-width=\"25\"/>\n";
  legend_text(y, "flipped faces: " + std::to_string(flipped));
  if(flipped > max_markers)
  {
    s += "<text x=\"" + std::to_string(legend_x + 520) + "\" y=\"" + std::to_string(y + 270) +
         "\" font-size=\"170\" fill=\"#444444\">(too many to circle)</text>\n";
    y += 200;
  }
  y += line + 100;
  s += "<path d=\"M" + std::to_string(legend_x) + " " + std::to_string(y) + "h400\" stroke=\"#000000\" stroke-width=\"22\"/>\n";
  legend_text(y, "border (" + std::to_string(layout.border.size()) + " vertices)");
  if(!layout.seams.empty())
  {
    y += line + 100;
    s += "<path d=\"M" + std::to_string(legend_x) + " " + std::to_string(y) +
         "h400\" stroke=\"#e66100\" stroke-width=\"44\" stroke-linecap=\"round\"/>\n";
    legend_text(y, "seams (" + std::to_string(layout.seam_edges) + " edges, both sides)");
  }
  y += line + 100;
  s += center_marker(legend_x + 200, y, 1.) + "\n";
  legend_text(y, "center");

  s += "</svg>\n";
  return s;
}

} // namespace mbp_cli

#endif // MBP_CLI_SVG_LAYOUT_H
