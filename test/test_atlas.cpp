// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// The texture atlas from end to end (issue 22): compute_atlas_of_polygon_soup() and
// compute_atlas() on soups with each defect users' files have, on CGAL's data meshes (core
// tier) and on the meshes of ../shared/data/atlas (extended tier). Every check is made on the
// output alone, by code that knows nothing of the package (atlas_check.h and the functions
// below): every input corner has a finite UV in the square, no two UV triangles overlap (in a
// chart or across charts), charts are a gutter apart and from the border, no triangle is
// flipped, and UV area over 3D area is the same in every chart.

#include <boost/test/unit_test.hpp>

#include "atlas_check.h"
#include "atlas_soups.h"
#include "test_support.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>

#include <CGAL/Surface_mesh_parameterization/compute_atlas.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <vector>

BOOST_AUTO_TEST_SUITE(atlas)

namespace SMP = CGAL::Surface_mesh_parameterization;
typedef CGAL::Simple_cartesian<double> K;
typedef K::Point_2                     Point_2;
typedef K::Point_3                     Point_3;
using mbp_test::Soup;

namespace {

struct Atlas_output
{
  std::vector<std::vector<Point_2> > uvs;
  std::vector<std::size_t> charts;
  SMP::Atlas_report report;
};

template <class Points, class Polygons>
Atlas_output atlas_of(const Points& points, const Polygons& polygons, const SMP::Atlas_options& options = {})
{
  Atlas_output out;
  BOOST_REQUIRE_EQUAL(SMP::compute_atlas_of_polygon_soup(points, polygons, out.uvs, out.charts, options, &out.report),
                      SMP::OK);
  return out;
}

// The options of the previous issue's atlas: one chart per component wherever its map is
// one-to-one.
SMP::Atlas_options without_bounds()
{
  SMP::Atlas_options options;
  options.max_area_spread = options.max_angle_distortion = std::numeric_limits<double>::infinity();
  options.min_compactness = 0.;
  return options;
}

template <class P>
Eigen::Vector3d at(const P& p)
{
  return Eigen::Vector3d(CGAL::to_double(p[0]), CGAL::to_double(p[1]), CGAL::to_double(p[2]));
}

// Twice the signed area of a UV polygon (the shoelace formula).
double twice_uv_area(const std::vector<Point_2>& uv)
{
  double sum = 0.;
  for(std::size_t j = 0; j < uv.size(); ++j)
  {
    const Point_2 &a = uv[j], &b = uv[(j + 1) % uv.size()];
    sum += a.x() * b.y() - a.y() * b.x();
  }
  return sum;
}

// The area of a planar 3D polygon (half the norm of Newell's normal).
template <class Points>
double polygon_area(const Points& points, const std::vector<std::size_t>& polygon)
{
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  for(std::size_t j = 0; j < polygon.size(); ++j)
    n += at(points[polygon[j]]).cross(at(points[polygon[(j + 1) % polygon.size()]]));
  return n.norm() / 2.;
}

// Every input corner has a finite UV at least a gutter from the border of the square, and
// every polygon a chart of the report.
template <class Polygons>
void check_corners(const Polygons& polygons, const Atlas_output& a, double gutter)
{
  BOOST_REQUIRE_EQUAL(a.uvs.size(), polygons.size());
  BOOST_REQUIRE_EQUAL(a.charts.size(), polygons.size());
  std::size_t missing = 0, outside = 0;
  for(std::size_t p = 0; p < polygons.size(); ++p)
  {
    missing += a.uvs[p].size() == polygons[p].size() ? 0 : 1;
    BOOST_CHECK_LT(a.charts[p], a.report.charts.size());
    for(const Point_2& uv : a.uvs[p])
      outside += std::isfinite(uv.x()) && std::isfinite(uv.y()) && uv.x() >= gutter * (1 - 1e-9) &&
                         uv.y() >= gutter * (1 - 1e-9) && uv.x() <= 1 - gutter * (1 - 1e-9) &&
                         uv.y() <= 1 - gutter * (1 - 1e-9)
                     ? 0
                     : 1;
  }
  BOOST_CHECK_EQUAL(missing, 0u);
  BOOST_CHECK_EQUAL(outside, 0u);
}

// The UV triangles of each chart: every polygon fanned from its first corner.
void chart_triangles(const Atlas_output& a, std::vector<std::vector<Eigen::Vector2d> >& uv,
                     std::vector<std::vector<std::array<int, 3> > >& triangles)
{
  uv.assign(a.report.charts.size(), {});
  triangles.assign(a.report.charts.size(), {});
  for(std::size_t p = 0; p < a.uvs.size(); ++p)
  {
    const std::size_t c = a.charts[p];
    const int first = int(uv[c].size());
    for(const Point_2& q : a.uvs[p])
      uv[c].emplace_back(q.x(), q.y());
    for(int j = 1; j + 1 < int(a.uvs[p].size()); ++j)
      triangles[c].push_back({{first, first + j, first + j + 1}});
  }
}

// Pairs of UV triangles of one chart whose interiors overlap: each triangle of nonzero area is
// shrunk towards its centroid by a millionth of its size, so that neighbors sharing an edge or
// a vertex are apart, then the exact test of atlas_check.h says whether two of them meet.
std::size_t overlaps_inside_charts(const std::vector<std::vector<Eigen::Vector2d> >& uv,
                                   const std::vector<std::vector<std::array<int, 3> > >& triangles)
{
  std::size_t pairs = 0;
  for(std::size_t c = 0; c < uv.size(); ++c)
  {
    std::vector<mbp_atlas_check::Triangle> shrunk;
    for(const std::array<int, 3>& t : triangles[c])
    {
      const Eigen::Vector2d a = uv[c][std::size_t(t[0])], b = uv[c][std::size_t(t[1])], d = uv[c][std::size_t(t[2])];
      const Eigen::Vector2d g = (a + b + d) / 3.;
      if(std::abs((b - a).x() * (d - a).y() - (b - a).y() * (d - a).x()) <= 1e-24)
        continue;
      auto pull = [&g](const Eigen::Vector2d& p) {
        const Eigen::Vector2d q = p + 1e-6 * (g - p);
        return mbp_atlas_check::K::Point_2(q.x(), q.y());
      };
      shrunk.push_back({{pull(a), pull(b), pull(d)}});
    }
    double distance = 0.;
    for(std::size_t i = 0; i < shrunk.size(); ++i)
      for(std::size_t j = i + 1; j < shrunk.size(); ++j)
        pairs += mbp_atlas_check::triangles_meet(shrunk[i], shrunk[j], distance) ? 1 : 0;
  }
  return pairs;
}

// No overlap in a chart or across charts, the gutter kept between charts (small soups: the
// pairwise test inside charts is quadratic).
void check_layout(const Atlas_output& a, const SMP::Atlas_options& options)
{
  std::vector<std::vector<Eigen::Vector2d> > uv;
  std::vector<std::vector<std::array<int, 3> > > triangles;
  chart_triangles(a, uv, triangles);
  const double gutter = double(options.gutter) / options.resolution;
  const mbp_atlas_check::Atlas_check check = mbp_atlas_check::check_atlas(uv, triangles, gutter);
  BOOST_CHECK_EQUAL(check.non_finite, 0u);
  BOOST_CHECK_EQUAL(check.outside, 0u);
  BOOST_CHECK_EQUAL(check.overlapping_pairs, 0u);
  BOOST_CHECK_EQUAL(check.close_pairs, 0u);
  BOOST_CHECK_EQUAL(overlaps_inside_charts(uv, triangles), 0u);
}

// UV area over 3D area, chart by chart, for soups of planar polygons: equal in every chart
// of nonzero area (one texel density), and equal to the report's density squared.
template <class Points, class Polygons>
void check_density(const Points& points, const Polygons& polygons, const Atlas_output& a)
{
  std::vector<double> area_3d(a.report.charts.size(), 0.), area_uv(a.report.charts.size(), 0.);
  for(std::size_t p = 0; p < polygons.size(); ++p)
  {
    area_3d[a.charts[p]] += polygon_area(points, polygons[p]);
    area_uv[a.charts[p]] += std::abs(twice_uv_area(a.uvs[p])) / 2.;
  }
  const double density = a.report.texel_density * a.report.texel_density;
  for(std::size_t c = 0; c < area_3d.size(); ++c)
    if(area_3d[c] > 1e-12)
      BOOST_CHECK_CLOSE(area_uv[c] / area_3d[c], density, 1e-7);  // percent: 1e-9 relative
}

// Polygons (of nonzero 3D area) whose UV polygon turns clockwise: none for a consistently
// oriented soup (the repair keeps the majority's orientation).
template <class Points, class Polygons>
std::size_t clockwise_polygons(const Points& points, const Polygons& polygons, const Atlas_output& a)
{
  std::size_t clockwise = 0;
  for(std::size_t p = 0; p < polygons.size(); ++p)
    if(polygon_area(points, polygons[p]) > 1e-12)
      clockwise += twice_uv_area(a.uvs[p]) < 0. ? 1 : 0;
  return clockwise;
}

// The checks every atlas passes; `planar`: the density check applies.
Atlas_output check_soup(const Soup& s, bool planar = true, const SMP::Atlas_options& options = {})
{
  const Atlas_output a = atlas_of(s.points, s.faces, options);
  check_corners(s.faces, a, double(options.gutter) / options.resolution);
  check_layout(a, options);
  if(planar)
    check_density(s.points, s.faces, a);
  BOOST_CHECK_GT(a.report.utilization, 0.);
  BOOST_CHECK_LE(a.report.utilization, 1.);
  return a;
}

} // namespace

