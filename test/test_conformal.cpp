// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// Conformal_parameterizer_3 with the measured border (Measured_conformal_parameterizer_3):
// equality with CGAL's DCP plugged with the measured border, the shared factorization
// (2 factorizations, 4 back-substitutions), the grounded spring Laplacian, concurrency,
// solvers, generic meshes, bad input; and with the automatic border (Automatic_border).

#include <boost/test/unit_test.hpp>

#include "test_support.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Seam_mesh.h>

#include <CGAL/Surface_mesh_parameterization/Discrete_conformal_map_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <CGAL/Surface_mesh_parameterization/Conformal_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Conformal_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Default_sparse_cholesky_traits.h>
#include <CGAL/Surface_mesh_parameterization/Fixed_center.h>
#include <CGAL/Surface_mesh_parameterization/Geodesic_border_distance.h>
#include <CGAL/Surface_mesh_parameterization/Geodesic_center_locator.h>
#include <CGAL/Surface_mesh_parameterization/Measured_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Measured_conformal_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_report.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/disk.h>
#include <CGAL/Surface_mesh_parameterization/internal/distances/poisson_distance.h>
#include <CGAL/Surface_mesh_parameterization/measure_quality.h>
#ifdef MBP_WITH_CHOLMOD
#include <CGAL/Surface_mesh_parameterization/Cholmod_supernodal_cholesky_traits.h>
#endif

#include <Eigen/SparseLU>

#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

BOOST_AUTO_TEST_SUITE(conformal)

namespace SMP = CGAL::Surface_mesh_parameterization;
typedef CGAL::Simple_cartesian<double>                          K;
typedef CGAL::Exact_predicates_inexact_constructions_kernel     EPICK;
typedef CGAL::Surface_mesh<K::Point_3>                          Mesh;
typedef CGAL::Polyhedron_3<EPICK>                               Poly;
typedef boost::graph_traits<Mesh>::vertex_descriptor            vertex_descriptor;
typedef Mesh::Property_map<vertex_descriptor, K::Point_2>       UV_map;
typedef CGAL::Eigen_solver_traits<Eigen::SparseLU<CGAL::Eigen_sparse_matrix<double>::EigenType> > LU;
typedef SMP::Measured_conformal_parameterizer_3<Mesh>           Conformal;
typedef SMP::Measured_conformal_parameterizer_3<Mesh, CGAL::Default, CGAL::Default, CGAL::Default,
                                                CGAL::Parallel_tag> Conformal_parallel;
// the automatic border, with the Poisson policies for its measured member
typedef SMP::Conformal_parameterizer_3<Mesh, SMP::Automatic_border<> > Automatic;
typedef SMP::Conformal_parameterizer_3<Mesh, SMP::Automatic_border<>, CGAL::Default, CGAL::Parallel_tag>
  Automatic_parallel;
typedef SMP::Parameterization_report                            Report;

namespace {

Mesh read(mbp_test::Tier tier, const std::string& name)
{
  Mesh m;
  mbp_test::read_mesh(mbp_test::tier_mesh(tier, name), m);
  return m;
}

// max |a - b| / max |b - center of [0,1]^2|, over all vertices
double relative_difference(const Mesh& m, UV_map a, UV_map b)
{
  double diff = 0., scale = 0.;
  for(vertex_descriptor v : vertices(m))
  {
    diff = (std::max)(diff, std::sqrt(CGAL::squared_distance(a[v], b[v])));
    scale = (std::max)(scale, std::sqrt(CGAL::squared_distance(b[v], K::Point_2(0.5, 0.5))));
  }
  return diff / scale;
}

std::vector<std::string> real_meshes(mbp_test::Tier tier)
{
  if(tier == mbp_test::Tier::extended)
    return {"matthew_nefertiti.off", "lilium.obj", "snail.obj", "mask.off"};
  return {"nefertiti.off", "mushroom.off", "patch-20.off"};
}

} // namespace

