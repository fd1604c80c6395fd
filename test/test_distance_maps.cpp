// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// Poisson distance maps (paper Eq. 1), the disk that shares one factorization
// (internal::Disk, the model of MeasuredDisk the policies see), the center locators, and the
// quality measures, on generated meshes whose geometry is known.

#include <boost/test/unit_test.hpp>

#include "test_support.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Surface_mesh_parameterization/Default_sparse_cholesky_traits.h>
#include <CGAL/Surface_mesh_parameterization/Fixed_center.h>
#include <CGAL/Surface_mesh_parameterization/Poisson_border_distance.h>
#include <CGAL/Surface_mesh_parameterization/Poisson_center_locator.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/disk.h>
#include <CGAL/Surface_mesh_parameterization/internal/distances/center_selection.h>
#include <CGAL/Surface_mesh_parameterization/measure_quality.h>
#include <CGAL/Surface_mesh_parameterization/poisson_distance_map.h>

#include <Eigen/SparseLU>

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

BOOST_AUTO_TEST_SUITE(distance_maps)

namespace SMP = CGAL::Surface_mesh_parameterization;
typedef CGAL::Simple_cartesian<double>                      K;
typedef CGAL::Surface_mesh<K::Point_3>                      Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor        vertex_descriptor;
typedef boost::graph_traits<Mesh>::halfedge_descriptor      halfedge_descriptor;
typedef Mesh::Property_map<vertex_descriptor, double>       Dmap;
typedef SMP::internal::Disk<Mesh, SMP::Default_sparse_cholesky_traits> Disk;

namespace {

const int RINGS = 10, SPOKES = 32;

Dmap new_map(Mesh& m, const std::string& name, double init = -1.)
{
  return m.add_property_map<vertex_descriptor, double>(name, init).first;
}

// The vertex of `m` at (x, y), up to rounding.
vertex_descriptor vertex_at(const Mesh& m, double x, double y)
{
  for(vertex_descriptor v : vertices(m))
    if(std::abs(m.point(v).x() - x) < 1e-12 && std::abs(m.point(v).y() - y) < 1e-12)
      return v;
  BOOST_FAIL("no vertex at (" << x << ", " << y << ")");
  return vertex_descriptor();
}

} // namespace

// ------------------------------------------------------------------ boundary Poisson map

BOOST_AUTO_TEST_CASE(bpdm_maximum_is_the_center_of_an_ellipse)
{
  Mesh m = mbp_test::make_mesh<Mesh>(mbp_test::hex_disk(RINGS, 2., 1.));  // x stretched: an ellipse
  Dmap f = new_map(m, "v:f");
  BOOST_REQUIRE_EQUAL(SMP::boundary_poisson_distance_map(m, mbp_test::longest_border(m), f), SMP::OK);

  const vertex_descriptor center(0);
  BOOST_REQUIRE(m.point(center) == K::Point_3(0, 0, 0));
  double second = 0.;
  for(vertex_descriptor v : vertices(m))
  {
    if(is_border(v, m))
      BOOST_TEST(f[v] == 0.);
    else
      BOOST_TEST(f[v] > 0.);
    if(v != center)
      second = (std::max)(second, f[v]);
  }
  // a single, clear global maximum at the polar vertex (paper Fig. 6)
  BOOST_TEST(f[center] > second * (1. + 1e-6));

  SMP::Poisson_center_locator locator;
  Disk disk;
  BOOST_REQUIRE_EQUAL(disk.build_disk(m, mbp_test::longest_border(m), get(CGAL::vertex_point, m)), SMP::OK);
  std::size_t c = 0;
  BOOST_REQUIRE_EQUAL(locator.locate_center(disk, c), SMP::OK);
  BOOST_TEST(disk.vertex(c) == center);
}

