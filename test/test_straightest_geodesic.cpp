// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// Straightest geodesics of Lee et al. (2006), the "cutting plane" method behind the paper's
// MBPSGP (internal/distances/straightest_geodesic.h): straight segments on flat meshes, failures behind
// the reentrant corner of an L, analytic geodesics of a cylinder and a sphere cap under
// refinement, the polyline's properties, real meshes (how often the border is reached), and
// degenerate input.

#include <boost/test/unit_test.hpp>

#include "test_support.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Surface_mesh_parameterization/internal/distances/straightest_geodesic.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/triangle_adjacency.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

BOOST_AUTO_TEST_SUITE(straightest_geodesic)

namespace SMPI = CGAL::Surface_mesh_parameterization::internal;
typedef SMPI::Straightest_geodesic_tracer Tracer;
typedef std::array<int, 3> Tri;

namespace {

// ------------------------------------------------------------------ meshes as arrays

typedef mbp_test::Arrays Arrays;

Arrays from_soup(const mbp_test::Soup& s) { return mbp_test::arrays_from_soup(s); }

Arrays read_arrays(mbp_test::Tier tier, const std::string& name)
{
  typedef CGAL::Simple_cartesian<double> K;
  typedef CGAL::Surface_mesh<K::Point_3> Mesh;
  Mesh mesh;
  mbp_test::read_mesh(mbp_test::tier_mesh(tier, name), mesh);
  Arrays a;
  std::map<Mesh::Vertex_index, int> index;
  for(Mesh::Vertex_index v : vertices(mesh))
  {
    index[v] = int(a.points.size());
    const K::Point_3& p = mesh.point(v);
    a.points.emplace_back(p.x(), p.y(), p.z());
  }
  for(Mesh::Face_index f : faces(mesh))
  {
    std::vector<int> t;
    for(Mesh::Vertex_index v : vertices_around_face(halfedge(f, mesh), mesh))
      t.push_back(index[v]);
    BOOST_REQUIRE_EQUAL(t.size(), 3u);
    a.faces.push_back({{t[0], t[1], t[2]}});
  }
  return a;
}

double bbox_diagonal(const Arrays& a)
{
  Eigen::Vector3d lo = a.points[0], hi = a.points[0];
  for(const Eigen::Vector3d& p : a.points)
  {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return (hi - lo).norm();
}

// vertices on an edge with a single face
std::vector<bool> border_flags(const Arrays& a)
{
  SMPI::Triangle_adjacency adj(a.points.size(), a.faces);
  std::vector<bool> border(a.points.size(), false);
  for(std::size_t f = 0; f < a.faces.size(); ++f)
    for(int k = 0; k < 3; ++k)
      if(adj.neighbor(f, k) < 0)
      {
        border[std::size_t(a.faces[f][std::size_t((k + 1) % 3)])] = true;
        border[std::size_t(a.faces[f][std::size_t((k + 2) % 3)])] = true;
      }
  return border;
}

// border edges (a, b) as vertex pairs
std::vector<std::array<int, 2> > border_edges(const Arrays& a)
{
  SMPI::Triangle_adjacency adj(a.points.size(), a.faces);
  std::vector<std::array<int, 2> > edges;
  for(std::size_t f = 0; f < a.faces.size(); ++f)
    for(int k = 0; k < 3; ++k)
      if(adj.neighbor(f, k) < 0)
        edges.push_back({{a.faces[f][std::size_t((k + 1) % 3)], a.faces[f][std::size_t((k + 2) % 3)]}});
  return edges;
}

// ------------------------------------------------------------------ polyline checks

double point_segment_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  const Eigen::Vector3d ab = b - a;
  const double l2 = ab.squaredNorm();
  double t = l2 > 0. ? (p - a).dot(ab) / l2 : 0.;
  t = std::min(1., std::max(0., t));
  return (p - (a + t * ab)).norm();
}

double point_triangle_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                               const Eigen::Vector3d& b, const Eigen::Vector3d& c)
{
  double d = std::min({point_segment_distance(p, a, b), point_segment_distance(p, b, c),
                       point_segment_distance(p, c, a)});
  const Eigen::Vector3d n = (b - a).cross(c - a);
  const double nn = n.squaredNorm();
  if(nn > 0.)
  {
    const Eigen::Vector3d q = p - n * (n.dot(p - a) / nn);
    const double wa = n.dot((b - q).cross(c - q)), wb = n.dot((c - q).cross(a - q)),
                 wc = n.dot((a - q).cross(b - q));
    if(wa >= 0. && wb >= 0. && wc >= 0.)
      d = std::min(d, (p - q).norm());
  }
  return d;
}

// Face bounding boxes, for the "two consecutive points in one triangle" test.
struct Face_boxes
{
  std::vector<Eigen::Vector3d> lo, hi;
  explicit Face_boxes(const Arrays& a)
  {
    for(const Tri& f : a.faces)
    {
      const Eigen::Vector3d &p = a.points[std::size_t(f[0])], &q = a.points[std::size_t(f[1])],
                            &r = a.points[std::size_t(f[2])];
      lo.push_back(p.cwiseMin(q).cwiseMin(r));
      hi.push_back(p.cwiseMax(q).cwiseMax(r));
    }
  }
};

bool in_one_triangle(const Arrays& a, const Face_boxes& boxes, const Eigen::Vector3d& p,
                     const Eigen::Vector3d& q, double tol)
{
  const Eigen::Vector3d lo = p.cwiseMin(q), hi = p.cwiseMax(q);
  for(std::size_t f = 0; f < a.faces.size(); ++f)
  {
    if((boxes.lo[f].array() > hi.array() + tol).any() || (boxes.hi[f].array() < lo.array() - tol).any())
      continue;
    const Eigen::Vector3d &x = a.points[std::size_t(a.faces[f][0])], &y = a.points[std::size_t(a.faces[f][1])],
                          &z = a.points[std::size_t(a.faces[f][2])];
    if(point_triangle_distance(p, x, y, z) <= tol && point_triangle_distance(q, x, y, z) <= tol)
      return true;
  }
  return false;
}

// The cutting plane, computed independently of the tracer: unit normal of the plane through
// p_s, p_t and the area-weighted vertex normal at s.
Eigen::Vector3d cutting_plane_normal(const Arrays& a, int s, int t)
{
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  for(const Tri& f : a.faces)
    if(f[0] == s || f[1] == s || f[2] == s)
    {
      const Eigen::Vector3d& p = a.points[std::size_t(f[0])];
      n += (a.points[std::size_t(f[1])] - p).cross(a.points[std::size_t(f[2])] - p);
    }
  return n.cross(a.points[std::size_t(t)] - a.points[std::size_t(s)]).normalized();
}

