// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// The edges of the library (issue 15), each against an independent oracle:
//  - a user's center that is not a vertex of the mesh is a wrong parameter (no out-of-bounds
//    read);
//  - results do not depend on the mesh's scale, from 1e-150 to 1e150 (UVs, quality figures,
//    distance maps scaled exactly);
//  - border loops of equal length: main_border()'s documented tie rule, invariant under
//    similarities and mirrors;
//  - fast marching on right-angled triangles is invariant under a rigid motion;
//  - a pinched disk (a vertex whose faces form several fans) is ERROR_NO_TOPOLOGICAL_DISC,
//    whatever the order of the faces;
//  - a sequential call starts no thread, a parallel one does, with the same result;
//  - the mean value system against CGAL's Mean_value_coordinates_parameterizer_3;
//  - the paper's Poisson distance map (Eq. 1, spring exponent r = 0, 1, 2) and the mean edge
//    length g against dense computations made here on an irregular mesh;
//  - the automatic border's bisection for the smallest valid blend, and the conformal
//    border's blend toward the circle, against their definitions.

#define BOOST_TEST_MODULE edges
#include <boost/test/unit_test.hpp>

#include "test_support.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include <CGAL/Surface_mesh_parameterization/Circular_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Mean_value_coordinates_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <CGAL/Surface_mesh_parameterization/Conformal_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Fixed_center.h>
#include <CGAL/Surface_mesh_parameterization/Geodesic_border_distance.h>
#include <CGAL/Surface_mesh_parameterization/geodesic_distance_map.h>
#include <CGAL/Surface_mesh_parameterization/main_border.h>
#include <CGAL/Surface_mesh_parameterization/measure_quality.h>
#include <CGAL/Surface_mesh_parameterization/Measured_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Measured_conformal_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_patch_3.h>
#include <CGAL/Surface_mesh_parameterization/poisson_distance_map.h>
#include <CGAL/Surface_mesh_parameterization/internal/concurrency.h>
#ifdef MBP_WITH_CHOLMOD
#include <CGAL/Surface_mesh_parameterization/Cholmod_supernodal_cholesky_traits.h>
#endif

#include <Eigen/Dense>
#include <Eigen/SparseLU>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace SMP = CGAL::Surface_mesh_parameterization;
typedef CGAL::Simple_cartesian<double>                          K;
typedef CGAL::Surface_mesh<K::Point_3>                          Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor            vertex_descriptor;
typedef boost::graph_traits<Mesh>::halfedge_descriptor          halfedge_descriptor;
typedef boost::graph_traits<Mesh>::face_descriptor              face_descriptor;
typedef Mesh::Property_map<vertex_descriptor, K::Point_2>       UV_map;
typedef Mesh::Property_map<vertex_descriptor, double>           Distance_map;
typedef CGAL::Eigen_solver_traits<Eigen::SparseLU<CGAL::Eigen_sparse_matrix<double>::EigenType> > LU;
typedef SMP::Measured_conformal_parameterizer_3<Mesh>           Full;
typedef SMP::Parameterization_patch_3<Mesh>                     Patch;

namespace {

// ---------------------------------------------------------------- meshes and maps

typedef std::function<std::array<double, 3>(const std::array<double, 3>&)> Transform;

Mesh make(const mbp_test::Soup& soup, const Transform& transform = nullptr)
{
  mbp_test::Soup s = soup;
  if(transform)
    for(auto& p : s.points)
      p = transform(p);
  Mesh m;
  mbp_test::soup_to_mesh(s, m);
  return m;
}

Transform scaling(double factor)
{
  return [factor](const std::array<double, 3>& p) {
    return std::array<double, 3>{{p[0] * factor, p[1] * factor, p[2] * factor}};
  };
}

// A rotation by `angle` about the axis (1, 2, 3) and a translation.
Transform rigid_motion(double angle, const std::array<double, 3>& translation)
{
  const Eigen::Matrix3d R = Eigen::AngleAxisd(angle, Eigen::Vector3d(1., 2., 3.).normalized()).toRotationMatrix();
  return [R, translation](const std::array<double, 3>& p) {
    const Eigen::Vector3d q = R * Eigen::Vector3d(p[0], p[1], p[2]);
    return std::array<double, 3>{{q.x() + translation[0], q.y() + translation[1], q.z() + translation[2]}};
  };
}

UV_map new_uv(Mesh& m, const std::string& name)
{
  return m.add_property_map<vertex_descriptor, K::Point_2>(name, K::Point_2(-7, -7)).first;
}

Distance_map new_distances(Mesh& m, const std::string& name)
{
  return m.add_property_map<vertex_descriptor, double>(name, -1.).first;
}

// Deterministic pseudo-random numbers in [0, 1) (the same on every platform).
struct Lcg
{
  std::uint32_t state;
  explicit Lcg(std::uint32_t seed) : state(seed) {}
  double operator()()
  {
    state = state * 1664525u + 1013904223u;
    return double(state >> 8) / double(1u << 24);
  }
};

// An irregular curved disk: the polar grid of the unit disk with every vertex moved at
// random (interior ones by up to a quarter of the ring spacing, border ones along and across
// the border), lifted onto a bump. Edge lengths vary by a factor of about 4, so that the
// spring exponent r of the Poisson distance map matters.
mbp_test::Soup irregular_disk(int rings = 6, int spokes = 20)
{
  mbp_test::Soup s = mbp_test::polar_disk(rings, spokes);
  Lcg rnd(12345);
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

// The flat square [0,1]^2 on a grid of n x n squares, each split along the same diagonal:
// every triangle is right-angled.
mbp_test::Soup square_grid(int n)
{
  return mbp_test::notched_grid(n, n, n, [](int, int) { return false; });
}

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

// The vertices of the border loop of `h`, as indices, sorted.
std::vector<std::size_t> loop_of(const Mesh& m, halfedge_descriptor h)
{
  std::vector<std::size_t> loop;
  for(halfedge_descriptor b : CGAL::halfedges_around_face(h, m))
    loop.push_back(std::size_t(source(b, m)));
  std::sort(loop.begin(), loop.end());
  return loop;
}

// largest |a - b| over the vertices, two meshes with the same vertex indices
double uv_difference(const Mesh& ma, UV_map a, const Mesh& mb, UV_map b)
{
  BOOST_REQUIRE_EQUAL(num_vertices(ma), num_vertices(mb));
  double worst = 0.;
  for(vertex_descriptor v : vertices(ma))
    worst = (std::max)(worst, std::hypot(a[v].x() - b[v].x(), a[v].y() - b[v].y()));
  return worst;
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

template <class Parameterizer>
SMP::Error_code run(Mesh& m, Parameterizer& p, halfedge_descriptor bhd, UV_map uv)
{
  return SMP::parameterize(m, p, bhd, uv);
}

} // namespace

// ================================================================ 1. Fixed_center

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
  Mesh m = make(two);
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
        UV_map uv = new_uv(*mesh, "v:uv");
        auto done = mesh->add_property_map<vertex_descriptor, bool>("v:done", false).first;
        auto index = mesh->add_property_map<vertex_descriptor, int>("v:index", 0).first;
        SMP::Measured_border_parameterizer_3<Mesh, SMP::Fixed_center<Mesh> > border{SMP::Fixed_center<Mesh>(v)};
        BOOST_TEST(border.parameterize(*mesh, bhd, uv, index, done) == SMP::ERROR_WRONG_PARAMETER);
        SMP::Measured_conformal_parameterizer_3<Mesh, SMP::Fixed_center<Mesh> > full{SMP::Fixed_center<Mesh>(v)};
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
    UV_map uv = new_uv(with_removed, "v:uv");
    SMP::Measured_conformal_parameterizer_3<Mesh, SMP::Fixed_center<Mesh> > full{SMP::Fixed_center<Mesh>(removed)};
    BOOST_TEST(run(with_removed, full, bhd, uv) == SMP::ERROR_WRONG_PARAMETER);
  }
  // the same locator with an interior vertex of the component works
  const vertex_descriptor good(Mesh::size_type(first_component ? 0 : n));
  UV_map uv = new_uv(m, "v:good");
  SMP::Measured_conformal_parameterizer_3<Mesh, SMP::Fixed_center<Mesh> > full{SMP::Fixed_center<Mesh>(good)};
  BOOST_TEST(run(m, full, bhd, uv) == SMP::OK);
  BOOST_TEST(full.center() == good);
}

