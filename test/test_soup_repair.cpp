// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// The input of the atlas (issue 22, item 1): polygon soups as users have them repaired into a
// triangle mesh the parameterizers accept, with every input corner mapped to where its UV
// will come from. Core tier: generated soups, one defect each, with the report's counts as
// constructed. Extended tier: the 15 meshes of ../shared/data/atlas (the folder atlas beside
// MBP_SHARED_MESH_DIR), with the counts of its PROVENANCE.md.

#include <boost/test/unit_test.hpp>

#include "atlas_soups.h"
#include "test_support.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/polygon_mesh_to_polygon_soup.h>

#include <CGAL/Surface_mesh_parameterization/internal/atlas/soup_repair.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/triangle_geometry.h>
#include <CGAL/Surface_mesh_parameterization/Soup_repair_report.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

BOOST_AUTO_TEST_SUITE(soup_repair)

namespace SMP = CGAL::Surface_mesh_parameterization;
typedef CGAL::Simple_cartesian<double>                       K;
typedef SMP::internal::Repaired_soup<K>                      Repaired;
typedef Repaired::Mesh                                       Mesh;
typedef Repaired::Source                                     Source;
typedef boost::graph_traits<Mesh>::vertex_descriptor         vertex_descriptor;
typedef boost::graph_traits<Mesh>::halfedge_descriptor       halfedge_descriptor;
typedef boost::graph_traits<Mesh>::face_descriptor           face_descriptor;
typedef std::vector<std::vector<std::size_t> >               Polygons;
using mbp_test::Soup;
using namespace mbp_test;

