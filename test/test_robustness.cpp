// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// Robustness to bad or tricky input (issue 15's edges, from test_edges.cpp), each against an
// independent oracle:
//  - a user's center that is not a vertex of the mesh is a wrong parameter (no out-of-bounds
//    read);
//  - border loops of equal length: main_border()'s documented tie rule, invariant under
//    similarities and mirrors;
//  - a pinched disk (a vertex whose faces form several fans) is ERROR_NO_TOPOLOGICAL_DISC,
//    whatever the order of the faces, for every entry point that takes a disk.

#include <boost/test/unit_test.hpp>

#include "test_support.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include <CGAL/Surface_mesh_parameterization/Conformal_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Conformal_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Default_sparse_cholesky_traits.h>
#include <CGAL/Surface_mesh_parameterization/Fixed_center.h>
#include <CGAL/Surface_mesh_parameterization/main_border.h>
#include <CGAL/Surface_mesh_parameterization/measure_quality.h>
#include <CGAL/Surface_mesh_parameterization/Measured_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_report.h>
#include <CGAL/Surface_mesh_parameterization/poisson_distance_map.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/disk.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

BOOST_AUTO_TEST_SUITE(robustness)

namespace SMP = CGAL::Surface_mesh_parameterization;
typedef CGAL::Simple_cartesian<double>                          K;
typedef CGAL::Surface_mesh<K::Point_3>                          Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor            vertex_descriptor;
typedef boost::graph_traits<Mesh>::halfedge_descriptor          halfedge_descriptor;
typedef Mesh::Property_map<vertex_descriptor, K::Point_2>       UV_map;
typedef Mesh::Property_map<vertex_descriptor, double>           Distance_map;
typedef SMP::Measured_conformal_parameterizer_3<Mesh>           Full;  // the paper's method
typedef SMP::internal::Disk<Mesh, SMP::Default_sparse_cholesky_traits> Disk;
typedef SMP::Measured_border<SMP::Fixed_center<Mesh> >          Fixed;
typedef SMP::Border_parameterizer_3<Mesh, Fixed>                Fixed_border;
typedef SMP::Conformal_parameterizer_3<Mesh, Fixed>             Fixed_full;

using mbp_test::rigid_motion;
using mbp_test::scaling;
using mbp_test::Transform;

namespace {

// largest |a - b| over the vertices, two meshes with the same vertex indices
double uv_difference(const Mesh& ma, UV_map a, const Mesh& mb, UV_map b)
{
  BOOST_REQUIRE_EQUAL(num_vertices(ma), num_vertices(mb));
  double worst = 0.;
  for(vertex_descriptor v : vertices(ma))
    worst = (std::max)(worst, std::hypot(a[v].x() - b[v].x(), a[v].y() - b[v].y()));
  return worst;
}

} // namespace

// ================================================================ Fixed_center

