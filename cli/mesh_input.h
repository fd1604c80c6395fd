// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// Input of the measured_parameterization program: reading a mesh file with a message that
// names the problem when it fails, the generated fallback mesh, and the checks that give a
// precise message before the library sees the mesh.

#ifndef MBP_CLI_MESH_INPUT_H
#define MBP_CLI_MESH_INPUT_H

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/main_border.h>

#include "mesh_reader.h"
#include "text_output.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <filesystem>
#include <new>
#include <string>
#include <vector>

#include <sys/stat.h>

namespace mbp_cli {

namespace SMP = CGAL::Surface_mesh_parameterization;

/// A failure of the program: a code of the library (`SMP::OK` for failures that have none,
/// such as an unreadable file) and the details.
struct Failure
{
  SMP::Error_code code = SMP::OK;
  std::string detail;

  bool failed() const { return !detail.empty() || code != SMP::OK; }
  /// the message: the library's text for the code, then the details.
  std::string message() const
  {
    if(code == SMP::OK)
      return detail;
    std::string m = SMP::get_measured_error_message(code);
    if(!detail.empty())
      m += ": " + detail;
    return m;
  }
};

namespace detail {

// Why the faces of `soup` do not form a polygon mesh, found after Euler::add_face refused
// face `failed` (the faces before it were added): a face of fewer than three vertices or
// using a vertex twice, an edge of more than two faces, two faces of opposite orientation,
// or a vertex whose faces do not form one fan.
inline std::string explain_soup(const Polygon_soup& soup, std::size_t failed)
{
  const std::size_t begin = soup.face_begin(failed), n = soup.face_size(failed);
  if(n < 3)
    return "face " + std::to_string(failed) + " has " + std::to_string(n) + (n == 1 ? " vertex" : " vertices") +
           " (a face needs at least three)";
  for(std::size_t a = 0; a < n; ++a)
    for(std::size_t b = a + 1; b < n; ++b)
      if(soup.corners[begin + a] == soup.corners[begin + b])
        return "face " + std::to_string(failed) + " uses vertex " + std::to_string(soup.corners[begin + a]) + " twice";
  // the directed edges of the faces before, by their source vertex
  for(std::size_t c = 0; c < n; ++c)
  {
    const std::uint32_t u = soup.corners[begin + c], v = soup.corners[begin + (c + 1) % n];
    std::size_t same = std::size_t(-1), opposite = std::size_t(-1);
    for(std::size_t f = 0; f < failed; ++f)
    {
      const std::size_t fb = soup.face_begin(f), fn = soup.face_size(f);
      for(std::size_t k = 0; k < fn; ++k)
      {
        const std::uint32_t x = soup.corners[fb + k], y = soup.corners[fb + (k + 1) % fn];
        if(x == u && y == v && same == std::size_t(-1))
          same = f;
        if(x == v && y == u && opposite == std::size_t(-1))
          opposite = f;
      }
    }
    const std::string edge = "the edge " + std::to_string(u) + "-" + std::to_string(v);
    if(same != std::size_t(-1) && opposite != std::size_t(-1))
      return edge + " has more than two faces (faces " + std::to_string((std::min)(same, opposite)) + ", " +
             std::to_string((std::max)(same, opposite)) + " and " + std::to_string(failed) + "): not a 2-manifold";
    if(same != std::size_t(-1))
      return "faces " + std::to_string(same) + " and " + std::to_string(failed) + " traverse " + edge +
             " in the same direction: their orientations are inconsistent (or the edge has more than two faces)";
  }
  return "face " + std::to_string(failed) + " makes a vertex non-manifold (its faces around the vertex would not "
         "form one fan)";
}

} // namespace detail

namespace detail {

// The failure of a file whose extension is not .off, .obj, .ply or .stl: a missing file or a
// directory is named first, as for the others.
inline Failure unsupported_extension(const std::string& path)
{
  Failure f;
  struct stat st;
  if(::stat(path.c_str(), &st) != 0 || S_ISDIR(st.st_mode))  // name these first
  {
    Polygon_soup none;
    f.detail = read_polygon_soup(path, "off", none).message;
    return f;
  }
  f.detail = "unsupported file extension '" + std::filesystem::path(path).extension().string() +
             "' (expected .off, .obj, .ply or .stl)";
  return f;
}

// Reads the polygon soup of `path` with the readers of mesh_reader.h.
inline Failure read_soup(const std::string& path, const std::string& ext, Polygon_soup& soup)
{
  Failure f;
  try
  {
    const Read_error e = read_polygon_soup(path, ext, soup);
    if(e.failed())
    {
      f.code = e.non_finite ? SMP::ERROR_NON_FINITE_COORDINATES : SMP::OK;
      f.detail = (e.non_finite || e.message == "no such file" || e.message.rfind("it is ", 0) == 0 ||
                  e.message == "the file is empty" || e.message.rfind("cannot open", 0) == 0)
                   ? e.message
                   : "cannot read it: " + e.message;
    }
  }
  catch(const std::bad_alloc&)  // the counts are checked against the file size: not expected
  {
    f.detail = "cannot read it: out of memory";
  }
  return f;
}

// Whether the vertices of `face` are at least three and distinct.
template <class VertexDescriptor>
bool distinct_vertices(const std::vector<VertexDescriptor>& face)
{
  if(face.size() < 3)
    return false;
  if(face.size() == 3)
    return face[0] != face[1] && face[1] != face[2] && face[0] != face[2];
  std::vector<VertexDescriptor> sorted = face;
  std::sort(sorted.begin(), sorted.end());
  return std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end();
}

// Builds `mesh` from `soup` as CGAL's polygon soup to polygon mesh does (the points are freed
// on the way), or says why the faces do not form a polygon mesh.
template <class Mesh>
Failure build_mesh(Polygon_soup& soup, Mesh& mesh)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::property_traits<
    typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type Point_3;
  mesh.reserve(static_cast<typename Mesh::size_type>(soup.points.size()),
               static_cast<typename Mesh::size_type>(std::min<std::size_t>(soup.corners.size(),
                                                                           soup.points.size() + soup.number_of_faces() + 64)),
               static_cast<typename Mesh::size_type>(soup.number_of_faces()));
  std::vector<vertex_descriptor> vertex(soup.points.size());
  auto vpm = get(CGAL::vertex_point, mesh);
  for(std::size_t i = 0; i < soup.points.size(); ++i)
  {
    vertex[i] = add_vertex(mesh);
    put(vpm, vertex[i], Point_3(soup.points[i][0], soup.points[i][1], soup.points[i][2]));
  }
  std::vector<std::array<double, 3> >().swap(soup.points);
  std::vector<vertex_descriptor> face;
  Failure f;
  for(std::size_t i = 0; i < soup.number_of_faces(); ++i)
  {
    face.clear();
    const std::size_t end = soup.face_end[i];
    for(std::size_t k = soup.face_begin(i); k < end; ++k)
      face.push_back(vertex[soup.corners[k]]);
    if(!distinct_vertices(face) || CGAL::Euler::add_face(face, mesh) == boost::graph_traits<Mesh>::null_face())
    {
      mesh.clear();
      f.detail = "not a polygon mesh: " + explain_soup(soup, i);
      return f;
    }
  }
  return f;
}

} // namespace detail

