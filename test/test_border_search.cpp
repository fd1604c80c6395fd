// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// The border searches against their definitions (issue 15, from test_edges.cpp): the
// automatic border's bisection for the smallest valid blend, and the conformal border's
// blend toward the circle (the smallest simple blend, its turning angles).

#include <boost/test/unit_test.hpp>

#include "test_support.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Surface_mesh_parameterization/Conformal_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Default_sparse_cholesky_traits.h>
#include <CGAL/Surface_mesh_parameterization/Fixed_center.h>
#include <CGAL/Surface_mesh_parameterization/Geodesic_border_distance.h>
#include <CGAL/Surface_mesh_parameterization/main_border.h>
#include <CGAL/Surface_mesh_parameterization/Measured_border.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_report.h>
#include <CGAL/Surface_mesh_parameterization/internal/borders/border_evaluator.h>
#include <CGAL/Surface_mesh_parameterization/internal/borders/border_members.h>
#include <CGAL/Surface_mesh_parameterization/internal/borders/border_search.h>
#include <CGAL/Surface_mesh_parameterization/internal/borders/border_step.h>
#include <CGAL/Surface_mesh_parameterization/internal/borders/conformal_border.h>
#include <CGAL/Surface_mesh_parameterization/internal/borders/polar_map.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/disk.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/validity.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

BOOST_AUTO_TEST_SUITE(border_search)

namespace SMP = CGAL::Surface_mesh_parameterization;
typedef CGAL::Simple_cartesian<double>                          K;
typedef CGAL::Surface_mesh<K::Point_3>                          Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor            vertex_descriptor;
typedef boost::graph_traits<Mesh>::halfedge_descriptor          halfedge_descriptor;
typedef Mesh::Property_map<vertex_descriptor, K::Point_2>       UV_map;
typedef SMP::internal::Disk<Mesh, SMP::Default_sparse_cholesky_traits> Disk;
typedef SMP::internal::Border_evaluator<Disk>                   Evaluator;

namespace {

// The trials of one member with one interior, as (blend, valid, objective).
struct Trial
{
  double blend;
  bool valid;
  double objective;
};

std::vector<Trial> trials_of(const Evaluator& evaluator, SMP::Border_family member, bool mean_value)
{
  std::vector<Trial> out;
  for(const SMP::internal::Border_trial& t : evaluator.trials())
    if(t.member == member && t.mean_value == mean_value)
      out.push_back({t.blend, t.valid, t.objective});
  return out;
}

// The search from a member whose own layout is not one-to-one: its result, the smallest valid
// blend it tried (what the parameterizer keeps), is larger than the member's own blend, every
// invalid trial is smaller, and the gap between the largest invalid trial and the result is
// that of `steps` bisection steps of [own, 1]; no more than steps + 1 trials besides the own
// layout's.
void check_search(Evaluator& evaluator, SMP::Border_family member, bool mean_value)
{
  const double own = evaluator.members().own_blend(member);
  const SMP::internal::Border_trial first = evaluator.evaluate({{member, own}}, mean_value).front();
  BOOST_REQUIRE_MESSAGE(!first.valid, "the member's own layout is one-to-one: nothing to search");
  const int steps = SMP::internal::valid_blend_bisection_steps;
  SMP::internal::search_smallest_valid_blend(evaluator, {member}, mean_value);
  const std::vector<Trial> trials = trials_of(evaluator, member, mean_value);
  bool seen = false;
  double largest_invalid = -1., smallest_valid = 2.;
  for(const Trial& x : trials)
  {
    if(x.valid)
      smallest_valid = (std::min)(smallest_valid, x.blend);
    else
      largest_invalid = (std::max)(largest_invalid, x.blend);
    BOOST_TEST(x.blend >= own);
    BOOST_TEST(x.blend <= 1.);
  }
  const double t = smallest_valid;
  for(const Trial& x : trials)
    seen = seen || (x.valid && x.blend == t);
  BOOST_TEST(seen);                      // a valid blend was found (1 at worst: convex)
  BOOST_REQUIRE(t > own);
  BOOST_TEST(t <= 1.);
  BOOST_TEST(largest_invalid < t);       // every invalid one is smaller
  if(t < 1.)
    BOOST_TEST(t - largest_invalid <= std::ldexp(1. - own, -steps) * (1. + 1e-12));
  BOOST_TEST(trials.size() <= std::size_t(steps + 2));
  // the kept layout is the valid one of lowest objective: the result's objective is finite
  double best_objective = std::numeric_limits<double>::infinity();
  for(const Trial& x : trials)
    if(x.valid && x.blend == t)
      best_objective = x.objective;
  BOOST_TEST(std::isfinite(best_objective));
  BOOST_TEST_MESSAGE("member " << int(member) << (mean_value ? ", mean value" : ", conformal") << " interior: "
                     << trials.size() << " trials, smallest valid blend " << t << " (objective " << best_objective
                     << "), largest invalid " << largest_invalid);
}

} // namespace