BOOST_AUTO_TEST_CASE(fixed_center_that_is_not_a_vertex_of_the_mesh_is_a_wrong_parameter)
{
  // two components: the bumpy disk, and a translated copy of it
  mbp_test::Soup soup = mbp_test::bumpy_disk(6, 16);
  const std::size_t n = soup.points.size();
  mbp_test::Soup two = soup;
  for(const auto& p : soup.points)
    two.points.push_back({{p[0] + 5., p[1], p[2]}});
  for(const auto& f : soup.faces)
    two.faces.push_back({f[0] + n, f[1] + n, f[2] + n});
  Mesh m = mbp_test::make_mesh<Mesh>(two);
  const halfedge_descriptor bhd = SMP::main_border(m).first;
  BOOST_REQUIRE(bhd != Mesh::null_halfedge());
  const bool first_component = std::size_t(source(bhd, m)) < n;
  // an interior vertex of the other component (its center)
  const vertex_descriptor other(Mesh::size_type(first_component ? n : 0));
  // a removed vertex (the mesh keeps its slot until garbage collection)
  Mesh with_removed = m;
  const vertex_descriptor removed = with_removed.add_vertex(K::Point_3(0., 0., 9.));
  with_removed.remove_vertex(removed);

  const std::vector<vertex_descriptor> bad{
    Mesh::null_vertex(), vertex_descriptor(Mesh::size_type(num_vertices(m))),
    vertex_descriptor(Mesh::size_type(num_vertices(m) + 1000)), vertex_descriptor(Mesh::size_type(1u << 28)), other};
  for(Mesh* mesh : {&m, &with_removed})
    for(vertex_descriptor v : bad)
      BOOST_TEST_CONTEXT("center index " << std::size_t(v))
      {
        UV_map uv = mbp_test::new_uv_map(*mesh, "v:uv");
        auto done = mesh->add_property_map<vertex_descriptor, bool>("v:done", false).first;
        auto index = mesh->add_property_map<vertex_descriptor, int>("v:index", 0).first;
        Fixed_border border{Fixed(SMP::Fixed_center<Mesh>(v))};
        BOOST_TEST(border.parameterize(*mesh, bhd, uv, index, done) == SMP::ERROR_WRONG_PARAMETER);
        Fixed_full full{Fixed(SMP::Fixed_center<Mesh>(v))};
        BOOST_TEST(full.parameterize(*mesh, bhd, uv, index, done) == SMP::ERROR_WRONG_PARAMETER);
        for(vertex_descriptor w : vertices(*mesh))
        {
          BOOST_TEST(uv[w] == K::Point_2(-7, -7));
          BOOST_TEST(!done[w]);
        }
        mesh->remove_property_map(uv);
        mesh->remove_property_map(done);
        mesh->remove_property_map(index);
      }
  {
    UV_map uv = mbp_test::new_uv_map(with_removed, "v:uv");
    Fixed_full full{Fixed(SMP::Fixed_center<Mesh>(removed))};
    BOOST_TEST(SMP::parameterize(with_removed, full, bhd, uv) == SMP::ERROR_WRONG_PARAMETER);
  }
  // the same locator with an interior vertex of the component works
  const vertex_descriptor good(Mesh::size_type(first_component ? 0 : n));
  UV_map uv = mbp_test::new_uv_map(m, "v:good");
  Fixed_full full{Fixed(SMP::Fixed_center<Mesh>(good))};
  SMP::Parameterization_report report;
  BOOST_TEST(SMP::parameterize(m, full, bhd, uv, &report) == SMP::OK);
  BOOST_TEST(report.has_center);
  BOOST_TEST(report.center == std::size_t(good));
}

// ================================================================ the main border

