// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// The linear systems of the disk against independent oracles (issue 15, from
// test_edges.cpp):
//  - the mean value system against CGAL's Mean_value_coordinates_parameterizer_3;
//  - the paper's Poisson distance map (Eq. 1, spring exponent r = 0, 1, 2, 1.5), from sources
//    and as the measured border's distance (the grounded spring system), and the mean edge
//    length g, against dense computations made here on an irregular mesh.

#include <boost/test/unit_test.hpp>

#include "test_support.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Surface_mesh_parameterization/Circular_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Mean_value_coordinates_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <CGAL/Surface_mesh_parameterization/Default_sparse_cholesky_traits.h>
#include <CGAL/Surface_mesh_parameterization/Fixed_center.h>
#include <CGAL/Surface_mesh_parameterization/main_border.h>
#include <CGAL/Surface_mesh_parameterization/Measured_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_report.h>
#include <CGAL/Surface_mesh_parameterization/poisson_distance_map.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/disk.h>

#include <Eigen/Dense>
#include <Eigen/SparseLU>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

BOOST_AUTO_TEST_SUITE(solvers)

namespace SMP = CGAL::Surface_mesh_parameterization;
typedef CGAL::Simple_cartesian<double>                          K;
typedef CGAL::Surface_mesh<K::Point_3>                          Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor            vertex_descriptor;
typedef boost::graph_traits<Mesh>::halfedge_descriptor          halfedge_descriptor;
typedef Mesh::Property_map<vertex_descriptor, K::Point_2>       UV_map;
typedef Mesh::Property_map<vertex_descriptor, double>           Distance_map;
typedef CGAL::Eigen_solver_traits<Eigen::SparseLU<CGAL::Eigen_sparse_matrix<double>::EigenType> > LU;
typedef SMP::internal::Disk<Mesh, SMP::Default_sparse_cholesky_traits> Disk;
typedef Mesh::Vertex_index                                      V;

using mbp_test::scaling;
using mbp_test::Transform;

namespace {

// An irregular curved disk: the polar grid of the unit disk with every vertex moved at
// random (interior ones by up to a quarter of the ring spacing, border ones along and across
// the border), lifted onto a bump. Edge lengths vary by a factor of about 4, so that the
// spring exponent r of the Poisson distance map matters.
mbp_test::Soup irregular_disk(int rings = 6, int spokes = 20)
{
  mbp_test::Soup s = mbp_test::polar_disk(rings, spokes);
  mbp_test::Lcg rnd(12345);
  const double h = 1. / rings, step = 2. * CGAL_PI / spokes;
  for(auto& p : s.points)
  {
    const double r = std::hypot(p[0], p[1]);
    if(r > 1. - 1e-9)
    {
      const double angle = std::atan2(p[1], p[0]) + 0.3 * step * (2. * rnd() - 1.);
      const double radius = 1. + 0.05 * (2. * rnd() - 1.);
      p[0] = radius * std::cos(angle);
      p[1] = radius * std::sin(angle);
    }
    else if(r > 0.)
    {
      p[0] += 0.25 * h * (2. * rnd() - 1.);
      p[1] += 0.25 * h * (2. * rnd() - 1.);
    }
    p[2] = 0.4 * p[0] * p[0] - 0.25 * p[1] + 0.3 * p[0] * p[1];
  }
  return s;
}

// ---------------------------------------------------------------- dense oracles

// Paper Eq. 1 with spring weights, computed here with dense matrices:
//   sum_j w_ij (f_i - f_j) = d_i g_i off the sources, f = 0 at the sources,
// w_ij = |x_i - x_j|^-r for every edge (once: CGAL's edges()), d_i = sum_j w_ij, g_i the mean
// length of the edges at i.
std::vector<double> dense_poisson_distances(const Mesh& m, const std::vector<vertex_descriptor>& sources, double r)
{
  const Eigen::Index n = Eigen::Index(num_vertices(m));
  Eigen::MatrixXd L = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd g = Eigen::VectorXd::Zero(n), count = Eigen::VectorXd::Zero(n);
  for(auto e : edges(m))
  {
    const Eigen::Index a = Eigen::Index(source(e, m)), b = Eigen::Index(target(e, m));
    const double l = std::sqrt(CGAL::squared_distance(m.point(source(e, m)), m.point(target(e, m))));
    const double w = std::pow(l, -r);
    L(a, b) -= w;
    L(b, a) -= w;
    L(a, a) += w;
    L(b, b) += w;
    g[a] += l;
    g[b] += l;
    count[a] += 1.;
    count[b] += 1.;
  }
  Eigen::VectorXd rhs(n);
  for(Eigen::Index i = 0; i < n; ++i)
    rhs[i] = L(i, i) * g[i] / count[i];
  for(vertex_descriptor s : sources)
  {
    const Eigen::Index i = Eigen::Index(s);
    L.row(i).setZero();
    L(i, i) = 1.;
    rhs[i] = 0.;
  }
  const Eigen::VectorXd f = L.partialPivLu().solve(rhs);
  return std::vector<double>(f.data(), f.data() + n);
}

// the mean length of the edges at `v` (each edge once, border edges included)
double mean_edge_length(const Mesh& m, vertex_descriptor v)
{
  double sum = 0.;
  int count = 0;
  for(halfedge_descriptor h : CGAL::halfedges_around_target(halfedge(v, m), m))
  {
    sum += std::sqrt(CGAL::squared_distance(m.point(source(h, m)), m.point(target(h, m))));
    ++count;
  }
  return sum / count;
}

} // namespace

