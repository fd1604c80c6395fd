// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// Validity: the one-to-one tests, the repair of folded measured parameterizations, and
// meshes with holes (filled virtually for the solves, every hole a simple polygon).

#include <boost/test/unit_test.hpp>

#include "test_support.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <CGAL/Surface_mesh_parameterization/Default_sparse_cholesky_traits.h>
#include <CGAL/Surface_mesh_parameterization/Fixed_center.h>
#include <CGAL/Surface_mesh_parameterization/Geodesic_border_distance.h>
#include <CGAL/Surface_mesh_parameterization/Measured_conformal_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_report.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/disk.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/validity.h>
#include <CGAL/Surface_mesh_parameterization/measure_quality.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

BOOST_AUTO_TEST_SUITE(validity)

namespace SMP = CGAL::Surface_mesh_parameterization;
typedef CGAL::Simple_cartesian<double>                          K;
typedef CGAL::Exact_predicates_inexact_constructions_kernel     EK;
typedef CGAL::Surface_mesh<K::Point_3>                          Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor            vertex_descriptor;
typedef boost::graph_traits<Mesh>::halfedge_descriptor          halfedge_descriptor;
typedef Mesh::Property_map<vertex_descriptor, K::Point_2>       UV_map;
typedef SMP::Measured_conformal_parameterizer_3<Mesh>           Conformal;
typedef SMP::internal::Disk<Mesh, SMP::Default_sparse_cholesky_traits> Disk;

namespace {

// The border loops of the mesh other than `bhd`'s, in UV: each must be a simple polygon.
bool holes_are_simple_polygons(const Mesh& m, halfedge_descriptor bhd, UV_map uv, int& holes)
{
  holes = 0;
  std::vector<bool> seen(num_halfedges(m), false);
  for(auto h : halfedges_around_face(bhd, m))
    seen[std::size_t(h)] = true;
  for(halfedge_descriptor h : halfedges(m))
  {
    if(!is_border(h, m) || seen[std::size_t(h)])
      continue;
    ++holes;
    std::vector<EK::Point_2> polygon;
    for(auto g : halfedges_around_face(h, m))
    {
      seen[std::size_t(g)] = true;
      polygon.emplace_back(uv[source(g, m)].x(), uv[source(g, m)].y());
    }
    const std::size_t n = polygon.size();
    for(std::size_t i = 0; i < n; ++i)
      for(std::size_t j = i + 2; j < n; ++j)
      {
        if(i == 0 && j == n - 1)
          continue;  // consecutive
        if(CGAL::do_intersect(EK::Segment_2(polygon[i], polygon[(i + 1) % n]),
                              EK::Segment_2(polygon[j], polygon[(j + 1) % n])))
          return false;
      }
  }
  return true;
}

} // namespace

// ------------------------------------------------------------------ the one-to-one tests

BOOST_AUTO_TEST_CASE(global_overlap_test)
{
  // A long flat strip, 40 x 1: mapped onto itself it is one-to-one; wound onto a circle so
  // that its ends overlap, no triangle is flipped but the map is not one-to-one.
  mbp_test::Soup strip;
  const int n = 80;
  for(int i = 0; i <= n; ++i)
    for(int j = 0; j <= 1; ++j)
      strip.points.push_back({0.5 * i, double(j), 0.});
  for(int i = 0; i < n; ++i)
  {
    const std::size_t a = std::size_t(2 * i), b = a + 2, c = a + 3, d = a + 1;
    strip.faces.push_back({a, b, c});
    strip.faces.push_back({a, c, d});
  }
  Mesh m = mbp_test::make_mesh<Mesh>(strip);
  UV_map uv = mbp_test::new_uv_map(m, "v:uv");
  for(vertex_descriptor v : vertices(m))
    uv[v] = K::Point_2(m.point(v).x(), m.point(v).y());
  BOOST_TEST(SMP::is_one_to_one_uv_map(m, faces(m), uv));
  BOOST_TEST(SMP::measure_quality(m, faces(m), uv).flipped_faces == 0u);
  for(vertex_descriptor v : vertices(m))  // angle = x / 5: 8 radians, more than a full turn
  {
    const double angle = m.point(v).x() / 5., radius = 3. - m.point(v).y();
    uv[v] = K::Point_2(radius * std::cos(angle), radius * std::sin(angle));
  }
  BOOST_TEST(SMP::measure_quality(m, faces(m), uv).flipped_faces == 0u);
  BOOST_TEST(!SMP::is_one_to_one_uv_map(m, faces(m), uv));
  // one vertex pushed across its neighbours: flipped faces
  for(vertex_descriptor v : vertices(m))
    uv[v] = K::Point_2(m.point(v).x(), m.point(v).y());
  uv[vertex_descriptor(21)] = K::Point_2(uv[vertex_descriptor(21)].x() + 2., uv[vertex_descriptor(21)].y());
  BOOST_TEST(SMP::measure_quality(m, faces(m), uv).flipped_faces > 0u);
  BOOST_TEST(!SMP::is_one_to_one_uv_map(m, faces(m), uv));
}