// ================================================================ 2. extreme scales

namespace {

struct Reference
{
  std::map<int, std::vector<K::Point_2> > uv;       // per border choice, by vertex index
  std::map<int, SMP::Parameterization_quality> quality;
  std::map<int, vertex_descriptor> center;
  std::vector<double> bpdm, pdm, geodesic, border_distances, edge_lengths, closed_lengths;
  double polar_scale = 0.;                            // UV length per unit of the mesh's length
};

const Full::Border_choice choices[] = {Full::MEASURED_BORDER, Full::CONFORMAL_BORDER, Full::AUTOMATIC_BORDER};

// every figure of `a` against `b`, relative (the angle distortions, which vanish for a
// conformal map of a flat mesh, with a floor)
void check_same_quality(const SMP::Parameterization_quality& a, const SMP::Parameterization_quality& b, double tolerance)
{
  auto same = [tolerance](double x, double y) {
    return std::abs(x - y) <= tolerance * (std::max)({std::abs(x), std::abs(y), 1e-3});
  };
  BOOST_TEST(same(a.angle_distortion, b.angle_distortion), a.angle_distortion << " vs " << b.angle_distortion);
  BOOST_TEST(same(a.angle_distortion_per_corner, b.angle_distortion_per_corner));
  BOOST_TEST(same(a.quasi_conformal_mean, b.quasi_conformal_mean));
  BOOST_TEST(same(a.quasi_conformal_max, b.quasi_conformal_max));
  BOOST_TEST(same(a.l2_stretch, b.l2_stretch), a.l2_stretch << " vs " << b.l2_stretch);
  BOOST_TEST(same(a.linf_stretch, b.linf_stretch));
  // the area distortions are logarithms of ratios: an absolute difference is a relative one
  // of the ratios
  auto same_log = [tolerance](double x, double y) { return std::abs(x - y) <= tolerance * (std::max)({std::abs(x), std::abs(y), 1.}); };
  BOOST_TEST(same_log(a.area_distortion_mean, b.area_distortion_mean), a.area_distortion_mean << " vs " << b.area_distortion_mean);
  BOOST_TEST(same_log(a.area_distortion_max, b.area_distortion_max), a.area_distortion_max << " vs " << b.area_distortion_max);
  BOOST_TEST(a.flipped_faces == b.flipped_faces);
  BOOST_TEST(a.number_of_faces == b.number_of_faces);
  BOOST_TEST(a.number_of_vertices == b.number_of_vertices);
}

// Everything the package measures on `m` (the border choices' UVs and figures, the distance
// maps, the records' lengths).
Reference measure_everything(Mesh& m)
{
  Reference r;
  const halfedge_descriptor bhd = SMP::main_border(m).first;
  for(Full::Border_choice choice : choices)
  {
    UV_map uv = new_uv(m, "v:uv");
    Full p;
    p.set_border_choice(choice);
    BOOST_REQUIRE_EQUAL(run(m, p, bhd, uv), SMP::OK);
    for(vertex_descriptor v : vertices(m))
      r.uv[choice].push_back(uv[v]);
    r.quality[choice] = SMP::measure_quality(m, faces(m), uv);
    r.center[choice] = p.center();
    if(choice == Full::MEASURED_BORDER)
    {
      const auto& record = p.border_parameterizer().last_record();
      r.border_distances = record.border_distances;
      r.polar_scale = record.polar_scale;
      // the record's polar map gives the border UVs: origin + scale * distance * direction
      for(std::size_t k = 0; k < record.border_vertices.size(); ++k)
      {
        const double radius = record.polar_scale * record.border_distances[k];
        const K::Point_2 q = uv[record.border_vertices[k]];
        BOOST_TEST(std::abs(q.x() - (record.polar_origin.x() + radius * std::cos(-record.border_angles[k]))) <= 1e-12);
        BOOST_TEST(std::abs(q.y() - (record.polar_origin.y() + radius * std::sin(-record.border_angles[k]))) <= 1e-12);
      }
    }
    m.remove_property_map(uv);
  }
  SMP::Conformal_border_parameterizer_3<Mesh> conformal;
  UV_map uv = new_uv(m, "v:border");
  auto done = m.add_property_map<vertex_descriptor, bool>("v:done", false).first;
  auto index = m.add_property_map<vertex_descriptor, int>("v:index", 0).first;
  BOOST_REQUIRE_EQUAL(conformal.parameterize(m, bhd, uv, index, done), SMP::OK);
  r.edge_lengths = conformal.last_record().edge_lengths;
  r.closed_lengths = conformal.last_record().closed_lengths;
  m.remove_property_map(uv);
  m.remove_property_map(done);
  m.remove_property_map(index);

  Distance_map f = new_distances(m, "v:f");
  const std::vector<vertex_descriptor> source(1, vertex_descriptor(0));
  BOOST_REQUIRE_EQUAL(SMP::boundary_poisson_distance_map(m, bhd, f), SMP::OK);
  for(vertex_descriptor v : vertices(m))
    r.bpdm.push_back(f[v]);
  BOOST_REQUIRE_EQUAL(SMP::poisson_distance_map(m, source, f), SMP::OK);
  for(vertex_descriptor v : vertices(m))
    r.pdm.push_back(f[v]);
  BOOST_REQUIRE_EQUAL(SMP::geodesic_distance_map(m, source, f), SMP::OK);
  for(vertex_descriptor v : vertices(m))
    r.geodesic.push_back(f[v]);
  m.remove_property_map(f);
  return r;
}

// `scaled` against `factor` times `reference`: exactly for a power of two, to 1e-12
// relative otherwise
void check_scaled_lengths(const std::vector<double>& scaled, const std::vector<double>& reference, double factor,
                          bool power_of_two, const std::string& what)
{
  BOOST_TEST_CONTEXT(what)
  {
    BOOST_REQUIRE_EQUAL(scaled.size(), reference.size());
    double largest = 0., worst = 0.;
    for(std::size_t i = 0; i < scaled.size(); ++i)
    {
      largest = (std::max)(largest, std::abs(reference[i]));
      worst = (std::max)(worst, std::abs(scaled[i] / factor - reference[i]));
      if(power_of_two)
        BOOST_TEST(scaled[i] == factor * reference[i]);
    }
    BOOST_TEST(largest > 0.);
    BOOST_TEST(worst <= 1e-12 * largest, "largest relative difference " << worst / largest);
  }
}

} // namespace