// The properties of a successful trace: starts at the source, ends at the target, lies in the
// cutting plane, consecutive points in one triangle, length = polyline length >= |t - s|.
// Returns the number of violations (each reported).
int check_success(const Arrays& a, const Face_boxes& boxes, int s, int t, double length,
                  const std::vector<Eigen::Vector3d>& path, double diag)
{
  const double tol = 1e-9 * diag;
  int bad = 0;
  auto fail = [&](const std::string& what) {
    ++bad;
    BOOST_ERROR("trace " << s << " -> " << t << ": " << what);
  };
  if(path.empty())
  {
    fail("empty path");
    return bad;
  }
  const Eigen::Vector3d& ps = a.points[std::size_t(s)];
  const Eigen::Vector3d& pt = a.points[std::size_t(t)];
  if(path.front() != ps)
    fail("does not start at the source");
  if(path.back() != pt)
    fail("does not end at the target");
  if(!std::isfinite(length) || length < (pt - ps).norm() * (1. - 1e-12))
    fail("length " + std::to_string(length) + " shorter than the Euclidean distance");
  double sum = 0.;
  for(std::size_t i = 1; i < path.size(); ++i)
    sum += (path[i] - path[i - 1]).norm();
  if(!(std::abs(sum - length) <= 1e-12 * std::max(1., length)))
    fail("length differs from the polyline's");
  if(s != t)
  {
    const Eigen::Vector3d m = cutting_plane_normal(a, s, t);
    for(const Eigen::Vector3d& p : path)
      if(!(std::abs(m.dot(p - ps)) <= tol))
      {
        fail("a point is off the cutting plane");
        break;
      }
  }
  for(std::size_t i = 1; i < path.size(); ++i)
    if(!in_one_triangle(a, boxes, path[i - 1], path[i], tol))
    {
      fail("points " + std::to_string(i - 1) + " and " + std::to_string(i) + " in no common triangle");
      break;
    }
  return bad;
}

// Whether a failed trace's partial path shows the reported failure: REACHED_BORDER ends on a
// border edge, CLOSED_LOOP ends at a point it had visited before. Returns 0 or 1 (reported).
int check_failure(const Arrays& a, const std::vector<std::array<int, 2> >& border, int s, int t,
                  Tracer::Status status, const std::vector<Eigen::Vector3d>& path, double diag)
{
  if(path.empty() || path.front() != a.points[std::size_t(s)])
  {
    BOOST_ERROR("failed trace " << s << " -> " << t << ": the partial path does not start at the source");
    return 1;
  }
  if(status == Tracer::REACHED_BORDER)
  {
    double d = std::numeric_limits<double>::infinity();
    for(const auto& e : border)
      d = std::min(d, point_segment_distance(path.back(), a.points[std::size_t(e[0])], a.points[std::size_t(e[1])]));
    if(!(d <= 1e-9 * diag) || path.back() == a.points[std::size_t(t)])
    {
      BOOST_ERROR("trace " << s << " -> " << t << " reports the border, but ends at distance " << d << " from it");
      return 1;
    }
  }
  if(status == Tracer::CLOSED_LOOP &&
     std::find(path.begin(), path.end() - 1, path.back()) == path.end() - 1)
  {
    BOOST_ERROR("trace " << s << " -> " << t << " reports a loop, but its last point is new");
    return 1;
  }
  return 0;
}

// ------------------------------------------------------------------ generated surfaces

// A strip of near-equilateral triangles in the (u, z) plane: rows j = 0..rows, even rows with
// the vertices u = u0 + i du (i = 0..columns), odd rows shifted by du / 2 (columns vertices),
// row spacing du sqrt(3) / 2. Then mapped by `map(u, z)`. `row_start[j]` is the index of the
// first vertex of row j.
struct Strip
{
  Arrays mesh;
  std::vector<int> row_start;
  std::vector<double> u, z;  // parameters of every vertex
};

template <class Map>
Strip brick_strip(int columns, int rows, double u0, double du, const Map& map)
{
  Strip s;
  const double dz = du * std::sqrt(3.) / 2.;
  for(int j = 0; j <= rows; ++j)
  {
    s.row_start.push_back(int(s.mesh.points.size()));
    const bool shifted = (j % 2 == 1);
    const int count = shifted ? columns : columns + 1;
    for(int i = 0; i < count; ++i)
    {
      const double u = u0 + (i + (shifted ? 0.5 : 0.)) * du, z = j * dz;
      s.u.push_back(u);
      s.z.push_back(z);
      s.mesh.points.push_back(map(u, z));
    }
  }
  for(int j = 0; j < rows; ++j)
  {
    const int A = s.row_start[std::size_t(j)], B = s.row_start[std::size_t(j) + 1];
    if(j % 2 == 0)  // A: columns + 1 vertices, B (shifted): columns vertices
    {
      for(int i = 0; i < columns; ++i)
        s.mesh.faces.push_back({{A + i, A + i + 1, B + i}});
      for(int i = 0; i + 1 < columns; ++i)
        s.mesh.faces.push_back({{A + i + 1, B + i + 1, B + i}});
    }
    else  // A (shifted): columns vertices, B: columns + 1 vertices
    {
      for(int i = 0; i < columns; ++i)
        s.mesh.faces.push_back({{A + i, B + i + 1, B + i}});
      for(int i = 0; i + 1 < columns; ++i)
        s.mesh.faces.push_back({{A + i, A + i + 1, B + i + 1}});
    }
  }
  return s;
}

// A closed torus (R = 2, r = 0.7), n x m quads split along one diagonal.
Arrays closed_torus(int n, int m)
{
  Arrays a;
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < m; ++j)
    {
      const double u = 2. * CGAL_PI * i / n, v = 2. * CGAL_PI * j / m;
      a.points.emplace_back((2. + 0.7 * std::cos(v)) * std::cos(u), (2. + 0.7 * std::cos(v)) * std::sin(u),
                            0.7 * std::sin(v));
    }
  auto id = [&](int i, int j) { return ((i + n) % n) * m + (j + m) % m; };
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < m; ++j)
    {
      a.faces.push_back({{id(i, j), id(i + 1, j), id(i + 1, j + 1)}});
      a.faces.push_back({{id(i, j), id(i + 1, j + 1), id(i, j + 1)}});
    }
  return a;
}

