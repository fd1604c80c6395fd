// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DISTANCES_FAST_MARCHING_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DISTANCES_FAST_MARCHING_H

// Fast marching geodesic distances on a triangulated surface: Kimmel & Sethian, "Computing
// geodesic paths on manifolds", PNAS 95 (1998). The paper's GDM (user manual: The method in a page)
// and the multi-source BGDM of step 1.
//
// The algorithm solves the eikonal equation |grad T| = 1 with T = 0 at the sources, in the
// order of increasing T, like Dijkstra's algorithm:
//
//  - every vertex is *far* (T = +infinity), *trial* (a tentative value in a binary heap) or
//    *accepted* (final). The sources are trial with T = 0.
//  - the trial vertex of smallest T is accepted; for every face (A, B, C) around it, the
//    value of each not yet accepted vertex C is updated from the accepted vertices of the face.
//
// The update of C from one face is first order and upwind. With A and B accepted, T is the
// linear function over the (planar) triangle with |grad T| = 1 and the values T(A), T(B): a
// plane wave crossing the edge AB. It is used only when
//  - it is *causal*: the direction the wave arrives from, -grad T, lies inside the angle of the
//    triangle at C (the characteristic through C crosses the edge AB), and
//  - it is *monotone*: T(C) >= max(T(A), T(B)), so the accepted values never decrease;
// otherwise the update is the edge-based (Dijkstra) one, min(T(A) + |AC|, T(B) + |BC|).
//
// Obtuse triangles. When the angle at C is obtuse, the plane waves that cross the edge AB
// causally miss most of the directions a wave can arrive from, and the edge updates that
// replace them make errors of the order of the distance (not of the edge length). Kimmel and
// Sethian split the obtuse angle: the triangles across the edge AB (opposite C) are unfolded
// one after the other into the plane of ABC (isometrically, from their 3D edge lengths), until
// the unfolded position D' of a vertex D lies in the *acute section* of C: the directions that
// make an angle of at most 90 degrees with both CA and CB. The virtual edge CD' splits ABC into
// the two triangles (C, A, D') and (C, D', B), both non-obtuse at C, which are used for the
// update instead of ABC, with the values T(A), T(B), T(D). The strip of unfolded triangles
// follows the section: when D' falls before it (on A's side), the next triangle is the one
// across the edge D'B, otherwise the one across AD'. The number of unfolding steps is bounded
// (`max_unfolding_steps`); the unfolding stops without a split at the border, at the bound, or
// when the strip wraps around C.
//
// The unfolding depends on the geometry only: it is done once, in the constructor, for every
// obtuse corner. Since D is not a neighbour of C, every split vertex keeps the list of corners
// it splits, and their vertices are updated again when it is accepted. Until D is accepted,
// and at the obtuse corners without a split, the update is the plane wave of ABC with the
// causality and monotonicity tests, then the edge updates.
//
// Properties: the accepted values never decrease (every update is monotone), the result is
// never larger than the Dijkstra edge-path distance (every edge update is performed), and on a
// flat mesh with one source it is never smaller than the Euclidean distance (the distance to a
// point is convex: a causal plane wave through upper bounds at A and B is an upper bound at C).
// With several sources it can be slightly smaller near the lines where fronts meet. The error
// is first order: a fraction of the edge length, made mostly in the first rings around a point
// source. Vertices of components without a source get +infinity. O(n log n): a binary heap
// with lazy deletion (stale entries are skipped when popped), a bounded amount of work per
// update, no allocation per vertex.

#include <CGAL/Surface_mesh_parameterization/internal/core/triangle_adjacency.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

class Fast_marching
{
public:
  typedef std::array<int, 3> Face;

  /// Counters of one `compute()` call, for tests and diagnostics.
  struct Statistics
  {
    std::size_t accepted = 0;          // vertices accepted (reached)
    std::size_t face_updates = 0;      // updates of a vertex from one face
    std::size_t obtuse_updates = 0;    // of which at an obtuse corner
    std::size_t split_updates = 0;     // of which used the split of the corner (unfolded vertex accepted)
  };

  /// Default bound on the number of triangles unfolded to split one obtuse angle.
  static constexpr int default_max_unfolding_steps() { return 10; }

