// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// Geodesic distance maps (fast marching, Dijkstra, heat method, exact), the geodesic center
// locator (BGDM) and the geodesic border distances (MBPGP), and the full matrix of center and
// distance policies over Surface_mesh, Polyhedron_3 and Seam_mesh.

#include <boost/test/unit_test.hpp>

#include "test_support.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Seam_mesh.h>
#include <CGAL/Unique_hash_map.h>

#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <CGAL/Surface_mesh_parameterization/Default_sparse_cholesky_traits.h>
#include <CGAL/Surface_mesh_parameterization/Fixed_center.h>
#include <CGAL/Surface_mesh_parameterization/Geodesic_border_distance.h>
#include <CGAL/Surface_mesh_parameterization/Geodesic_center_locator.h>
#include <CGAL/Surface_mesh_parameterization/Measured_conformal_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Poisson_border_distance.h>
#include <CGAL/Surface_mesh_parameterization/Poisson_center_locator.h>
#include <CGAL/Surface_mesh_parameterization/Straightest_geodesic_border_distance.h>
#include <CGAL/Surface_mesh_parameterization/geodesic_distance_map.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/disk.h>
#include <CGAL/Surface_mesh_parameterization/measure_quality.h>

#include <boost/property_map/property_map.hpp>

#include <array>
#include <cmath>
#include <map>
#include <string>
#include <tuple>
#include <type_traits>
#include <typeinfo>
#include <vector>

BOOST_AUTO_TEST_SUITE(geodesics)

namespace SMP = CGAL::Surface_mesh_parameterization;
typedef CGAL::Simple_cartesian<double>                          K;
typedef CGAL::Exact_predicates_inexact_constructions_kernel     EPICK;
typedef CGAL::Surface_mesh<K::Point_3>                          Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor            vertex_descriptor;
typedef Mesh::Property_map<vertex_descriptor, double>           Dmap;
typedef SMP::Heat_method_geodesics<>                            Heat;
typedef SMP::Heat_method_geodesics<CGAL::Heat_method_3::Intrinsic_Delaunay> Heat_idt;
typedef SMP::internal::Disk<Mesh, SMP::Default_sparse_cholesky_traits> Disk;

namespace {

double euclid(const Mesh& m, vertex_descriptor a, vertex_descriptor b)
{
  return std::sqrt(CGAL::squared_distance(m.point(a), m.point(b)));
}

struct Errors
{
  double max_relative = 0.;  // over vertices farther than `near` from the sources
  double min_relative = 0.;  // most negative (distance below the Euclidean one)
};

template <class Method>
Errors distance_errors(Mesh& m, const std::vector<vertex_descriptor>& sources, double near)
{
  Dmap d = m.add_property_map<vertex_descriptor, double>("v:d", -1.).first;
  BOOST_REQUIRE_EQUAL(SMP::geodesic_distance_map<Method>(m, sources, d), SMP::OK);
  Errors e;
  for(vertex_descriptor v : vertices(m))
  {
    double ref = std::numeric_limits<double>::infinity();
    for(vertex_descriptor s : sources)
      ref = (std::min)(ref, euclid(m, v, s));
    if(ref == 0.)
    {
      BOOST_TEST(d[v] == 0.);
      continue;
    }
    if(ref < near)
      continue;
    e.max_relative = (std::max)(e.max_relative, (d[v] - ref) / ref);
    e.min_relative = (std::min)(e.min_relative, (d[v] - ref) / ref);
  }
  m.remove_property_map(d);
  return e;
}

// flat disks that are convex: geodesic = Euclidean distance
std::vector<std::pair<std::string, mbp_test::Soup> > flat_convex_meshes()
{
  return {{"hex ellipse", mbp_test::hex_disk(12, 2., 1.)}, {"polar disk", mbp_test::polar_disk(10, 32)}};
}

} // namespace

// ------------------------------------------------------------------ distance maps