BOOST_AUTO_TEST_CASE(global_overlap_test_agrees_with_cgals)
{
  // is_one_to_one_uv_map() against CGAL's own test (the public is_one_to_one_mapping() member
  // of LSCM_parameterizer_3), on the flat layout of a disk with more and more vertices moved
  // by pseudo-random offsets: both must give the same answer every time, and both answers
  // must occur.
  Mesh m = mbp_test::make_mesh<Mesh>(mbp_test::polar_disk(6, 16));
  const halfedge_descriptor bhd = mbp_test::longest_border(m);
  UV_map uv = mbp_test::new_uv_map(m, "v:uv");
  SMP::LSCM_parameterizer_3<Mesh> cgal;
  mbp_test::Lcg lcg(12345u);
  auto random = [&lcg]() { return 2. * lcg() - 1.; };  // in [-1, 1), the same sequence everywhere
  int valid = 0, invalid = 0;
  for(int trial = 0; trial < 300; ++trial)
  {
    for(vertex_descriptor v : vertices(m))
      uv[v] = K::Point_2(m.point(v).x(), m.point(v).y());
    const double amplitude = 0.02 + 0.001 * trial;
    for(int k = 0; k < 1 + trial % 5; ++k)
    {
      const vertex_descriptor v(Mesh::size_type(std::abs(random()) * double(num_vertices(m))) % num_vertices(m));
      uv[v] = K::Point_2(uv[v].x() + amplitude * random(), uv[v].y() + amplitude * random());
    }
    const bool ours = SMP::is_one_to_one_uv_map(m, faces(m), uv);
    const bool theirs = cgal.is_one_to_one_mapping(m, bhd, uv);
    BOOST_TEST_CONTEXT("trial " << trial) { BOOST_TEST(ours == theirs); }
    (ours ? valid : invalid)++;
  }
  BOOST_TEST_MESSAGE(valid << " one-to-one layouts, " << invalid << " folded ones");
  BOOST_TEST(valid > 30);
  BOOST_TEST(invalid > 30);
}

