// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_GEODESIC_METHOD_TAGS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_GEODESIC_METHOD_TAGS_H

/// \file geodesic_method_tags.h
/// Tags that select the algorithm of `geodesic_distance_map()`, `Geodesic_center_locator`
/// and `Geodesic_border_distance`.

namespace CGAL {

namespace Heat_method_3 {
struct Direct;  // the tags of CGAL's Heat_method_3 (Surface_mesh_geodesic_distances_3.h)
struct Intrinsic_Delaunay;
} // namespace Heat_method_3

namespace Surface_mesh_parameterization {

/// \ingroup PkgSurfaceMeshParameterizationMeasured
/// Fast marching on the triangles (Kimmel and Sethian 1998), with obtuse triangles split by
/// unfolding their neighbours; first-order accurate, \f$ O(n \log n) \f$. The paper's choice
/// (MBPGP). Implemented in this package (CGAL has none).
struct Fast_marching_geodesics {};

/// \ingroup PkgSurfaceMeshParameterizationMeasured
/// Shortest paths along the edges (Dijkstra, through Boost Graph): fast, but the distance
/// follows the edges, so it overestimates the geodesic distance (by up to ~8% on regular
/// triangulations, depending on the direction).
struct Dijkstra_geodesics {};

/// \ingroup PkgSurfaceMeshParameterizationMeasured
/// The heat method of Crane et al. through CGAL's `Heat_method_3` (`Mode`:
/// `CGAL::Heat_method_3::Direct`, the default, or `CGAL::Heat_method_3::Intrinsic_Delaunay`,
/// more accurate on poor triangulations). Two factorizations once; then each set of
/// sources costs two back-substitutions.
template <class Mode = CGAL::Heat_method_3::Direct>
struct Heat_method_geodesics {};

/// \ingroup PkgSurfaceMeshParameterizationMeasured
/// Exact geodesic distances on the polyhedral surface (Xin and Wang's algorithm) through
/// CGAL's `Surface_mesh_shortest_path`. The reference, and the slowest.
struct Exact_geodesics {};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_GEODESIC_METHOD_TAGS_H
