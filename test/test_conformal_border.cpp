// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// The conformal border (Conformal_border_parameterizer_3, and Conformal_parameterizer_3 with
// Conformal_border / Automatic_border), against independent computations:
// planar non-star-shaped disks reproduced exactly, a developable patch unrolled exactly, the
// turning angles recomputed from a dense cotangent Laplacian assembled here, the closing
// step against a dense solution of its least-squares problem, the sign of the correction,
// the blend of a self-overlapping border, and CGAL's DCP with the drop-in border; the
// conformal-length member (Conformal_length_border, issue 23): its scale factors against a dense
// solve, the conformal border at blend 0, the circle's turning angles and a near-conformal
// layout at blend 1.

#include <boost/test/unit_test.hpp>

#include "test_support.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Seam_mesh.h>

#include <CGAL/Surface_mesh_parameterization/Barycentric_mapping_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Circular_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_authalic_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_conformal_map_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Mean_value_coordinates_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <CGAL/Surface_mesh_parameterization/Conformal_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Conformal_length_border.h>
#include <CGAL/Surface_mesh_parameterization/Conformal_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Geodesic_border_distance.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_report.h>
#include <CGAL/Surface_mesh_parameterization/Default_sparse_cholesky_traits.h>
#include <CGAL/Surface_mesh_parameterization/internal/borders/border_members.h>
#include <CGAL/Surface_mesh_parameterization/internal/borders/conformal_border.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/disk.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/validity.h>
#include <CGAL/Surface_mesh_parameterization/measure_quality.h>

#include <Eigen/Dense>
#include <Eigen/SparseLU>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <limits>
#include <string>
#include <vector>

BOOST_AUTO_TEST_SUITE(conformal_border)

namespace SMP = CGAL::Surface_mesh_parameterization;
typedef CGAL::Simple_cartesian<double>                          K;
typedef CGAL::Exact_predicates_inexact_constructions_kernel     EPICK;
typedef CGAL::Surface_mesh<K::Point_3>                          Mesh;
typedef CGAL::Polyhedron_3<EPICK>                               Poly;
typedef boost::graph_traits<Mesh>::vertex_descriptor            vertex_descriptor;
typedef boost::graph_traits<Mesh>::halfedge_descriptor          halfedge_descriptor;
typedef Mesh::Property_map<vertex_descriptor, K::Point_2>       UV_map;
typedef CGAL::Eigen_solver_traits<Eigen::SparseLU<CGAL::Eigen_sparse_matrix<double>::EigenType> > LU;
typedef SMP::Conformal_border_parameterizer_3<Mesh>             Border;
typedef mbp_test::Reporting_border<Border>                      Reporting_border;
typedef SMP::Parameterization_report                            Report;
typedef SMP::internal::Disk<Mesh, SMP::Default_sparse_cholesky_traits> Disk;
typedef SMP::internal::Conformal_border_data                    Conformal_data;

