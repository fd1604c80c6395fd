// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// compute_disk_seams(): the cut leaves a disk (Euler characteristic 1, one border loop, one
// piece, counted on CGAL's Seam_mesh), the cut graph has 2g independent loops, cones sit where
// the scale factor is extreme, results are deterministic and invariant under rigid motions,
// the cut mesh flattens without flipped faces, shortening shortens, and bad input gets a
// named error; the report names cones and problem elements by their position in vertices(tm)
// and faces(tm), and the cone placement factorizes once. Generated meshes: an icosphere, ellipsoids, a torus, a double torus, a
// cylinder, a disk with two holes, a punctured torus. The extended tier runs every closed,
// holed and higher-genus mesh of the project's meshes.

#include <boost/test/unit_test.hpp>

#include "test_support.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Seam_mesh.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>

#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <CGAL/Surface_mesh_parameterization/Conformal_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/compute_disk_seams.h>
#include <CGAL/Surface_mesh_parameterization/measure_quality.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <map>
#include <set>
#include <string>
#include <vector>

BOOST_AUTO_TEST_SUITE(seams)

namespace SMP = CGAL::Surface_mesh_parameterization;
typedef CGAL::Simple_cartesian<double>                        K;
typedef CGAL::Surface_mesh<K::Point_3>                        Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor          vertex_descriptor;
typedef boost::graph_traits<Mesh>::edge_descriptor            edge_descriptor;
typedef Mesh::Property_map<edge_descriptor, bool>             Seam_edge_map;
typedef Mesh::Property_map<vertex_descriptor, bool>           Seam_vertex_map;
typedef CGAL::Seam_mesh<Mesh, Seam_edge_map, Seam_vertex_map> Seam_mesh;
typedef SMP::Disk_seams_report                                Report;