MBP_TIERED_TEST_CASE(equals_cgal_dcp_with_the_measured_border_and_a_direct_solver)
{
  std::vector<std::pair<std::string, Mesh> > meshes;
  if(tier == mbp_test::Tier::core)
  {
    meshes.emplace_back("bumpy disk", mbp_test::make_mesh<Mesh>(mbp_test::bumpy_disk()));
    meshes.emplace_back("L-shape", mbp_test::make_mesh<Mesh>(mbp_test::l_shape()));
  }
  for(const std::string& name : real_meshes(tier))
    meshes.emplace_back(name, read(tier, name));
  for(auto& named : meshes)
  {
    Mesh& m = named.second;
    const auto bhd = mbp_test::longest_border(m);
    UV_map ours = mbp_test::new_uv_map(m, "v:ours"), cgal = mbp_test::new_uv_map(m, "v:cgal");
    Conformal conformal;
    BOOST_REQUIRE_EQUAL(SMP::parameterize(m, conformal, bhd, ours), SMP::OK);
    SMP::Discrete_conformal_map_parameterizer_3<Mesh, SMP::Measured_border_parameterizer_3<Mesh>, LU> dcp;
    BOOST_REQUIRE_EQUAL(SMP::parameterize(m, dcp, bhd, cgal), SMP::OK);
    const double d = relative_difference(m, ours, cgal);
    BOOST_TEST_MESSAGE(named.first << ": relative difference to CGAL's DCP " << d);
    BOOST_TEST_CONTEXT(named.first) { BOOST_TEST(d <= 1e-9); }
  }
}

BOOST_AUTO_TEST_CASE(two_factorizations_and_four_back_substitutions)
{
  Mesh m = mbp_test::make_mesh<Mesh>(mbp_test::bumpy_disk());
  UV_map uv = mbp_test::new_uv_map(m, "v:uv");
  Conformal conformal;
  Report r;
  BOOST_REQUIRE_EQUAL(SMP::parameterize(m, conformal, mbp_test::longest_border(m), uv, &r), SMP::OK);
  BOOST_TEST(r.status == SMP::OK);
  BOOST_TEST(r.statistics.factorizations == 2);      // L_II, and the spring Laplacian
  BOOST_TEST(r.statistics.back_substitutions == 4);  // BPDM, PDM, u, v
  BOOST_TEST(r.vertices == num_vertices(m));
  BOOST_TEST(r.faces == num_faces(m));
  for(double t : {r.preparation_seconds, r.center_seconds, r.distance_seconds, r.border_map_seconds,
                  r.interior_seconds, r.output_seconds})
  {
    BOOST_TEST(t >= 0.);
    BOOST_TEST(t <= r.total_seconds);
  }
  BOOST_TEST(r.preparation_seconds + r.center_seconds + r.distance_seconds + r.border_map_seconds +
             r.interior_seconds + r.output_seconds <= r.total_seconds * (1. + 1e-9));
  // the center is the drop-in measured border parameterizer's
  Report border_report;
  {
    UV_map b = mbp_test::new_uv_map(m, "v:border");
    auto done = m.add_property_map<vertex_descriptor, bool>("v:done", false).first;
    auto vimap = m.add_property_map<vertex_descriptor, int>("v:i", 0).first;
    SMP::Measured_border_parameterizer_3<Mesh> border;
    BOOST_REQUIRE_EQUAL(border.parameterize(m, mbp_test::longest_border(m), b, vimap, done, &border_report), SMP::OK);
  }
  BOOST_REQUIRE(r.has_center);
  BOOST_REQUIRE(border_report.has_center);
  BOOST_TEST(r.center == border_report.center);
  BOOST_TEST(!is_border(vertex_descriptor(Mesh::size_type(r.center)), m));

  // with a user center, L_II serves only the interior: still 2 factorizations, 3 solves
  typedef SMP::Measured_conformal_parameterizer_3<Mesh, SMP::Fixed_center<Mesh> > Fixed;
  Fixed fixed{Fixed::Border_policy(SMP::Fixed_center<Mesh>(vertex_descriptor(17)))};
  Report fixed_report;
  BOOST_REQUIRE_EQUAL(SMP::parameterize(m, fixed, mbp_test::longest_border(m), uv, &fixed_report), SMP::OK);
  BOOST_TEST(fixed_report.statistics.factorizations == 2);
  BOOST_TEST(fixed_report.statistics.back_substitutions == 3);
  BOOST_REQUIRE(fixed_report.has_center);
  BOOST_TEST(vertex_descriptor(Mesh::size_type(fixed_report.center)) == vertex_descriptor(17));
}

