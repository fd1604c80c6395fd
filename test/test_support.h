// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// Shared helpers of the test suites: generated meshes with known geometry, and the real meshes
// of the two tiers of tests:
//  - core tier (every clone): generated meshes, and CGAL's data meshes (Debian's
//    libcgal-demo, extracted into the build tree): core_mesh(name);
//  - extended tier: the project's meshes in MBP_SHARED_MESH_DIR (../shared/data/meshes by
//    default); shared_mesh(name). Extended test cases carry the Boost.Test label "extended"
//    (MBP_EXTENDED_TIER, MBP_TIERED_TEST_CASE): CTest runs them as the separate entry
//    SUITE_extended, reported as skipped when that folder is absent (test/CMakeLists.txt).

#ifndef MBP_TEST_SUPPORT_H
#define MBP_TEST_SUPPORT_H

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/number_type_config.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_report.h>

#include <boost/test/unit_test.hpp>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

// The decorator of an extended test case: BOOST_AUTO_TEST_CASE(name, MBP_EXTENDED_TIER).
#define MBP_EXTENDED_TIER * boost::unit_test::label("extended")

// A test case run on both tiers: `name` (core) and `name_extended` (extended), one body with
// the parameter `tier` (mbp_test::Tier) that chooses the meshes:
//   MBP_TIERED_TEST_CASE(some_property) { for(name : (tier == mbp_test::Tier::core) ? ... : ...) }
#define MBP_TIERED_TEST_CASE(name)                                                     \
  static void name##_body(mbp_test::Tier tier);                                        \
  BOOST_AUTO_TEST_CASE(name) { name##_body(mbp_test::Tier::core); }                    \
  BOOST_AUTO_TEST_CASE(name##_extended, MBP_EXTENDED_TIER)                             \
  {                                                                                    \
    name##_body(mbp_test::Tier::extended);                                             \
  }                                                                                    \
  static void name##_body(mbp_test::Tier tier)

namespace mbp_test {

// ---------------------------------------------------------------- real meshes

enum class Tier { core, extended };

inline bool file_exists(const std::string& path)
{
  std::ifstream in(path);
  return in.good();
}

// CGAL's data meshes ("" when the archive was not found at configure time).
inline std::string cgal_mesh_dir() { return MBP_CGAL_MESH_DIR; }
// The project's meshes of the extended tier (may be absent): the environment variable
// MBP_SHARED_MESH_DIR when set (test/extended_tier.sh sets it), else the configured folder.
inline std::string shared_mesh_dir()
{
  const char* dir = std::getenv("MBP_SHARED_MESH_DIR");
  return (dir != nullptr && *dir != '\0') ? std::string(dir) : std::string(MBP_SHARED_MESH_DIR);
}

// Path of a core-tier mesh, one of CGAL's data meshes. Fails the test (never skips) when it is
// missing: every clone has these.
inline std::string core_mesh(const std::string& name)
{
  BOOST_REQUIRE_MESSAGE(!cgal_mesh_dir().empty(),
                        "CGAL's data meshes were not found at configure time (MBP_CGAL_DATA_ARCHIVE: "
                        "Debian package libcgal-demo, installed by scripts/setup.sh)");
  const std::string path = cgal_mesh_dir() + "/" + name;
  BOOST_REQUIRE_MESSAGE(file_exists(path), "missing core test mesh " << path);
  return path;
}

// Path of an extended-tier mesh. Fails the test when it is missing: CTest only runs the
// extended tier when the folder is there.
inline std::string shared_mesh(const std::string& name)
{
  const std::string path = shared_mesh_dir() + "/" + name;
  BOOST_REQUIRE_MESSAGE(file_exists(path), "missing extended-tier mesh " << path
                        << " (the extended tier needs MBP_SHARED_MESH_DIR)");
  return path;
}

inline std::string tier_mesh(Tier tier, const std::string& name)
{
  return tier == Tier::core ? core_mesh(name) : shared_mesh(name);
}

// Transitional, for the suites not yet split into tiers: their real meshes are the core
// tier's. To be removed once no suite calls them.
inline std::string mesh_set() { return "cgal"; }
inline std::string require_mesh(const std::string& name) { return core_mesh(name); }

// The kernel of a mesh's points (what CGAL's parameterizers use for their UVs).
template <class Mesh>
using Kernel_of = typename CGAL::Kernel_traits<typename boost::property_traits<
  typename boost::property_map<Mesh, CGAL::vertex_point_t>::const_type>::value_type>::Kernel;

template <class Mesh>
void read_mesh(const std::string& path, Mesh& mesh)
{
  BOOST_REQUIRE_MESSAGE(CGAL::IO::read_polygon_mesh(path, mesh), "cannot read " << path);
  BOOST_REQUIRE(!faces(mesh).empty());
}

template <class Mesh>
typename boost::graph_traits<Mesh>::halfedge_descriptor longest_border(const Mesh& mesh)
{
  return CGAL::Polygon_mesh_processing::longest_border(mesh).first;
}

// ---------------------------------------------------------------- generated meshes

struct Soup
{
  std::vector<std::array<double, 3> > points;
  std::vector<std::vector<std::size_t> > faces;
};

// A tube of radius 1 around the z axis: `rings` + 1 rings of `spokes` vertices (vertex i of
// ring j at angle 2 pi i / spokes, height step j), two triangles per quad, turning
// counterclockwise seen from outside; open at both ends, or with `capped` closed above the
// last ring by a fan to one apex a step higher (the last vertex).
inline Soup tube(int spokes, int rings, double step, bool capped)
{
  Soup s;
  for(int j = 0; j <= rings; ++j)
    for(int i = 0; i < spokes; ++i)
      s.points.push_back({{std::cos(2. * CGAL_PI * i / spokes), std::sin(2. * CGAL_PI * i / spokes), step * j}});
  auto id = [spokes](int i, int j) { return std::size_t(j * spokes + (i % spokes)); };
  for(int j = 0; j < rings; ++j)
    for(int i = 0; i < spokes; ++i)
    {
      s.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      s.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  if(capped)
  {
    s.points.push_back({{0., 0., step * (rings + 1)}});
    for(int i = 0; i < spokes; ++i)
      s.faces.push_back({id(i, rings), id(i + 1, rings), s.points.size() - 1});
  }
  return s;
}

// A polar grid of the disk of radius 1: the center (vertex 0), `rings` rings of `spokes`
// vertices at radius k/rings, and one extra vertex in the middle of every quad between two
// rings, which is split into four triangles. With `spokes` divisible by 4 the mesh is
// symmetric under x -> -x and y -> -y. Then x is scaled by `a`, y by `b`, and z = height(x, y).
inline Soup polar_disk(int rings, int spokes, double a = 1., double b = 1.,
                       const std::function<double(double, double)>& height = nullptr)
{
  Soup s;
  auto add = [&](double r, double angle) {
    const double x = a * r * std::cos(angle), y = b * r * std::sin(angle);
    s.points.push_back({x, y, height ? height(x, y) : 0.});
    return s.points.size() - 1;
  };
  add(0., 0.);
  std::vector<std::vector<std::size_t> > ring(static_cast<std::size_t>(rings) + 1);
  ring[0].assign(static_cast<std::size_t>(spokes), 0);
  const double step = 2. * CGAL_PI / spokes;
  for(int k = 1; k <= rings; ++k)
    for(int j = 0; j < spokes; ++j)
      ring[static_cast<std::size_t>(k)].push_back(add(double(k) / rings, j * step));
  for(int j = 0; j < spokes; ++j)
  {
    const std::size_t jn = static_cast<std::size_t>((j + 1) % spokes), jj = static_cast<std::size_t>(j);
    s.faces.push_back({0, ring[1][jj], ring[1][jn]});
    for(int k = 1; k < rings; ++k)
    {
      const std::size_t m = add((k + 0.5) / rings, (j + 0.5) * step);
      const std::size_t A = ring[static_cast<std::size_t>(k)][jj], B = ring[static_cast<std::size_t>(k) + 1][jj];
      const std::size_t C = ring[static_cast<std::size_t>(k) + 1][jn], D = ring[static_cast<std::size_t>(k)][jn];
      s.faces.push_back({A, B, m});
      s.faces.push_back({B, C, m});
      s.faces.push_back({C, D, m});
      s.faces.push_back({D, A, m});
    }
  }
  return s;
}

// A quasi-uniform disk: the triangular lattice inside the hexagon of `rings` rings, each
// lattice ring pushed radially onto the circle of radius k/rings. Every interior vertex has
// degree 6; the mesh is symmetric under x -> -x and y -> -y. Then x is scaled by `a`, y by `b`.
// Vertex 0 is the center.
inline Soup hex_disk(int rings, double a = 1., double b = 1.)
{
  Soup s;
  std::vector<std::vector<long> > id(static_cast<std::size_t>(2 * rings + 1),
                                     std::vector<long>(static_cast<std::size_t>(2 * rings + 1), -1));
  auto ring_of = [](int q, int r) { return (std::abs(q) + std::abs(r) + std::abs(q + r)) / 2; };
  auto index = [&](int q, int r) -> long& {
    return id[static_cast<std::size_t>(q + rings)][static_cast<std::size_t>(r + rings)];
  };
  auto add = [&](int q, int r) {
    const double x = q + 0.5 * r, y = 0.5 * std::sqrt(3.) * r;
    const int k = ring_of(q, r);
    const double scale = (k == 0) ? 0. : (double(k) / rings) / std::sqrt(x * x + y * y);
    index(q, r) = static_cast<long>(s.points.size());
    s.points.push_back({a * scale * x, b * scale * y, 0.});
  };
  add(0, 0);
  for(int q = -rings; q <= rings; ++q)
    for(int r = -rings; r <= rings; ++r)
      if((q != 0 || r != 0) && ring_of(q, r) <= rings)
        add(q, r);
  auto inside = [&](int q, int r) {
    return q >= -rings && q <= rings && r >= -rings && r <= rings && ring_of(q, r) <= rings;
  };
  for(int q = -rings; q < rings; ++q)
    for(int r = -rings; r < rings; ++r)
    {
      if(inside(q, r) && inside(q + 1, r) && inside(q, r + 1))
        s.faces.push_back({std::size_t(index(q, r)), std::size_t(index(q + 1, r)), std::size_t(index(q, r + 1))});
      if(inside(q + 1, r) && inside(q + 1, r + 1) && inside(q, r + 1))
        s.faces.push_back({std::size_t(index(q + 1, r)), std::size_t(index(q + 1, r + 1)), std::size_t(index(q, r + 1))});
    }
  return s;
}

// A flat grid of step 1/n over [0, cells_x/n] x [0, cells_y/n], every square split along the
// same diagonal, without the squares (i, j) for which `removed(i, j)` holds. The removed
// squares must leave a disk (cut a notch from the border, not a hole).
template <class Removed>
Soup notched_grid(int n, int cells_x, int cells_y, const Removed& removed)
{
  Soup s;
  std::vector<std::vector<long> > id(static_cast<std::size_t>(cells_x + 1),
                                     std::vector<long>(static_cast<std::size_t>(cells_y + 1), -1));
  auto vertex = [&](int i, int j) {
    long& v = id[std::size_t(i)][std::size_t(j)];
    if(v < 0)
    {
      v = static_cast<long>(s.points.size());
      s.points.push_back({double(i) / n, double(j) / n, 0.});
    }
    return std::size_t(v);
  };
  for(int i = 0; i < cells_x; ++i)
    for(int j = 0; j < cells_y; ++j)
      if(!removed(i, j))
      {
        const std::size_t a = vertex(i, j), b = vertex(i + 1, j), c = vertex(i + 1, j + 1), d = vertex(i, j + 1);
        s.faces.push_back({a, b, c});
        s.faces.push_back({a, c, d});
      }
  return s;
}

// A flat L-shaped domain, [0,2]^2 minus (1,2]^2, on a grid of step 1/n: star-shaped from the
// points near its reentrant corner, not from the others.
inline Soup l_shape(int n = 8)
{
  return notched_grid(n, 2 * n, 2 * n, [n](int i, int j) { return i >= n && j >= n; });
}

// A flat C-shaped domain, [0,3]^2 minus [1,3] x [1,2]: from any point of its left bar, the
// tips of its arms are hidden.
inline Soup c_shape(int n = 6)
{
  return notched_grid(n, 3 * n, 3 * n, [n](int i, int j) { return i >= n && j >= n && j < 2 * n; });
}

// A curved, asymmetric disk: the polar grid lifted onto a smooth bump.
inline Soup bumpy_disk(int rings = 8, int spokes = 24)
{
  return polar_disk(rings, spokes, 1.3, 0.9, [](double x, double y) {
    return 0.35 * x * x - 0.2 * y + 0.25 * x * y + 0.1 * std::sin(3. * x);
  });
}

// A torus (grid of n x m quads split in two) with one face removed: open, genus 1.
inline Soup punctured_torus(int n = 12, int m = 8)
{
  Soup s;
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < m; ++j)
    {
      const double u = 2. * CGAL_PI * i / n, v = 2. * CGAL_PI * j / m;
      s.points.push_back({(2. + 0.7 * std::cos(v)) * std::cos(u), (2. + 0.7 * std::cos(v)) * std::sin(u),
                          0.7 * std::sin(v)});
    }
  auto id = [&](int i, int j) { return static_cast<std::size_t>(((i + n) % n) * m + (j + m) % m); };
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < m; ++j)
    {
      s.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      if(i != 0 || j != 0)
        s.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return s;
}

// The soup without the faces incident to the given vertices, and without those vertices
// (indices are compacted).
inline Soup remove_vertices(const Soup& soup, const std::vector<std::size_t>& removed)
{
  std::vector<bool> gone(soup.points.size(), false);
  for(std::size_t v : removed)
    gone[v] = true;
  std::vector<std::size_t> new_index(soup.points.size(), 0);
  Soup out;
  for(std::size_t i = 0; i < soup.points.size(); ++i)
    if(!gone[i])
    {
      new_index[i] = out.points.size();
      out.points.push_back(soup.points[i]);
    }
  for(const auto& f : soup.faces)
  {
    bool keep = true;
    for(std::size_t v : f)
      keep = keep && !gone[v];
    if(!keep)
      continue;
    std::vector<std::size_t> g;
    for(std::size_t v : f)
      g.push_back(new_index[v]);
    out.faces.push_back(g);
  }
  return out;
}

// The polar grid (curved) with two square holes: the four faces around the middle vertex of
// two quads are removed.
inline Soup disk_with_two_holes()
{
  const int rings = 12, spokes = 32;
  const Soup s = polar_disk(rings, spokes, 1.2, 1., [](double x, double y) { return 0.2 * x * y; });
  auto mid = [&](int k, int j) { return std::size_t(1 + rings * spokes + j * (rings - 1) + (k - 1)); };
  return remove_vertices(s, {mid(4, 3), mid(8, 20)});
}

template <class Mesh>
void soup_to_mesh(const Soup& soup, Mesh& mesh)
{
  typedef typename boost::property_traits<
    typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type Point_3;
  std::vector<Point_3> points;
  for(const auto& p : soup.points)
    points.emplace_back(p[0], p[1], p[2]);
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, soup.faces, mesh);
  BOOST_REQUIRE(CGAL::is_valid_polygon_mesh(mesh));
}


// ---------------------------------------------------------------- the reports (issue 21)
// Helpers of the suites that read the reports of the package's parameterizers
// (test_measured_border, test_conformal, test_conformal_border, test_real_meshes).
// ---------------------------------------------------------------- helpers shared by the suites
// (issue 21, item 6: helpers that several suites used to copy)

// Deterministic pseudo-random numbers in [0, 1) (the same sequence on every platform).
struct Lcg
{
  std::uint32_t state;
  explicit Lcg(std::uint32_t seed) : state(seed) {}
  double operator()()
  {
    state = state * 1664525u + 1013904223u;
    return double(state >> 8) / double(1u << 24);
  }
};

// A map of the points of a soup (a similarity, a rigid motion...).
typedef std::function<std::array<double, 3>(const std::array<double, 3>&)> Transform;

inline Transform scaling(double factor)
{
  return [factor](const std::array<double, 3>& p) {
    return std::array<double, 3>{{p[0] * factor, p[1] * factor, p[2] * factor}};
  };
}

// A rotation by `angle` about the axis (1, 2, 3) and a translation.
inline Transform rigid_motion(double angle, const std::array<double, 3>& translation)
{
  const Eigen::Matrix3d R = Eigen::AngleAxisd(angle, Eigen::Vector3d(1., 2., 3.).normalized()).toRotationMatrix();
  return [R, translation](const std::array<double, 3>& p) {
    const Eigen::Vector3d q = R * Eigen::Vector3d(p[0], p[1], p[2]);
    return std::array<double, 3>{{q.x() + translation[0], q.y() + translation[1], q.z() + translation[2]}};
  };
}

// The mesh of a soup, its points mapped by `transform` when given.
template <class Mesh>
Mesh make_mesh(const Soup& soup, const Transform& transform = nullptr)
{
  Soup s = soup;
  if(transform)
    for(auto& p : s.points)
      p = transform(p);
  Mesh m;
  soup_to_mesh(s, m);
  return m;
}

// A new UV property map of a Surface_mesh, every UV (-7, -7) (a value no parameterizer writes).
template <class Mesh>
typename Mesh::template Property_map<typename boost::graph_traits<Mesh>::vertex_descriptor,
                                     typename Kernel_of<Mesh>::Point_2>
new_uv_map(Mesh& m, const std::string& name)
{
  typedef typename Kernel_of<Mesh>::Point_2 Point_2;
  return m.template add_property_map<typename boost::graph_traits<Mesh>::vertex_descriptor, Point_2>(
    name, Point_2(-7, -7)).first;
}

// A new vertex distance map of a Surface_mesh, every distance -1 (a value no distance map writes).
template <class Mesh>
typename Mesh::template Property_map<typename boost::graph_traits<Mesh>::vertex_descriptor, double>
new_distance_map(Mesh& m, const std::string& name)
{
  return m.template add_property_map<typename boost::graph_traits<Mesh>::vertex_descriptor, double>(name, -1.).first;
}

// The vertices of the border loop of `bhd`, from source(bhd) on: vertex k is the source of
// the k-th halfedge of the loop (the order of the reports' per-border-vertex fields).
template <class Mesh>
std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor>
border_loop_vertices(const Mesh& m, typename boost::graph_traits<Mesh>::halfedge_descriptor bhd)
{
  std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> loop;
  for(auto h : CGAL::halfedges_around_face(bhd, m))
    loop.push_back(source(h, m));
  return loop;
}

// The vertex at `position` in the range vertices(m) (how a report names a vertex, e.g. its
// center).
template <class Mesh>
typename boost::graph_traits<Mesh>::vertex_descriptor vertex_at_position(const Mesh& m, std::size_t position)
{
  BOOST_REQUIRE_LT(position, static_cast<std::size_t>(num_vertices(m)));
  auto it = vertices(m).begin();
  for(std::size_t k = 0; k < position; ++k)
    ++it;
  return *it;
}

// A border parameterizer of the package (Border_parameterizer_3: Measured_border_ or
// Conformal_border_parameterizer_3) that writes the report of each of its calls into
// `*report`: CGAL's fixed border parameterizers call the copy they hold without a report,
// so this is how a test reads the report of the border step run inside CGAL's DCP (copies
// share the pointer, which the test owns; the package's parameterizers share nothing).
template <class Border>
class Reporting_border : public Border
{
public:
  explicit Reporting_border(CGAL::Surface_mesh_parameterization::Parameterization_report* report = nullptr,
                            const Border& border = Border())
    : Border(border), m_report(report)
  { }

  template <class VertexUVmap, class VertexIndexMap, class VertexParameterizedMap>
  CGAL::Surface_mesh_parameterization::Error_code
  parameterize(const typename Border::Triangle_mesh& mesh, typename Border::halfedge_descriptor bhd,
               VertexUVmap uvmap, VertexIndexMap vimap, VertexParameterizedMap vpmap)
  {
    return Border::parameterize(mesh, bhd, uvmap, vimap, vpmap, m_report);
  }

private:
  CGAL::Surface_mesh_parameterization::Parameterization_report* m_report;
};

// The vertices of the border loop of `h` as indices (a Surface_mesh's), sorted: the loop as a
// set, to compare loops found from different halfedges.
template <class Mesh>
std::vector<std::size_t> sorted_loop(const Mesh& m, typename boost::graph_traits<Mesh>::halfedge_descriptor h)
{
  std::vector<std::size_t> loop;
  for(auto b : CGAL::halfedges_around_face(h, m))
    loop.push_back(std::size_t(source(b, m)));
  std::sort(loop.begin(), loop.end());
  return loop;
}

// The border loops of a mesh: one halfedge each, and how often the loop visits its most
// visited vertex (more than once: the loop goes through a pinched vertex).
template <class Mesh>
std::vector<std::pair<typename boost::graph_traits<Mesh>::halfedge_descriptor, int> > border_loops(const Mesh& m)
{
  typedef typename boost::graph_traits<Mesh>::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  std::vector<std::pair<halfedge_descriptor, int> > loops;
  std::set<halfedge_descriptor> seen;
  for(halfedge_descriptor h : halfedges(m))
    if(is_border(h, m) && seen.insert(h).second)
    {
      std::map<vertex_descriptor, int> visits;
      int most = 0;
      for(halfedge_descriptor b : CGAL::halfedges_around_face(h, m))
      {
        seen.insert(b);
        most = (std::max)(most, ++visits[source(b, m)]);
      }
      loops.emplace_back(h, most);
    }
  return loops;
}

// The flat square [0,1]^2 on a grid of n x n squares, each split along the same diagonal:
// every triangle is right-angled.
inline Soup square_grid(int n)
{
  return notched_grid(n, n, n, [](int, int) { return false; });
}

// The spiral ramp: a strip of 1.6 turns, flat to first order, rising slowly; its conformal
// border overlaps itself.
inline Soup spiral_ramp(int cols = 120, int rows = 5)
{
  Soup s;
  for(int i = 0; i <= cols; ++i)
    for(int j = 0; j <= rows; ++j)
    {
      const double theta = 3.2 * CGAL_PI * i / cols, r = 1. + double(j) / rows;
      s.points.push_back({{r * std::cos(theta), r * std::sin(theta), 0.08 * theta}});
    }
  auto id = [rows](int i, int j) { return std::size_t(i * (rows + 1) + j); };
  for(int i = 0; i < cols; ++i)
    for(int j = 0; j < rows; ++j)
    {
      s.faces.push_back({id(i, j), id(i + 1, j + 1), id(i + 1, j)});
      s.faces.push_back({id(i, j), id(i, j + 1), id(i + 1, j + 1)});
    }
  return s;
}

// A triangle mesh as plain arrays (the kernels of fast marching and straightest geodesics
// take them): points, faces, and the main border loop when it is known.
struct Arrays
{
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<int, 3> > faces;
  std::vector<int> border;
};

inline Arrays arrays_from_soup(const Soup& s)
{
  Arrays a;
  for(const auto& p : s.points)
    a.points.emplace_back(p[0], p[1], p[2]);
  for(const auto& f : s.faces)
    a.faces.push_back({{int(f[0]), int(f[1]), int(f[2])}});
  return a;
}

} // namespace mbp_test

#endif // MBP_TEST_SUPPORT_H
