// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// Measured_border_parameterizer_3 as a drop-in border parameterizer of CGAL's fixed border
// parameterizers: the polar border map, CGAL's conventions, generic meshes, invariance, and
// one test per kind of bad input.

#include <boost/test/unit_test.hpp>

#include "test_support.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Seam_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/Unique_hash_map.h>

#include <CGAL/Surface_mesh_parameterization/Barycentric_mapping_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Circular_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_authalic_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_conformal_map_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Mean_value_coordinates_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <CGAL/Surface_mesh_parameterization/Fixed_center.h>
#include <CGAL/Surface_mesh_parameterization/Measured_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_report.h>
#include <CGAL/Surface_mesh_parameterization/measure_quality.h>

#include <Eigen/SparseLU>

#include <boost/property_map/property_map.hpp>

#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <vector>

BOOST_AUTO_TEST_SUITE(measured_border)

namespace SMP = CGAL::Surface_mesh_parameterization;
typedef CGAL::Simple_cartesian<double>                               SC;
typedef CGAL::Exact_predicates_inexact_constructions_kernel          EPICK;
typedef CGAL::Surface_mesh<SC::Point_3>                              SM;
typedef CGAL::Surface_mesh<EPICK::Point_3>                           SM_epick;
typedef CGAL::Polyhedron_3<SC>                                       Poly;
typedef CGAL::Polyhedron_3<EPICK>                                    Poly_epick;
typedef CGAL::Eigen_solver_traits<Eigen::SparseLU<CGAL::Eigen_sparse_matrix<double>::EigenType> > LU;

typedef boost::graph_traits<SM>::vertex_descriptor                   SM_vertex;
typedef boost::graph_traits<SM>::edge_descriptor                     SM_edge;
typedef SM::Property_map<SM_edge, bool>                              SM_seam_edges;
typedef SM::Property_map<SM_vertex, bool>                            SM_seam_vertices;
typedef CGAL::Seam_mesh<SM, SM_seam_edges, SM_seam_vertices>         Seam_sm;

typedef boost::graph_traits<Poly_epick>::vertex_descriptor           Poly_vertex;
typedef boost::graph_traits<Poly_epick>::edge_descriptor             Poly_edge;
typedef CGAL::Unique_hash_map<Poly_edge, bool>                       Poly_edge_flags;
typedef CGAL::Unique_hash_map<Poly_vertex, bool>                     Poly_vertex_flags;
typedef CGAL::Seam_mesh<Poly_epick,
                        boost::associative_property_map<Poly_edge_flags>,
                        boost::associative_property_map<Poly_vertex_flags> > Seam_poly;

typedef std::array<double, 3>                  Key3;     // a vertex, by its 3D position
typedef std::map<Key3, std::array<double, 2> > UV_by_point;