BOOST_AUTO_TEST_CASE(grounded_spring_laplacian_gives_the_poisson_distance_map)
{
  // The PDM from a source s solves the spring Laplacian restricted to V \ {s}. The package
  // gets it from one factorization grounded at a fixed vertex: check both agree, for
  // several sources, the ground vertex included.
  for(const mbp_test::Soup& soup : {mbp_test::bumpy_disk(), mbp_test::l_shape()})
  {
    Mesh m = mbp_test::make_mesh<Mesh>(soup);
    SMP::internal::Disk<Mesh, SMP::Default_sparse_cholesky_traits> patch;
    BOOST_REQUIRE_EQUAL(patch.build_disk(m, mbp_test::longest_border(m), get(CGAL::vertex_point, m)), SMP::OK);
    BOOST_REQUIRE_EQUAL(patch.factorize_spring_laplacian(1.), SMP::OK);
    const std::size_t n = patch.number_of_vertices();
    const std::size_t ground = static_cast<std::size_t>(patch.border().front());  // the spring system's ground
    for(std::size_t s : {ground, std::size_t(0), n / 3, n - 1})
      for(double r : {1., 2.})
      {
        std::vector<double> grounded, direct;
        BOOST_REQUIRE_EQUAL(patch.solve_spring_poisson(s, r, grounded), SMP::OK);
        BOOST_REQUIRE_EQUAL(SMP::internal::spring_poisson_distance(patch, std::vector<int>{int(s)}, r, direct),
                            SMP::OK);
        double worst = 0., largest = 0.;
        for(std::size_t i = 0; i < n; ++i)
        {
          worst = (std::max)(worst, std::abs(grounded[i] - direct[i]));
          largest = (std::max)(largest, direct[i]);
        }
        BOOST_TEST(grounded[s] == 0.);
        BOOST_TEST(worst <= 1e-10 * largest);
      }
  }
}

MBP_TIERED_TEST_CASE(concurrency_does_not_change_the_result)
{
  for(const std::string& name : real_meshes(tier))
  {
    Mesh m = read(tier, name);
    UV_map a = mbp_test::new_uv_map(m, "v:a"), b = mbp_test::new_uv_map(m, "v:b");
    Conformal_parallel concurrent;  // CGAL::Parallel_tag: the spring factorization in a second thread
    Conformal sequential;
    Report ra, rb;
    BOOST_REQUIRE_EQUAL(SMP::parameterize(m, concurrent, mbp_test::longest_border(m), a, &ra), SMP::OK);
    BOOST_REQUIRE_EQUAL(SMP::parameterize(m, sequential, mbp_test::longest_border(m), b, &rb), SMP::OK);
    BOOST_TEST(ra.has_center);
    BOOST_TEST(ra.center == rb.center);
    BOOST_TEST(relative_difference(m, a, b) == 0.);
  }
}

MBP_TIERED_TEST_CASE(every_solver_gives_the_same_parameterization)
{
  Mesh m = read(tier, real_meshes(tier)[0]);
  UV_map ldlt = mbp_test::new_uv_map(m, "v:ldlt");
  Conformal a;
  Report ra;
  BOOST_REQUIRE_EQUAL(SMP::parameterize(m, a, mbp_test::longest_border(m), ldlt, &ra), SMP::OK);
  // the paper's method with the solver traits of `solver`: the same center and map as LDLT
  auto same_as_ldlt = [&](auto solver, const std::string& name) {
    typedef SMP::Measured_conformal_parameterizer_3<Mesh, SMP::Poisson_center_locator,
                                                    SMP::Poisson_border_distance, decltype(solver)> Other;
    BOOST_TEST_CONTEXT(name)
    {
      UV_map uv = mbp_test::new_uv_map(m, "v:" + name);
      Other other(typename Other::Border_policy(), solver);  // the traits object is passed in
      Report r;
      BOOST_REQUIRE_EQUAL(SMP::parameterize(m, other, mbp_test::longest_border(m), uv, &r), SMP::OK);
      BOOST_TEST(ra.center == r.center);
      BOOST_TEST(relative_difference(m, uv, ldlt) <= 1e-9);
      BOOST_TEST(r.statistics.factorizations == 2);
    }
  };
  same_as_ldlt(LU(), "lu");
#ifdef MBP_WITH_CHOLMOD
  same_as_ldlt(SMP::Cholmod_supernodal_cholesky_traits(), "cholmod");
  same_as_ldlt(SMP::Cholmod_nested_dissection_cholesky_traits(), "nested");
#else
  BOOST_TEST_MESSAGE("CHOLMOD not available in this build: CHOLMOD solver not tested");
#endif
}