  /// `points`: vertex positions; `faces`: consistently oriented triangles with indices in
  /// [0, points.size()) forming a manifold patch (borders and several components allowed).
  /// Both are kept by reference: they must outlive this object and stay unchanged.
  /// `max_unfolding_steps` bounds the unfolding of obtuse angles (0 disables it: obtuse
  /// triangles then use only the plane wave with its causality test and the edge updates).
  /// The unfolding depends on the geometry only: it is done here, once, for every obtuse corner.
  Fast_marching(const std::vector<Eigen::Vector3d>& points, const std::vector<Face>& faces,
                int max_unfolding_steps = default_max_unfolding_steps())
    : m_points(points), m_faces(faces), m_adjacency(points.size(), faces),
      m_max_unfolding_steps(max_unfolding_steps < 0 ? 0 : max_unfolding_steps)
  {
    split_obtuse_corners();
  }

  // the inputs are kept by reference: refuse temporaries
  Fast_marching(std::vector<Eigen::Vector3d>&&, const std::vector<Face>&, int = 0) = delete;
  Fast_marching(const std::vector<Eigen::Vector3d>&, std::vector<Face>&&, int = 0) = delete;
  Fast_marching(std::vector<Eigen::Vector3d>&&, std::vector<Face>&&, int = 0) = delete;

  const Triangle_adjacency& adjacency() const { return m_adjacency; }
  /// number of corners with an angle above 90 degrees
  std::size_t number_of_obtuse_corners() const { return m_obtuse_corners; }
  /// number of obtuse corners split by an unfolded vertex (the others use the fallback)
  std::size_t number_of_split_corners() const { return m_splits.size(); }

  /// `distances[i]` = fast marching distance from the nearest source (0 at the sources),
  /// +infinity where no source is reachable. Source indices outside [0, points.size()) are
  /// ignored. Never produces NaN (a non-finite candidate value is discarded). `compute()`
  /// does not modify the object: concurrent calls are safe.
  void compute(const std::vector<int>& sources, std::vector<double>& distances,
               Statistics* statistics = nullptr) const
  {
    const std::size_t n = m_points.size();
    distances.assign(n, infinity());
    std::vector<unsigned char> accepted(n, 0);
    Statistics stats;
    Heap heap;
    heap.reserve(n + sources.size());
    for(int s : sources)
      if(s >= 0 && static_cast<std::size_t>(s) < n && distances[static_cast<std::size_t>(s)] != 0.)
      {
        distances[static_cast<std::size_t>(s)] = 0.;
        heap.emplace_back(0., s);
      }
    std::make_heap(heap.begin(), heap.end(), std::greater<Entry>());
    while(!heap.empty())
    {
      std::pop_heap(heap.begin(), heap.end(), std::greater<Entry>());
      const Entry top = heap.back();
      heap.pop_back();
      const std::size_t v = static_cast<std::size_t>(top.second);
      if(accepted[v] || top.first > distances[v])  // stale entry (lazy deletion)
        continue;
      accepted[v] = 1;
      ++stats.accepted;
      accept_neighbors(v, distances, accepted, heap, stats);
    }
    if(statistics != nullptr)
      *statistics = stats;
  }

private:
  typedef std::pair<double, int> Entry;  // (tentative value, vertex)
  typedef std::vector<Entry> Heap;       // a min-heap (std::greater)

  // The vertices whose value may improve now that v is accepted: the other corners of its
  // faces, and the obtuse corners split by v (v is not in their face).
  void accept_neighbors(std::size_t v, std::vector<double>& distances, std::vector<unsigned char>& accepted,
                        Heap& heap, Statistics& stats) const
  {
    for(const Triangle_adjacency::Corner* c = m_adjacency.corners_begin(v); c != m_adjacency.corners_end(v); ++c)
      for(int j = 1; j <= 2; ++j)
        relax(static_cast<std::size_t>(c->face), (c->k + j) % 3, distances, accepted, heap, stats);
    for(std::size_t i = m_split_offsets[v]; i < m_split_offsets[v + 1]; ++i)
    {
      const Split& split = m_splits[m_splits_by_vertex[i]];
      relax(static_cast<std::size_t>(split.face), split.corner, distances, accepted, heap, stats);
    }
  }