BOOST_AUTO_TEST_CASE(exact_geodesics_equal_the_euclidean_distance_on_flat_convex_meshes)
{
  for(auto& named : flat_convex_meshes())
  {
    Mesh m = mbp_test::make_mesh<Mesh>(named.second);
    for(const std::vector<vertex_descriptor>& sources :
        {std::vector<vertex_descriptor>{vertex_descriptor(0)},
         std::vector<vertex_descriptor>{vertex_descriptor(3), vertex_descriptor(Mesh::size_type(num_vertices(m) - 1))}})
    {
      const Errors e = distance_errors<SMP::Exact_geodesics>(m, sources, 0.);
      BOOST_TEST_CONTEXT(named.first)
      {
        BOOST_TEST(e.max_relative <= 1e-9);
        BOOST_TEST(e.min_relative >= -1e-9);
      }
    }
  }
}

BOOST_AUTO_TEST_CASE(approximate_geodesics_are_close_to_the_euclidean_distance)
{
  // Stated bounds at distance >= 0.3 from the source on unit disks (measured values in the
  // log). Fast marching is first order: its error is a fraction of an edge length, mostly
  // made near the source, so the relative error shrinks with the distance (hex disk of 24
  // rings: within 5%); heat method within 10% (Direct) / 8% (intrinsic Delaunay); Dijkstra
  // never below the Euclidean distance, and on the hexagonal lattice at most 2/sqrt(3) - 1
  // = 15.5% above it (the worst direction between two lattice directions).
  const std::vector<std::pair<std::string, mbp_test::Soup> > meshes = {
    {"hex disk", mbp_test::hex_disk(24)}, {"polar disk", mbp_test::polar_disk(10, 32)}};
  for(auto& named : meshes)
  {
    Mesh m = mbp_test::make_mesh<Mesh>(named.second);
    const std::vector<vertex_descriptor> sources = {vertex_descriptor(0)};
    const double near = 0.3;
    const Errors fm = distance_errors<SMP::Fast_marching_geodesics>(m, sources, near);
    const Errors heat = distance_errors<Heat>(m, sources, near);
    const Errors idt = distance_errors<Heat_idt>(m, sources, near);
    const Errors dij = distance_errors<SMP::Dijkstra_geodesics>(m, sources, near);
    BOOST_TEST_MESSAGE(named.first << ": relative error range: fast marching [" << fm.min_relative << ", "
                       << fm.max_relative << "], heat [" << heat.min_relative << ", " << heat.max_relative
                       << "], heat iDT [" << idt.min_relative << ", " << idt.max_relative << "], Dijkstra ["
                       << dij.min_relative << ", " << dij.max_relative << "]");
    BOOST_TEST_CONTEXT(named.first)
    {
      BOOST_TEST(fm.min_relative >= -1e-12);  // a convex flat domain: never below Euclidean
      BOOST_TEST(fm.max_relative <= 0.05);
      BOOST_TEST((std::max)(heat.max_relative, -heat.min_relative) <= 0.10);
      BOOST_TEST((std::max)(idt.max_relative, -idt.min_relative) <= 0.08);
      BOOST_TEST(dij.min_relative >= -1e-12);
      BOOST_TEST(dij.max_relative <= 2. / std::sqrt(3.) - 1. + 1e-9);
      BOOST_TEST(fm.max_relative < dij.max_relative);
    }
  }
}

BOOST_AUTO_TEST_CASE(geodesic_distance_map_checks_its_input)
{
  Mesh m = mbp_test::make_mesh<Mesh>(mbp_test::bumpy_disk());
  Dmap d = m.add_property_map<vertex_descriptor, double>("v:d", -1.).first;
  BOOST_TEST(SMP::geodesic_distance_map<SMP::Exact_geodesics>(m, std::vector<vertex_descriptor>{}, d)
             == SMP::ERROR_WRONG_PARAMETER);
  Mesh empty;
  BOOST_TEST(SMP::geodesic_distance_map(empty, std::vector<vertex_descriptor>{vertex_descriptor(0)}, d)
             == SMP::ERROR_EMPTY_MESH);
  mbp_test::Soup bad = mbp_test::bumpy_disk();
  bad.points[4][0] = std::numeric_limits<double>::infinity();
  Mesh b = mbp_test::make_mesh<Mesh>(bad);
  Dmap db = b.add_property_map<vertex_descriptor, double>("v:d", -1.).first;
  BOOST_TEST(SMP::geodesic_distance_map<Heat>(b, std::vector<vertex_descriptor>{vertex_descriptor(0)}, db)
             == SMP::ERROR_NON_FINITE_COORDINATES);
  for(vertex_descriptor v : vertices(b))
    BOOST_TEST(db[v] == -1.);  // nothing written
}