namespace {

// ---------------------------------------------------------------- generated meshes

// The icosahedron subdivided `levels` times, on the unit sphere, then mapped by `warp`.
mbp_test::Soup icosphere(int levels, const std::function<std::array<double, 3>(std::array<double, 3>)>& warp = nullptr)
{
  mbp_test::Soup s;
  const double t = 0.5 * (1. + std::sqrt(5.));
  const double ico[12][3] = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                             {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  auto add = [&s](std::array<double, 3> p) {
    const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    s.points.push_back({p[0] / r, p[1] / r, p[2] / r});
    return s.points.size() - 1;
  };
  for(const auto& p : ico)
    add({p[0], p[1], p[2]});
  s.faces = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
             {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
             {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
  for(int level = 0; level < levels; ++level)
  {
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> middle;
    auto mid = [&](std::size_t a, std::size_t b) {
      const auto key = std::make_pair((std::min)(a, b), (std::max)(a, b));
      const auto it = middle.find(key);
      if(it != middle.end())
        return it->second;
      const std::array<double, 3> pa = s.points[a], pb = s.points[b];
      return middle[key] = add({pa[0] + pb[0], pa[1] + pb[1], pa[2] + pb[2]});
    };
    std::vector<std::vector<std::size_t> > faces;
    for(const auto& f : s.faces)
    {
      const std::size_t a = mid(f[0], f[1]), b = mid(f[1], f[2]), c = mid(f[2], f[0]);
      faces.push_back({f[0], a, c});
      faces.push_back({f[1], b, a});
      faces.push_back({f[2], c, b});
      faces.push_back({a, b, c});
    }
    s.faces = faces;
  }
  if(warp)
    for(auto& p : s.points)
      p = warp(p);
  return s;
}

// A deterministic bump field: no symmetry, so no exact ties between vertices.
std::array<double, 3> lumpy(std::array<double, 3> p)
{
  const double r = 1. + 0.15 * std::sin(3. * p[0] + 1.) * std::cos(2. * p[1] - 0.5) + 0.1 * p[2] * p[0];
  return {1.3 * r * p[0], r * p[1], 0.8 * r * p[2]};
}

// Vertex (i, j) of an n x m grid on a torus (radii R, r), quads split along one diagonal;
// `bumps` adds an asymmetric wave.
mbp_test::Soup torus(int n, int m, double R = 2., double r = 0.7, bool bumps = false)
{
  mbp_test::Soup s;
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < m; ++j)
    {
      const double u = 2. * CGAL_PI * i / n, v = 2. * CGAL_PI * j / m;
      const double rr = r * (bumps ? 1. + 0.2 * std::sin(2. * u + 0.3) * std::cos(v - 0.7) : 1.);
      s.points.push_back({(R + rr * std::cos(v)) * std::cos(u), (R + rr * std::cos(v)) * std::sin(u), rr * std::sin(v)});
    }
  auto id = [&](int i, int j) { return static_cast<std::size_t>(((i + n) % n) * m + (j + m) % m); };
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < m; ++j)
    {
      s.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      s.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return s;
}

// A double torus: the connected sum of a torus and its mirror image. The one-ring of the
// outermost vertex of each is removed, and the two hexagonal holes are joined by a short tube.
mbp_test::Soup double_torus(int n = 24, int m = 12)
{
  const mbp_test::Soup a = torus(n, m);
  mbp_test::Soup s = mbp_test::remove_vertices(a, {0});  // vertex (0, 0) at (2.7, 0, 0)
  const std::size_t half = s.points.size();
  const std::vector<std::vector<std::size_t> > faces = s.faces;
  for(std::size_t i = 0; i < half; ++i)
    s.points.push_back({6. - s.points[i][0], s.points[i][1], s.points[i][2]});  // mirror at x = 3
  for(const auto& f : faces)
    s.faces.push_back({f[0] + half, f[2] + half, f[1] + half});
  // the hole: the neighbours of the removed vertex (0, 0), in order around it (indices - 1)
  const int around[6][2] = {{0, -1}, {1, 0}, {1, 1}, {0, 1}, {-1, 0}, {-1, -1}};
  std::size_t ring[6];
  for(int k = 0; k < 6; ++k)
    ring[k] = static_cast<std::size_t>(((around[k][0] + n) % n) * m + (around[k][1] + m) % m) - 1;
  for(int k = 0; k < 6; ++k)
  {
    const std::size_t p = ring[k], q = ring[(k + 1) % 6];
    s.faces.push_back({p, q, q + half});
    s.faces.push_back({p, q + half, p + half});
  }
  std::vector<K::Point_3> points;
  for(const auto& p : s.points)
    points.emplace_back(p[0], p[1], p[2]);
  CGAL::Polygon_mesh_processing::orient_polygon_soup(points, s.faces);
  s.points.clear();
  for(const K::Point_3& p : points)
    s.points.push_back({p.x(), p.y(), p.z()});
  return s;
}

// An open cylinder of n x m quads (two border loops), each split in two.
mbp_test::Soup cylinder(int n = 24, int m = 10)
{
  mbp_test::Soup s;
  for(int j = 0; j <= m; ++j)
    for(int i = 0; i < n; ++i)
    {
      const double u = 2. * CGAL_PI * (i + 0.5 * (j % 2)) / n;
      s.points.push_back({std::cos(u), std::sin(u), 0.25 * j});
    }
  auto id = [&](int i, int j) { return static_cast<std::size_t>(j * n + (i + n) % n); };
  for(int j = 0; j < m; ++j)
    for(int i = 0; i < n; ++i)
    {
      s.faces.push_back({id(i, j), id(i + 1, j), id(i + (j % 2), j + 1)});
      s.faces.push_back({id(i + 1, j), id(i + 1 + (j % 2), j + 1), id(i + (j % 2), j + 1)});
    }
  return s;
}

// ---------------------------------------------------------------- seams and checks

struct Seams
{
  Seam_edge_map edges;
  Seam_vertex_map vertices;
  Report report;
  SMP::Error_code status = SMP::ERROR_WRONG_PARAMETER;
};

Seams compute(Mesh& mesh, const SMP::Disk_seams_options& options = SMP::Disk_seams_options())
{
  Seams s;
  s.edges = mesh.add_property_map<edge_descriptor, bool>("e:seam", false).first;
  s.vertices = mesh.add_property_map<vertex_descriptor, bool>("v:seam", false).first;
  s.status = SMP::compute_disk_seams(mesh, s.edges, s.vertices, options, &s.report);
  return s;
}

// The vertex at `position` in vertices(mesh) (how the report names vertices), and back.
vertex_descriptor vertex_at(const Mesh& mesh, std::size_t position)
{
  BOOST_REQUIRE_LT(position, num_vertices(mesh));
  return *std::next(vertices(mesh).begin(), static_cast<std::ptrdiff_t>(position));
}

std::size_t position_of(const Mesh& mesh, vertex_descriptor v)
{
  return static_cast<std::size_t>(std::distance(vertices(mesh).begin(), std::find(vertices(mesh).begin(),
                                                                                  vertices(mesh).end(), v)));
}

bool is_cone(const Mesh& mesh, const Seams& s, vertex_descriptor v)
{
  const std::vector<std::size_t>& cones = s.report.cones;
  return std::find(cones.begin(), cones.end(), position_of(mesh, v)) != cones.end();
}

std::set<std::size_t> seam_set(const Mesh& mesh, const Seams& s)
{
  std::set<std::size_t> set;
  for(edge_descriptor e : edges(mesh))
    if(get(s.edges, e))
      set.insert(std::size_t(e));
  return set;
}

// The topology of the cut mesh, counted on CGAL's Seam_mesh with its own iterators.
struct Cut_topology
{
  long chi = 0;
  std::size_t border_loops = 0, components = 0;
};

Cut_topology cut_topology(const Seam_mesh& sm)
{
  typedef boost::graph_traits<Seam_mesh>::halfedge_descriptor halfedge_descriptor;
  typedef boost::graph_traits<Seam_mesh>::face_descriptor     face_descriptor;
  Cut_topology t;
  const long V = static_cast<long>(std::distance(vertices(sm).begin(), vertices(sm).end()));
  const long H = static_cast<long>(std::distance(halfedges(sm).begin(), halfedges(sm).end()));
  const long F = static_cast<long>(std::distance(faces(sm).begin(), faces(sm).end()));
  t.chi = V - H / 2 + F;
  std::set<halfedge_descriptor> walked;
  for(halfedge_descriptor h : halfedges(sm))
    if(is_border(h, sm) && walked.insert(h).second)
    {
      ++t.border_loops;
      for(halfedge_descriptor b : CGAL::halfedges_around_face(h, sm))
        walked.insert(b);
    }
  std::set<face_descriptor> seen;
  for(face_descriptor f : faces(sm))
  {
    if(!seen.insert(f).second)
      continue;
    ++t.components;
    std::vector<face_descriptor> stack(1, f);
    while(!stack.empty())
    {
      const face_descriptor g = stack.back();
      stack.pop_back();
      for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(g, sm), sm))
        if(!is_border(opposite(h, sm), sm) && seen.insert(face(opposite(h, sm), sm)).second)
          stack.push_back(face(opposite(h, sm), sm));
    }
  }
  return t;
}

// Checks the cut: a disk on CGAL's Seam_mesh, and the seam maps consistent with the report.
void check_disk(const Mesh& mesh, const Seams& s)
{
  BOOST_REQUIRE_EQUAL(s.status, SMP::OK);
  std::size_t count = 0;
  double length = 0.;
  for(edge_descriptor e : edges(mesh))
    if(get(s.edges, e))
    {
      ++count;
      BOOST_CHECK(!is_border(e, mesh));
      BOOST_CHECK(get(s.vertices, source(halfedge(e, mesh), mesh)) && get(s.vertices, target(halfedge(e, mesh), mesh)));
      length += std::sqrt(CGAL::squared_distance(mesh.point(source(halfedge(e, mesh), mesh)),
                                                 mesh.point(target(halfedge(e, mesh), mesh))));
    }
  BOOST_CHECK_EQUAL(count, s.report.number_of_seam_edges);
  BOOST_CHECK_CLOSE(length + 1., s.report.seam_length + 1., 1e-9);
  for(std::size_t c : s.report.cones)
    BOOST_CHECK(get(s.vertices, vertex_at(mesh, c)));
  Seam_mesh sm(mesh, s.edges, s.vertices);
  sm.set_seam_edges_number(s.report.number_of_seam_edges);
  const Cut_topology t = cut_topology(sm);
  BOOST_CHECK_EQUAL(t.chi, 1);
  BOOST_CHECK_EQUAL(t.border_loops, 1u);
  BOOST_CHECK_EQUAL(t.components, 1u);
}

// The cycle rank of the graph of seam edges and border edges, E - V + (connected pieces).
long cut_graph_cycle_rank(const Mesh& mesh, const Seams& s)
{
  std::map<vertex_descriptor, vertex_descriptor> parent;
  std::function<vertex_descriptor(vertex_descriptor)> root = [&](vertex_descriptor v) {
    return parent[v] == v ? v : parent[v] = root(parent[v]);
  };
  long E = 0;
  for(edge_descriptor e : edges(mesh))
    if(get(s.edges, e) || is_border(e, mesh))
    {
      ++E;
      const vertex_descriptor a = source(halfedge(e, mesh), mesh), b = target(halfedge(e, mesh), mesh);
      parent.emplace(a, a);
      parent.emplace(b, b);
    }
  long pieces = static_cast<long>(parent.size());
  for(edge_descriptor e : edges(mesh))
    if(get(s.edges, e) || is_border(e, mesh))
    {
      const vertex_descriptor a = root(source(halfedge(e, mesh), mesh)), b = root(target(halfedge(e, mesh), mesh));
      if(a != b)
      {
        parent[a] = b;
        --pieces;
      }
    }
  return E - static_cast<long>(parent.size()) + pieces;
}

// Flattens the cut mesh and checks it: no flipped face, one-to-one.
SMP::Parameterization_quality flatten_and_check(const Mesh& mesh, const Seams& s)
{
  Seam_mesh sm(mesh, s.edges, s.vertices);
  sm.set_seam_edges_number(s.report.number_of_seam_edges);
  const auto bhd = CGAL::Polygon_mesh_processing::longest_border(sm).first;
  auto uv = get(CGAL::dynamic_vertex_property_t<K::Point_2>(), sm);
  const SMP::Conformal_parameterizer_3<Seam_mesh, SMP::Conformal_border> parameterizer;
  const SMP::Error_code status = SMP::parameterize(sm, parameterizer, bhd, uv);
  BOOST_REQUIRE_MESSAGE(status == SMP::OK, SMP::get_measured_error_message(status));
  const SMP::Parameterization_quality q = SMP::measure_quality(sm, faces(sm), uv);
  BOOST_CHECK_EQUAL(q.flipped_faces, 0u);
  BOOST_CHECK(SMP::is_one_to_one_uv_map(sm, faces(sm), uv));
  return q;
}

} // namespace