// ------------------------------------------------------------------ core tier: one defect each

BOOST_AUTO_TEST_CASE(two_components_sharing_nothing)
{
  Soup s = mbp_test::grid(3);
  Soup far = mbp_test::grid(2);
  for(auto& p : far.points)
    p[0] += 10.;
  mbp_test::append(s, far);
  const Atlas_output a = check_soup(s);
  BOOST_CHECK_EQUAL(a.report.repair.components, 2u);
  BOOST_CHECK_EQUAL(a.report.charts.size(), 2u);
  BOOST_CHECK(a.charts.front() != a.charts.back());
  BOOST_CHECK_EQUAL(clockwise_polygons(s.points, s.faces, a), 0u);
}

BOOST_AUTO_TEST_CASE(vertex_shared_by_two_cones)
{
  const Soup s = mbp_test::two_cones();
  const Atlas_output a = check_soup(s);
  BOOST_CHECK_EQUAL(a.report.repair.pinched_vertices, 1u);
  BOOST_CHECK_EQUAL(clockwise_polygons(s.points, s.faces, a), 0u);
}

BOOST_AUTO_TEST_CASE(edge_with_three_faces)
{
  const Soup s = mbp_test::edge_with_three_faces_soup();
  const Atlas_output a = check_soup(s);
  BOOST_CHECK_EQUAL(a.report.repair.non_manifold_edges, 1u);
}

BOOST_AUTO_TEST_CASE(flipped_faces)
{
  const Soup s = mbp_test::with_reversed_faces(mbp_test::grid(4), 1, 7);
  const Atlas_output a = check_soup(s);
  const std::size_t reversed = (s.faces.size() - 1 + 6) / 7;
  BOOST_CHECK_EQUAL(a.report.repair.reoriented_polygons, reversed);
  // the reversed faces, in their input order, turn the other way in UV: nothing else does
  BOOST_CHECK_EQUAL(clockwise_polygons(s.points, s.faces, a), reversed);
}

