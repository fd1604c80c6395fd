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
// polygon where its UV comes from once the charts are flattened.

#include <CGAL/Surface_mesh_parameterization/Soup_repair_report.h>

#include <CGAL/Surface_mesh.h>

#include <boost/graph/graph_traits.hpp>

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// Where the UV of one input corner comes from: the UVs of two halfedges of one face of the
// repaired mesh (so of one chart), uv = (1 - t) uv(from) + t uv(to), where uv(h) is the UV
// of the corner of face(h) at target(h).
//  - ON_HALFEDGE: from == to, t == 0, and target(from) has the corner's point: the corner of
//    a face kept, or of a dropped polygon at a point a face kept has;
//  - ON_SEGMENT: a corner of a zero-area triangle or degenerate polygon laid on an edge of a
//    face kept: the point at t on the segment from target(from) to target(to) is the corner's
//    point, or its projection on that segment;
//  - COLLAPSED: from == to, t == 0, at a vertex of a face kept other than the corner's point
//    (a dropped element that shares no edge with a face kept): a zero-area UV triangle all
//    the same;
//  - ISOLATED: from and to are null: no face of the repaired mesh has the corner's point;
//    the chart code gives the corner a UV of its own (any point: nothing is drawn there).
template <class Mesh>
struct Corner_source
{
  typedef typename boost::graph_traits<Mesh>::halfedge_descriptor halfedge_descriptor;
  enum Kind { ON_HALFEDGE, ON_SEGMENT, COLLAPSED, ISOLATED };

  halfedge_descriptor from = boost::graph_traits<Mesh>::null_halfedge();
  halfedge_descriptor to = boost::graph_traits<Mesh>::null_halfedge();
  double t = 0.;
  Kind kind = ISOLATED;
};

// A triangle of zero area (2A <= 1e-12 l^2, l its longest edge), removed from the mesh: the
// parameterizers reject it. Its corners lie on one edge of the face kept `face` (the face
// across its longest edge when that is kept; else the face kept reached through other zero-area
// triangles), or at one vertex (COLLAPSED), or nowhere (ISOLATED, null face).
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

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_ATLAS_REPAIRED_SOUP_H