  // Updates corner k of face f unless its vertex is accepted; a smaller value is pushed.
  void relax(std::size_t f, int k, std::vector<double>& distances, std::vector<unsigned char>& accepted, Heap& heap,
             Statistics& stats) const
  {
    const std::size_t vc = static_cast<std::size_t>(m_faces[f][static_cast<std::size_t>(k)]);
    if(accepted[vc])
      return;
    const double value = update(f, k, distances, accepted, stats);
    if(value < distances[vc])  // false for NaN
    {
      distances[vc] = value;
      heap.emplace_back(value, static_cast<int>(vc));
      std::push_heap(heap.begin(), heap.end(), std::greater<Entry>());
    }
  }

  typedef Eigen::Vector2d Vector_2;

  // The split of an obtuse corner: the vertex found by the unfolding and its unfolded position,
  // in the frame of the corner (see `frame()`).
  struct Split
  {
    int face;
    int corner;
    int vertex;
    Vector_2 position;
  };

  static double infinity() { return std::numeric_limits<double>::infinity(); }

  static double cross(const Vector_2& a, const Vector_2& b) { return a.x() * b.y() - a.y() * b.x(); }

  // The plane wave at C = origin from the vertices at e1 and e2 with values t1 and t2:
  // T(C) = t1 + y where y solves |grad T| = 1 for the linear T of the triangle. With
  // u = t2 - t1, c = |e1 - e2| and s = |e1 x e2| (twice the area), the quadratic
  //   c^2 y^2 - 2 u (e1 . (e1 - e2)) y + u^2 |e1|^2 - s^2 = 0
  // has the discriminant s^2 (c^2 - u^2) / 4 (real roots iff |u| <= c); its larger root is the
  // downwind solution. The arrival direction -grad T = alpha e1 + beta e2 with
  //   alpha s^2 = y (e2 . (e2 - e1)) + u (e1 . e2),   beta s^2 = y (e1 . (e1 - e2)) - u |e1|^2;
  // causality is alpha >= 0 and beta >= 0. Everything is relative to t1, so large distances
  // lose no precision. Returns +infinity when there is no causal, monotone solution.
  static double plane_wave(const Vector_2& e1, const Vector_2& e2, double t1, double t2)
  {
    const Vector_2 e12 = e1 - e2;
    const double c2 = e12.squaredNorm();
    const double s = std::abs(cross(e1, e2));
    const double u = t2 - t1;
    if(!(c2 > 0.) || !(s > 0.) || !(u * u < c2))
      return infinity();
    const double w = e1.dot(e12);
    const double y = (u * w + s * std::sqrt(c2 - u * u)) / c2;
    if(!(y >= 0.) || !(y >= u))  // monotone: T(C) >= max(t1, t2)
      return infinity();
    const double alpha = -y * e2.dot(e12) + u * e1.dot(e2);
    const double beta = y * w - u * e1.squaredNorm();
    if(!(alpha >= 0.) || !(beta >= 0.))  // not causal
      return infinity();
    return t1 + y;
  }

  // The update of a (virtual) triangle: the plane wave if causal, else the edge updates.
  static double triangle_update(const Vector_2& e1, const Vector_2& e2, double t1, double t2)
  {
    return (std::min)(plane_wave(e1, e2, t1, t2), (std::min)(t1 + e1.norm(), t2 + e2.norm()));
  }

  // The frame of corner kc of face f: C at the origin, A = t[kc+1] at `ea` on the positive x
  // axis, B = t[kc+2] at `eb` above it. False for a degenerate corner (a zero-length edge, zero
  // angle, or non-finite coordinates).
  bool frame(std::size_t f, int kc, Vector_2& ea, Vector_2& eb) const
  {
    const Face& t = m_faces[f];
    const Eigen::Vector3d& pc = m_points[static_cast<std::size_t>(t[static_cast<std::size_t>(kc)])];
    const Eigen::Vector3d ea3 = m_points[static_cast<std::size_t>(t[static_cast<std::size_t>((kc + 1) % 3)])] - pc;
    const Eigen::Vector3d eb3 = m_points[static_cast<std::size_t>(t[static_cast<std::size_t>((kc + 2) % 3)])] - pc;
    const double la = ea3.norm();
    if(!(la > 0.) || !std::isfinite(la))
      return false;
    ea = Vector_2(la, 0.);
    eb = Vector_2(ea3.dot(eb3) / la, ea3.cross(eb3).norm() / la);
    return eb.y() > 0. && std::isfinite(eb.x()) && std::isfinite(eb.y());
  }