BOOST_AUTO_TEST_CASE(results_do_not_depend_on_the_scale_of_the_mesh)
{
  const std::vector<std::pair<double, bool> > factors{
    {std::ldexp(1., -490), true}, {std::ldexp(1., -270), true}, {std::ldexp(1., 260), true},
    {std::ldexp(1., 495), true}, {1e-150, false}, {1e-80, false}, {1e-6, false}, {1e6, false},
    {1e78, false}, {1e150, false}};
  for(const auto& named : {std::make_pair(std::string("planar grid"), square_grid(10)),
                           std::make_pair(std::string("curved disk"), mbp_test::bumpy_disk(6, 20))})
  {
    Mesh unit = make(named.second);
    const Reference reference = measure_everything(unit);
    for(const auto& [factor, power_of_two] : factors)
      BOOST_TEST_CONTEXT(named.first << " scaled by " << factor)
      {
        Mesh m = make(named.second, scaling(factor));
        const Reference scaled = measure_everything(m);
        for(Full::Border_choice choice : choices)
          BOOST_TEST_CONTEXT("border choice " << int(choice))
          {
            BOOST_TEST(scaled.center.at(choice) == reference.center.at(choice));
            double worst = 0.;
            CGAL::Bbox_2 box;
            for(std::size_t i = 0; i < num_vertices(m); ++i)
            {
              const K::Point_2 &a = scaled.uv.at(choice)[i], &b = reference.uv.at(choice)[i];
              worst = (std::max)(worst, std::hypot(a.x() - b.x(), a.y() - b.y()));
              box += b.bbox();
            }
            const double diameter = std::hypot(box.xmax() - box.xmin(), box.ymax() - box.ymin());
            BOOST_TEST(worst <= 1e-12 * diameter, "UV difference " << worst / diameter << " of the diameter");
            if(power_of_two)
              BOOST_TEST(worst == 0.);
            check_same_quality(scaled.quality.at(choice), reference.quality.at(choice), 1e-12);
          }
        check_scaled_lengths(scaled.bpdm, reference.bpdm, factor, power_of_two, "boundary Poisson distance map");
        check_scaled_lengths(scaled.pdm, reference.pdm, factor, power_of_two, "Poisson distance map");
        check_scaled_lengths(scaled.geodesic, reference.geodesic, factor, power_of_two, "geodesic distance map");
        check_scaled_lengths(scaled.border_distances, reference.border_distances, factor, power_of_two,
                             "measured border record: border distances");
        check_scaled_lengths(std::vector<double>(1, 1. / scaled.polar_scale), std::vector<double>(1, 1. / reference.polar_scale),
                             factor, power_of_two, "measured border record: polar scale (UV length per unit of length)");
        check_scaled_lengths(scaled.edge_lengths, reference.edge_lengths, factor, power_of_two,
                             "conformal border record: edge lengths");
        check_scaled_lengths(scaled.closed_lengths, reference.closed_lengths, factor, power_of_two,
                             "conformal border record: closed lengths");
      }
  }
}