// ---------------------------------------------------------------- closed surfaces

BOOST_AUTO_TEST_CASE(sphere_is_cut_into_a_disk_through_the_default_cones)
{
  Mesh mesh = mbp_test::make_mesh<Mesh>(icosphere(3));
  const Seams s = compute(mesh);
  check_disk(mesh, s);
  BOOST_CHECK_EQUAL(s.report.genus, 0);
  BOOST_CHECK_EQUAL(s.report.number_of_loops, 0);
  BOOST_CHECK_EQUAL(s.report.cones.size(), std::size_t(SMP::Disk_seams_options::default_number_of_cones));
  // on a sphere the cut is a tree: one vertex more than edges
  std::size_t seam_vertices = 0;
  for(vertex_descriptor v : vertices(mesh))
    seam_vertices += get(s.vertices, v) ? 1 : 0;
  BOOST_CHECK_EQUAL(seam_vertices, s.report.number_of_seam_edges + 1);
  BOOST_CHECK_EQUAL(cut_graph_cycle_rank(mesh, s), 0);
  // every leaf of the tree is a cone (dangling trees are pruned)
  for(vertex_descriptor v : vertices(mesh))
  {
    int degree = 0;
    for(auto h : CGAL::halfedges_around_target(v, mesh))
      degree += get(s.edges, edge(h, mesh)) ? 1 : 0;
    if(degree == 1)
      BOOST_CHECK(is_cone(mesh, s, v));
  }
  // one factorization; a back-substitution for the first cone, for the scale factor, and for
  // the Green function of each other cone
  BOOST_CHECK_EQUAL(s.report.statistics.factorizations, 1);
  BOOST_CHECK_EQUAL(s.report.statistics.back_substitutions, static_cast<int>(s.report.cones.size()) + 1);
  flatten_and_check(mesh, s);
}