BOOST_AUTO_TEST_CASE(duplicated_face)
{
  Soup s = mbp_test::grid(2);
  s.faces.push_back(s.faces[3]);
  const Atlas_output a = atlas_of(s.points, s.faces);
  BOOST_CHECK_EQUAL(a.report.repair.duplicate_polygons, 1u);
  // the duplicate lies on the face it repeats, in 3D and in UV
  BOOST_CHECK(a.uvs.back() == a.uvs[3]);
  BOOST_CHECK_EQUAL(a.charts.back(), a.charts[3]);
  // without it, the atlas of the grid
  Atlas_output rest = a;
  rest.uvs.pop_back();
  rest.charts.pop_back();
  s.faces.pop_back();
  check_corners(s.faces, rest, 2. / 1024);
  check_layout(rest, SMP::Atlas_options());
  check_density(s.points, s.faces, rest);
}

BOOST_AUTO_TEST_CASE(zero_area_face)
{
  const Soup s = mbp_test::zero_area_face_on_an_edge_soup();
  const Atlas_output a = check_soup(s);
  BOOST_CHECK_EQUAL(a.report.repair.zero_area_triangles, 1u);
  // the sliver (polygon 3) gets a zero-area UV triangle, inside the square
  BOOST_CHECK_SMALL(twice_uv_area(a.uvs[3]), 1e-12);
}

BOOST_AUTO_TEST_CASE(quads_and_a_pentagon)
{
  const Soup s = mbp_test::quads_and_a_pentagon_soup();
  const Atlas_output a = check_soup(s);
  BOOST_CHECK_EQUAL(a.report.repair.triangulated_polygons, 3u);
  BOOST_CHECK_EQUAL(clockwise_polygons(s.points, s.faces, a), 0u);
}

// The seams of a closed surface of quads go around the quads, never through a diagonal: every
// quad keeps one UV per corner (a quad cut by a seam would get corners from both sides: its UV
// polygon would overlap its neighbors' or turn clockwise).
BOOST_AUTO_TEST_CASE(seams_keep_polygons_whole)
{
  const Soup s = mbp_test::sheared_quad_torus(16);
  const Atlas_output a = check_soup(s, false, without_bounds());  // non-planar quads; one chart
  BOOST_CHECK_EQUAL(a.report.repair.triangulated_polygons, s.faces.size());
  BOOST_CHECK_EQUAL(a.report.charts.size(), 1u);
  BOOST_CHECK_EQUAL(a.report.charts[0].flattening, SMP::SEAMED_CHART);
  BOOST_CHECK_EQUAL(clockwise_polygons(s.points, s.faces, a), 0u);
}

BOOST_AUTO_TEST_CASE(moebius_strip)
{
  const Soup s = mbp_test::moebius_strip_soup(12);
  const Atlas_output a = check_soup(s, false);  // non-planar quads
  BOOST_CHECK_EQUAL(a.report.repair.non_orientable_components, 1u);
}

BOOST_AUTO_TEST_CASE(gutter_and_resolution_are_kept)
{
  Soup s;
  for(int k = 0; k < 6; ++k)
  {
    Soup piece = mbp_test::grid(1 + k % 3);
    for(auto& p : piece.points)
      p = {{p[0] * (1 + k), p[1], p[2] + 3. * k}};
    mbp_test::append(s, piece);
  }
  SMP::Atlas_options options;
  options.resolution = 128;
  options.gutter = 5;
  options.min_compactness = 0.;  // the rectangles, up to 6 times as long as wide, are kept whole
  const Atlas_output a = check_soup(s, true, options);
  BOOST_CHECK_EQUAL(a.report.charts.size(), 6u);
}

BOOST_AUTO_TEST_CASE(what_cannot_be_textured_is_an_error)
{
  std::vector<std::vector<Point_2> > uvs(1, std::vector<Point_2>(3));
  std::vector<std::size_t> charts(1, 7);
  const std::vector<Point_3> none;
  const std::vector<std::vector<std::size_t> > no_polygon;
  BOOST_CHECK_EQUAL(SMP::compute_atlas_of_polygon_soup(none, no_polygon, uvs, charts), SMP::ERROR_EMPTY_MESH);
  BOOST_CHECK(uvs.empty() && charts.empty());
  Soup s = mbp_test::grid(2);
  s.points[4][2] = std::numeric_limits<double>::quiet_NaN();
  BOOST_CHECK_EQUAL(SMP::compute_atlas_of_polygon_soup(s.points, s.faces, uvs, charts),
                    SMP::ERROR_NON_FINITE_COORDINATES);
  BOOST_CHECK(uvs.empty() && charts.empty());
  SMP::Atlas_options bad;
  bad.gutter = bad.resolution;
  const Soup t = mbp_test::grid(2);
  BOOST_CHECK_EQUAL(SMP::compute_atlas_of_polygon_soup(t.points, t.faces, uvs, charts, bad), SMP::ERROR_WRONG_PARAMETER);
}

// The face graph form writes the same UVs and charts as the soup form, on a Surface_mesh and
// on a Polyhedron_3 (quads: polygon meshes are accepted).
template <class Mesh>
void check_face_graph_form(const Soup& s)
{
  Mesh mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(s.points, s.faces, mesh);
  typedef typename boost::graph_traits<Mesh>::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::graph_traits<Mesh>::face_descriptor face_descriptor;
  auto uv = get(CGAL::dynamic_halfedge_property_t<Point_2>(), mesh);
  auto chart = get(CGAL::dynamic_face_property_t<std::size_t>(), mesh);
  SMP::Atlas_report report;
  BOOST_REQUIRE_EQUAL(SMP::compute_atlas(mesh, uv, chart, SMP::Atlas_options(), &report), SMP::OK);
  const Atlas_output a = atlas_of(s.points, s.faces);
  std::size_t p = 0, differences = 0;
  for(face_descriptor f : faces(mesh))
  {
    std::size_t j = 0;
    for(halfedge_descriptor h : halfedges_around_face(halfedge(f, mesh), mesh))
      differences += get(uv, h) == a.uvs[p][j++] ? 0 : 1;
    differences += get(chart, f) == a.charts[p] ? 0 : 1;
    ++p;
  }
  BOOST_CHECK_EQUAL(differences, 0u);
  BOOST_CHECK_EQUAL(report.charts.size(), a.report.charts.size());
}