BOOST_AUTO_TEST_CASE(quality_figures_do_not_depend_on_the_scale_of_the_mesh_or_of_the_uvs)
{
  Mesh unit = make(mbp_test::bumpy_disk(6, 20));
  UV_map uv = new_uv(unit, "v:uv");
  Full p;
  BOOST_REQUIRE_EQUAL(run(unit, p, SMP::main_border(unit).first, uv), SMP::OK);
  const SMP::Parameterization_quality reference = SMP::measure_quality(unit, faces(unit), uv);
  BOOST_TEST(reference.angle_distortion > 1e-3);  // a curved disk: the figures are not trivial
  for(double mesh_factor : {1e-150, 1e-80, 1., 1e78, 1e150})
    for(double uv_factor : {1e-150, 1e-6, 1., 1e150})
      BOOST_TEST_CONTEXT("mesh scaled by " << mesh_factor << ", UVs by " << uv_factor)
      {
        Mesh m = make(mbp_test::bumpy_disk(6, 20), scaling(mesh_factor));
        UV_map scaled = new_uv(m, "v:uv");
        for(vertex_descriptor v : vertices(m))
          scaled[v] = K::Point_2(uv[v].x() * uv_factor, uv[v].y() * uv_factor);
        check_same_quality(SMP::measure_quality(m, faces(m), scaled), reference, 1e-12);
      }
}

// ================================================================ 3. the main border

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
        const Mesh m = make(tube(n), transform);
        const auto [bhd, length] = SMP::main_border(m);
        BOOST_REQUIRE(bhd != Mesh::null_halfedge());
        BOOST_TEST(is_border(bhd, m));
        BOOST_TEST(std::size_t(source(bhd, m)) == 0u);
        BOOST_TEST(loop_of(m, bhd).front() == 0u);
        BOOST_TEST(std::abs(length - CGAL::Polygon_mesh_processing::face_border_length(bhd, m)) <= 1e-12 * length);
        plain_rule_choices.insert(loop_of(m, CGAL::Polygon_mesh_processing::longest_border(m).first).front());
      }
    BOOST_TEST_MESSAGE("tube of " << n << ": the longest loop alone picks " << plain_rule_choices.size()
                       << " different loops over the transformations");
    // the parameterization follows: the same UVs for the tube scaled by 1e-6
    Mesh a = make(tube(n)), b = make(tube(n), scaling(1e-6));
    UV_map ua = new_uv(a, "v:uv"), ub = new_uv(b, "v:uv");
    Full pa, pb;
    BOOST_REQUIRE_EQUAL(run(a, pa, SMP::main_border(a).first, ua), SMP::OK);
    BOOST_REQUIRE_EQUAL(run(b, pb, SMP::main_border(b).first, ub), SMP::OK);
    BOOST_TEST(uv_difference(a, ua, b, ub) <= 1e-12);
  }

  // equal lengths, different numbers of vertices: the tie goes to the loop with more vertices
  // (the top square, 8 vertices, against the bottom one, 4)
  const mbp_test::Soup squares = tube_between(square_loop(1, 2.), square_loop(2, 2.));
  for(const auto& [name, transform] : transforms)
    BOOST_TEST_CONTEXT("square tube, " << name)
    {
      const Mesh m = make(squares, transform);
      const halfedge_descriptor bhd = SMP::main_border(m).first;
      BOOST_TEST(loop_of(m, bhd).size() == 8u);
      BOOST_TEST(std::size_t(source(bhd, m)) == 4u);  // the first vertex of the top loop
    }

  // no tie: the longer loop wins, whatever the numbers of vertices (a 24-gon of radius 0.3
  // against a square of side 1 with 4 vertices)
  const mbp_test::Soup frustum = tube_between(circle_loop(24, 0.3), square_loop(1, 1.));
  for(const auto& [name, transform] : transforms)
    BOOST_TEST_CONTEXT("frustum, " << name)
    {
      const Mesh m = make(frustum, transform);
      const auto [bhd, length] = SMP::main_border(m);
      BOOST_TEST(loop_of(m, bhd).size() == 4u);
      BOOST_TEST(std::abs(length - CGAL::Polygon_mesh_processing::face_border_length(bhd, m)) <= 1e-12 * length);
    }

  // a closed mesh has no border
  mbp_test::Soup closed = tube_between(square_loop(1, 1.), square_loop(1, 1.));
  closed.faces.push_back({0, 2, 1});
  closed.faces.push_back({0, 3, 2});
  closed.faces.push_back({4, 5, 6});
  closed.faces.push_back({4, 6, 7});
  const Mesh box = make(closed);
  BOOST_TEST(SMP::main_border(box).first == Mesh::null_halfedge());
}

// ================================================================ 4. fast marching