/// reads the polygon soup of the file `path` (.off, .obj, .ply or .stl) with the streaming
/// readers of mesh_reader.h: points in file order (STL: equal points merged, in order of first
/// appearance), every index checked, no non-finite coordinate. On failure, the message names
/// the problem (the caller prefixes the file name).
inline Failure read_soup_file(const std::string& path, Polygon_soup& soup)
{
  if(!is_mesh_file_name(path))
    return detail::unsupported_extension(path);
  return detail::read_soup(path, lowercase_extension(path), soup);
}

/// reads the polygon mesh of the file `path` (.off, .obj, .ply or .stl) with the streaming
/// readers of mesh_reader.h, then builds it as CGAL's polygon soup to polygon mesh does
/// (every point a vertex, in file order; `Euler::add_face` in file order, which refuses a
/// face that would break the halfedge structure). Vertices keep the order of the file (STL:
/// equal points merged, in order of first appearance). On failure, the message names the
/// problem (the caller prefixes the file name).
template <class Mesh>
Failure read_mesh(const std::string& path, Mesh& mesh)
{
  Polygon_soup soup;
  const Failure f = read_soup_file(path, soup);
  if(f.failed())
    return f;
  return detail::build_mesh(soup, mesh);
}

/// The fallback default mesh: a curved, elliptic disk (a hexagonal lattice pushed onto
/// concentric circles, lifted onto an asymmetric bump), 1261 vertices and 2400 faces.
/// `Mesh` is a `CGAL::Surface_mesh`, as in the rest of this file.
template <class Mesh>
void make_curved_disk(Mesh& mesh)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::property_traits<
    typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type Point_3;
  const int rings = 20;
  const std::size_t side = std::size_t(2 * rings + 1);
  auto ring_of = [](int q, int r) { return (std::abs(q) + std::abs(r) + std::abs(q + r)) / 2; };
  auto inside = [&](int q, int r) {
    return q >= -rings && q <= rings && r >= -rings && r <= rings && ring_of(q, r) <= rings;
  };
  std::vector<vertex_descriptor> id(side * side);
  auto slot = [&](int q, int r) -> vertex_descriptor& { return id[std::size_t(q + rings) * side + std::size_t(r + rings)]; };

  for(int q = -rings; q <= rings; ++q)
    for(int r = -rings; r <= rings; ++r)
      if(inside(q, r))
      {
        // lattice point, moved radially so that lattice ring k lies on the circle k / rings
        const double x = q + 0.5 * r, y = 0.5 * std::sqrt(3.) * r;
        const int k = ring_of(q, r);
        const double scale = (k == 0) ? 0. : (double(k) / rings) / std::sqrt(x * x + y * y);
        const double px = 1.4 * scale * x, py = 0.9 * scale * y;
        const double pz = 0.45 * px * px - 0.25 * py * py + 0.2 * px * py + 0.15 * std::sin(3. * px);
        slot(q, r) = mesh.add_vertex(Point_3(px, py, pz));
      }
  for(int q = -rings; q < rings; ++q)
    for(int r = -rings; r < rings; ++r)
    {
      if(inside(q, r) && inside(q + 1, r) && inside(q, r + 1))
        CGAL::Euler::add_face(std::array<vertex_descriptor, 3>{slot(q, r), slot(q + 1, r), slot(q, r + 1)}, mesh);
      if(inside(q + 1, r) && inside(q + 1, r + 1) && inside(q, r + 1))
        CGAL::Euler::add_face(std::array<vertex_descriptor, 3>{slot(q + 1, r), slot(q + 1, r + 1), slot(q, r + 1)}, mesh);
    }
}