// ------------------------------------------------------------------ centers

BOOST_AUTO_TEST_CASE(geodesic_center_respects_the_symmetries)
{
  // the ellipse has two BGDM maxima (paper Fig. 6): the tie-break gives the polar vertex
  {
    Mesh m = mbp_test::make_mesh<Mesh>(mbp_test::hex_disk(12, 2., 1.));
    Disk patch;
    BOOST_REQUIRE_EQUAL(patch.build_disk(m, mbp_test::longest_border(m), get(CGAL::vertex_point, m)), SMP::OK);
    std::size_t c = 0;
    BOOST_REQUIRE_EQUAL((SMP::Geodesic_center_locator<SMP::Exact_geodesics>().locate_center(patch, c)), SMP::OK);
    BOOST_TEST(patch.vertex(c) == vertex_descriptor(0));
    BOOST_REQUIRE_EQUAL((SMP::Geodesic_center_locator<SMP::Fast_marching_geodesics>().locate_center(patch, c)),
                        SMP::OK);
    BOOST_TEST(std::abs(m.point(patch.vertex(c)).y()) < 1e-12);  // on the long axis
  }
  // a curved egg, symmetric only under x -> -x: the center lies on the axis x = 0
  {
    mbp_test::Soup soup = mbp_test::hex_disk(12);
    for(auto& p : soup.points)
    {
      if(p[1] > 0.)
        p[1] *= 1.5;
      p[2] = 0.3 * p[0] * p[0];
    }
    Mesh m = mbp_test::make_mesh<Mesh>(soup);
    Disk patch;
    BOOST_REQUIRE_EQUAL(patch.build_disk(m, mbp_test::longest_border(m), get(CGAL::vertex_point, m)), SMP::OK);
    std::size_t c = 0;
    BOOST_REQUIRE_EQUAL((SMP::Geodesic_center_locator<SMP::Exact_geodesics>().locate_center(patch, c)), SMP::OK);
    BOOST_TEST(std::abs(m.point(patch.vertex(c)).x()) < 1e-12);
    BOOST_REQUIRE_EQUAL(SMP::Poisson_center_locator().locate_center(patch, c), SMP::OK);
    BOOST_TEST(std::abs(m.point(patch.vertex(c)).x()) < 1e-12);
  }
}

// ------------------------------------------------------------------ measured parameterizations

namespace {

template <class Center, class Distance>
SMP::Parameterization_quality measured(Mesh& m, SMP::Error_code expected = SMP::OK)
{
  auto uv = m.add_property_map<vertex_descriptor, K::Point_2>("v:uv").first;
  SMP::Measured_conformal_parameterizer_3<Mesh, Center, Distance> p;
  const SMP::Error_code status = SMP::parameterize(m, p, mbp_test::longest_border(m), uv);
  BOOST_REQUIRE_EQUAL(status, expected);
  SMP::Parameterization_quality q;
  if(status == SMP::OK)
    q = SMP::measure_quality(m, faces(m), uv);
  m.remove_property_map(uv);
  return q;
}

} // namespace

MBP_TIERED_TEST_CASE(exact_measured_border_reproduces_flat_star_shaped_meshes)
{
  // paper Table 1, Ellipse, MBPGP = 0: the polar map of exact distances is the flat shape
  std::vector<std::pair<std::string, Mesh> > meshes;
  if(tier == mbp_test::Tier::core)
    meshes.emplace_back("hex ellipse", mbp_test::make_mesh<Mesh>(mbp_test::hex_disk(12, 2., 1.)));
  else
  {
    Mesh bump;
    mbp_test::read_mesh(mbp_test::shared_mesh("bump-domain.obj"), bump);
    meshes.emplace_back("bump-domain.obj", std::move(bump));
  }
  for(auto& named : meshes)
  {
    const SMP::Parameterization_quality a =
      measured<SMP::Poisson_center_locator, SMP::Geodesic_border_distance<SMP::Exact_geodesics> >(named.second);
    const SMP::Parameterization_quality b =
      measured<SMP::Geodesic_center_locator<SMP::Exact_geodesics>,
               SMP::Geodesic_border_distance<SMP::Exact_geodesics> >(named.second);
    BOOST_TEST_MESSAGE(named.first << ": exact MBPGP angle distortion " << a.angle_distortion << ", L2 "
                       << a.l2_stretch << ", area " << a.area_distortion_max);
    for(const SMP::Parameterization_quality& q : {a, b})
      BOOST_TEST_CONTEXT(named.first)
      {
        BOOST_TEST(q.angle_distortion <= 1e-9);
        BOOST_TEST(q.angle_distortion_per_corner <= 1e-9);
        BOOST_TEST(q.area_distortion_max <= 1e-9);
        BOOST_TEST(std::abs(q.l2_stretch - 1.) <= 1e-9);
        BOOST_TEST(std::abs(q.quasi_conformal_max - 1.) <= 1e-9);
        BOOST_TEST(q.flipped_faces == 0u);
      }
  }
}