#ifdef MBP_WITH_CHOLMOD
// The 5-point Laplacian of an n x n grid with Dirichlet border: the orderings give the same
// solution, and nested dissection fills less than AMD (the grid is its textbook case).
BOOST_AUTO_TEST_CASE(cholmod_orderings_solve_alike_and_nested_dissection_fills_less)
{
  const int n = 120, N = n * n;
  std::vector<Eigen::Triplet<double> > t;
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < n; ++j)
    {
      const int r = i * n + j;
      t.emplace_back(r, r, 4.);
      if(i > 0)     t.emplace_back(r, r - n, -1.);
      if(i + 1 < n) t.emplace_back(r, r + n, -1.);
      if(j > 0)     t.emplace_back(r, r - 1, -1.);
      if(j + 1 < n) t.emplace_back(r, r + 1, -1.);
    }
  SMP::Cholmod_supernodal_cholesky_traits::Matrix A(N, N);
  A.eigen_object().setFromTriplets(t.begin(), t.end());
  Eigen::MatrixXd b = Eigen::MatrixXd::Ones(N, 2), x_amd, x_nd;
  b.col(1).setLinSpaced(N, -1., 1.);

  SMP::Cholmod_supernodal_cholesky_traits amd;
  SMP::Cholmod_nested_dissection_cholesky_traits nd;
  BOOST_TEST(amd.ordering() == SMP::Cholmod_supernodal_cholesky_traits::AMD);
  BOOST_TEST(nd.ordering() == SMP::Cholmod_supernodal_cholesky_traits::NESTED_DISSECTION);
  double D = 0.;
  BOOST_REQUIRE(amd.factor(A, D));
  BOOST_REQUIRE(nd.factor(A, D));
  BOOST_REQUIRE(amd.solve(b, x_amd));
  BOOST_REQUIRE(nd.solve(b, x_nd));
  const Eigen::MatrixXd residual = A.eigen_object() * x_nd - b;
  BOOST_TEST(residual.cwiseAbs().maxCoeff() <= 1e-9);
  BOOST_TEST((x_nd - x_amd).cwiseAbs().maxCoeff() <= 1e-9 * x_amd.cwiseAbs().maxCoeff());
  BOOST_TEST_MESSAGE("factor nonzeros: AMD " << amd.factor_nonzeros() << ", nested dissection "
                     << nd.factor_nonzeros());
  BOOST_TEST(nd.factor_nonzeros() > std::size_t(N));
  BOOST_TEST(nd.factor_nonzeros() < amd.factor_nonzeros());
}
#endif

MBP_TIERED_TEST_CASE(result_is_valid_and_better_than_the_circle_on_open_patches)
{
  for(const std::string& name : real_meshes(tier))
  {
    Mesh m = read(tier, name);
    UV_map uv = mbp_test::new_uv_map(m, "v:uv"), circle = mbp_test::new_uv_map(m, "v:circle");
    Conformal conformal;
    BOOST_REQUIRE_EQUAL(SMP::parameterize(m, conformal, mbp_test::longest_border(m), uv), SMP::OK);
    SMP::Discrete_conformal_map_parameterizer_3<Mesh, SMP::Circular_border_arc_length_parameterizer_3<Mesh>, LU> dcp;
    BOOST_REQUIRE_EQUAL(SMP::parameterize(m, dcp, mbp_test::longest_border(m), circle), SMP::OK);
    const SMP::Parameterization_quality q = SMP::measure_quality(m, faces(m), uv);
    const SMP::Parameterization_quality qc = SMP::measure_quality(m, faces(m), circle);
    BOOST_TEST_CONTEXT(name)
    {
      BOOST_TEST(q.flipped_faces == 0u);
      BOOST_TEST(q.angle_distortion < 0.8 * qc.angle_distortion);
      for(vertex_descriptor v : vertices(m))
      {
        BOOST_TEST(uv[v].x() >= -1e-12);
        BOOST_TEST(uv[v].x() <= 1. + 1e-12);
        BOOST_TEST(uv[v].y() >= -1e-12);
        BOOST_TEST(uv[v].y() <= 1. + 1e-12);
      }
    }
  }
}

