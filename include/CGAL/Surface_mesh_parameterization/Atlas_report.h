// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_ATLAS_REPORT_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_ATLAS_REPORT_H

/// \file Atlas_report.h
/// The options of a texture atlas (`compute_atlas()`) and what its computation did.

#include <CGAL/Surface_mesh_parameterization/Soup_repair_report.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgSurfaceMeshParameterizationMeasured
/// How a chart that misses the distortion bound is split (`Atlas_options::split`): each face
/// goes to the nearest of the seed faces, in a distance where a step between adjacent faces
/// costs the change of a feature plus the distance of their centroids over the square root of
/// the chart's area. A chart cut open by seams (`SEAMED_CHART`) whose one-to-one map is
/// \f$ r \f$ times over a bound (the larger of its area spread and its angle distortion over
/// their bounds) is split into \f$ 1 + \lceil \log_2 r \rceil \f$ parts, 2 to 8, any other
/// in two; the seeds past the first two are the faces farthest from the seeds so far. When the chart has sharp edges (dihedral angle of 30 degrees or
/// more), faces joined across smooth edges move together, so that a flat or smooth face of a
/// CAD part is never cut.
enum Atlas_split
{
  /// the feature is the normal (a step costs the angle between the normals); the seeds are
  /// two faces farthest apart, so that the cut falls where the surface turns the most between
  /// them (segmentation by normals, as xatlas's and D-charts' region growing)
  SPLIT_BY_NORMALS,
  /// the feature is the log of the conformal scale factor of the chart's map (UV area over 3D
  /// area); the seeds are the faces of the smallest and of the largest scale, so that the cut
  /// falls between the extremes (as Boundary First Flattening's cones, placed where the scale
  /// factor is extreme)
  SPLIT_BY_SCALE
};

/// \ingroup PkgSurfaceMeshParameterizationMeasured
/// The options of `compute_atlas()` and `compute_atlas_of_polygon_soup()`: the texture the
/// atlas is made for, and the distortion bound of its charts. (An options object rather than
/// named parameters: CGAL 5.5's named parameters are a closed list.)
struct Atlas_options
{
  /// The bound on a chart's area spread (`Atlas_chart_report::area_spread`, default 0.2):
  /// a chart whose one-to-one map exceeds it, or misses `max_angle_distortion` or
  /// `min_compactness`, is split into parts (`split`), recursively, until each part meets the
  /// bounds (a single triangle always does). A part of a chart whose map is one-to-one keeps
  /// that map where its own figures meet the bounds; the other parts are flattened again.
  /// Infinity (with `max_angle_distortion` infinite and `min_compactness` 0) keeps one chart
  /// per connected component wherever a one-to-one map exists.
  double max_area_spread = 0.2;
  /// The bound on a chart's angle distortion (the paper's, `Atlas_chart_report::angle_distortion`,
  /// default 0.2).
  double max_angle_distortion = 0.2;
  /// The bound on a chart's compactness (`Atlas_chart_report::compactness`, default 0.3):
  /// a long strip or a sparse ring sets the scale of the whole atlas and fills the square
  /// badly, so it is cut too, unless it is short: its longer side at most half the side of
  /// a square of the whole mesh's area (such a chart fits into the gaps of the packing). A
  /// chart that misses only this bound is cut across the longer side of its smallest bounding
  /// rectangle, at its middle, and its pieces keep their UVs (a part of a one-to-one map is
  /// one-to-one, with the same distortion: nothing is flattened again). Zero keeps every shape.
  double min_compactness = 0.3;
  /// How a chart that misses the bounds is split (default `SPLIT_BY_NORMALS`).
  Atlas_split split = SPLIT_BY_NORMALS;
  /// Texels per side of the square texture the atlas is packed for (default 1024, at least 8).
  unsigned int resolution = 1024;
  /// Texels kept free between any two charts and between a chart and the border of the square
  /// (default 2; at most `resolution / 4`).
  unsigned int gutter = 2;
};

/// \ingroup PkgSurfaceMeshParameterizationMeasured
/// How a chart of an atlas was flattened.
enum Chart_flattening
{
  /// a topological disk, flattened by `Conformal_parameterizer_3` (automatic border)
  DISK_CHART,
  /// any other surface, cut open by `compute_disk_seams()` and then flattened the same way
  SEAMED_CHART,
  /// the parameterizers gave no one-to-one map: the faces unfolded isometrically, one by one,
  /// across the edges of a spanning tree of the faces (each face keeps its shape)
  UNFOLDED_CHART
};

/// \ingroup PkgSurfaceMeshParameterizationMeasured
/// One chart of an atlas: a connected set of triangles of the repaired mesh with a one-to-one
/// map into the unit square.
struct Atlas_chart_report
{
  std::size_t faces = 0;                    ///< triangles of the repaired mesh in the chart
  Chart_flattening flattening = DISK_CHART;  ///< how it was flattened
  double area_3d = 0.;                      ///< its area in 3D (the input's unit)
  double area_uv = 0.;                      ///< its area in the atlas (the unit square's unit)
  /// the paper's angle distortion (`Parameterization_quality::angle_distortion`) of the
  /// chart cut open along its seams
  double angle_distortion = 0.;
  /// area-weighted mean of |log(UV area / 3D area)| over its faces, after one scale of the
  /// chart (0: every face keeps its share of the chart's area)
  double area_spread = 0.;
  /// its UV area over the square of the longer side of its smallest bounding rectangle
  /// (pi / 4 for a disk, 1 / n for a straight strip n times as long as wide)
  double compactness = 0.;
};

/// \ingroup PkgSurfaceMeshParameterizationMeasured
/// What `compute_atlas()` and `compute_atlas_of_polygon_soup()` did: the repairs of the input,
/// the charts, the packing, and the time of each step.
struct Atlas_report
{
  /// the repairs that made the input a triangle mesh of oriented, manifold components
  Soup_repair_report repair;
  /// the charts, by chart id (the ids written to the face or polygon chart map)
  std::vector<Atlas_chart_report> charts;
  double max_area_spread = 0.;       ///< the charts' bound on area spread (`Atlas_options`)
  double max_angle_distortion = 0.;  ///< the charts' bound on angle distortion (`Atlas_options`)
  double min_compactness = 0.;       ///< the charts' bound on compactness (`Atlas_options`)
  /// charts split or cut because they missed a bound (each adds at least one chart)
  std::size_t splits = 0;
  /// the area of all charts in the atlas over the area of the unit square
  double utilization = 0.;
  /// the scale of 3D lengths into the atlas (UV length per unit of 3D length), the same in
  /// every chart: UV area is proportional to 3D area across charts
  double texel_density = 0.;
  /// the charts' angle distortions, weighted by their 3D areas
  double angle_distortion = 0.;
  /// area-weighted mean of |log(UV area / 3D area)| over all faces, after one scale of the
  /// whole atlas (0: every face keeps its share of the area)
  double area_spread = 0.;
  /// \name Wall-clock time of the steps (seconds)
  /// @{
  double repair_seconds = 0.;   ///< the repair of the input (step 1)
  double chart_seconds = 0.;    ///< the charts: flattening, splits, figures (step 2)
  double packing_seconds = 0.;  ///< the packing into the square (step 3)
  double total_seconds = 0.;    ///< the whole call
  /// @}
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_ATLAS_REPORT_H