namespace {

// The faces of a soup made counterclockwise in the xy-plane (for planar soups).
void orient_ccw(mbp_test::Soup& s)
{
  for(auto& f : s.faces)
  {
    const auto &a = s.points[f[0]], &b = s.points[f[1]], &c = s.points[f[2]];
    if((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) < 0.)
      std::swap(f[1], f[2]);
  }
}

// A grid of `cols` x `rows` quads over (s, w) in [0,1]^2, each split in two, mapped by `at`.
template <class Map>
mbp_test::Soup grid(int cols, int rows, const Map& at)
{
  mbp_test::Soup s;
  for(int i = 0; i <= cols; ++i)
    for(int j = 0; j <= rows; ++j)
      s.points.push_back(at(double(i) / cols, double(j) / rows));
  auto id = [rows](int i, int j) { return std::size_t(i * (rows + 1) + j); };
  for(int i = 0; i < cols; ++i)
    for(int j = 0; j < rows; ++j)
    {
      s.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      s.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return s;
}

// A flat spiral strip (one and a half turns): a planar disk that is not star-shaped.
mbp_test::Soup planar_spiral()
{
  mbp_test::Soup s = grid(90, 4, [](double a, double b) {
    const double theta = 3. * CGAL_PI * a, rho = 1. + 0.35 * theta + 0.3 * (b - 0.5);
    return std::array<double, 3>{{rho * std::cos(theta), rho * std::sin(theta), 0.}};
  });
  orient_ccw(s);
  return s;
}

// The flat C-shape rolled onto a prism (a polyhedral cylinder whose edges are the grid's
// vertical lines): every triangle stays in one flat strip, so the surface is isometric to
// the C-shape. `planar` receives the C-shape's own coordinates.
mbp_test::Soup rolled_c_shape(std::vector<std::array<double, 2> >& planar)
{
  const int n = 6;
  mbp_test::Soup s = mbp_test::c_shape(n);
  orient_ccw(s);
  const double alpha = 1.5 * CGAL_PI / (3 * n);         // turn per column: 3/4 of a turn in all
  const double R = (1. / n) / (2. * std::sin(0.5 * alpha));  // chord of one column = 1/n
  planar.clear();
  for(auto& p : s.points)
  {
    planar.push_back({{p[0], p[1]}});
    const double theta = std::round(p[0] * n) * alpha;
    p = {{R * std::sin(theta), p[1], R * (1. - std::cos(theta))}};
  }
  return s;
}

// An annular ramp turning 1.6 times around: flat to first order, its conformal border
// overlaps itself.
mbp_test::Soup spiral_ramp()
{
  mbp_test::Soup s = grid(120, 5, [](double a, double b) {
    const double theta = 3.2 * CGAL_PI * a, r = 1. + b;
    return std::array<double, 3>{{r * std::cos(theta), r * std::sin(theta), 0.08 * theta}};
  });
  orient_ccw(s);
  return s;
}

// max over vertices of |uv - (a x + b)| / diameter(x) for the best similarity (a, b complex).
double similarity_error(const Mesh& m, UV_map uv, const std::vector<std::array<double, 2> >& x)
{
  std::vector<std::complex<double> > X, U;
  for(vertex_descriptor v : vertices(m))
  {
    X.emplace_back(x[std::size_t(v)][0], x[std::size_t(v)][1]);
    U.emplace_back(uv[v].x(), uv[v].y());
  }
  std::complex<double> cx(0.), cu(0.);
  for(std::size_t i = 0; i < X.size(); ++i)
  {
    cx += X[i];
    cu += U[i];
  }
  cx /= double(X.size());
  cu /= double(U.size());
  std::complex<double> num(0.);
  double den = 0., diameter = 0.;
  for(std::size_t i = 0; i < X.size(); ++i)
  {
    num += std::conj(X[i] - cx) * (U[i] - cu);
    den += std::norm(X[i] - cx);
  }
  const std::complex<double> a = num / den;
  double error = 0.;
  for(std::size_t i = 0; i < X.size(); ++i)
  {
    error = (std::max)(error, std::abs(a * (X[i] - cx) + cu - U[i]));
    diameter = (std::max)(diameter, std::abs(U[i] - cu));
  }
  return error / (2. * diameter);
}

std::vector<std::array<double, 2> > xy(const mbp_test::Soup& s)
{
  std::vector<std::array<double, 2> > x;
  for(const auto& p : s.points)
    x.push_back({{p[0], p[1]}});
  return x;
}

double angle_distortion(const Mesh& m, UV_map uv)
{
  return SMP::measure_quality(m, faces(m), uv).angle_distortion;
}

// The complete parameterizer with the border policy `BorderPolicy`; its UVs in `uv`, the
// report of the call in `*report` when given.
template <class BorderPolicy>
SMP::Error_code flatten(Mesh& m, UV_map uv, Report* report = nullptr)
{
  const SMP::Conformal_parameterizer_3<Mesh, BorderPolicy> p;
  return SMP::parameterize(m, p, mbp_test::longest_border(m), uv, report);
}

// A report's border polygon as Eigen vectors (what the internal polygon functions take).
std::vector<Eigen::Vector2d> eigen_polygon(const std::vector<std::array<double, 2> >& uv)
{
  std::vector<Eigen::Vector2d> p;
  for(const auto& q : uv)
    p.emplace_back(q[0], q[1]);
  return p;
}

// The dense cotangent Laplacian L = D - W of the mesh (w_ij = (cot a + cot b) / 2, the
// corners opposite edge ij) and the angle sums of the vertices, computed here.
void dense_laplacian(const Mesh& m, Eigen::MatrixXd& L, std::vector<double>& sums)
{
  const std::size_t n = num_vertices(m);
  L = Eigen::MatrixXd::Zero(Eigen::Index(n), Eigen::Index(n));
  sums.assign(n, 0.);
  for(auto f : faces(m))
  {
    std::vector<vertex_descriptor> t;
    for(auto h : halfedges_around_face(halfedge(f, m), m))
      t.push_back(target(h, m));
    for(int k = 0; k < 3; ++k)
    {
      const K::Point_3 &p = m.point(t[k]), &a = m.point(t[(k + 1) % 3]), &b = m.point(t[(k + 2) % 3]);
      const K::Vector_3 u = a - p, v = b - p;
      const double angle = std::atan2(std::sqrt(CGAL::cross_product(u, v).squared_length()), u * v);
      sums[std::size_t(t[k])] += angle;
      const double w = 0.5 / std::tan(angle);  // cotangent weight of the opposite edge
      const Eigen::Index i = Eigen::Index(t[(k + 1) % 3]), j = Eigen::Index(t[(k + 2) % 3]);
      L(i, j) -= w;
      L(j, i) -= w;
      L(i, i) += w;
      L(j, j) += w;
    }
  }
}

// The turning angles k - L_BI L_II^-1 Omega computed here from a dense cotangent Laplacian.
std::vector<double> dense_turning_angles(const Mesh& m, halfedge_descriptor bhd)
{
  const std::size_t n = num_vertices(m);
  Eigen::MatrixXd L;
  std::vector<double> sums;
  dense_laplacian(m, L, sums);
  std::vector<vertex_descriptor> border;
  std::vector<bool> on_border(n, false);
  for(auto h : halfedges_around_face(bhd, m))
  {
    border.push_back(source(h, m));
    on_border[std::size_t(source(h, m))] = true;
  }
  std::vector<Eigen::Index> inner;
  for(std::size_t i = 0; i < n; ++i)
    if(!on_border[i])
      inner.push_back(Eigen::Index(i));
  Eigen::MatrixXd LII(inner.size(), inner.size());
  Eigen::VectorXd omega(inner.size());
  for(std::size_t a = 0; a < inner.size(); ++a)
  {
    omega[Eigen::Index(a)] = 2. * CGAL_PI - sums[std::size_t(inner[a])];
    for(std::size_t b = 0; b < inner.size(); ++b)
      LII(Eigen::Index(a), Eigen::Index(b)) = L(inner[a], inner[b]);
  }
  const Eigen::VectorXd u = LII.ldlt().solve(omega);
  std::vector<double> turning;
  for(vertex_descriptor b : border)
  {
    double h = 0.;
    for(std::size_t a = 0; a < inner.size(); ++a)
      h += L(Eigen::Index(b), inner[a]) * u[Eigen::Index(a)];
    turning.push_back(CGAL_PI - sums[std::size_t(b)] - h);
  }
  return turning;
}

// The conformal-length member's data on a disk mesh, built on its longest border: the conformal
// border's data and the scale factors u_B.
struct Length_member
{
  Mesh m;
  Disk disk;
  Conformal_data data;
  std::vector<double> scale;

  explicit Length_member(const mbp_test::Soup& soup) : m(mbp_test::make_mesh<Mesh>(soup))
  {
    BOOST_REQUIRE_EQUAL(disk.build_disk(m, mbp_test::longest_border(m), get(CGAL::vertex_point, m)), SMP::OK);
    BOOST_REQUIRE_EQUAL(SMP::internal::conformal_border_data(disk, data), SMP::OK);
    BOOST_REQUIRE_EQUAL(SMP::internal::conformal_length_data(disk, data, scale), SMP::OK);
    BOOST_REQUIRE_EQUAL(scale.size(), disk.border().size());
  }
};

double largest_distance(const std::vector<Eigen::Vector2d>& a, const std::vector<Eigen::Vector2d>& b)
{
  double d = (a.size() == b.size()) ? 0. : std::numeric_limits<double>::infinity();
  for(std::size_t k = 0; k < a.size() && k < b.size(); ++k)
    d = (std::max)(d, (a[k] - b[k]).norm());
  return d;
}

// A border parameterizer that places given UVs (a test double for CGAL's DCP).
struct Given_border
{
  std::vector<vertex_descriptor> vertices;
  std::vector<Eigen::Vector2d> uv;
  template <class UVmap, class Vimap, class Vpmap>
  SMP::Error_code parameterize(const Mesh&, halfedge_descriptor, UVmap uvmap, Vimap, Vpmap vpmap)
  {
    for(std::size_t k = 0; k < vertices.size(); ++k)
    {
      put(uvmap, vertices[k], K::Point_2(uv[k].x(), uv[k].y()));
      put(vpmap, vertices[k], true);
    }
    return SMP::OK;
  }
  bool is_border_convex() const { return false; }
};

// The angle distortion of CGAL's DCP (sparse LU) with the border polygon `polygon` (in the
// disk's border order); `flips` gets its flipped faces, `one_to_one` whether it is one-to-one.
double dcp_with_border(Mesh& m, const Disk& disk, const std::vector<Eigen::Vector2d>& polygon, const std::string& name,
                       std::size_t& flips, bool& one_to_one)
{
  Given_border given;
  for(int b : disk.border())
    given.vertices.push_back(disk.vertex(std::size_t(b)));
  given.uv = polygon;
  UV_map uv = mbp_test::new_uv_map(m, name);
  SMP::Discrete_conformal_map_parameterizer_3<Mesh, Given_border, LU> dcp(given);
  BOOST_REQUIRE_EQUAL(SMP::parameterize(m, dcp, mbp_test::longest_border(m), uv), SMP::OK);
  const SMP::Parameterization_quality q = SMP::measure_quality(m, faces(m), uv);
  flips = q.flipped_faces;
  one_to_one = SMP::is_one_to_one_uv_map(m, faces(m), uv);
  return q.angle_distortion;
}

} // namespace

BOOST_AUTO_TEST_CASE(planar_non_star_shaped_disks_are_reproduced_exactly)
{
  for(const auto& named : {std::make_pair(std::string("spiral"), planar_spiral()),
                           std::make_pair(std::string("C-shape"), mbp_test::c_shape(6))})
  {
    mbp_test::Soup soup = named.second;
    orient_ccw(soup);
    Mesh m = mbp_test::make_mesh<Mesh>(soup);
    UV_map conformal = mbp_test::new_uv_map(m, "v:conformal"), circle = mbp_test::new_uv_map(m, "v:circle"), measured = mbp_test::new_uv_map(m, "v:measured");
    BOOST_REQUIRE_EQUAL(flatten<SMP::Conformal_border>(m, conformal), SMP::OK);
    const double e = similarity_error(m, conformal, xy(soup));
    BOOST_TEST_MESSAGE(named.first << ": conformal border, distance to the input after alignment " << e);
    BOOST_TEST_CONTEXT(named.first) { BOOST_TEST(e <= 1e-8); }
    // the drop-in border alone: the border polygon is the input's, and it is not convex
    Border border;
    UV_map b = mbp_test::new_uv_map(m, "v:border");
    auto vpm = m.add_property_map<vertex_descriptor, bool>("v:done", false).first;
    auto vim = m.add_property_map<vertex_descriptor, int>("v:index", 0).first;
    Report r;
    BOOST_REQUIRE_EQUAL(border.parameterize(m, mbp_test::longest_border(m), b, vim, vpm, &r), SMP::OK);
    BOOST_TEST(r.conformal_blend == 0.);
    BOOST_TEST(!border.is_border_convex());
    // the circle and the measured border cannot reproduce it
    flatten<SMP::Circular_border>(m, circle);
    flatten<SMP::Measured_border<> >(m, measured);
    BOOST_TEST(similarity_error(m, circle, xy(soup)) > 1e-3);
    BOOST_TEST(similarity_error(m, measured, xy(soup)) > 1e-3);
  }
}

BOOST_AUTO_TEST_CASE(a_developable_patch_is_unrolled_exactly)
{
  std::vector<std::array<double, 2> > planar;
  Mesh m = mbp_test::make_mesh<Mesh>(rolled_c_shape(planar));
  double height = 0.;  // the patch is really bent
  for(vertex_descriptor v : vertices(m))
    height = (std::max)(height, m.point(v).z());
  BOOST_TEST(height > 0.5);
  UV_map uv = mbp_test::new_uv_map(m, "v:uv"), circle = mbp_test::new_uv_map(m, "v:circle");
  BOOST_REQUIRE_EQUAL(flatten<SMP::Conformal_border>(m, uv), SMP::OK);
  const double e = similarity_error(m, uv, planar);
  BOOST_TEST_MESSAGE("rolled C-shape: distance to the unrolled shape " << e);
  BOOST_TEST(e <= 1e-8);
  BOOST_TEST(angle_distortion(m, uv) <= 1e-12);
  flatten<SMP::Circular_border>(m, circle);
  BOOST_TEST(similarity_error(m, circle, planar) > 1e-3);
}

BOOST_AUTO_TEST_CASE(turning_angles_closing_and_lengths_against_dense_computations)
{
  Mesh m = mbp_test::make_mesh<Mesh>(mbp_test::bumpy_disk(6, 20));
  const halfedge_descriptor bhd = mbp_test::longest_border(m);
  Border border;
  UV_map uv = mbp_test::new_uv_map(m, "v:uv");
  auto vpm = m.add_property_map<vertex_descriptor, bool>("v:done", false).first;
  auto vim = m.add_property_map<vertex_descriptor, int>("v:index", 0).first;
  Report r;
  BOOST_REQUIRE_EQUAL(border.parameterize(m, bhd, uv, vim, vpm, &r), SMP::OK);
  const std::vector<vertex_descriptor> loop = mbp_test::border_loop_vertices(m, bhd);
  const std::size_t mb = loop.size();
  BOOST_REQUIRE_EQUAL(r.turning_angles.size(), mb);
  BOOST_REQUIRE_EQUAL(r.corrections.size(), mb);
  BOOST_REQUIRE_EQUAL(r.edge_lengths.size(), mb);
  BOOST_REQUIRE_EQUAL(r.closed_lengths.size(), mb);
  BOOST_REQUIRE_EQUAL(r.border_uv.size(), mb);

  // the turning angles: a dense cotangent Laplacian and a dense solve, assembled here
  const std::vector<double> dense = dense_turning_angles(m, bhd);
  double sum = 0., worst = 0., correction = 0.;
  for(std::size_t k = 0; k < mb; ++k)
  {
    sum += r.turning_angles[k];
    worst = (std::max)(worst, std::abs(r.turning_angles[k] - dense[k]));
    correction = (std::max)(correction, std::abs(r.corrections[k]));
  }
  BOOST_TEST(std::abs(sum - 2. * CGAL_PI) <= 1e-10);  // discrete Gauss-Bonnet
  BOOST_TEST(worst <= 1e-10);
  BOOST_TEST(correction > 1e-3);  // a curved disk: the correction matters

  // closing: the dense least-squares problem min sum (l* - l)^2 / l subject to T l* = 0
  std::vector<double> phi(mb, 0.);
  for(std::size_t k = 1; k < mb; ++k)
    phi[k] = phi[k - 1] - r.turning_angles[k];
  const Eigen::Index n = Eigen::Index(mb);
  Eigen::MatrixXd kkt = Eigen::MatrixXd::Zero(n + 2, n + 2);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n + 2);
  for(Eigen::Index k = 0; k < n; ++k)
  {
    const double l = r.edge_lengths[std::size_t(k)];
    kkt(k, k) = 1. / l;
    rhs[k] = 1.;  // (1/l) * l
    kkt(k, n) = kkt(n, k) = std::cos(phi[std::size_t(k)]);
    kkt(k, n + 1) = kkt(n + 1, k) = std::sin(phi[std::size_t(k)]);
  }
  const Eigen::VectorXd solution = kkt.fullPivLu().solve(rhs);
  double length_error = 0., total = 0.;
  Eigen::Vector2d gap(0., 0.);
  for(std::size_t k = 0; k < mb; ++k)
  {
    length_error = (std::max)(length_error, std::abs(r.closed_lengths[k] - solution[Eigen::Index(k)]));
    total += r.edge_lengths[k];
    gap += r.closed_lengths[k] * Eigen::Vector2d(std::cos(phi[k]), std::sin(phi[k]));
  }
  BOOST_TEST(length_error <= 1e-12 * total);
  BOOST_TEST(gap.norm() <= 1e-12 * total);