namespace {

template <class Point>
Eigen::Vector3d to_eigen(const Point& p)
{
  return Eigen::Vector3d(CGAL::to_double(p[0]), CGAL::to_double(p[1]), CGAL::to_double(p[2]));
}

Eigen::Vector3d at(const Mesh& m, vertex_descriptor v) { return to_eigen(m.point(v)); }

// The 3D point a source stands for: the same blend of its halfedges' targets.
Eigen::Vector3d source_point(const Mesh& m, const Source& s)
{
  return (1. - s.t) * at(m, target(s.from, m)) + s.t * at(m, target(s.to, m));
}

bool is_face_halfedge(const Mesh& m, halfedge_descriptor h)
{
  return h != boost::graph_traits<Mesh>::null_halfedge() && std::size_t(h) < m.num_halfedges() &&
         !m.is_removed(h) && !is_border(h, m);
}

std::array<std::size_t, 3> face_vertices(const Mesh& m, face_descriptor f)
{
  const halfedge_descriptor h = halfedge(f, m);
  return {{std::size_t(source(h, m)), std::size_t(target(h, m)), std::size_t(target(next(h, m), m))}};
}

// Written without CGAL's halfedge structure, from vertex triples: the directed edges that
// belong to more than one triangle (none when every edge has at most two triangles running it
// opposite ways: consistently oriented), and the vertices whose triangles are not one fan
// (connected through edges at the vertex): pinched.
std::pair<std::size_t, std::size_t> manifold_defects(const std::vector<std::array<std::size_t, 3> >& triangles)
{
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> triangle_of;  // per directed edge
  std::map<std::size_t, std::vector<std::size_t> > around;
  std::size_t repeated = 0, pinched = 0;
  for(std::size_t f = 0; f < triangles.size(); ++f)
    for(std::size_t k = 0; k < 3; ++k)
    {
      repeated += triangle_of.emplace(std::make_pair(triangles[f][k], triangles[f][(k + 1) % 3]), f).second ? 0 : 1;
      around[triangles[f][k]].push_back(f);
    }
  for(const auto& v : around)
  {
    std::set<std::size_t> fan = {v.second.front()};
    for(std::vector<std::size_t> front = {v.second.front()}; !front.empty();)
    {
      const std::array<std::size_t, 3>& t = triangles[front.back()];
      front.pop_back();
      const std::size_t k = std::size_t(std::find(t.begin(), t.end(), v.first) - t.begin());
      for(const auto& e : {std::make_pair(t[(k + 1) % 3], v.first), std::make_pair(v.first, t[(k + 2) % 3])})
      {
        const auto across = triangle_of.find(e);  // the triangle on the other side of an edge at v
        if(across != triangle_of.end() && fan.insert(across->second).second)
          front.push_back(across->second);
      }
    }
    pinched += fan.size() == v.second.size() ? 0 : 1;
  }
  return std::make_pair(repeated, pinched);
}

// The repaired mesh: valid, triangles of nonzero area, oriented and manifold (CGAL's checks and
// manifold_defects()), no isolated vertex, no garbage; its per-face vectors and the
// report's totals agree with it.
void check_mesh(const Repaired& r)
{
  const Mesh& m = r.mesh;
  BOOST_CHECK(CGAL::is_valid_polygon_mesh(m));
  BOOST_CHECK(CGAL::is_triangle_mesh(m));
  BOOST_CHECK(!m.has_garbage());
  BOOST_CHECK_EQUAL(r.report.faces, m.number_of_faces());
  BOOST_CHECK_EQUAL(r.report.vertices, m.number_of_vertices());
  BOOST_REQUIRE_EQUAL(r.face_polygon.size(), m.number_of_faces());
  BOOST_REQUIRE_EQUAL(r.face_component.size(), m.number_of_faces());
  std::size_t zero_area = 0, isolated = 0, components = 0;
  for(face_descriptor f : faces(m))
  {
    const halfedge_descriptor h = halfedge(f, m);
    zero_area += SMP::internal::is_degenerate_triangle(at(m, source(h, m)), at(m, target(h, m)),
                                                       at(m, target(next(h, m), m))) ? 1 : 0;
    components = (std::max)(components, r.face_component[std::size_t(f)] + 1);
  }
  for(vertex_descriptor v : vertices(m))
    isolated += (halfedge(v, m) == boost::graph_traits<Mesh>::null_halfedge()) ? 1 : 0;
  std::vector<halfedge_descriptor> cones;
  CGAL::Polygon_mesh_processing::non_manifold_vertices(m, std::back_inserter(cones));
  BOOST_CHECK_EQUAL(zero_area, 0u);
  BOOST_CHECK(cones.empty());
  BOOST_CHECK_EQUAL(isolated, 0u);
  BOOST_CHECK_EQUAL(components, r.report.components);
  std::vector<std::array<std::size_t, 3> > triangles;
  for(face_descriptor f : faces(m))
    triangles.push_back(face_vertices(m, f));
  BOOST_CHECK(manifold_defects(triangles) == std::make_pair(std::size_t(0), std::size_t(0)));
}

struct Corner_counts
{
  std::size_t on_halfedge = 0, on_segment = 0, collapsed = 0, isolated = 0;
  std::size_t off_point = 0;  // ON_SEGMENT corners farther than the tolerance from their point
};

// Every input corner has a source: two halfedges of one face of the mesh, whatever its kind;
// ON_HALFEDGE exactly at the corner's point, ON_SEGMENT within `tolerance` of it (else
// counted), COLLAPSED and ISOLATED at one vertex.
template <class Point>
Corner_counts check_corners(const std::vector<Point>& points, const Polygons& polygons, const Repaired& r,
                            double tolerance)
{
  Corner_counts n;
  BOOST_REQUIRE_EQUAL(r.corner_offset.size(), polygons.size() + 1);
  BOOST_REQUIRE_EQUAL(r.corners.size(), r.corner_offset.back());
  for(std::size_t p = 0; p < polygons.size(); ++p)
    for(std::size_t j = 0; j < polygons[p].size(); ++j)
    {
      const Source& s = r.corner(p, j);
      BOOST_REQUIRE(is_face_halfedge(r.mesh, s.from) && is_face_halfedge(r.mesh, s.to));
      BOOST_CHECK(face(s.from, r.mesh) == face(s.to, r.mesh));
      BOOST_CHECK(s.t >= 0. && s.t <= 1.);
      const double distance = (source_point(r.mesh, s) - to_eigen(points[polygons[p][j]])).norm();
      if(s.kind == Source::ON_HALFEDGE)
        BOOST_CHECK(s.from == s.to && distance == 0.);
      else if(s.kind == Source::ON_SEGMENT)
        n.off_point += distance > tolerance ? 1 : 0;
      else
        BOOST_CHECK(s.from == s.to && s.t == 0.);
      ++(s.kind == Source::ON_HALFEDGE ? n.on_halfedge : s.kind == Source::ON_SEGMENT ? n.on_segment
         : s.kind == Source::COLLAPSED ? n.collapsed : n.isolated);
    }
  BOOST_CHECK_EQUAL(n.collapsed, r.report.collapsed_corners);
  BOOST_CHECK_EQUAL(n.isolated, r.report.isolated_corners);
  return n;
}

// The UVs of the input corners through repaired_triangles() and input_corner_uv(), with a
// random UV on every corner of every face (as charts give a UV per face corner): finite, and
// of zero area for every polygon of zero area (`zero_area`) with no face of its own. Returns
// the number of polygons without a face of their own (zero-area, degenerate, duplicates).
std::size_t check_corner_uvs(const Polygons& polygons, const std::vector<bool>& zero_area, const Repaired& r)
{
  const SMP::internal::Atlas_triangles t = SMP::internal::repaired_triangles(r);
  BOOST_REQUIRE_EQUAL(t.faces.size(), r.mesh.number_of_faces());
  std::mt19937 random(22);
  std::uniform_real_distribution<double> uniform(0., 1.);
  std::vector<std::array<Eigen::Vector2d, 3> > uv(t.faces.size());
  std::vector<bool> has_face(polygons.size(), false);
  for(face_descriptor f : faces(r.mesh))
  {
    has_face[r.face_polygon[std::size_t(f)]] = true;
    int k = 0;
    for(halfedge_descriptor h : halfedges_around_face(halfedge(f, r.mesh), r.mesh))
    {
      BOOST_CHECK_EQUAL(t.faces[std::size_t(f)][std::size_t(k)], int(target(h, r.mesh)));
      BOOST_CHECK(SMP::internal::face_corner(r.mesh, h) == std::make_pair(std::size_t(f), k));
      uv[std::size_t(f)][std::size_t(k++)] = Eigen::Vector2d(uniform(random), uniform(random));
    }
  }
  const auto corner_uv = [&uv](std::size_t f, int k) { return uv[f][std::size_t(k)]; };
  std::size_t without_face = 0, not_finite = 0, not_flat = 0;
  for(std::size_t p = 0; p < polygons.size(); ++p)
  {
    std::vector<Eigen::Vector2d> corners;
    for(std::size_t j = 0; j < polygons[p].size(); ++j)
      corners.push_back(SMP::internal::input_corner_uv(r, p, j, corner_uv));
    double area = 0.;
    for(std::size_t j = 0; j < corners.size(); ++j)
    {
      not_finite += corners[j].allFinite() ? 0 : 1;
      area += corners[j].x() * corners[(j + 1) % corners.size()].y() - corners[(j + 1) % corners.size()].x() * corners[j].y();
    }
    without_face += has_face[p] ? 0 : 1;
    not_flat += (!has_face[p] && zero_area[p] && std::abs(area) > 1e-12) ? 1 : 0;
  }
  BOOST_CHECK_EQUAL(not_finite, 0u);
  BOOST_CHECK_EQUAL(not_flat, 0u);
  return without_face;
}

// The Newell normal of a polygon (twice its area vector when planar), about its first point.
template <class Point>
Eigen::Vector3d newell_normal(const std::vector<Point>& points, const std::vector<std::size_t>& polygon)
{
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  const Eigen::Vector3d o = to_eigen(points[polygon[0]]);
  for(std::size_t j = 0; j < polygon.size(); ++j)
    n += (to_eigen(points[polygon[j]]) - o).cross(to_eigen(points[polygon[(j + 1) % polygon.size()]]) - o);
  return n;
}

template <class Point>
bool is_planar(const std::vector<Point>& points, const std::vector<std::size_t>& polygon)
{
  const Eigen::Vector3d n = newell_normal(points, polygon);
  double size = 0., height = 0.;
  for(const std::size_t i : polygon)
  {
    const Eigen::Vector3d d = to_eigen(points[i]) - to_eigen(points[polygon[0]]);
    size = (std::max)(size, d.norm());
    height = (std::max)(height, n.norm() == 0. ? 0. : std::abs(d.dot(n.normalized())));
  }
  return height <= 1e-9 * size;
}

// The 3D area is kept: the faces of the planar input polygons have their area (Newell's) to
// 1e-12 relative, in all, duplicates of a polygon counted once (their points as a set). A
// non-planar polygon has no area of its own, but its faces, a surface it bounds, cover at
// least the norm of its vector area (Newell's). Returns the number of non-planar polygons.
template <class Point>
std::size_t check_area(const std::vector<Point>& points, const Polygons& polygons, const Repaired& r)
{
  std::vector<double> face_area(polygons.size(), 0.);  // of the faces of each polygon
  for(face_descriptor f : faces(r.mesh))
  {
    const halfedge_descriptor h = halfedge(f, r.mesh);
    const Eigen::Vector3d a = at(r.mesh, source(h, r.mesh)), b = at(r.mesh, target(h, r.mesh));
    face_area[r.face_polygon[std::size_t(f)]] += (b - a).cross(at(r.mesh, target(next(h, r.mesh), r.mesh)) - a).norm() / 2.;
  }
  std::set<std::vector<std::array<double, 3> > > seen;
  std::size_t non_planar = 0, uncovered = 0;
  double expected = 0., got = 0.;
  for(std::size_t p = 0; p < polygons.size(); ++p)
  {
    std::vector<std::array<double, 3> > key;
    for(const std::size_t i : polygons[p])
      key.push_back({{CGAL::to_double(points[i][0]), CGAL::to_double(points[i][1]), CGAL::to_double(points[i][2])}});
    std::sort(key.begin(), key.end());
    key.erase(std::unique(key.begin(), key.end()), key.end());
    const double vector_area = newell_normal(points, polygons[p]).norm() / 2.;
    const bool first = seen.insert(key).second;
    if(!is_planar(points, polygons[p]))
    {
      ++non_planar;
      uncovered += (first && face_area[p] < (1. - 1e-12) * vector_area) ? 1 : 0;
      continue;
    }
    expected += first ? vector_area : 0.;
    got += face_area[p];
  }
  BOOST_CHECK_MESSAGE(std::abs(got - expected) <= 1e-12 * expected,
                      "area of the faces " << got << ", of the input polygons " << expected);
  BOOST_CHECK_EQUAL(uncovered, 0u);
  return non_planar;
}

// Whether each polygon has zero area (the parameterizers' test: twice its area <= 1e-12 times
// the square of its diameter).
template <class Point>
std::vector<bool> zero_area_polygons(const std::vector<Point>& points, const Polygons& polygons)
{
  std::vector<bool> zero(polygons.size());
  for(std::size_t p = 0; p < polygons.size(); ++p)
  {
    double size = 0.;
    for(const std::size_t i : polygons[p])
      for(const std::size_t j : polygons[p])
        size = (std::max)(size, (to_eigen(points[i]) - to_eigen(points[j])).norm());
    zero[p] = newell_normal(points, polygons[p]).norm() <= 1e-12 * size * size;
  }
  return zero;
}

// Traceability and orientation: the points of every face are points of its input polygon, and
// the input polygons whose faces turn the other way are the report's reoriented polygons
// (faces of one polygon all turn the same way). Polygons without a normal are not counted.
template <class Point>
void check_faces_against_input(const std::vector<Point>& points, const Polygons& polygons, const Repaired& r)
{
  std::vector<int> turn(polygons.size(), 0);
  std::size_t foreign = 0, mixed = 0;
  for(face_descriptor f : faces(r.mesh))
  {
    const std::vector<std::size_t>& polygon = polygons[r.face_polygon[std::size_t(f)]];
    std::vector<Eigen::Vector3d> corners;
    for(halfedge_descriptor h : halfedges_around_face(halfedge(f, r.mesh), r.mesh))
      corners.push_back(at(r.mesh, target(h, r.mesh)));
    for(const Eigen::Vector3d& c : corners)
      foreign += std::none_of(polygon.begin(), polygon.end(),
                              [&](std::size_t i) { return to_eigen(points[i]) == c; }) ? 1 : 0;
    const Eigen::Vector3d n = newell_normal(points, polygon);
    if(n.norm() == 0.)
      continue;
    const int t = (corners[1] - corners[0]).cross(corners[2] - corners[0]).dot(n) > 0. ? 1 : -1;
    int& known = turn[r.face_polygon[std::size_t(f)]];
    mixed += (known != 0 && known != t) ? 1 : 0;
    known = t;
  }
  BOOST_CHECK_EQUAL(foreign, 0u);
  BOOST_CHECK_EQUAL(mixed, 0u);
  BOOST_CHECK_EQUAL(std::size_t(std::count(turn.begin(), turn.end(), -1)), r.report.reoriented_polygons);
}

// Every property of a repaired soup but the report's counts: the mesh, the faces against the
// input, every corner's source and UV, the area. Returns the corner counts.
template <class Point>
Corner_counts check_repaired(const std::vector<Point>& points, const Polygons& polygons, const Repaired& r,
                             double tolerance)
{
  check_mesh(r);
  check_faces_against_input(points, polygons, r);
  const Corner_counts n = check_corners(points, polygons, r, tolerance);
  check_corner_uvs(polygons, zero_area_polygons(points, polygons), r);
  check_area(points, polygons, r);
  return n;
}

// The counts of two reports, field by field.
void check_report(const SMP::Soup_repair_report& got, const SMP::Soup_repair_report& want)
{
#define MBP_SAME_COUNT(field) BOOST_CHECK_MESSAGE(got.field == want.field, #field ": " << got.field << ", expected " << want.field)
  MBP_SAME_COUNT(input_points); MBP_SAME_COUNT(input_polygons); MBP_SAME_COUNT(input_corners);
  MBP_SAME_COUNT(merged_points); MBP_SAME_COUNT(degenerate_polygons); MBP_SAME_COUNT(polygons_with_repeated_points);
  MBP_SAME_COUNT(duplicate_polygons); MBP_SAME_COUNT(non_manifold_edges); MBP_SAME_COUNT(pinched_vertices);
  MBP_SAME_COUNT(non_orientable_components); MBP_SAME_COUNT(vertices_split_non_manifold);
  MBP_SAME_COUNT(vertices_split_non_orientable); MBP_SAME_COUNT(reoriented_polygons); MBP_SAME_COUNT(detached_polygons);
  MBP_SAME_COUNT(triangulated_polygons); MBP_SAME_COUNT(triangles_from_polygons);
  MBP_SAME_COUNT(zero_area_triangles); MBP_SAME_COUNT(vertices_split_after_removal);
  MBP_SAME_COUNT(vertices); MBP_SAME_COUNT(faces); MBP_SAME_COUNT(components);
  MBP_SAME_COUNT(collapsed_corners); MBP_SAME_COUNT(isolated_corners);
#undef MBP_SAME_COUNT
}

// A report with the input counts of `soup` and the given result, no repair.
SMP::Soup_repair_report plain_report(const Soup& soup, std::size_t vertices, std::size_t faces,
                                     std::size_t components = 1)
{
  SMP::Soup_repair_report want;
  want.input_points = soup.points.size();
  want.input_polygons = soup.faces.size();
  for(const auto& polygon : soup.faces)
    want.input_corners += polygon.size();
  want.vertices = vertices;
  want.faces = faces;
  want.components = components;
  return want;
}

// Repairs the soup and checks everything but the counts; returns the corner counts.
Corner_counts repair(const Soup& soup, Repaired& r, double tolerance = 1e-12)
{
  BOOST_REQUIRE_EQUAL(SMP::internal::repair_soup_for_atlas(soup.points, soup.faces, r), SMP::OK);
  return check_repaired(soup.points, soup.faces, r, tolerance);
}

std::size_t faces_facing_up(const Mesh& m)
{
  std::size_t up = 0;
  for(face_descriptor f : faces(m))
  {
    const halfedge_descriptor h = halfedge(f, m);
    const Eigen::Vector3d a = at(m, source(h, m)), b = at(m, target(h, m)), c = at(m, target(next(h, m), m));
    up += (b - a).cross(c - a).z() > 0. ? 1 : 0;
  }
  return up;
}

// The working soups of orient_manifold_soup() and of CGAL's orient_polygon_soup() on the same
// cleaned soup agree: the same polygons reversed, each the same way round, the same pinched
// points split into the same fans (a corner's point in one always goes with the same point in
// the other). False, with nothing checked, when the soup is not for orient_manifold_soup().
template <class Point>
bool check_orientations_agree(const std::vector<Point>& points, const Polygons& polygons)
{
  SMP::Soup_repair_report ours, cgal;
  SMP::internal::Working_soup<K::Point_3> a;
  BOOST_REQUIRE_EQUAL(SMP::internal::load_soup(points, polygons, a, ours), SMP::OK);
  SMP::internal::merge_points(a, ours);
  SMP::internal::simplify_polygons(a, ours);
  SMP::internal::merge_polygons(a, ours);
  SMP::internal::Working_soup<K::Point_3> b = a;
  cgal = ours;
  if(!SMP::internal::orient_manifold_soup(a, ours))
    return false;
  SMP::internal::orient_with_cgal(b, cgal);
  check_report(ours, cgal);
  BOOST_CHECK(a.id_reversed == b.id_reversed);
  BOOST_REQUIRE_EQUAL(a.polygons.size(), b.polygons.size());
  BOOST_CHECK_EQUAL(a.points.size(), b.points.size());
  std::map<std::size_t, std::size_t> a_to_b;
  std::size_t unmatched = 0, inconsistent = 0;
  for(std::size_t q = 0; q < a.polygons.size(); ++q)
  {
    const auto &pa = a.polygons[q], &pb = b.polygons[q];
    const std::size_t n = pa.size();
    BOOST_REQUIRE(pa.id == pb.id && n == pb.size());
    std::size_t shift = 0;
    auto same_from = [&](std::size_t k) {
      for(std::size_t j = 0; j < n; ++j)
        if(a.point_origin[pa[j]] != b.point_origin[pb[(j + k) % n]])
          return false;
      return true;
    };
    while(shift < n && !same_from(shift))
      ++shift;
    unmatched += shift == n ? 1 : 0;
    for(std::size_t j = 0; j < n && shift < n; ++j)
      inconsistent += a_to_b.emplace(pa[j], pb[(j + shift) % n]).first->second != pb[(j + shift) % n] ? 1 : 0;
  }
  std::set<std::size_t> images;
  for(const auto& ab : a_to_b)
    images.insert(ab.second);
  BOOST_CHECK_EQUAL(unmatched, 0u);
  BOOST_CHECK_EQUAL(inconsistent, 0u);
  BOOST_CHECK_EQUAL(images.size(), a_to_b.size());
  return true;
}

} // namespace