BOOST_AUTO_TEST_CASE(fast_marching_on_right_angled_triangles_is_invariant_under_a_rigid_motion)
{
  const mbp_test::Soup grid = square_grid(16);
  const Mesh m = make(grid);
  // corner, middle of a side, and center of the square
  std::vector<std::vector<vertex_descriptor> > sources;
  for(const std::array<double, 2>& q : std::vector<std::array<double, 2> >{{{0., 0.}}, {{0.5, 0.}}, {{0.5, 0.5}}})
    for(vertex_descriptor v : vertices(m))
      if(std::abs(m.point(v).x() - q[0]) < 1e-12 && std::abs(m.point(v).y() - q[1]) < 1e-12)
        sources.push_back(std::vector<vertex_descriptor>(1, v));
  BOOST_REQUIRE_EQUAL(sources.size(), 3u);
  for(const auto& motion : {rigid_motion(std::sqrt(2.), {{0.3, -1.7, 2.9}}), rigid_motion(CGAL_PI / 7., {{1e3, 0., -2.}}),
                            rigid_motion(1., {{0., 0., 0.}})})
  {
    Mesh moved = make(grid, motion);
    for(const auto& source : sources)
      BOOST_TEST_CONTEXT("source " << std::size_t(source.front()))
      {
        Mesh a = m;
        Distance_map da = new_distances(a, "v:d"), db = new_distances(moved, "v:d");
        BOOST_REQUIRE_EQUAL(SMP::geodesic_distance_map<SMP::Fast_marching_geodesics>(a, source, da), SMP::OK);
        BOOST_REQUIRE_EQUAL(SMP::geodesic_distance_map<SMP::Fast_marching_geodesics>(moved, source, db), SMP::OK);
        double worst = 0., largest = 0.;
        for(vertex_descriptor v : vertices(a))
        {
          worst = (std::max)(worst, std::abs(da[v] - db[v]));
          largest = (std::max)(largest, da[v]);
        }
        BOOST_TEST(worst <= 1e-12 * largest, "relative deviation " << worst / largest);
        moved.remove_property_map(db);
      }
  }
}

// ================================================================ 5. pinched disks

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

// the border loops of a mesh: one halfedge each, and how often each visits its most visited vertex
std::vector<std::pair<halfedge_descriptor, int> > border_loops(const Mesh& m)
{
  std::vector<std::pair<halfedge_descriptor, int> > loops;
  std::set<halfedge_descriptor> seen;
  for(halfedge_descriptor h : halfedges(m))
    if(is_border(h, m) && seen.insert(h).second)
    {
      std::map<vertex_descriptor, int> visits;
      int most = 0;
      for(halfedge_descriptor b : CGAL::halfedges_around_face(h, m))
      {
        seen.insert(b);
        most = (std::max)(most, ++visits[source(b, m)]);
      }
      loops.emplace_back(h, most);
    }
  return loops;
}

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
  UV_map uv = new_uv(m, "v:uv");
  auto done = m.add_property_map<vertex_descriptor, bool>("v:done", false).first;
  auto index = m.add_property_map<vertex_descriptor, int>("v:index", 0).first;
  Distance_map f = new_distances(m, "v:f");
  for(Full::Border_choice choice : {Full::MEASURED_BORDER, Full::CONFORMAL_BORDER, Full::CIRCULAR_BORDER, Full::AUTOMATIC_BORDER})
  {
    Full p;
    p.set_border_choice(choice);
    BOOST_TEST(p.parameterize(m, bhd, uv, index, done) == SMP::ERROR_NO_TOPOLOGICAL_DISC, "border choice " << int(choice));
  }
  SMP::Measured_border_parameterizer_3<Mesh> measured;
  BOOST_TEST(measured.parameterize(m, bhd, uv, index, done) == SMP::ERROR_NO_TOPOLOGICAL_DISC);
  SMP::Conformal_border_parameterizer_3<Mesh> conformal;
  BOOST_TEST(conformal.parameterize(m, bhd, uv, index, done) == SMP::ERROR_NO_TOPOLOGICAL_DISC);
  BOOST_TEST(SMP::boundary_poisson_distance_map(m, bhd, f) == SMP::ERROR_NO_TOPOLOGICAL_DISC);
  Patch patch;
  BOOST_TEST(patch.build_disk(m, bhd, get(CGAL::vertex_point, m)) == SMP::ERROR_NO_TOPOLOGICAL_DISC);
  BOOST_TEST(patch.number_of_vertices() == 0u);
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
        UV_map uv = new_uv(m, "v:uv");
        Full p;
        p.set_border_choice(Full::CONFORMAL_BORDER);
        BOOST_REQUIRE_EQUAL(run(m, p, SMP::main_border(m).first, uv), SMP::OK);
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

// ================================================================ 6. concurrency