namespace detail {

// Faces that are not triangles: how many, and the first.
template <class Mesh>
Failure non_triangles(const Mesh& mesh)
{
  typedef typename boost::graph_traits<Mesh>::face_descriptor face_descriptor;
  Failure f;
  std::size_t non_triangles = 0, first_index = 0, first_degree = 0, index = 0;
  for(face_descriptor fd : faces(mesh))
  {
    const std::size_t degree = CGAL::halfedges_around_face(halfedge(fd, mesh), mesh).size();
    if(degree != 3 && non_triangles++ == 0)
    {
      first_index = index;
      first_degree = degree;
    }
    ++index;
  }
  if(non_triangles > 0)
  {
    f.code = SMP::ERROR_NON_TRIANGULAR_MESH;
    f.detail = std::to_string(non_triangles) + " of its " + std::to_string(num_faces(mesh)) +
               " faces are not triangles (the first is face " + std::to_string(first_index) + ", with " +
               std::to_string(first_degree) + " vertices); triangulate it first";
  }
  return f;
}

// All the vertices of the faces at one point: no extent at all (every face has zero area).
template <class Mesh>
Failure no_extent(const Mesh& mesh)
{
  Failure f;
  bool first = true, one_point = true;
  typename boost::property_traits<typename boost::property_map<Mesh, CGAL::vertex_point_t>::const_type>::value_type
    p0(0., 0., 0.);
  std::size_t used = 0;
  for(auto v : vertices(mesh))
  {
    if(halfedge(v, mesh) == boost::graph_traits<Mesh>::null_halfedge())  // in no face
      continue;
    ++used;
    if(first)
      p0 = get(CGAL::vertex_point, mesh, v);
    else if(get(CGAL::vertex_point, mesh, v) != p0)
      one_point = false;
    first = false;
  }
  if(one_point)
    f.detail = "all " + std::to_string(used) + " vertices of its faces coincide (at " + exact(CGAL::to_double(p0.x())) +
               " " + exact(CGAL::to_double(p0.y())) + " " + exact(CGAL::to_double(p0.z())) +
               "): the mesh has no extent";
  return f;
}

} // namespace detail