BOOST_AUTO_TEST_CASE(face_graph_form)
{
  check_face_graph_form<CGAL::Surface_mesh<Point_3> >(mbp_test::quads_and_a_pentagon_soup());
  check_face_graph_form<CGAL::Polyhedron_3<K> >(mbp_test::quads_and_a_pentagon_soup());
}

// ------------------------------------------- core tier: charts within the bounds (issue 23)

namespace {

// The largest |log(UV area / (3D area x density^2))| over the polygons of nonzero 3D area:
// 0 when every polygon keeps its area at the atlas' one density (planar polygons).
template <class Points, class Polygons>
double largest_area_distortion(const Points& points, const Polygons& polygons, const Atlas_output& a)
{
  const double density = a.report.texel_density * a.report.texel_density;
  double largest = 0.;
  for(std::size_t p = 0; p < polygons.size(); ++p)
  {
    const double area_3d = polygon_area(points, polygons[p]);
    if(area_3d > 1e-12)
      largest = (std::max)(largest, std::abs(std::log(std::abs(twice_uv_area(a.uvs[p])) / 2. / (area_3d * density))));
  }
  return largest;
}

// The largest |UV angle - 3D angle| over the corners of the polygons (planar polygons).
template <class Points, class Polygons>
double largest_angle_change(const Points& points, const Polygons& polygons, const Atlas_output& a)
{
  double largest = 0.;
  for(std::size_t p = 0; p < polygons.size(); ++p)
  {
    const std::size_t n = polygons[p].size();
    for(std::size_t j = 0; j < n; ++j)
    {
      const Eigen::Vector3d o = at(points[polygons[p][j]]);
      const Eigen::Vector3d e = at(points[polygons[p][(j + 1) % n]]) - o, g = at(points[polygons[p][(j + n - 1) % n]]) - o;
      const Eigen::Vector2d uo(a.uvs[p][j].x(), a.uvs[p][j].y());
      const Eigen::Vector2d ue = Eigen::Vector2d(a.uvs[p][(j + 1) % n].x(), a.uvs[p][(j + 1) % n].y()) - uo;
      const Eigen::Vector2d ug = Eigen::Vector2d(a.uvs[p][(j + n - 1) % n].x(), a.uvs[p][(j + n - 1) % n].y()) - uo;
      const double angle_3d = std::atan2(e.cross(g).norm(), e.dot(g));
      const double angle_uv = std::atan2(std::abs(ue.x() * ug.y() - ue.y() * ug.x()), ue.dot(ug));
      largest = (std::max)(largest, std::abs(angle_3d - angle_uv));
    }
  }
  return largest;
}

} // namespace

// A developable strip wound 1.5 turns around a cone unrolls to more than a turn: one chart
// cannot be both one-to-one and undistorted (without bounds: one chart, one-to-one, its area
// distorted). Within the distortion bounds: one-to-one, and every quad keeps its shape and its
// area, in two charts, each less than a turn. The default compactness bound (0.3) cuts the
// shorter one (an arc of about 195 degrees, compactness 0.27) once more across, its UVs kept:
// three charts, still undistorted.
BOOST_AUTO_TEST_CASE(strip_around_a_cone)
{
  const Soup s = mbp_test::strip_around_a_cone(120);
  const Atlas_output one = check_soup(s, true, without_bounds());
  BOOST_CHECK_EQUAL(one.report.charts.size(), 1u);
  BOOST_CHECK_GT(largest_area_distortion(s.points, s.faces, one), 0.1);
  SMP::Atlas_options distortion_only;
  distortion_only.min_compactness = 0.;
  for(const SMP::Atlas_options& options : {distortion_only, SMP::Atlas_options()})
  {
    const Atlas_output a = check_soup(s, true, options);
    BOOST_TEST_MESSAGE("strip around a cone, compactness >= " << options.min_compactness << ": " << a.report.charts.size()
                       << " charts, " << a.report.splits << " splits; largest area distortion "
                       << largest_area_distortion(s.points, s.faces, a) << ", angle change "
                       << largest_angle_change(s.points, s.faces, a) << " (one chart: "
                       << largest_area_distortion(s.points, s.faces, one) << ", "
                       << largest_angle_change(s.points, s.faces, one) << ")");
    BOOST_CHECK_LE(a.report.charts.size(), options.min_compactness > 0. ? 3u : 2u);
    BOOST_CHECK_LT(largest_area_distortion(s.points, s.faces, a), 1e-6);
    BOOST_CHECK_LT(largest_angle_change(s.points, s.faces, a), 1e-6);
    BOOST_CHECK_EQUAL(clockwise_polygons(s.points, s.faces, a), 0u);
  }
}