// ---------------------------------------------------------------- core tier: generated soups

BOOST_AUTO_TEST_CASE(two_components_sharing_nothing)
{
  Soup s = square();
  append(s, square(5.));
  Repaired r;
  const Corner_counts n = repair(s, r);
  check_report(r.report, plain_report(s, 8, 4, 2));
  BOOST_CHECK_EQUAL(n.on_halfedge, 12u);
  BOOST_CHECK(r.face_component[0] != r.face_component[2]);
}

BOOST_AUTO_TEST_CASE(vertex_shared_by_two_cones)
{
  const Soup s = two_cones();
  Repaired r;
  const Corner_counts n = repair(s, r);
  SMP::Soup_repair_report want = plain_report(s, 10, 8, 2);
  want.pinched_vertices = 1;
  want.vertices_split_non_manifold = 1;
  check_report(r.report, want);
  BOOST_CHECK_EQUAL(n.on_halfedge, 24u);
}

BOOST_AUTO_TEST_CASE(edge_with_three_faces)
{
  Soup s = edge_with_three_faces_soup();
  Repaired r;
  const Corner_counts n = repair(s, r);
  SMP::Soup_repair_report want = plain_report(s, 9, 3, 3);
  want.non_manifold_edges = 1;
  want.vertices_split_non_manifold = 4;  // both ends, on 3 sheets each
  check_report(r.report, want);
  BOOST_CHECK_EQUAL(n.on_halfedge, 9u);
}