BOOST_AUTO_TEST_CASE(a_sequential_call_starts_no_thread)
{
  // more than 10000 interior vertices: with Parallel_tag, the multi-column solves split their
  // columns over two threads
  mbp_test::Soup soup = mbp_test::hex_disk(60);
  for(auto& p : soup.points)
    p[2] = 0.3 * p[0] * p[0] - 0.2 * p[1] * p[1] + 0.1 * p[0] * p[1];
  Mesh m = make(soup);
  const halfedge_descriptor bhd = SMP::main_border(m).first;
  // the patch-level step that Measured_conformal_parameterizer_3 composes: a Sequential_tag
  // measured border leaves the patch's later multi-column solves (the automatic border's
  // batch of candidate layouts) single-threaded; a Parallel_tag one lets them use two threads
  // (the control that this solve reaches the threaded path)
  {
    const auto threads_of_a_batch_after_the_border = [&](auto border) {
      Patch patch;
      BOOST_REQUIRE_EQUAL(patch.build_disk(m, bhd, get(CGAL::vertex_point, m)), SMP::OK);
      BOOST_REQUIRE(patch.interior_vertices().size() >= 10000u);
      std::vector<Eigen::Vector2d> border_uv;
      BOOST_REQUIRE_EQUAL(border.parameterize_border(patch, border_uv, true), SMP::OK);
      Eigen::MatrixXd values = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(border_uv.size()), 4), rhs, x;
      for(std::size_t k = 0; k < border_uv.size(); ++k)
        values.row(static_cast<Eigen::Index>(k)) << border_uv[k].x(), border_uv[k].y(), 1., -border_uv[k].x();
      patch.interior_rhs_from_border(values, rhs);
      const long before = SMP::internal::threads_started();
      BOOST_REQUIRE_EQUAL(patch.solve_interior(rhs, x), SMP::OK);
      const long started = SMP::internal::threads_started() - before;
      // the solve is right whatever the threads: constant border values give a constant
      BOOST_TEST((x.col(2).array() - 1.).abs().maxCoeff() < 1e-9);
      BOOST_TEST((x.col(3) + x.col(0)).cwiseAbs().maxCoeff() <= 1e-12 * x.col(0).cwiseAbs().maxCoeff());
      return started;
    };
    BOOST_TEST(threads_of_a_batch_after_the_border(SMP::Measured_border_parameterizer_3<Mesh>()) == 0);
    typedef SMP::Measured_border_parameterizer_3<Mesh, CGAL::Default, CGAL::Default, CGAL::Default,
                                                 CGAL::Parallel_tag> Parallel_border;
    BOOST_TEST(threads_of_a_batch_after_the_border(Parallel_border()) >= 1);
  }
  typedef SMP::Measured_conformal_parameterizer_3<Mesh, CGAL::Default, CGAL::Default, CGAL::Default, CGAL::Parallel_tag>
    Parallel;
  for(Full::Border_choice choice : {Full::MEASURED_BORDER, Full::AUTOMATIC_BORDER})
    BOOST_TEST_CONTEXT("border choice " << int(choice))
    {
      UV_map sequential_uv = new_uv(m, "v:sequential"), parallel_uv = new_uv(m, "v:parallel");
      long before = SMP::internal::threads_started();
      Full sequential;  // CGAL::Sequential_tag, the default
      sequential.set_border_choice(choice);
      BOOST_REQUIRE_EQUAL(run(m, sequential, bhd, sequential_uv), SMP::OK);
      BOOST_TEST(SMP::internal::threads_started() - before == 0);

      before = SMP::internal::threads_started();
      Parallel parallel;
      parallel.set_border_choice(static_cast<Parallel::Border_choice>(choice));
      BOOST_REQUIRE_EQUAL(run(m, parallel, bhd, parallel_uv), SMP::OK);
      const long started = SMP::internal::threads_started() - before;
      BOOST_TEST_MESSAGE("Parallel_tag: " << started << " threads");
      BOOST_TEST(started >= 1);
      BOOST_TEST(uv_difference(m, sequential_uv, m, parallel_uv) == 0.);
      BOOST_TEST(sequential.center() == parallel.center());

      // CGAL's DCP with the measured border: sequential too
      before = SMP::internal::threads_started();
      SMP::Measured_border_parameterizer_3<Mesh> border;
      UV_map border_uv = new_uv(m, "v:border");
      auto done = m.add_property_map<vertex_descriptor, bool>("v:done", false).first;
      auto index = m.add_property_map<vertex_descriptor, int>("v:index", 0).first;
      BOOST_REQUIRE_EQUAL(border.parameterize(m, bhd, border_uv, index, done), SMP::OK);
      BOOST_TEST(SMP::internal::threads_started() - before == 0);
      m.remove_property_map(border_uv);
      m.remove_property_map(done);
      m.remove_property_map(index);
      m.remove_property_map(sequential_uv);
      m.remove_property_map(parallel_uv);
    }
#ifdef MBP_WITH_CHOLMOD
  {
    typedef SMP::Measured_conformal_parameterizer_3<Mesh, CGAL::Default, CGAL::Default,
                                                    SMP::Cholmod_supernodal_cholesky_traits> Cholmod;
    UV_map uv = new_uv(m, "v:cholmod");
    const long before = SMP::internal::threads_started();
    Cholmod p;
    p.set_border_choice(Cholmod::AUTOMATIC_BORDER);
    BOOST_REQUIRE_EQUAL(run(m, p, bhd, uv), SMP::OK);
    BOOST_TEST(SMP::internal::threads_started() - before == 0);
  }
#else
  BOOST_TEST_MESSAGE("CHOLMOD not available in this build: its sequential call not tested");
#endif
}

// ================================================================ the mean value system