namespace {

template <class Mesh>
Key3 key(const Mesh& m, typename boost::graph_traits<Mesh>::vertex_descriptor v)
{
  const auto& p = get(get(CGAL::vertex_point, m), v);
  return {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
}

template <class Mesh>
struct Maps
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  // CGAL's fixed border parameterizers read the UVs as the mesh kernel's Point_2
  typedef typename mbp_test::Kernel_of<Mesh>::Point_2 Point_2;
  typedef typename boost::property_map<Mesh, CGAL::dynamic_vertex_property_t<Point_2> >::const_type UV;
  typedef typename boost::property_map<Mesh, CGAL::dynamic_vertex_property_t<bool> >::const_type Flag;
  UV uv;
  Flag parameterized;
  explicit Maps(const Mesh& m)
    : uv(get(CGAL::dynamic_vertex_property_t<Point_2>(), m)),
      parameterized(get(CGAL::dynamic_vertex_property_t<bool>(), m))
  {
    for(vertex_descriptor v : vertices(m))
    {
      put(uv, v, Point_2(-7., -7.));  // sentinel: "never written"
      put(parameterized, v, false);
    }
  }
  bool untouched(const Mesh& m) const
  {
    for(vertex_descriptor v : vertices(m))
      if(get(uv, v) != Point_2(-7., -7.) || get(parameterized, v))
        return false;
    return true;
  }
};

// The fixed border parameterizer's vertex index map, as CGAL's parameterize() builds it.
template <class Mesh>
typename boost::property_map<Mesh, CGAL::dynamic_vertex_property_t<int> >::const_type index_map(const Mesh& m)
{
  auto vimap = get(CGAL::dynamic_vertex_property_t<int>(), m);
  int i = 0;
  for(auto v : vertices(m))
    put(vimap, v, i++);
  return vimap;
}

double signed_area(const std::vector<SC::Point_2>& polygon)
{
  double a = 0.;
  for(std::size_t k = 0; k < polygon.size(); ++k)
  {
    const SC::Point_2 &p = polygon[k], &q = polygon[(k + 1) % polygon.size()];
    a += p.x() * q.y() - p.y() * q.x();
  }
  return 0.5 * a;
}

bool strictly_convex_clockwise(const std::vector<SC::Point_2>& p)
{
  for(std::size_t k = 0; k < p.size(); ++k)
  {
    const SC::Vector_2 e1 = p[k] - p[(k + p.size() - 1) % p.size()], e2 = p[(k + 1) % p.size()] - p[k];
    if(!(e1.x() * e2.y() - e1.y() * e2.x() < 0.))
      return false;
  }
  return true;
}

// Runs DCP with the measured border (SparseLU) and returns the UVs by 3D position; also
// checks the generic invariants of a successful run.
template <class Mesh>
UV_by_point measured_dcp(const Mesh& mesh)
{
  typedef mbp_test::Reporting_border<SMP::Measured_border_parameterizer_3<Mesh> > Border;
  typedef typename boost::graph_traits<Mesh>::halfedge_descriptor halfedge_descriptor;
  Mesh& m = const_cast<Mesh&>(mesh);
  const halfedge_descriptor bhd = mbp_test::longest_border(m);
  Maps<Mesh> maps(m);
  SMP::Parameterization_report report;
  SMP::Discrete_conformal_map_parameterizer_3<Mesh, Border, LU> dcp(Border{&report});
  BOOST_REQUIRE_EQUAL(SMP::parameterize(m, dcp, bhd, maps.uv), SMP::OK);
  // the report of the border step that ran inside CGAL's DCP
  BOOST_TEST(report.status == SMP::OK);
  BOOST_REQUIRE(report.has_center);
  const auto center = mbp_test::vertex_at_position(m, report.center);
  BOOST_TEST(!is_border(center, m));
  const SMP::Parameterization_quality q = SMP::measure_quality(m, faces(m), maps.uv);
  BOOST_TEST(q.flipped_faces == 0u);
  UV_by_point result;
  for(auto v : vertices(m))
  {
    const auto p = get(maps.uv, v);
    BOOST_REQUIRE(std::isfinite(p.x()) && std::isfinite(p.y()));
    BOOST_TEST(p.x() >= 0.);
    BOOST_TEST(p.x() <= 1.);
    BOOST_TEST(p.y() >= 0.);
    BOOST_TEST(p.y() <= 1.);
    result[key(m, v)] = {p.x(), p.y()};
  }
  return result;
}

void compare(const UV_by_point& a, const UV_by_point& b, double tolerance)
{
  BOOST_REQUIRE_EQUAL(a.size(), b.size());
  double worst = 0.;
  for(const auto& e : a)
  {
    const auto it = b.find(e.first);
    BOOST_REQUIRE(it != b.end());
    worst = (std::max)(worst, std::hypot(e.second[0] - it->second[0], e.second[1] - it->second[1]));
  }
  BOOST_TEST(worst <= tolerance);
}

// A flat star-shaped "flower" domain: its measured border is not convex.
mbp_test::Soup flower()
{
  mbp_test::Soup s = mbp_test::polar_disk(10, 40);
  for(auto& p : s.points)
  {
    const double f = 1. + 0.35 * std::cos(5. * std::atan2(p[1], p[0]));
    p[0] *= f;
    p[1] *= f;
  }
  return s;
}

} // namespace

// ------------------------------------------------------------------ the polar border map