BOOST_AUTO_TEST_CASE(closed_genus_0_gets_at_least_two_cones)
{
  Mesh mesh = mbp_test::make_mesh<Mesh>(icosphere(2, lumpy));
  SMP::Disk_seams_options options;
  options.number_of_cones = 0;
  const Seams s = compute(mesh, options);
  check_disk(mesh, s);
  BOOST_CHECK_EQUAL(s.report.cones.size(), 2u);
  options.number_of_cones = 7;
  Mesh other = mbp_test::make_mesh<Mesh>(icosphere(2, lumpy));
  const Seams t = compute(other, options);
  check_disk(other, t);
  BOOST_CHECK_EQUAL(t.report.cones.size(), 7u);
}

// On an elongated ellipsoid the curvature gathers at the two tips of the long axis, so the
// scale factor is most extreme there: the first two cones are the two tips.
BOOST_AUTO_TEST_CASE(first_cones_are_the_tips_of_an_ellipsoid)
{
  Mesh mesh = mbp_test::make_mesh<Mesh>(icosphere(3, [](std::array<double, 3> p) {
    return std::array<double, 3>{3. * p[0], p[1] + 0.01 * p[0], 0.9 * p[2]};
  }));
  SMP::Disk_seams_options options;
  options.number_of_cones = 2;
  const Seams s = compute(mesh, options);
  check_disk(mesh, s);
  BOOST_REQUIRE_EQUAL(s.report.cones.size(), 2u);
  const double x0 = mesh.point(vertex_at(mesh, s.report.cones[0])).x();
  const double x1 = mesh.point(vertex_at(mesh, s.report.cones[1])).x();
  BOOST_CHECK_CLOSE(std::abs(x0), 3., 1e-6);
  BOOST_CHECK_CLOSE(std::abs(x1), 3., 1e-6);
  BOOST_CHECK_LT(x0 * x1, 0.);
  // the cut joins them along a shortest edge path: at least the distance of the tips, and
  // not much more than half the perimeter of the ellipse of semi-axes 3 and 0.9 (Ramanujan)
  const double half_perimeter = 0.5 * CGAL_PI * (3. * (3. + 0.9) - std::sqrt((9. + 0.9) * (3. + 2.7)));
  BOOST_CHECK_GT(s.report.seam_length, 6.);
  BOOST_CHECK_LT(s.report.seam_length, 1.15 * half_perimeter);
}

BOOST_AUTO_TEST_CASE(torus_gets_two_loops)
{
  Mesh mesh = mbp_test::make_mesh<Mesh>(torus(24, 12));
  const Seams s = compute(mesh);
  check_disk(mesh, s);
  BOOST_CHECK_EQUAL(s.report.genus, 1);
  BOOST_CHECK_EQUAL(s.report.number_of_loops, 2);
  BOOST_CHECK_EQUAL(cut_graph_cycle_rank(mesh, s), 2);
  BOOST_CHECK(s.report.cones.empty());
  BOOST_CHECK_EQUAL(s.report.statistics.factorizations, 0);
  // the shortest system: a meridian (2 pi 0.7 = 4.40 on the smooth torus, the polygon is
  // shorter) and the inner equator (2 pi 1.3 = 8.17); a loop around the outer equator
  // (2 pi 2.7 = 17.0) would be far longer
  BOOST_CHECK_LT(s.report.seam_length, 1.1 * (2. * CGAL_PI * 0.7 + 2. * CGAL_PI * 1.3));
  flatten_and_check(mesh, s);
}

