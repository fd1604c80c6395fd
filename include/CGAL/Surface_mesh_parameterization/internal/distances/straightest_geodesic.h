// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DISTANCES_STRAIGHTEST_GEODESIC_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DISTANCES_STRAIGHTEST_GEODESIC_H

// The straightest geodesic distance of Lee et al. (2006), the "cutting plane" method behind the
// paper's MBPSGP (paper sections 2.1-2.2, Figs. 2, 3 and 5; user manual: The method in a page): the
// path from a source vertex to a target vertex is the intersection of the surface with the
// plane through both vertices and the normal at the source, followed triangle by triangle from
// the source towards the target. The path need not exist (paper Fig. 2: the traced curve
// closes on itself, or reaches the border elsewhere); the tracer then reports a failure and
// never a length.
//
// Conventions of the walk (the plane is  {x : m . (x - source) = 0},  m = N x (p_target - p_source)
// normalized, N the area-weighted vertex normal at the source):
// - Start: among the plane's crossings of the source's one-ring, the one on the target's side,
//   i.e. with the largest positive cosine to the projection of p_target - p_source onto the
//   tangent plane (the target itself when it is a neighbour).
// - Every vertex gets the signed distance d(v) = m . (p_v - p_source), snapped to 0 when
//   |d(v)| <= tolerance() (by default 1e-10 times the patch's bounding box diagonal); d(source) = d(target) = 0 exactly (the plane contains both by
//   construction). The snapped sign of a vertex is a function of the vertex alone, so the
//   combinatorial decisions taken from two faces sharing an edge always agree.
// - An edge is crossed only where its two endpoints have strictly opposite signs; the
//   crossing point is interpolated linearly (always in the same edge orientation).
// - A vertex with d = 0 is passed *through*: the walk continues in that vertex's one-ring with
//   the plane's crossings of the one-ring (crossed opposite edges, or neighbours with d = 0,
//   reached along an edge lying in the plane), the way it came from excluded. With one
//   crossing left the walk takes it (the curve simply continues); with several (a saddle or a
//   fold of the one-ring) it takes the one most aligned with the incoming direction (the far
//   side, no going back).
// - Since d(target) = 0 exactly, no edge incident to the target is ever crossed: the path
//   reaches the target exactly when it enters a triangle incident to the target (through the
//   edge opposite it), or when the target is a crossing of the one-ring of a vertex passed
//   through. In the latter case the target is taken when it lies ahead (positive dot product
//   with the incoming direction) or is the only way on; a target left behind at such a
//   branch is a failure ("passed by the target").
// - The walk fails when it reaches the border, revisits a vertex or enters a triangle through
//   the same edge a second time, i.e. crosses it again in the same direction (a closed loop:
//   the walk is deterministic from there on), or exceeds 4 F + V + 8 steps (cannot happen
//   after the loop test; kept as a guard).
// Cost of a trace: proportional to the number of triangles and one-rings it crosses.

#include <CGAL/Surface_mesh_parameterization/internal/core/triangle_adjacency.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <unordered_set>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// Traces straightest geodesics (cutting plane paths) between vertices of an indexed triangle
// patch.
//
// The tracer keeps references to `points` and `faces` (and builds a `Triangle_adjacency` on
// them): both vectors must outlive the tracer and stay unchanged while it is used. Once
// constructed, `trace()` is const and keeps no state between calls, so several threads may
// trace concurrently on one tracer.
class Straightest_geodesic_tracer
{
public:
  typedef std::array<int, 3> Face;

  // Outcome of a trace.
  enum Status
  {
    REACHED_TARGET = 0,   // success: the length is the length of the traced polyline
    INVALID_INPUT,        // invalid mesh (see is_valid()), index out of range, or a vertex without faces
    UNDEFINED_PLANE,      // zero normal at the source, or target - source parallel to it
    NO_START_DIRECTION,   // no crossing of the source's one-ring lies on the target's side
    REACHED_BORDER,       // the path left the patch elsewhere (paper Fig. 2b)
    CLOSED_LOOP,          // the path came back to a vertex or triangle it had crossed (Fig. 2a)
    PASSED_TARGET,        // the path went through a neighbour of the target and left it behind
    STEP_LIMIT            // more than 4 F + V + 8 steps (guard; not expected)
  };