BOOST_AUTO_TEST_CASE(border_is_the_polar_map_of_the_measured_distances)
{
  for(const mbp_test::Soup& soup : {mbp_test::bumpy_disk(), flower(), mbp_test::l_shape(), mbp_test::hex_disk(8, 2., 1.)})
  {
    SM m = mbp_test::make_mesh<SM>(soup);
    const auto bhd = mbp_test::longest_border(m);
    Maps<SM> maps(m);
    SMP::Measured_border_parameterizer_3<SM> border;
    SMP::Parameterization_report rec;
    BOOST_REQUIRE_EQUAL(border.parameterize(m, bhd, maps.uv, index_map(m), maps.parameterized, &rec), SMP::OK);
    // border vertex k of the report is the source of the k-th halfedge of halfedges_around_face(bhd)
    const std::vector<SM_vertex> loop = mbp_test::border_loop_vertices(m, bhd);
    const std::size_t n = loop.size();
    BOOST_REQUIRE(n >= 3u);
    BOOST_REQUIRE_EQUAL(rec.border_uv.size(), n);
    BOOST_REQUIRE_EQUAL(rec.border_distances.size(), n);
    BOOST_REQUIRE_EQUAL(rec.border_angles.size(), n);
    BOOST_REQUIRE(rec.has_center);
    const SM_vertex center = mbp_test::vertex_at_position(m, rec.center);
    BOOST_TEST(!is_border(center, m));

    // the loop starts at source(bhd) and follows halfedges_around_face(bhd): the report's
    // polygon is the one written in the map, in that order
    std::size_t k = 0;
    for(k = 0; k < n; ++k)
    {
      BOOST_TEST(rec.border_uv[k][0] == get(maps.uv, loop[k]).x());
      BOOST_TEST(rec.border_uv[k][1] == get(maps.uv, loop[k]).y());
    }

    // angles: 0 first, strictly increasing, proportional to the 3D angles at the center
    const SC::Point_3& c = m.point(center);
    double total = 0.;
    std::vector<double> theta(n);
    for(k = 0; k < n; ++k)
    {
      const SC::Vector_3 a = m.point(loop[k]) - c, b = m.point(loop[(k + 1) % n]) - c;
      theta[k] = std::acos((std::max)(-1., (std::min)(1., a * b / std::sqrt(a.squared_length() * b.squared_length()))));
      total += theta[k];
    }
    BOOST_TEST(rec.border_angles[0] == 0.);
    for(k = 0; k + 1 < n; ++k)
    {
      BOOST_TEST(rec.border_angles[k + 1] > rec.border_angles[k]);
      BOOST_TEST(std::abs(rec.border_angles[k + 1] - rec.border_angles[k] - 2. * CGAL_PI * theta[k] / total) < 1e-9);
    }
    BOOST_TEST(std::abs(2. * CGAL_PI - rec.border_angles[n - 1] - 2. * CGAL_PI * theta[n - 1] / total) < 1e-9);

    // positions: origin + scale * r_k * (cos(-phi_k), sin(-phi_k)), inside [0,1]^2, bounding box
    // centered with its longest side spanning [0,1]
    std::vector<SC::Point_2> polygon;
    double lo[2] = {1e9, 1e9}, hi[2] = {-1e9, -1e9};
    for(k = 0; k < n; ++k)
    {
      const SC::Point_2 p = get(maps.uv, loop[k]);
      BOOST_TEST(get(maps.parameterized, loop[k]));
      BOOST_TEST(rec.border_distances[k] > 0.);
      const double r = rec.polar_scale * rec.border_distances[k];
      BOOST_TEST(std::abs(p.x() - (rec.polar_origin[0] + r * std::cos(-rec.border_angles[k]))) < 1e-12);
      BOOST_TEST(std::abs(p.y() - (rec.polar_origin[1] + r * std::sin(-rec.border_angles[k]))) < 1e-12);
      lo[0] = (std::min)(lo[0], p.x()); lo[1] = (std::min)(lo[1], p.y());
      hi[0] = (std::max)(hi[0], p.x()); hi[1] = (std::max)(hi[1], p.y());
      polygon.push_back(p);
    }
    BOOST_TEST(lo[0] >= 0.); BOOST_TEST(lo[1] >= 0.); BOOST_TEST(hi[0] <= 1.); BOOST_TEST(hi[1] <= 1.);
    BOOST_TEST(std::abs((std::max)(hi[0] - lo[0], hi[1] - lo[1]) - 1.) < 1e-12);
    BOOST_TEST(std::abs(lo[0] + hi[0] - 1.) < 1e-12);
    BOOST_TEST(std::abs(lo[1] + hi[1] - 1.) < 1e-12);
    // only the border was written
    for(auto v : vertices(m))
      if(!is_border(v, m))
        BOOST_TEST(!get(maps.parameterized, v));

    // CGAL's orientation: the loop runs clockwise in UV, like the circular border's
    BOOST_TEST(signed_area(polygon) < 0.);
    Maps<SM> circle_maps(m);
    SMP::Circular_border_arc_length_parameterizer_3<SM>().parameterize(m, bhd, circle_maps.uv, index_map(m),
                                                                        circle_maps.parameterized);
    std::vector<SC::Point_2> circle;
    for(auto v : loop)
      circle.push_back(get(circle_maps.uv, v));
    BOOST_TEST(signed_area(circle) < 0.);
    // both put source(bhd) at angle 0, to the right of their center
    BOOST_TEST(std::abs(circle[0].y() - 0.5) < 1e-15);
    BOOST_TEST(circle[0].x() > 0.5);
    BOOST_TEST(std::abs(polygon[0].y() - rec.polar_origin[1]) < 1e-12);
    BOOST_TEST(polygon[0].x() > rec.polar_origin[0]);

    // is_border_convex() is honest, and so is the report
    BOOST_TEST(border.is_border_convex() == strictly_convex_clockwise(polygon));
    BOOST_TEST(rec.border_convex == strictly_convex_clockwise(polygon));
  }
}