BOOST_AUTO_TEST_CASE(double_torus_gets_four_loops)
{
  Mesh mesh = mbp_test::make_mesh<Mesh>(double_torus());
  BOOST_REQUIRE_EQUAL(long(num_vertices(mesh)) - long(num_edges(mesh)) + long(num_faces(mesh)), -2);
  const Seams s = compute(mesh);
  check_disk(mesh, s);
  BOOST_CHECK_EQUAL(s.report.genus, 2);
  BOOST_CHECK_EQUAL(s.report.number_of_loops, 4);
  BOOST_CHECK_EQUAL(cut_graph_cycle_rank(mesh, s), 4);
  flatten_and_check(mesh, s);
}

BOOST_AUTO_TEST_CASE(cones_on_a_torus_join_the_loops)
{
  Mesh mesh = mbp_test::make_mesh<Mesh>(torus(24, 12, 2., 0.7, true));
  SMP::Disk_seams_options options;
  options.number_of_cones = 3;
  const Seams s = compute(mesh, options);
  check_disk(mesh, s);
  BOOST_CHECK_EQUAL(s.report.cones.size(), 3u);
  BOOST_CHECK_EQUAL(cut_graph_cycle_rank(mesh, s), 2);
  flatten_and_check(mesh, s);
}

// ---------------------------------------------------------------- surfaces with border

BOOST_AUTO_TEST_CASE(cylinder_gets_one_arc_between_its_borders)
{
  Mesh mesh = mbp_test::make_mesh<Mesh>(cylinder());
  const Seams s = compute(mesh);
  check_disk(mesh, s);
  BOOST_CHECK_EQUAL(s.report.number_of_border_loops, 2u);
  BOOST_CHECK_EQUAL(s.report.number_of_loops, 1);
  BOOST_CHECK(s.report.holes_joined);
  // the shortest arc zigzags up the 10 rows: each edge between two rows has height 0.25 and
  // at least the chord of half a step around (2 sin(pi/48)), and such a path exists
  BOOST_CHECK_CLOSE(s.report.seam_length, 10. * std::sqrt(0.0625 + std::pow(2. * std::sin(CGAL_PI / 48.), 2)), 1e-9);
  // the seam graph plus the border: rank 2 (the two borders; the arc joins them)
  BOOST_CHECK_EQUAL(cut_graph_cycle_rank(mesh, s), 2);
  flatten_and_check(mesh, s);
}

BOOST_AUTO_TEST_CASE(holes_are_joined_to_the_outer_border_or_kept)
{
  Mesh mesh = mbp_test::make_mesh<Mesh>(mbp_test::disk_with_two_holes());
  const Seams s = compute(mesh);
  check_disk(mesh, s);
  BOOST_CHECK_EQUAL(s.report.number_of_border_loops, 3u);
  BOOST_CHECK_EQUAL(s.report.number_of_loops, 2);
  BOOST_CHECK_EQUAL(cut_graph_cycle_rank(mesh, s), 3);
  flatten_and_check(mesh, s);

  Mesh kept = mbp_test::make_mesh<Mesh>(mbp_test::disk_with_two_holes());
  SMP::Disk_seams_options options;
  options.join_holes = false;
  const Seams k = compute(kept, options);
  BOOST_REQUIRE_EQUAL(k.status, SMP::OK);
  BOOST_CHECK_EQUAL(k.report.number_of_seam_edges, 0u);
  BOOST_CHECK(!k.report.holes_joined);
}

BOOST_AUTO_TEST_CASE(punctured_torus_gets_two_arcs)
{
  Mesh mesh = mbp_test::make_mesh<Mesh>(mbp_test::punctured_torus(16, 10));
  const Seams s = compute(mesh);
  check_disk(mesh, s);
  BOOST_CHECK_EQUAL(s.report.genus, 1);
  BOOST_CHECK_EQUAL(s.report.number_of_loops, 2);
  BOOST_CHECK_EQUAL(cut_graph_cycle_rank(mesh, s), 3);
  flatten_and_check(mesh, s);
}

BOOST_AUTO_TEST_CASE(a_disk_needs_no_seam)
{
  Mesh mesh = mbp_test::make_mesh<Mesh>(mbp_test::bumpy_disk());
  const Seams s = compute(mesh);
  check_disk(mesh, s);
  BOOST_CHECK_EQUAL(s.report.number_of_seam_edges, 0u);
  BOOST_CHECK(s.report.cones.empty());
}

// ---------------------------------------------------------------- determinism, motions