// A cube: at most six charts, each undistorted (every quad keeps its shape and its area).
BOOST_AUTO_TEST_CASE(cube_in_flat_charts)
{
  const Soup s = mbp_test::cube_of_quads(4);
  for(SMP::Atlas_split split : {SMP::SPLIT_BY_NORMALS, SMP::SPLIT_BY_SCALE})
  {
    SMP::Atlas_options options;
    options.split = split;
    const Atlas_output a = check_soup(s, true, options);
    BOOST_TEST_MESSAGE("cube, split " << int(split) << ": " << a.report.charts.size() << " charts, largest area distortion "
                       << largest_area_distortion(s.points, s.faces, a));
    BOOST_CHECK_LE(a.report.charts.size(), 6u);
    BOOST_CHECK_LT(largest_area_distortion(s.points, s.faces, a), 1e-6);
    BOOST_CHECK_LT(largest_angle_change(s.points, s.faces, a), 1e-6);
    for(const SMP::Atlas_chart_report& c : a.report.charts)
      BOOST_CHECK(c.area_spread <= options.max_area_spread && c.angle_distortion <= options.max_angle_distortion);
  }
}

// The bounds hold chart by chart on a curved closed surface, and a tighter bound gives more
// charts of lower spread; bad bounds are refused.
BOOST_AUTO_TEST_CASE(bounds_are_kept)
{
  const Soup s = mbp_test::sheared_quad_torus(24);
  std::size_t previous_charts = 0;
  for(double bound : {0.4, 0.1, 0.03})
  {
    SMP::Atlas_options options;
    options.max_area_spread = bound;
    const Atlas_output a = check_soup(s, false, options);
    for(const SMP::Atlas_chart_report& c : a.report.charts)
      BOOST_CHECK_LE(c.area_spread, bound);
    BOOST_CHECK_GE(a.report.charts.size(), previous_charts);
    previous_charts = a.report.charts.size();
  }
  std::vector<std::vector<Point_2> > uvs;
  std::vector<std::size_t> charts;
  SMP::Atlas_options bad;
  bad.max_area_spread = std::numeric_limits<double>::quiet_NaN();
  BOOST_CHECK_EQUAL(SMP::compute_atlas_of_polygon_soup(s.points, s.faces, uvs, charts, bad), SMP::ERROR_WRONG_PARAMETER);
  bad = SMP::Atlas_options();
  bad.min_compactness = -1.;
  BOOST_CHECK_EQUAL(SMP::compute_atlas_of_polygon_soup(s.points, s.faces, uvs, charts, bad), SMP::ERROR_WRONG_PARAMETER);
}

// Corners of one vertex a rounding apart get one UV; copies of a vertex far apart (the two
// sides of a seam) keep theirs.
BOOST_AUTO_TEST_CASE(corners_a_rounding_apart_are_welded)
{
  SMP::internal::Atlas_triangles t;
  t.points = {Eigen::Vector3d(0., 0., 0.), Eigen::Vector3d(1., 0., 0.), Eigen::Vector3d(1., 1., 0.),
              Eigen::Vector3d(0., 1., 0.)};
  t.faces = {{{0, 1, 2}}, {{0, 2, 3}}};
  SMP::internal::Atlas_chart chart;
  chart.faces = {0, 1};
  const Eigen::Vector2d a(0., 0.), b(1., 0.), c(1., 1.), d(0., 1.);
  chart.corners = {{{a, b, c}}, {{a, Eigen::Vector2d(std::nextafter(1., 2.), 1.), d}}};
  BOOST_CHECK(SMP::internal::weld_rounded_corners(t, chart));
  BOOST_CHECK(chart.corners[1][1] == c);
  BOOST_CHECK(SMP::internal::is_one_to_one_chart(t, chart));
  BOOST_CHECK(!SMP::internal::weld_rounded_corners(t, chart));  // nothing left to weld
  chart.corners[1] = {{Eigen::Vector2d(0., 3.), Eigen::Vector2d(1., 3.), Eigen::Vector2d(0., 4.)}};  // a seam's other side
  BOOST_CHECK(!SMP::internal::weld_rounded_corners(t, chart));
  BOOST_CHECK(chart.corners[1][0] == Eigen::Vector2d(0., 3.));
}

// A fan around the origin whose last triangle comes back to within `gap` of the first one's
// edge, not joined to it (a T-junction's crack of a CAD mesh): its unfolding is the plane
// itself. Within the clearance (relative 1e-10) the chart is refused, since the packing's
// rotation and scale could round it over; a real gap passes; the atlas of the crack has no
// overlapping pair.
BOOST_AUTO_TEST_CASE(a_crack_within_the_clearance_is_not_one_to_one)
{
  for(double gap : {1e-14, 1e-12, 1e-3})
    BOOST_TEST_CONTEXT("gap " << gap)
    {
      Soup s;
      s.points = {{{0., 0., 0.}}, {{2., 0., 0.}}, {{1., 1., 0.}}, {{-1., 0., 0.}}, {{0.5, -1., 0.}}, {{1., -gap, 0.}}};
      s.faces = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 5}};
      SMP::internal::Atlas_triangles t;
      for(const auto& p : s.points)
        t.points.emplace_back(p[0], p[1], p[2]);
      for(const auto& f : s.faces)
        t.faces.push_back({{int(f[0]), int(f[1]), int(f[2])}});
      const SMP::internal::Atlas_chart chart = SMP::internal::unfold_isometrically(t, {0, 1, 2, 3});
      BOOST_TEST(SMP::internal::is_one_to_one_chart(t, chart) == (gap > 1e-9));
      const Atlas_output a = check_soup(s, true, SMP::Atlas_options());
      BOOST_TEST((gap > 1e-9 ? a.report.charts.size() == 1u : a.report.charts.size() >= 2u));
    }
}