// ------------------------------------------------------------------ flat visibility

double cross2(const Eigen::Vector3d& a, const Eigen::Vector3d& b) { return a.x() * b.y() - a.y() * b.x(); }

double segment_segment_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& q,
                                 const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  const double o1 = cross2(q - p, a - p), o2 = cross2(q - p, b - p);
  const double o3 = cross2(b - a, p - a), o4 = cross2(b - a, q - a);
  if(((o1 > 0. && o2 < 0.) || (o1 < 0. && o2 > 0.)) && ((o3 > 0. && o4 < 0.) || (o3 < 0. && o4 > 0.)))
    return 0.;
  return std::min({point_segment_distance(p, a, b), point_segment_distance(q, a, b),
                   point_segment_distance(a, p, q), point_segment_distance(b, p, q)});
}

// On a flat (z = 0) patch with one border: whether the segment from interior vertex s to
// vertex t lies in the patch with a margin (1), leaves it through a border edge (-1), or is
// too close to call (0).
int flat_visibility(const Arrays& a, const std::vector<std::array<int, 2> >& border, const std::vector<bool>& on_border,
                    int s, int t, double margin)
{
  const Eigen::Vector3d& ps = a.points[std::size_t(s)];
  const Eigen::Vector3d& pt = a.points[std::size_t(t)];
  const Eigen::Vector3d st = pt - ps;
  bool close = false;
  for(const auto& e : border)
  {
    const Eigen::Vector3d& pa = a.points[std::size_t(e[0])];
    const Eigen::Vector3d& pb = a.points[std::size_t(e[1])];
    const Eigen::Vector3d ab = pb - pa;
    // a transverse crossing with a margin on both segments: the segment leaves the patch
    const double o1 = cross2(ab, ps - pa), o2 = cross2(ab, pt - pa);
    const double o3 = cross2(st, pa - ps), o4 = cross2(st, pb - ps);
    const double m1 = margin * ab.norm(), m2 = margin * st.norm();
    if(((o1 > m1 && o2 < -m1) || (o1 < -m1 && o2 > m1)) && ((o3 > m2 && o4 < -m2) || (o3 < -m2 && o4 > m2)))
      return -1;
    if(e[0] == t || e[1] == t)
    {
      // the segment must arrive at a border target away from its border edges
      const Eigen::Vector3d other = a.points[std::size_t(e[0] == t ? e[1] : e[0])] - pt;
      if(std::abs(cross2(other, -st)) <= 1e-6 * other.norm() * st.norm())
        close = true;
      continue;
    }
    if(segment_segment_distance(ps, pt, pa, pb) <= margin)
      close = true;
  }
  if(close)
    return 0;
  if(on_border[std::size_t(t)])
  {
    // arriving at t from inside: s - t within the angle of a face at t
    const Eigen::Vector3d d = ps - pt;
    bool inside = false;
    for(const Tri& f : a.faces)
      for(int k = 0; k < 3; ++k)
        if(f[std::size_t(k)] == t)
        {
          const Eigen::Vector3d ea = a.points[std::size_t(f[std::size_t((k + 1) % 3)])] - pt;
          const Eigen::Vector3d eb = a.points[std::size_t(f[std::size_t((k + 2) % 3)])] - pt;
          const double orientation = cross2(ea, eb) > 0. ? 1. : -1.;
          if(orientation * cross2(ea, d) >= 0. && orientation * cross2(d, eb) >= 0.)
            inside = true;
        }
    return inside ? 1 : 0;
  }
  return 1;
}

// Exact visibility on l_shape(n), in grid units: the segment (i0, j0) -> (i1, j1) leaves the
// L iff it meets the open square (n, 2n)^2.
bool l_shape_hidden(long i0, long j0, long i1, long j1, long n)
{
  // t in [lo, hi] with open/closed ends, as fractions num/den (den > 0)
  struct Bound { long num, den; bool open; };
  Bound lo{0, 1, false}, hi{1, 1, false};
  auto less = [](long a, long b, long c, long d) { return a * d < c * b; };
  auto raise = [&](long num, long den) {  // t > num/den
    if(less(lo.num, lo.den, num, den)) lo = Bound{num, den, true};
    else if(!less(num, den, lo.num, lo.den)) lo.open = true;
  };
  auto lower = [&](long num, long den) {  // t < num/den
    if(less(num, den, hi.num, hi.den)) hi = Bound{num, den, true};
    else if(!less(hi.num, hi.den, num, den)) hi.open = true;
  };
  for(int axis = 0; axis < 2; ++axis)
  {
    const long x0 = axis == 0 ? i0 : j0, dx = axis == 0 ? i1 - i0 : j1 - j0;
    if(dx == 0)
    {
      if(!(n < x0 && x0 < 2 * n))
        return false;
    }
    else if(dx > 0)
    {
      raise(n - x0, dx);
      lower(2 * n - x0, dx);
    }
    else
    {
      raise(x0 - 2 * n, -dx);
      lower(x0 - n, -dx);
    }
  }
  if(less(lo.num, lo.den, hi.num, hi.den))
    return true;
  return !less(hi.num, hi.den, lo.num, lo.den) && !lo.open && !hi.open;
}

std::string status_histogram(const std::map<Tracer::Status, int>& h)
{
  std::ostringstream out;
  for(const auto& kv : h)
    out << " [" << Tracer::status_message(kv.first) << ": " << kv.second << "]";
  return out.str();
}

} // namespace

// ====================================================================== flat meshes