  // the polygon written in the map has those edges, up to one scale and one rotation
  const std::vector<Eigen::Vector2d> polygon = eigen_polygon(r.border_uv);
  const double scale = (polygon[1] - polygon[0]).norm() / r.closed_lengths[0];
  for(std::size_t k = 0; k < mb; ++k)
  {
    const Eigen::Vector2d e = polygon[(k + 1) % mb] - polygon[k];
    BOOST_TEST(std::abs(e.norm() - scale * r.closed_lengths[k]) <= 1e-12);
    const Eigen::Vector2d p(uv[loop[k]].x(), uv[loop[k]].y());
    BOOST_TEST((p - polygon[k]).norm() == 0.);
  }
}

BOOST_AUTO_TEST_CASE(the_sign_of_the_correction)
{
  // A curved, asymmetric disk: the opposite sign k + h gives turning angles that do not sum
  // to 2 pi and a layout (CGAL's DCP with that border) with far more angle distortion.
  Mesh m = mbp_test::make_mesh<Mesh>(mbp_test::bumpy_disk(8, 24));
  const halfedge_descriptor bhd = mbp_test::longest_border(m);
  UV_map ours = mbp_test::new_uv_map(m, "v:ours"), wrong = mbp_test::new_uv_map(m, "v:wrong");
  const SMP::Conformal_parameterizer_3<Mesh, SMP::Conformal_border> full;
  BOOST_REQUIRE_EQUAL(SMP::parameterize(m, full, bhd, ours), SMP::OK);

  Border border;
  UV_map b = mbp_test::new_uv_map(m, "v:b");
  auto vpm = m.add_property_map<vertex_descriptor, bool>("v:done", false).first;
  auto vim = m.add_property_map<vertex_descriptor, int>("v:index", 0).first;
  Report r;
  BOOST_REQUIRE_EQUAL(border.parameterize(m, bhd, b, vim, vpm, &r), SMP::OK);
  std::vector<double> opposite(r.turning_angles.size());
  double sum = 0.;
  for(std::size_t k = 0; k < opposite.size(); ++k)
  {
    opposite[k] = r.geodesic_curvatures[k] + r.corrections[k];
    sum += opposite[k];
  }
  BOOST_TEST(std::abs(sum - 2. * CGAL_PI) > 1e-2);
  Given_border given;
  given.vertices = mbp_test::border_loop_vertices(m, bhd);
  BOOST_REQUIRE(SMP::internal::polygon_from_turning_angles(opposite, r.edge_lengths, given.uv) == SMP::OK);
  SMP::Discrete_conformal_map_parameterizer_3<Mesh, Given_border, LU> dcp(given);
  BOOST_REQUIRE_EQUAL(SMP::parameterize(m, dcp, bhd, wrong), SMP::OK);
  const double a = angle_distortion(m, ours), w = angle_distortion(m, wrong);
  BOOST_TEST_MESSAGE("angle distortion: k - h " << a << ", k + h " << w);
  BOOST_TEST(10. * a < w);
}