BOOST_AUTO_TEST_CASE(convexity_is_claimed_only_when_verified)
{
  // the L-shape's measured border is not convex; the flat ellipse's is
  {
    SM m = mbp_test::make_mesh<SM>(mbp_test::l_shape());
    Maps<SM> maps(m);
    SMP::Measured_border_parameterizer_3<SM> border;
    BOOST_REQUIRE_EQUAL(border.parameterize(m, mbp_test::longest_border(m), maps.uv, index_map(m), maps.parameterized), SMP::OK);
    BOOST_TEST(!border.is_border_convex());
  }
  {
    SM m = mbp_test::make_mesh<SM>(mbp_test::hex_disk(8, 2., 1.));
    Maps<SM> maps(m);
    SMP::Measured_border_parameterizer_3<SM> border;
    BOOST_TEST(!border.is_border_convex());  // nothing verified yet
    BOOST_REQUIRE_EQUAL(border.parameterize(m, mbp_test::longest_border(m), maps.uv, index_map(m), maps.parameterized), SMP::OK);
    BOOST_TEST(border.is_border_convex());
  }
}

// ------------------------------------------------------------------ drop-in use in CGAL

BOOST_AUTO_TEST_CASE(drop_in_for_every_fixed_border_parameterizer)
{
  typedef SMP::Measured_border_parameterizer_3<SM> Border;
  for(const mbp_test::Soup& soup : {mbp_test::bumpy_disk(), mbp_test::l_shape()})
  {
    SM m = mbp_test::make_mesh<SM>(soup);
    const auto bhd = mbp_test::longest_border(m);
    Maps<SM> reference(m);
    Border direct;
    BOOST_REQUIRE_EQUAL(direct.parameterize(m, bhd, reference.uv, index_map(m), reference.parameterized), SMP::OK);

    auto check = [&](auto parameterizer, const char* name) {
      Maps<SM> maps(m);
      BOOST_TEST_CONTEXT(name)
      {
        BOOST_REQUIRE_EQUAL(SMP::parameterize(m, parameterizer, bhd, maps.uv), SMP::OK);
        for(auto h : halfedges_around_face(bhd, m))  // the border is the measured one
          BOOST_TEST(get(maps.uv, source(h, m)) == get(reference.uv, source(h, m)));
        const SMP::Parameterization_quality q = SMP::measure_quality(m, faces(m), maps.uv);
        BOOST_TEST(q.flipped_faces == 0u);
        for(auto v : vertices(m))
          BOOST_TEST(std::isfinite(get(maps.uv, v).x()));
      }
    };
    // CGAL's default solver (BiCGSTAB) too: the drop-in must work unchanged
    check(SMP::Discrete_conformal_map_parameterizer_3<SM, Border>(), "DCP");
    check(SMP::Mean_value_coordinates_parameterizer_3<SM, Border>(), "MVC");
    check(SMP::Barycentric_mapping_parameterizer_3<SM, Border>(), "Barycentric");
    check(SMP::Discrete_authalic_parameterizer_3<SM, Border>(), "Discrete authalic");
  }
}