// ================================================================ the automatic border's search

BOOST_AUTO_TEST_CASE(search_finds_the_smallest_valid_blend_by_bisection)
{
  // the measured border folds: the C-shape seen from a vertex of its top arm with exact
  // geodesic radii (the discrete conformal interior of that border folds)
  {
    Mesh m = mbp_test::make_mesh<Mesh>(mbp_test::c_shape());
    vertex_descriptor center = Mesh::null_vertex();
    for(vertex_descriptor v : vertices(m))
      if(CGAL::squared_distance(m.point(v), K::Point_3(1.5, 13. / 6., 0.)) < 1e-12)
        center = v;
    BOOST_REQUIRE(center != Mesh::null_vertex());
    Disk disk;
    BOOST_REQUIRE_EQUAL(disk.build_disk(m, SMP::main_border(m).first, get(CGAL::vertex_point, m)), SMP::OK);
    // the measured member as Measured_border builds it for the complete parameterizer
    SMP::Parameterization_report report;
    SMP::internal::Border_step<Disk> step(disk, report, false, true);
    const SMP::Measured_border<SMP::Fixed_center<Mesh>, SMP::Geodesic_border_distance<SMP::Exact_geodesics> > border{
      SMP::Fixed_center<Mesh>(center)};
    BOOST_REQUIRE_EQUAL(border.build(step), SMP::OK);
    BOOST_REQUIRE(step.members.has(SMP::MEASURED));
    Evaluator evaluator(disk, step.members);
    check_search(evaluator, SMP::MEASURED, false);
  }
  // the conformal border overlaps itself: the spiral ramp (flat to first order, 1.6 turns);
  // its member starts at its smallest simple blend
  {
    Mesh m = mbp_test::make_mesh<Mesh>(mbp_test::spiral_ramp());
    Disk disk;
    BOOST_REQUIRE_EQUAL(disk.build_disk(m, SMP::main_border(m).first, get(CGAL::vertex_point, m)), SMP::OK);
    SMP::internal::Border_members members(disk);
    std::vector<Eigen::Vector2d> polygon;
    std::vector<double> closed;
    BOOST_REQUIRE_EQUAL(members.add_conformal(disk, polygon, closed), SMP::OK);
    BOOST_TEST(members.own_blend(SMP::CONFORMAL) > 0.);
    Evaluator evaluator(disk, members);
    const SMP::internal::Border_trial own =
      evaluator.evaluate({{SMP::CONFORMAL, members.own_blend(SMP::CONFORMAL)}}, false).front();
    BOOST_TEST_MESSAGE("spiral ramp: the conformal member's own layout is " << (own.valid ? "" : "not ") << "one-to-one");
    if(!own.valid)
      check_search(evaluator, SMP::CONFORMAL, false);
  }
}

// ================================================================ the measured border's blend

// The measured member's blend toward the circle (border_members.h) against its definition,
// computed here: at blend t the polar angle of border vertex k is (1 - t) phi_k + t c_k and
// its radius (1 - t) r_k / mean(r) + t, so t = 0 is the measured border (radii normalized)
// and t = 1 the circle; the placement only scales uniformly and translates.
BOOST_AUTO_TEST_CASE(measured_border_blend_toward_the_circle_against_its_definition)
{
  const std::vector<double> phi = {0., 0.3, 1.6, 2.0, 3.9, 4.4, 5.8};   // a star-shaped border
  const std::vector<double> r = {1.0, 2.5, 0.7, 1.9, 1.2, 3.0, 0.9};
  const std::size_t n = phi.size();
  std::vector<double> circle(n);
  for(std::size_t k = 0; k < n; ++k)
    circle[k] = 2. * CGAL_PI * double(k) / double(n);
  double mean = 0.;
  for(double x : r)
    mean += x / double(n);
  for(double t : {0., 0.3, 0.7, 1.})
  {
    SMP::internal::Polar_border out;
    BOOST_REQUIRE_EQUAL(SMP::internal::blended_border(phi, r, circle, t, out), SMP::OK);
    BOOST_REQUIRE_EQUAL(out.uv.size(), n);
    BOOST_TEST(out.scale > 0.);
    for(std::size_t k = 0; k < n; ++k)
    {
      const double a = (1. - t) * phi[k] + t * circle[k];
      const double rho = (1. - t) * r[k] / mean + t;
      const Eigen::Vector2d expected = out.origin + out.scale * rho * Eigen::Vector2d(std::cos(-a), std::sin(-a));
      BOOST_TEST((out.uv[k] - expected).norm() < 1e-12, "t = " << t << ", vertex " << k);
      BOOST_TEST(std::abs(out.angles[k] - a) < 1e-12, "t = " << t << ", vertex " << k);
    }
  }
}