BOOST_AUTO_TEST_CASE(a_self_overlapping_border_is_blended_until_valid)
{
  Mesh m = mbp_test::make_mesh<Mesh>(spiral_ramp());
  const halfedge_descriptor bhd = mbp_test::longest_border(m);
  Border border;
  UV_map b = mbp_test::new_uv_map(m, "v:b");
  auto vpm = m.add_property_map<vertex_descriptor, bool>("v:done", false).first;
  auto vim = m.add_property_map<vertex_descriptor, int>("v:index", 0).first;
  Report r;
  BOOST_REQUIRE_EQUAL(border.parameterize(m, bhd, b, vim, vpm, &r), SMP::OK);
  // the conformal border itself overlaps: a blend was needed, and the result is simple
  BOOST_TEST(r.conformal_blend > 0.);
  BOOST_TEST(r.conformal_blend < 1.);
  BOOST_TEST(SMP::internal::is_simple_polygon(eigen_polygon(r.border_uv)));
  std::vector<Eigen::Vector2d> at_zero;
  BOOST_REQUIRE(SMP::internal::polygon_from_turning_angles(r.turning_angles, r.edge_lengths, at_zero) == SMP::OK);
  BOOST_TEST(!SMP::internal::is_simple_polygon(at_zero));

  // the complete parameterizer: the smallest blend whose layout is one-to-one
  UV_map uv = mbp_test::new_uv_map(m, "v:uv");
  Report report;
  BOOST_REQUIRE_EQUAL(flatten<SMP::Conformal_border>(m, uv, &report), SMP::OK);
  BOOST_TEST(SMP::is_one_to_one_uv_map(m, faces(m), uv));
  BOOST_TEST(report.kept_border == SMP::CONFORMAL);
  BOOST_TEST(report.blend >= r.conformal_blend);
  BOOST_TEST(report.blend < 1.);
  // the automatic border: valid, and never worse than that
  UV_map automatic_uv = mbp_test::new_uv_map(m, "v:automatic");
  BOOST_REQUIRE_EQUAL(flatten<SMP::Automatic_border<> >(m, automatic_uv), SMP::OK);
  BOOST_TEST(SMP::is_one_to_one_uv_map(m, faces(m), automatic_uv));
  BOOST_TEST(angle_distortion(m, automatic_uv) <= angle_distortion(m, uv) * (1. + 1e-12));
}

BOOST_AUTO_TEST_CASE(drop_in_border_in_cgal_dcp_equals_the_complete_parameterizer)
{
  for(const auto& named : {std::make_pair(std::string("bumpy disk"), mbp_test::bumpy_disk()),
                           std::make_pair(std::string("rolled C"), [] {
                             std::vector<std::array<double, 2> > p;
                             return rolled_c_shape(p);
                           }())})
  {
    Mesh m = mbp_test::make_mesh<Mesh>(named.second);
    const halfedge_descriptor bhd = mbp_test::longest_border(m);
    UV_map full_uv = mbp_test::new_uv_map(m, "v:full"), dcp_uv = mbp_test::new_uv_map(m, "v:dcp");
    BOOST_REQUIRE_EQUAL(flatten<SMP::Conformal_border>(m, full_uv), SMP::OK);
    SMP::Discrete_conformal_map_parameterizer_3<Mesh, Border, LU> dcp;
    BOOST_REQUIRE_EQUAL(SMP::parameterize(m, dcp, bhd, dcp_uv), SMP::OK);
    double diff = 0.;
    for(vertex_descriptor v : vertices(m))
      diff = (std::max)(diff, std::sqrt(CGAL::squared_distance(full_uv[v], dcp_uv[v])));
    BOOST_TEST_MESSAGE(named.first << ": drop-in in CGAL's DCP against the complete parameterizer " << diff);
    BOOST_TEST_CONTEXT(named.first) { BOOST_TEST(diff <= 1e-9); }
  }
}

BOOST_AUTO_TEST_CASE(drop_in_border_in_every_fixed_border_parameterizer_and_mesh_type)
{
  // a curved disk whose conformal border is convex: every fixed border map is then valid
  const mbp_test::Soup soup = mbp_test::polar_disk(8, 24, 1., 1., [](double x, double y) { return 0.3 * (x * x + y * y); });
  Mesh m = mbp_test::make_mesh<Mesh>(soup);
  const halfedge_descriptor bhd = mbp_test::longest_border(m);
  UV_map uv = mbp_test::new_uv_map(m, "v:uv");
  Report report;  // the report of the border step that CGAL's DCP runs on its copy
  SMP::Discrete_conformal_map_parameterizer_3<Mesh, Reporting_border> dcp(Reporting_border{&report});
  BOOST_REQUIRE_EQUAL(SMP::parameterize(m, dcp, bhd, uv), SMP::OK);
  BOOST_TEST(SMP::is_one_to_one_uv_map(m, faces(m), uv));
  BOOST_TEST(report.border_convex);
  const std::vector<vertex_descriptor> loop = mbp_test::border_loop_vertices(m, bhd);
  BOOST_REQUIRE_EQUAL(report.border_uv.size(), loop.size());
  for(std::size_t k = 0; k < loop.size(); ++k)
  {
    const K::Point_2 p = uv[loop[k]];
    BOOST_TEST(std::abs(p.x() - report.border_uv[k][0]) == 0.);
    BOOST_TEST(std::abs(p.y() - report.border_uv[k][1]) == 0.);
  }
  SMP::Mean_value_coordinates_parameterizer_3<Mesh, Border> mvc;
  BOOST_TEST(SMP::parameterize(m, mvc, bhd, uv) == SMP::OK);
  BOOST_TEST(SMP::is_one_to_one_uv_map(m, faces(m), uv));
  SMP::Barycentric_mapping_parameterizer_3<Mesh, Border> bary;
  BOOST_TEST(SMP::parameterize(m, bary, bhd, uv) == SMP::OK);
  BOOST_TEST(SMP::is_one_to_one_uv_map(m, faces(m), uv));
  SMP::Discrete_authalic_parameterizer_3<Mesh, Border> authalic;
  BOOST_TEST(SMP::parameterize(m, authalic, bhd, uv) == SMP::OK);
  BOOST_TEST(SMP::is_one_to_one_uv_map(m, faces(m), uv));

  // Polyhedron_3: the same border
  Poly poly;
  mbp_test::soup_to_mesh(soup, poly);
  typedef boost::graph_traits<Poly>::vertex_descriptor Pv;
  std::map<Pv, EPICK::Point_2> uv_storage;
  auto poly_uv = boost::make_assoc_property_map(uv_storage);
  typedef mbp_test::Reporting_border<SMP::Conformal_border_parameterizer_3<Poly> > Poly_border;
  Report poly_report;
  SMP::Discrete_conformal_map_parameterizer_3<Poly, Poly_border> poly_dcp(Poly_border{&poly_report});
  BOOST_REQUIRE_EQUAL(SMP::parameterize(poly, poly_dcp, mbp_test::longest_border(poly), poly_uv), SMP::OK);
  BOOST_TEST((poly_report.border_uv == report.border_uv));

  // Seam_mesh: a tube cut open along one of its lines is a disk
  mbp_test::Soup tube = grid(24, 6, [](double a, double b) {
    const double t = 2. * CGAL_PI * a;
    return std::array<double, 3>{{std::cos(t), std::sin(t), 1.5 * b}};
  });
  // glue the last column onto the first
  const std::size_t rows = 7;
  for(auto& f : tube.faces)
    for(std::size_t& v : f)
      if(v >= 24 * rows)
        v -= 24 * rows;
  tube.points.resize(24 * rows);
  Mesh base = mbp_test::make_mesh<Mesh>(tube);
  typedef Mesh::Property_map<boost::graph_traits<Mesh>::edge_descriptor, bool> Seam_edges;
  typedef Mesh::Property_map<vertex_descriptor, bool> Seam_vertices;
  typedef CGAL::Seam_mesh<Mesh, Seam_edges, Seam_vertices> Seam;
  Seam_edges se = base.add_property_map<boost::graph_traits<Mesh>::edge_descriptor, bool>("e:seam", false).first;
  Seam_vertices sv = base.add_property_map<vertex_descriptor, bool>("v:seam", false).first;
  Seam seam(base, se, sv);
  for(std::size_t j = 0; j + 1 < rows; ++j)
  {
    const auto e = edge(vertex_descriptor(std::uint32_t(j)), vertex_descriptor(std::uint32_t(j + 1)), base);
    BOOST_REQUIRE(e.second);
    seam.add_seam(source(e.first, base), target(e.first, base));
  }
  const auto seam_bhd = CGAL::Polygon_mesh_processing::longest_border(seam).first;
  typedef boost::graph_traits<Seam>::vertex_descriptor Sv;
  std::map<Sv, K::Point_2> seam_storage;
  auto seam_uv = boost::make_assoc_property_map(seam_storage);
  typedef mbp_test::Reporting_border<SMP::Conformal_border_parameterizer_3<Seam> > Seam_border;
  Report seam_report;
  SMP::Discrete_conformal_map_parameterizer_3<Seam, Seam_border, LU> seam_dcp(Seam_border{&seam_report});
  BOOST_REQUIRE_EQUAL(SMP::parameterize(seam, seam_dcp, seam_bhd, seam_uv), SMP::OK);
  // the tube is developable: the cut-open tube unrolls to a rectangle (four corners turn by
  // pi/2, every other border vertex is straight)
  const auto& turning = seam_report.turning_angles;
  BOOST_TEST(!turning.empty());
  int corners = 0;
  for(double k : turning)
  {
    if(std::abs(k - 0.5 * CGAL_PI) <= 1e-9)
      ++corners;
    else
      BOOST_TEST(std::abs(k) <= 1e-9);
  }
  BOOST_TEST(corners == 4);
  SMP::Conformal_parameterizer_3<Seam, SMP::Conformal_border> seam_full;
  std::map<Sv, K::Point_2> full_storage;
  auto full_uv = boost::make_assoc_property_map(full_storage);
  Report seam_full_report;
  BOOST_REQUIRE_EQUAL(SMP::parameterize(seam, seam_full, seam_bhd, full_uv, &seam_full_report), SMP::OK);
  BOOST_TEST(seam_full_report.statistics.factorizations == 1);
}

