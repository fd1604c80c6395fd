// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// The documentation figures of the measured boundary parameterization package, generated
// from the project's meshes:
//
//   make_figures MESH_DIR FIG_DIR WORK_DIR [--zoom=Z]
//
// writes into WORK_DIR one SVG per composite figure (3D views rendered by raster.h and
// embedded as PNG, UV layouts drawn as vectors by cli/svg_layout.h); the script
// scripts/make_figures.sh turns each into FIG_DIR/NAME.png with rsvg-convert (at zoom Z, the
// resolution the 3D views are rendered for). FIG_DIR receives the vector UV layouts (SVG) and
// figures.md, which lists every figure with what it shows and its distortion figures.
//
// Figures: the paper's Fig. 1 (distance maps, domains and texture: measured method vs CGAL's
// discrete conformal map with a circle border), Fig. 4 (effect of the center), Fig. 9
// (domains of the Poisson, geodesic, automatic and free-boundary LSCM methods), the distance
// maps, and the README's picture.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/Circular_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_conformal_map_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/Eigen_sparse_matrix.h>

#include <CGAL/Surface_mesh_parameterization/Automatic_border.h>
#include <CGAL/Surface_mesh_parameterization/Conformal_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Fixed_center.h>
#include <CGAL/Surface_mesh_parameterization/Geodesic_border_distance.h>
#include <CGAL/Surface_mesh_parameterization/Geodesic_center_locator.h>
#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_report.h>
#include <CGAL/Surface_mesh_parameterization/Poisson_border_distance.h>
#include <CGAL/Surface_mesh_parameterization/Poisson_center_locator.h>
#include <CGAL/Surface_mesh_parameterization/geodesic_distance_map.h>
#include <CGAL/Surface_mesh_parameterization/geodesic_method_tags.h>
#include <CGAL/Surface_mesh_parameterization/measure_quality.h>
#include <CGAL/Surface_mesh_parameterization/poisson_distance_map.h>

#include <Eigen/SparseLU>

#include "../../cli/svg_layout.h"
#include "raster.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

typedef CGAL::Simple_cartesian<double>                      Kernel;
typedef Kernel::Point_2                                     Point_2;
typedef Kernel::Point_3                                     Point_3;
typedef CGAL::Surface_mesh<Point_3>                         Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor        vertex_descriptor;
typedef boost::graph_traits<Mesh>::halfedge_descriptor      halfedge_descriptor;
typedef boost::graph_traits<Mesh>::face_descriptor          face_descriptor;

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace fs = std::filesystem;
using mbp_fig::Vec2;
using mbp_fig::Vec3;

typedef CGAL::Eigen_solver_traits<Eigen::SparseLU<CGAL::Eigen_sparse_matrix<double>::EigenType> > LU;
typedef SMP::Measured_conformal_parameterizer_3<Mesh>                                    MBPPP;
typedef SMP::Measured_conformal_parameterizer_3<Mesh, SMP::Poisson_center_locator,
                                                SMP::Geodesic_border_distance<> >         MBPGP;
typedef SMP::Measured_conformal_parameterizer_3<Mesh, SMP::Geodesic_center_locator<>,
                                                SMP::Poisson_border_distance>             BGDM_PP;
typedef SMP::Measured_conformal_parameterizer_3<Mesh, SMP::Fixed_center<Mesh>,
                                                SMP::Poisson_border_distance>             Fixed_PP;
typedef SMP::Measured_conformal_parameterizer_3<Mesh, SMP::Fixed_center<Mesh>,
                                                SMP::Geodesic_border_distance<> >         Fixed_GP;
// the automatic border with the paper's default policies (Poisson) for its measured member
typedef SMP::Conformal_parameterizer_3<Mesh, SMP::Automatic_border<> >                   Automatic_P;
typedef SMP::Discrete_conformal_map_parameterizer_3<
  Mesh, SMP::Circular_border_arc_length_parameterizer_3<Mesh>, LU>                       DCP_circle;
typedef SMP::LSCM_parameterizer_3<Mesh>                                                  LSCM;

const std::size_t none = std::size_t(-1);

// ------------------------------------------------------------------------------- text

std::string fixed(double x, int decimals = 4)
{
  char b[64];
  std::snprintf(b, sizeof(b), "%.*f", decimals, x);
  return b;
}

std::string esc(const std::string& s) { return mbp_cli::detail::xml_escaped(s); }

// The value of a color bar's tick, short: 0.001, 0.25, 3e-05.
std::string tick_text(double x)
{
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.2g", x);
  return buffer;
}

// The color of raster.h's viridis map at t in [0, 1], as an SVG color.
std::string viridis_color(double t)
{
  const Vec3 c = mbp_fig::viridis(t);
  char hex[8];
  std::snprintf(hex, sizeof(hex), "#%02x%02x%02x", unsigned(std::lround(c[0] * 255.)),
                unsigned(std::lround(c[1] * 255.)), unsigned(std::lround(c[2] * 255.)));
  return hex;
}

// ------------------------------------------------------------------------------- meshes

struct Input
{
  std::string file, title;
  Mesh mesh;
  halfedge_descriptor bhd;
  mbp_fig::Tri_mesh tri;
  mbp_fig::Camera camera;
  std::vector<std::size_t> border;  // vertex indices along the border loop
};

// How a mesh is looked at: the direction toward the viewer is the area-weighted mean normal
// (the side the open surface faces), times `flip`; `up` is projected to the vertical.
struct View
{
  Vec3 up{0., 1., 0.};
  double flip = 1.;
  Vec3 tilt{0., 0., 0.};  // added to the unit view direction
};

bool load(const std::string& dir, const std::string& file, const std::string& title, const View& view, Input& in)
{
  in.file = file;
  in.title = title;
  const std::string path = dir + "/" + file;
  if(!CGAL::IO::read_polygon_mesh(path, in.mesh) || faces(in.mesh).empty() || !CGAL::is_triangle_mesh(in.mesh))
  {
    std::cerr << "error: cannot read a triangle mesh from '" << path << "'\n";
    return false;
  }
  in.bhd = CGAL::Polygon_mesh_processing::longest_border(in.mesh).first;
  if(in.bhd == boost::graph_traits<Mesh>::null_halfedge())
  {
    std::cerr << "error: '" << path << "' has no border\n";
    return false;
  }
  for(vertex_descriptor v : vertices(in.mesh))
  {
    const Point_3& p = in.mesh.point(v);
    in.tri.points.push_back({p.x(), p.y(), p.z()});
  }
  Vec3 normal{0., 0., 0.};
  for(face_descriptor f : faces(in.mesh))
  {
    std::array<std::size_t, 3> t;
    int k = 0;
    for(vertex_descriptor v : vertices_around_face(halfedge(f, in.mesh), in.mesh))
      t[std::size_t(k++)] = std::size_t(v.idx());
    in.tri.faces.push_back(t);
    const Vec3& a = in.tri.points[t[0]];
    normal = mbp_fig::add(normal, mbp_fig::cross(mbp_fig::sub(in.tri.points[t[1]], a), mbp_fig::sub(in.tri.points[t[2]], a)));
  }
  in.camera.toward_viewer = mbp_fig::add(mbp_fig::mul(mbp_fig::normalized(normal), view.flip), view.tilt);
  in.camera.up = view.up;
  for(halfedge_descriptor h : halfedges_around_face(in.bhd, in.mesh))
    in.border.push_back(std::size_t(source(h, in.mesh).idx()));
  return true;
}