BOOST_AUTO_TEST_CASE(patch_test_accepts_valid_and_rejects_folded_layouts)
{
  Mesh m = mbp_test::make_mesh<Mesh>(mbp_test::disk_with_two_holes());
  Disk patch;
  BOOST_REQUIRE_EQUAL(patch.build_disk(m, mbp_test::longest_border(m), get(CGAL::vertex_point, m)), SMP::OK);
  BOOST_REQUIRE_EQUAL(patch.hole_loops().size(), 2u);
  // the flat layout of the (almost flat) mesh: one-to-one
  std::vector<Eigen::Vector2d> uv(patch.number_of_vertices());
  for(std::size_t i = 0; i < uv.size(); ++i)
    uv[i] = patch.point(i).head<2>();
  BOOST_TEST(SMP::internal::is_one_to_one(patch, uv));
  // a hole mirrored through its centroid is traversed the wrong way
  std::vector<Eigen::Vector2d> bad = uv;
  Eigen::Vector2d c = Eigen::Vector2d::Zero();
  for(int i : patch.hole_loops()[0])
    c += uv[std::size_t(i)];
  c /= double(patch.hole_loops()[0].size());
  for(int i : patch.hole_loops()[0])  // mirrored across the vertical line through c
    bad[std::size_t(i)] = Eigen::Vector2d(2. * c.x() - uv[std::size_t(i)].x(), uv[std::size_t(i)].y());
  BOOST_TEST(!SMP::internal::border_curves_are_valid(patch, bad));
  // a hole vertex moved across the outer border: the curves intersect
  bad = uv;
  bad[std::size_t(patch.hole_loops()[1][0])] = Eigen::Vector2d(3., 0.);
  BOOST_TEST(!SMP::internal::border_curves_are_valid(patch, bad));
  BOOST_TEST(!SMP::internal::is_one_to_one(patch, bad));
}

// ------------------------------------------------------------------ holes

BOOST_AUTO_TEST_CASE(holes_are_filled_virtually_and_stay_simple_polygons)
{
  Mesh m = mbp_test::make_mesh<Mesh>(mbp_test::disk_with_two_holes());
  const halfedge_descriptor bhd = mbp_test::longest_border(m);
  Disk patch;
  BOOST_REQUIRE_EQUAL(patch.build_disk(m, bhd, get(CGAL::vertex_point, m)), SMP::OK);
  BOOST_TEST(patch.number_of_border_loops() == 3);
  BOOST_TEST(patch.number_of_real_vertices() == num_vertices(m));
  BOOST_TEST(patch.number_of_vertices() == num_vertices(m) + 2);    // one virtual vertex per hole
  BOOST_TEST(patch.number_of_real_faces() == num_faces(m));
  BOOST_TEST(patch.number_of_faces() == num_faces(m) + 8);          // each hole has 4 edges
  BOOST_TEST(patch.is_virtual(num_vertices(m)));
  BOOST_TEST((patch.vertex(num_vertices(m)) == boost::graph_traits<Mesh>::null_vertex()));
  // the filled patch is a disk: every edge but the outer border's has two faces
  std::size_t single = 0;
  for(unsigned char mask : patch.single_edge_masks())
    single += (mask & 1) + ((mask >> 1) & 1) + ((mask >> 2) & 1);
  BOOST_TEST(single == patch.border().size());

  UV_map uv = mbp_test::new_uv_map(m, "v:uv");
  Conformal conformal;
  SMP::Parameterization_report report;
  BOOST_REQUIRE_EQUAL(SMP::parameterize(m, conformal, bhd, uv, &report), SMP::OK);
  BOOST_REQUIRE(report.has_center);
  BOOST_TEST(!is_border(vertex_descriptor(Mesh::size_type(report.center)), m));
  BOOST_TEST(SMP::is_one_to_one_uv_map(m, faces(m), uv));
  int holes = 0;
  BOOST_TEST(holes_are_simple_polygons(m, bhd, uv, holes));
  BOOST_TEST(holes == 2);
  BOOST_TEST(report.vertices == num_vertices(m));
}