MBP_TIERED_TEST_CASE(flat_domain_not_star_shaped_is_not_reproduced)
{
  // A polar border is star-shaped: a flat domain that is star-shaped from none of its points
  // cannot be reproduced, wherever the center is. The C-shape (core): from a point of the left
  // bar the tips of the two arms cannot both be seen, and no point of an arm sees the other
  // arm's tip. The alligator (extended tier). Report what the exact geodesic border gives.
  Mesh m;
  if(tier == mbp_test::Tier::core)
    m = mbp_test::make_mesh<Mesh>(mbp_test::c_shape());
  else
    mbp_test::read_mesh(mbp_test::shared_mesh("alligator.obj"), m);
  auto uv = m.add_property_map<vertex_descriptor, K::Point_2>("v:uv").first;
  SMP::Measured_conformal_parameterizer_3<Mesh, SMP::Poisson_center_locator,
                                          SMP::Geodesic_border_distance<SMP::Exact_geodesics> > p;
  const SMP::Error_code status = SMP::parameterize(m, p, mbp_test::longest_border(m), uv);
  BOOST_TEST_MESSAGE("exact MBPGP on a flat non-star-shaped domain: " << SMP::get_measured_error_message(status));
  if(status == SMP::OK)
  {
    const SMP::Parameterization_quality q = SMP::measure_quality(m, faces(m), uv);
    BOOST_TEST_MESSAGE("  angle distortion " << q.angle_distortion << ", L2 " << q.l2_stretch << ", flipped "
                       << q.flipped_faces << ", area distortion max " << q.area_distortion_max);
    BOOST_TEST(q.angle_distortion > 1e-6);  // not an isometry: the shape cannot be reproduced
  }
  else
    BOOST_TEST(status == SMP::ERROR_DEGENERATE_BORDER_MAP);
}

BOOST_AUTO_TEST_CASE(geodesic_variant_costs_one_factorization_and_three_back_substitutions)
{
  Mesh m = mbp_test::make_mesh<Mesh>(mbp_test::bumpy_disk());
  auto uv = m.add_property_map<vertex_descriptor, K::Point_2>("v:uv").first;
  SMP::Measured_conformal_parameterizer_3<Mesh, SMP::Poisson_center_locator,
                                          SMP::Geodesic_border_distance<> > p;
  SMP::Parameterization_report report;
  BOOST_REQUIRE_EQUAL(SMP::parameterize(m, p, mbp_test::longest_border(m), uv, &report), SMP::OK);
  BOOST_TEST(report.statistics.factorizations == 1);
  BOOST_TEST(report.statistics.back_substitutions == 3);
}

// ------------------------------------------------------------------ the policy matrix

