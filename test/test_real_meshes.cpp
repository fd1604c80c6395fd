// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// Real meshes, CGAL's data meshes (core tier) and the project's meshes (extended tier): DCP
// with the measured border against DCP with CGAL's circular arc-length border, the Poisson
// distance map's positivity (paper Theorem A1), and Polyhedron_3 against Surface_mesh.

#include <boost/test/unit_test.hpp>

#include "test_support.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Surface_mesh_parameterization/Circular_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_conformal_map_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <CGAL/Surface_mesh_parameterization/Measured_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_report.h>
#include <CGAL/Surface_mesh_parameterization/measure_quality.h>
#include <CGAL/Surface_mesh_parameterization/poisson_distance_map.h>

#include <Eigen/SparseLU>

#include <array>
#include <cmath>
#include <map>
#include <string>
#include <vector>

BOOST_AUTO_TEST_SUITE(real_meshes)

namespace SMP = CGAL::Surface_mesh_parameterization;
typedef CGAL::Simple_cartesian<double>                          K;
typedef CGAL::Exact_predicates_inexact_constructions_kernel     EPICK;
typedef CGAL::Surface_mesh<K::Point_3>                          Mesh;
typedef CGAL::Polyhedron_3<EPICK>                               Poly;
typedef boost::graph_traits<Mesh>::vertex_descriptor            vertex_descriptor;
typedef CGAL::Eigen_solver_traits<Eigen::SparseLU<CGAL::Eigen_sparse_matrix<double>::EigenType> > LU;

namespace {

// Which meshes to run, and what is expected of each. The paper's method is meant to win on
// open patches; on nearly closed shapes with a short border the circle is as good or slightly
// better (reported, not asserted); the remaining disks are run and checked for validity.
struct Mesh_lists
{
  std::vector<std::string> open_patches, nearly_closed, other_disks;
  // disks on which the measured border is known to fold (not star-shaped from the center,
  // or cut seams): their flips are reported; repairing them is a separate feature
  std::vector<std::string> known_folds;
};

Mesh_lists mesh_lists(mbp_test::Tier tier)
{
  Mesh_lists l;
  if(tier == mbp_test::Tier::extended)  // the project's meshes, without the copies of CGAL's
  {
    l.open_patches = {"matthew_nefertiti.off", "bff_face.obj", "mask.off", "bimba_i.obj", "maxFace.obj",
                      "lilium.obj", "snail.obj", "inspired_mesh.obj", "irr4-cyl2.off"};
    l.nearly_closed = {"venus.off", "spothead.obj", "igl_face.obj"};
    l.other_disks = {"alligator.obj", "bimba_hole.off", "blade-nice-flip-cyl2.off", "bump-domain.obj",
                     "dog.obj", "horse.obj", "woody-hi.off"};
    l.known_folds = {"alligator.obj", "dog.obj", "horse.obj"};
  }
  else  // CGAL's data meshes (Debian's libcgal-demo)
  {
    l.open_patches = {"nefertiti.off", "mushroom.off", "cylinder_locally_refined.off", "cylinder.off",
                      "mesh_with_border.off", "patch-20.off", "plane.off"};
    l.nearly_closed = {"lion-head.off", "blob.off"};
    l.other_disks = {"patch-01.off", "patch-13.off", "patch-21.off", "patch-23.off", "mannequin-devil.off"};
  }
  return l;
}

bool contains(const std::vector<std::string>& v, const std::string& s)
{
  return std::find(v.begin(), v.end(), s) != v.end();
}

struct Result
{
  SMP::Error_code status;
  SMP::Parameterization_quality q;
};

template <class Border>
Result dcp(Mesh& mesh, Border border)
{
  auto uv = mesh.add_property_map<vertex_descriptor, K::Point_2>("v:uv").first;
  SMP::Discrete_conformal_map_parameterizer_3<Mesh, Border, LU> parameterizer(border);
  Result r;
  r.status = SMP::parameterize(mesh, parameterizer, mbp_test::longest_border(mesh), uv);
  if(r.status == SMP::OK)
  {
    r.q = SMP::measure_quality(mesh, faces(mesh), uv);
    for(vertex_descriptor v : vertices(mesh))
      BOOST_REQUIRE(std::isfinite(uv[v].x()) && std::isfinite(uv[v].y()));
  }
  mesh.remove_property_map(uv);
  return r;
}

struct Comparison
{
  Result circle, measured;
  double ratio() const { return measured.q.angle_distortion / circle.q.angle_distortion; }
};

Comparison compare_borders(mbp_test::Tier tier, const std::string& name)
{
  Mesh mesh;
  mbp_test::read_mesh(mbp_test::tier_mesh(tier, name), mesh);
  Comparison c;
  c.circle = dcp(mesh, SMP::Circular_border_arc_length_parameterizer_3<Mesh>());
  SMP::Parameterization_report measured;  // the report of the border step inside CGAL's DCP
  c.measured = dcp(mesh, mbp_test::Reporting_border<SMP::Measured_border_parameterizer_3<Mesh> >(&measured));
  BOOST_REQUIRE_EQUAL(c.circle.status, SMP::OK);
  BOOST_REQUIRE_MESSAGE(c.measured.status == SMP::OK,
                        name << ": " << SMP::get_measured_error_message(c.measured.status));
  BOOST_TEST(measured.status == SMP::OK);
  BOOST_REQUIRE(measured.has_center);
  const vertex_descriptor center = mbp_test::vertex_at_position(mesh, measured.center);
  BOOST_TEST_MESSAGE(name << ": V " << num_vertices(mesh) << ", angle distortion circle "
                     << c.circle.q.angle_distortion << " measured " << c.measured.q.angle_distortion
                     << " (ratio " << c.ratio() << "), L2 circle " << c.circle.q.l2_stretch << " measured "
                     << c.measured.q.l2_stretch << ", flips circle " << c.circle.q.flipped_faces
                     << " measured " << c.measured.q.flipped_faces << ", center " << center);
  return c;
}

} // namespace