MBP_TIERED_TEST_CASE(real_meshes_with_holes)
{
  // CGAL's data meshes with holes; the project's meshes add nefertiti-entire (its other meshes
  // with holes are copies of CGAL's)
  const std::vector<std::string> names = (tier == mbp_test::Tier::core)
    ? std::vector<std::string>{"lion.off", "holes.off", "head.off", "blade.off", "mech-holes-shark.off"}
    : std::vector<std::string>{"nefertiti-entire.off"};
  for(const std::string& name : names)
    BOOST_TEST_CONTEXT(name)
    {
      Mesh m;
      mbp_test::read_mesh(mbp_test::tier_mesh(tier, name), m);
      const halfedge_descriptor bhd = mbp_test::longest_border(m);
      UV_map uv = mbp_test::new_uv_map(m, "v:uv");
      Conformal conformal;
      SMP::Parameterization_report r;
      BOOST_REQUIRE_EQUAL(SMP::parameterize(m, conformal, bhd, uv, &r), SMP::OK);
      const SMP::Parameterization_quality q = SMP::measure_quality(m, faces(m), uv);
      int holes = 0;
      BOOST_TEST(q.flipped_faces == 0u);
      BOOST_TEST(SMP::is_one_to_one_uv_map(m, faces(m), uv));
      BOOST_TEST(holes_are_simple_polygons(m, bhd, uv, holes));
      BOOST_TEST(holes > 0);
      BOOST_TEST_MESSAGE(name << ": " << holes << " holes, angle distortion " << q.angle_distortion
                         << (r.repaired ? ", repaired (" + std::to_string(r.flipped_faces_before_repair) +
                                            " flipped faces before; blend " + std::to_string(r.blend) +
                                            (r.mean_value_interior ? ", mean value interior)" : ")")
                                        : std::string(", valid without repair")));
    }
}

// ------------------------------------------------------------------ repair

namespace {

// Runs a parameterizer with the border policy `border` without repair (a clear error and
// nothing written, or a valid map), then with the default repair (always one-to-one).
// Returns whether it folded.
template <class BorderPolicy>
bool check_repair(Mesh& m, const BorderPolicy& border)
{
  typedef SMP::Conformal_parameterizer_3<Mesh, BorderPolicy> Parameterizer;
  const halfedge_descriptor bhd = mbp_test::longest_border(m);
  UV_map uv = mbp_test::new_uv_map(m, "v:uv");
  auto done = m.add_property_map<vertex_descriptor, bool>("v:done", false).first;
  auto vimap = m.add_property_map<vertex_descriptor, int>("v:i", 0).first;
  const Parameterizer unrepaired(border, typename Parameterizer::Solver_traits(), SMP::NO_REPAIR);
  SMP::Parameterization_report before;
  const SMP::Error_code raw = unrepaired.parameterize(m, bhd, uv, vimap, done, &before);
  if(raw == SMP::OK)
    BOOST_TEST(SMP::is_one_to_one_uv_map(m, faces(m), uv));
  else
  {
    BOOST_TEST(raw == SMP::ERROR_NO_1_TO_1_MAPPING);
    BOOST_TEST(!before.valid_before_repair);
    for(vertex_descriptor v : vertices(m))
    {
      BOOST_TEST(uv[v] == K::Point_2(-7, -7));
      BOOST_TEST(!done[v]);
    }
  }
  const Parameterizer repairing(border, typename Parameterizer::Solver_traits(), SMP::BLEND_TOWARD_CIRCLE);
  SMP::Parameterization_report r;
  BOOST_REQUIRE_EQUAL(repairing.parameterize(m, bhd, uv, vimap, done, &r), SMP::OK);
  BOOST_TEST(SMP::is_one_to_one_uv_map(m, faces(m), uv));
  BOOST_TEST(r.repaired == (raw != SMP::OK));
  BOOST_TEST(r.flipped_faces_before_repair == before.flipped_faces_before_repair);
  if(r.repaired)
  {
    BOOST_TEST(r.blend >= 0.);
    BOOST_TEST(r.blend <= 1.);
    BOOST_TEST(r.repair_candidates > 0);
    BOOST_TEST_MESSAGE("repaired " << r.flipped_faces_before_repair << " flipped faces: blend " << r.blend
                       << (r.mean_value_interior ? ", mean value interior" : ", conformal interior")
                       << ", angle distortion " << SMP::measure_quality(m, faces(m), uv).angle_distortion
                       << ", " << r.repair_candidates << " candidates, " << r.repair_seconds << " s");
  }
  m.remove_property_map(uv);
  m.remove_property_map(done);
  m.remove_property_map(vimap);
  return raw != SMP::OK;
}

} // namespace