namespace {

typedef Mesh::Property_map<boost::graph_traits<Mesh>::edge_descriptor, bool> SM_seam_edges;
typedef Mesh::Property_map<vertex_descriptor, bool>                          SM_seam_vertices;
typedef CGAL::Seam_mesh<Mesh, SM_seam_edges, SM_seam_vertices>              Seam_sm;
typedef CGAL::Polyhedron_3<EPICK>                                            Poly;

template <class M> struct Centers
{
  typedef std::tuple<SMP::Poisson_center_locator,
                     SMP::Geodesic_center_locator<SMP::Fast_marching_geodesics>,
                     SMP::Geodesic_center_locator<SMP::Dijkstra_geodesics>,
                     SMP::Geodesic_center_locator<Heat>,
                     SMP::Geodesic_center_locator<SMP::Exact_geodesics> > type;
};
template <class M> struct Distances
{
  typedef std::tuple<SMP::Poisson_border_distance,
                     SMP::Geodesic_border_distance<SMP::Fast_marching_geodesics>,
                     SMP::Geodesic_border_distance<SMP::Dijkstra_geodesics>,
                     SMP::Geodesic_border_distance<Heat>,
                     SMP::Geodesic_border_distance<SMP::Exact_geodesics>,
                     SMP::Straightest_geodesic_border_distance > type;
};

// Runs one center/distance combination on `mesh`: a valid star-shaped layout, or (only for
// straightest geodesics) ERROR_DISTANCE_COMPUTATION_FAILED.
template <class M, class Center, class Distance>
void run_combination(M& mesh, int& runs, int& straightest_failures)
{
  typedef typename mbp_test::Kernel_of<M>::Point_2 Point_2;
  typedef typename boost::graph_traits<M>::vertex_descriptor vertex;
  // (not a dynamic property map: CGAL 6's copies Point_2(), whose coordinates are
  // indeterminate, into every vertex, which GCC 12 flags)
  std::map<vertex, Point_2> uv_storage;
  auto uv = boost::make_assoc_property_map(uv_storage);
  SMP::Measured_conformal_parameterizer_3<M, Center, Distance> p;
  SMP::Parameterization_report report;
  const SMP::Error_code status = SMP::parameterize(mesh, p, mbp_test::longest_border(mesh), uv, &report);
  ++runs;
  if(std::is_same<Distance, SMP::Straightest_geodesic_border_distance >::value &&
     status == SMP::ERROR_DISTANCE_COMPUTATION_FAILED)
  {
    ++straightest_failures;
    return;
  }
  BOOST_TEST_CONTEXT(typeid(Center).name() << " + " << typeid(Distance).name())
  {
    BOOST_REQUIRE_EQUAL(status, SMP::OK);
    const SMP::Parameterization_quality q = SMP::measure_quality(mesh, faces(mesh), uv);
    BOOST_TEST(q.flipped_faces == 0u);
    BOOST_TEST(std::isfinite(q.angle_distortion));
    BOOST_TEST(report.vertices == num_vertices(mesh));
  }
}

template <class M, class Center, class... Distance>
void run_center(M& mesh, std::tuple<Distance...>*, int& runs, int& failures)
{
  (run_combination<M, Center, Distance>(mesh, runs, failures), ...);
}

template <class M, class... Center>
void run_matrix(M& mesh, std::tuple<Center...>*, int& runs, int& failures)
{
  (run_center<M, Center>(mesh, static_cast<typename Distances<M>::type*>(nullptr), runs, failures), ...);
}

template <class M>
void run_all(M& mesh, const char* name)
{
  int runs = 0, failures = 0;
  run_matrix(mesh, static_cast<typename Centers<M>::type*>(nullptr), runs, failures);
  BOOST_TEST(runs == 30);
  BOOST_TEST_MESSAGE(name << ": " << runs << " combinations, straightest geodesics failed for "
                     << failures << " of 5 centers");
}

} // namespace

BOOST_AUTO_TEST_CASE(every_center_and_distance_combination_on_every_mesh_type)
{
  // a curved, mildly bumpy disk: every method is well defined on it
  const mbp_test::Soup soup = mbp_test::polar_disk(6, 16, 1.2, 0.9,
                                                   [](double x, double y) { return 0.15 * x * x + 0.1 * x * y; });
  {
    Mesh m = mbp_test::make_mesh<Mesh>(soup);
    run_all(m, "Surface_mesh");
  }
  {
    Poly m;
    mbp_test::soup_to_mesh(soup, m);
    run_all(m, "Polyhedron_3");
  }
  {
    Mesh base = mbp_test::make_mesh<Mesh>(soup);
    SM_seam_edges se = base.add_property_map<boost::graph_traits<Mesh>::edge_descriptor, bool>("e:seam", false).first;
    SM_seam_vertices sv = base.add_property_map<vertex_descriptor, bool>("v:seam", false).first;
    Seam_sm seam(base, se, sv);
    run_all(seam, "Seam_mesh");
  }
}

BOOST_AUTO_TEST_SUITE_END()