// ------------------------------------------------------------------------------- parameterizations

struct Result
{
  std::string method;                 // short name
  bool ok = false;
  std::vector<Vec2> uv;               // per vertex index, normalized (see normalize_uv)
  SMP::Parameterization_quality quality;
  std::vector<SMP::Face_quality> face_quality;
  std::size_t center = none;          // vertex index
  std::string note;                   // repair, chosen border...
};

typedef Mesh::Property_map<vertex_descriptor, Point_2> UV_map;

// The UVs and the per-face quality of `parameterize(uvmap)`.
template <class Parameterize>
Result run(Input& in, const std::string& method, Parameterize parameterize)
{
  Result r;
  r.method = method;
  UV_map uvmap = in.mesh.add_property_map<vertex_descriptor, Point_2>("v:figure_uv", Point_2(0., 0.)).first;
  const SMP::Error_code status = parameterize(uvmap);
  if(status != SMP::OK)
  {
    std::cerr << "warning: " << method << " failed on " << in.file << ": " << SMP::get_measured_error_message(status)
              << "\n";
    in.mesh.remove_property_map(uvmap);
    return r;
  }
  auto fq = in.mesh.add_property_map<face_descriptor, SMP::Face_quality>("f:figure_quality").first;
  r.quality = SMP::measure_quality_per_face(in.mesh, faces(in.mesh), uvmap, fq);
  for(vertex_descriptor v : vertices(in.mesh))
    r.uv.push_back({uvmap[v].x(), uvmap[v].y()});
  for(face_descriptor f : faces(in.mesh))
    r.face_quality.push_back(fq[f]);
  in.mesh.remove_property_map(fq);
  in.mesh.remove_property_map(uvmap);
  r.ok = true;
  return r;
}

// A parameterizer of CGAL.
template <class Parameterizer>
Result run_method(Input& in, const Parameterizer& parameterizer, const std::string& method)
{
  Parameterizer p = parameterizer;
  return run(in, method, [&](UV_map uvmap) { return SMP::parameterize(in.mesh, p, in.bhd, uvmap); });
}

template <class BorderPolicy>
struct Is_automatic : std::false_type { };
template <class CenterLocator, class BorderDistance>
struct Is_automatic<SMP::Automatic_border<CenterLocator, BorderDistance> > : std::true_type { };

// A parameterizer of this package, with its report: the center, the repair, the border kept.
template <class Ours>
Result measured(Input& in, const Ours& parameterizer, const std::string& method)
{
  SMP::Parameterization_report report;
  Result r = run(in, method, [&](UV_map uvmap) { return SMP::parameterize(in.mesh, parameterizer, in.bhd, uvmap, &report); });
  if(!r.ok)
    return r;
  // the center's position in vertices(mesh): its index (the meshes have no removed vertex)
  r.center = report.has_center ? report.center : none;
  if(Is_automatic<typename Ours::Border_policy>::value && report.chosen_candidate >= 0)
  {
    const SMP::Border_candidate& c = report.border_candidates[std::size_t(report.chosen_candidate)];
    const char* family = (c.family == SMP::CIRCLE) ? "circle"
                         : (c.family == SMP::MEASURED) ? "measured border"
                                                       : "conformal border";
    r.note = (c.family == SMP::CIRCLE) ? std::string("kept: circle")
                                       : std::string("kept: ") + family +
                                           (c.blend > 0. ? ", blend " + fixed(c.blend, 2) : std::string());
  }
  else if(report.repaired)
    r.note = std::string("repaired: blend ") + fixed(report.blend, 2) +
             (report.mean_value_interior ? ", mean value" : "");
  return r;
}

// Rotates the UVs (no mirror: that would flip faces) to match the 3D view best (least
// squares), then scales them so that the UV area equals 1 and translates the bounding box
// to the origin: every layout of a mesh is then seen as the surface is, at the same scale.
void normalize_uv(const Input& in, Result& r)
{
  const std::size_t n = r.uv.size();
  std::vector<Vec2> s(n);
  Vec2 cs{0., 0.}, cq{0., 0.};
  for(std::size_t i = 0; i < n; ++i)
  {
    s[i] = in.camera.project(in.tri.points[i]);
    cs = {cs[0] + s[i][0] / double(n), cs[1] + s[i][1] / double(n)};
    cq = {cq[0] + r.uv[i][0] / double(n), cq[1] + r.uv[i][1] / double(n)};
  }
  double sd = 0., sc = 0.;
  for(std::size_t i = 0; i < n; ++i)
  {
    const double qx = r.uv[i][0] - cq[0], qy = r.uv[i][1] - cq[1];
    const double px = s[i][0] - cs[0], py = s[i][1] - cs[1];
    sd += qx * px + qy * py;
    sc += qx * py - qy * px;
  }
  const double angle = std::atan2(sc, sd), c = std::cos(angle), si = std::sin(angle);
  for(Vec2& q : r.uv)
    q = {c * (q[0] - cq[0]) - si * (q[1] - cq[1]), si * (q[0] - cq[0]) + c * (q[1] - cq[1])};
  double area = 0.;
  for(const auto& t : in.tri.faces)
  {
    const Vec2 &a = r.uv[t[0]], &b = r.uv[t[1]], &d = r.uv[t[2]];
    area += 0.5 * std::abs((b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]));
  }
  const double scale = (area > 0.) ? 1. / std::sqrt(area) : 1.;
  double umin = std::numeric_limits<double>::max(), vmin = umin;
  for(Vec2& q : r.uv)
  {
    q = {q[0] * scale, q[1] * scale};
    umin = (std::min)(umin, q[0]);
    vmin = (std::min)(vmin, q[1]);
  }
  for(Vec2& q : r.uv)
    q = {q[0] - umin, q[1] - vmin};
}

// ------------------------------------------------------------------------------- pictures