namespace {

// Unit quads in z = 0 at the cells (i, j), turning counterclockwise seen from +z; shared
// corners listed once.
Soup quads_at(const std::vector<std::array<int, 2> >& cells)
{
  Soup s;
  std::map<std::array<int, 2>, std::size_t> id;
  auto point = [&](int i, int j) {
    const auto inserted = id.emplace(std::array<int, 2>{{i, j}}, s.points.size());
    if(inserted.second)
      s.points.push_back({{double(i), double(j), 0.}});
    return inserted.first->second;
  };
  for(const std::array<int, 2>& c : cells)
    s.faces.push_back({point(c[0], c[1]), point(c[0] + 1, c[1]), point(c[0] + 1, c[1] + 1), point(c[0], c[1] + 1)});
  return s;
}

// The quads of a soup as the atlas's triangle set (equal points merged, two triangles per
// quad, one polygon), and a chart of all its faces whose UVs are the 3D points scaled by 2 (a
// one-to-one map in the plane z = 0).
void quads_as_chart(const Soup& s, SMP::internal::Atlas_triangles& t, SMP::internal::Atlas_chart& chart)
{
  std::map<std::array<double, 3>, int> id;
  std::vector<int> point_id;
  for(const auto& p : s.points)
  {
    point_id.push_back(id.emplace(p, int(t.points.size())).first->second);
    if(point_id.back() == int(t.points.size()))
      t.points.emplace_back(p[0], p[1], p[2]);
  }
  for(std::size_t q = 0; q < s.faces.size(); ++q)
    for(const std::array<std::size_t, 3>& k : {std::array<std::size_t, 3>{{0, 1, 2}}, std::array<std::size_t, 3>{{0, 2, 3}}})
    {
      t.faces.push_back({{point_id[s.faces[q][k[0]]], point_id[s.faces[q][k[1]]], point_id[s.faces[q][k[2]]]}});
      t.face_polygon.push_back(q);
      chart.faces.push_back(t.faces.size() - 1);
      chart.corners.emplace_back();
      for(std::size_t c = 0; c < 3; ++c)
        chart.corners.back()[c] = 2. * t.points[std::size_t(t.faces.back()[c])].head<2>();
    }
}

} // namespace

// A U of quads (two arms 10 long, 5 apart) cut across its longer side (its height) at the
// middle: the bottom half (one U-shaped island) and the two tops of the arms (two islands).
// Each face keeps its UVs exactly, each quad goes whole to one piece, the pieces partition
// the faces and each spans half the height.
BOOST_AUTO_TEST_CASE(a_cut_across_keeps_the_uvs)
{
  std::vector<std::array<int, 2> > cells;
  for(int j = 0; j < 10; ++j)
    cells.push_back({{0, j}}), cells.push_back({{4, j}});
  for(int i = 1; i < 4; ++i)
    cells.push_back({{i, 0}});
  SMP::internal::Atlas_triangles t;
  SMP::internal::Atlas_chart chart;
  quads_as_chart(quads_at(cells), t, chart);
  SMP::internal::chart_area_figures(t, chart);
  SMP::internal::chart_compactness(chart);  // the smallest box, which the cut goes across
  const std::vector<SMP::internal::Atlas_chart> pieces = SMP::internal::cut_across(t, chart);
  BOOST_REQUIRE_EQUAL(pieces.size(), 3u);
  std::vector<int> piece_of(t.faces.size(), -1);
  std::vector<int> polygon_piece(cells.size(), -1);
  for(std::size_t p = 0; p < pieces.size(); ++p)
  {
    BOOST_REQUIRE_EQUAL(pieces[p].corners.size(), pieces[p].faces.size());
    double low = HUGE_VAL, high = -HUGE_VAL;
    for(std::size_t i = 0; i < pieces[p].faces.size(); ++i)
    {
      const std::size_t f = pieces[p].faces[i];
      BOOST_CHECK_EQUAL(piece_of[f], -1);
      piece_of[f] = int(p);
      BOOST_CHECK(pieces[p].corners[i] == chart.corners[f]);  // face f is chart face f
      int& polygon = polygon_piece[t.face_polygon[f]];
      BOOST_CHECK(polygon == -1 || polygon == int(p));
      polygon = int(p);
      for(const Eigen::Vector2d& uv : pieces[p].corners[i])
        low = (std::min)(low, uv.y()), high = (std::max)(high, uv.y());
    }
    BOOST_CHECK_CLOSE(high - low, 10., 1e-9);  // half of the height 20 (UVs: 2 x the 3D points)
  }
  BOOST_CHECK(std::count(piece_of.begin(), piece_of.end(), -1) == 0);
}

// The number of parts of a split of a chart cut open by seams: 1 + ceil(log2 r) for a map r
// times over the larger of its two bounds' ratios, 2 to 8; a disk's: the same from 2 to 3,
// and 2 when r < 4.
BOOST_AUTO_TEST_CASE(a_chart_far_over_the_bounds_is_split_into_more_parts)
{
  SMP::Atlas_options options;
  options.max_area_spread = 0.2;
  options.max_angle_distortion = 0.1;
  const SMP::internal::Chart_bounds bounds{options, 0.};
  SMP::internal::Atlas_chart chart;
  chart.flattening = SMP::DISK_CHART;
  for(const std::array<double, 3>& c : {std::array<double, 3>{{0.3, 0., 2.}}, std::array<double, 3>{{0.79, 0.05, 2.}},
                                        std::array<double, 3>{{0.1, 0.39, 2.}}, std::array<double, 3>{{0.8, 0., 3.}},
                                        std::array<double, 3>{{0.1, 0.4, 3.}}, std::array<double, 3>{{20., 0., 3.}}})
  {
    chart.area_spread = c[0];
    chart.angle_distortion = c[1];
    BOOST_CHECK_EQUAL(SMP::internal::split_count(chart, bounds), std::size_t(c[2]));
  }
  chart.flattening = SMP::SEAMED_CHART;
  for(const std::array<double, 3>& c : {std::array<double, 3>{{0.3, 0., 2.}}, std::array<double, 3>{{0.8, 0.05, 3.}},
                                        std::array<double, 3>{{0.81, 0.05, 4.}}, std::array<double, 3>{{0.1, 0.35, 3.}},
                                        std::array<double, 3>{{0.1, 0.41, 4.}}, std::array<double, 3>{{20., 0., 8.}},
                                        std::array<double, 3>{{1e300, 0., 8.}}})
  {
    chart.area_spread = c[0];
    chart.angle_distortion = c[1];
    BOOST_CHECK_EQUAL(SMP::internal::split_count(chart, bounds), std::size_t(c[2]));
  }
}