/// checks what the program needs before the library runs, with precise messages: faces, all
/// triangles, one connected component.
template <class Mesh>
Failure check_mesh(const Mesh& mesh)
{
  Failure f;
  if(faces(mesh).empty())
  {
    f.code = SMP::ERROR_EMPTY_MESH;
    f.detail = "it has no faces (" + std::to_string(num_vertices(mesh)) + " vertices)";
    return f;
  }
  f = detail::non_triangles(mesh);
  if(!f.failed())
    f = detail::no_extent(mesh);
  if(f.failed())
    return f;
  auto component = get(CGAL::dynamic_face_property_t<std::size_t>(), mesh);
  const std::size_t components = CGAL::Polygon_mesh_processing::connected_components(mesh, component);
  if(components > 1)
  {
    f.code = SMP::ERROR_NO_TOPOLOGICAL_DISC;
    f.detail = "it has " + std::to_string(components) +
               " connected components (the program needs one: extract it first)";
  }
  return f;
}

/// Coordinates scaled by a power of two (exact in floating point) while the library runs,
/// when their magnitude is so large that squared lengths overflow (above 2^60, about 1e18) or
/// so small that they underflow (below 2^-60): a conformal map does not depend on the scale,
/// and the UVs are normalized. `restore()` puts the input's coordinates back, exactly.
template <class Mesh>
class Scaled_coordinates
{
public:
  explicit Scaled_coordinates(Mesh& mesh) : m_mesh(mesh)
  {
    double largest = 0.;
    for(auto v : vertices(mesh))
    {
      const auto& p = mesh.point(v);
      largest = (std::max)({largest, std::abs(CGAL::to_double(p.x())), std::abs(CGAL::to_double(p.y())),
                            std::abs(CGAL::to_double(p.z()))});
    }
    if(!(largest > std::ldexp(1., 60) || (largest > 0. && largest < std::ldexp(1., -60))) || !std::isfinite(largest))
      return;
    m_exponent = -std::ilogb(largest);
    typedef typename boost::property_traits<typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type
      Point_3;
    for(auto v : vertices(mesh))
    {
      const Point_3& p = mesh.point(v);
      m_original.push_back(p);
      mesh.point(v) = Point_3(std::ldexp(CGAL::to_double(p.x()), m_exponent), std::ldexp(CGAL::to_double(p.y()), m_exponent),
                              std::ldexp(CGAL::to_double(p.z()), m_exponent));
    }
  }