BOOST_AUTO_TEST_CASE(core_meshes_are_present)
{
  BOOST_TEST_MESSAGE("CGAL's data meshes: " << mbp_test::cgal_mesh_dir());
  for(const std::string& name : mesh_lists(mbp_test::Tier::core).open_patches)
    BOOST_TEST(mbp_test::file_exists(mbp_test::core_mesh(name)));
}

MBP_TIERED_TEST_CASE(measured_border_lowers_angle_distortion_on_open_patches)
{
  for(const std::string& name : mesh_lists(tier).open_patches)
  {
    BOOST_TEST_CONTEXT(name)
    {
      const Comparison c = compare_borders(tier, name);
      BOOST_TEST(c.measured.q.flipped_faces <= c.circle.q.flipped_faces);
      // "clearly lower": at least 20% below the circle
      BOOST_TEST(c.ratio() <= 0.8);
    }
  }
}

MBP_TIERED_TEST_CASE(nearly_closed_shapes_are_measured_and_reported)
{
  // On nearly closed shapes with a short border the circle is as good or slightly better:
  // the ratios are reported; the assertion is only that the measured border stays valid and
  // within a factor 1.5 of the circle.
  for(const std::string& name : mesh_lists(tier).nearly_closed)
  {
    BOOST_TEST_CONTEXT(name)
    {
      const Comparison c = compare_borders(tier, name);
      BOOST_TEST(c.measured.q.flipped_faces <= c.circle.q.flipped_faces);
      BOOST_TEST(c.ratio() < 1.5);
    }
  }
}

MBP_TIERED_TEST_CASE(every_other_disk_mesh_is_parameterized)
{
  const Mesh_lists lists = mesh_lists(tier);
  for(const std::string& name : lists.other_disks)
  {
    BOOST_TEST_CONTEXT(name)
    {
      const Comparison c = compare_borders(tier, name);
      if(!contains(lists.known_folds, name))
        BOOST_TEST(c.measured.q.flipped_faces <= c.circle.q.flipped_faces);
    }
  }
}