// On a flat convex patch every two vertices see each other: every trace succeeds and is the
// straight segment.
BOOST_AUTO_TEST_CASE(flat_convex_patches_give_straight_segments)
{
  struct Case { std::string name; mbp_test::Soup soup; };
  std::vector<Case> cases;
  cases.push_back({"hex_disk(6)", mbp_test::hex_disk(6)});
  cases.push_back({"hex_disk(5, 1.7, 0.6)", mbp_test::hex_disk(5, 1.7, 0.6)});
  cases.push_back({"polar_disk(4, 16)", mbp_test::polar_disk(4, 16)});
  // bumpy_disk's polar grid before its lift (bumpy_disk itself is curved: see below)
  cases.push_back({"polar_disk(5, 24, 1.3, 0.9)", mbp_test::polar_disk(5, 24, 1.3, 0.9)});
  for(const Case& c : cases)
  {
    const Arrays a = from_soup(c.soup);
    const Tracer tracer(a.points, a.faces);
    BOOST_REQUIRE(tracer.is_valid());
    const Face_boxes boxes(a);
    const double diag = bbox_diagonal(a);
    double worst = 0.;
    int traces = 0, bad = 0;
    std::vector<Eigen::Vector3d> path;
    for(int s = 0; s < int(a.points.size()); ++s)
      for(int t = 0; t < int(a.points.size()); ++t)
      {
        if(s == t)
          continue;
        double length = -1.;
        const bool ok = tracer.trace(s, t, length, &path);
        ++traces;
        if(!ok)
        {
          ++bad;
          if(bad < 5)
            BOOST_ERROR(c.name << ": trace " << s << " -> " << t << " failed");
          continue;
        }
        const double euclid = (a.points[std::size_t(t)] - a.points[std::size_t(s)]).norm();
        worst = std::max(worst, std::abs(length - euclid) / euclid);
        if((s * 7 + t) % 5 == 0)  // the (brute force) polyline check on a fifth of the pairs
          bad += check_success(a, boxes, s, t, length, path, diag);
      }
    BOOST_TEST_MESSAGE(c.name << ": " << traces << " traces, max |L - |t-s|| / |t-s| = " << worst);
    BOOST_TEST(bad == 0);
    BOOST_TEST(worst <= 1e-12);
  }
}

// The L-shape: the straightest path from s to t is the segment when it stays in the L, and
// the trace fails exactly when the segment passes the reentrant corner outside the L.
BOOST_AUTO_TEST_CASE(l_shape_hidden_targets_fail)
{
  const int n = 6;
  const Arrays a = from_soup(mbp_test::l_shape(n));
  const Tracer tracer(a.points, a.faces);
  BOOST_REQUIRE(tracer.is_valid());
  const Face_boxes boxes(a);
  const double diag = bbox_diagonal(a);
  const std::vector<std::array<int, 2> > border = border_edges(a);
  auto grid = [&](int v) {
    return std::array<long, 2>{{std::lround(a.points[std::size_t(v)].x() * n), std::lround(a.points[std::size_t(v)].y() * n)}};
  };
  int visible = 0, hidden = 0, wrong = 0;
  double worst = 0.;
  std::map<Tracer::Status, int> hidden_status;
  std::vector<Eigen::Vector3d> path;
  for(int s = 0; s < int(a.points.size()); ++s)
    for(int t = 0; t < int(a.points.size()); ++t)
    {
      if(s == t)
        continue;
      const auto gs = grid(s), gt = grid(t);
      const bool is_hidden = l_shape_hidden(gs[0], gs[1], gt[0], gt[1], n);
      double length = -1.;
      const Tracer::Status status = tracer.trace_with_status(s, t, length, &path);
      if(is_hidden)
      {
        ++hidden;
        ++hidden_status[status];
        if(status == Tracer::REACHED_TARGET || length != -1.)
          ++wrong;
        else
          wrong += check_failure(a, border, s, t, status, path, diag);
        continue;
      }
      ++visible;
      if(status != Tracer::REACHED_TARGET)
      {
        if(++wrong < 5)
          BOOST_ERROR("visible pair " << s << " -> " << t << " failed: " << Tracer::status_message(status));
        continue;
      }
      const double euclid = (a.points[std::size_t(t)] - a.points[std::size_t(s)]).norm();
      worst = std::max(worst, std::abs(length - euclid) / euclid);
      if((s + t) % 7 == 0)
        wrong += check_success(a, boxes, s, t, length, path, diag);
    }
  BOOST_TEST_MESSAGE("l_shape(" << n << "): " << visible << " visible pairs (max rel. error " << worst << "), "
                                << hidden << " hidden pairs, failures:" << status_histogram(hidden_status));
  BOOST_TEST(wrong == 0);
  BOOST_TEST(worst <= 1e-12);
  BOOST_TEST(hidden > 1000);

  // one named case: from the upper arm, behind the corner, into the right arm
  auto vertex_at = [&](double x, double y) {
    for(int v = 0; v < int(a.points.size()); ++v)
      if(std::abs(a.points[std::size_t(v)].x() - x) < 1e-12 && std::abs(a.points[std::size_t(v)].y() - y) < 1e-12)
        return v;
    BOOST_FAIL("no vertex at " << x << ", " << y);
    return -1;
  };
  const int s = vertex_at(1. / 3., 5. / 3.), t = vertex_at(5. / 3., 2. / 3.);
  double length = 42.;
  BOOST_TEST(tracer.trace_with_status(s, t, length, &path) == Tracer::REACHED_BORDER);
  BOOST_TEST(length == 42.);  // untouched
  // the partial path runs along the segment and stops on the border x = 1, above the corner
  BOOST_REQUIRE(path.size() >= 2);
  BOOST_TEST(std::abs(path.back().x() - 1.) < 1e-12);
  BOOST_TEST(path.back().y() > 1.);
  // seen the other way round: from the corner's own border, a start direction out of the L
  const int corner = vertex_at(2., 1.), above = vertex_at(1., 2.);
  BOOST_TEST(tracer.trace_with_status(corner, above, length) == Tracer::NO_START_DIRECTION);
  // but through the reentrant corner itself, the segment is inside: reached
  const int p = vertex_at(1. / 3., 5. / 3.), q = vertex_at(5. / 3., 1. / 3.);
  BOOST_TEST(tracer.trace(p, q, length, &path));
  BOOST_TEST(std::abs(length - (a.points[std::size_t(q)] - a.points[std::size_t(p)]).norm()) < 1e-12);
}