BOOST_AUTO_TEST_CASE(bpdm_respects_the_symmetries_of_the_ellipse)
{
  Mesh m = mbp_test::make_mesh<Mesh>(mbp_test::hex_disk(RINGS, 2., 1.));
  Dmap f = new_map(m, "v:f");
  BOOST_REQUIRE_EQUAL(SMP::boundary_poisson_distance_map(m, mbp_test::longest_border(m), f), SMP::OK);
  double fmax = 0.;
  for(vertex_descriptor v : vertices(m))
    fmax = (std::max)(fmax, f[v]);
  for(vertex_descriptor v : vertices(m))
  {
    const K::Point_3& p = m.point(v);
    BOOST_TEST(std::abs(f[vertex_at(m, -p.x(), p.y())] - f[v]) < 1e-9 * fmax);
    BOOST_TEST(std::abs(f[vertex_at(m, p.x(), -p.y())] - f[v]) < 1e-9 * fmax);
  }
}

BOOST_AUTO_TEST_CASE(bpdm_is_zero_on_the_loop_and_solves_equation_1)
{
  // Check the discrete equation itself: sum_j w_ij (f_i - f_j) = d_i g_i at interior vertices,
  // with cotangent weights recomputed here from the geometry.
  Mesh m = mbp_test::make_mesh<Mesh>(mbp_test::bumpy_disk());
  Dmap f = new_map(m, "v:f");
  BOOST_REQUIRE_EQUAL(SMP::boundary_poisson_distance_map(m, mbp_test::longest_border(m), f), SMP::OK);

  std::map<std::pair<std::size_t, std::size_t>, double> w;
  for(auto fd : faces(m))
  {
    std::vector<vertex_descriptor> t;
    for(vertex_descriptor v : vertices_around_face(halfedge(fd, m), m))
      t.push_back(v);
    for(int k = 0; k < 3; ++k)
    {
      const K::Point_3 &p = m.point(t[k]), &a = m.point(t[(k + 1) % 3]), &b = m.point(t[(k + 2) % 3]);
      const K::Vector_3 u = a - p, v = b - p;
      const double cot = (u * v) / std::sqrt(CGAL::cross_product(u, v).squared_length());
      std::size_t i = t[(k + 1) % 3], j = t[(k + 2) % 3];
      if(i > j) std::swap(i, j);
      w[{i, j}] += 0.5 * cot;
    }
  }
  std::vector<double> d(num_vertices(m), 0.), lap(num_vertices(m), 0.), g(num_vertices(m), 0.), deg(num_vertices(m), 0.);
  for(const auto& e : w)
  {
    const vertex_descriptor a(static_cast<Mesh::size_type>(e.first.first)), b(static_cast<Mesh::size_type>(e.first.second));
    d[a] += e.second; d[b] += e.second;
    lap[a] += e.second * (f[a] - f[b]);
    lap[b] += e.second * (f[b] - f[a]);
    const double l = std::sqrt(CGAL::squared_distance(m.point(a), m.point(b)));
    g[a] += l; g[b] += l; deg[a] += 1; deg[b] += 1;
  }
  for(vertex_descriptor v : vertices(m))
  {
    if(is_border(v, m))
    {
      BOOST_TEST(f[v] == 0.);
      continue;
    }
    BOOST_TEST(f[v] > 0.);
    BOOST_TEST(std::abs(lap[v] - d[v] * g[v] / deg[v]) < 1e-9 * d[v] * g[v] / deg[v]);
  }
}

// ------------------------------------------------------------------ Poisson distance map