BOOST_AUTO_TEST_CASE(flipped_faces_take_the_majority_orientation)
{
  Soup s = grid(3);
  for(std::size_t f : {1u, 7u, 12u})
    std::reverse(s.faces[f].begin(), s.faces[f].end());
  Repaired r;
  repair(s, r);
  SMP::Soup_repair_report want = plain_report(s, 16, 18);
  want.reoriented_polygons = 3;
  check_report(r.report, want);
  BOOST_CHECK_EQUAL(faces_facing_up(r.mesh), 18u);

  // most faces flipped: the component turns the other way, the few others are reoriented
  Soup t = grid(3);
  for(std::size_t f = 0; f < 13; ++f)
    std::reverse(t.faces[f].begin(), t.faces[f].end());
  Repaired q;
  repair(t, q);
  want.reoriented_polygons = 5;
  check_report(q.report, want);
  BOOST_CHECK_EQUAL(faces_facing_up(q.mesh), 0u);
}

BOOST_AUTO_TEST_CASE(duplicated_faces)
{
  Soup s = square();
  s.faces.push_back({1, 2, 0});  // the first face again, from another corner
  s.faces.push_back({0, 3, 2});  // the second face, reversed
  Repaired r;
  const Corner_counts n = repair(s, r);
  SMP::Soup_repair_report want = plain_report(s, 4, 2);
  want.duplicate_polygons = 2;
  check_report(r.report, want);
  BOOST_CHECK_EQUAL(n.on_halfedge, 12u);
  // a duplicate's corners take the kept face's UVs
  for(std::size_t j = 0; j < 3; ++j)
  {
    BOOST_CHECK(face(r.corner(2, j).from, r.mesh) == face(r.corner(0, 0).from, r.mesh));
    BOOST_CHECK(face(r.corner(3, j).from, r.mesh) == face(r.corner(1, 0).from, r.mesh));
  }
}