// Real flat meshes: every trace whose segment stays inside the patch (with a margin) succeeds
// with the Euclidean length; every trace whose segment crosses the border fails; and any
// success is the straight segment.
BOOST_AUTO_TEST_CASE(flat_real_meshes, MBP_EXTENDED_TIER)
{
  // bump-domain is (nearly) convex: no segment leaves it; woody-hi is far from convex
  const std::vector<std::pair<std::string, int> > meshes{{"bump-domain.obj", 0}, {"woody-hi.off", 1000}};
  for(const auto& mesh : meshes)
  {
    const std::string& name = mesh.first;
    const Arrays a = read_arrays(mbp_test::Tier::extended, name);
    for(const Eigen::Vector3d& p : a.points)
      BOOST_REQUIRE(p.z() == 0.);
    const Tracer tracer(a.points, a.faces);
    BOOST_REQUIRE(tracer.is_valid());
    const Face_boxes boxes(a);
    const double diag = bbox_diagonal(a);
    const std::vector<bool> on_border = border_flags(a);
    const std::vector<std::array<int, 2> > border = border_edges(a);

    std::vector<int> sources;
    for(int v = 0; v < int(a.points.size()) && sources.size() < 10; v += int(a.points.size()) / 10 + 1)
    {
      int w = v;
      while(w < int(a.points.size()) && on_border[std::size_t(w)])
        ++w;
      if(w < int(a.points.size()))
        sources.push_back(w);
    }
    int visible = 0, reached_visible = 0, hidden = 0, failed_hidden = 0, unclear = 0, reached_unclear = 0,
        bad = 0, border_targets = 0, border_reached = 0, checked = 0;
    double worst = 0.;
    std::vector<Eigen::Vector3d> path;
    for(int s : sources)
      for(int t = 0; t < int(a.points.size()); ++t)
      {
        if(t == s)
          continue;
        const int visibility = flat_visibility(a, border, on_border, s, t, 1e-7 * diag);
        double length = -1.;
        const bool ok = tracer.trace(s, t, length, &path);
        if(on_border[std::size_t(t)])
        {
          ++border_targets;
          border_reached += ok;
        }
        if(ok)
        {
          const double euclid = (a.points[std::size_t(t)] - a.points[std::size_t(s)]).norm();
          worst = std::max(worst, std::abs(length - euclid) / euclid);
          if(++checked % 97 == 0)
            bad += check_success(a, boxes, s, t, length, path, diag);
        }
        else
          bad += (length != -1.) + check_failure(a, border, s, t, tracer.trace_with_status(s, t, length, &path), path, diag);
        if(visibility == 1)
        {
          ++visible;
          reached_visible += ok;
          if(!ok && bad++ < 5)
            BOOST_ERROR(name << ": visible pair " << s << " -> " << t << " not reached");
        }
        else if(visibility == -1)
        {
          ++hidden;
          failed_hidden += !ok;
          if(ok && bad++ < 5)
            BOOST_ERROR(name << ": hidden pair " << s << " -> " << t << " reached");
        }
        else
        {
          ++unclear;
          reached_unclear += ok;
        }
      }
    BOOST_TEST_MESSAGE(name << ": " << sources.size() << " sources; visible pairs reached " << reached_visible
                            << "/" << visible << ", hidden pairs failed " << failed_hidden << "/" << hidden
                            << ", too close to call reached " << reached_unclear << "/" << unclear
                            << "; border targets reached " << border_reached << "/" << border_targets
                            << "; max |L - |t-s|| / |t-s| = " << worst);
    BOOST_TEST(bad == 0);
    BOOST_TEST(reached_visible == visible);
    BOOST_TEST(failed_hidden == hidden);
    BOOST_TEST(visible > 1000);
    BOOST_TEST(hidden >= mesh.second);
    BOOST_TEST(worst <= 1e-9);
  }
}

// ====================================================================== curved meshes

// A cylinder of radius 1: rulings (u fixed) and circles (z fixed) are geodesics and are the
// sections by the normal planes. The polyhedral path differs from them by O(du^2).
BOOST_AUTO_TEST_CASE(cylinder_rulings_and_circles)
{
  const double R = 1.;
  auto cylinder = [R](double u, double z) { return Eigen::Vector3d(R * std::cos(u / R), R * std::sin(u / R), z); };
  double previous_ruling = 1., previous_circle = 1.;
  for(int columns : {8, 16, 32, 64})
  {
    const double du = 2. / columns;  // u in [-1, 1]: 2 radians of the circle
    const int rows = 2 * int(std::lround(0.6 / (du * std::sqrt(3.) / 2.)));  // height ~1.2
    const Strip strip = brick_strip(columns, rows, -1., du, cylinder);
    const Arrays& a = strip.mesh;
    const Tracer tracer(a.points, a.faces);
    BOOST_REQUIRE(tracer.is_valid());
    const Face_boxes boxes(a);
    const double diag = bbox_diagonal(a);
    double ruling_error = 0., circle_error = 0.;
    int traces = 0, bad = 0;
    std::vector<Eigen::Vector3d> path;
    auto check = [&](int s, int t, double exact, double& error) {
      double length = -1.;
      const Tracer::Status status = tracer.trace_with_status(s, t, length, &path);
      ++traces;
      if(status != Tracer::REACHED_TARGET)
      {
        if(++bad < 5)
          BOOST_ERROR("cylinder " << columns << ": " << s << " -> " << t << ": " << Tracer::status_message(status));
        return;
      }
      error = std::max(error, std::abs(length - exact) / exact);
      if(traces % 11 == 0)
        bad += check_success(a, boxes, s, t, length, path, diag);
    };
    // rulings: unshifted rows (even), the same column, up and down; not the first and last
    // columns, whose rulings leave the patch (the odd rows start and end half a step inside)
    for(int i : {1, columns / 4, columns / 2, columns - 1})
      for(int j0 = 0; j0 <= rows; j0 += 2)
        for(int j1 = 0; j1 <= rows; j1 += 2)
          if(j0 != j1)
          {
            const int s = strip.row_start[std::size_t(j0)] + i, t = strip.row_start[std::size_t(j1)] + i;
            check(s, t, std::abs(strip.z[std::size_t(t)] - strip.z[std::size_t(s)]), ruling_error);
          }
    // circles: interior rows, from every vertex but the row's two ends to every vertex of the
    // row. (At a border vertex the area-weighted normal tilts in z, the normal plane is not
    // horizontal, and its section is not the circle.)
    for(int j : {1, 2, rows / 2, rows - 1})
    {
      const int first = strip.row_start[std::size_t(j)];
      const int last = strip.row_start[std::size_t(j) + 1];
      for(int s = first + 1; s + 1 < last; ++s)
        for(int t = first; t < last; ++t)
          if(s != t)
            check(s, t, std::abs(strip.u[std::size_t(t)] - strip.u[std::size_t(s)]), circle_error);
    }
    BOOST_TEST_MESSAGE("cylinder, du = " << du << " (" << a.faces.size() << " faces, " << traces
                                         << " traces): max rel. error rulings " << ruling_error << " (du^2/96 = "
                                         << du * du / 96 << "), circles " << circle_error
                                         << " (du^2/24 = " << du * du / 24 << ")");
    BOOST_TEST(bad == 0);
    // stated tolerances: chord of an arc of angle du (circles), du^2/96 (rulings)
    BOOST_TEST(circle_error <= du * du / 20.);
    BOOST_TEST(ruling_error <= du * du / 80.);
    BOOST_TEST(circle_error <= previous_circle / 3.);
    BOOST_TEST(ruling_error <= previous_ruling / 3.);
    previous_circle = circle_error;
    previous_ruling = ruling_error;
  }
}