BOOST_AUTO_TEST_CASE(report_of_the_call_inside_cgal_dcp_and_policies_plug_in)
{
  typedef SMP::Measured_border_parameterizer_3<SM, SMP::Fixed_center<SM> > Measured;
  typedef mbp_test::Reporting_border<Measured> Border;
  SM m = mbp_test::make_mesh<SM>(mbp_test::bumpy_disk());
  const SM_vertex chosen(17);
  BOOST_REQUIRE(!is_border(chosen, m));
  SMP::Parameterization_report report;
  const Measured measured{Measured::Border_policy(SMP::Fixed_center<SM>(chosen))};
  BOOST_TEST(measured.border_policy().center_locator().vertex() == chosen);
  SMP::Discrete_conformal_map_parameterizer_3<SM, Border, LU> dcp(Border(&report, measured));
  Maps<SM> maps(m);
  BOOST_REQUIRE_EQUAL(SMP::parameterize(m, dcp, mbp_test::longest_border(m), maps.uv), SMP::OK);
  // the report of the border step that CGAL's DCP ran on its own copy
  BOOST_TEST(report.status == SMP::OK);
  BOOST_REQUIRE(report.has_center);
  BOOST_TEST(SM_vertex(SM::size_type(report.center)) == chosen);
  BOOST_TEST(report.border_uv.size() == std::size_t(24));
  BOOST_TEST(report.statistics.factorizations == 1);  // Fixed_center: only the PDM
  // nothing is shared between copies: the object given to DCP made no call of its own
  BOOST_TEST(!measured.is_border_convex());
}

// ------------------------------------------------------------------ generic over meshes

BOOST_AUTO_TEST_CASE(same_result_on_every_halfedge_graph)
{
  const mbp_test::Soup soup = mbp_test::bumpy_disk();
  const UV_by_point reference = measured_dcp(mbp_test::make_mesh<SM>(soup));
  compare(reference, measured_dcp(mbp_test::make_mesh<SM_epick>(soup)), 1e-12);
  compare(reference, measured_dcp(mbp_test::make_mesh<Poly>(soup)), 1e-12);
  compare(reference, measured_dcp(mbp_test::make_mesh<Poly_epick>(soup)), 1e-12);

  // Seam_mesh with no seam is the same disk; its vertex descriptors are halfedges
  {
    SM sm = mbp_test::make_mesh<SM>(soup);
    SM_seam_edges se = sm.add_property_map<SM_edge, bool>("e:seam", false).first;
    SM_seam_vertices sv = sm.add_property_map<SM_vertex, bool>("v:seam", false).first;
    Seam_sm seam(sm, se, sv);
    compare(reference, measured_dcp(seam), 1e-12);
  }
  {
    Poly_epick pm = mbp_test::make_mesh<Poly_epick>(soup);
    Poly_edge_flags ef(false);
    Poly_vertex_flags vf(false);
    Seam_poly seam(pm, boost::make_assoc_property_map(ef), boost::make_assoc_property_map(vf));
    compare(reference, measured_dcp(seam), 1e-12);
  }
}

