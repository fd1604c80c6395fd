// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_SOUP_REPAIR_REPORT_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_SOUP_REPAIR_REPORT_H

/// \file Soup_repair_report.h
/// What the repair of a polygon soup into the triangle mesh of a texture atlas did.

#include <cstddef>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgSurfaceMeshParameterizationMeasured
/// The repairs made to a polygon soup (points and polygons as read by CGAL's readers, e.g.
/// `CGAL::IO::read_polygon_soup()`) to turn it into a triangle mesh whose connected components
/// can be parameterized one by one: valid, of triangles of nonzero area, consistently oriented,
/// manifold. No input polygon is lost: every corner of every input polygon gets its UV from a
/// face of the repaired mesh; a polygon of zero area gets a UV polygon of zero area inside a
/// chart. Counts of polygons are counts of input polygons; counts of points are counts of
/// input points after duplicate points are merged.
///
/// Only what cannot be textured at all is an error, and gives no mesh: a soup with no face
/// left (no polygon of three distinct points, or all of zero area), a point with a
/// non-finite coordinate, an index out of range. The report then says what was found up to
/// the error.
struct Soup_repair_report
{
  /// \name The input
  /// @{
  std::size_t input_points = 0;    ///< points of the soup
  std::size_t input_polygons = 0;  ///< polygons of the soup
  std::size_t input_corners = 0;   ///< corners of all polygons (the sum of their sizes)
  /// @}

  /// \name Repairs of the soup
  /// @{
  /// points that repeat the exact coordinates of an earlier point, merged into it
  std::size_t merged_points = 0;
  /// polygons with fewer than 3 distinct points (after the merge): they give no face; their
  /// corners take the UVs of faces at the same points
  std::size_t degenerate_polygons = 0;
  /// polygons that pass through a point twice but have at least 3 distinct points: repeated
  /// consecutive points are dropped and the polygon is split where it passes through a point
  /// again; the pieces with at least 3 points are kept
  std::size_t polygons_with_repeated_points = 0;
  /// polygons with the same points as an earlier polygon (in the same cyclic order, either
  /// orientation): removed, their corners take the UVs of the polygon kept
  std::size_t duplicate_polygons = 0;
  /// edges shared by 3 or more polygons: the polygons are separated along them
  std::size_t non_manifold_edges = 0;
  /// points whose polygons form several fans (not on a non-manifold edge nor on a cut of a
  /// non-orientable piece): one vertex per fan
  std::size_t pinched_vertices = 0;
  /// pieces (polygons connected through edges shared by two polygons) that cannot be
  /// oriented consistently, like a Moebius strip: cut open
  std::size_t non_orientable_components = 0;
  /// vertices added to separate non-manifold edges and pinched vertices
  std::size_t vertices_split_non_manifold = 0;
  /// vertices added along the cuts of the non-orientable pieces
  std::size_t vertices_split_non_orientable = 0;
  /// polygons whose orientation was reversed: in each connected component the orientation
  /// of the majority of its polygons is kept
  std::size_t reoriented_polygons = 0;
  /// polygons that the oriented soup still could not attach to the mesh (none is expected:
  /// a safeguard): given their own copies of their points
  std::size_t detached_polygons = 0;
  /// @}

  /// \name Repairs of the mesh
  /// @{
  /// polygons of more than 3 points, triangulated
  std::size_t triangulated_polygons = 0;
  /// triangles made from them
  std::size_t triangles_from_polygons = 0;
  /// triangles of (numerically) zero area, `2A <= 1e-12 l^2` with `l` the longest edge,
  /// which no parameterizer accepts: removed from the mesh; their corners are placed on an
  /// edge of a face kept (a zero-area UV triangle)
  std::size_t zero_area_triangles = 0;
  /// vertices added to separate the fans of the vertices that the removal of the zero-area
  /// triangles left pinched
  std::size_t vertices_split_after_removal = 0;
  /// @}

  /// \name The result
  /// @{
  std::size_t vertices = 0;    ///< vertices of the repaired mesh
  std::size_t faces = 0;       ///< triangles of the repaired mesh
  std::size_t components = 0;  ///< connected components of the repaired mesh
  /// corners placed at a point of a face kept other than their own (corners of degenerate or
  /// zero-area polygons that share no edge with a face kept)
  std::size_t collapsed_corners = 0;
  /// corners whose point is on no face of the repaired mesh (of degenerate or zero-area
  /// polygons apart from every face kept): the corners of such a polygon all get the UV of
  /// the vertex of the repaired mesh nearest to the first of them
  std::size_t isolated_corners = 0;
  /// @}
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_SOUP_REPAIR_REPORT_H