// A spherical cap (radius 1, angular radius 1): the normal section through two points is, up to
// the discrete normal's error, the great circle. Its length converges to the arc length.
BOOST_AUTO_TEST_CASE(sphere_cap_great_circles)
{
  double previous = 1.;
  for(int rings : {6, 12, 24, 48})
  {
    mbp_test::Soup soup = mbp_test::hex_disk(rings);
    std::vector<double> rho;
    for(auto& p : soup.points)
    {
      const double r = std::hypot(p[0], p[1]), phi = std::atan2(p[1], p[0]);
      rho.push_back(r);
      const double theta = 1. * r;
      p = {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
    }
    const Arrays a = from_soup(soup);
    const Tracer tracer(a.points, a.faces);
    BOOST_REQUIRE(tracer.is_valid());
    const Face_boxes boxes(a);
    const double diag = bbox_diagonal(a);
    // sources: the pole and three vertices off the pole; targets: every vertex with rho <= 0.9
    std::vector<int> sources{0};
    for(const auto& xy : std::vector<std::array<double, 2> >{{{0.3, 0.2}}, {{-0.45, 0.1}}, {{0.05, -0.6}}})
    {
      const double r = std::hypot(xy[0], xy[1]);
      const Eigen::Vector3d wanted(std::sin(r) * xy[0] / r, std::sin(r) * xy[1] / r, std::cos(r));
      int best = 0;
      for(int v = 0; v < int(a.points.size()); ++v)
        if((a.points[std::size_t(v)] - wanted).norm() < (a.points[std::size_t(best)] - wanted).norm())
          best = v;
      sources.push_back(best);
    }
    double worst = 0., sum = 0.;
    int traces = 0, bad = 0;
    std::map<Tracer::Status, int> status_count;
    std::vector<Eigen::Vector3d> path;
    for(int s : sources)
      for(int t = 0; t < int(a.points.size()); ++t)
      {
        if(t == s || rho[std::size_t(t)] > 0.9 + 1e-9)
          continue;
        double length = -1.;
        const Tracer::Status status = tracer.trace_with_status(s, t, length, &path);
        ++status_count[status];
        ++traces;
        if(status != Tracer::REACHED_TARGET)
          continue;
        const double arc = std::acos(std::min(1., a.points[std::size_t(s)].dot(a.points[std::size_t(t)])));
        const double error = std::abs(length - arc) / arc;
        worst = std::max(worst, error);
        sum += error;
        if(traces % 13 == 0)
          bad += check_success(a, boxes, s, t, length, path, diag);
      }
    const double h = 1. / rings;
    BOOST_TEST_MESSAGE("sphere cap, rings = " << rings << " (" << a.faces.size() << " faces, " << traces
                                              << " traces): max rel. error " << worst << ", mean "
                                              << sum / traces << ", max / h^2 = " << worst / (h * h)
                                              << ";" << status_histogram(status_count));
    BOOST_TEST(bad == 0);
    BOOST_TEST(status_count[Tracer::REACHED_TARGET] == traces);  // a cap smaller than a hemisphere
    BOOST_TEST(worst <= 0.25 * h * h);                          // stated tolerance
    BOOST_TEST(worst <= previous / 3.);
    previous = worst;
  }
}

// A curved, asymmetric patch: every successful trace has the polyline's properties and is no
// shorter than the chord; every failure leaves the length alone.
BOOST_AUTO_TEST_CASE(bumpy_disk_properties)
{
  const Arrays a = from_soup(mbp_test::bumpy_disk());
  const Tracer tracer(a.points, a.faces);
  BOOST_REQUIRE(tracer.is_valid());
  const Face_boxes boxes(a);
  const double diag = bbox_diagonal(a);
  std::map<Tracer::Status, int> status_count;
  int bad = 0;
  double max_ratio = 0.;
  std::vector<Eigen::Vector3d> path;
  for(int s = 0; s < int(a.points.size()); s += 3)
    for(int t = 0; t < int(a.points.size()); ++t)
    {
      double length = -1.;
      const Tracer::Status status = tracer.trace_with_status(s, t, length, &path);
      ++status_count[status];
      if(status == Tracer::REACHED_TARGET)
      {
        if(s == t)
          BOOST_TEST(length == 0.);
        else
          max_ratio = std::max(max_ratio, length / (a.points[std::size_t(t)] - a.points[std::size_t(s)]).norm());
        if((s + 3 * t) % 4 == 0)
          bad += check_success(a, boxes, s, t, length, path, diag);
      }
      else if(length != -1.)
        ++bad;
    }
  BOOST_TEST_MESSAGE("bumpy_disk: max length / chord " << max_ratio << ";" << status_histogram(status_count));
  BOOST_TEST(bad == 0);
  BOOST_TEST(status_count[Tracer::REACHED_TARGET] > 0);
}

// Real curved meshes: from the interior vertex nearest the centroid to every border vertex.
// The paper reports that MBPSGP fails on most models: count how often the border is reached.
MBP_TIERED_TEST_CASE(real_curved_meshes_border_reach)
{
  const std::vector<std::string> names = (tier == mbp_test::Tier::core)
    ? std::vector<std::string>{"nefertiti.off", "mushroom.off", "patch-01.off", "lion-head.off"}
    : std::vector<std::string>{"matthew_nefertiti.off", "lilium.obj", "venus.off", "spothead.obj", "maxFace.obj",
                               "bimba_hole.off"};
  for(const std::string& name : names)
  {
    const Arrays a = read_arrays(tier, name);
    const Tracer tracer(a.points, a.faces);
    BOOST_REQUIRE(tracer.is_valid());
    const Face_boxes boxes(a);
    const double diag = bbox_diagonal(a);
    const std::vector<bool> on_border = border_flags(a);
    const std::vector<std::array<int, 2> > border = border_edges(a);
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for(const Eigen::Vector3d& p : a.points)
      centroid += p;
    centroid /= double(a.points.size());
    int center = -1;
    for(int v = 0; v < int(a.points.size()); ++v)
      if(!on_border[std::size_t(v)] && tracer.adjacency().corners_begin(std::size_t(v)) != tracer.adjacency().corners_end(std::size_t(v)) &&
         (center < 0 || (a.points[std::size_t(v)] - centroid).norm() < (a.points[std::size_t(center)] - centroid).norm()))
        center = v;
    BOOST_REQUIRE(center >= 0);

    std::map<Tracer::Status, int> status_count;
    int targets = 0, bad = 0;
    double min_ratio = std::numeric_limits<double>::infinity(), max_ratio = 0.;
    std::vector<Eigen::Vector3d> path;
    for(int t = 0; t < int(a.points.size()); ++t)
    {
      if(!on_border[std::size_t(t)])
        continue;
      ++targets;
      double length = -1.;
      const Tracer::Status status = tracer.trace_with_status(center, t, length, &path);
      ++status_count[status];
      if(status == Tracer::REACHED_TARGET)
      {
        const double ratio = length / (a.points[std::size_t(t)] - a.points[std::size_t(center)]).norm();
        min_ratio = std::min(min_ratio, ratio);
        max_ratio = std::max(max_ratio, ratio);
        bad += check_success(a, boxes, center, t, length, path, diag);
      }
      else  // a failure leaves the length alone and gives the partial path, which shows the failure
        bad += (length != -1.) + check_failure(a, border, center, t, status, path, diag);
    }
    const int reached = status_count[Tracer::REACHED_TARGET];
    BOOST_TEST_MESSAGE(name << ": from vertex " << center << ", reached " << reached << "/" << targets
                            << " border vertices (length / chord in [" << min_ratio << ", " << max_ratio
                            << "]);" << status_histogram(status_count));
    BOOST_TEST(bad == 0);
    BOOST_TEST(min_ratio >= 1. - 1e-12);
  }
}

// ====================================================================== special cases

BOOST_AUTO_TEST_CASE(source_is_target_and_invalid_indices)
{
  const Arrays a = from_soup(mbp_test::hex_disk(3));
  const Tracer tracer(a.points, a.faces);
  BOOST_REQUIRE(tracer.is_valid());
  std::vector<Eigen::Vector3d> path{Eigen::Vector3d(9, 9, 9)};
  double length = -1.;
  BOOST_TEST(tracer.trace(5, 5, length, &path));
  BOOST_TEST(length == 0.);
  BOOST_REQUIRE(path.size() == 1u);
  BOOST_TEST(path[0] == a.points[5]);

  const int n = int(a.points.size());
  for(const std::array<int, 2>& st : std::vector<std::array<int, 2> >{
        {{-1, 0}}, {{0, -1}}, {{n, 0}}, {{0, n}}, {{std::numeric_limits<int>::max(), 1}}, {{std::numeric_limits<int>::min(), 1}}})
  {
    length = -1.;
    BOOST_TEST(!tracer.trace(st[0], st[1], length, &path));
    BOOST_TEST(tracer.trace_with_status(st[0], st[1], length) == Tracer::INVALID_INPUT);
    BOOST_TEST(length == -1.);
    BOOST_TEST(path.empty());
  }
  // a neighbour: one segment
  int neighbour = -1;
  for(const Tri& f : a.faces)
    for(int k = 0; k < 3; ++k)
      if(f[std::size_t(k)] == 0)
        neighbour = f[std::size_t((k + 1) % 3)];
  BOOST_REQUIRE(neighbour > 0);
  BOOST_TEST(tracer.trace(0, neighbour, length, &path));
  BOOST_TEST(path.size() == 2u);
  BOOST_TEST(std::abs(length - a.points[std::size_t(neighbour)].norm()) < 1e-15);
}

BOOST_AUTO_TEST_CASE(invalid_meshes)
{
  std::vector<Eigen::Vector3d> points{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  double length = -1.;
  {
    const std::vector<Tri> none;
    const Tracer tracer(points, none);
    BOOST_TEST(!tracer.is_valid());
    BOOST_TEST(tracer.trace_with_status(0, 1, length) == Tracer::INVALID_INPUT);
  }
  for(const Tri& bad : std::vector<Tri>{{{0, 1, 4}}, {{-1, 1, 2}}, {{0, 1, 1}}, {{2, 2, 2}}})
  {
    const std::vector<Tri> faces{{{0, 1, 2}}, bad};
    const Tracer tracer(points, faces);
    BOOST_TEST(!tracer.is_valid());
    BOOST_TEST(!tracer.trace(0, 2, length));
  }
  {
    std::vector<Eigen::Vector3d> nan_points = points;
    nan_points[3] = Eigen::Vector3d(std::numeric_limits<double>::quiet_NaN(), 0, 0);
    const std::vector<Tri> faces{{{0, 1, 2}}, {{1, 3, 2}}};
    const Tracer tracer(nan_points, faces);
    BOOST_TEST(!tracer.is_valid());
    BOOST_TEST(!tracer.trace(0, 2, length));
    nan_points[3] = Eigen::Vector3d(std::numeric_limits<double>::infinity(), 0, 0);
    const Tracer tracer2(nan_points, faces);
    BOOST_TEST(!tracer2.is_valid());
  }
  {
    // all points at one place
    const std::vector<Eigen::Vector3d> same(3, Eigen::Vector3d(1, 2, 3));
    const std::vector<Tri> faces{{{0, 1, 2}}};
    const Tracer tracer(same, faces);
    BOOST_TEST(!tracer.is_valid());
  }
  {
    // a vertex used by no face (3), and a target straight along the source's normal (4)
    std::vector<Eigen::Vector3d> p{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 5, 5}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}};
    const std::vector<Tri> faces{{{0, 1, 2}}, {{4, 5, 6}}};
    const Tracer tracer(p, faces);
    BOOST_REQUIRE(tracer.is_valid());
    BOOST_TEST(tracer.trace_with_status(0, 3, length) == Tracer::INVALID_INPUT);
    BOOST_TEST(tracer.trace_with_status(3, 0, length) == Tracer::INVALID_INPUT);
    BOOST_TEST(tracer.trace_with_status(0, 4, length) == Tracer::UNDEFINED_PLANE);
    BOOST_TEST(length == -1.);
    // another component: never reached
    BOOST_TEST(!tracer.trace(0, 5, length));
    BOOST_TEST(tracer.trace(0, 1, length));
    BOOST_TEST(length == 1.);
  }
}