BOOST_AUTO_TEST_CASE(holes_are_filled_as_for_the_measured_border)
{
  Mesh m = mbp_test::make_mesh<Mesh>(mbp_test::disk_with_two_holes());
  UV_map uv = mbp_test::new_uv_map(m, "v:uv");
  BOOST_REQUIRE_EQUAL(flatten<SMP::Conformal_border>(m, uv), SMP::OK);
  BOOST_TEST(SMP::is_one_to_one_uv_map(m, faces(m), uv));
  Border border;
  UV_map b = mbp_test::new_uv_map(m, "v:b");
  auto vpm = m.add_property_map<vertex_descriptor, bool>("v:done", false).first;
  auto vim = m.add_property_map<vertex_descriptor, int>("v:index", 0).first;
  Report r;
  BOOST_REQUIRE_EQUAL(border.parameterize(m, mbp_test::longest_border(m), b, vim, vpm, &r), SMP::OK);
  BOOST_REQUIRE(!r.turning_angles.empty());
  double sum = 0.;
  for(double k : r.turning_angles)
    sum += k;
  BOOST_TEST(std::abs(sum - 2. * CGAL_PI) <= 1e-10);
  // the conformal border beats the circle on this curved disk
  UV_map circle = mbp_test::new_uv_map(m, "v:circle");
  BOOST_REQUIRE_EQUAL(flatten<SMP::Circular_border>(m, circle), SMP::OK);
  BOOST_TEST(angle_distortion(m, uv) < 0.5 * angle_distortion(m, circle));
}

BOOST_AUTO_TEST_CASE(one_factorization_unless_poisson_distances_are_asked_for)
{
  Mesh m = mbp_test::make_mesh<Mesh>(mbp_test::bumpy_disk());
  UV_map uv = mbp_test::new_uv_map(m, "v:uv");
  auto no_center_one_factorization = [&](auto policy, const char* name) {
    BOOST_TEST_CONTEXT(name)
    {
      Report r;
      BOOST_REQUIRE_EQUAL(flatten<decltype(policy)>(m, uv, &r), SMP::OK);
      BOOST_TEST(r.statistics.factorizations == 1);
      BOOST_TEST(!r.has_center);
    }
  };
  no_center_one_factorization(SMP::Conformal_border(), "conformal");
  no_center_one_factorization(SMP::Circular_border(), "circle");
  // conformal: the angle defects, then u and v
  Report conformal;
  flatten<SMP::Conformal_border>(m, uv, &conformal);
  BOOST_TEST(conformal.statistics.back_substitutions == 3);
  // automatic with geodesic distances: one factorization for the search, one for the
  // holomorphic extension of its layout (within the bound here: the last layout tried)
  SMP::Conformal_parameterizer_3<Mesh, SMP::Automatic_border<SMP::Poisson_center_locator,
    SMP::Geodesic_border_distance<SMP::Fast_marching_geodesics> > > geodesic;
  Report geodesic_report;
  BOOST_REQUIRE_EQUAL(SMP::parameterize(m, geodesic, mbp_test::longest_border(m), uv, &geodesic_report), SMP::OK);
  BOOST_TEST(geodesic_report.statistics.factorizations == 2);
  BOOST_TEST(geodesic_report.border_candidates.back().holomorphic_extension);
  // automatic with the paper's Poisson distances: the conformal layout is valid here, so the
  // measured member is not built: no center, no spring Laplacian
  Report poisson;
  BOOST_REQUIRE_EQUAL(flatten<SMP::Automatic_border<> >(m, uv, &poisson), SMP::OK);
  BOOST_TEST(poisson.statistics.factorizations == 2);
  BOOST_TEST(!poisson.has_center);
  // the measured border alone: the paper's two factorizations
  Report measured;
  BOOST_REQUIRE_EQUAL(flatten<SMP::Measured_border<> >(m, uv, &measured), SMP::OK);
  BOOST_TEST(measured.statistics.factorizations == 2);
}

BOOST_AUTO_TEST_CASE(automatic_border_keeps_the_best_valid_candidate)
{
  Mesh m = mbp_test::make_mesh<Mesh>(mbp_test::bumpy_disk());
  UV_map uv = mbp_test::new_uv_map(m, "v:uv");
  Report r;
  BOOST_REQUIRE_EQUAL(flatten<SMP::Automatic_border<> >(m, uv, &r), SMP::OK);
  BOOST_REQUIRE(r.chosen_candidate >= 0);
  bool members[3] = {false, false, false};
  for(const SMP::Border_candidate& c : r.border_candidates)
  {
    if(c.valid)
      BOOST_TEST(r.border_candidates[std::size_t(r.chosen_candidate)].objective <= c.objective);
    members[c.family] = true;
  }
  BOOST_TEST(members[SMP::CIRCLE]);
  BOOST_TEST(members[SMP::CONFORMAL]);
  BOOST_TEST(!members[SMP::MEASURED]);  // built only when the conformal layout folds
  // the kept layout is the one written, and its figure is the paper's angle distortion
  BOOST_TEST(std::abs(angle_distortion(m, uv) - r.border_candidates[std::size_t(r.chosen_candidate)].objective) <=
             1e-9 * angle_distortion(m, uv));
  BOOST_TEST(r.kept_border == SMP::CONFORMAL);
}

BOOST_AUTO_TEST_CASE(distortion_bound_ranks_within_first_then_angle_and_area_together)
{
  const SMP::Distortion_bound bound;  // 0.2 and 0.2
  const double inf = std::numeric_limits<double>::infinity();
  BOOST_TEST(bound.met_by(0.2, 0.2));
  BOOST_TEST(!bound.met_by(0.2, 0.21));
  // within the bound: by angle alone, before every layout outside it
  BOOST_TEST(bound.rank(0.01, 0.19) < bound.rank(0.02, 0.01));
  BOOST_TEST(bound.rank(0.2, 0.2) < bound.rank(1e-9, 0.21));
  // outside: a relative trade, (a / 0.2) (s / 0.2)
  BOOST_TEST(std::abs(bound.rank(0.4, 0.8) - (1. + 2. * 4.)) <= 1e-12);
  BOOST_TEST(bound.rank(0.0095, 3.313) < bound.rank(0.0428, 3.294));  // a little area for much angle loses
  BOOST_TEST(bound.rank(0.0104, 0.636) < bound.rank(0.262, 0.417));   // much angle for a little area wins
  // an infinite bound does not count: by angle alone, or by area alone outside the other bound
  const SMP::Distortion_bound no_bound{inf, inf}, area_only{inf, 0.2};
  BOOST_TEST(no_bound.rank(0.01, 50.) < no_bound.rank(0.02, 0.));
  BOOST_TEST(area_only.rank(9., 0.3) < area_only.rank(0.01, 0.4));
  BOOST_TEST(std::isinf(SMP::Distortion_bound{0., 0.2}.rank(0.1, 0.)));  // 0 times infinity is not NaN
}