  // A short text for each status.
  static const char* status_message(Status s)
  {
    switch(s)
    {
      case REACHED_TARGET: return "reached the target";
      case INVALID_INPUT: return "invalid input";
      case UNDEFINED_PLANE: return "cutting plane undefined (zero normal, or target along the normal)";
      case NO_START_DIRECTION: return "no start direction towards the target";
      case REACHED_BORDER: return "reached the border elsewhere";
      case CLOSED_LOOP: return "the path closes on itself";
      case PASSED_TARGET: return "the path passes by the target";
      case STEP_LIMIT: return "step bound exceeded";
    }
    return "unknown";
  }

  // Default relative tolerance: a vertex is on the cutting plane when its distance to it is
  // at most this times the diagonal of the bounding box of the patch.
  static constexpr double default_relative_tolerance() { return 1e-10; }

  // `points`, `faces`: a consistently oriented manifold triangle patch (borders allowed; closed
  // meshes and handles are fine too). Vertices not used by any face are ignored. The mesh is
  // invalid (`is_valid()` false, every trace fails with `INVALID_INPUT`) when a face has an
  // index out of [0, points.size()) or a repeated index, when a vertex used by a face has a
  // non-finite coordinate, or when there is no face or all used points coincide.
  Straightest_geodesic_tracer(const std::vector<Eigen::Vector3d>& points,
                              const std::vector<Face>& faces,
                              double relative_tolerance = default_relative_tolerance())
    : m_points(points), m_faces(faces)
  {
    const int n = static_cast<int>(points.size());
    if(faces.empty() || points.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
      return;
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
    Eigen::Vector3d hi = -lo;
    for(const Face& f : faces)
    {
      for(int v : f)
      {
        if(v < 0 || v >= n)
          return;
        const Eigen::Vector3d& p = points[static_cast<std::size_t>(v)];
        if(!p.allFinite())
          return;
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
      }
      if(f[0] == f[1] || f[1] == f[2] || f[2] == f[0])
        return;
    }
    const double diagonal = (hi - lo).norm();
    if(!(diagonal > 0.) || !std::isfinite(diagonal))
      return;
    m_tolerance = (relative_tolerance >= 0. && std::isfinite(relative_tolerance))
                    ? relative_tolerance * diagonal
                    : default_relative_tolerance() * diagonal;
    m_adjacency.build(points.size(), faces);
    m_valid = true;
  }

  // whether the mesh passed the checks of the constructor.
  bool is_valid() const { return m_valid; }

  // absolute tolerance on the signed distance to the cutting plane.
  double tolerance() const { return m_tolerance; }

  // the adjacency the walk uses (valid meshes only).
  const Triangle_adjacency& adjacency() const { return m_adjacency; }

  // area-weighted average of the normals of the faces at `v` (unnormalized: the sum of the
  // cross products of the incident faces); zero for an invalid mesh or index.
  Eigen::Vector3d vertex_normal(int v) const
  {
    Eigen::Vector3d n = Eigen::Vector3d::Zero();
    if(!m_valid || v < 0 || static_cast<std::size_t>(v) >= m_points.size())
      return n;
    for(const Triangle_adjacency::Corner* c = m_adjacency.corners_begin(static_cast<std::size_t>(v));
        c != m_adjacency.corners_end(static_cast<std::size_t>(v)); ++c)
    {
      const Face& f = m_faces[static_cast<std::size_t>(c->face)];
      const Eigen::Vector3d& a = point(f[0]);
      n += (point(f[1]) - a).cross(point(f[2]) - a);
    }
    return n;
  }

  // The intersection of the surface with the plane through `source`, `target` and the normal
  // at `source` (area-weighted average of the incident face normals), traced from `source` in
  // the direction of `target` triangle by triangle. Returns true and the path length when the
  // trace reaches vertex `target`; returns false when it cannot (it reaches the border
  // elsewhere, closes on itself, passes by the target, or exceeds a step bound) -- never a
  // wrong length. `source == target` gives length 0.
  //
  // On success `length` is the length of the polyline and `*path` (when given) the polyline:
  // it starts with the source's point, ends with the target's point, and every two
  // consecutive points lie in one triangle (vertices, or points on edges). On failure
  // `length` is not modified and `*path` holds the part traced before the failure (for
  // diagnostics, as in the paper's Fig. 2; empty for invalid input).
  bool trace(int source, int target, double& length, std::vector<Eigen::Vector3d>* path = nullptr) const
  {
    return trace_with_status(source, target, length, path) == REACHED_TARGET;
  }

  // `trace()`, telling why a trace failed.
  Status trace_with_status(int source, int target, double& length,
                           std::vector<Eigen::Vector3d>* path = nullptr) const
  {
    if(path)
      path->clear();
    const int n = static_cast<int>(m_points.size());
    if(!m_valid || source < 0 || source >= n || target < 0 || target >= n ||
       !has_faces(source) || !has_faces(target))
      return INVALID_INPUT;

    std::vector<Eigen::Vector3d> local;
    std::vector<Eigen::Vector3d>& polyline = path ? *path : local;
    polyline.push_back(point(source));
    if(source == target)
    {
      length = 0.;
      return REACHED_TARGET;
    }

    // the cutting plane
    const Eigen::Vector3d normal = vertex_normal(source);
    const Eigen::Vector3d chord = point(target) - point(source);
    const double normal_norm = normal.norm(), chord_norm = chord.norm();
    if(!(normal_norm > 0.) || !(chord_norm > 0.))
      return UNDEFINED_PLANE;
    Eigen::Vector3d m = normal.cross(chord);
    const double m_norm = m.norm();
    if(!(m_norm > 1e-12 * normal_norm * chord_norm) || !std::isfinite(m_norm))
      return UNDEFINED_PLANE;
    m /= m_norm;
    const Eigen::Vector3d unit_normal = normal / normal_norm;
    Eigen::Vector3d direction = chord - chord.dot(unit_normal) * unit_normal;  // target side
    direction.normalize();

    const Plane plane{point(source), m, m_tolerance, source, target};
    Walk walk(*this, plane, polyline);
    const Status status = walk.run(direction);
    if(status != REACHED_TARGET)
      return status;

    double sum = 0.;
    for(std::size_t i = 1; i < polyline.size(); ++i)
      sum += (polyline[i] - polyline[i - 1]).norm();
    if(!std::isfinite(sum))  // cannot happen for finite input; never report a wrong length
      return INVALID_INPUT;
    length = sum;
    return REACHED_TARGET;
  }

private:
  // The cutting plane and the snapped signs of the vertices.
  struct Plane
  {
    Eigen::Vector3d origin;
    Eigen::Vector3d normal;  // unit
    double tolerance;
    int source, target;
  };

  const Eigen::Vector3d& point(int v) const { return m_points[static_cast<std::size_t>(v)]; }

  bool has_faces(int v) const
  {
    return m_adjacency.corners_begin(static_cast<std::size_t>(v)) !=
           m_adjacency.corners_end(static_cast<std::size_t>(v));
  }

  // One trace: the state of the walk over the triangles.
  class Walk
  {
  public:
    Walk(const Straightest_geodesic_tracer& tracer, const Plane& plane, std::vector<Eigen::Vector3d>& polyline)
      : m_tracer(tracer), m_plane(plane), m_polyline(polyline)
    {}

    // Walks from the source, initially in `direction` (unit, tangent at the source).
    Status run(const Eigen::Vector3d& direction)
    {
      const Triangle_adjacency& adj = m_tracer.m_adjacency;
      const std::size_t max_steps = 4 * adj.number_of_faces() + adj.number_of_vertices() + 8;
      m_at_vertex = true;
      m_vertex = m_plane.source;
      m_arrival_face = m_arrival_vertex = -1;
      m_at_source = true;
      m_heading = direction;
      for(std::size_t step = 0; step < max_steps; ++step)
      {
        Status status = STEP_LIMIT;
        if(!(m_at_vertex ? leave_vertex(status) : cross_face(status)))
          return status;
      }
      return STEP_LIMIT;
    }

  private:
    // At a vertex: the walk ends there (false, with its status), or goes on to the chosen
    // crossing of the plane with the vertex's one-ring.
    bool leave_vertex(Status& status)
    {
      if(m_vertex == m_plane.target)
        return (status = REACHED_TARGET, false);
      if(!m_visited_vertices.insert(m_vertex).second)
        return (status = CLOSED_LOOP, false);
      collect_candidates(m_vertex, m_arrival_face, m_arrival_vertex);
      int chosen = -1;
      status = m_at_source ? choose_start(m_vertex, m_heading, chosen) : choose_continuation(m_vertex, m_heading, chosen);
      if(status != REACHED_TARGET)
        return false;
      m_at_source = false;
      const Candidate c = m_candidates[static_cast<std::size_t>(chosen)];
      const Eigen::Vector3d from = m_tracer.point(m_vertex);
      m_polyline.push_back(c.point);
      update_heading(m_heading, c.point - from);
      if(c.vertex >= 0)
      {
        m_arrival_vertex = m_vertex;
        m_arrival_face = -1;
        m_vertex = c.vertex;
      }
      else
      {
        m_at_vertex = false;
        m_face = c.face;
        m_corner = c.corner;
      }
      return true;
    }

    // On an edge (crossing from face m_face across the edge opposite its corner m_corner, at
    // the last point of the polyline): enters the face across it and leaves it through a vertex
    // or an edge; false, with the status, when the walk ends.
    bool cross_face(Status& status)
    {
      const Triangle_adjacency& adj = m_tracer.m_adjacency;
      const int g = adj.neighbor(static_cast<std::size_t>(m_face), m_corner);
      if(g < 0)
        return (status = REACHED_BORDER, false);
      const int kg = adj.neighbor_corner(static_cast<std::size_t>(m_face), m_corner);
      if(!m_visited_crossings.insert(3 * static_cast<std::int64_t>(g) + kg).second)
        return (status = CLOSED_LOOP, false);
      const Face& f = adj.face(static_cast<std::size_t>(g));
      const int c = f[static_cast<std::size_t>(kg)];
      const int a = f[static_cast<std::size_t>((kg + 1) % 3)];
      const int b = f[static_cast<std::size_t>((kg + 2) % 3)];
      const int sa = sign(a), sb = sign(b), sc = sign(c);
      if(sa == 0 || sb == 0 || sa == sb)  // the entry edge must be crossed (cannot happen)
        return (status = REACHED_BORDER, false);
      const Eigen::Vector3d from = m_polyline.back();
      if(sc == 0)  // the plane leaves the triangle through its vertex c
      {
        m_polyline.push_back(m_tracer.point(c));
        update_heading(m_heading, m_tracer.point(c) - from);
        m_at_vertex = true;
        m_vertex = c;
        m_arrival_face = g;
        m_arrival_vertex = -1;
        return true;
      }
      // leave through the edge whose endpoints have opposite signs: (b, c) or (c, a)
      const Eigen::Vector3d q = (sc == sa) ? crossing(b, c) : crossing(c, a);
      m_polyline.push_back(q);
      update_heading(m_heading, q - from);
      m_face = g;
      m_corner = (sc == sa) ? (kg + 1) % 3 : (kg + 2) % 3;
      return true;
    }

    // A crossing of the cutting plane with the one-ring of a vertex v: either a point on the
    // edge opposite corner `corner` of face `face` (`vertex` = -1), or a neighbour `vertex`
    // with d = 0, reached along an edge in the plane.
    struct Candidate
    {
      int face;
      int corner;
      int vertex;
      Eigen::Vector3d point;
    };

    // snapped sign of the signed distance to the plane
    int sign(int v) const
    {
      if(v == m_plane.source || v == m_plane.target)
        return 0;
      const double d = distance(v);
      if(d > m_plane.tolerance)
        return 1;
      if(d < -m_plane.tolerance)
        return -1;
      return 0;
    }

    double distance(int v) const { return m_plane.normal.dot(m_tracer.point(v) - m_plane.origin); }

    // the crossing point of the plane with edge (a, b), whose ends have opposite signs;
    // computed from the smaller index so that both faces of the edge get the same point
    Eigen::Vector3d crossing(int a, int b) const
    {
      if(a > b)
        std::swap(a, b);
      const double da = distance(a), db = distance(b);
      double t = da / (da - db);
      if(!(t >= 0.))  // guards against rounding only: da and db have opposite signs
        t = 0.;
      if(t > 1.)
        t = 1.;
      return m_tracer.point(a) + t * (m_tracer.point(b) - m_tracer.point(a));
    }

    static void update_heading(Eigen::Vector3d& heading, const Eigen::Vector3d& step)
    {
      const double len = step.norm();
      if(len > 0. && std::isfinite(len))
        heading = step / len;
    }

    // the plane's crossings of the one-ring of v, without the way the walk came from
    void collect_candidates(int v, int arrival_face, int arrival_vertex)
    {
      const Triangle_adjacency& adj = m_tracer.m_adjacency;
      m_candidates.clear();
      auto add_vertex = [&](int w, int face, int corner) {
        if(w == arrival_vertex)
          return;
        for(const Candidate& c : m_candidates)
          if(c.vertex == w)
            return;
        m_candidates.push_back(Candidate{face, corner, w, m_tracer.point(w)});
      };
      for(const Triangle_adjacency::Corner* corner = adj.corners_begin(static_cast<std::size_t>(v));
          corner != adj.corners_end(static_cast<std::size_t>(v)); ++corner)
      {
        const Face& f = adj.face(static_cast<std::size_t>(corner->face));
        const int a = f[static_cast<std::size_t>((corner->k + 1) % 3)];
        const int b = f[static_cast<std::size_t>((corner->k + 2) % 3)];
        const int sa = sign(a), sb = sign(b);
        if(sa * sb < 0)
        {
          if(corner->face != arrival_face)
            m_candidates.push_back(Candidate{corner->face, corner->k, -1, crossing(a, b)});
          continue;
        }
        if(sa == 0)
          add_vertex(a, corner->face, corner->k);
        if(sb == 0)
          add_vertex(b, corner->face, corner->k);
      }
    }

    // cosine of the angle between `heading` (unit) and the candidate's direction from v;
    // 0 for a candidate at the position of v
    double alignment(int v, const Candidate& c, const Eigen::Vector3d& heading) const
    {
      const Eigen::Vector3d d = c.point - m_tracer.point(v);
      const double len = d.norm();
      if(!(len > 0.) || !std::isfinite(len))
        return 0.;
      return d.dot(heading) / len;
    }

    // The two choices below set `chosen` (an index into m_candidates) and return
    // REACHED_TARGET when the walk can go on, or the failure status.

    // at the source: the crossing on the target's side (the target itself when it is a
    // neighbour, which is always on that side), best aligned with the start direction
    Status choose_start(int v, const Eigen::Vector3d& direction, int& chosen) const
    {
      double best = 0.;
      for(std::size_t i = 0; i < m_candidates.size(); ++i)
      {
        const double cosine = alignment(v, m_candidates[i], direction);
        if(m_candidates[i].vertex == m_plane.target && cosine > 0.)
        {
          chosen = static_cast<int>(i);
          return REACHED_TARGET;
        }
        if(cosine > best)
        {
          best = cosine;
          chosen = static_cast<int>(i);
        }
      }
      return chosen >= 0 ? REACHED_TARGET : NO_START_DIRECTION;
    }

    // through a vertex on the plane: the only crossing left, or the target if it lies ahead,
    // or the crossing best aligned with the incoming direction
    Status choose_continuation(int v, const Eigen::Vector3d& heading, int& chosen) const
    {
      if(m_candidates.empty())
        return REACHED_BORDER;
      if(m_candidates.size() == 1)
      {
        chosen = 0;
        return REACHED_TARGET;
      }
      double best = -std::numeric_limits<double>::infinity();
      bool target_seen = false;
      for(std::size_t i = 0; i < m_candidates.size(); ++i)
      {
        const double cosine = alignment(v, m_candidates[i], heading);
        if(m_candidates[i].vertex == m_plane.target)
        {
          if(cosine > 0.)
          {
            chosen = static_cast<int>(i);
            return REACHED_TARGET;
          }
          target_seen = true;
        }
        if(cosine > best)
        {
          best = cosine;
          chosen = static_cast<int>(i);
        }
      }
      if(target_seen && m_candidates[static_cast<std::size_t>(chosen)].vertex != m_plane.target)
        return PASSED_TARGET;
      return REACHED_TARGET;
    }

    const Straightest_geodesic_tracer& m_tracer;
    const Plane& m_plane;
    std::vector<Eigen::Vector3d>& m_polyline;
    std::vector<Candidate> m_candidates;
    std::unordered_set<int> m_visited_vertices;
    std::unordered_set<std::int64_t> m_visited_crossings;
    int m_face = -1;
    int m_corner = -1;
    bool m_at_vertex = true, m_at_source = true;
    int m_vertex = -1, m_arrival_face = -1, m_arrival_vertex = -1;
    Eigen::Vector3d m_heading = Eigen::Vector3d::Zero();
  };

  const std::vector<Eigen::Vector3d>& m_points;
  const std::vector<Face>& m_faces;
  Triangle_adjacency m_adjacency;
  double m_tolerance = 0.;
  bool m_valid = false;
};

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DISTANCES_STRAIGHTEST_GEODESIC_H