// Plane sections of a closed torus through two points on different meridians: the traced
// meridian closes on itself.
BOOST_AUTO_TEST_CASE(closed_loop_is_detected)
{
  const int n = 12, m = 8;
  const Arrays a = closed_torus(n, m);
  const Tracer tracer(a.points, a.faces);
  BOOST_REQUIRE(tracer.is_valid());
  const int s = 0;                        // u = 0, v = 0 (outer equator)
  const int t = (n / 2) * m + m / 4;      // u = pi, v = pi / 2 (top)
  double length = -1.;
  std::vector<Eigen::Vector3d> path;
  const Tracer::Status status = tracer.trace_with_status(s, t, length, &path);
  BOOST_TEST_MESSAGE("torus " << s << " -> " << t << ": " << Tracer::status_message(status) << " after "
                              << path.size() << " points");
  BOOST_TEST(status == Tracer::CLOSED_LOOP);
  BOOST_TEST(length == -1.);
  BOOST_TEST(path.size() > std::size_t(m / 2));
  BOOST_TEST(check_failure(a, {}, s, t, status, path, 1.) == 0);

  // every pair on the closed torus terminates; successes are valid
  const Face_boxes boxes(a);
  const double diag = bbox_diagonal(a);
  std::map<Tracer::Status, int> status_count;
  int bad = 0;
  for(int p = 0; p < int(a.points.size()); ++p)
    for(int q = 0; q < int(a.points.size()); ++q)
    {
      length = -1.;
      const Tracer::Status st = tracer.trace_with_status(p, q, length, &path);
      ++status_count[st];
      if(st == Tracer::REACHED_TARGET)
      {
        if((p + q) % 5 == 0)
          bad += check_success(a, boxes, p, q, length, path, diag);
      }
      else
        bad += (length != -1.) + check_failure(a, {}, p, q, st, path, diag);
    }
  BOOST_TEST_MESSAGE("closed torus, all pairs:" << status_histogram(status_count));
  BOOST_TEST(bad == 0);
  BOOST_TEST(status_count[Tracer::CLOSED_LOOP] > 0);
  BOOST_TEST(status_count[Tracer::STEP_LIMIT] == 0);
}