namespace {

// The rank of a reported candidate by `bound` (+infinity when it is not valid).
double candidate_rank(const SMP::Distortion_bound& bound, const SMP::Border_candidate& c)
{
  return c.valid ? bound.rank(c.objective, c.area_spread) : std::numeric_limits<double>::infinity();
}

} // namespace

BOOST_AUTO_TEST_CASE(automatic_border_tries_the_conformal_length_member_and_ranks_by_its_bound)
{
  // the spiral ramp's conformal border overlaps itself: the conformal-length member is tried
  Mesh m = mbp_test::make_mesh<Mesh>(spiral_ramp());
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<SMP::Border_family> kept_members;
  for(const SMP::Distortion_bound& bound :
      {SMP::Distortion_bound(), SMP::Distortion_bound{inf, inf}, SMP::Distortion_bound{inf, 0.01},
       SMP::Distortion_bound{1e-6, 1e-6}})
    BOOST_TEST_CONTEXT("bound " << bound.max_angle_distortion << ", " << bound.max_area_spread)
    {
      UV_map uv = mbp_test::new_uv_map(m, "v:uv");
      Report r;
      const SMP::Conformal_parameterizer_3<Mesh, SMP::Automatic_border<> > p{SMP::Automatic_border<>(bound)};
      BOOST_REQUIRE_EQUAL(SMP::parameterize(m, p, mbp_test::longest_border(m), uv, &r), SMP::OK);
      BOOST_REQUIRE(r.chosen_candidate >= 0);
      BOOST_TEST(r.conformal_blend > 0.);  // the conformal border's own blend, kept in the report
      bool lengths = false;
      const SMP::Border_candidate& kept = r.border_candidates[std::size_t(r.chosen_candidate)];
      for(const SMP::Border_candidate& c : r.border_candidates)
      {
        lengths = lengths || c.family == SMP::CONFORMAL_LENGTHS;
        BOOST_TEST((c.valid == std::isfinite(c.area_spread)));
        BOOST_TEST(candidate_rank(bound, kept) <= candidate_rank(bound, c));
      }
      BOOST_TEST(lengths);
      // the kept figures are those of the written map, computed independently
      const SMP::Parameterization_quality q = SMP::measure_quality(m, faces(m), uv);
      BOOST_TEST(SMP::is_one_to_one_uv_map(m, faces(m), uv));
      BOOST_TEST(std::abs(q.angle_distortion - kept.objective) <= 1e-9 * q.angle_distortion);
      BOOST_TEST(std::abs(q.area_distortion_mean - kept.area_spread) <= 1e-9 * q.area_distortion_mean);
      BOOST_TEST_MESSAGE("kept " << int(kept.family) << " at " << kept.blend << ": angle " << kept.objective
                                 << ", area spread " << kept.area_spread << ", " << r.border_candidates.size()
                                 << " candidates");
      kept_members.push_back(kept.family);
    }
  // the bound decides: by angle alone the conformal-length member (a thousand times less angle
  // distortion here); by area alone another member (the conformal lengths crush the ramp)
  BOOST_REQUIRE_EQUAL(kept_members.size(), 4u);
  BOOST_TEST(kept_members[1] == SMP::CONFORMAL_LENGTHS);
  BOOST_TEST(kept_members[2] != SMP::CONFORMAL_LENGTHS);
}

// ------------------------------------------------------------------ real disks (extended tier)

namespace {

std::vector<std::string> real_disks()
{
  return {"alligator.obj", "bff_face.obj", "bimba_hole.off", "bimba_i.obj", "blade-nice-flip-cyl2.off",
          "bump-domain.obj", "cylinder_locally_refined.off", "dog.obj", "horse.obj", "igl_face.obj",
          "inspired_mesh.obj", "irr4-cyl2.off", "lilium.obj", "lion-head.off", "mask.off",
          "matthew_nefertiti.off", "maxFace.obj", "mushroom.off", "patch-01.off", "snail.obj",
          "spothead.obj", "venus.off", "woody-hi.off"};
}

} // namespace

// ================================================================ the conformal-length member

BOOST_AUTO_TEST_CASE(conformal_length_scale_factors_against_a_dense_solve)
{
  // L u = [Omega_I ; k_B - c] solved here densely, pinned at the center (the package pins its
  // first border vertex), the mean removed
  Length_member member(mbp_test::bumpy_disk(5, 16));
  auto& [m, disk, data, scale] = member;
  Eigen::MatrixXd L;
  std::vector<double> sums;
  dense_laplacian(m, L, sums);
  const std::size_t n = num_vertices(m), mb = disk.border().size();
  std::vector<std::size_t> border;
  for(int b : disk.border())
    border.push_back(std::size_t(disk.vertex(std::size_t(b))));
  std::vector<double> lengths(mb);
  double total = 0.;
  for(std::size_t k = 0; k < mb; ++k)
    total += lengths[k] = std::sqrt(CGAL::squared_distance(m.point(vertex_descriptor(Mesh::size_type(border[k]))),
                                                           m.point(vertex_descriptor(Mesh::size_type(border[(k + 1) % mb])))));
  Eigen::VectorXd f = Eigen::VectorXd::Zero(Eigen::Index(n));
  for(std::size_t i = 0; i < n; ++i)
    f[Eigen::Index(i)] = 2. * CGAL_PI - sums[i];
  for(std::size_t k = 0; k < mb; ++k)
    f[Eigen::Index(border[k])] = CGAL_PI - sums[border[k]] - CGAL_PI * (lengths[(k + mb - 1) % mb] + lengths[k]) / total;
  BOOST_TEST(std::abs(f.sum()) <= 1e-10);  // discrete Gauss-Bonnet
  const Eigen::Index pin = 0, r = Eigen::Index(n) - 1;  // vertex 0: the center, interior
  Eigen::VectorXd u = Eigen::VectorXd::Zero(Eigen::Index(n));
  u.tail(r) = L.bottomRightCorner(r, r).ldlt().solve(f.tail(r));
  BOOST_TEST(std::abs(L.row(pin).dot(u) - f[pin]) <= 1e-9);  // the pinned row holds too
  u.array() -= u.mean();
  double worst = 0., span = 0.;
  for(std::size_t k = 0; k < mb; ++k)
  {
    worst = (std::max)(worst, std::abs(scale[k] - u[Eigen::Index(border[k])]));
    span = (std::max)(span, std::abs(scale[k] - scale[0]));
  }
  BOOST_TEST_MESSAGE("scale factors: largest difference to the dense solve " << worst << ", span " << span);
  BOOST_TEST(worst <= 1e-10);
  BOOST_TEST(span > 1e-2);  // a curved, elongated disk: the factors matter
}