// ================================================================ the conformal border's blend

BOOST_AUTO_TEST_CASE(conformal_border_blend_toward_the_circle_against_its_definition)
{
  // the spiral ramp: its conformal border overlaps itself, so the border is blended
  Mesh m = mbp_test::make_mesh<Mesh>(mbp_test::spiral_ramp());
  const halfedge_descriptor bhd = SMP::main_border(m).first;
  SMP::Conformal_border_parameterizer_3<Mesh> border;
  UV_map uv = mbp_test::new_uv_map(m, "v:uv");
  auto done = m.add_property_map<vertex_descriptor, bool>("v:done", false).first;
  auto index = m.add_property_map<vertex_descriptor, int>("v:index", 0).first;
  SMP::Parameterization_report r;
  BOOST_REQUIRE_EQUAL(border.parameterize(m, bhd, uv, index, done, &r), SMP::OK);
  const double t = r.conformal_blend;
  BOOST_TEST(t > 0.);
  BOOST_TEST(t < 1.);
  const std::vector<vertex_descriptor> border_vertices = mbp_test::border_loop_vertices(m, bhd);
  const std::size_t n = border_vertices.size();
  BOOST_REQUIRE_EQUAL(r.border_uv.size(), n);
  BOOST_REQUIRE_EQUAL(r.turning_angles.size(), n);
  BOOST_REQUIRE_EQUAL(r.edge_lengths.size(), n);
  std::vector<Eigen::Vector2d> border_uv;
  for(const std::array<double, 2>& p : r.border_uv)
    border_uv.emplace_back(p[0], p[1]);

  // the circle's turning angles from the 3D border lengths, computed here:
  // c_k = pi (l_{k-1} + l_k) / sum l
  std::vector<double> l(n);
  double total = 0.;
  for(std::size_t k = 0; k < n; ++k)
  {
    l[k] = std::sqrt(CGAL::squared_distance(m.point(border_vertices[k]), m.point(border_vertices[(k + 1) % n])));
    total += l[k];
    BOOST_TEST(std::abs(l[k] - r.edge_lengths[k]) <= 1e-14 * total);
  }
  // the turning angles of the polygon written, clockwise positive, against
  // (1 - t) k~ + t c
  double worst = 0., sum = 0.;
  std::vector<double> blended(n);
  for(std::size_t k = 0; k < n; ++k)
  {
    const double c = CGAL_PI * (l[(k + n - 1) % n] + l[k]) / total;
    blended[k] = (1. - t) * r.turning_angles[k] + t * c;
    const Eigen::Vector2d a = border_uv[k] - border_uv[(k + n - 1) % n];
    const Eigen::Vector2d b = border_uv[(k + 1) % n] - border_uv[k];
    const double turn = -std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));  // clockwise: positive
    sum += turn;
    worst = (std::max)(worst, std::abs(std::remainder(turn - blended[k], 2. * CGAL_PI)));
    const K::Point_2 p = uv[border_vertices[k]];
    BOOST_TEST((p.x() == border_uv[k].x() && p.y() == border_uv[k].y()));
  }
  BOOST_TEST(worst <= 1e-9, "largest turning angle difference " << worst);
  BOOST_TEST(std::abs(sum - 2. * CGAL_PI) <= 1e-9);  // a simple clockwise polygon
  BOOST_TEST(SMP::internal::is_simple_polygon(border_uv));
  // the smallest simple blend: a slightly smaller one is not simple
  std::vector<double> smaller(n);
  const double below = t - std::ldexp(1., -SMP::internal::simple_blend_bisection_steps);
  for(std::size_t k = 0; k < n; ++k)
    smaller[k] = (1. - below) * r.turning_angles[k] + below * CGAL_PI * (l[(k + n - 1) % n] + l[k]) / total;
  std::vector<Eigen::Vector2d> polygon;
  BOOST_REQUIRE(SMP::internal::polygon_from_turning_angles(smaller, l, polygon) == SMP::OK);
  BOOST_TEST(!SMP::internal::is_simple_polygon(polygon));
}

BOOST_AUTO_TEST_SUITE_END()