BOOST_AUTO_TEST_CASE(polyhedron_and_seam_mesh)
{
  const mbp_test::Soup soup = mbp_test::bumpy_disk();
  Mesh sm = mbp_test::make_mesh<Mesh>(soup);
  UV_map uv = mbp_test::new_uv_map(sm, "v:uv");
  Conformal conformal;
  BOOST_REQUIRE_EQUAL(SMP::parameterize(sm, conformal, mbp_test::longest_border(sm), uv), SMP::OK);
  std::map<std::array<double, 3>, K::Point_2> by_point;
  for(vertex_descriptor v : vertices(sm))
    by_point[{sm.point(v).x(), sm.point(v).y(), sm.point(v).z()}] = uv[v];

  {
    Poly poly;
    mbp_test::soup_to_mesh(soup, poly);
    typedef boost::graph_traits<Poly>::vertex_descriptor Poly_vertex;
    std::map<Poly_vertex, EPICK::Point_2> storage;
    auto puv = boost::make_assoc_property_map(storage);
    SMP::Measured_conformal_parameterizer_3<Poly> p;
    BOOST_REQUIRE_EQUAL(SMP::parameterize(poly, p, mbp_test::longest_border(poly), puv), SMP::OK);
    double worst = 0.;
    for(Poly_vertex v : vertices(poly))
    {
      const K::Point_2& ref = by_point.at({v->point().x(), v->point().y(), v->point().z()});
      worst = (std::max)(worst, std::hypot(ref.x() - get(puv, v).x(), ref.y() - get(puv, v).y()));
    }
    BOOST_TEST(worst < 1e-12);
  }
  {
    typedef Mesh::Property_map<boost::graph_traits<Mesh>::edge_descriptor, bool> Seam_edges;
    typedef Mesh::Property_map<vertex_descriptor, bool> Seam_vertices;
    typedef CGAL::Seam_mesh<Mesh, Seam_edges, Seam_vertices> Seam;
    Mesh base = mbp_test::make_mesh<Mesh>(soup);
    Seam_edges se = base.add_property_map<boost::graph_traits<Mesh>::edge_descriptor, bool>("e:seam", false).first;
    Seam_vertices sv = base.add_property_map<vertex_descriptor, bool>("v:seam", false).first;
    Seam seam(base, se, sv);
    auto suv = get(CGAL::dynamic_vertex_property_t<K::Point_2>(), seam);
    SMP::Measured_conformal_parameterizer_3<Seam> p;
    BOOST_REQUIRE_EQUAL(SMP::parameterize(seam, p, mbp_test::longest_border(seam), suv), SMP::OK);
    double worst = 0.;
    for(auto v : vertices(seam))
    {
      const K::Point_3& q = get(get(CGAL::vertex_point, seam), v);
      const K::Point_2& ref = by_point.at({q.x(), q.y(), q.z()});
      worst = (std::max)(worst, std::sqrt(CGAL::squared_distance(ref, get(suv, v))));
    }
    BOOST_TEST(worst < 1e-12);
  }
}

BOOST_AUTO_TEST_CASE(bad_input_writes_nothing)
{
  auto expect = [](Mesh& m, boost::graph_traits<Mesh>::halfedge_descriptor bhd, SMP::Error_code code) {
    UV_map uv = mbp_test::new_uv_map(m, "v:uv");
    auto done = m.add_property_map<vertex_descriptor, bool>("v:done", false).first;
    auto vimap = m.add_property_map<vertex_descriptor, int>("v:i", 0).first;
    Conformal conformal;
    Report report;
    BOOST_TEST(conformal.parameterize(m, bhd, uv, vimap, done, &report) == code);
    BOOST_TEST(report.status == code);
    for(vertex_descriptor v : vertices(m))
    {
      BOOST_TEST(uv[v] == K::Point_2(-7, -7));
      BOOST_TEST(!done[v]);
    }
  };
  {
    Mesh empty;
    expect(empty, boost::graph_traits<Mesh>::null_halfedge(), SMP::ERROR_EMPTY_MESH);
  }
  {
    mbp_test::Soup soup = mbp_test::bumpy_disk();
    soup.points[5][2] = std::numeric_limits<double>::quiet_NaN();
    Mesh m = mbp_test::make_mesh<Mesh>(soup);
    expect(m, mbp_test::longest_border(m), SMP::ERROR_NON_FINITE_COORDINATES);
  }
  {
    Mesh torus = mbp_test::make_mesh<Mesh>(mbp_test::punctured_torus());
    expect(torus, mbp_test::longest_border(torus), SMP::ERROR_NO_TOPOLOGICAL_DISC);
  }
  {
    // a user center on the border
    Mesh m = mbp_test::make_mesh<Mesh>(mbp_test::bumpy_disk());
    const auto bhd = mbp_test::longest_border(m);
    UV_map uv = mbp_test::new_uv_map(m, "v:uv");
    typedef SMP::Measured_conformal_parameterizer_3<Mesh, SMP::Fixed_center<Mesh> > Fixed;
    Fixed fixed{Fixed::Border_policy(SMP::Fixed_center<Mesh>(source(bhd, m)))};
    BOOST_TEST(SMP::parameterize(m, fixed, bhd, uv) == SMP::ERROR_WRONG_PARAMETER);
    for(vertex_descriptor v : vertices(m))
      BOOST_TEST(uv[v] == K::Point_2(-7, -7));
  }
}