BOOST_AUTO_TEST_CASE(mean_value_system_equals_cgal_mean_value_coordinates)
{
  for(const auto& named : {std::make_pair(std::string("curved disk"), mbp_test::bumpy_disk(8, 24)),
                           std::make_pair(std::string("disk with two holes"), mbp_test::disk_with_two_holes())})
    BOOST_TEST_CONTEXT(named.first)
    {
      Mesh m = make(named.second);
      const halfedge_descriptor bhd = SMP::main_border(m).first;
      Patch patch;
      BOOST_REQUIRE_EQUAL(patch.build_disk(m, bhd, get(CGAL::vertex_point, m)), SMP::OK);

      // CGAL treats a hole's vertices as interior vertices whose ring has a gap (its mean
      // value weights span the gap), the patch fills each hole with a virtual vertex. For
      // CGAL, the holes are filled here with a real vertex where build_disk() documents the
      // virtual one: the loop's centroid lifted by a fifth of its mean radius along its normal.
      Mesh filled = m;
      std::vector<K::Point_3> fillings;
      for(const auto& loop : border_loops(m))
      {
        if(loop_of(m, loop.first) == loop_of(m, bhd))
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
      // the patch's virtual vertices are where the documentation says
      for(std::size_t i = patch.number_of_real_vertices(); i < patch.number_of_vertices(); ++i)
      {
        const Eigen::Vector3d p = patch.point(i) * patch.length_unit();
        double nearest = std::numeric_limits<double>::infinity();
        for(const K::Point_3& q : fillings)
          nearest = (std::min)(nearest, (p - Eigen::Vector3d(q.x(), q.y(), q.z())).norm());
        BOOST_TEST(nearest <= 1e-12);
      }

      // CGAL: arc-length circle, mean value coordinates, a direct solver
      UV_map cgal_uv = new_uv(filled, "v:cgal");
      SMP::Mean_value_coordinates_parameterizer_3<Mesh, SMP::Circular_border_arc_length_parameterizer_3<Mesh>, LU> mvc;
      BOOST_REQUIRE_EQUAL(SMP::parameterize(filled, mvc, bhd, cgal_uv), SMP::OK);

      // the patch's mean value system with CGAL's border values
      Patch::Engine* system = patch.mean_value_system();
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
  Mesh m = make(irregular_disk());
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
        Distance_map f = new_distances(m, "v:f");
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
      // Laplacian and one back-substitution), through the border parameterizer's record
      const std::vector<double> oracle = dense_poisson_distances(m, {center}, r);
      SMP::Measured_border_parameterizer_3<Mesh, SMP::Fixed_center<Mesh>, SMP::Poisson_border_distance<Mesh> > border{
        SMP::Fixed_center<Mesh>(center), SMP::Poisson_border_distance<Mesh>(r)};
      UV_map uv = new_uv(m, "v:uv");
      auto done = m.add_property_map<vertex_descriptor, bool>("v:done", false).first;
      auto index = m.add_property_map<vertex_descriptor, int>("v:index", 0).first;
      BOOST_REQUIRE_EQUAL(border.parameterize(m, bhd, uv, index, done), SMP::OK);
      const auto& record = border.last_record();
      BOOST_REQUIRE_EQUAL(record.border_distances.size(), record.border_vertices.size());
      double worst = 0., largest = 0.;
      std::vector<double> at_border;
      for(std::size_t k = 0; k < record.border_vertices.size(); ++k)
      {
        const double expected = oracle[std::size_t(record.border_vertices[k])];
        worst = (std::max)(worst, std::abs(record.border_distances[k] - expected));
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
                           std::make_pair(std::string("planar grid"), square_grid(6))})
    BOOST_TEST_CONTEXT(named.first)
    {
      Mesh m = make(named.second, scaling(1e-3));
      Patch patch;
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

// ================================================================ the automatic border's search

namespace {

// The trials of one member with one interior, as (blend, valid, objective).
struct Trial
{
  double blend;
  bool valid;
  double objective;
};

std::vector<Trial> trials_of(const SMP::internal::Border_evaluator<Patch>& evaluator, SMP::internal::Border_member member,
                             bool mean_value)
{
  std::vector<Trial> out;
  for(const SMP::internal::Border_trial& t : evaluator.trials())
    if(t.member == member && t.mean_value == mean_value)
      out.push_back({t.blend, t.valid, t.objective});
  return out;
}

// The search from a member whose own layout is not one-to-one: the blend it returns is a valid
// trial, no valid trial is smaller, every invalid trial is smaller, and the gap between the
// largest invalid trial and the result is that of `steps` bisection steps of [own, 1].
void check_search(SMP::internal::Border_evaluator<Patch>& evaluator, SMP::internal::Border_member member, bool mean_value)
{
  const double own = evaluator.family().own_blend(member);
  const SMP::internal::Border_trial first = evaluator.evaluate({{member, own}}, mean_value).front();
  BOOST_REQUIRE_MESSAGE(!first.valid, "the member's own layout is one-to-one: nothing to search");
  const int steps = 5;
  const std::vector<double> found = SMP::internal::search_smallest_valid_blend(evaluator, {member}, mean_value, steps);
  BOOST_REQUIRE_EQUAL(found.size(), 1u);
  const double t = found.front();
  BOOST_REQUIRE(t > own);
  const std::vector<Trial> trials = trials_of(evaluator, member, mean_value);
  bool seen = false;
  double largest_invalid = -1., smallest_valid = 2.;
  for(const Trial& x : trials)
  {
    if(x.valid)
      smallest_valid = (std::min)(smallest_valid, x.blend);
    else
      largest_invalid = (std::max)(largest_invalid, x.blend);
    seen = seen || (x.valid && x.blend == t);
    BOOST_TEST(x.blend >= own);
    BOOST_TEST(x.blend <= 1.);
  }
  BOOST_TEST(seen);                      // the result was tried and is one-to-one
  BOOST_TEST(smallest_valid == t);       // no valid blend tried is smaller
  BOOST_TEST(largest_invalid < t);       // every invalid one is smaller
  if(t < 1.)
    BOOST_TEST(t - largest_invalid <= std::ldexp(1. - own, -steps) * (1. + 1e-12));
  BOOST_TEST(trials.size() <= std::size_t(steps + 2));
  double best_objective = std::numeric_limits<double>::infinity();
  for(const Trial& x : trials)
    if(x.valid && x.blend == t)
      best_objective = x.objective;
  BOOST_TEST_MESSAGE("member " << int(member) << (mean_value ? ", mean value" : ", conformal") << " interior: "
                     << trials.size() << " trials, smallest valid blend " << t << " (objective " << best_objective
                     << "), largest invalid " << largest_invalid);
}

} // namespace

BOOST_AUTO_TEST_CASE(search_finds_the_smallest_valid_blend_by_bisection)
{
  // the measured border folds: the C-shape seen from a vertex of its top arm with exact
  // geodesic radii (the discrete conformal interior of that border folds)
  {
    Mesh m = make(mbp_test::c_shape());
    vertex_descriptor center = Mesh::null_vertex();
    for(vertex_descriptor v : vertices(m))
      if(CGAL::squared_distance(m.point(v), K::Point_3(1.5, 13. / 6., 0.)) < 1e-12)
        center = v;
    BOOST_REQUIRE(center != Mesh::null_vertex());
    Patch patch;
    BOOST_REQUIRE_EQUAL(patch.build_disk(m, SMP::main_border(m).first, get(CGAL::vertex_point, m)), SMP::OK);
    SMP::Measured_border_parameterizer_3<Mesh, SMP::Fixed_center<Mesh>,
                                         SMP::Geodesic_border_distance<Mesh, SMP::Exact_geodesics> > border{
      SMP::Fixed_center<Mesh>(center)};
    std::vector<Eigen::Vector2d> uv;
    BOOST_REQUIRE_EQUAL(border.parameterize_border(patch, uv), SMP::OK);
    SMP::internal::Border_family<Patch> family(patch);
    family.add_measured(border.last_record().border_angles, border.last_record().border_distances);
    SMP::internal::Border_evaluator<Patch> evaluator(patch, family);
    check_search(evaluator, SMP::internal::MEASURED_MEMBER, false);
  }
  // the conformal border overlaps itself: the spiral ramp (flat to first order, 1.6 turns);
  // its member starts at its smallest simple blend
  {
    mbp_test::Soup s;
    const int cols = 120, rows = 5;
    for(int i = 0; i <= cols; ++i)
      for(int j = 0; j <= rows; ++j)
      {
        const double theta = 3.2 * CGAL_PI * i / cols, r = 1. + double(j) / rows;
        s.points.push_back({{r * std::cos(theta), r * std::sin(theta), 0.08 * theta}});
      }
    auto id = [](int i, int j) { return std::size_t(i * (rows + 1) + j); };
    for(int i = 0; i < cols; ++i)
      for(int j = 0; j < rows; ++j)
      {
        s.faces.push_back({id(i, j), id(i + 1, j + 1), id(i + 1, j)});
        s.faces.push_back({id(i, j), id(i, j + 1), id(i + 1, j + 1)});
      }
    Mesh m = make(s);
    Patch patch;
    BOOST_REQUIRE_EQUAL(patch.build_disk(m, SMP::main_border(m).first, get(CGAL::vertex_point, m)), SMP::OK);
    SMP::internal::Border_family<Patch> family(patch);
    BOOST_REQUIRE_EQUAL(family.add_conformal(patch), SMP::OK);
    BOOST_TEST(family.own_blend(SMP::internal::CONFORMAL_MEMBER) > 0.);
    SMP::internal::Border_evaluator<Patch> evaluator(patch, family);
    const SMP::internal::Border_trial own =
      evaluator.evaluate({{SMP::internal::CONFORMAL_MEMBER, family.own_blend(SMP::internal::CONFORMAL_MEMBER)}}, false).front();
    BOOST_TEST_MESSAGE("spiral ramp: the conformal member's own layout is " << (own.valid ? "" : "not ") << "one-to-one");
    if(!own.valid)
      check_search(evaluator, SMP::internal::CONFORMAL_MEMBER, false);
  }
}

// ================================================================ the conformal border's blend

BOOST_AUTO_TEST_CASE(conformal_border_blend_toward_the_circle_against_its_definition)
{
  // the spiral ramp: its conformal border overlaps itself, so the border is blended
  mbp_test::Soup s;
  const int cols = 120, rows = 5;
  for(int i = 0; i <= cols; ++i)
    for(int j = 0; j <= rows; ++j)
    {
      const double theta = 3.2 * CGAL_PI * i / cols, r = 1. + double(j) / rows;
      s.points.push_back({{r * std::cos(theta), r * std::sin(theta), 0.08 * theta}});
    }
  auto id = [](int i, int j) { return std::size_t(i * (rows + 1) + j); };
  for(int i = 0; i < cols; ++i)
    for(int j = 0; j < rows; ++j)
    {
      s.faces.push_back({id(i, j), id(i + 1, j + 1), id(i + 1, j)});
      s.faces.push_back({id(i, j), id(i, j + 1), id(i + 1, j + 1)});
    }
  Mesh m = make(s);
  const halfedge_descriptor bhd = SMP::main_border(m).first;
  SMP::Conformal_border_parameterizer_3<Mesh> border;
  UV_map uv = new_uv(m, "v:uv");
  auto done = m.add_property_map<vertex_descriptor, bool>("v:done", false).first;
  auto index = m.add_property_map<vertex_descriptor, int>("v:index", 0).first;
  BOOST_REQUIRE_EQUAL(border.parameterize(m, bhd, uv, index, done), SMP::OK);
  const auto& r = border.last_record();
  const double t = r.blend;
  BOOST_TEST(t > 0.);
  BOOST_TEST(t < 1.);
  const std::size_t n = r.border_vertices.size();

  // the circle's turning angles from the 3D border lengths, computed here:
  // c_k = pi (l_{k-1} + l_k) / sum l
  std::vector<double> l(n);
  double total = 0.;
  for(std::size_t k = 0; k < n; ++k)
  {
    l[k] = std::sqrt(CGAL::squared_distance(m.point(r.border_vertices[k]), m.point(r.border_vertices[(k + 1) % n])));
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
    const Eigen::Vector2d a = r.border_uv[k] - r.border_uv[(k + n - 1) % n];
    const Eigen::Vector2d b = r.border_uv[(k + 1) % n] - r.border_uv[k];
    const double turn = -std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));  // clockwise: positive
    sum += turn;
    worst = (std::max)(worst, std::abs(std::remainder(turn - blended[k], 2. * CGAL_PI)));
    const K::Point_2 p = uv[r.border_vertices[k]];
    BOOST_TEST((p.x() == r.border_uv[k].x() && p.y() == r.border_uv[k].y()));
  }
  BOOST_TEST(worst <= 1e-9, "largest turning angle difference " << worst);
  BOOST_TEST(std::abs(sum - 2. * CGAL_PI) <= 1e-9);  // a simple clockwise polygon
  BOOST_TEST(SMP::internal::is_simple_polygon(r.border_uv));
  // the smallest simple blend: a slightly smaller one is not simple
  std::vector<double> smaller(n);
  const double below = t - std::ldexp(1., -SMP::Conformal_border_parameterizer_3<Mesh>::blend_bisection_steps());
  for(std::size_t k = 0; k < n; ++k)
    smaller[k] = (1. - below) * r.turning_angles[k] + below * CGAL_PI * (l[(k + n - 1) % n] + l[k]) / total;
  std::vector<Eigen::Vector2d> polygon;
  BOOST_REQUIRE(SMP::internal::polygon_from_turning_angles(smaller, l, polygon) == SMP::OK);
  BOOST_TEST(!SMP::internal::is_simple_polygon(polygon));
}