// ================================================================ the mean value system

BOOST_AUTO_TEST_CASE(mean_value_system_equals_cgal_mean_value_coordinates)
{
  for(const auto& named : {std::make_pair(std::string("curved disk"), mbp_test::bumpy_disk(8, 24)),
                           std::make_pair(std::string("disk with two holes"), mbp_test::disk_with_two_holes())})
    BOOST_TEST_CONTEXT(named.first)
    {
      Mesh m = mbp_test::make_mesh<Mesh>(named.second);
      const halfedge_descriptor bhd = SMP::main_border(m).first;
      Disk patch;
      BOOST_REQUIRE_EQUAL(patch.build_disk(m, bhd, get(CGAL::vertex_point, m)), SMP::OK);

      // CGAL treats a hole's vertices as interior vertices whose ring has a gap (its mean
      // value weights span the gap), the disk fills each hole with a virtual vertex. For
      // CGAL, the holes are filled here with a real vertex where build_disk() documents the
      // virtual one: the loop's centroid lifted by a fifth of its mean radius along its normal.
      Mesh filled = m;
      std::vector<K::Point_3> fillings;
      for(const auto& loop : mbp_test::border_loops(m))
      {
        if(mbp_test::sorted_loop(m, loop.first) == mbp_test::sorted_loop(m, bhd))
          continue;
        std::vector<halfedge_descriptor> hole;
        for(halfedge_descriptor b : CGAL::halfedges_around_face(loop.first, m))
          hole.push_back(b);
        Eigen::Vector3d centroid = Eigen::Vector3d::Zero(), normal = Eigen::Vector3d::Zero();
        auto at = [&m](vertex_descriptor v) { return Eigen::Vector3d(m.point(v).x(), m.point(v).y(), m.point(v).z()); };
        for(halfedge_descriptor b : hole)
          centroid += at(source(b, m));
        centroid /= double(hole.size());
        double radius = 0.;
        for(halfedge_descriptor b : hole)
        {
          normal += (at(source(b, m)) - centroid).cross(at(target(b, m)) - centroid);
          radius += (at(source(b, m)) - centroid).norm();
        }
        radius /= double(hole.size());
        const Eigen::Vector3d c = centroid + 0.2 * radius * normal.normalized();
        fillings.emplace_back(c.x(), c.y(), c.z());
        const V added = filled.add_vertex(fillings.back());
        for(halfedge_descriptor b : hole)
          BOOST_REQUIRE(filled.add_face(source(b, m), target(b, m), added) != Mesh::null_face());
      }
      BOOST_TEST(fillings.size() == patch.hole_loops().size());
      BOOST_TEST(patch.number_of_vertices() == num_vertices(filled));
      // the disk's virtual vertices are where the documentation says
      for(std::size_t i = patch.number_of_real_vertices(); i < patch.number_of_vertices(); ++i)
      {
        const Eigen::Vector3d p = patch.point(i) * patch.length_unit();
        double nearest = std::numeric_limits<double>::infinity();
        for(const K::Point_3& q : fillings)
          nearest = (std::min)(nearest, (p - Eigen::Vector3d(q.x(), q.y(), q.z())).norm());
        BOOST_TEST(nearest <= 1e-12);
      }

      // CGAL: arc-length circle, mean value coordinates, a direct solver
      UV_map cgal_uv = mbp_test::new_uv_map(filled, "v:cgal");
      SMP::Mean_value_coordinates_parameterizer_3<Mesh, SMP::Circular_border_arc_length_parameterizer_3<Mesh>, LU> mvc;
      BOOST_REQUIRE_EQUAL(CGAL::Surface_mesh_parameterization::parameterize(filled, mvc, bhd, cgal_uv), SMP::OK);

      // the disk's mean value system with CGAL's border values
      Disk::Engine* system = patch.systems().mean_value();
      BOOST_REQUIRE(system != nullptr);
      const std::vector<int>& border = patch.border();
      Eigen::MatrixXd values(Eigen::Index(border.size()), 2), rhs, x;
      for(std::size_t k = 0; k < border.size(); ++k)
      {
        const K::Point_2 q = cgal_uv[patch.vertex(std::size_t(border[k]))];
        values(Eigen::Index(k), 0) = q.x();
        values(Eigen::Index(k), 1) = q.y();
      }
      system->rhs_from_fixed(values, rhs);
      BOOST_REQUIRE(system->solve(rhs, x) == SMP::OK);
      const std::vector<int>& interior = patch.interior_vertices();
      double worst = 0.;
      std::size_t compared = 0;
      for(std::size_t r = 0; r < interior.size(); ++r)
      {
        const std::size_t i = std::size_t(interior[r]);
        if(patch.is_virtual(i))
          continue;
        const K::Point_2 q = cgal_uv[patch.vertex(i)];
        worst = (std::max)(worst, std::hypot(x(Eigen::Index(r), 0) - q.x(), x(Eigen::Index(r), 1) - q.y()));
        ++compared;
      }
      BOOST_TEST(compared == patch.number_of_real_vertices() - border.size());
      BOOST_TEST_MESSAGE(named.first << ": mean value system against CGAL's MVC " << worst);
      BOOST_TEST(worst <= 1e-9);
    }
}