BOOST_AUTO_TEST_CASE(zero_area_face_on_the_edge_of_a_face_kept)
{
  // A(0) B(1) C(2) M(3) E(4): the sliver A M B (M the middle of AB) lies along the edge AB
  // of the face A B C, across its longest edge. It is the only link between A B C and the two
  // faces below A M B: removed, it leaves A and B pinched, split into two components.
  Soup s = zero_area_face_on_an_edge_soup();
  Repaired r;
  const Corner_counts n = repair(s, r);
  SMP::Soup_repair_report want = plain_report(s, 7, 3, 2);
  want.zero_area_triangles = 1;
  want.vertices_split_after_removal = 2;
  check_report(r.report, want);
  BOOST_CHECK_EQUAL(n.on_halfedge, 9u);
  BOOST_CHECK_EQUAL(n.on_segment, 3u);
  BOOST_CHECK_EQUAL(n.off_point, 0u);
  BOOST_REQUIRE_EQUAL(r.zero_area_triangles.size(), 1u);
  const auto& z = r.zero_area_triangles.front();
  BOOST_CHECK_EQUAL(z.polygon, 3u);
  BOOST_CHECK(z.face == face(r.corner(0, 0).from, r.mesh));
  BOOST_CHECK_CLOSE(r.corner(3, 1).t + r.corner(3, 1).t, 1., 1e-12);  // M halfway
}

BOOST_AUTO_TEST_CASE(zero_area_face_whose_removal_pinches_vertices)
{
  // the sliver P Q R (P, Q, R on a line) is the only link between three triangles, one on
  // each of its edges: removed, it leaves P, Q and R pinched
  Soup s;
  s.points = {{{0., 0., 0.}}, {{1., 0., 0.}}, {{2., 0., 0.}},
              {{.5, 0., 1.}}, {{1.5, 0., -1.}}, {{1., 1., 0.}}};
  s.faces = {{0, 1, 2}, {1, 0, 3}, {2, 1, 4}, {0, 2, 5}};
  Repaired r;
  const Corner_counts n = repair(s, r);
  SMP::Soup_repair_report want = plain_report(s, 9, 3, 3);
  want.zero_area_triangles = 1;
  want.vertices_split_after_removal = 3;
  check_report(r.report, want);
  BOOST_CHECK_EQUAL(n.on_segment, 3u);
  BOOST_CHECK_EQUAL(n.off_point, 0u);
  // placed across its longest edge P R, on the face P R (1, 1, 0)
  BOOST_CHECK(r.zero_area_triangles.front().face == face(r.corner(3, 0).from, r.mesh));
}

BOOST_AUTO_TEST_CASE(quads_and_a_pentagon)
{
  Soup s = quads_and_a_pentagon_soup();
  Repaired r;
  const Corner_counts n = repair(s, r);
  SMP::Soup_repair_report want = plain_report(s, 9, 7);
  want.triangulated_polygons = 3;
  want.triangles_from_polygons = 7;
  check_report(r.report, want);
  BOOST_CHECK_EQUAL(n.on_halfedge, 13u);
  // each polygon's triangles: n - 2 of them, covering its area
  std::vector<std::size_t> count(3, 0);
  std::vector<double> area(3, 0.);
  for(face_descriptor f : faces(r.mesh))
  {
    ++count[r.face_polygon[std::size_t(f)]];
    area[r.face_polygon[std::size_t(f)]] += CGAL::Polygon_mesh_processing::face_area(f, r.mesh);
  }
  BOOST_CHECK(count == std::vector<std::size_t>({2, 2, 3}));
  for(std::size_t p = 0; p < 3; ++p)
    BOOST_CHECK_CLOSE(area[p], newell_normal(s.points, s.faces[p]).norm() / 2., 1e-9);
}

BOOST_AUTO_TEST_CASE(polygon_on_a_line)
{
  // B A X Y, all on the line y = 0 along the edge A B of a square: CGAL refuses to triangulate
  // it (zero normal), the fan makes two zero-area triangles, placed on the edge A B
  Soup s = square();
  s.points.push_back({{-1., 0., 0.}});
  s.points.push_back({{2., 0., 0.}});
  s.faces.push_back({1, 0, 4, 5});
  Repaired r;
  const Corner_counts n = repair(s, r);
  SMP::Soup_repair_report want = plain_report(s, 4, 2);
  want.triangulated_polygons = 1;
  want.triangles_from_polygons = 2;
  want.zero_area_triangles = 2;
  check_report(r.report, want);
  BOOST_CHECK_EQUAL(n.on_segment, 4u);
  BOOST_CHECK_EQUAL(n.off_point, 2u);  // X and Y, projected on the segment A B
  for(std::size_t j = 0; j < 4; ++j)
    BOOST_CHECK(face(r.corner(2, j).from, r.mesh) == face(r.corner(0, 0).from, r.mesh));
}

