// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_PARAMETERIZATION_REPORT_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_PARAMETERIZATION_REPORT_H

/// \file Parameterization_report.h
/// What a call of the package's parameterizers did: the one report type of the package.

#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>

#include <array>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgSurfaceMeshParameterizationMeasured
/// Counters of the numerical work of a call: sparse factorizations and back-substitutions
/// (one per right-hand side), with their wall-clock times.
struct Solver_statistics
{
  int factorizations = 0;               ///< sparse factorizations
  int back_substitutions = 0;           ///< back-substitutions, one per right-hand side
  double factorization_seconds = 0.;    ///< time of the factorizations (seconds)
  double back_substitution_seconds = 0.;  ///< time of the back-substitutions (seconds)

  /// adds the counters of `other`.
  void add(const Solver_statistics& other)
  {
    factorizations += other.factorizations;
    back_substitutions += other.back_substitutions;
    factorization_seconds += other.factorization_seconds;
    back_substitution_seconds += other.back_substitution_seconds;
  }
};

/// \ingroup PkgSurfaceMeshParameterizationMeasured
/// The members of the border family. Each member is a path of borders from the member
/// itself (blend 0) to a convex border (blend 1); see `Automatic_border`.
enum Border_family
{
  /// the circle with arc-length angles (CGAL's circular border); its blend is 1
  CIRCLE,
  /// the measured border of the paper (a center and its distances to the border), blended
  /// toward the circle in polar coordinates (angle and normalized radius)
  MEASURED,
  /// the conformal border, blended toward the circle's turning angles (edge lengths kept)
  CONFORMAL,
  /// the conformal border with conformal lengths: at blend \f$ t \f$ the conformal member's
  /// turning angles, the border edge lengths scaled by \f$ e^{-t (u_i + u_j) / 2} \f$, with
  /// \f$ u \f$ the scale factors of the whole cotangent Laplacian that make the circle's
  /// turning angles conformal (Boundary First Flattening's general boundary problem); one more
  /// sparse factorization (`Conformal_length_border`)
  CONFORMAL_LENGTHS
};

/// \ingroup PkgSurfaceMeshParameterizationMeasured
/// A layout tried by a parameterizer: a border of the family and an interior map.
struct Border_candidate
{
  /// which member of the family
  Border_family family = CIRCLE;
  /// the blend toward the member's convex border (0: the member itself; 1 for the circle)
  double blend = 0.;
  /// whether the interior is the mean value coordinates map (a repair) rather than the
  /// discrete conformal map
  bool mean_value_interior = false;
  /// whether the layout is one-to-one
  bool valid = false;
  /// its angle distortion (`+infinity` when not valid)
  double objective = std::numeric_limits<double>::infinity();
  /// its area spread (`Distortion_bound`; `+infinity` when not valid)
  double area_spread = std::numeric_limits<double>::infinity();
  /// whether the layout is the holomorphic extension of the border's first coordinate
  /// (`Automatic_border`, step 5): the first coordinate the discrete conformal map's, the
  /// second its harmonic conjugate, the border moved accordingly
  bool holomorphic_extension = false;
};

/// \ingroup PkgSurfaceMeshParameterizationMeasured
///
/// The report of one call of a parameterizer of this package (`Conformal_parameterizer_3`,
/// `Measured_border_parameterizer_3`, `Conformal_border_parameterizer_3`): pass a pointer to
/// one as the optional last argument of `parameterize()`. A call fills the fields of the
/// steps it ran and leaves the others at their default values. Lengths are in the mesh's unit.
///
/// Border vertex `k` is the `k`-th vertex of the loop `halfedges_around_face(bhd, mesh)`,
/// starting at `source(bhd)`; border edge `k` joins border vertices `k` and `k + 1` (modulo
/// the loop's size). Vertices are named by their position in the range `vertices(mesh)`.
struct Parameterization_report
{
  Error_code status = ERROR_WRONG_PARAMETER;  ///< status of the call
  ///@{
  /// number of vertices and faces of the parameterized component
  std::size_t vertices = 0, faces = 0;
  ///@}

  /// \name Stage times (wall clock, seconds)
  /// @{
  /// input checks and indexing of the component
  double preparation_seconds = 0.;
  /// the measured border's step 1: locating the center (with, for the complete
  /// parameterizer, the factorization of \f$ L_{II} \f$ and the distance policy's
  /// preparation)
  double center_seconds = 0.;
  double distance_seconds = 0.;  ///< the measured border's step 2: the distances from the center to the border
  double border_map_seconds = 0.;  ///< the measured border's step 3: the polar border map
  double conformal_border_seconds = 0.;  ///< the conformal border's turning angles and polygon
  /// the conformal-length border's scale factors (the factorization of the whole cotangent
  /// Laplacian and one solve) and polygon, without the conformal border's own time
  double conformal_length_seconds = 0.;
  /// the interior solves, validity checks and angle distortions of the candidates before
  /// any repair (for the automatic border, the whole search)
  double interior_seconds = 0.;
  double repair_seconds = 0.;  ///< the repair
  double output_seconds = 0.;  ///< writing the UVs into the property maps
  double total_seconds = 0.;  ///< the whole call
  /// @}