// ---------------------------------------------------------------- the automatic border

namespace {

// The angle distortion of the parameterization with the border policy of `p` without repair,
// or +infinity when it is not one-to-one.
template <class Parameterizer>
double unrepaired_angle_distortion(Mesh& m, const Parameterizer& p, const std::string& name)
{
  UV_map uv = mbp_test::new_uv_map(m, name);
  const Parameterizer unrepaired(p.border_policy(), p.solver_traits(), SMP::NO_REPAIR);
  const SMP::Error_code status = SMP::parameterize(m, unrepaired, mbp_test::longest_border(m), uv);
  BOOST_TEST((status == SMP::OK || status == SMP::ERROR_NO_1_TO_1_MAPPING), name << ": " << status);
  return status == SMP::OK ? SMP::measure_quality(m, faces(m), uv).angle_distortion
                           : std::numeric_limits<double>::infinity();
}

std::vector<std::string> automatic_border_meshes(mbp_test::Tier tier)
{
  if(tier == mbp_test::Tier::extended)  // open patches, and nearly closed shapes where the circle wins
    return {"matthew_nefertiti.off", "lilium.obj", "inspired_mesh.obj", "snail.obj", "venus.off", "lion-head.off",
            "alligator.obj"};
  return {"nefertiti.off", "mushroom.off", "patch-20.off"};
}

} // namespace