BOOST_AUTO_TEST_CASE(seam_mesh_with_a_cut)
{
  // Cut the polar grid from the border inwards along a zigzag path that turns around the
  // center (ring 8 spoke 0, mid, ring 7 spoke 1, mid, ..., ring 4 spoke 4): the border loop
  // goes around the slit, whose vertices get two UVs (one per side).
  const int rings = 8, spokes = 24;
  const mbp_test::Soup soup = mbp_test::polar_disk(rings, spokes, 1.3, 0.9,
                                                   [](double x, double y) { return 0.3 * x * y; });
  auto ring_vertex = [&](int k, int j) { return std::size_t(1 + (k - 1) * spokes + j); };
  auto mid_vertex = [&](int k, int j) { return std::size_t(1 + rings * spokes + j * (rings - 1) + (k - 1)); };
  std::vector<std::size_t> path;
  for(int s = 0; s < 4; ++s)
  {
    path.push_back(ring_vertex(rings - s, s));
    path.push_back(mid_vertex(rings - s - 1, s));
  }
  path.push_back(ring_vertex(rings - 4, 4));
  const int cut = int(path.size()) - 1;

  auto check = [&](auto& seam, auto add_seam) {
    typedef std::decay_t<decltype(seam)> Seam;
    for(std::size_t i = 0; i + 1 < path.size(); ++i)
      BOOST_REQUIRE(add_seam(path[i], path[i + 1]));
    const auto bhd = mbp_test::longest_border(seam);
    Maps<Seam> maps(seam);
    typedef mbp_test::Reporting_border<SMP::Measured_border_parameterizer_3<Seam> > Border;
    SMP::Parameterization_report report;
    SMP::Discrete_conformal_map_parameterizer_3<Seam, Border, LU> dcp(Border{&report});
    BOOST_REQUIRE_EQUAL(SMP::parameterize(seam, dcp, bhd, maps.uv), SMP::OK);
    BOOST_TEST(report.border_uv.size() == std::size_t(spokes + 2 * cut));
    BOOST_TEST(SMP::measure_quality(seam, faces(seam), maps.uv).flipped_faces == 0u);
    // the two copies of a slit vertex are apart in UV
    std::map<Key3, std::vector<typename Maps<Seam>::Point_2> > copies;
    for(auto v : vertices(seam))
      copies[key(seam, v)].push_back(get(maps.uv, v));
    int split = 0;
    for(const auto& c : copies)
      if(c.second.size() == 2)
      {
        ++split;
        BOOST_TEST(CGAL::squared_distance(c.second[0], c.second[1]) > 1e-6);
      }
    BOOST_TEST(split == cut);  // every slit vertex but the tip is duplicated
  };
  {
    SM sm = mbp_test::make_mesh<SM>(soup);
    SM_seam_edges se = sm.add_property_map<SM_edge, bool>("e:seam", false).first;
    SM_seam_vertices sv = sm.add_property_map<SM_vertex, bool>("v:seam", false).first;
    Seam_sm seam(sm, se, sv);
    check(seam, [&](std::size_t a, std::size_t b) {
      return seam.add_seam(SM_vertex(SM::size_type(a)), SM_vertex(SM::size_type(b)));
    });
  }
  {
    Poly_epick pm = mbp_test::make_mesh<Poly_epick>(soup);
    Poly_edge_flags ef(false);
    Poly_vertex_flags vf(false);
    Seam_poly seam(pm, boost::make_assoc_property_map(ef), boost::make_assoc_property_map(vf));
    std::vector<Poly_vertex> pv(vertices(pm).begin(), vertices(pm).end());
    check(seam, [&](std::size_t a, std::size_t b) { return seam.add_seam(pv[a], pv[b]); });
  }
}

BOOST_AUTO_TEST_CASE(slit_pointing_at_the_center_is_a_degenerate_border_map)
{
  // A radial slit: all its vertices are seen from the center in one direction, so the polar
  // map cannot be star-shaped. The call must fail rather than fold.
  const int rings = 8, spokes = 24;
  SM sm = mbp_test::make_mesh<SM>(mbp_test::polar_disk(rings, spokes));
  SM_seam_edges se = sm.add_property_map<SM_edge, bool>("e:seam", false).first;
  SM_seam_vertices sv = sm.add_property_map<SM_vertex, bool>("v:seam", false).first;
  Seam_sm seam(sm, se, sv);
  for(int k = 3; k < rings; ++k)
    BOOST_REQUIRE(seam.add_seam(SM_vertex(SM::size_type(1 + (k - 1) * spokes)), SM_vertex(SM::size_type(1 + k * spokes))));
  typedef SMP::Measured_border_parameterizer_3<Seam_sm, SMP::Fixed_center<Seam_sm> > Border;
  Seam_sm::vertex_descriptor center;
  for(auto v : vertices(seam))
    if(key(seam, v) == Key3{0., 0., 0.})
      center = v;
  Maps<Seam_sm> maps(seam);
  Border border{Border::Border_policy(SMP::Fixed_center<Seam_sm>(center))};
  BOOST_TEST(border.parameterize(seam, mbp_test::longest_border(seam), maps.uv, index_map(seam), maps.parameterized)
             == SMP::ERROR_DEGENERATE_BORDER_MAP);
  BOOST_TEST(maps.untouched(seam));
}

BOOST_AUTO_TEST_CASE(result_is_invariant_under_rigid_motion_and_uniform_scaling)
{
  const mbp_test::Soup soup = mbp_test::bumpy_disk();
  mbp_test::Soup moved = soup;
  const double s = 0.023, c = std::cos(2.1), sn = std::sin(2.1);
  for(auto& p : moved.points)
  {
    const std::array<double, 3> q = p;
    p = {s * (c * q[0] + sn * q[2]) - 3., s * q[1] + 100., s * (-sn * q[0] + c * q[2]) + 0.5};
  }
  const UV_by_point a = measured_dcp(mbp_test::make_mesh<SM>(soup)), b = measured_dcp(mbp_test::make_mesh<SM>(moved));
  // match vertices by index (positions moved): both maps are ordered by the same vertices
  SM ma = mbp_test::make_mesh<SM>(soup), mb = mbp_test::make_mesh<SM>(moved);
  double worst = 0.;
  for(auto v : vertices(ma))
  {
    const auto& ua = a.at(key(ma, v));
    const auto& ub = b.at(key(mb, v));
    worst = (std::max)(worst, std::hypot(ua[0] - ub[0], ua[1] - ub[1]));
  }
  BOOST_TEST(worst < 1e-9);
}