namespace {

// An open tube (a cylinder of `n` vertices around, `rows` rows of quads): its two border
// loops are equal regular polygons, of exactly equal length in exact arithmetic.
mbp_test::Soup tube(int n, int rows = 5)
{
  mbp_test::Soup s;
  for(int j = 0; j <= rows; ++j)
    for(int i = 0; i < n; ++i)
    {
      const double t = 2. * CGAL_PI * i / n;
      s.points.push_back({{std::cos(t), std::sin(t), 2. * j / rows}});
    }
  auto id = [n](int i, int j) { return std::size_t(j * n + i % n); };
  for(int j = 0; j < rows; ++j)
    for(int i = 0; i < n; ++i)
    {
      s.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      s.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return s;
}

// A tube between two border loops given as point lists of `bottom` (z = 0) and `top` (z = 1)
// polygons (counterclockwise in xy), triangulated by merging the two loops by their
// parameter along the polygon.
mbp_test::Soup tube_between(const std::vector<std::array<double, 2> >& bottom,
                            const std::vector<std::array<double, 2> >& top)
{
  mbp_test::Soup s;
  for(const auto& p : bottom)
    s.points.push_back({{p[0], p[1], 0.}});
  for(const auto& p : top)
    s.points.push_back({{p[0], p[1], 1.}});
  const std::size_t nb = bottom.size(), nt = top.size();
  std::size_t i = 0, j = 0;
  while(i < nb || j < nt)
  {
    // advance on the loop whose next vertex comes first along the polygon
    const bool bottom_first = (j == nt) || (i < nb && double(i + 1) / double(nb) <= double(j + 1) / double(nt));
    if(bottom_first)
    {
      s.faces.push_back({i % nb, (i + 1) % nb, nb + j % nt});
      ++i;
    }
    else
    {
      s.faces.push_back({i % nb, nb + (j + 1) % nt, nb + j % nt});
      ++j;
    }
  }
  return s;
}

std::vector<std::array<double, 2> > square_loop(int per_side, double side)
{
  std::vector<std::array<double, 2> > p;
  const double corners[5][2] = {{0., 0.}, {side, 0.}, {side, side}, {0., side}, {0., 0.}};
  for(int c = 0; c < 4; ++c)
    for(int k = 0; k < per_side; ++k)
    {
      const double t = double(k) / per_side;
      p.push_back({{corners[c][0] + t * (corners[c + 1][0] - corners[c][0]),
                    corners[c][1] + t * (corners[c + 1][1] - corners[c][1])}});
    }
  return p;
}

std::vector<std::array<double, 2> > circle_loop(int n, double radius)
{
  std::vector<std::array<double, 2> > p;
  for(int k = 0; k < n; ++k)
    p.push_back({{0.5 + radius * std::cos(2. * CGAL_PI * k / n), 0.5 + radius * std::sin(2. * CGAL_PI * k / n)}});
  return p;
}

} // namespace

BOOST_AUTO_TEST_CASE(main_border_ties_follow_the_documented_rule_under_every_similarity)
{
  const std::vector<std::pair<std::string, Transform> > transforms{
    {"identity", nullptr},
    {"scaled by 1e-6", scaling(1e-6)},
    {"scaled by 3e5", scaling(3e5)},
    {"mirrored", [](const std::array<double, 3>& p) { return std::array<double, 3>{{-p[0], p[1], p[2]}}; }},
    {"mirrored along the axis", [](const std::array<double, 3>& p) { return std::array<double, 3>{{p[0], p[1], 2. - p[2]}}; }},
    {"translated by 1e6", [](const std::array<double, 3>& p) { return std::array<double, 3>{{p[0] + 1e6, p[1] + 1e6, p[2] + 1e6}}; }},
    {"rotated", rigid_motion(std::sqrt(2.), {{0., 0., 0.}})},
    {"moved", rigid_motion(1., {{0.3, -1.7, 2.9}})}};

  // tubes with two equal round ends (the same number of vertices): the tie goes to the loop
  // of the vertex that comes first, vertex 0, which is also the start
  for(int n : {13, 31})
  {
    std::set<std::size_t> plain_rule_choices;  // what the longest loop alone gives
    for(const auto& [name, transform] : transforms)
      BOOST_TEST_CONTEXT("tube of " << n << ", " << name)
      {
        const Mesh m = mbp_test::make_mesh<Mesh>(tube(n), transform);
        const auto [bhd, length] = SMP::main_border(m);
        BOOST_REQUIRE(bhd != Mesh::null_halfedge());
        BOOST_TEST(is_border(bhd, m));
        BOOST_TEST(std::size_t(source(bhd, m)) == 0u);
        BOOST_TEST(mbp_test::sorted_loop(m, bhd).front() == 0u);
        BOOST_TEST(std::abs(length - CGAL::Polygon_mesh_processing::face_border_length(bhd, m)) <= 1e-12 * length);
        plain_rule_choices.insert(mbp_test::sorted_loop(m, CGAL::Polygon_mesh_processing::longest_border(m).first).front());
      }
    BOOST_TEST_MESSAGE("tube of " << n << ": the longest loop alone picks " << plain_rule_choices.size()
                       << " different loops over the transformations");
    // the parameterization follows: the same UVs for the tube scaled by 1e-6
    Mesh a = mbp_test::make_mesh<Mesh>(tube(n)), b = mbp_test::make_mesh<Mesh>(tube(n), scaling(1e-6));
    UV_map ua = mbp_test::new_uv_map(a, "v:uv"), ub = mbp_test::new_uv_map(b, "v:uv");
    const Full p;
    BOOST_REQUIRE_EQUAL(SMP::parameterize(a, p, SMP::main_border(a).first, ua), SMP::OK);
    BOOST_REQUIRE_EQUAL(SMP::parameterize(b, p, SMP::main_border(b).first, ub), SMP::OK);
    BOOST_TEST(uv_difference(a, ua, b, ub) <= 1e-12);
  }

  // equal lengths, different numbers of vertices: the tie goes to the loop with more vertices
  // (the top square, 8 vertices, against the bottom one, 4)
  const mbp_test::Soup squares = tube_between(square_loop(1, 2.), square_loop(2, 2.));
  for(const auto& [name, transform] : transforms)
    BOOST_TEST_CONTEXT("square tube, " << name)
    {
      const Mesh m = mbp_test::make_mesh<Mesh>(squares, transform);
      const halfedge_descriptor bhd = SMP::main_border(m).first;
      BOOST_TEST(mbp_test::sorted_loop(m, bhd).size() == 8u);
      BOOST_TEST(std::size_t(source(bhd, m)) == 4u);  // the first vertex of the top loop
    }

  // no tie: the longer loop wins, whatever the numbers of vertices (a 24-gon of radius 0.3
  // against a square of side 1 with 4 vertices)
  const mbp_test::Soup frustum = tube_between(circle_loop(24, 0.3), square_loop(1, 1.));
  for(const auto& [name, transform] : transforms)
    BOOST_TEST_CONTEXT("frustum, " << name)
    {
      const Mesh m = mbp_test::make_mesh<Mesh>(frustum, transform);
      const auto [bhd, length] = SMP::main_border(m);
      BOOST_TEST(mbp_test::sorted_loop(m, bhd).size() == 4u);
      BOOST_TEST(std::abs(length - CGAL::Polygon_mesh_processing::face_border_length(bhd, m)) <= 1e-12 * length);
    }

  // a closed mesh has no border
  mbp_test::Soup closed = tube_between(square_loop(1, 1.), square_loop(1, 1.));
  closed.faces.push_back({0, 2, 1});
  closed.faces.push_back({0, 3, 2});
  closed.faces.push_back({4, 5, 6});
  closed.faces.push_back({4, 6, 7});
  const Mesh box = mbp_test::make_mesh<Mesh>(closed);
  BOOST_TEST(SMP::main_border(box).first == Mesh::null_halfedge());
}

// ================================================================ pinched disks

namespace {

typedef Mesh::Vertex_index V;

// An annulus (rings of radius 1..1+rings, `n` sectors) cut along the sector line at angle 0
// except at one vertex of that line, which stays shared: a disk whose border touches itself
// at that vertex (the pinch), one component. `pinched_ring` is the ring of the shared vertex,
// `reverse` the order in which the faces are added.
Mesh pinched_annulus(int n, int rings, int pinched_ring, bool reverse)
{
  Mesh m;
  std::vector<std::vector<V> > id(std::size_t(n + 1), std::vector<V>(std::size_t(rings + 1)));
  for(int j = 0; j <= n; ++j)
    for(int k = 0; k <= rings; ++k)
    {
      if(j == n && k == pinched_ring)
      {
        id[std::size_t(j)][std::size_t(k)] = id[0][std::size_t(k)];
        continue;
      }
      const double t = 2. * CGAL_PI * j / n, r = 1. + k;
      id[std::size_t(j)][std::size_t(k)] = m.add_vertex(K::Point_3(r * std::cos(t), r * std::sin(t), 0.2 * std::sin(t)));
    }
  std::vector<std::array<V, 3> > faces;
  for(std::size_t j = 0; j < std::size_t(n); ++j)
    for(std::size_t k = 0; k < std::size_t(rings); ++k)
    {
      faces.push_back({{id[j][k], id[j + 1][k], id[j + 1][k + 1]}});
      faces.push_back({{id[j][k], id[j + 1][k + 1], id[j][k + 1]}});
    }
  if(reverse)
    std::reverse(faces.begin(), faces.end());
  for(const auto& f : faces)
    BOOST_REQUIRE(m.add_face(f[0], f[1], f[2]) != Mesh::null_face());
  BOOST_REQUIRE(CGAL::is_valid_polygon_mesh(m));
  return m;
}

// A disk (center, `rings` rings of 12 vertices) whose outer ring vertices 0, 4 and 8 are one
// vertex: three fans at one vertex, one component. The faces are added with the given stride
// (1: in order): the mesh's border loops then differ (three loops through the pinch, or one
// loop through it three times).
Mesh three_fan_pinch(int stride)
{
  const int n = 12, rings = 3;
  Mesh m;
  const V c = m.add_vertex(K::Point_3(0., 0., 0.));
  const V pinch = m.add_vertex(K::Point_3(0., 0., 1.));
  std::vector<std::vector<V> > id(std::size_t(n), std::vector<V>(std::size_t(rings + 1), c));
  for(int j = 0; j < n; ++j)
    for(int k = 1; k <= rings; ++k)
      id[std::size_t(j)][std::size_t(k)] =
        (k == rings && j % 4 == 0) ? pinch
                                   : m.add_vertex(K::Point_3(k * std::cos(2. * CGAL_PI * j / n), k * std::sin(2. * CGAL_PI * j / n), 0.));
  std::vector<std::array<V, 3> > faces;
  for(std::size_t j = 0; j < std::size_t(n); ++j)
  {
    const std::size_t jn = (j + 1) % std::size_t(n);
    faces.push_back({{c, id[j][1], id[jn][1]}});
    for(std::size_t k = 1; k < std::size_t(rings); ++k)
    {
      faces.push_back({{id[j][k], id[j][k + 1], id[jn][k + 1]}});
      faces.push_back({{id[j][k], id[jn][k + 1], id[jn][k]}});
    }
  }
  std::vector<std::array<V, 3> > ordered;
  for(int first = 0; first < stride; ++first)
    for(std::size_t q = std::size_t(first); q < faces.size(); q += std::size_t(stride))
      ordered.push_back(faces[q]);
  for(const auto& f : ordered)
    BOOST_REQUIRE(m.add_face(f[0], f[1], f[2]) != Mesh::null_face());
  BOOST_REQUIRE(CGAL::is_valid_polygon_mesh(m));
  return m;
}

// Two disks (a center and a ring of six) that share one vertex of their rings: a bow tie, two
// components joined at a vertex.
Mesh bow_tie()
{
  Mesh m;
  const V shared = m.add_vertex(K::Point_3(0., 0., 0.));
  for(double side : {-1., 1.})
  {
    const V c = m.add_vertex(K::Point_3(side, 0., 0.));
    std::vector<V> ring;
    for(int k = 0; k < 6; ++k)
    {
      const double t = CGAL_PI * k / 3.;
      ring.push_back(k == 0 ? shared : m.add_vertex(K::Point_3(side - side * std::cos(t), std::sin(t), 0.)));
    }
    for(int k = 0; k < 6; ++k)
    {
      const V a = ring[std::size_t(k)], b = ring[std::size_t((k + 1) % 6)];
      BOOST_REQUIRE(m.add_face(c, side > 0 ? b : a, side > 0 ? a : b) != Mesh::null_face());
    }
  }
  BOOST_REQUIRE(CGAL::is_valid_polygon_mesh(m));
  return m;
}

std::vector<std::pair<halfedge_descriptor, int> > border_loops(const Mesh& m) { return mbp_test::border_loops(m); }

// whether some vertex has its faces in more than one fan (more than one border halfedge
// into it)
bool has_pinched_vertex(const Mesh& m)
{
  for(vertex_descriptor v : vertices(m))
  {
    int gaps = 0;
    for(halfedge_descriptor h : CGAL::halfedges_around_target(halfedge(v, m), m))
      gaps += is_border(h, m) ? 1 : 0;
    if(gaps > 1)
      return true;
  }
  return false;
}

// Every entry point that takes a disk rejects the loop of `bhd` with ERROR_NO_TOPOLOGICAL_DISC
// and writes nothing.
void check_rejected(Mesh& m, halfedge_descriptor bhd)
{
  UV_map uv = mbp_test::new_uv_map(m, "v:uv");
  auto done = m.add_property_map<vertex_descriptor, bool>("v:done", false).first;
  auto index = m.add_property_map<vertex_descriptor, int>("v:index", 0).first;
  Distance_map f = mbp_test::new_distance_map(m, "v:f");
  // the complete parameterizer with each border policy
  auto rejects = [&](const auto& p, const char* border) {
    BOOST_TEST(p.parameterize(m, bhd, uv, index, done) == SMP::ERROR_NO_TOPOLOGICAL_DISC, "border " << border);
  };
  rejects(SMP::Conformal_parameterizer_3<Mesh, SMP::Measured_border<> >(), "measured");
  rejects(SMP::Conformal_parameterizer_3<Mesh, SMP::Conformal_border>(), "conformal");
  rejects(SMP::Conformal_parameterizer_3<Mesh, SMP::Circular_border>(), "circular");
  rejects(SMP::Conformal_parameterizer_3<Mesh, SMP::Automatic_border<> >(), "automatic");
  SMP::Measured_border_parameterizer_3<Mesh> measured;
  BOOST_TEST(measured.parameterize(m, bhd, uv, index, done) == SMP::ERROR_NO_TOPOLOGICAL_DISC);
  SMP::Conformal_border_parameterizer_3<Mesh> conformal;
  BOOST_TEST(conformal.parameterize(m, bhd, uv, index, done) == SMP::ERROR_NO_TOPOLOGICAL_DISC);
  BOOST_TEST(SMP::boundary_poisson_distance_map(m, bhd, f) == SMP::ERROR_NO_TOPOLOGICAL_DISC);
  Disk disk;
  BOOST_TEST(disk.build_disk(m, bhd, get(CGAL::vertex_point, m)) == SMP::ERROR_NO_TOPOLOGICAL_DISC);
  BOOST_TEST(disk.number_of_vertices() == 0u);
  for(vertex_descriptor v : vertices(m))
  {
    BOOST_TEST(uv[v] == K::Point_2(-7, -7));
    BOOST_TEST(!done[v]);
    BOOST_TEST(f[v] == -1.);
  }
  m.remove_property_map(uv);
  m.remove_property_map(done);
  m.remove_property_map(index);
  m.remove_property_map(f);
}

} // namespace

BOOST_AUTO_TEST_CASE(pinched_disks_are_not_topological_disks)
{
  // a disk whose border touches itself at one vertex: the halfedge structure makes it two
  // border loops through the pinch (each once), which used to be accepted, the enclosed
  // region taken for a hole
  for(int ring : {0, 3})
    for(bool reverse : {false, true})
      BOOST_TEST_CONTEXT("annulus pinched on ring " << ring << (reverse ? ", faces reversed" : ""))
      {
        Mesh m = pinched_annulus(24, 3, ring, reverse);
        BOOST_TEST(has_pinched_vertex(m));
        const auto loops = border_loops(m);
        BOOST_TEST(loops.size() == 2u);
        for(const auto& loop : loops)
        {
          BOOST_TEST(loop.second == 1);  // no loop visits a vertex twice
          check_rejected(m, loop.first);
        }
        // the remedy the manual names: split the pinched vertex, then it is a disk
        CGAL::Polygon_mesh_processing::duplicate_non_manifold_vertices(m);
        BOOST_TEST(!has_pinched_vertex(m));
        BOOST_REQUIRE_EQUAL(border_loops(m).size(), 1u);
        UV_map uv = mbp_test::new_uv_map(m, "v:uv");
        const SMP::Conformal_parameterizer_3<Mesh, SMP::Conformal_border> p;
        BOOST_REQUIRE_EQUAL(SMP::parameterize(m, p, SMP::main_border(m).first, uv), SMP::OK);
        BOOST_TEST(SMP::is_one_to_one_uv_map(m, faces(m), uv));
      }

  // three fans at one vertex: depending on the order of the faces, three loops through the
  // pinch or one loop through it three times; rejected either way
  std::set<std::size_t> loop_counts;
  for(int stride : {1, 2, 3, 4})
    BOOST_TEST_CONTEXT("three fans, faces added with stride " << stride)
    {
      Mesh m = three_fan_pinch(stride);
      BOOST_TEST(has_pinched_vertex(m));
      const auto loops = border_loops(m);
      loop_counts.insert(loops.size());
      for(const auto& loop : loops)
        check_rejected(m, loop.first);
    }
  BOOST_TEST(loop_counts.size() == 2u);  // both structures were tried

  // a bow tie: one loop through the shared vertex twice, leaving each disk's faces
  Mesh tie = bow_tie();
  BOOST_TEST(has_pinched_vertex(tie));
  for(const auto& loop : border_loops(tie))
  {
    BOOST_TEST(loop.second == 2);
    check_rejected(tie, loop.first);
  }
}

BOOST_AUTO_TEST_SUITE_END()