MBP_TIERED_TEST_CASE(border_polygon_is_star_shaped_and_convexity_is_honest)
{
  int convex = 0, non_convex = 0;
  const Mesh_lists lists = mesh_lists(tier);
  for(const std::string& name : lists.open_patches)
  {
    Mesh mesh;
    mbp_test::read_mesh(mbp_test::tier_mesh(tier, name), mesh);
    auto uv = mesh.add_property_map<vertex_descriptor, K::Point_2>("v:uv").first;
    auto done = mesh.add_property_map<vertex_descriptor, bool>("v:done", false).first;
    auto vimap = mesh.add_property_map<vertex_descriptor, int>("v:i", 0).first;
    SMP::Measured_border_parameterizer_3<Mesh> border;
    SMP::Parameterization_report report;
    const auto bhd = mbp_test::longest_border(mesh);
    BOOST_REQUIRE_EQUAL(border.parameterize(mesh, bhd, uv, vimap, done, &report), SMP::OK);
    const auto& angles = report.border_angles;
    const auto& radii = report.border_distances;
    const std::vector<vertex_descriptor> loop = mbp_test::border_loop_vertices(mesh, bhd);
    bool strictly_convex = true;
    const std::size_t n = angles.size();
    BOOST_REQUIRE_EQUAL(radii.size(), n);
    BOOST_REQUIRE_EQUAL(loop.size(), n);
    for(std::size_t k = 0; k < n; ++k)
    {
      if(k + 1 < n)
        BOOST_TEST(angles[k + 1] > angles[k]);
      BOOST_TEST(radii[k] > 0.);
      const K::Point_2 &a = uv[loop[(k + n - 1) % n]], &b = uv[loop[k]], &c = uv[loop[(k + 1) % n]];
      if(!(CGAL::orientation(a, b, c) == CGAL::RIGHT_TURN))
        strictly_convex = false;
    }
    BOOST_TEST(angles.back() < 2. * CGAL_PI);
    BOOST_TEST_CONTEXT(name)
    {
      BOOST_TEST(border.is_border_convex() == strictly_convex);
      BOOST_TEST(report.border_convex == strictly_convex);
    }
    (strictly_convex ? convex : non_convex)++;
  }
  BOOST_TEST(convex > 0);      // both cases were exercised
  BOOST_TEST(non_convex > 0);
}

MBP_TIERED_TEST_CASE(poisson_distance_map_is_positive_away_from_its_sources)
{
  // Paper Theorem A1: with positive spring weights the map is 0 at the sources and > 0 elsewhere.
  const Mesh_lists lists = mesh_lists(tier);
  for(const std::string& name : {lists.open_patches[0], lists.open_patches[1], lists.nearly_closed[0]})
  {
    Mesh mesh;
    mbp_test::read_mesh(mbp_test::tier_mesh(tier, name), mesh);
    const std::vector<vertex_descriptor> sources = {vertex_descriptor(0),
                                                    vertex_descriptor(Mesh::size_type(num_vertices(mesh) / 2))};
    for(double r : {0., 1., 2.})
    {
      auto f = mesh.add_property_map<vertex_descriptor, double>("v:f", -1.).first;
      BOOST_REQUIRE_EQUAL(SMP::poisson_distance_map(mesh, sources, f, r), SMP::OK);
      std::size_t bad = 0;
      for(vertex_descriptor v : vertices(mesh))
      {
        const bool source = (v == sources[0] || v == sources[1]);
        if(source ? f[v] != 0. : !(f[v] > 0.))
          ++bad;
      }
      BOOST_TEST_CONTEXT(name << ", r = " << r) { BOOST_TEST(bad == 0u); }
      mesh.remove_property_map(f);
    }
  }
}

MBP_TIERED_TEST_CASE(polyhedron_and_surface_mesh_agree_on_a_real_mesh)
{
  const std::string path = mbp_test::tier_mesh(tier, mesh_lists(tier).open_patches[0]);
  Mesh sm;
  Poly poly;
  mbp_test::read_mesh(path, sm);
  mbp_test::read_mesh(path, poly);

  std::map<std::array<double, 3>, std::array<double, 2> > uv_sm;
  {
    auto uv = sm.add_property_map<vertex_descriptor, K::Point_2>("v:uv").first;
    SMP::Discrete_conformal_map_parameterizer_3<Mesh, SMP::Measured_border_parameterizer_3<Mesh>, LU> p;
    BOOST_REQUIRE_EQUAL(SMP::parameterize(sm, p, mbp_test::longest_border(sm), uv), SMP::OK);
    for(vertex_descriptor v : vertices(sm))
      uv_sm[{sm.point(v).x(), sm.point(v).y(), sm.point(v).z()}] = {uv[v].x(), uv[v].y()};
  }
  typedef boost::graph_traits<Poly>::vertex_descriptor Poly_vertex;
  std::map<Poly_vertex, EPICK::Point_2> storage;
  auto uv = boost::make_assoc_property_map(storage);
  SMP::Discrete_conformal_map_parameterizer_3<Poly, SMP::Measured_border_parameterizer_3<Poly>, LU> p;
  BOOST_REQUIRE_EQUAL(SMP::parameterize(poly, p, mbp_test::longest_border(poly), uv), SMP::OK);
  double worst = 0.;
  for(Poly_vertex v : vertices(poly))
  {
    const auto& a = uv_sm.at({v->point().x(), v->point().y(), v->point().z()});
    worst = (std::max)(worst, std::hypot(a[0] - get(uv, v).x(), a[1] - get(uv, v).y()));
  }
  BOOST_TEST(worst < 1e-9);
}

BOOST_AUTO_TEST_SUITE_END()