BOOST_AUTO_TEST_CASE(pdm_is_zero_at_the_source_positive_elsewhere_and_grows_with_distance)
{
  Mesh m = mbp_test::make_mesh<Mesh>(mbp_test::polar_disk(RINGS, SPOKES));  // the unit disk
  const vertex_descriptor center(0);
  for(double r : {0., 1., 2.})
  {
    Dmap f = new_map(m, "v:f");
    BOOST_REQUIRE_EQUAL(SMP::poisson_distance_map(m, std::vector<vertex_descriptor>{center}, f, r), SMP::OK);
    BOOST_TEST(f[center] == 0.);
    for(vertex_descriptor v : vertices(m))
      if(v != center)
        BOOST_TEST(f[v] > 0.);
    // along every spoke, the map increases strictly from one ring to the next, and it is the
    // same on every ring vertex (the mesh has 32-fold rotational symmetry)
    for(int j = 0; j < SPOKES; ++j)
    {
      double previous = 0.;
      for(int k = 1; k <= RINGS; ++k)
      {
        const double angle = 2. * CGAL_PI * j / SPOKES, radius = double(k) / RINGS;
        const vertex_descriptor v = vertex_at(m, radius * std::cos(angle), radius * std::sin(angle));
        const vertex_descriptor v0 = vertex_at(m, radius, 0.);
        BOOST_TEST(f[v] > previous);
        BOOST_TEST(std::abs(f[v] - f[v0]) < 1e-9 * f[v0]);
        previous = f[v];
      }
    }
    m.remove_property_map(f);
  }
}

BOOST_AUTO_TEST_CASE(pdm_several_sources_and_components)
{
  // Two disjoint disks; sources only in the first: the second is left untouched.
  mbp_test::Soup a = mbp_test::polar_disk(4, 8), b = mbp_test::polar_disk(3, 8);
  const std::size_t offset = a.points.size();
  for(auto p : b.points)
    a.points.push_back({p[0] + 5., p[1], p[2]});
  for(auto t : b.faces)
    a.faces.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  Mesh m = mbp_test::make_mesh<Mesh>(a);
  Dmap f = new_map(m, "v:f", -1.);
  const std::vector<vertex_descriptor> sources = {vertex_descriptor(0), vertex_descriptor(5)};
  BOOST_REQUIRE_EQUAL(SMP::poisson_distance_map(m, sources, f), SMP::OK);
  for(vertex_descriptor v : vertices(m))
  {
    if(std::size_t(v) >= offset)
      BOOST_TEST(f[v] == -1.);
    else if(v == sources[0] || v == sources[1])
      BOOST_TEST(f[v] == 0.);
    else
      BOOST_TEST(f[v] > 0.);
  }
  BOOST_TEST(SMP::poisson_distance_map(m, std::vector<vertex_descriptor>{}, f) == SMP::ERROR_WRONG_PARAMETER);
  BOOST_TEST(SMP::poisson_distance_map(m, sources, f, std::nan("")) == SMP::ERROR_WRONG_PARAMETER);
}

BOOST_AUTO_TEST_CASE(maps_are_invariant_under_rigid_motion_and_scale_with_the_mesh)
{
  Mesh m = mbp_test::make_mesh<Mesh>(mbp_test::bumpy_disk());
  Mesh moved = m;
  const double s = 3.7;
  const double c = std::cos(0.8), sn = std::sin(0.8);
  for(vertex_descriptor v : vertices(moved))
  {
    const K::Point_3 p = m.point(v);  // rotate about z, then about x, scale, translate
    const double x = c * p.x() - sn * p.y(), y = sn * p.x() + c * p.y(), z = p.z();
    moved.point(v) = K::Point_3(s * x + 10., s * (c * y - sn * z) - 4., s * (sn * y + c * z) + 1.);
  }
  Dmap f = new_map(m, "v:f"), fm = new_map(moved, "v:f");
  Dmap p = new_map(m, "v:p"), pm = new_map(moved, "v:p");
  BOOST_REQUIRE_EQUAL(SMP::boundary_poisson_distance_map(m, mbp_test::longest_border(m), f), SMP::OK);
  BOOST_REQUIRE_EQUAL(SMP::boundary_poisson_distance_map(moved, mbp_test::longest_border(moved), fm), SMP::OK);
  const std::vector<vertex_descriptor> src = {vertex_descriptor(7)};
  BOOST_REQUIRE_EQUAL(SMP::poisson_distance_map(m, src, p), SMP::OK);
  BOOST_REQUIRE_EQUAL(SMP::poisson_distance_map(moved, src, pm), SMP::OK);
  for(vertex_descriptor v : vertices(m))
  {
    BOOST_TEST(std::abs(fm[v] - s * f[v]) <= 1e-9 * s * (1. + f[v]));
    BOOST_TEST(std::abs(pm[v] - s * p[v]) <= 1e-9 * s * (1. + p[v]));
  }
}