  // Whether the corner at C of the frame (ea, eb) is obtuse. A right angle (a grid's corner)
  // is not: the relative tolerance keeps the choice of branch, and the values, independent of
  // the rounding of a rigid motion.
  static bool is_obtuse(const Vector_2& eb)
  {
    return eb.x() < -obtuse_tolerance() * eb.norm();
  }
  static constexpr double obtuse_tolerance() { return 1e-9; }

  // The value of vertex C = corner kc of face f from the accepted vertices of that face (and,
  // for an obtuse corner, from its split vertex).
  double update(std::size_t f, int kc, const std::vector<double>& T,
                const std::vector<unsigned char>& accepted, Statistics& stats) const
  {
    ++stats.face_updates;
    const Face& t = m_faces[f];
    const std::size_t vc = static_cast<std::size_t>(t[static_cast<std::size_t>(kc)]);
    const std::size_t va = static_cast<std::size_t>(t[static_cast<std::size_t>((kc + 1) % 3)]);
    const std::size_t vb = static_cast<std::size_t>(t[static_cast<std::size_t>((kc + 2) % 3)]);
    const bool known_a = accepted[va] != 0, known_b = accepted[vb] != 0;

    double best = infinity();  // the edge updates are always valid
    if(known_a)
      best = (std::min)(best, T[va] + (m_points[va] - m_points[vc]).norm());
    if(known_b)
      best = (std::min)(best, T[vb] + (m_points[vb] - m_points[vc]).norm());

    Vector_2 ea, eb;
    if(!frame(f, kc, ea, eb))  // degenerate: edge updates only
      return best;
    if(!is_obtuse(eb))
    {
      if(known_a && known_b)
        best = (std::min)(best, plane_wave(ea, eb, T[va], T[vb]));
      return best;
    }

    ++stats.obtuse_updates;
    const int s = m_split_of_corner[f][static_cast<std::size_t>(kc)];
    if(s >= 0 && accepted[static_cast<std::size_t>(m_splits[static_cast<std::size_t>(s)].vertex)])
    {
      // Kimmel-Sethian: the two non-obtuse virtual triangles (C, A, D') and (C, D', B)
      const Split& split = m_splits[static_cast<std::size_t>(s)];
      const double td = T[static_cast<std::size_t>(split.vertex)];
      ++stats.split_updates;
      if(known_a)
        best = (std::min)(best, triangle_update(ea, split.position, T[va], td));
      if(known_b)
        best = (std::min)(best, triangle_update(split.position, eb, td, T[vb]));
      return best;
    }
    // no split (yet): the plane wave of ABC, if causal and monotone
    if(known_a && known_b)
      best = (std::min)(best, plane_wave(ea, eb, T[va], T[vb]));
    return best;
  }

  // Finds the split of every obtuse corner, and lists the splits by split vertex.
  void split_obtuse_corners()
  {
    const std::size_t F = m_faces.size();
    m_split_of_corner.assign(F, {{-1, -1, -1}});
    m_obtuse_corners = 0;
    for(std::size_t f = 0; f < F; ++f)
      for(int k = 0; k < 3; ++k)
      {
        Vector_2 ea, eb;
        if(!frame(f, k, ea, eb) || !is_obtuse(eb))
          continue;
        ++m_obtuse_corners;
        Split split = {static_cast<int>(f), k, -1, Vector_2::Zero()};
        if(unfold(f, k, ea, eb, split.vertex, split.position))
        {
          m_split_of_corner[f][static_cast<std::size_t>(k)] = static_cast<int>(m_splits.size());
          m_splits.push_back(split);
        }
      }
    const std::size_t n = m_points.size();
    m_split_offsets.assign(n + 1, 0);
    for(const Split& split : m_splits)
      ++m_split_offsets[static_cast<std::size_t>(split.vertex) + 1];
    for(std::size_t i = 0; i < n; ++i)
      m_split_offsets[i + 1] += m_split_offsets[i];
    m_splits_by_vertex.resize(m_splits.size());
    std::vector<std::size_t> fill(m_split_offsets.begin(), m_split_offsets.end() - 1);
    for(std::size_t s = 0; s < m_splits.size(); ++s)
      m_splits_by_vertex[fill[static_cast<std::size_t>(m_splits[s].vertex)]++] = s;
  }