// ------------------------------------------------------------------ bad input

namespace {

// Runs the border parameterizer alone and through DCP; both must fail with `expected` and
// write nothing.
template <class Mesh>
void expect_failure(Mesh& m, typename boost::graph_traits<Mesh>::halfedge_descriptor bhd, SMP::Error_code expected)
{
  Maps<Mesh> maps(m);
  SMP::Measured_border_parameterizer_3<Mesh> border;
  SMP::Parameterization_report report;
  const SMP::Error_code status = border.parameterize(m, bhd, maps.uv, index_map(m), maps.parameterized, &report);
  BOOST_TEST(status == expected, SMP::get_measured_error_message(status));
  BOOST_TEST(maps.untouched(m));
  BOOST_TEST(!border.is_border_convex());
  BOOST_TEST(!report.has_center);
  BOOST_TEST(report.status == expected);
  BOOST_TEST(report.border_uv.empty());
  if(bhd != boost::graph_traits<Mesh>::null_halfedge() && !faces(m).empty())
  {
    SMP::Discrete_conformal_map_parameterizer_3<Mesh, SMP::Measured_border_parameterizer_3<Mesh>, LU> dcp;
    // With assertions on (the sanitizer build), CGAL's DCP checks its own preconditions
    // (triangle mesh, border halfedge, valid mesh) before the border parameterizer runs.
    bool rejected_by_cgal = false;
    SMP::Error_code status = SMP::OK;
    try
    {
      status = dcp.parameterize(m, bhd, maps.uv, index_map(m), maps.parameterized);
    }
    catch(const CGAL::Precondition_exception&)
    {
      rejected_by_cgal = true;
    }
#if defined(NDEBUG) || defined(CGAL_NDEBUG) || defined(CGAL_NO_PRECONDITIONS)
    BOOST_TEST(!rejected_by_cgal);
#endif
    if(!rejected_by_cgal)
      BOOST_TEST(status == expected);
    BOOST_TEST(maps.untouched(m));
  }
}

} // namespace

BOOST_AUTO_TEST_CASE(bad_input_empty_mesh)
{
  SM m;
  expect_failure(m, boost::graph_traits<SM>::null_halfedge(), SMP::ERROR_EMPTY_MESH);
}

BOOST_AUTO_TEST_CASE(bad_input_non_triangle_faces)
{
  mbp_test::Soup quads;
  for(int i = 0; i < 4; ++i)
    for(int j = 0; j < 4; ++j)
      quads.points.push_back({double(i), double(j), 0.});
  for(std::size_t i = 0; i < 3; ++i)
    for(std::size_t j = 0; j < 3; ++j)
      quads.faces.push_back({4 * i + j, 4 * (i + 1) + j, 4 * (i + 1) + j + 1, 4 * i + j + 1});
  SM m = mbp_test::make_mesh<SM>(quads);
  expect_failure(m, mbp_test::longest_border(m), SMP::ERROR_NON_TRIANGULAR_MESH);
}

BOOST_AUTO_TEST_CASE(bad_input_null_or_non_border_halfedge)
{
  SM m = mbp_test::make_mesh<SM>(mbp_test::bumpy_disk());
  expect_failure(m, boost::graph_traits<SM>::null_halfedge(), SMP::ERROR_INVALID_BORDER_HALFEDGE);
  const auto interior = halfedge(*faces(m).begin(), m);
  BOOST_REQUIRE(!is_border(interior, m));
  expect_failure(m, interior, SMP::ERROR_INVALID_BORDER_HALFEDGE);
}