  Solver_statistics statistics;  ///< factorizations and back-substitutions of the call, with their times

  /// \name The border polygon
  /// @{
  /// the UV of each border vertex, as written in the map (empty after a failure)
  std::vector<std::array<double, 2> > border_uv;
  bool border_convex = false;  ///< whether the border polygon was verified strictly convex
  /// @}

  /// \name The measured border (when a center was located)
  /// @{
  /// whether a center was located (also when a later step failed)
  bool has_center = false;
  std::size_t center = 0;  ///< the center vertex, by its position in `vertices(mesh)`
  /// distance from the center to each border vertex, as the distance policy measures it, in
  /// the mesh's unit (geodesic distances are lengths; the Poisson distance map's values are
  /// those of the paper's Eq. 1, which scale as lengths but are not lengths); 0 for a vertex
  /// that the policy could not reach, after `ERROR_DISTANCE_COMPUTATION_FAILED`
  std::vector<double> border_distances;
  std::size_t unreachable_border_vertices = 0;  ///< border vertices the distance policy could not reach
  /// polar angle \f$ \varphi_k \in [0, 2\pi) \f$ of each border vertex (the UV angle is
  /// \f$ -\varphi_k \f$)
  std::vector<double> border_angles;
  /// UV position of the polar origin: border vertex `k` is at
  /// `polar_origin + polar_scale * border_distances[k] * (cos(-phi_k), sin(-phi_k))`
  std::array<double, 2> polar_origin = {{0.5, 0.5}};
  double polar_scale = 1.;  ///< UV length per unit of `border_distances`
  /// @}

  /// \name The conformal border (when it was computed)
  /// @{
  /// 3D length of each border edge
  std::vector<double> edge_lengths;
  /// the length of each border edge in the closed polygon, before its uniform scaling into
  /// \f$ [0,1]^2 \f$
  std::vector<double> closed_lengths;
  std::vector<double> geodesic_curvatures;  ///< geodesic curvature \f$ \kappa_k = \pi - s_k \f$ of each border vertex
  std::vector<double> corrections;  ///< the correction \f$ h_k = (L_{BI} u_I)_k \f$
  std::vector<double> turning_angles;  ///< the target turning angle \f$ \tilde\kappa_k = \kappa_k - h_k \f$ (sum \f$ 2\pi \f$)
  /// the smallest blend toward the circle's turning angles at which the conformal polygon
  /// (for `Conformal_length_border`: the conformal-length polygon) is simple (0 when the
  /// conformal border itself is simple)
  double conformal_blend = 0.;
  /// `Conformal_length_border`: the scale factor \f$ u_k \f$ of each border vertex
  /// (\f$ L u = (\Omega_I, \kappa_B - c) \f$, the mean of \f$ u \f$ over the disk removed);
  /// the lengths of blend \f$ t \f$ are `edge_lengths` scaled by
  /// \f$ e^{-t (u_k + u_{k+1}) / 2} \f$ up to one uniform factor
  std::vector<double> scale_factors;
  /// @}

  /// \name The choice of the layout (the complete parameterizer)
  /// @{
  /// whether a layout of the chosen border (for the automatic border: of a member or a
  /// blend with the discrete conformal interior) was one-to-one before any repair
  bool valid_before_repair = true;
  /// faces flipped by the chosen border's layout before repair (for the automatic border:
  /// the fewest over the members' own borders)
  std::size_t flipped_faces_before_repair = 0;
  bool repaired = false;  ///< whether the result was repaired
  Border_family kept_border = CIRCLE;  ///< the member of the result
  double blend = 0.;  ///< the blend of the result toward its member's convex border (0: the member itself)
  /// whether the interior of the result is the mean value coordinates map (rather than the
  /// discrete conformal map)
  bool mean_value_interior = false;
  /// whether the result is the holomorphic extension of its border's first coordinate
  /// (`Border_candidate::holomorphic_extension`)
  bool holomorphic_extension = false;
  int repair_candidates = 0;  ///< layouts tried by the repair
  std::vector<Border_candidate> border_candidates;  ///< every layout tried, in the order tried (the repair's included)
  int chosen_candidate = -1;  ///< the index of the kept layout in `border_candidates` (-1 after a failure)
  /// @}
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_PARAMETERIZATION_REPORT_H