BOOST_AUTO_TEST_CASE(conformal_length_member_at_blend_zero_is_the_conformal_border)
{
  for(const auto& named : {std::make_pair(std::string("bumpy disk"), mbp_test::bumpy_disk()),
                           std::make_pair(std::string("spiral ramp"), spiral_ramp())})
  {
    BOOST_TEST_CONTEXT(named.first)
    {
      Length_member member(named.second);
      auto& [m, disk, data, scale] = member;
      std::vector<Eigen::Vector2d> ours, conformal, half, kept;
      BOOST_REQUIRE(SMP::internal::conformal_length_polygon(data, scale, 0., ours) == SMP::OK);
      BOOST_REQUIRE(SMP::internal::polygon_from_turning_angles(data.turning, data.lengths, conformal) == SMP::OK);
      BOOST_TEST(largest_distance(ours, conformal) <= 1e-12);
      // at t > 0 the lengths differ from the kept ones: another polygon
      BOOST_REQUIRE(SMP::internal::conformal_length_polygon(data, scale, 0.5, half) == SMP::OK);
      BOOST_REQUIRE(SMP::internal::polygon_from_turning_angles(SMP::internal::blended_turning_angles(data, 0.5),
                                                               data.lengths, kept) == SMP::OK);
      BOOST_TEST(largest_distance(half, kept) > 1e-3);
    }
  }
  // where the conformal border is simple, the policy gives the conformal border's map
  Mesh m = mbp_test::make_mesh<Mesh>(mbp_test::bumpy_disk());
  UV_map conformal = mbp_test::new_uv_map(m, "v:conformal"), lengths = mbp_test::new_uv_map(m, "v:lengths");
  Report report;
  BOOST_REQUIRE_EQUAL(flatten<SMP::Conformal_border>(m, conformal), SMP::OK);
  BOOST_REQUIRE_EQUAL(flatten<SMP::Conformal_length_border>(m, lengths, &report), SMP::OK);
  BOOST_TEST(report.kept_border == SMP::CONFORMAL_LENGTHS);
  BOOST_TEST(report.conformal_blend == 0.);
  BOOST_TEST(report.blend == 0.);
  BOOST_TEST(report.statistics.factorizations == 2);  // L_II and the grounded L
  BOOST_TEST(report.scale_factors.size() == report.edge_lengths.size());
  double worst = 0.;
  for(vertex_descriptor v : vertices(m))
    worst = (std::max)(worst, std::sqrt(CGAL::squared_distance(conformal[v], lengths[v])));
  BOOST_TEST(worst <= 1e-12);
}

BOOST_AUTO_TEST_CASE(conformal_length_member_starts_at_its_smallest_simple_blend)
{
  // the spiral ramp's conformal border overlaps itself: the member's own blend is the smallest
  // (to 2^-20) at which its polygon is simple
  Mesh m = mbp_test::make_mesh<Mesh>(spiral_ramp());
  Disk disk;
  BOOST_REQUIRE_EQUAL(disk.build_disk(m, mbp_test::longest_border(m), get(CGAL::vertex_point, m)), SMP::OK);
  SMP::internal::Border_members members(disk);
  std::vector<Eigen::Vector2d> polygon, uv;
  std::vector<double> closed;
  BOOST_REQUIRE_EQUAL(members.add_conformal_lengths(disk, polygon, closed), SMP::OK);
  BOOST_REQUIRE(members.has(SMP::CONFORMAL_LENGTHS));
  BOOST_REQUIRE(members.has(SMP::CONFORMAL));
  const double t = members.own_blend(SMP::CONFORMAL_LENGTHS);
  BOOST_TEST_MESSAGE("spiral ramp: own blend, conformal " << members.own_blend(SMP::CONFORMAL) << ", conformal lengths " << t);
  BOOST_TEST(t > 0.);
  BOOST_TEST(t <= 1.);
  BOOST_REQUIRE(members.border(SMP::CONFORMAL_LENGTHS, t, uv));
  BOOST_TEST(largest_distance(uv, polygon) == 0.);
  BOOST_TEST(!members.border(SMP::CONFORMAL_LENGTHS, t - std::ldexp(1., -20), uv));
  // the complete parameterizer keeps a one-to-one layout of the member
  UV_map map = mbp_test::new_uv_map(m, "v:uv");
  Report report;
  BOOST_REQUIRE_EQUAL(flatten<SMP::Conformal_length_border>(m, map, &report), SMP::OK);
  BOOST_TEST(report.kept_border == SMP::CONFORMAL_LENGTHS);
  BOOST_TEST(report.conformal_blend == t);
  BOOST_TEST(report.blend >= t);
  BOOST_TEST(SMP::is_one_to_one_uv_map(m, faces(m), map));
}

BOOST_AUTO_TEST_CASE(conformal_length_member_at_blend_one_turns_as_the_circle_and_is_near_conformal)
{
  Length_member member(mbp_test::bumpy_disk(8, 24));
  auto& [m, disk, data, scale] = member;
  std::vector<Eigen::Vector2d> ours, kept, opposite;
  BOOST_REQUIRE(SMP::internal::conformal_length_polygon(data, scale, 1., ours) == SMP::OK);
  // the turning angles of the polygon (clockwise) are the circle's
  const std::size_t mb = ours.size();
  double worst = 0.;
  for(std::size_t k = 0; k < mb; ++k)
  {
    const Eigen::Vector2d a = ours[k] - ours[(k + mb - 1) % mb], b = ours[(k + 1) % mb] - ours[k];
    const double turn = -std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
    worst = (std::max)(worst, std::abs(turn - data.circle[k]));
  }
  BOOST_TEST(worst <= 1e-9);
  // the length-kept blend at t = 1 (the arc-length circle), and the opposite sign exp(+u)
  BOOST_REQUIRE(SMP::internal::polygon_from_turning_angles(SMP::internal::blended_turning_angles(data, 1.),
                                                           data.lengths, kept) == SMP::OK);
  std::vector<double> negated(scale);
  for(double& x : negated)
    x = -x;
  BOOST_REQUIRE(SMP::internal::conformal_length_polygon(data, negated, 1., opposite) == SMP::OK);
  std::size_t flips = 0, kept_flips = 0, opposite_flips = 0;
  bool one_to_one = false, other = false;
  const double a = dcp_with_border(m, disk, ours, "v:ours", flips, one_to_one);
  const double k = dcp_with_border(m, disk, kept, "v:kept", kept_flips, other);
  const double o = dcp_with_border(m, disk, opposite, "v:opposite", opposite_flips, other);
  BOOST_TEST_MESSAGE("angle distortion at t = 1: conformal lengths exp(-u) " << a << ", lengths kept " << k
                     << ", exp(+u) " << o << " (" << opposite_flips << " flips)");
  BOOST_TEST(flips == 0u);
  BOOST_TEST(one_to_one);
  BOOST_TEST(10. * a < k);
  BOOST_TEST(10. * a < o);
}

BOOST_AUTO_TEST_CASE(conformal_length_scale_factors_vanish_on_a_planar_regular_disk)
{
  // a planar disk whose border is a regular polygon: Omega = 0 inside and k = c on the border,
  // so u = 0 (the member is the conformal border, i.e. the disk itself, at every blend)
  Length_member member(mbp_test::polar_disk(6, 20));
  auto& [m, disk, data, scale] = member;
  double largest = 0.;
  for(double x : scale)
    largest = (std::max)(largest, std::abs(x));
  BOOST_TEST(largest <= 1e-10);
}

// A quarter of a cylinder (radius 1, height 1.5) on a grid of 16 x 12 quads whose vertices
// are moved along the surface by up to 0.3 of a cell: developable, but the triangles no
// longer lie in flat strips, so the discrete angle defects are small and not zero, and the
// conformal border's lengths are closed by a change (as on cylinder_locally_refined.off).
mbp_test::Soup jittered_cylinder_patch()
{
  const int cols = 16, rows = 12;
  mbp_test::Soup s = grid(cols, rows, [](double a, double b) {
    const double ja = (a > 0. && a < 1.) ? 0.3 / cols * std::sin(37. * a + 91. * b) : 0.;
    const double jb = (b > 0. && b < 1.) ? 0.3 / rows * std::cos(53. * a - 29. * b) : 0.;
    const double theta = 0.5 * CGAL_PI * (a + ja);
    return std::array<double, 3>{{std::cos(theta), 1.5 * (b + jb), std::sin(theta)}};
  });
  return s;
}

// The UVs of the mesh's vertices, by vertex index.
std::vector<std::array<double, 2> > uv_by_vertex(const Mesh& m, UV_map uv)
{
  std::vector<std::array<double, 2> > x(num_vertices(m));
  for(vertex_descriptor v : vertices(m))
    x[std::size_t(v)] = {{uv[v].x(), uv[v].y()}};
  return x;
}

