// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// A small software renderer for the documentation figures: a triangle mesh seen from a
// chosen direction (orthographic), z-buffered, with smooth Lambert shading, colored either by
// a checkerboard texture through per-vertex UVs or by a per-vertex scalar (a color map with
// iso-lines), supersampled for anti-aliasing; and a PNG encoder (stored deflate blocks, so no
// zlib: the figure script lets rsvg-convert recompress the final pictures). No CGAL here.

#ifndef MBP_FIGURES_RASTER_H
#define MBP_FIGURES_RASTER_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace mbp_fig {

typedef std::array<double, 3> Vec3;
typedef std::array<double, 2> Vec2;

inline Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Vec3 add(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline Vec3 mul(const Vec3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3 cross(const Vec3& a, const Vec3& b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline Vec3 normalized(const Vec3& a)
{
  const double n = std::sqrt(dot(a, a));
  return n > 0. ? mul(a, 1. / n) : Vec3{0., 0., 1.};
}

/// An indexed triangle mesh.
struct Tri_mesh
{
  std::vector<Vec3> points;
  std::vector<std::array<std::size_t, 3> > faces;
};

/// An orthographic camera: `toward_viewer` points from the object to the eye, `up` is
/// projected to the screen's vertical.
struct Camera
{
  Vec3 toward_viewer{0., 0., 1.};
  Vec3 up{0., 1., 0.};

  Vec3 z() const { return normalized(toward_viewer); }
  Vec3 x() const { return normalized(cross(up, z())); }
  Vec3 y() const { return cross(z(), x()); }
  /// screen coordinates (x right, y up) of `p`
  Vec2 project(const Vec3& p) const { return {dot(p, x()), dot(p, y())}; }
};

/// An RGB image, 8 bits a channel, rows top to bottom.
struct Image
{
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;
};

/// Viridis, t in [0, 1], as RGB in [0, 1].
inline Vec3 viridis(double t)
{
  static const double stops[9][3] = {
    {0x44, 0x01, 0x54}, {0x47, 0x2d, 0x7b}, {0x3b, 0x52, 0x8b}, {0x2c, 0x72, 0x8e}, {0x21, 0x91, 0x8c},
    {0x28, 0xae, 0x80}, {0x5e, 0xc9, 0x62}, {0xad, 0xdc, 0x30}, {0xfd, 0xe7, 0x25}};
  t = std::clamp(t, 0., 1.) * 8.;
  const int i = (std::min)(int(t), 7);
  const double s = t - i;
  Vec3 c;
  for(int k = 0; k < 3; ++k)
    c[std::size_t(k)] = (stops[i][k] + s * (stops[i + 1][k] - stops[i][k])) / 255.;
  return c;
}

/// What the faces show.
struct Surface_style
{
  enum Mode { CHECKERBOARD, SCALAR, PLAIN } mode = PLAIN;
  /// CHECKERBOARD: per-vertex UVs; a cell has side `checker_size` in UV units.
  std::vector<Vec2> uv;
  double checker_size = 0.1;
  Vec3 checker_dark{0.16, 0.32, 0.62}, checker_light{0.96, 0.95, 0.90};
  /// SCALAR: per-vertex values, mapped linearly from [scalar_min, scalar_max] to viridis;
  /// an iso-line every `iso_step` (none when <= 0).
  std::vector<double> scalar;
  double scalar_min = 0., scalar_max = 1., iso_step = 0.;
  /// PLAIN: one color.
  Vec3 plain{0.8, 0.8, 0.8};
  /// faces seen from behind (the surface is open): this color, shaded, no texture
  Vec3 back{0.55, 0.55, 0.58};
};

/// Where the renderer put the mesh: screen point (x right, y up) -> pixel of the output image.
struct Viewport
{
  double scale = 1., offset_x = 0., offset_y = 0.;
  int width = 0, height = 0;
  /// pixel coordinates (x right, y down) of screen point `s`
  Vec2 pixel(const Vec2& s) const { return {offset_x + scale * s[0], offset_y - scale * s[1]}; }
};

/// renders `mesh` seen by `camera` into a `width` x `height` image (white background, the
/// mesh fitted with a margin of `margin` pixels), `supersampling`^2 samples a pixel.
inline Image render(const Tri_mesh& mesh, const Camera& camera, const Surface_style& style, int width,
                    int height, Viewport& viewport, int margin = 6, int supersampling = 3)
{
  const Vec3 ex = camera.x(), ey = camera.y(), ez = camera.z();
  const std::size_t nv = mesh.points.size();

  // Vertex normals (area weighted) and face orientation toward the viewer.
  std::vector<Vec3> vn(nv, Vec3{0., 0., 0.});
  std::vector<bool> front(mesh.faces.size());
  for(std::size_t f = 0; f < mesh.faces.size(); ++f)
  {
    const auto& t = mesh.faces[f];
    const Vec3 n = cross(sub(mesh.points[t[1]], mesh.points[t[0]]), sub(mesh.points[t[2]], mesh.points[t[0]]));
    for(std::size_t k : t)
      vn[k] = add(vn[k], n);
    front[f] = dot(n, ez) >= 0.;
  }
  for(Vec3& n : vn)
    n = normalized(n);

  // Fit: screen bounding box -> image minus margins.
  double xmin = std::numeric_limits<double>::max(), xmax = -xmin, ymin = xmin, ymax = -xmin;
  std::vector<Vec3> s(nv);  // screen x, y, depth (larger = nearer)
  for(std::size_t i = 0; i < nv; ++i)
  {
    s[i] = {dot(mesh.points[i], ex), dot(mesh.points[i], ey), dot(mesh.points[i], ez)};
    xmin = (std::min)(xmin, s[i][0]); xmax = (std::max)(xmax, s[i][0]);
    ymin = (std::min)(ymin, s[i][1]); ymax = (std::max)(ymax, s[i][1]);
  }
  const double scale = (std::min)((width - 2. * margin) / (std::max)(xmax - xmin, 1e-300),
                                  (height - 2. * margin) / (std::max)(ymax - ymin, 1e-300));
  viewport.scale = scale;
  viewport.offset_x = 0.5 * width - scale * 0.5 * (xmin + xmax);
  viewport.offset_y = 0.5 * height + scale * 0.5 * (ymin + ymax);
  viewport.width = width;
  viewport.height = height;

  const int ss = (std::max)(1, supersampling);
  const int W = width * ss, H = height * ss;
  std::vector<int> face_at(std::size_t(W) * std::size_t(H), -1);
  std::vector<float> depth(face_at.size(), -std::numeric_limits<float>::max());
  std::vector<float> b1(face_at.size()), b2(face_at.size());
  std::vector<Vec2> px(nv);
  for(std::size_t i = 0; i < nv; ++i)
  {
    const Vec2 p = viewport.pixel({s[i][0], s[i][1]});
    px[i] = {p[0] * ss, p[1] * ss};
  }

  // Rasterize: sample centers at (i + 0.5, j + 0.5).
  for(std::size_t f = 0; f < mesh.faces.size(); ++f)
  {
    const auto& t = mesh.faces[f];
    const Vec2 &a = px[t[0]], &b = px[t[1]], &c = px[t[2]];
    const double area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    if(std::abs(area) < 1e-12)
      continue;
    const int i0 = (std::max)(0, int(std::floor((std::min)({a[0], b[0], c[0]}) - 0.5)));
    const int i1 = (std::min)(W - 1, int(std::ceil((std::max)({a[0], b[0], c[0]}) - 0.5)));
    const int j0 = (std::max)(0, int(std::floor((std::min)({a[1], b[1], c[1]}) - 0.5)));
    const int j1 = (std::min)(H - 1, int(std::ceil((std::max)({a[1], b[1], c[1]}) - 0.5)));
    for(int j = j0; j <= j1; ++j)
      for(int i = i0; i <= i1; ++i)
      {
        const double x = i + 0.5, y = j + 0.5;
        const double w1 = ((x - a[0]) * (c[1] - a[1]) - (y - a[1]) * (c[0] - a[0])) / area;
        const double w2 = ((b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0])) / area;
        const double w0 = 1. - w1 - w2;
        if(w0 < 0. || w1 < 0. || w2 < 0.)
          continue;
        const float z = float(w0 * s[t[0]][2] + w1 * s[t[1]][2] + w2 * s[t[2]][2]);
        const std::size_t k = std::size_t(j) * std::size_t(W) + std::size_t(i);
        if(z > depth[k])
        {
          depth[k] = z;
          face_at[k] = int(f);
          b1[k] = float(w1);
          b2[k] = float(w2);
        }
      }
  }

  // Scalar per sample (for the iso-lines, whose width is measured in samples).
  std::vector<float> value;
  if(style.mode == Surface_style::SCALAR)
  {
    value.assign(face_at.size(), 0.f);
    for(std::size_t k = 0; k < face_at.size(); ++k)
      if(face_at[k] >= 0)
      {
        const auto& t = mesh.faces[std::size_t(face_at[k])];
        value[k] = float((1. - b1[k] - b2[k]) * style.scalar[t[0]] + b1[k] * style.scalar[t[1]] +
                         b2[k] * style.scalar[t[2]]);
      }
  }

  // Shade: a key light from the upper left in front, ambient, two-sided.
  const Vec3 light = normalized(add(add(ez, mul(ey, 0.55)), mul(ex, -0.35)));
  std::vector<float> accum(std::size_t(width) * std::size_t(height) * 3, 0.f);
  for(int j = 0; j < H; ++j)
    for(int i = 0; i < W; ++i)
    {
      const std::size_t k = std::size_t(j) * std::size_t(W) + std::size_t(i);
      Vec3 color{1., 1., 1.};
      const int f = face_at[k];
      if(f >= 0)
      {
        const auto& t = mesh.faces[std::size_t(f)];
        const double w1 = b1[k], w2 = b2[k], w0 = 1. - w1 - w2;
        Vec3 n = normalized(add(add(mul(vn[t[0]], w0), mul(vn[t[1]], w1)), mul(vn[t[2]], w2)));
        const bool is_front = front[std::size_t(f)];
        if(!is_front)
          n = mul(n, -1.);
        if(dot(n, ez) < 0.)  // interpolated normal turned away at a silhouette
          n = normalized(add(n, mul(ez, -dot(n, ez))));
        const double shade = 0.28 + 0.72 * (std::max)(0., dot(n, light));
        Vec3 base = style.plain;
        if(!is_front)
          base = style.back;
        else if(style.mode == Surface_style::CHECKERBOARD)
        {
          const double u = w0 * style.uv[t[0]][0] + w1 * style.uv[t[1]][0] + w2 * style.uv[t[2]][0];
          const double v = w0 * style.uv[t[0]][1] + w1 * style.uv[t[1]][1] + w2 * style.uv[t[2]][1];
          const long cu = long(std::floor(u / style.checker_size)), cv = long(std::floor(v / style.checker_size));
          base = (((cu + cv) & 1L) == 0) ? style.checker_light : style.checker_dark;
        }
        else if(style.mode == Surface_style::SCALAR)
        {
          const double val = value[k];
          base = viridis((val - style.scalar_min) / (std::max)(style.scalar_max - style.scalar_min, 1e-300));
          if(style.iso_step > 0.)
          {
            // distance to the nearest iso-value, in samples, from the local gradient
            const std::size_t kr = (i + 1 < W) ? k + 1 : k - 1, kd = (j + 1 < H) ? k + std::size_t(W) : k - std::size_t(W);
            double gx = 0., gy = 0.;
            if(face_at[kr] >= 0) gx = double(value[kr]) - val;
            if(face_at[kd] >= 0) gy = double(value[kd]) - val;
            const double g = std::hypot(gx, gy);
            const double r = val / style.iso_step;
            const double d = std::abs(r - std::round(r)) * style.iso_step;
            if(g > 0. && d / g < 0.55 * ss && val > 0.5 * style.iso_step)
              base = mul(base, 0.35);
          }
        }
        color = mul(base, shade);
      }
      float* out = &accum[(std::size_t(j / ss) * std::size_t(width) + std::size_t(i / ss)) * 3];
      for(int c = 0; c < 3; ++c)
        out[c] += float(color[std::size_t(c)]);
    }

  Image image;
  image.width = width;
  image.height = height;
  image.rgb.resize(accum.size());
  const float inv = 1.f / float(ss * ss);
  for(std::size_t k = 0; k < accum.size(); ++k)
    image.rgb[k] = std::uint8_t(std::lround(std::clamp(accum[k] * inv, 0.f, 1.f) * 255.f));
  return image;
}

namespace detail {

inline std::uint32_t crc32(const std::uint8_t* data, std::size_t n, std::uint32_t crc = 0)
{
  static std::uint32_t table[256] = {0};
  if(table[1] == 0)
    for(std::uint32_t i = 0; i < 256; ++i)
    {
      std::uint32_t c = i;
      for(int k = 0; k < 8; ++k)
        c = (c & 1u) ? 0xedb88320u ^ (c >> 1) : c >> 1;
      table[i] = c;
    }
  crc = ~crc;
  for(std::size_t i = 0; i < n; ++i)
    crc = table[(crc ^ data[i]) & 0xffu] ^ (crc >> 8);
  return ~crc;
}

inline void put32(std::string& s, std::uint32_t x)
{
  for(int k = 3; k >= 0; --k)
    s += char((x >> (8 * k)) & 0xffu);
}

inline void chunk(std::string& png, const char* type, const std::string& data)
{
  put32(png, std::uint32_t(data.size()));
  const std::string body = std::string(type, 4) + data;
  png += body;
  put32(png, crc32(reinterpret_cast<const std::uint8_t*>(body.data()), body.size()));
}

} // namespace detail

/// the PNG file of `image` (8-bit RGB, deflate "stored" blocks: not compressed).
inline std::string png_file(const Image& image)
{
  std::string raw;
  raw.reserve(std::size_t(image.height) * (std::size_t(image.width) * 3 + 1));
  for(int j = 0; j < image.height; ++j)
  {
    raw += char(0);  // filter: none
    raw.append(reinterpret_cast<const char*>(&image.rgb[std::size_t(j) * std::size_t(image.width) * 3]),
               std::size_t(image.width) * 3);
  }
  std::string z;
  z += char(0x78);
  z += char(0x01);
  std::uint32_t a = 1, b = 0;
  for(unsigned char c : raw)
  {
    a = (a + c) % 65521u;
    b = (b + a) % 65521u;
  }
  for(std::size_t pos = 0; pos < raw.size() || pos == 0;)
  {
    const std::size_t n = (std::min)(raw.size() - pos, std::size_t(65535));
    const bool last = pos + n >= raw.size();
    z += char(last ? 1 : 0);
    z += char(n & 0xffu);
    z += char((n >> 8) & 0xffu);
    z += char(~n & 0xffu);
    z += char((~n >> 8) & 0xffu);
    z.append(raw, pos, n);
    pos += n;
    if(last)
      break;
  }
  detail::put32(z, (b << 16) | a);

  std::string png("\x89PNG\r\n\x1a\n", 8);
  std::string ihdr;
  detail::put32(ihdr, std::uint32_t(image.width));
  detail::put32(ihdr, std::uint32_t(image.height));
  ihdr += char(8);  // bit depth
  ihdr += char(2);  // RGB
  ihdr += char(0);
  ihdr += char(0);
  ihdr += char(0);
  detail::chunk(png, "IHDR", ihdr);
  detail::chunk(png, "IDAT", z);
  detail::chunk(png, "IEND", std::string());
  return png;
}

/// base64 of `data` (for data: URIs)
inline std::string base64(const std::string& data)
{
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((data.size() + 2) / 3 * 4);
  for(std::size_t i = 0; i < data.size(); i += 3)
  {
    const std::uint32_t n = (std::uint32_t(std::uint8_t(data[i])) << 16) |
                            (i + 1 < data.size() ? std::uint32_t(std::uint8_t(data[i + 1])) << 8 : 0u) |
                            (i + 2 < data.size() ? std::uint32_t(std::uint8_t(data[i + 2])) : 0u);
    out += digits[(n >> 18) & 63u];
    out += digits[(n >> 12) & 63u];
    out += (i + 1 < data.size()) ? digits[(n >> 6) & 63u] : '=';
    out += (i + 2 < data.size()) ? digits[n & 63u] : '=';
  }
  return out;
}

} // namespace mbp_fig

#endif // MBP_FIGURES_RASTER_H