// ================================================================ the Poisson distance map, g

BOOST_AUTO_TEST_CASE(poisson_distance_maps_solve_equation_1_with_the_spring_exponent)
{
  Mesh m = mbp_test::make_mesh<Mesh>(irregular_disk());
  const halfedge_descriptor bhd = SMP::main_border(m).first;
  // the mesh is irregular: edge lengths vary by a factor of more than 3
  double shortest = std::numeric_limits<double>::infinity(), longest = 0.;
  for(auto e : edges(m))
  {
    const double l = std::sqrt(CGAL::squared_distance(m.point(source(e, m)), m.point(target(e, m))));
    shortest = (std::min)(shortest, l);
    longest = (std::max)(longest, l);
  }
  BOOST_TEST(longest > 3. * shortest);

  const vertex_descriptor center(0), other(Mesh::size_type(num_vertices(m) / 2));
  BOOST_REQUIRE(!is_border(center, m));
  std::vector<double> previous;
  for(double r : {0., 1., 2., 1.5})
    BOOST_TEST_CONTEXT("spring exponent " << r)
    {
      // the multi-source map (poisson_distance_map)
      for(const std::vector<vertex_descriptor>& sources : {std::vector<vertex_descriptor>{center},
                                                           std::vector<vertex_descriptor>{center, other}})
      {
        const std::vector<double> oracle = dense_poisson_distances(m, sources, r);
        Distance_map f = mbp_test::new_distance_map(m, "v:f");
        BOOST_REQUIRE_EQUAL(SMP::poisson_distance_map(m, sources, f, r), SMP::OK);
        double worst = 0., largest = 0.;
        for(vertex_descriptor v : vertices(m))
        {
          worst = (std::max)(worst, std::abs(f[v] - oracle[std::size_t(v)]));
          largest = (std::max)(largest, oracle[std::size_t(v)]);
        }
        BOOST_TEST(worst <= 1e-10 * largest, sources.size() << " source(s): relative difference " << worst / largest);
        m.remove_property_map(f);
      }

      // the border distance of the paper (Poisson_border_distance: the grounded spring
      // Laplacian and one back-substitution), through the border parameterizer's report
      const std::vector<double> oracle = dense_poisson_distances(m, {center}, r);
      typedef SMP::Measured_border<SMP::Fixed_center<Mesh>, SMP::Poisson_border_distance> Policy;
      SMP::Border_parameterizer_3<Mesh, Policy> border{Policy(SMP::Fixed_center<Mesh>(center),
                                                              SMP::Poisson_border_distance(r))};
      UV_map uv = mbp_test::new_uv_map(m, "v:uv");
      auto done = m.add_property_map<vertex_descriptor, bool>("v:done", false).first;
      auto index = m.add_property_map<vertex_descriptor, int>("v:index", 0).first;
      SMP::Parameterization_report report;
      BOOST_REQUIRE_EQUAL(border.parameterize(m, bhd, uv, index, done, &report), SMP::OK);
      const std::vector<vertex_descriptor> border_vertices = mbp_test::border_loop_vertices(m, bhd);
      BOOST_REQUIRE_EQUAL(report.border_distances.size(), border_vertices.size());
      double worst = 0., largest = 0.;
      std::vector<double> at_border;
      for(std::size_t k = 0; k < border_vertices.size(); ++k)
      {
        const double expected = oracle[std::size_t(border_vertices[k])];
        worst = (std::max)(worst, std::abs(report.border_distances[k] - expected));
        largest = (std::max)(largest, expected);
        at_border.push_back(expected);
      }
      BOOST_TEST(worst <= 1e-10 * largest, "border distances: relative difference " << worst / largest);
      // the exponent is visible on this mesh: the normalized border distances change with r
      if(!previous.empty())
      {
        double change = 0.;
        const double sa = std::accumulate(at_border.begin(), at_border.end(), 0.);
        const double sb = std::accumulate(previous.begin(), previous.end(), 0.);
        for(std::size_t k = 0; k < at_border.size(); ++k)
          change = (std::max)(change, std::abs(at_border[k] / sa - previous[k] / sb) * double(at_border.size()));
        BOOST_TEST(change > 1e-3, "largest relative change of the normalized distances " << change);
      }
      previous = at_border;
      m.remove_property_map(uv);
      m.remove_property_map(done);
      m.remove_property_map(index);
    }
}