// The largest residual of the discrete Cauchy-Riemann equations of a layout (u, v) against a
// dense cotangent Laplacian assembled here: L u = 0 and L v = 0 at interior vertices, and on
// the border loop of `bhd` (L v)_k = s (u_{k+1} - u_{k-1}) / 2 for one sign s; over the
// layout's diameter.
double cauchy_riemann_residual(const Mesh& m, halfedge_descriptor bhd, const std::vector<std::array<double, 2> >& uv)
{
  Eigen::MatrixXd L;
  std::vector<double> sums;
  dense_laplacian(m, L, sums);
  const std::size_t n = num_vertices(m);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(Eigen::Index(n)), v = u;
  for(std::size_t i = 0; i < n; ++i)
  {
    u[Eigen::Index(i)] = uv[i][0];
    v[Eigen::Index(i)] = uv[i][1];
  }
  const Eigen::VectorXd Lu = L * u, Lv = L * v;
  std::vector<std::size_t> border;
  std::vector<bool> on_border(n, false);
  for(auto h : halfedges_around_face(bhd, m))
  {
    border.push_back(std::size_t(source(h, m)));
    on_border[border.back()] = true;
  }
  double interior = 0., plus = 0., minus = 0.;
  for(std::size_t i = 0; i < n; ++i)
    if(!on_border[i])
      interior = (std::max)(interior, (std::max)(std::abs(Lu[Eigen::Index(i)]), std::abs(Lv[Eigen::Index(i)])));
  const std::size_t mb = border.size();
  for(std::size_t k = 0; k < mb; ++k)
  {
    const double d = 0.5 * (u[Eigen::Index(border[(k + 1) % mb])] - u[Eigen::Index(border[(k + mb - 1) % mb])]);
    plus = (std::max)(plus, std::abs(Lv[Eigen::Index(border[k])] - d));
    minus = (std::max)(minus, std::abs(Lv[Eigen::Index(border[k])] + d));
  }
  return (std::max)(interior, (std::min)(plus, minus)) / (u.maxCoeff() - u.minCoeff());
}

BOOST_AUTO_TEST_CASE(holomorphic_extension_satisfies_the_discrete_cauchy_riemann_equations)
{
  for(const auto& [name, soup] : {std::make_pair("bumpy disk", mbp_test::bumpy_disk()),
                                  std::make_pair("jittered cylinder", jittered_cylinder_patch())})
    BOOST_TEST_CONTEXT(name)
    {
      Mesh m = mbp_test::make_mesh<Mesh>(soup);
      UV_map uv = mbp_test::new_uv_map(m, "v:uv"), dirichlet = mbp_test::new_uv_map(m, "v:dirichlet");
      Report r;
      BOOST_REQUIRE_EQUAL(flatten<SMP::Automatic_border<> >(m, uv, &r), SMP::OK);
      // within the bound: the extension of the kept layout was tried last and is kept
      BOOST_REQUIRE(!r.border_candidates.empty());
      BOOST_TEST(r.border_candidates.back().holomorphic_extension);
      BOOST_TEST(r.holomorphic_extension);
      BOOST_TEST(r.border_candidates[std::size_t(r.chosen_candidate)].holomorphic_extension);
      const double holomorphic = cauchy_riemann_residual(m, mbp_test::longest_border(m), uv_by_vertex(m, uv));
      // the conformal border with both coordinates fixed on it (Dirichlet) does not satisfy them
      BOOST_REQUIRE_EQUAL(flatten<SMP::Conformal_border>(m, dirichlet), SMP::OK);
      const double fixed = cauchy_riemann_residual(m, mbp_test::longest_border(m), uv_by_vertex(m, dirichlet));
      BOOST_TEST_MESSAGE(name << ": Cauchy-Riemann residual " << holomorphic << " (Dirichlet: " << fixed << ")");
      BOOST_TEST(holomorphic <= 1e-9);
      BOOST_TEST(fixed > 1e3 * holomorphic);
      // more conformal, one-to-one
      BOOST_TEST(angle_distortion(m, uv) < angle_distortion(m, dirichlet));
      BOOST_TEST(SMP::measure_quality(m, faces(m), uv).flipped_faces == 0u);
    }
}

BOOST_AUTO_TEST_CASE(holomorphic_extension_only_within_the_bound_and_when_enabled)
{
  // beyond the bound (1e-6 on the area spread: no layout of the bumpy disk meets it)
  // the extension is not tried: the atlas splits such a layout, and its factorization is saved
  Mesh m = mbp_test::make_mesh<Mesh>(mbp_test::bumpy_disk());
  UV_map uv = mbp_test::new_uv_map(m, "v:uv");
  const SMP::Conformal_parameterizer_3<Mesh, SMP::Automatic_border<> > p(
    SMP::Automatic_border<>(SMP::Distortion_bound{0.2, 1e-6}));
  Report r;
  BOOST_REQUIRE_EQUAL(SMP::parameterize(m, p, mbp_test::longest_border(m), uv, &r), SMP::OK);
  for(const SMP::Border_candidate& c : r.border_candidates)
    BOOST_TEST(!c.holomorphic_extension);
  BOOST_TEST(r.statistics.factorizations == 1);
  // turned off (as the atlas does on the parts of its splits): within the bound, not tried
  const SMP::Conformal_parameterizer_3<Mesh, SMP::Automatic_border<> > off(
    SMP::Automatic_border<>(SMP::Distortion_bound(), false));
  BOOST_TEST(!SMP::Automatic_border<>(SMP::Distortion_bound(), false).holomorphic_extension());
  Report o;
  BOOST_REQUIRE_EQUAL(SMP::parameterize(m, off, mbp_test::longest_border(m), uv, &o), SMP::OK);
  for(const SMP::Border_candidate& c : o.border_candidates)
    BOOST_TEST(!c.holomorphic_extension);
  BOOST_TEST(o.statistics.factorizations == 1);
  BOOST_TEST(SMP::Distortion_bound().met_by(o.border_candidates[std::size_t(o.chosen_candidate)].objective,
                                            o.border_candidates[std::size_t(o.chosen_candidate)].area_spread));
}

BOOST_AUTO_TEST_CASE(real_disks_automatic_border, MBP_EXTENDED_TIER)
{
  std::vector<double> ratios;
  for(const std::string& name : real_disks())
  {
    Mesh m;
    mbp_test::read_mesh(mbp_test::shared_mesh(name), m);
    UV_map uv = mbp_test::new_uv_map(m, "v:uv"), circle = mbp_test::new_uv_map(m, "v:circle");
    BOOST_TEST_CONTEXT(name)
    {
      Report r;
      BOOST_REQUIRE_EQUAL(flatten<SMP::Automatic_border<> >(m, uv, &r), SMP::OK);
      const SMP::Parameterization_quality q = SMP::measure_quality(m, faces(m), uv);
      BOOST_TEST(q.flipped_faces == 0u);
      BOOST_TEST(SMP::is_one_to_one_uv_map(m, faces(m), uv));
      // on these disks the bound's rank keeps the valid layout of lowest angle distortion
      const SMP::Border_candidate& kept = r.border_candidates[std::size_t(r.chosen_candidate)];
      for(const SMP::Border_candidate& c : r.border_candidates)
      {
        if(c.valid)
          BOOST_TEST(q.angle_distortion <= c.objective * (1. + 1e-9) + 1e-15);
        BOOST_TEST(candidate_rank(SMP::Distortion_bound(), kept) <= candidate_rank(SMP::Distortion_bound(), c));
      }
      // where the conformal polygon overlaps itself (horse), the conformal-length member is kept
      BOOST_TEST((r.conformal_blend > 0.) == (r.kept_border == SMP::CONFORMAL_LENGTHS));
      double circle_distortion = std::numeric_limits<double>::quiet_NaN();
      if(flatten<SMP::Circular_border>(m, circle) == SMP::OK)
        circle_distortion = angle_distortion(m, circle);
      ratios.push_back(q.angle_distortion / circle_distortion);
      BOOST_TEST_MESSAGE(name << ": automatic " << q.angle_distortion << " (kept " << int(r.kept_border)
                              << ", blend " << r.blend << "), circle " << circle_distortion);
    }
  }
  std::sort(ratios.begin(), ratios.end());
  const double median = ratios[ratios.size() / 2];
  BOOST_TEST_MESSAGE("median automatic / circle: " << median);
  BOOST_TEST(median <= 0.02);
}

BOOST_AUTO_TEST_SUITE_END()