BOOST_AUTO_TEST_CASE(bad_input_border_loop_of_two_vertices)
{
  // An octahedron cut along a single edge: the only border loop has two vertices.
  mbp_test::Soup octa;
  octa.points = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  octa.faces = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  SM sm = mbp_test::make_mesh<SM>(octa);
  SM_seam_edges se = sm.add_property_map<SM_edge, bool>("e:seam", false).first;
  SM_seam_vertices sv = sm.add_property_map<SM_vertex, bool>("v:seam", false).first;
  Seam_sm seam(sm, se, sv);
  BOOST_REQUIRE(seam.add_seam(SM_vertex(0), SM_vertex(4)));
  auto bhd = boost::graph_traits<Seam_sm>::null_halfedge();
  for(auto h : halfedges(seam))
    if(is_border(h, seam))
      bhd = h;
  BOOST_REQUIRE(bhd != boost::graph_traits<Seam_sm>::null_halfedge());
  BOOST_REQUIRE_EQUAL(halfedges_around_face(bhd, seam).size(), 2u);
  expect_failure(seam, bhd, SMP::ERROR_BORDER_TOO_SHORT);
}

BOOST_AUTO_TEST_CASE(bad_input_no_interior_vertex)
{
  mbp_test::Soup fan;  // a strip of triangles: every vertex is on the border
  fan.points = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}};
  fan.faces = {{0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}};
  SM m = mbp_test::make_mesh<SM>(fan);
  expect_failure(m, mbp_test::longest_border(m), SMP::ERROR_NO_INTERIOR_VERTEX);
}

BOOST_AUTO_TEST_CASE(bad_input_zero_area_triangle)
{
  // a square with a center vertex moved onto the middle of one side
  mbp_test::Soup sq;
  sq.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0., 0}};
  sq.faces = {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
  SM m = mbp_test::make_mesh<SM>(sq);
  expect_failure(m, mbp_test::longest_border(m), SMP::ERROR_DEGENERATE_FACE);
  // also a triangle of a real size with an edge of length zero (duplicated point)
  sq.points[4] = {0., 0., 0.};
  SM m2 = mbp_test::make_mesh<SM>(sq);
  expect_failure(m2, mbp_test::longest_border(m2), SMP::ERROR_DEGENERATE_FACE);
}

BOOST_AUTO_TEST_CASE(bad_input_non_finite_coordinates)
{
  for(double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
  {
    mbp_test::Soup soup = mbp_test::bumpy_disk();
    soup.points[3][1] = bad;
    SM m = mbp_test::make_mesh<SM>(soup);
    expect_failure(m, mbp_test::longest_border(m), SMP::ERROR_NON_FINITE_COORDINATES);
  }
}

BOOST_AUTO_TEST_CASE(bad_input_not_a_disk)
{
  // genus one with a hole
  SM torus = mbp_test::make_mesh<SM>(mbp_test::punctured_torus());
  expect_failure(torus, mbp_test::longest_border(torus), SMP::ERROR_NO_TOPOLOGICAL_DISC);

  // two fans glued at one border vertex: the border loop passes twice through it
  SM pinched;
  std::vector<SM_vertex> v;
  for(auto p : std::vector<SC::Point_3>{{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {-0.5, 1, 0}, {-1, 0, 0},
                                         {1, 0, 0.2}, {0.5, -1, 0}, {-0.5, -1, 0}, {-1, 0, 0.2}})
    v.push_back(pinched.add_vertex(p));
  // hub 0 joined to fan A (1..4) and fan B (5..8) that touch only at vertex 0
  const SM_vertex c1 = pinched.add_vertex(SC::Point_3(0, 0.5, 0.1)), c2 = pinched.add_vertex(SC::Point_3(0, -0.5, 0.1));
  bool ok = true;
  for(auto f : std::vector<std::array<SM_vertex, 3> >{{v[0], v[1], c1}, {v[1], v[2], c1}, {v[2], v[3], c1},
                                                      {v[3], v[4], c1}, {v[4], v[0], c1}})
    ok = ok && pinched.add_face(f[0], f[1], f[2]) != SM::null_face();
  for(auto f : std::vector<std::array<SM_vertex, 3> >{{v[0], v[8], c2}, {v[8], v[7], c2}, {v[7], v[6], c2},
                                                      {v[6], v[5], c2}, {v[5], v[0], c2}})
    ok = ok && pinched.add_face(f[0], f[1], f[2]) != SM::null_face();
  BOOST_REQUIRE(ok);
  expect_failure(pinched, mbp_test::longest_border(pinched), SMP::ERROR_NO_TOPOLOGICAL_DISC);
}

BOOST_AUTO_TEST_SUITE_END()