BOOST_AUTO_TEST_CASE(mean_edge_length_g_counts_every_edge_once_on_border_vertices_too)
{
  for(const auto& named : {std::make_pair(std::string("irregular disk"), irregular_disk()),
                           std::make_pair(std::string("planar grid"), mbp_test::square_grid(6))})
    BOOST_TEST_CONTEXT(named.first)
    {
      Mesh m = mbp_test::make_mesh<Mesh>(named.second, scaling(1e-3));
      Disk patch;
      BOOST_REQUIRE_EQUAL(patch.build_disk(m, SMP::main_border(m).first, get(CGAL::vertex_point, m)), SMP::OK);
      const std::vector<double>& g = patch.mean_spoke_lengths();
      std::size_t border = 0;
      double worst = 0.;
      for(std::size_t i = 0; i < patch.number_of_real_vertices(); ++i)
      {
        const vertex_descriptor v = patch.vertex(i);
        const double expected = mean_edge_length(m, v);
        worst = (std::max)(worst, std::abs(g[i] * patch.length_unit() - expected) / expected);
        border += is_border(v, m) ? 1 : 0;
      }
      BOOST_TEST(border > 0u);
      BOOST_TEST(worst <= 1e-14);
    }
}

BOOST_AUTO_TEST_SUITE_END()