// The UV layout of `r` as an SVG document (svg_layout.h) without caption or legend, colors
// over [lo, hi].
std::string layout_svg(const Input& in, const Result& r, double lo, double hi, bool legend = false,
                       const std::string& title = std::string(), const std::vector<std::string>& caption = {})
{
  mbp_cli::Svg_layout l;
  l.uv = r.uv;
  l.faces = in.tri.faces;
  for(const SMP::Face_quality& fq : r.face_quality)
  {
    l.face_angle_distortion.push_back(fq.angle_distortion);
    l.face_flipped.push_back(!(fq.uv_area > 0.));
  }
  l.border = in.border;
  l.center = (r.center == none) ? l.uv.size() : r.center;
  l.center_label = "center";
  l.center_text = legend;
  l.title = title;
  l.caption = caption;
  l.color_lo = lo;
  l.color_hi = hi;
  l.legend = legend;
  if(!legend)  // a small panel of a composite figure
  {
    l.wireframe = 0;
    l.mark_scale = 2.5;
  }
  return mbp_cli::svg_document(l);
}

// 2nd and 98th percentiles of the positive per-face angle distortions of `results`.
std::pair<double, double> distortion_range(const std::vector<const Result*>& results)
{
  std::vector<double> a;
  for(const Result* r : results)
    for(const SMP::Face_quality& fq : r->face_quality)
      if(fq.angle_distortion > 0. && std::isfinite(fq.angle_distortion))
        a.push_back(fq.angle_distortion);
  if(a.empty())
    return {1e-4, 1.};
  std::sort(a.begin(), a.end());
  return {a[std::size_t(0.02 * double(a.size() - 1))], a[std::size_t(0.98 * double(a.size() - 1))]};
}

// A composite figure in pixels: text, raster images, nested SVG documents, color bars.
class Composite
{
public:
  Composite(double width, double height, double zoom) : m_width(width), m_height(height), m_zoom(zoom) { }

  void text(double x, double y, const std::string& t, double size = 14., bool bold = false,
            const char* anchor = "start", const char* color = "#000000")
  {
    m_body += "<text x=\"" + fixed(x, 1) + "\" y=\"" + fixed(y, 1) + "\" font-size=\"" + fixed(size, 1) + "\"" +
              (bold ? " font-weight=\"bold\"" : "") + " text-anchor=\"" + anchor + "\" fill=\"" + color + "\">" +
              esc(t) + "</text>\n";
  }

  // A 3D view rendered at `zoom` times the display size (w, h).
  mbp_fig::Viewport view(double x, double y, double w, double h, const Input& in, const mbp_fig::Surface_style& style)
  {
    mbp_fig::Viewport vp;
    const mbp_fig::Image image =
      mbp_fig::render(in.tri, in.camera, style, int(std::lround(w * m_zoom)), int(std::lround(h * m_zoom)), vp);
    m_body += "<image x=\"" + fixed(x, 1) + "\" y=\"" + fixed(y, 1) + "\" width=\"" + fixed(w, 1) + "\" height=\"" +
              fixed(h, 1) + "\" preserveAspectRatio=\"none\" xlink:href=\"data:image/png;base64," +
              mbp_fig::base64(mbp_fig::png_file(image)) + "\"/>\n";
    m_view_x = x;
    m_view_y = y;
    m_view_zoom = m_zoom;
    return vp;
  }

  // The center marker of svg_layout.h at the vertex `v` of the last view.
  void center(const Input& in, const mbp_fig::Viewport& vp, std::size_t v)
  {
    if(v == none)
      return;
    const Vec2 p = vp.pixel(in.camera.project(in.tri.points[v]));
    marker(m_view_x + p[0] / m_view_zoom, m_view_y + p[1] / m_view_zoom);
  }

  void marker(double cx, double cy, double r = 5.5)
  {
    const std::string x = fixed(cx, 1), y = fixed(cy, 1);
    m_body += "<circle cx=\"" + x + "\" cy=\"" + y + "\" r=\"" + fixed(r, 1) +
              "\" fill=\"#ffffff\" stroke=\"#000000\" stroke-width=\"1.4\"/><path d=\"M" + fixed(cx - 1.8 * r, 1) + " " +
              y + "h" + fixed(3.6 * r, 1) + "M" + x + " " + fixed(cy - 1.8 * r, 1) + "v" + fixed(3.6 * r, 1) +
              "\" stroke=\"#000000\" stroke-width=\"1.4\"/>\n";
  }

  // An SVG document (svg_layout.h) fitted into the box (aspect ratio kept, centered).
  void nested(double x, double y, double w, double h, const std::string& document)
  {
    std::size_t start = document.find("<svg");
    std::size_t end = document.find('>', start);
    std::string tag = document.substr(start, end - start);
    const std::size_t vb = tag.find("viewBox=");
    const std::size_t vb_end = tag.find('"', vb + 9);
    const std::string viewbox = tag.substr(vb, vb_end + 1 - vb);
    const std::size_t ff = tag.find("font-family=");
    const std::string font = (ff == std::string::npos) ? std::string() : tag.substr(ff);
    m_body += "<svg x=\"" + fixed(x, 1) + "\" y=\"" + fixed(y, 1) + "\" width=\"" + fixed(w, 1) + "\" height=\"" +
              fixed(h, 1) + "\" " + viewbox + " " + font + ">";
    std::string inner = document.substr(end + 1);
    const std::size_t title = inner.find("<title>");
    if(title != std::string::npos)
      inner.erase(title, inner.find("</title>") + 8 - title);
    m_body += inner + "\n";
  }

  // The angle distortion color bar of svg_layout.h (32 bins of viridis, log scale), high
  // values on top.
  void distortion_bar(double x, double y, double h, double lo, double hi, const std::string& title)
  {
    const int bins = 32;
    const double w = 16.;
    text(x, y - 8., title, 12.);
    for(int b = 0; b < bins; ++b)
    {
      const double top = y + h * (bins - 1 - b) / bins;
      m_body += "<rect x=\"" + fixed(x, 1) + "\" y=\"" + fixed(top, 2) + "\" width=\"" + fixed(w, 1) + "\" height=\"" +
                fixed(h / bins + 0.3, 2) + "\" fill=\"" + viridis_color((b + 0.5) / bins) + "\"/>";
    }
    m_body += "<rect x=\"" + fixed(x, 1) + "\" y=\"" + fixed(y, 1) + "\" width=\"" + fixed(w, 1) + "\" height=\"" +
              fixed(h, 1) + "\" fill=\"none\" stroke=\"#000000\" stroke-width=\"0.8\"/>\n";
    const double llo = std::log10(lo), lhi = std::log10(hi);
    auto tick = [&](double t, const std::string& label) {
      const double ty = y + (1. - t) * h;
      m_body += "<path d=\"M" + fixed(x + w, 1) + " " + fixed(ty, 1) + "h5\" stroke=\"#000000\" stroke-width=\"0.8\"/>";
      text(x + w + 8., ty + 4., label, 11.);
    };
    tick(1., "\xe2\x89\xa5 " + tick_text(hi));
    tick(0., "\xe2\x89\xa4 " + tick_text(lo));
    const double gap = 14. / h;
    double last = -1.;
    const bool fine = lhi - llo < 2.;
    for(int e = int(std::floor(llo)); e <= int(std::ceil(lhi)); ++e)
      for(double m : {1., 2., 5.})
      {
        if(m != 1. && !fine)
          continue;
        const double t = (std::log10(m) + e - llo) / (lhi - llo);
        if(t > gap && t < 1. - gap && t > last + gap)
        {
          tick(t, tick_text(m * std::pow(10., e)));
          last = t;
        }
      }
  }

