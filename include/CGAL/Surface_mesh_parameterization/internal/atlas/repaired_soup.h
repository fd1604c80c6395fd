// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_ATLAS_REPAIRED_SOUP_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_ATLAS_REPAIRED_SOUP_H

// What the repair of a polygon soup for the atlas gives (soup_repair.h): the repaired
// triangle mesh, the input polygon of each of its faces, and for every corner of every input
// polygon where its UV comes from once the charts are flattened; the repaired mesh as the
// triangle set of the charts (charts.h), and the UV of an input corner from the UVs of the
// corners of the triangle set.

#include <CGAL/Surface_mesh_parameterization/internal/atlas/charts.h>
#include <CGAL/Surface_mesh_parameterization/Soup_repair_report.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Surface_mesh.h>

#include <boost/graph/graph_traits.hpp>

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// Where the UV of one input corner comes from: the UVs of two halfedges of one face of the
// repaired mesh (so of one chart), uv = (1 - t) uv(from) + t uv(to), where uv(h) is the UV
// of the corner of face(h) at target(h) (corner_uv()). Every kind has both halfedges:
//  - ON_HALFEDGE: from == to, t == 0, and target(from) has the corner's point: the corner of
//    a face kept, or of a dropped polygon at a point a face kept has;
//  - ON_SEGMENT: a corner of a zero-area triangle or degenerate polygon laid on an edge of a
//    face kept: the point at t on the segment from target(from) to target(to) is the corner's
//    point, or its projection on that segment;
//  - COLLAPSED: from == to, t == 0, at a vertex of a face kept other than the corner's point
//    (a dropped element that shares no edge with a face kept);
//  - ISOLATED: from == to, t == 0: no face of the repaired mesh has the corner's point; the
//    corners of one polygon so are all at the vertex nearest to the point of the first.
// So the corners of a zero-area or dropped polygon get a zero-area UV polygon inside a chart.
template <class Mesh>
struct Corner_source
{
  typedef typename boost::graph_traits<Mesh>::halfedge_descriptor halfedge_descriptor;
  enum Kind { ON_HALFEDGE, ON_SEGMENT, COLLAPSED, ISOLATED };

  // (null only inside the repair, never in its result)
  halfedge_descriptor from = boost::graph_traits<Mesh>::null_halfedge();
  halfedge_descriptor to = boost::graph_traits<Mesh>::null_halfedge();
  double t = 0.;
  Kind kind = ISOLATED;
};

// A triangle of zero area (2A <= 1e-12 l^2, l its longest edge), removed from the mesh: the
// parameterizers reject it. Its corners lie on one edge of the face kept `face` (the face
// across its longest edge when that is kept; else the face kept reached through other zero-area
// triangles), or at one vertex (COLLAPSED), or at the vertex nearest to it (ISOLATED).
template <class Mesh>
struct Zero_area_triangle
{
  typedef typename boost::graph_traits<Mesh>::face_descriptor face_descriptor;
  typedef typename Mesh::Point Point_3;

  std::size_t polygon = 0;                     // the input polygon it comes from
  std::array<Point_3, 3> points;               // its corners, in the mesh's orientation
  face_descriptor face = boost::graph_traits<Mesh>::null_face();
  std::array<Corner_source<Mesh>, 3> corners;  // where the UVs of its corners come from
};

template <class Kernel>
struct Repaired_soup
{
  typedef typename Kernel::Point_3 Point_3;
  typedef CGAL::Surface_mesh<Point_3> Mesh;
  typedef Corner_source<Mesh> Source;

  // The repaired mesh: triangles of nonzero area, valid, manifold, each connected component
  // consistently oriented; no isolated vertex; indices 0..n-1 (no garbage).
  Mesh mesh;
  // per face (by index): the input polygon it comes from (traceable triangles of a polygon),
  // and its connected component, 0..report.components-1
  std::vector<std::size_t> face_polygon, face_component;
  // per input polygon p: the source of its corner j is corners[corner_offset[p] + j]
  std::vector<std::size_t> corner_offset;
  std::vector<Source> corners;
  std::vector<Zero_area_triangle<Mesh> > zero_area_triangles;
  Soup_repair_report report;

  const Source& corner(std::size_t polygon, std::size_t j) const { return corners[corner_offset[polygon] + j]; }
};

// The corner of the repaired mesh that halfedge h of a face stands for: (face index, k), h
// being the k-th halfedge of halfedges_around_face(halfedge(face)), the corner at target(h).
template <class Mesh>
std::pair<std::size_t, int> face_corner(const Mesh& mesh, typename boost::graph_traits<Mesh>::halfedge_descriptor h)
{
  const auto f = face(h, mesh);
  int k = 0;
  for(auto g = halfedge(f, mesh); g != h; g = next(g, mesh))
    ++k;
  return std::make_pair(std::size_t(f), k);
}

// The repaired mesh as the triangle set of the charts: point i the point of vertex i, and
// corner k of face f (faces[f][k]) its corner face_corner() numbers (f, k).
template <class Kernel>
Atlas_triangles repaired_triangles(const Repaired_soup<Kernel>& r)
{
  Atlas_triangles t;
  t.points.reserve(r.mesh.number_of_vertices());
  for(auto v : vertices(r.mesh))
  {
    const auto& p = r.mesh.point(v);
    t.points.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  }
  t.faces.resize(r.mesh.number_of_faces());
  for(auto f : faces(r.mesh))
  {
    int k = 0;
    for(auto h : halfedges_around_face(halfedge(f, r.mesh), r.mesh))
      t.faces[std::size_t(f)][std::size_t(k++)] = int(target(h, r.mesh));
  }
  t.face_polygon = r.face_polygon;
  return t;
}

// The UV of corner j of input polygon p: (1 - t) uv(from) + t uv(to) (Corner_source), where
// corner_uv(f, k) is the UV of corner k of face f of repaired_triangles() (an Eigen::Vector2d,
// as Atlas_chart::corners holds them).
template <class Kernel, class CornerUV>
Eigen::Vector2d input_corner_uv(const Repaired_soup<Kernel>& r, std::size_t p, std::size_t j, CornerUV corner_uv)
{
  const auto& s = r.corner(p, j);
  const std::pair<std::size_t, int> from = face_corner(r.mesh, s.from), to = face_corner(r.mesh, s.to);
  const Eigen::Vector2d a = corner_uv(from.first, from.second);
  return s.t == 0. ? a : Eigen::Vector2d((1. - s.t) * a + s.t * corner_uv(to.first, to.second));
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_ATLAS_REPAIRED_SOUP_H