MBP_TIERED_TEST_CASE(automatic_border_is_never_worse_than_its_members)
{
  for(const std::string& name : automatic_border_meshes(tier))
    BOOST_TEST_CONTEXT(name)
    {
      Mesh m = read(tier, name);
      UV_map uv = mbp_test::new_uv_map(m, "v:auto"), circle_uv = mbp_test::new_uv_map(m, "v:circle");
      Automatic automatic;
      Report report;
      BOOST_REQUIRE_EQUAL(SMP::parameterize(m, automatic, mbp_test::longest_border(m), uv, &report), SMP::OK);
      const SMP::Parameterization_quality q = SMP::measure_quality(m, faces(m), uv);
      BOOST_TEST(q.flipped_faces == 0u);
      BOOST_TEST(SMP::is_one_to_one_uv_map(m, faces(m), uv));

      // the references, computed independently: CGAL's DCP with its arc-length circle and
      // with the drop-in conformal border, and this package's Poisson measured border
      // without repair
      SMP::Discrete_conformal_map_parameterizer_3<Mesh, SMP::Circular_border_arc_length_parameterizer_3<Mesh>, LU> dcp;
      BOOST_REQUIRE_EQUAL(SMP::parameterize(m, dcp, mbp_test::longest_border(m), circle_uv), SMP::OK);
      const double circle = SMP::measure_quality(m, faces(m), circle_uv).angle_distortion;
      const double poisson = unrepaired_angle_distortion(m, Conformal(), "v:poisson");
      UV_map conformal_uv = mbp_test::new_uv_map(m, "v:conformal");
      typedef mbp_test::Reporting_border<SMP::Conformal_border_parameterizer_3<Mesh> > Reporting_conformal_border;
      Report conformal_border;  // the report of the border step inside CGAL's DCP
      SMP::Discrete_conformal_map_parameterizer_3<Mesh, Reporting_conformal_border, LU> conformal_dcp(
        Reporting_conformal_border{&conformal_border});
      BOOST_REQUIRE_EQUAL(SMP::parameterize(m, conformal_dcp, mbp_test::longest_border(m), conformal_uv), SMP::OK);
      BOOST_REQUIRE(conformal_border.status == SMP::OK);
      const double conformal = SMP::is_one_to_one_uv_map(m, faces(m), conformal_uv)
                                 ? SMP::measure_quality(m, faces(m), conformal_uv).angle_distortion
                                 : std::numeric_limits<double>::infinity();
      BOOST_TEST_MESSAGE(name << ": auto " << q.angle_distortion << ", circle " << circle << ", Poisson " << poisson
                              << ", conformal " << conformal << ", " << report.border_candidates.size()
                              << " candidates");
      const double slack = 1e-9 * circle;
      BOOST_TEST(q.angle_distortion <= circle + slack);
      BOOST_TEST(q.angle_distortion <= poisson + slack);
      BOOST_TEST(q.angle_distortion <= conformal + slack);

      // the report: a bounded search, the circle, the measured border and the conformal
      // border among the candidates with the distortions computed above, the kept one the
      // best valid one
      BOOST_TEST(report.border_candidates.size() <= 15u);
      BOOST_REQUIRE(report.chosen_candidate >= 0);
      int members = 0;
      double best = std::numeric_limits<double>::infinity();
      for(const SMP::Border_candidate& c : report.border_candidates)
      {
        BOOST_TEST((c.valid == std::isfinite(c.objective)));
        if(c.valid)
          best = (std::min)(best, c.objective);
        if(c.family == SMP::CIRCLE)
        {
          ++members;
          BOOST_TEST(c.valid);
          BOOST_TEST(std::abs(c.objective - circle) <= 1e-7 * circle);
        }
        if(c.family == SMP::MEASURED && c.blend == 0.)
        {
          ++members;
          BOOST_TEST((c.valid ? std::abs(c.objective - poisson) <= 1e-7 * poisson : !std::isfinite(poisson)));
        }
        if(c.family == SMP::CONFORMAL && c.blend == conformal_border.conformal_blend && !c.holomorphic_extension)
        {
          ++members;
          BOOST_TEST((c.valid ? std::abs(c.objective - conformal) <= 1e-7 * conformal + 1e-15 : !std::isfinite(conformal)));
        }
      }
      // the measured member is built only when the conformal layout is not one-to-one
      BOOST_TEST(members == (std::isfinite(conformal) ? 2 : 3));
      const SMP::Border_candidate& kept =
        report.border_candidates[static_cast<std::size_t>(report.chosen_candidate)];
      BOOST_TEST(kept.objective == best);
      BOOST_TEST(std::abs(kept.objective - q.angle_distortion) <= 1e-9 * q.angle_distortion + 1e-15);
      BOOST_TEST(report.status == SMP::OK);
      BOOST_TEST(!report.repaired);
    }
}

MBP_TIERED_TEST_CASE(automatic_border_finds_the_flat_shape)
{
  // a flat disk whose border vertices are evenly spaced on a circle: the circle member is the
  // exact shape (the cotangent Laplacian reproduces linear functions)
  if(tier == mbp_test::Tier::core)
  {
    Mesh m = mbp_test::make_mesh<Mesh>(mbp_test::polar_disk(8, 32));
    UV_map uv = mbp_test::new_uv_map(m, "v:uv");
    Automatic automatic;
    BOOST_REQUIRE_EQUAL(SMP::parameterize(m, automatic, mbp_test::longest_border(m), uv), SMP::OK);
    const SMP::Parameterization_quality q = SMP::measure_quality(m, faces(m), uv);
    BOOST_TEST(q.angle_distortion <= 1e-9);
    BOOST_TEST(std::abs(q.l2_stretch - 1.) <= 1e-9);
  }
  // flat star-shaped disks that are not round (a generated ellipse; bump-domain.obj): with
  // exact geodesic distances the measured border, a member, is the exact shape
  std::vector<std::pair<std::string, Mesh> > meshes;
  if(tier == mbp_test::Tier::core)
    meshes.emplace_back("hex ellipse", mbp_test::make_mesh<Mesh>(mbp_test::hex_disk(10, 2., 1.)));
  else
    meshes.emplace_back("bump-domain.obj", read(tier, "bump-domain.obj"));
  for(auto& named : meshes)
    BOOST_TEST_CONTEXT(named.first)
    {
      Mesh& m = named.second;
      UV_map uv = mbp_test::new_uv_map(m, "v:uv");
      SMP::Conformal_parameterizer_3<Mesh, SMP::Automatic_border<SMP::Geodesic_center_locator<SMP::Exact_geodesics>,
                                                                 SMP::Geodesic_border_distance<SMP::Exact_geodesics> > >
        automatic;
      Report report;
      BOOST_REQUIRE_EQUAL(SMP::parameterize(m, automatic, mbp_test::longest_border(m), uv, &report), SMP::OK);
      const SMP::Parameterization_quality q = SMP::measure_quality(m, faces(m), uv);
      BOOST_TEST(q.angle_distortion <= 1e-9);
      BOOST_TEST(q.area_distortion_max <= 1e-9);
      BOOST_TEST(std::abs(q.l2_stretch - 1.) <= 1e-9);
      BOOST_REQUIRE(report.chosen_candidate >= 0);
      const auto& kept = report.border_candidates[static_cast<std::size_t>(report.chosen_candidate)];
      BOOST_TEST(kept.blend == ((kept.family == SMP::CIRCLE) ? 1. : 0.));
    }
}