BOOST_AUTO_TEST_CASE(generated_fold_is_repaired_or_rejected)
{
  // The C-shaped flat domain seen from a vertex of its top arm: the exact geodesic radii of
  // the hidden parts make the discrete conformal interior fold.
  Mesh m = mbp_test::make_mesh<Mesh>(mbp_test::c_shape());
  vertex_descriptor center;
  for(vertex_descriptor v : vertices(m))
    if(CGAL::squared_distance(m.point(v), K::Point_3(1.5, 13. / 6., 0.)) < 1e-12)
      center = v;
  BOOST_REQUIRE(center != Mesh::null_vertex());
  typedef SMP::Measured_border<SMP::Fixed_center<Mesh>, SMP::Geodesic_border_distance<SMP::Exact_geodesics> > Exact;
  BOOST_TEST(check_repair(m, Exact(SMP::Fixed_center<Mesh>(center))));
}

MBP_TIERED_TEST_CASE(real_folds_of_the_poisson_border_are_repaired_or_rejected)
{
  // the meshes where DCP with the measured (Poisson) border folds: in CGAL's data three_peaks;
  // in the project's meshes alligator (flat, not star-shaped), horse and dog (cut seams)
  const std::vector<std::string> names = (tier == mbp_test::Tier::core)
    ? std::vector<std::string>{"three_peaks.off"}
    : std::vector<std::string>{"alligator.obj", "horse.obj", "dog.obj"};
  for(const std::string& name : names)
    BOOST_TEST_CONTEXT(name)
    {
      Mesh m;
      mbp_test::read_mesh(mbp_test::tier_mesh(tier, name), m);
      BOOST_TEST(check_repair(m, Conformal::Border_policy()));
    }
}

BOOST_AUTO_TEST_CASE(rounding_that_defeats_the_circle_ends_the_repair)
{
  // 45 units deep: the conformal factor of the far rings (about exp(-45) = 3e-20) is below the
  // precision of a UV near 0.5, so every map of this disk into the unit square collapses
  // them, the circle's mean value map too (Floater's theorem needs exact arithmetic).
  const int spokes = 16, rings = int(std::ceil(45. / (2. * CGAL_PI / spokes)));
  // A tube closed at one end, open at z = 0 (its border), its rings one edge length apart: a
  // disk whose conformal map shrinks the ring at depth z by about exp(-z).
  Mesh m = mbp_test::make_mesh<Mesh>(mbp_test::tube(spokes, rings, 2. * CGAL_PI / spokes, true));
  const halfedge_descriptor bhd = mbp_test::longest_border(m);
  BOOST_REQUIRE_EQUAL(CGAL::halfedges_around_face(bhd, m).size(), std::size_t(spokes));
  UV_map uv = mbp_test::new_uv_map(m, "v:uv");
  SMP::Parameterization_report r;
  BOOST_TEST(SMP::parameterize(m, SMP::Conformal_parameterizer_3<Mesh>(), bhd, uv, &r) == SMP::ERROR_NO_1_TO_1_MAPPING);
  for(vertex_descriptor v : vertices(m))
    BOOST_TEST(uv[v] == K::Point_2(-7, -7));  // nothing written
  // The repair tried each member's own border with the mean value interior, found the
  // circle's folded, and searched no blend: one mean value layout per member, none valid.
  std::vector<SMP::Border_family> mean_value_members;
  bool circle_tried = false;
  for(const SMP::Border_candidate& c : r.border_candidates)
    if(c.mean_value_interior)
    {
      BOOST_TEST(!c.valid);
      circle_tried = circle_tried || c.family == SMP::CIRCLE;
      BOOST_TEST((std::find(mean_value_members.begin(), mean_value_members.end(), c.family) ==
                  mean_value_members.end()), "member " << int(c.family) << " blended (t = " << c.blend << ")");
      mean_value_members.push_back(c.family);
    }
  BOOST_TEST(circle_tried);
  BOOST_TEST(mean_value_members.size() >= 2u);
}

BOOST_AUTO_TEST_SUITE_END()