BOOST_AUTO_TEST_CASE(solver_is_a_template_parameter)
{
  typedef CGAL::Eigen_solver_traits<Eigen::SparseLU<CGAL::Eigen_sparse_matrix<double>::EigenType> > LU;
  Mesh m = mbp_test::make_mesh<Mesh>(mbp_test::bumpy_disk());
  Dmap a = new_map(m, "v:a"), b = new_map(m, "v:b");
  BOOST_REQUIRE_EQUAL(SMP::boundary_poisson_distance_map(m, mbp_test::longest_border(m), a), SMP::OK);
  BOOST_REQUIRE_EQUAL(SMP::boundary_poisson_distance_map(m, mbp_test::longest_border(m), b,
                        CGAL::parameters::sparse_linear_solver(LU())), SMP::OK);
  for(vertex_descriptor v : vertices(m))
    BOOST_TEST(std::abs(a[v] - b[v]) < 1e-10 * (1. + std::abs(a[v])));
  const std::vector<vertex_descriptor> src = {vertex_descriptor(0)};
  BOOST_REQUIRE_EQUAL(SMP::poisson_distance_map(m, src, a), SMP::OK);
  BOOST_REQUIRE_EQUAL(SMP::poisson_distance_map(m, src, b, 1., CGAL::parameters::sparse_linear_solver(LU())), SMP::OK);
  for(vertex_descriptor v : vertices(m))
    BOOST_TEST(std::abs(a[v] - b[v]) < 1e-10 * (1. + std::abs(a[v])));
}

BOOST_AUTO_TEST_CASE(custom_vertex_point_map)
{
  // The maps read positions through the vertex_point_map named parameter.
  Mesh m = mbp_test::make_mesh<Mesh>(mbp_test::bumpy_disk());
  auto doubled = m.add_property_map<vertex_descriptor, K::Point_3>("v:doubled").first;
  for(vertex_descriptor v : vertices(m))
    doubled[v] = K::Point_3(2 * m.point(v).x(), 2 * m.point(v).y(), 2 * m.point(v).z());
  Dmap a = new_map(m, "v:a"), b = new_map(m, "v:b");
  BOOST_REQUIRE_EQUAL(SMP::boundary_poisson_distance_map(m, mbp_test::longest_border(m), a), SMP::OK);
  BOOST_REQUIRE_EQUAL(SMP::boundary_poisson_distance_map(m, mbp_test::longest_border(m), b,
                        CGAL::parameters::vertex_point_map(doubled)), SMP::OK);
  for(vertex_descriptor v : vertices(m))
    BOOST_TEST(std::abs(b[v] - 2. * a[v]) < 1e-9 * (1. + a[v]));
}

// ------------------------------------------------------------------ disk and policies