  // A linear viridis color bar from 0 to `max`, with iso-line ticks every `step`.
  void scalar_bar(double x, double y, double h, double max, double step, const std::string& title)
  {
    const int bins = 64;
    const double w = 12.;
    text(x + w / 2, y - 8., title, 11., false, "middle");
    for(int b = 0; b < bins; ++b)
    {
      const Vec3 c = mbp_fig::viridis((b + 0.5) / bins);
      char hex[8];
      std::snprintf(hex, sizeof(hex), "#%02x%02x%02x", unsigned(std::lround(c[0] * 255)),
                    unsigned(std::lround(c[1] * 255)), unsigned(std::lround(c[2] * 255)));
      const double top = y + h * (bins - 1 - b) / bins;
      m_body += "<rect x=\"" + fixed(x, 1) + "\" y=\"" + fixed(top, 2) + "\" width=\"" + fixed(w, 1) +
                "\" height=\"" + fixed(h / bins + 0.3, 2) + "\" fill=\"" + hex + "\"/>";
    }
    m_body += "<rect x=\"" + fixed(x, 1) + "\" y=\"" + fixed(y, 1) + "\" width=\"" + fixed(w, 1) + "\" height=\"" +
              fixed(h, 1) + "\" fill=\"none\" stroke=\"#000000\" stroke-width=\"0.8\"/>\n";
    // as many decimals as the step needs (2.5 -> 1), no exponent
    const int decimals = (std::max)(0, -int(std::floor(std::log10(step) + 1e-9)) +
                                         (std::abs(step / std::pow(10., std::floor(std::log10(step) + 1e-9)) - 2.5) < 1e-9 ? 1 : 0));
    auto label = [&](double v) { return fixed(v, decimals); };
    int n = int(std::floor(max / step + 1e-9));
    const int every = (n > 8) ? 2 : 1;
    for(int k = 0; k <= n; ++k)
    {
      const double ty = y + (1. - k * step / max) * h;
      m_body += "<path d=\"M" + fixed(x + w, 1) + " " + fixed(ty, 1) + "h4\" stroke=\"#000000\" stroke-width=\"0.8\"/>";
      if(k % every == 0 && (max - k * step) / max > 0.06)
        text(x + w + 6., ty + 4., label(k * step), 10.);
    }
    text(x + w + 6., y + 4., label(max), 10.);
  }

  void raw(const std::string& s) { m_body += s; }

  std::string document() const
  {
    return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" "
           "xmlns:xlink=\"http://www.w3.org/1999/xlink\" width=\"" +
           fixed(m_width, 0) + "\" height=\"" + fixed(m_height, 0) + "\" viewBox=\"0 0 " + fixed(m_width, 0) + " " +
           fixed(m_height, 0) + "\" font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\">\n<rect width=\"" +
           fixed(m_width, 0) + "\" height=\"" + fixed(m_height, 0) + "\" fill=\"#ffffff\"/>\n" + m_body + "</svg>\n";
  }

private:
  double m_width, m_height, m_zoom;
  double m_view_x = 0., m_view_y = 0., m_view_zoom = 1.;
  std::string m_body;
};

mbp_fig::Surface_style checkerboard(const Result& r)
{
  mbp_fig::Surface_style s;
  s.mode = mbp_fig::Surface_style::CHECKERBOARD;
  s.uv = r.uv;
  s.checker_size = 1. / 14.;  // UV area 1: about 14 x 14 cells
  return s;
}

// A "nice" step giving about `n` iso-lines below `max`.
double iso_step(double max, int n = 10)
{
  const double raw = max / n, p = std::pow(10., std::floor(std::log10(raw)));
  for(double m : {1., 2., 2.5, 5., 10.})
    if(m * p >= raw)
      return m * p;
  return 10. * p;
}

mbp_fig::Surface_style scalar_style(const std::vector<double>& values, double& max, double& step)
{
  mbp_fig::Surface_style s;
  s.mode = mbp_fig::Surface_style::SCALAR;
  s.scalar = values;
  max = 0.;
  for(double v : values)
    max = (std::max)(max, v);
  step = iso_step(max);
  s.scalar_min = 0.;
  s.scalar_max = max;
  s.iso_step = step;
  return s;
}

bool write_file(const fs::path& path, const std::string& text)
{
  std::ofstream out(path, std::ios::binary);
  out << text;
  out.close();
  if(!out)
  {
    std::cerr << "error: cannot write '" << path.string() << "'\n";
    return false;
  }
  std::cout << "wrote " << path.string() << " (" << text.size() / 1024 << " KiB)\n";
  return true;
}

std::string numbers(const Result& r)
{
  if(!r.ok)
    return "failed";
  std::string s = "angle distortion " + fixed(r.quality.angle_distortion) + ", L2 " + fixed(r.quality.l2_stretch);
  if(r.quality.flipped_faces > 0)
    s += ", " + std::to_string(r.quality.flipped_faces) + " flipped";
  return s;
}

// ------------------------------------------------------------------------------- distance maps

struct Distances
{
  std::vector<double> bpdm, pdm, geodesic;
};

Distances distances(Input& in, std::size_t center)
{
  Distances d;
  auto map = in.mesh.add_property_map<vertex_descriptor, double>("v:figure_distance", 0.).first;
  auto copy = [&](std::vector<double>& out) {
    for(vertex_descriptor v : vertices(in.mesh))
      out.push_back(map[v]);
  };
  if(SMP::boundary_poisson_distance_map(in.mesh, in.bhd, map) != SMP::OK)
    std::cerr << "warning: BPDM failed on " << in.file << "\n";
  copy(d.bpdm);
  const std::vector<vertex_descriptor> sources{vertex_descriptor(Mesh::size_type(center))};
  if(SMP::poisson_distance_map(in.mesh, sources, map) != SMP::OK)
    std::cerr << "warning: PDM failed on " << in.file << "\n";
  copy(d.pdm);
  if(SMP::geodesic_distance_map<SMP::Fast_marching_geodesics>(in.mesh, sources, map) != SMP::OK)
    std::cerr << "warning: fast marching failed on " << in.file << "\n";
  copy(d.geodesic);
  in.mesh.remove_property_map(map);
  return d;
}