  /// the power of two the coordinates were multiplied by (0: not scaled)
  int exponent() const { return m_exponent; }

  void restore()
  {
    std::size_t i = 0;
    for(auto v : vertices(m_mesh))
      if(i < m_original.size())
        m_mesh.point(v) = m_original[i++];
    m_original.clear();
  }

private:
  Mesh& m_mesh;
  int m_exponent = 0;
  std::vector<typename boost::property_traits<typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type>
    m_original;
};

/// sets `bhd` to a halfedge of the longest border of `tm` (a mesh, or a `Seam_mesh`, whose
/// seams are on its border) and `border_length` to the 3D length of that border: the
/// library's `main_border()`, whose rule for loops of equal length does not depend on
/// rounding (the same loop, from the same vertex, for the mesh moved, mirrored or scaled).
/// Fails for a closed mesh, which needs seams.
template <class TriangleMesh>
Failure find_longest_border(const TriangleMesh& tm,
                            typename boost::graph_traits<TriangleMesh>::halfedge_descriptor& bhd,
                            double& border_length)
{
  Failure f;
  const auto border = CGAL::Surface_mesh_parameterization::main_border(tm);
  if(border.first == boost::graph_traits<TriangleMesh>::null_halfedge())
  {
    f.detail = "the mesh is closed (it has no border): give seams that cut it open into a disk with"
               " --seams=FILE.selection.txt";
    return f;
  }
  bhd = border.first;
  border_length = CGAL::to_double(border.second);
  return f;
}

/// The first face whose doubled area `2A` is at most `threshold` times its longest squared
/// edge (the library's test of `ERROR_DEGENERATE_FACE`), to name it in the message; empty
/// when there is none.
template <class Mesh>
std::string find_degenerate_face(const Mesh& mesh, double threshold)
{
  std::size_t index = 0;
  for(auto fd : faces(mesh))
  {
    std::vector<std::size_t> ids;
    std::vector<std::array<double, 3> > p;
    for(auto v : CGAL::vertices_around_face(halfedge(fd, mesh), mesh))
    {
      const auto& q = mesh.point(v);
      ids.push_back(std::size_t(v));
      p.push_back({CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z())});
    }
    if(p.size() == 3)
    {
      auto sub = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
        return std::array<double, 3>{a[0] - b[0], a[1] - b[1], a[2] - b[2]};
      };
      auto sq = [](const std::array<double, 3>& a) { return a[0] * a[0] + a[1] * a[1] + a[2] * a[2]; };
      const std::array<double, 3> a = sub(p[1], p[0]), b = sub(p[2], p[0]), c = sub(p[2], p[1]);
      const std::array<double, 3> n = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
      const double longest2 = (std::max)({sq(a), sq(b), sq(c)});
      const double double_area = std::sqrt(sq(n));
      if(!(double_area > threshold * longest2) || !std::isfinite(double_area))
        return "face " + std::to_string(index) + " (vertices " + std::to_string(ids[0]) + " " +
               std::to_string(ids[1]) + " " + std::to_string(ids[2]) + ")";
    }
    ++index;
  }
  return std::string();
}

/// The first vertex with a non-finite coordinate, to name it in the message; empty when there
/// is none (CGAL's binary readers let NaN through; its text readers stop at it).
template <class Mesh>
std::string find_non_finite_vertex(const Mesh& mesh)
{
  for(auto v : vertices(mesh))
  {
    const auto& p = mesh.point(v);
    if(!std::isfinite(CGAL::to_double(p.x())) || !std::isfinite(CGAL::to_double(p.y())) ||
       !std::isfinite(CGAL::to_double(p.z())))
      return "vertex " + std::to_string(std::size_t(v));
  }
  return std::string();
}

} // namespace mbp_cli

#endif // MBP_CLI_MESH_INPUT_H