BOOST_AUTO_TEST_CASE(disk_shares_one_factorization_of_the_interior_laplacian)
{
  Mesh m = mbp_test::make_mesh<Mesh>(mbp_test::bumpy_disk());
  Disk disk;
  BOOST_REQUIRE_EQUAL(disk.build_disk(m, mbp_test::longest_border(m), get(CGAL::vertex_point, m)), SMP::OK);
  BOOST_TEST(disk.border().size() == std::size_t(24));
  BOOST_TEST(disk.interior_vertices().size() + disk.border().size() == num_vertices(m));
  BOOST_TEST(disk.number_of_border_loops() == 1);
  // border loop order: source(h) for h around the border face
  std::vector<vertex_descriptor> expected;
  for(halfedge_descriptor h : halfedges_around_face(mbp_test::longest_border(m), m))
    expected.push_back(source(h, m));
  for(std::size_t k = 0; k < expected.size(); ++k)
    BOOST_TEST(disk.vertex(static_cast<std::size_t>(disk.border()[k])) == expected[k]);

  std::size_t c = 0;
  BOOST_REQUIRE_EQUAL(SMP::Poisson_center_locator().locate_center(disk, c), SMP::OK);
  BOOST_TEST(disk.statistics().factorizations == 1);
  BOOST_TEST(disk.statistics().back_substitutions == 1);
  std::vector<double> rhs(disk.interior_vertices().size(), 1.), x;
  BOOST_REQUIRE_EQUAL(disk.solve_interior(rhs, x), SMP::OK);
  BOOST_REQUIRE_EQUAL(disk.solve_interior(rhs, x), SMP::OK);
  BOOST_TEST(disk.statistics().factorizations == 1);       // reused
  BOOST_TEST(disk.statistics().back_substitutions == 3);

  std::vector<double> dist;
  BOOST_REQUIRE_EQUAL(SMP::Poisson_border_distance().compute_border_distances(disk, c, dist), SMP::OK);
  BOOST_TEST(disk.statistics().factorizations == 2);       // the spring Laplacian
  BOOST_TEST(dist.size() == disk.border().size());
  for(double d : dist)
    BOOST_TEST(d > 0.);
}

BOOST_AUTO_TEST_CASE(fixed_center_returns_the_user_vertex_and_rejects_border_vertices)
{
  Mesh m = mbp_test::make_mesh<Mesh>(mbp_test::bumpy_disk());
  Disk disk;
  BOOST_REQUIRE_EQUAL(disk.build_disk(m, mbp_test::longest_border(m), get(CGAL::vertex_point, m)), SMP::OK);
  std::size_t c = 0;
  BOOST_REQUIRE_EQUAL(SMP::Fixed_center<Mesh>(vertex_descriptor(5)).locate_center(disk, c), SMP::OK);
  BOOST_TEST(disk.vertex(c) == vertex_descriptor(5));
  const vertex_descriptor b = source(mbp_test::longest_border(m), m);
  BOOST_TEST(SMP::Fixed_center<Mesh>(b).locate_center(disk, c) == SMP::ERROR_WRONG_PARAMETER);
  BOOST_TEST(SMP::Fixed_center<Mesh>().locate_center(disk, c) == SMP::ERROR_WRONG_PARAMETER);
}

BOOST_AUTO_TEST_CASE(tied_maxima_resolve_to_the_vertex_nearest_their_mean)
{
  Mesh m = mbp_test::make_mesh<Mesh>(mbp_test::polar_disk(RINGS, SPOKES, 2., 1.));
  Disk disk;
  BOOST_REQUIRE_EQUAL(disk.build_disk(m, mbp_test::longest_border(m), get(CGAL::vertex_point, m)), SMP::OK);
  // two symmetric maxima on the long axis (as BGDM has on the paper's ellipse), equal up
  // to rounding: the center is the polar vertex between them
  std::vector<double> values(disk.number_of_vertices(), 0.);
  values[static_cast<std::size_t>(disk.index(vertex_at(m, 0.6, 0.)))] = 1.;
  values[static_cast<std::size_t>(disk.index(vertex_at(m, -0.6, 0.)))] = 1. - 1e-13;
  const int c = SMP::internal::argmax_with_tie_break(disk, values);
  BOOST_REQUIRE(c >= 0);
  BOOST_TEST(disk.vertex(static_cast<std::size_t>(c)) == vertex_descriptor(0));
  // a clear single maximum wins outright
  values[static_cast<std::size_t>(disk.index(vertex_at(m, -0.6, 0.)))] = 0.9;
  BOOST_TEST(disk.vertex(static_cast<std::size_t>(SMP::internal::argmax_with_tie_break(disk, values)))
             == vertex_at(m, 0.6, 0.));
}