// What the values of a distance map are, for its color bar: a geodesic distance is a length
// in the mesh's units; a Poisson map (paper Eq. 1, right-hand side the mean edge length) is
// not: it grows about as the square of the distance over the mean edge length, so only its
// shape (ordering, maximum) means something.
enum class Map_unit { length, poisson };

const char* unit_title(Map_unit unit) { return unit == Map_unit::length ? "length" : "Eq. 1"; }

// A distance map panel: the 3D view (w x h) and its color bar on the right, titled with what
// its values are.
void distance_panel(Composite& fig, double x, double y, double w, double h, const Input& in,
                    const std::vector<double>& values, std::size_t center, Map_unit unit)
{
  double max = 0., step = 0.;
  const mbp_fig::Surface_style style = scalar_style(values, max, step);
  const mbp_fig::Viewport vp = fig.view(x, y, w - 60., h, in, style);
  fig.center(in, vp, center);
  fig.scalar_bar(x + w - 52., y + 26., h - 40., max, step, unit_title(unit));
}

// ------------------------------------------------------------------------------- main

int main(int argc, char** argv)
{
  std::vector<std::string> args;
  double zoom = 2.;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if(a.rfind("--zoom=", 0) == 0)
      zoom = std::atof(a.c_str() + 7);
    else
      args.push_back(a);
  }
  if(args.size() == 2 && args[0].rfind("--preview", 0) != 0 && fs::is_regular_file(args[0]))
  {
    // preview of one mesh (a development aid): plain views with each axis up
    Composite fig(6 * 210., 230., 1.);
    const Vec3 ups[6] = {{1., 0., 0.}, {-1., 0., 0.}, {0., 1., 0.}, {0., -1., 0.}, {0., 0., 1.}, {0., 0., -1.}};
    const char* names[6] = {"+x", "-x", "+y", "-y", "+z", "-z"};
    for(int k = 0; k < 6; ++k)
    {
      View v;
      v.up = ups[k];
      Input in;
      const fs::path p(args[0]);
      if(!load(p.parent_path().string(), p.filename().string(), "", v, in))
        return EXIT_FAILURE;
      fig.view(k * 210., 0., 200., 200., in, mbp_fig::Surface_style());
      fig.text(k * 210. + 100., 220., names[k], 14., true, "middle");
    }
    return write_file(args[1], fig.document()) ? EXIT_SUCCESS : EXIT_FAILURE;
  }
  if(args.size() != 3 || !(zoom > 0.))
  {
    std::cerr << "usage: make_figures MESH_DIR FIG_DIR WORK_DIR [--zoom=Z]\n";
    return EXIT_FAILURE;
  }
  const std::string mesh_dir = args[0];
  const fs::path fig_dir = args[1], work_dir = args[2];
  fs::create_directories(fig_dir);
  fs::create_directories(work_dir);

  std::ostringstream md;  // figures.md
  md << "# Figures\n\n"
     << "Generated by `scripts/make_figures.sh` (program `doc/figures/make_figures.cpp`) from the project's "
        "collection of public test meshes (the extended tier of the tests); do not edit by hand.\n\n"
     << "Distortion figures as in `measure_quality.h`: *angle distortion* is the paper's conformal distortion "
        "(Sheffer-de Sturler angle error with ABF's optimal angles, summed over corners and divided by the number "
        "of vertices), *L2* is Sander's L2 stretch normalised so that 1 is optimal. UV layouts are colored by the "
        "per-face angle distortion (mean of the 3 corners, log scale, viridis); the layouts of one figure share one "
        "color range. Each layout is rotated (never mirrored) to match the 3D view and scaled to UV area 1; the "
        "checkerboard has cells of side 1/14 in those units, so all textures of a mesh use the same cell size. "
        "The cross in a circle marks the center vertex. Grey on a 3D view is the back side of the surface.\n\n";

  // ---- meshes
  Input nefertiti, maxface, lilium, mask;
  View front_y;                          // y up
  if(!load(mesh_dir, "matthew_nefertiti.off", "Nefertiti", front_y, nefertiti) ||
     !load(mesh_dir, "maxFace.obj", "Max face", front_y, maxface) ||
     !load(mesh_dir, "lilium.obj", "Lilium", front_y, lilium) ||
     !load(mesh_dir, "mask.off", "Mask", front_y, mask))
    return EXIT_FAILURE;

  // ---- Fig. 1: overview on Nefertiti
  {
    Input& in = nefertiti;
    MBPPP mbpp;
    Result ours = measured(in, mbpp, "MBPPP");
    DCP_circle dcp;
    Result circle = run_method(in, dcp, "DCP (circle)");
    if(!ours.ok || !circle.ok)
      return EXIT_FAILURE;
    normalize_uv(in, ours);
    normalize_uv(in, circle);
    const Distances d = distances(in, ours.center);
    const auto range = distortion_range({&ours, &circle});

    const double pw = 300., ph = 300., gap = 14., top = 40., cap = 44.;
    const double W = 2 * pw + 3 * gap + 170., H = top + 3 * (ph + cap) + gap;
    Composite fig(W, H, zoom);
    fig.text(gap, 26., "Fig. 1  Overview of the method on " + in.title + " (" + std::to_string(in.tri.faces.size()) +
                         " faces)", 17., true);
    double y = top;
    distance_panel(fig, gap, y, pw, ph, in, d.bpdm, ours.center, Map_unit::poisson);
    fig.text(gap, y + ph + 18., "(a) boundary Poisson distance map (BPDM)", 13.);
    fig.text(gap, y + ph + 35., "and its maximum: the center (not a length)", 13., false, "start", "#444444");
    distance_panel(fig, 2 * gap + pw, y, pw, ph, in, d.pdm, ours.center, Map_unit::poisson);
    fig.text(2 * gap + pw, y + ph + 18., "(b) Poisson distance map (PDM)", 13.);
    fig.text(2 * gap + pw, y + ph + 35., "from the center (not a length)", 13., false, "start", "#444444");
    y += ph + cap;
    fig.nested(gap, y, pw, ph, layout_svg(in, ours, range.first, range.second));
    fig.text(gap, y + ph + 18., "(c) parameter domain, measured method", 13.);
    fig.text(gap, y + ph + 35., numbers(ours), 13., false, "start", "#444444");
    fig.center(in, fig.view(2 * gap + pw, y, pw, ph, in, checkerboard(ours)), ours.center);
    fig.text(2 * gap + pw, y + ph + 18., "(d) texture mapping, measured method", 13.);
    y += ph + cap;
    fig.nested(gap, y, pw, ph, layout_svg(in, circle, range.first, range.second));
    fig.text(gap, y + ph + 18., "(e) parameter domain, DCP with circle border", 13.);
    fig.text(gap, y + ph + 35., numbers(circle), 13., false, "start", "#444444");
    fig.view(2 * gap + pw, y, pw, ph, in, checkerboard(circle));
    fig.text(2 * gap + pw, y + ph + 18., "(f) texture mapping, DCP with circle border", 13.);
    fig.distortion_bar(2 * pw + 3 * gap + 10., top + ph + cap + 30., 2 * ph, range.first, range.second,
                       "angle distortion");
    fig.text(2 * pw + 3 * gap + 10., top + ph + cap + 2 * ph + 55., "per face (c), (e)", 11., false, "start", "#444444");
    if(!write_file(work_dir / "fig1_overview.svg", fig.document()))
      return EXIT_FAILURE;

    md << "## fig1_overview.png: the paper's Fig. 1 on " << in.title << "\n\n"
       << "`" << in.file << "`, " << in.tri.points.size() << " vertices, " << in.tri.faces.size()
       << " faces. (a) boundary Poisson distance map (BPDM) with its maximum, the center (vertex " << ours.center
       << "); (b) Poisson distance map (PDM) from the center; iso-lines every step of the color bar. The color "
          "bars of (a) and (b) give values of the paper's Eq. 1 (\"Eq. 1\"), which are not lengths: with the mean "
          "edge length as right-hand side they grow about as the square of the distance over the mean edge length; "
          "only their shape (ordering, maximum) is used. (c), (d) the "
          "measured method (MBPPP: BPDM center, PDM border distances, polar border map, discrete conformal "
          "interior): parameter domain and checkerboard texture. (e), (f) the same for CGAL's "
          "`Discrete_conformal_map_parameterizer_3` with its circular (arc-length) border.\n\n"
       << "| method | angle distortion | L2 stretch | flipped faces |\n|---|---|---|---|\n"
       << "| measured (MBPPP) | " << fixed(ours.quality.angle_distortion) << " | " << fixed(ours.quality.l2_stretch)
       << " | " << ours.quality.flipped_faces << " |\n"
       << "| DCP, circle border | " << fixed(circle.quality.angle_distortion) << " | "
       << fixed(circle.quality.l2_stretch) << " | " << circle.quality.flipped_faces << " |\n\n"
       << "Paper (Cutface model): 0.4493 / 1.3896 for the measured method, 0.7778 / 1.6753 for DCP.\n\n";

    // vector UV layout with legend and caption
    std::vector<std::string> caption = {
      std::to_string(in.tri.points.size()) + " vertices, " + std::to_string(in.tri.faces.size()) +
        " faces, measured boundary parameterization (MBPPP)",
      "angle distortion " + fixed(ours.quality.angle_distortion) + ",  L2 stretch " + fixed(ours.quality.l2_stretch) +
        ",  flipped faces " + std::to_string(ours.quality.flipped_faces)};
    if(!write_file(fig_dir / "uv_layout_nefertiti.svg",
                   layout_svg(in, ours, 0., 0., true, in.title + " (" + in.file + ")", caption)))
      return EXIT_FAILURE;
    md << "## uv_layout_nefertiti.svg: the UV layout alone (vector)\n\n"
       << "The layout of (c) with its own legend (color range: 2nd to 98th percentile of its faces), as the "
          "command-line program's `--svg` draws it.\n\n";

    // ---- distance maps (c) with the geodesic distance too, on two meshes
    {
      MBPPP mf;
      Result other = measured(maxface, mf, "MBPPP");
      const Distances d2 = distances(maxface, other.center);
      const double dw = 280., dh = 280.;
      Composite dm(3 * dw + 4 * gap, top + 2 * (dh + cap) + 20., zoom);
      dm.text(gap, 26., "Distance maps on the surface (center = maximum of the BPDM)", 17., true);
      const char* names[3] = {"BPDM (Eq. 1 values, not a length)", "PDM from the center (Eq. 1, not a length)",
                              "geodesic distance from the center (length)"};
      const Map_unit units[3] = {Map_unit::poisson, Map_unit::poisson, Map_unit::length};
      for(int row = 0; row < 2; ++row)
      {
        Input& m = row == 0 ? nefertiti : maxface;
        const Distances& dd = row == 0 ? d : d2;
        const std::size_t c = row == 0 ? ours.center : other.center;
        const double yy = top + row * (dh + cap);
        const std::vector<double>* maps[3] = {&dd.bpdm, &dd.pdm, &dd.geodesic};
        for(int k = 0; k < 3; ++k)
        {
          distance_panel(dm, gap + k * (dw + gap), yy, dw, dh, m, *maps[k], c, units[k]);
          dm.text(gap + k * (dw + gap), yy + dh + 18., std::string("(") + char('a' + 3 * row + k) + ") " + names[k], 12.5);
        }
        dm.text(gap, yy + dh + 35., m.title + " (" + m.file + ")", 12., false, "start", "#444444");
      }
      if(!write_file(work_dir / "distance_maps.svg", dm.document()))
        return EXIT_FAILURE;
      md << "## distance_maps.png: the distance maps\n\n"
         << "Top: " << nefertiti.title << " (`" << nefertiti.file << "`), bottom: " << maxface.title << " (`"
         << maxface.file << "`). (a, d) boundary Poisson distance map (cotangent weights, 0 on the border) and its "
            "maximum, the center; (b, e) Poisson distance map from the center (spring weights 1/length); (c, f) "
            "geodesic distance from the center by fast marching. The Poisson distance from the center is a smooth, "
            "rounder stand-in for the geodesic distance: its iso-lines are nearly circles around the center. "
            "Iso-lines at each tick. Color bars: the geodesic distance (\"length\") in the mesh's length units; the "
            "two Poisson maps (\"Eq. 1\") in values of the paper's Eq. 1, which are not lengths: with the mean edge "
            "length as right-hand side they grow about as the square of the distance over the mean edge length, so "
            "their scale depends on the mesh resolution and only their shape (ordering, maximum) is used.\n\n";
    }

    // ---- README picture: what the package is for: the automatic border against CGAL's
    // circle, textures and UV domains side by side, one color range
    {
      Result automatic = measured(in, Automatic_P(), "automatic border");
      if(!automatic.ok)
        return EXIT_FAILURE;
      normalize_uv(in, automatic);
      const auto hero_range = distortion_range({&automatic, &circle});
      const double hw = 250., hh = 250.;
      Composite hero(4 * hw + 5 * gap + 150., hh + 84., zoom);
      hero.view(gap, 10., hw, hh, in, checkerboard(automatic));
      hero.nested(2 * gap + hw, 10., hw, hh, layout_svg(in, automatic, hero_range.first, hero_range.second));
      hero.view(3 * gap + 2 * hw, 10., hw, hh, in, checkerboard(circle));
      hero.nested(4 * gap + 3 * hw, 10., hw, hh, layout_svg(in, circle, hero_range.first, hero_range.second));
      hero.distortion_bar(4 * hw + 5 * gap + 10., 50., hh - 80., hero_range.first, hero_range.second,
                          "angle distortion");
      hero.text(gap, hh + 32., in.title + ": the automatic border (" + automatic.note + "), texture and UV domain",
                13.);
      hero.text(gap, hh + 50., numbers(automatic), 12., false, "start", "#444444");
      hero.text(3 * gap + 2 * hw, hh + 32., "CGAL's discrete conformal map with its circle border", 13.);
      hero.text(3 * gap + 2 * hw, hh + 50., numbers(circle), 12., false, "start", "#444444");
      hero.text(gap, hh + 72., "UV domains colored by per-face angle distortion, one color range for both.", 12.,
                false, "start", "#444444");
      if(!write_file(work_dir / "hero.svg", hero.document()))
        return EXIT_FAILURE;
      md << "## hero.png: the README picture\n\n"
         << in.title << ": the checkerboard texture and the UV domain of the automatic border ("
         << automatic.note << "; " << numbers(automatic) << ") beside those of CGAL's discrete conformal map "
         << "with its circle border (" << numbers(circle) << "); the two UV domains share one color range.\n\n";
    }
  }

  // ---- Fig. 4: effect of the center
  {
    Input& in = maxface;
    // the BPDM and BGDM centers
    MBPPP bpdm_p;
    const Result bpdm_result = measured(in, bpdm_p, "BPDM center");
    BGDM_PP bgdm_p;
    const Result bgdm_result = measured(in, bgdm_p, "BGDM center");
    if(!bpdm_result.ok || !bgdm_result.ok)
      return EXIT_FAILURE;
    // a poor center: the interior vertex with a BPDM between 20% and 30% of its maximum that is
    // farthest from the BPDM center
    auto bpdm = in.mesh.add_property_map<vertex_descriptor, double>("v:figure_bpdm", 0.).first;
    SMP::boundary_poisson_distance_map(in.mesh, in.bhd, bpdm);
    double bmax = 0.;
    for(vertex_descriptor v : vertices(in.mesh))
      bmax = (std::max)(bmax, bpdm[v]);
    const Point_3 gc = in.mesh.point(vertex_descriptor(Mesh::size_type(bpdm_result.center)));
    vertex_descriptor poor_v;
    double best = -1.;
    for(vertex_descriptor v : vertices(in.mesh))
      if(!CGAL::is_border(v, in.mesh) && bpdm[v] >= 0.2 * bmax && bpdm[v] <= 0.3 * bmax)
      {
        const double dist = CGAL::squared_distance(in.mesh.point(v), gc);
        if(dist > best)
        {
          best = dist;
          poor_v = v;
        }
      }
    in.mesh.remove_property_map(bpdm);
    const vertex_descriptor centers[3] = {vertex_descriptor(Mesh::size_type(bpdm_result.center)),
                                          vertex_descriptor(Mesh::size_type(bgdm_result.center)), poor_v};
    // each center with Poisson (row 0) and geodesic (row 1) border distances, without repair
    // when the result is valid
    Result results[2][3];
    for(int k = 0; k < 3; ++k)
    {
      const SMP::Fixed_center<Mesh> fixed_center(centers[k]);
      const Fixed_PP::Border_policy pp(fixed_center);
      results[0][k] = measured(in, Fixed_PP(pp, Fixed_PP::Solver_traits(), SMP::NO_REPAIR), "MBPPP");
      if(!results[0][k].ok)
        results[0][k] = measured(in, Fixed_PP(pp, Fixed_PP::Solver_traits(), SMP::BLEND_TOWARD_CIRCLE), "MBPPP");
      const Fixed_GP::Border_policy gp(fixed_center);
      results[1][k] = measured(in, Fixed_GP(gp, Fixed_GP::Solver_traits(), SMP::NO_REPAIR), "MBPGP");
      if(!results[1][k].ok)
        results[1][k] = measured(in, Fixed_GP(gp, Fixed_GP::Solver_traits(), SMP::BLEND_TOWARD_CIRCLE), "MBPGP");
      for(int row = 0; row < 2; ++row)
      {
        if(!results[row][k].ok)
          return EXIT_FAILURE;
        normalize_uv(in, results[row][k]);
      }
    }
    std::vector<const Result*> all;
    for(auto& row : results)
      for(const Result& r : row)
        all.push_back(&r);
    const auto range = distortion_range(all);
    const double pw = 250., ph = 250., gap = 14., left = 30., top = 76., cap = 50.;
    Composite fig(left + 3 * pw + 4 * gap + 140., top + 3 * ph + 2 * cap + 60., zoom);
    fig.text(gap, 26., "Fig. 4  Effect of the center vertex on " + in.title, 17., true);
    const char* names[3] = {"(a) maximum of the BPDM", "(b) maximum of the BGDM", "(c) a poor center"};
    const char* row_names[3] = {"domain, Poisson distances", "domain, geodesic distances", "texture, Poisson distances"};
    for(int k = 0; k < 3; ++k)
    {
      const double x = left + gap + k * (pw + gap);
      fig.text(x + pw / 2, top - 26., names[k], 13.5, true, "middle");
      fig.text(x + pw / 2, top - 9., "center: vertex " + std::to_string(centers[k].idx()), 12.5, false, "middle",
               "#444444");
      for(int row = 0; row < 2; ++row)
      {
        const Result& r = results[row][k];
        const double y = top + row * (ph + cap);
        fig.nested(x, y, pw, ph, layout_svg(in, r, range.first, range.second));
        fig.text(x, y + ph + 18., numbers(r), 12.5, false, "start", "#222222");
        if(!r.note.empty())
          fig.text(x, y + ph + 34., r.note, 12., false, "start", "#444444");
      }
      fig.center(in, fig.view(x, top + 2 * (ph + cap), pw, ph, in, checkerboard(results[0][k])), results[0][k].center);
    }
    for(int row = 0; row < 3; ++row)
    {
      const double cy = top + row * (ph + cap) + ph / 2, cx = left;
      fig.raw("<text x=\"" + fixed(cx, 1) + "\" y=\"" + fixed(cy, 1) + "\" font-size=\"13\" text-anchor=\"middle\" "
              "fill=\"#444444\" transform=\"rotate(-90 " + fixed(cx, 1) + " " + fixed(cy, 1) + ")\">" +
              esc(row_names[row]) + "</text>\n");
    }
    fig.distortion_bar(left + 3 * pw + 4 * gap + 10., top + 30., 1.5 * ph, range.first, range.second,
                       "angle distortion");
    fig.text(gap, top + 3 * ph + 2 * cap + 25., in.title + " (" + in.file + ", " + std::to_string(in.tri.faces.size()) +
                                                   " faces); the center is marked; one color range for all domains",
             12., false, "start", "#444444");
    if(!write_file(work_dir / "fig4_center.svg", fig.document()))
      return EXIT_FAILURE;
    md << "## fig4_center.png: the paper's Fig. 4, effect of the center\n\n"
       << "`" << in.file << "`, " << in.tri.points.size() << " vertices, " << in.tri.faces.size()
       << " faces. The measured method with three centers (given through `Fixed_center`): (a) the package's default "
          "center, the maximum of the boundary Poisson distance map (BPDM); (b) the maximum of the boundary geodesic "
          "distance map (BGDM); (c) a poor center: the interior vertex with a BPDM between 20% and 30% of its "
          "maximum that is farthest from the BPDM center. Top row: parameter domains with Poisson border distances "
          "(MBPPP); middle row: with fast marching geodesic border distances (MBPGP, the paper's \"local geodesic "
          "parameterization\"); bottom row: the checkerboard through the MBPPP results. No repair unless noted.\n\n"
       << "| center | vertex | MBPPP angle distortion | MBPPP L2 | MBPGP angle distortion | MBPGP L2 |\n"
          "|---|---|---|---|---|---|\n";
    for(int k = 0; k < 3; ++k)
    {
      md << "| " << names[k] + 4 << " | " << centers[k].idx();
      for(int row = 0; row < 2; ++row)
      {
        const Result& r = results[row][k];
        md << " | " << fixed(r.quality.angle_distortion);
        if(r.quality.flipped_faces > 0)
          md << " (" << r.quality.flipped_faces << " flipped)";
        if(!r.note.empty())
          md << " (" << r.note << ")";
        md << " | " << fixed(r.quality.l2_stretch);
      }
      md << " |\n";
    }
    md << "\n";
  }

  // ---- Fig. 9: domains of the methods
  {
    Input* meshes[4] = {&nefertiti, &lilium, &maxface, &mask};
    const int columns = 5;
    const char* heads[columns] = {"texture (MBPPP)", "MBPPP: Poisson", "MBPGP: geodesic", "automatic border",
                                  "LSCM: free border"};
    std::vector<std::vector<Result> > rows;
    for(Input* in : meshes)
    {
      std::vector<Result> row;
      row.push_back(measured(*in, MBPPP(), "MBPPP"));
      row.push_back(measured(*in, MBPGP(), "MBPGP"));
      row.push_back(measured(*in, Automatic_P(), "automatic"));
      row.push_back(run_method(*in, LSCM(), "LSCM"));
      for(Result& r : row)
        if(r.ok)
          normalize_uv(*in, r);
      rows.push_back(row);
    }
    // one color range per row: the layouts of one mesh are compared; the meshes' distortions
    // differ by orders of magnitude, so a shared range would flatten most rows into one color
    std::vector<std::pair<double, double> > ranges;
    for(const auto& row : rows)
    {
      std::vector<const Result*> ok;
      for(const Result& r : row)
        if(r.ok)
          ok.push_back(&r);
      ranges.push_back(distortion_range(ok));
    }
    const double pw = 210., ph = 210., gap = 12., top = 58., cap = 50.;
    Composite fig(columns * (pw + gap) + gap + 130., top + 4 * (ph + cap) + 10., zoom);
    fig.text(gap, 24., "Fig. 9  Parameter domains of the measured methods and of LSCM (free border)", 17., true);
    for(int k = 0; k < columns; ++k)
      fig.text(gap + k * (pw + gap) + pw / 2, top - 10., heads[k], 13., true, "middle");
    md << "## fig9_domains.png: the paper's Fig. 9, parameter domains\n\n"
       << "Rows: " << nefertiti.title << ", " << lilium.title << ", " << maxface.title << ", " << mask.title
       << ". Columns: the checkerboard through MBPPP; the domains of MBPPP (BPDM center, Poisson distances), MBPGP "
          "(BPDM center, fast marching geodesic distances), the automatic border "
          "(`Conformal_parameterizer_3` with `Automatic_border<>`: the best of the border family, circle, measured and conformal "
          "borders and their blends) "
          "and CGAL's `LSCM_parameterizer_3` (free border, two fixed vertices) in place of the paper's ABF++. "
          "One color range per row (per mesh), with its color bar at the end of the row: the layouts of a mesh "
          "are comparable with each other, not with those of another row.\n\n"
       << "| mesh | faces | MBPPP | MBPGP | automatic | LSCM |\n|---|---|---|---|---|---|\n";
    for(int row = 0; row < 4; ++row)
    {
      Input& in = *meshes[row];
      const double y = top + row * (ph + cap);
      const auto& rs = rows[std::size_t(row)];
      if(rs[0].ok)
        fig.center(in, fig.view(gap, y, pw, ph, in, checkerboard(rs[0])), rs[0].center);
      fig.text(gap, y + ph + 18., in.title, 12.5, true);
      fig.text(gap, y + ph + 34., in.file + ", " + std::to_string(in.tri.faces.size()) + " faces", 11.5, false,
               "start", "#444444");
      md << "| " << in.title << " (`" << in.file << "`) | " << in.tri.faces.size();
      for(int k = 0; k < 4; ++k)
      {
        const Result& r = rs[std::size_t(k)];
        const double x = gap + (k + 1) * (pw + gap);
        if(r.ok)
          fig.nested(x, y, pw, ph, layout_svg(in, r, ranges[std::size_t(row)].first, ranges[std::size_t(row)].second));
        fig.text(x, y + ph + 18., r.ok ? "angle dist. " + fixed(r.quality.angle_distortion) + ", L2 " +
                                           fixed(r.quality.l2_stretch)
                                       : std::string("failed"), 11.5);
        std::string second = r.note;
        if(r.ok && r.quality.flipped_faces > 0)
          second = std::to_string(r.quality.flipped_faces) + " flipped faces" + (second.empty() ? "" : "; " + second);
        if(!second.empty())
          fig.text(x, y + ph + 34., second, 11., false, "start", "#444444");
        md << " | " << (r.ok ? fixed(r.quality.angle_distortion) + " / " + fixed(r.quality.l2_stretch) : "failed");
        if(r.ok && r.quality.flipped_faces > 0)
          md << " (" << r.quality.flipped_faces << " flipped)";
        if(!r.note.empty())
          md << " (" << r.note << ")";
      }
      md << " |\n";
      fig.distortion_bar(columns * (pw + gap) + gap + 10., y + 20., ph - 30., ranges[std::size_t(row)].first,
                         ranges[std::size_t(row)].second, "angle dist.");
    }
    md << "\nEach cell: angle distortion / L2 stretch.\n\n";
    if(!write_file(work_dir / "fig9_domains.svg", fig.document()))
      return EXIT_FAILURE;
  }

  if(!write_file(fig_dir / "figures.md", md.str()))
    return EXIT_FAILURE;
  return EXIT_SUCCESS;
}