BOOST_AUTO_TEST_CASE(moebius_strip)
{
  // 8 quads around a circle, the strip's direction turning half a turn: the last quad meets
  // the first upside down
  Soup s = moebius_strip_soup(8);
  Repaired r;
  const Corner_counts c = repair(s, r);
  SMP::Soup_repair_report want = plain_report(s, 18, 16);
  want.triangulated_polygons = 8;
  want.triangles_from_polygons = 16;
  want.non_orientable_components = 1;
  want.vertices_split_non_orientable = 2;  // the two ends of the cut, both on the border
  want.reoriented_polygons = r.report.reoriented_polygons;  // checked against the input above
  check_report(r.report, want);
  BOOST_CHECK_LE(r.report.reoriented_polygons, 4u);
  BOOST_CHECK_EQUAL(c.on_halfedge, 32u);
  // the quads are not planar (check_area() leaves them out): each one's two triangles cover it
  // along one of its diagonals
  std::vector<double> area(s.faces.size(), 0.);
  for(face_descriptor f : faces(r.mesh))
    area[r.face_polygon[std::size_t(f)]] += CGAL::Polygon_mesh_processing::face_area(f, r.mesh);
  auto triangle = [&s](std::size_t a, std::size_t b, std::size_t c) {
    return (to_eigen(s.points[b]) - to_eigen(s.points[a])).cross(to_eigen(s.points[c]) - to_eigen(s.points[a])).norm() / 2.;
  };
  for(std::size_t p = 0; p < s.faces.size(); ++p)
  {
    const std::vector<std::size_t>& q = s.faces[p];
    const double along_02 = triangle(q[0], q[1], q[2]) + triangle(q[0], q[2], q[3]);
    const double along_13 = triangle(q[1], q[2], q[3]) + triangle(q[1], q[3], q[0]);
    BOOST_CHECK(std::abs(area[p] - along_02) <= 1e-12 * along_02 || std::abs(area[p] - along_13) <= 1e-12 * along_13);
  }
}

BOOST_AUTO_TEST_CASE(polygons_through_a_point_twice)
{
  const Soup s = polygons_through_a_point_twice_soup();
  Repaired r;
  const Corner_counts n = repair(s, r);
  SMP::Soup_repair_report want = plain_report(s, 10, 4, 3);
  want.degenerate_polygons = 3;
  want.polygons_with_repeated_points = 2;
  want.duplicate_polygons = 1;
  want.pinched_vertices = 1;
  want.vertices_split_non_manifold = 1;
  want.isolated_corners = 3;
  check_report(r.report, want);
  BOOST_CHECK_EQUAL(n.on_segment, 7u);  // the corners of the first two degenerate polygons
  BOOST_CHECK_EQUAL(n.off_point, 0u);
  BOOST_CHECK(face(r.corner(2, 1).from, r.mesh) == face(r.corner(0, 0).from, r.mesh));
}

BOOST_AUTO_TEST_CASE(duplicate_points_are_merged)
{
  // the two triangles of a square, each with its own points (as in an STL file)
  Soup s;
  s.points = {{{0., 0., 0.}}, {{1., 0., 0.}}, {{1., 1., 0.}}, {{0., 0., 0.}}, {{1., 1., 0.}}, {{0., 1., 0.}}};
  s.faces = {{0, 1, 2}, {3, 4, 5}};
  Repaired r;
  repair(s, r);
  SMP::Soup_repair_report want = plain_report(s, 4, 2);
  want.merged_points = 2;
  check_report(r.report, want);
}

// The error for a soup, and nothing output: `r`, filled by an earlier repair, is left empty
// but for the report. Returns the report.
SMP::Soup_repair_report expect_error(const Soup& soup, SMP::Error_code expected)
{
  Repaired r;
  BOOST_REQUIRE_EQUAL(SMP::internal::repair_soup_for_atlas(square().points, square().faces, r), SMP::OK);
  BOOST_CHECK_EQUAL(SMP::internal::repair_soup_for_atlas(soup.points, soup.faces, r), expected);
  BOOST_CHECK(r.mesh.is_empty() && r.mesh.number_of_removed_vertices() == 0);
  BOOST_CHECK(r.face_polygon.empty() && r.face_component.empty());
  BOOST_CHECK(r.corner_offset.empty() && r.corners.empty() && r.zero_area_triangles.empty());
  BOOST_CHECK_EQUAL(r.report.input_polygons, soup.faces.size());
  return r.report;
}

BOOST_AUTO_TEST_CASE(what_cannot_be_textured_is_an_error)
{
  Soup s = square();
  s.points[1][2] = std::numeric_limits<double>::quiet_NaN();
  expect_error(s, SMP::ERROR_NON_FINITE_COORDINATES);
  s.points[1][2] = -std::numeric_limits<double>::infinity();
  expect_error(s, SMP::ERROR_NON_FINITE_COORDINATES);
  s = square();
  s.points.push_back({{0., std::numeric_limits<double>::infinity(), 0.}});  // no polygon has it: an error all the same
  expect_error(s, SMP::ERROR_NON_FINITE_COORDINATES);
  // no face: no polygon, no polygon of 3 distinct points, or all of zero area
  expect_error(Soup(), SMP::ERROR_EMPTY_MESH);
  Soup degenerate = square();
  degenerate.faces = {{0, 1, 0}, {2, 2, 2}, {3}, {}};
  BOOST_CHECK_EQUAL(expect_error(degenerate, SMP::ERROR_EMPTY_MESH).degenerate_polygons, 4u);
  Soup flat = square();
  flat.points[2] = {{2., 0., 0.}};
  flat.faces = {{0, 1, 2}, {2, 1, 0, 3}};
  flat.points[3] = {{3., 0., 0.}};
  BOOST_CHECK_EQUAL(expect_error(flat, SMP::ERROR_EMPTY_MESH).zero_area_triangles, 3u);
  // an index out of range: not a soup
  Soup out_of_range = square();
  out_of_range.faces.push_back({0, 1, 9});
  expect_error(out_of_range, SMP::ERROR_WRONG_PARAMETER);
}