// ------------------------------------------------------------------ quality measures

BOOST_AUTO_TEST_CASE(quality_of_an_isometry_and_of_a_similarity_is_optimal)
{
  Mesh m = mbp_test::make_mesh<Mesh>(mbp_test::polar_disk(6, 16, 1.5, 1.));  // flat, z = 0
  auto uv = m.add_property_map<vertex_descriptor, K::Point_2>("v:uv").first;
  for(vertex_descriptor v : vertices(m))  // rotated and scaled copy
    uv[v] = K::Point_2(0.3 * (0.6 * m.point(v).x() - 0.8 * m.point(v).y()) + 5.,
                       0.3 * (0.8 * m.point(v).x() + 0.6 * m.point(v).y()));
  const SMP::Parameterization_quality q = SMP::measure_quality(m, faces(m), uv);
  BOOST_TEST(q.angle_distortion < 1e-20);
  BOOST_TEST(q.angle_distortion_per_corner < 1e-20);
  BOOST_TEST(std::abs(q.quasi_conformal_mean - 1.) < 1e-9);
  BOOST_TEST(std::abs(q.quasi_conformal_max - 1.) < 1e-9);
  BOOST_TEST(std::abs(q.l2_stretch - 1.) < 1e-9);
  BOOST_TEST(std::abs(q.linf_stretch - 1.) < 1e-9);
  BOOST_TEST(q.area_distortion_max < 1e-9);
  BOOST_TEST(q.flipped_faces == 0u);
  BOOST_TEST(q.number_of_faces == num_faces(m));
  BOOST_TEST(q.number_of_vertices == num_vertices(m));
}

BOOST_AUTO_TEST_CASE(quality_of_an_affine_map_has_known_singular_values)
{
  // uv = diag(2, 0.5) x: s1 = 2, s2 = 0.5 on every face. QC = 4; UV->3D singular values are
  // 1/s2 = 2 and 1/s1 = 0.5, and the area is preserved, so L2 = sqrt((4 + 1/4) / 2),
  // Linf = 2, and there is no area distortion.
  Mesh m = mbp_test::make_mesh<Mesh>(mbp_test::polar_disk(6, 16));
  auto uv = m.add_property_map<vertex_descriptor, K::Point_2>("v:uv").first;
  for(vertex_descriptor v : vertices(m))
    uv[v] = K::Point_2(2. * m.point(v).x(), 0.5 * m.point(v).y());
  const SMP::Parameterization_quality q = SMP::measure_quality(m, faces(m), uv);
  BOOST_TEST(std::abs(q.quasi_conformal_mean - 4.) < 1e-9);
  BOOST_TEST(std::abs(q.quasi_conformal_max - 4.) < 1e-9);
  BOOST_TEST(std::abs(q.l2_stretch - std::sqrt(4.25 / 2.)) < 1e-9);
  BOOST_TEST(std::abs(q.linf_stretch - 2.) < 1e-9);
  BOOST_TEST(q.area_distortion_max < 1e-9);
  BOOST_TEST(q.angle_distortion > 0.01);
  // mirror image: every face flipped
  for(vertex_descriptor v : vertices(m))
    uv[v] = K::Point_2(-m.point(v).x(), m.point(v).y());
  BOOST_TEST(SMP::measure_quality(m, faces(m), uv).flipped_faces == num_faces(m));
}

BOOST_AUTO_TEST_CASE(error_messages_cover_every_code)
{
  for(int code = 0; code <= 15; ++code)
    BOOST_TEST(std::string(SMP::get_measured_error_message(code)) != "Unknown error");
  BOOST_TEST(std::string(SMP::get_measured_error_message(SMP::ERROR_BORDER_TOO_SHORT))
             == "This border parameterization requires a longer border");
  BOOST_TEST(std::string(SMP::get_measured_error_message(16)) == "Unknown error");
}

BOOST_AUTO_TEST_SUITE_END()