MBP_TIERED_TEST_CASE(automatic_border_is_deterministic)
{
  const std::string name = automatic_border_meshes(tier)[1];
  Mesh m = read(tier, name);
  UV_map a = mbp_test::new_uv_map(m, "v:a"), b = mbp_test::new_uv_map(m, "v:b"), c = mbp_test::new_uv_map(m, "v:c");
  Automatic first, second;
  Automatic_parallel parallel;  // the parallel variant must give the same
  Report first_report, second_report, parallel_report;
  BOOST_REQUIRE_EQUAL(SMP::parameterize(m, first, mbp_test::longest_border(m), a, &first_report), SMP::OK);
  BOOST_REQUIRE_EQUAL(SMP::parameterize(m, second, mbp_test::longest_border(m), b, &second_report), SMP::OK);
  BOOST_REQUIRE_EQUAL(SMP::parameterize(m, parallel, mbp_test::longest_border(m), c, &parallel_report), SMP::OK);
  BOOST_TEST(relative_difference(m, a, b) == 0.);
  BOOST_TEST(relative_difference(m, a, c) == 0.);
  auto same_report = [&first_report](const Report& other) {
    const auto& x = first_report.border_candidates;
    const auto& y = other.border_candidates;
    BOOST_REQUIRE_EQUAL(x.size(), y.size());
    for(std::size_t i = 0; i < x.size(); ++i)
    {
      BOOST_TEST(int(x[i].family) == int(y[i].family));
      BOOST_TEST(x[i].blend == y[i].blend);
      BOOST_TEST(x[i].valid == y[i].valid);
      BOOST_TEST(((x[i].objective == y[i].objective) || (!x[i].valid && !y[i].valid)));
    }
    BOOST_TEST(first_report.chosen_candidate == other.chosen_candidate);
  };
  same_report(second_report);
  same_report(parallel_report);

  // the same choice through Polyhedron_3
  Poly poly;
  mbp_test::read_mesh(mbp_test::tier_mesh(tier, name), poly);
  typedef boost::graph_traits<Poly>::vertex_descriptor Poly_vertex;
  std::map<Poly_vertex, EPICK::Point_2> storage;
  auto puv = boost::make_assoc_property_map(storage);
  SMP::Conformal_parameterizer_3<Poly, SMP::Automatic_border<> > p;
  Report poly_report;
  BOOST_REQUIRE_EQUAL(SMP::parameterize(poly, p, mbp_test::longest_border(poly), puv, &poly_report), SMP::OK);
  BOOST_TEST(poly_report.chosen_candidate == first_report.chosen_candidate);
  std::map<std::array<double, 3>, K::Point_2> by_point;
  for(vertex_descriptor v : vertices(m))
    by_point[{m.point(v).x(), m.point(v).y(), m.point(v).z()}] = a[v];
  double worst = 0.;
  for(Poly_vertex v : vertices(poly))
  {
    const K::Point_2& ref = by_point.at({v->point().x(), v->point().y(), v->point().z()});
    worst = (std::max)(worst, std::hypot(ref.x() - get(puv, v).x(), ref.y() - get(puv, v).y()));
  }
  BOOST_TEST(worst < 1e-9);
}

BOOST_AUTO_TEST_SUITE_END()