BOOST_AUTO_TEST_CASE(a_soup_that_is_not_a_polygon_mesh_is_built_all_the_same)
{
  // orient_polygon_soup() should leave no such soup; the mesh stage takes one all the same:
  // two triangles running the edge 0 -> 1 the same way, the second detached
  SMP::internal::Working_soup<K::Point_3> soup;
  soup.points = {K::Point_3(0, 0, 0), K::Point_3(1, 0, 0), K::Point_3(0, 1, 0), K::Point_3(0, -1, 0)};
  soup.point_origin = {0, 1, 2, 3};
  soup.polygons.resize(2);
  soup.polygons[0].assign({0, 1, 2});
  soup.polygons[1].assign({0, 1, 3});
  soup.polygons[1].id = 1;
  SMP::Soup_repair_report report;
  SMP::internal::Working_mesh<K::Point_3> w;
  SMP::internal::build_mesh(soup, w, report);
  BOOST_CHECK_EQUAL(report.detached_polygons, 1u);
  BOOST_REQUIRE_EQUAL(w.mesh.number_of_faces(), 2u);
  BOOST_CHECK_EQUAL(w.mesh.number_of_vertices(), 7u);
  // point 3 is left isolated, as isolated input points are: the repair removes them later
  BOOST_CHECK_EQUAL(CGAL::Polygon_mesh_processing::remove_isolated_vertices(w.mesh), 1u);
  BOOST_CHECK(CGAL::is_valid_polygon_mesh(w.mesh));
  BOOST_CHECK_EQUAL(get(w.face_id, face_descriptor(1)), 1u);
  BOOST_CHECK(soup.polygons[1] == std::vector<std::size_t>({4, 5, 6}));
  for(std::size_t k = 0; k < 3; ++k)  // the copies stand for the points they copy
    BOOST_CHECK_EQUAL(get(w.vertex_point, vertex_descriptor(std::uint32_t(4 + k))), std::vector<std::size_t>({0, 1, 3})[k]);
}

BOOST_AUTO_TEST_CASE(orientation_without_cgal_agrees_with_cgal)
{
  // the soups orient_manifold_soup() takes: pinched vertices with closed fans or open ones,
  // reversed faces, a component mostly reversed; not those with a non-manifold edge or a
  // non-orientable piece, which it leaves to CGAL
  Soup pinched_and_flipped = with_reversed_faces(two_cones(), 1, 3);
  append(pinched_and_flipped, with_reversed_faces(grid(6), 0, 2));
  append(pinched_and_flipped, polygons_through_a_point_twice_soup());
  BOOST_CHECK(check_orientations_agree(pinched_and_flipped.points, pinched_and_flipped.faces));
  BOOST_CHECK(check_orientations_agree(grid(4).points, with_reversed_faces(grid(4), 3, 1).faces));
  Soup three_faces;
  three_faces.points = {{{0., 0., 0.}}, {{1., 0., 0.}}, {{.5, 1., 0.}}, {{.5, -1., 0.}}, {{.5, 0., 1.}}};
  three_faces.faces = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  BOOST_CHECK(!check_orientations_agree(three_faces.points, three_faces.faces));
  Soup strip = grid(2);  // a strip whose ends are glued the wrong way: not orientable
  strip.faces = {{0, 1, 4, 3}, {1, 2, 5, 4}, {2, 3, 0, 5}};
  BOOST_CHECK(!check_orientations_agree(strip.points, strip.faces));
}

BOOST_AUTO_TEST_CASE(the_independent_manifold_check_sees_the_defects)
{
  typedef std::vector<std::array<std::size_t, 3> > Triangles;
  auto defects = [](const Triangles& t) { return manifold_defects(t); };
  BOOST_CHECK(defects(Triangles{{{0, 1, 2}}, {{1, 0, 3}}}) == std::make_pair(std::size_t(0), std::size_t(0)));
  BOOST_CHECK(defects(Triangles{{{0, 1, 2}}, {{0, 1, 3}}}).first == 1u);   // a flipped neighbour
  BOOST_CHECK(defects(Triangles{{{0, 1, 2}}, {{1, 0, 3}}, {{0, 1, 4}}}).first == 1u);  // three faces
  BOOST_CHECK(defects(Triangles{{{0, 1, 2}}, {{0, 3, 4}}}).second == 1u);  // two fans at 0
  Triangles cones;  // two closed fans at 0
  for(const std::vector<std::size_t>& f : two_cones().faces)
    cones.push_back({{f[0], f[1], f[2]}});
  BOOST_CHECK(defects(cones) == std::make_pair(std::size_t(0), std::size_t(1)));
}

BOOST_AUTO_TEST_CASE(triangle_mesh_given_directly)
{
  const Mesh input = mbp_test::make_mesh<Mesh>(mbp_test::polar_disk(3, 8));
  // the soup of the mesh as compute_atlas() makes it, with CGAL's function
  std::vector<K::Point_3> points;
  std::vector<std::vector<std::size_t> > polygons;
  CGAL::Polygon_mesh_processing::polygon_mesh_to_polygon_soup(input, points, polygons);
  Repaired r;
  BOOST_REQUIRE_EQUAL(SMP::internal::repair_soup_for_atlas(points, polygons, r), SMP::OK);
  check_mesh(r);
  check_report(r.report, [&] {
    SMP::Soup_repair_report want;
    want.input_points = want.vertices = input.number_of_vertices();
    want.input_polygons = want.faces = input.number_of_faces();
    want.input_corners = 3 * input.number_of_faces();
    want.components = 1;
    return want;
  }());
  // corner i of the soup is the target of the i-th halfedge around the faces of the mesh
  std::vector<boost::graph_traits<Mesh>::halfedge_descriptor> corners;
  for(auto f : faces(input))
    for(auto h : halfedges_around_face(halfedge(f, input), input))
      corners.push_back(h);
  BOOST_REQUIRE_EQUAL(corners.size(), r.corners.size());
  for(std::size_t i = 0; i < corners.size(); ++i)
  {
    BOOST_CHECK(r.corners[i].kind == Source::ON_HALFEDGE);
    BOOST_CHECK(r.mesh.point(target(r.corners[i].from, r.mesh)) == input.point(target(corners[i], input)));
  }
}

// ---------------------------------------------------------------- extended tier: ../shared/data/atlas