// A cube split into 2, 3 and 6 parts by normals (split_sides()): exactly that many parts, each
// connected, each side of the cube (a flat patch) and each quad whole in one part; in 6 parts,
// one side each.
BOOST_AUTO_TEST_CASE(a_split_into_parts_keeps_flat_sides_whole)
{
  SMP::internal::Atlas_triangles t;
  SMP::internal::Atlas_chart chart;
  quads_as_chart(mbp_test::cube_of_quads(4), t, chart);
  auto side_of = [&](std::size_t f) {  // the cube's side of a face: its normal's axis and sign
    const Eigen::Vector3d& a = t.points[std::size_t(t.faces[f][0])];
    const Eigen::Vector3d n = (t.points[std::size_t(t.faces[f][1])] - a).cross(t.points[std::size_t(t.faces[f][2])] - a);
    Eigen::Index axis;
    n.cwiseAbs().maxCoeff(&axis);
    return int(2 * axis) + (n[axis] > 0. ? 1 : 0);
  };
  for(std::size_t count : {2u, 3u, 6u})
    BOOST_TEST_CONTEXT(count << " parts")
    {
      const std::vector<int> part = SMP::internal::split_sides(t, chart.faces, SMP::internal::subset_neighbors(t, chart.faces),
                                                               SMP::SPLIT_BY_NORMALS, nullptr, count);
      std::vector<std::vector<std::size_t> > faces(count);
      std::map<int, int> part_of_side;
      std::map<std::size_t, int> part_of_quad;
      for(std::size_t i = 0; i < part.size(); ++i)
      {
        BOOST_REQUIRE(part[i] >= 0 && std::size_t(part[i]) < count);
        faces[std::size_t(part[i])].push_back(chart.faces[i]);
        BOOST_CHECK_EQUAL(part_of_side.emplace(side_of(chart.faces[i]), part[i]).first->second, part[i]);
        BOOST_CHECK_EQUAL(part_of_quad.emplace(t.face_polygon[chart.faces[i]], part[i]).first->second, part[i]);
      }
      BOOST_CHECK_EQUAL(part_of_side.size(), 6u);
      for(const std::vector<std::size_t>& f : faces)
        BOOST_CHECK_EQUAL(SMP::internal::edge_components(t, f).size(), 1u);  // not empty, connected
      if(count == 6)
        for(const std::vector<std::size_t>& f : faces)
          BOOST_CHECK_EQUAL(f.size(), t.faces.size() / 6);
    }
}

// corners_by_vertex() (Boost's integer_sort of packed keys) against std::sort of the
// (vertex, corner) pairs, on small and large charts, with vertex ids beyond 16 and 21 bits.
BOOST_AUTO_TEST_CASE(corners_are_ordered_by_vertex_as_sorted_pairs)
{
  std::mt19937 random(5);
  for(std::size_t faces : {5u, 600u, 700u, 5000u})
    for(int range : {50, 70000, 3000000})
      BOOST_TEST_CONTEXT(faces << " faces, vertices below " << range)
      {
        SMP::internal::Atlas_triangles t;
        SMP::internal::Atlas_chart chart;
        std::uniform_int_distribution<int> vertex(0, range - 1);
        for(std::size_t f = 0; f < faces; ++f)
        {
          t.faces.push_back({{vertex(random), vertex(random), vertex(random)}});
          chart.faces.push_back(faces - 1 - f);  // not in the order of t
        }
        chart.corners.resize(faces);
        std::vector<std::pair<int, std::size_t> > pairs;
        for(std::size_t c = 0; c < 3 * faces; ++c)
          pairs.emplace_back(t.faces[chart.faces[c / 3]][c % 3], c);
        std::sort(pairs.begin(), pairs.end());
        const std::vector<std::uint32_t> corners = SMP::internal::corners_by_vertex(t, chart);
        BOOST_REQUIRE_EQUAL(corners.size(), pairs.size());
        bool same = true;
        for(std::size_t i = 0; i < corners.size(); ++i)
          same = same && corners[i] == pairs[i].second;
        BOOST_TEST(same);
      }
}

// A flattened chart's angle distortion is the parameterizer's (of the layout it kept; the
// measure of the chart then does not compute it): it equals chart_angle_distortion() of the
// chart's UVs, on a disk (an open box, where the circle's layout and the conformal border's
// differ) and on a closed surface cut open by seams (the cube).
BOOST_AUTO_TEST_CASE(a_flattened_chart_has_the_angle_distortion_of_its_uvs)
{
  SMP::internal::Atlas_triangles t;
  SMP::internal::Atlas_chart cube;
  quads_as_chart(mbp_test::cube_of_quads(4), t, cube);
  std::vector<std::size_t> open_box;  // the cube without its side of normal +z
  for(std::size_t f : cube.faces)
  {
    const Eigen::Vector3d& a = t.points[std::size_t(t.faces[f][0])];
    const Eigen::Vector3d n = (t.points[std::size_t(t.faces[f][1])] - a).cross(t.points[std::size_t(t.faces[f][2])] - a);
    if(!(n.z() > 0.5 * n.norm()))
      open_box.push_back(f);
  }
  BOOST_REQUIRE_EQUAL(open_box.size(), cube.faces.size() * 5 / 6);
  const SMP::Atlas_options options;
  for(const auto& c : {std::make_pair(open_box, SMP::DISK_CHART), std::make_pair(cube.faces, SMP::SEAMED_CHART)})
    for(bool whole : {true, false})  // with the holomorphic extension of a layout within the bound, and without
    {
      SMP::internal::Atlas_chart chart;
      BOOST_REQUIRE(SMP::internal::flatten_subset(t, c.first, SMP::internal::subset_neighbors(t, c.first), options, whole, chart));
      BOOST_CHECK(chart.flattening == c.second);
      BOOST_CHECK(chart.angle_known);
      SMP::internal::Atlas_chart again = chart;
      SMP::internal::chart_angle_distortion(t, again);
      BOOST_CHECK_GT(again.angle_distortion, 0.);
      BOOST_CHECK_SMALL(chart.angle_distortion - again.angle_distortion, 1e-12 * (1. + again.angle_distortion));
    }
}