BOOST_AUTO_TEST_CASE(seams_are_deterministic_and_invariant_under_rigid_motions)
{
  const mbp_test::Soup shapes[] = {icosphere(3, lumpy), torus(20, 10, 2., 0.7, true), double_torus(20, 10)};
  // a rotation about an oblique axis, and a translation
  const double c = std::cos(0.7), sn = std::sin(0.7);
  const std::array<double, 3> axis = {2. / 3., 1. / 3., 2. / 3.};
  for(const mbp_test::Soup& shape : shapes)
  {
    Mesh a = mbp_test::make_mesh<Mesh>(shape), b = mbp_test::make_mesh<Mesh>(shape);
    mbp_test::Soup moved = shape;
    for(auto& p : moved.points)
    {
      const double d = axis[0] * p[0] + axis[1] * p[1] + axis[2] * p[2];
      const std::array<double, 3> x = {axis[1] * p[2] - axis[2] * p[1], axis[2] * p[0] - axis[0] * p[2],
                                       axis[0] * p[1] - axis[1] * p[0]};
      for(int k = 0; k < 3; ++k)
        p[k] = c * p[k] + sn * x[k] + (1. - c) * d * axis[k] + 10. * (k + 1);
    }
    Mesh m = mbp_test::make_mesh<Mesh>(moved);
    const Seams sa = compute(a), sb = compute(b), sm = compute(m);
    check_disk(a, sa);
    check_disk(m, sm);
    BOOST_CHECK(seam_set(a, sa) == seam_set(b, sb));
    BOOST_CHECK(sa.report.cones == sb.report.cones);
    BOOST_CHECK(seam_set(a, sa) == seam_set(m, sm));
    BOOST_CHECK(sa.report.cones == sm.report.cones);
    BOOST_CHECK_CLOSE(sa.report.seam_length, sm.report.seam_length, 1e-9);
  }
}

// The report is optional; the named parameter vertex_point_map gives the points: a mesh whose
// own points are stretched, cut with the map of the original points, gets the original's seams.
BOOST_AUTO_TEST_CASE(report_is_optional_and_points_come_from_the_named_parameter)
{
  Mesh mesh = mbp_test::make_mesh<Mesh>(icosphere(2, lumpy)), quiet = mbp_test::make_mesh<Mesh>(icosphere(2, lumpy)), stretched = mbp_test::make_mesh<Mesh>(icosphere(2, lumpy));
  const Seams s = compute(mesh);
  check_disk(mesh, s);
  Seams q;
  q.edges = quiet.add_property_map<edge_descriptor, bool>("e:seam", false).first;
  q.vertices = quiet.add_property_map<vertex_descriptor, bool>("v:seam", false).first;
  BOOST_CHECK_EQUAL(SMP::compute_disk_seams(quiet, q.edges, q.vertices), SMP::OK);
  BOOST_CHECK(seam_set(mesh, s) == seam_set(quiet, q));

  auto original = stretched.add_property_map<vertex_descriptor, K::Point_3>("v:original").first;
  for(vertex_descriptor v : vertices(stretched))
  {
    const K::Point_3 p = stretched.point(v);
    put(original, v, p);
    stretched.point(v) = K::Point_3(4. * p.x(), p.y(), 0.5 * p.z());
  }
  BOOST_CHECK(seam_set(mesh, s) != seam_set(stretched, compute(stretched)));
  Seams t;
  t.edges = stretched.add_property_map<edge_descriptor, bool>("e:seam2", false).first;
  t.vertices = stretched.add_property_map<vertex_descriptor, bool>("v:seam2", false).first;
  t.status = SMP::compute_disk_seams(stretched, t.edges, t.vertices, {}, &t.report,
                                     CGAL::parameters::vertex_point_map(original));
  BOOST_REQUIRE_EQUAL(t.status, SMP::OK);
  BOOST_CHECK(seam_set(mesh, s) == seam_set(stretched, t));
  BOOST_CHECK(s.report.cones == t.report.cones);
  BOOST_CHECK_CLOSE(s.report.seam_length, t.report.seam_length, 1e-9);
}

// The named parameter edge_is_constrained_map: the edges along the meridians of a torus
// (where the shortest meridian loop runs) are avoided; the seams still cut a disk, and their
// reported length is the geometric one (check_disk()).
BOOST_AUTO_TEST_CASE(seams_avoid_constrained_edges)
{
  Mesh mesh = mbp_test::make_mesh<Mesh>(torus(24, 12));
  auto meridian = mesh.add_property_map<edge_descriptor, bool>("e:meridian", false).first;
  for(edge_descriptor e : edges(mesh))
  {
    const K::Point_3 &p = mesh.point(source(halfedge(e, mesh), mesh)), &q = mesh.point(target(halfedge(e, mesh), mesh));
    meridian[e] = std::abs(std::atan2(p.y(), p.x()) - std::atan2(q.y(), q.x())) < 1e-9;
  }
  auto constrained_seams = [&](const Mesh& m, const Seams& s) {
    std::size_t count = 0;
    for(edge_descriptor e : edges(m))
      count += (get(s.edges, e) && meridian[e]) ? 1 : 0;
    return count;
  };
  const Seams free = compute(mesh);
  BOOST_REQUIRE_GT(constrained_seams(mesh, free), 0u);  // the free cut runs along a meridian
  Seams s;
  s.edges = mesh.add_property_map<edge_descriptor, bool>("e:seam_constrained", false).first;
  s.vertices = mesh.add_property_map<vertex_descriptor, bool>("v:seam_constrained", false).first;
  s.status = SMP::compute_disk_seams(mesh, s.edges, s.vertices, {}, &s.report,
                                     CGAL::parameters::edge_is_constrained_map(meridian));
  check_disk(mesh, s);
  BOOST_CHECK_EQUAL(constrained_seams(mesh, s), 0u);
  BOOST_CHECK_EQUAL(s.report.number_of_loops, 2);
  BOOST_CHECK_GT(s.report.seam_length, free.report.seam_length);  // a zigzag instead
  BOOST_CHECK_LT(s.report.seam_length, 3. * free.report.seam_length);
  flatten_and_check(mesh, s);
}