namespace {

// The atlas meshes: the folder atlas beside the project's meshes of the extended tier
// (MBP_SHARED_MESH_DIR, ../shared/data/meshes: so ../shared/data/atlas). The test fails when
// it is missing: CTest runs the extended tier only when the project's meshes are there.
std::string atlas_mesh(const std::string& name)
{
  const std::string path = mbp_test::shared_mesh_dir() + "/../atlas/" + name;
  BOOST_REQUIRE_MESSAGE(mbp_test::file_exists(path), "missing atlas mesh " << path
                        << " (the extended tier needs ../atlas beside MBP_SHARED_MESH_DIR)");
  return path;
}

// The counts of PROVENANCE.md that the report can be held to, -1 where not comparable.
// PROVENANCE.md describes the stored mesh before any repair, with faces connected through
// shared vertex indices; the report counts after the points are merged and the degenerate and
// duplicate polygons dropped. So: V and F as read (input points and polygons); duplicate points
// (merged points); non-orientable components; polygons by size (triangulated polygons and the
// triangles they make, n - 2 each); and, on the meshes without duplicate points, degenerate or
// duplicate faces (all but Gravgen, capsule and Spider_binary), non-manifold edges and pinched
// vertices, and the components where there are neither (cycloidal and pig are split at them).
struct Provenance
{
  const char* file;
  long points, polygons, merged, triangulated, triangles, components, non_manifold_edges, pinched, non_orientable;
};

const Provenance atlas_meshes[] = {
  {"1002_tray_bottom.STL", 2216, 4520, 0, 0, 0, 1, 0, 0, 0},
  {"Gravgen.obj", 11803, 17692, 3041, 0, 0, -1, -1, -1, 0},
  {"Spider_binary.stl", 722, 1368, 0, 0, 0, -1, -1, -1, -1},
  {"b9_mesh.off", 5951, 10174, 0, 0, 0, 47, 0, 0, 0},
  {"blobby-shuffled.off", 2027, 4050, 0, 0, 0, 1, 0, 0, 0},
  {"capsule.obj", 5252, 10200, 250, 0, 0, -1, -1, -1, 0},
  {"cycloidal.ply", 21384, 43368, 0, 0, 0, -1, 242, 26, 0},
  {"gazebo.obj", 480, 730, 0, 0, 0, 56, 0, 0, 0},
  {"lion_vase_poly.off", 46206, 23105, 0, 23104, 92407, 1, 0, 0, 0},
  {"lionstatue.obj", 31825, 63338, 0, 0, 0, 1, 0, 0, 0},
  {"moebius.obj", 280, 224, 0, 224, 448, 1, 0, 0, 1},
  {"pig.stl", 8642, 16848, 0, 0, 0, -1, 0, 421, 0},
  {"pizza.obj", 24916, 49954, 0, 0, 0, 1, 0, 0, 0},
  {"plane_holes.obj", 8519, 16747, 0, 0, 0, 1, 0, 0, 0},
  {"sword-quad-dominant.obj", 22293, 22465, 0, 22117, 44234, 1, 0, 0, 0},
};

void check_provenance(const Provenance& want, const SMP::Soup_repair_report& got)
{
  auto same = [&](const char* what, long expected, std::size_t value) {
    if(expected >= 0)
      BOOST_CHECK_MESSAGE(std::size_t(expected) == value,
                          want.file << ": " << what << " " << value << ", PROVENANCE.md " << expected);
  };
  same("points", want.points, got.input_points);
  same("polygons", want.polygons, got.input_polygons);
  same("merged points", want.merged, got.merged_points);
  same("triangulated polygons", want.triangulated, got.triangulated_polygons);
  same("triangles from polygons", want.triangles, got.triangles_from_polygons);
  same("components", want.components, got.components);
  same("non-manifold edges", want.non_manifold_edges, got.non_manifold_edges);
  same("pinched vertices", want.pinched, got.pinched_vertices);
  same("non-orientable components", want.non_orientable, got.non_orientable_components);
}

void print_report(const std::string& file, const SMP::Soup_repair_report& r, const Corner_counts& n)
{
  BOOST_TEST_MESSAGE(file << ": V " << r.input_points << " F " << r.input_polygons << " | merged " << r.merged_points
    << ", degenerate " << r.degenerate_polygons << ", repeated " << r.polygons_with_repeated_points
    << ", duplicates " << r.duplicate_polygons << ", NM edges " << r.non_manifold_edges
    << ", pinched " << r.pinched_vertices << ", non-orientable " << r.non_orientable_components
    << ", split NM " << r.vertices_split_non_manifold << ", split NO " << r.vertices_split_non_orientable
    << ", reoriented " << r.reoriented_polygons << ", triangulated " << r.triangulated_polygons
    << " -> " << r.triangles_from_polygons << ", zero-area " << r.zero_area_triangles
    << ", split after removal " << r.vertices_split_after_removal << " | V " << r.vertices
    << " F " << r.faces << " components " << r.components << " | corners: exact " << n.on_halfedge
    << ", on segment " << n.on_segment << " (" << n.off_point << " projected), collapsed "
    << n.collapsed << ", isolated " << n.isolated);
}

} // namespace

BOOST_AUTO_TEST_CASE(atlas_meshes_repaired, MBP_EXTENDED_TIER)
{
  for(const Provenance& mesh : atlas_meshes)
  {
    BOOST_TEST_CONTEXT(mesh.file)
    {
      std::vector<K::Point_3> points;
      Polygons polygons;
      BOOST_REQUIRE(CGAL::IO::read_polygon_soup(atlas_mesh(mesh.file), points, polygons));
      Repaired r;
      const auto start = std::chrono::steady_clock::now();
      BOOST_REQUIRE_EQUAL(SMP::internal::repair_soup_for_atlas(points, polygons, r), SMP::OK);
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const CGAL::Bbox_3 box = CGAL::bbox_3(points.begin(), points.end());
      const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                        CGAL::square(box.zmax() - box.zmin()));
      check_mesh(r);
      check_faces_against_input(points, polygons, r);
      const Corner_counts n = check_corners(points, polygons, r, 1e-9 * diagonal);
      const bool ours = check_orientations_agree(points, polygons);
      const std::size_t non_planar = check_area(points, polygons, r);
      const std::size_t without_face = check_corner_uvs(polygons, zero_area_polygons(points, polygons), r);
      BOOST_TEST_MESSAGE(mesh.file << ": repaired in " << seconds << " s, oriented by "
                         << (ours ? "orient_manifold_soup()" : "CGAL") << "; " << non_planar
                         << " non-planar polygons, " << without_face << " polygons without a face");
      print_report(mesh.file, r.report, n);
      check_provenance(mesh, r.report);
    }
  }
}

BOOST_AUTO_TEST_SUITE_END()