// A flat strip of 16 unit quads: one chart has compactness 1/16 and fills a sixteenth of the
// square at most. Within the default bounds it is cut across (16 -> 8 -> 4 -> 2 quads: a piece
// of 4 has compactness 0.25 < 0.3 and is longer than half the side of a square of the strip's
// area; a piece of 2 has 0.5): 8 undistorted charts after 7 cuts, which fill the square more
// than twice as well.
BOOST_AUTO_TEST_CASE(a_long_strip_is_cut_into_compact_charts)
{
  std::vector<std::array<int, 2> > cells;
  for(int i = 0; i < 16; ++i)
    cells.push_back({{i, 0}});
  const Soup s = quads_at(cells);
  const Atlas_output one = check_soup(s, true, without_bounds());
  BOOST_CHECK_EQUAL(one.report.charts.size(), 1u);
  const Atlas_output a = check_soup(s);
  BOOST_TEST_MESSAGE("strip of 16 quads: " << a.report.charts.size() << " charts, " << a.report.splits
                     << " cuts, utilization " << a.report.utilization << " (one chart: " << one.report.utilization << ")");
  BOOST_CHECK_EQUAL(a.report.charts.size(), 8u);
  BOOST_CHECK_EQUAL(a.report.splits, 7u);
  for(const SMP::Atlas_chart_report& c : a.report.charts)
    BOOST_CHECK_CLOSE(c.compactness, 0.5, 1e-6);
  BOOST_CHECK_LT(largest_area_distortion(s.points, s.faces, a), 1e-6);
  BOOST_CHECK_LT(largest_angle_change(s.points, s.faces, a), 1e-6);
  BOOST_CHECK_GT(a.report.utilization, 2. * one.report.utilization);
}

// ----------------------------------------------------------- core tier: CGAL's data meshes

namespace {

// A mesh file read as a soup, its atlas checked (without the quadratic test inside charts on
// big meshes: the charts' own validity is the parameterizers' and is tested there).
Atlas_output check_file(const std::string& file, std::size_t& polygons_out)
{
  std::vector<Point_3> points;
  std::vector<std::vector<std::size_t> > polygons;
  BOOST_REQUIRE_MESSAGE(CGAL::IO::read_polygon_soup(file, points, polygons) && !polygons.empty(), file);
  const SMP::Atlas_options options;
  const Atlas_output a = atlas_of(points, polygons, options);
  check_corners(polygons, a, double(options.gutter) / options.resolution);
  std::vector<std::vector<Eigen::Vector2d> > uv;
  std::vector<std::vector<std::array<int, 3> > > triangles;
  chart_triangles(a, uv, triangles);
  const mbp_atlas_check::Atlas_check check =
      mbp_atlas_check::check_atlas(uv, triangles, double(options.gutter) / options.resolution);
  BOOST_CHECK_MESSAGE(check.overlapping_pairs == 0 && check.close_pairs == 0,
                      file << ": " << check.overlapping_pairs << " overlapping pairs, " << check.close_pairs
                           << " pairs closer than the gutter");
  polygons_out = polygons.size();
  return a;
}

void print_figures(const std::string& name, std::size_t polygons, const SMP::Atlas_report& r)
{
  BOOST_TEST_MESSAGE(name << ": " << polygons << " polygons, " << r.charts.size() << " charts, utilization "
                          << r.utilization << ", angle distortion " << r.angle_distortion << ", area spread "
                          << r.area_spread << "; " << r.total_seconds << " s (repair " << r.repair_seconds
                          << ", charts " << r.chart_seconds << ", packing " << r.packing_seconds << ")");
}

} // namespace

BOOST_AUTO_TEST_CASE(cgal_data_meshes)
{
  for(const char* name : {"blobby_3cc.off", "cube_quad.off", "blobby-shuffled.off", "cross_quad.off"})
  {
    std::size_t polygons = 0;
    const Atlas_output a = check_file(mbp_test::core_mesh(name), polygons);
    print_figures(name, polygons, a.report);
  }
}

// ------------------------------------------------------ extended tier: ../shared/data/atlas

BOOST_AUTO_TEST_CASE(atlas_meshes, MBP_EXTENDED_TIER)
{
  const std::string dir = mbp_test::shared_mesh_dir() + "/../atlas";
  for(const char* name : {"1002_tray_bottom.STL", "Gravgen.obj", "Spider_binary.stl", "b9_mesh.off",
                          "blobby-shuffled.off", "capsule.obj", "cycloidal.ply", "gazebo.obj", "lion_vase_poly.off",
                          "lionstatue.obj", "moebius.obj", "pig.stl", "pizza.obj", "plane_holes.obj",
                          "sword-quad-dominant.obj"})
  {
    std::size_t polygons = 0;
    const Atlas_output a = check_file(dir + "/" + name, polygons);
    print_figures(name, polygons, a.report);
  }
}

BOOST_AUTO_TEST_SUITE_END()