// ---------------------------------------------------------------- shortening

// A torus cut along a meridian that makes a detour, and the inner equator: shortening
// straightens the meridian.
BOOST_AUTO_TEST_CASE(shortening_straightens_a_detour)
{
  const int n = 24, m = 12;
  Mesh mesh = mbp_test::make_mesh<Mesh>(torus(n, m));
  SMP::internal::Indexed_surface s;
  Report report;
  SMP::internal::Surface_indexer<Mesh> indexer(mesh, s, report);
  BOOST_REQUIRE_EQUAL(indexer.index(get(CGAL::vertex_point, mesh)), SMP::NO_PROBLEM);
  // soup vertex (i, j) is mesh vertex i*m + j (polygon_soup_to_polygon_mesh keeps the order)
  std::vector<char> cut(static_cast<std::size_t>(s.number_of_edges()), 0);
  auto mark = [&](int i0, int j0, int i1, int j1) {
    const int a = ((i0 + n) % n) * m + (j0 + m) % m, b = ((i1 + n) % n) * m + (j1 + m) % m;
    for(int k = s.ring_offsets[static_cast<std::size_t>(a)]; k < s.ring_offsets[static_cast<std::size_t>(a) + 1]; ++k)
    {
      const int e = s.ring_edges[static_cast<std::size_t>(k)];
      if(s.other_end(e, a) == b)
      {
        cut[static_cast<std::size_t>(e)] = 1;
        return;
      }
    }
    BOOST_FAIL("not an edge");
  };
  for(int i = 0; i < n; ++i)  // inner equator: j = m/2
    mark(i, m / 2, i + 1, m / 2);
  // the meridian at i = 0, with a detour through i = 3 instead of its edges j = 0..4
  mark(0, 0, 1, 0); mark(1, 0, 2, 0); mark(2, 0, 3, 0);
  mark(3, 0, 3, 1); mark(3, 1, 3, 2); mark(3, 2, 3, 3); mark(3, 3, 3, 4);
  mark(3, 4, 2, 4); mark(2, 4, 1, 4); mark(1, 4, 0, 4);
  for(int j = 4; j < m; ++j)
    mark(0, j, 0, j + 1);
  std::vector<char> terminal(static_cast<std::size_t>(s.number_of_vertices()), 0);
  BOOST_REQUIRE(SMP::internal::is_disk_cut(s, cut));
  auto length = [&]() {
    double l = 0.;
    for(int e = 0; e < s.number_of_edges(); ++e)
      l += cut[static_cast<std::size_t>(e)] ? s.edge_lengths[static_cast<std::size_t>(e)] : 0.;
    return l;
  };
  const double before = length();
  const int replaced = SMP::internal::shorten_cut(s, terminal, 1, 3, cut);
  BOOST_CHECK_GE(replaced, 1);
  BOOST_CHECK(SMP::internal::is_disk_cut(s, cut));
  BOOST_CHECK_LT(length(), before - 1.);
  // the meridian is straight again, and the inner equator, the shortest loop around the
  // hole, is kept
  const double meridian = 2. * m * 0.7 * std::sin(CGAL_PI / m), equator = 2. * n * 1.3 * std::sin(CGAL_PI / n);
  BOOST_CHECK_CLOSE(length(), meridian + equator, 1e-9);
}

// ---------------------------------------------------------------- bad input