// Noisy, folded and degenerate meshes: every trace terminates; no NaN; successes are valid.
BOOST_AUTO_TEST_CASE(robust_on_noisy_and_degenerate_meshes)
{
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> uniform(-1., 1.);
  for(int variant = 0; variant < 4; ++variant)
  {
    mbp_test::Soup soup = mbp_test::hex_disk(7);
    const double h = 1. / 7.;
    for(std::size_t v = 1; v < soup.points.size(); ++v)
    {
      soup.points[v][0] += (variant >= 1 ? 0.3 : 0.) * h * uniform(rng);
      soup.points[v][1] += (variant >= 1 ? 0.3 : 0.) * h * uniform(rng);
      soup.points[v][2] += (variant == 0 ? 0.05 : variant == 1 ? 0.3 : 1.5) * h * uniform(rng);
    }
    if(variant == 3)
    {
      // zero-area faces: some vertices moved onto a neighbour or onto the middle of an edge
      for(std::size_t f = 0; f < soup.faces.size(); f += 9)
      {
        const auto& t = soup.faces[f];
        if(f % 2 == 0)
          soup.points[t[0]] = soup.points[t[1]];
        else
          for(int k = 0; k < 3; ++k)
            soup.points[t[2]][std::size_t(k)] = 0.5 * (soup.points[t[0]][std::size_t(k)] + soup.points[t[1]][std::size_t(k)]);
      }
    }
    const Arrays a = from_soup(soup);
    const Tracer tracer(a.points, a.faces);
    BOOST_REQUIRE(tracer.is_valid());
    const Face_boxes boxes(a);
    const double diag = bbox_diagonal(a);
    const std::vector<std::array<int, 2> > border = border_edges(a);
    std::map<Tracer::Status, int> status_count;
    int bad = 0;
    std::vector<Eigen::Vector3d> path;
    const auto start = std::chrono::steady_clock::now();
    for(int s = 0; s < int(a.points.size()); ++s)
      for(int t = 0; t < int(a.points.size()); t += 2)
      {
        double length = -1.;
        const Tracer::Status st = tracer.trace_with_status(s, t, length, &path);
        ++status_count[st];
        for(const Eigen::Vector3d& p : path)
          if(!p.allFinite())
            ++bad;
        if(st == Tracer::REACHED_TARGET)
        {
          if(variant < 3 && (s + t) % 11 == 0)
            bad += check_success(a, boxes, s, t, length, path, diag);
          else if(!std::isfinite(length) ||
                  length < (a.points[std::size_t(t)] - a.points[std::size_t(s)]).norm() * (1. - 1e-12))
            ++bad;
        }
        else
          bad += (length != -1.) + check_failure(a, border, s, t, st, path, diag);
      }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    BOOST_TEST_MESSAGE("noisy hex_disk(7), variant " << variant << " (" << seconds << " s):"
                                                     << status_histogram(status_count));
    BOOST_TEST(bad == 0);
    BOOST_TEST(status_count[Tracer::STEP_LIMIT] == 0);
  }

  // a flipped face (inconsistent orientation: its edges count as border) and a non-manifold
  // edge shared by three faces
  Arrays a = from_soup(mbp_test::hex_disk(4));
  std::swap(a.faces[7][0], a.faces[7][1]);
  const int extra = int(a.points.size());
  a.points.emplace_back(0.1, 0.1, 1.);
  a.faces.push_back({{a.faces[20][0], a.faces[20][1], extra}});
  const Tracer tracer(a.points, a.faces);
  BOOST_REQUIRE(tracer.is_valid());
  int successes = 0;
  for(int s = 0; s < int(a.points.size()); ++s)
    for(int t = 0; t < int(a.points.size()); ++t)
    {
      double length = -1.;
      if(tracer.trace(s, t, length))
      {
        ++successes;
        BOOST_TEST(std::isfinite(length));
        BOOST_TEST(length >= (a.points[std::size_t(t)] - a.points[std::size_t(s)]).norm() * (1. - 1e-12));
      }
      else
        BOOST_TEST(length == -1.);
    }
  BOOST_TEST(successes > 0);
}

BOOST_AUTO_TEST_SUITE_END()