  // Unfolds the triangles across the edge AB opposite the obtuse corner kc of face f into the
  // plane of (C, A, B) (C at the origin, A at `ea`, B at `eb`) until the unfolded position of
  // a vertex lies in the acute section of C: {x : x . ea >= 0 and x . eb >= 0}. The current
  // window is the edge (P, Q) of face g opposite its corner kg, with P on A's side; every ray
  // of the section crosses it. On success, `vd` is the vertex and `ed` its unfolded position.
  // Places vertex d in the plane of the unfolding, on the side of the line (p, q) away from C
  // (the origin), with its 3D distances to the vertices vp and vq placed at p and q.
  bool place_across(int d, int vp, int vq, const Vector_2& p, const Vector_2& q, Vector_2& pos) const
  {
    const Eigen::Vector3d& pd3 = m_points[static_cast<std::size_t>(d)];
    const double lp2 = (pd3 - m_points[static_cast<std::size_t>(vp)]).squaredNorm();
    const double lq2 = (pd3 - m_points[static_cast<std::size_t>(vq)]).squaredNorm();
    const Vector_2 pq = q - p;
    const double e = pq.norm();
    if(!(e > 0.))
      return false;
    const Vector_2 dir = pq / e;
    Vector_2 normal(-dir.y(), dir.x());
    if(normal.dot(p) < 0.)  // C (the origin) must be on the negative side
      normal = -normal;
    const double x = (lp2 - lq2 + e * e) / (2. * e);
    const double h2 = lp2 - x * x;
    pos = p + x * dir + (h2 > 0. ? std::sqrt(h2) : 0.) * normal;
    return pos.allFinite();
  }

  bool unfold(std::size_t f, int kc, const Vector_2& ea, const Vector_2& eb, int& vd, Vector_2& ed) const
  {
    const Face& t = m_faces[f];
    const int vc = t[static_cast<std::size_t>(kc)];
    int vp = t[static_cast<std::size_t>((kc + 1) % 3)], vq = t[static_cast<std::size_t>((kc + 2) % 3)];
    Vector_2 p = ea, q = eb;
    std::size_t g = f;
    int kg = kc;
    for(int step = 0; step < m_max_unfolding_steps; ++step)
    {
      const int h = m_adjacency.neighbor(g, kg);
      if(h < 0)  // border
        return false;
      const int kd = m_adjacency.neighbor_corner(g, kg);
      const Face& th = m_faces[static_cast<std::size_t>(h)];
      const int d = th[static_cast<std::size_t>(kd)];
      const int k1 = (kd + 1) % 3, k2 = (kd + 2) % 3;
      const int kp = (th[static_cast<std::size_t>(k1)] == vp) ? k1 : k2;
      const int kq = 3 - kd - kp;
      if(d == vc || d == vp || d == vq || th[static_cast<std::size_t>(kp)] != vp ||
         th[static_cast<std::size_t>(kq)] != vq)  // wrapped around, or not a manifold strip
        return false;

      Vector_2 pos;
      if(!place_across(d, vp, vq, p, q, pos))
        return false;

      // in the acute section, right angles included up to rounding (cos >= -1e-12)
      const double along_a = pos.dot(ea), along_b = pos.dot(eb);
      const double tolerance = -1e-12 * pos.norm();
      if(along_a >= tolerance * ea.norm() && along_b >= tolerance * eb.norm())
      {
        vd = d;
        ed = pos;
        return true;
      }
      if(along_a < 0. && along_b < 0.)  // behind C: not a strip along the section
        return false;
      g = static_cast<std::size_t>(h);
      if(along_b < 0.)  // before the section, on A's side: continue across (D, Q)
      {
        vp = d;
        p = pos;
        kg = kp;
      }
      else  // past the section, on B's side: continue across (P, D)
      {
        vq = d;
        q = pos;
        kg = kq;
      }
    }
    return false;  // not found within the bound
  }

  const std::vector<Eigen::Vector3d>& m_points;
  const std::vector<Face>& m_faces;
  Triangle_adjacency m_adjacency;
  int m_max_unfolding_steps;
  std::size_t m_obtuse_corners = 0;
  std::vector<Split> m_splits;
  std::vector<std::array<int, 3> > m_split_of_corner;  // index in m_splits, or -1
  std::vector<std::size_t> m_split_offsets;            // splits by split vertex (CSR)
  std::vector<std::size_t> m_splits_by_vertex;
};

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DISTANCES_FAST_MARCHING_H