BOOST_AUTO_TEST_CASE(bad_input_gets_a_named_error_and_no_output)
{
  // two spheres: several components
  mbp_test::Soup two = icosphere(1);
  const std::size_t n = two.points.size();
  const mbp_test::Soup second = icosphere(1, [](std::array<double, 3> p) {
    return std::array<double, 3>{p[0] + 5., p[1], p[2]};
  });
  two.points.insert(two.points.end(), second.points.begin(), second.points.end());
  for(auto f : second.faces)
    two.faces.push_back({f[0] + n, f[1] + n, f[2] + n});
  Mesh mesh = mbp_test::make_mesh<Mesh>(two);
  Seams s;
  s.edges = mesh.add_property_map<edge_descriptor, bool>("e:seam", true).first;
  s.vertices = mesh.add_property_map<vertex_descriptor, bool>("v:seam", true).first;
  s.status = SMP::compute_disk_seams(mesh, s.edges, s.vertices, SMP::Disk_seams_options(), &s.report);
  BOOST_CHECK_EQUAL(s.status, SMP::ERROR_NO_TOPOLOGICAL_DISC);
  BOOST_CHECK_EQUAL(s.report.problem, SMP::SEVERAL_COMPONENTS);
  BOOST_CHECK_EQUAL(s.report.number_of_components, 2u);
  BOOST_CHECK(std::string(SMP::disk_seams_problem_message(s.report.problem)).find("components") != std::string::npos);
  for(edge_descriptor e : edges(mesh))  // nothing written
    BOOST_CHECK(get(s.edges, e));

  // a bow tie: two fans at one vertex
  Mesh bow;
  const vertex_descriptor c = bow.add_vertex(K::Point_3(0, 0, 0));
  const vertex_descriptor p[4] = {bow.add_vertex(K::Point_3(1, 0, 0)), bow.add_vertex(K::Point_3(1, 1, 0)),
                                  bow.add_vertex(K::Point_3(-1, 0, 0)), bow.add_vertex(K::Point_3(-1, -1, 0))};
  BOOST_REQUIRE(bow.add_face(c, p[0], p[1]) != Mesh::null_face());
  BOOST_REQUIRE(bow.add_face(c, p[2], p[3]) != Mesh::null_face());
  const Seams b = compute(bow);
  BOOST_CHECK_EQUAL(b.status, SMP::ERROR_NO_TOPOLOGICAL_DISC);
  BOOST_CHECK_EQUAL(b.report.problem, SMP::NON_MANIFOLD_VERTEX);
  BOOST_CHECK_EQUAL(b.report.problem_vertex, position_of(bow, c));
  BOOST_CHECK_EQUAL(b.report.problem_face, Report::no_element);
  BOOST_CHECK(std::string(SMP::disk_seams_problem_message(b.report.problem)).find("manifold") != std::string::npos);

  // a quad
  Mesh quad;
  quad.add_face(quad.add_vertex(K::Point_3(0, 0, 0)), quad.add_vertex(K::Point_3(1, 0, 0)),
                quad.add_vertex(K::Point_3(1, 1, 0)), quad.add_vertex(K::Point_3(0, 1, 0)));
  const Seams q = compute(quad);
  BOOST_CHECK_EQUAL(q.status, SMP::ERROR_NON_TRIANGULAR_MESH);
  BOOST_CHECK_EQUAL(q.report.problem, SMP::FACE_NOT_A_TRIANGLE);
  BOOST_CHECK_EQUAL(q.report.problem_face, 0u);

  Mesh empty;
  BOOST_CHECK_EQUAL(compute(empty).status, SMP::ERROR_EMPTY_MESH);
}

// ---------------------------------------------------------------- the project's meshes

namespace {

std::string shared_meshes()
{
  return mbp_test::shared_mesh_dir();  // the configured folder, or MBP_SHARED_MESH_DIR of the environment
}

} // namespace

// Every closed, holed and higher-genus mesh of ../shared/data/meshes (PROVENANCE.md classes
// CLOSED, HOLES, OPEN g>0) is cut into a disk that flattens without flipped faces and one to
// one; the MESSY ones get a named error.
BOOST_AUTO_TEST_CASE(project_meshes_are_cut_into_disks, MBP_EXTENDED_TIER)
{
  const char* meshes[] = {"bear.off", "cgal_hand.off", "fandisk.off", "kitten.obj", "blade.off", "head.off",
                          "holes.off", "lion.off", "mech-holes-shark.off", "nefertiti-entire.off", "Hand1.off",
                          "punctured-torus.obj"};
  for(const char* name : meshes)
  {
    BOOST_TEST_MESSAGE(name);
    Mesh mesh;
    mbp_test::read_mesh(shared_meshes() + "/" + name, mesh);
    const Seams s = compute(mesh);
    check_disk(mesh, s);
    const SMP::Parameterization_quality q = flatten_and_check(mesh, s);
    BOOST_CHECK_LE(q.angle_distortion, 0.05);  // the target of issue 16
    BOOST_TEST_MESSAGE(name << ": " << s.report.number_of_seam_edges << " seam edges, " << s.report.cones.size()
                            << " cones, angle distortion " << q.angle_distortion);
  }
  const std::pair<const char*, SMP::Disk_seams_problem> messy[] = {
    {"mask_cone.off", SMP::SEVERAL_COMPONENTS}, {"ogre.obj", SMP::NON_MANIFOLD_VERTEX},
    {"polygon_mesh.off", SMP::NON_MANIFOLD_VERTEX}};
  for(const auto& m : messy)
  {
    Mesh mesh;
    mbp_test::read_mesh(shared_meshes() + "/" + m.first, mesh);
    const Seams s = compute(mesh);
    BOOST_CHECK_EQUAL(s.status, SMP::ERROR_NO_TOPOLOGICAL_DISC);
    BOOST_CHECK_EQUAL(s.report.problem, m.second);
  }
}

BOOST_AUTO_TEST_SUITE_END()
