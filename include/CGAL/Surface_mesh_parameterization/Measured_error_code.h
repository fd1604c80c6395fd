// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_MEASURED_ERROR_CODE_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_MEASURED_ERROR_CODE_H

/// \file Measured_error_code.h
/// Error codes of the measured boundary parameterization package, and their messages.

#include <CGAL/Surface_mesh_parameterization/Error_code.h>

namespace CGAL {
namespace Surface_mesh_parameterization {

// CGAL's `Error_code` has the enumerators 0..9, so (C++17 [dcl.enum]/8) every value in
// 0..15 is a valid `Error_code` value. The package uses 10..15 for the failures that CGAL's
// list cannot name. If a future CGAL grows its list, this assertion stops the build rather
// than letting two meanings share one number.
static_assert(static_cast<int>(ERROR_WRONG_PARAMETER) == 9,
              "CGAL's Error_code list changed: revisit Measured_error_code.h");

/// \name Package-specific error codes
/// Failures that CGAL's `Error_code` list cannot name. They are values of CGAL's
/// `Error_code` type, so they travel unchanged through CGAL's own parameterizers (for
/// example through `Fixed_border_parameterizer_3::parameterize()`, which forwards the
/// border parameterizer's status). Use `get_measured_error_message()` for the text of any
/// code, CGAL's or ours (CGAL 5.5's `get_error_message()` is off by one for codes >= 4).
/// @{

/// A face of the mesh has (numerically) zero area: its longest edge `l` and its doubled
/// area `2A` satisfy `2A <= 1e-12 l^2`, so its cotangent weights are not defined.
inline constexpr Error_code ERROR_DEGENERATE_FACE = static_cast<Error_code>(10);
/// A vertex coordinate is infinite or NaN.
inline constexpr Error_code ERROR_NON_FINITE_COORDINATES = static_cast<Error_code>(11);
/// Every vertex of the component lies on its border loop: there is no interior vertex (no
/// unknown of the interior solve, no center for the polar border map).
inline constexpr Error_code ERROR_NO_INTERIOR_VERTEX = static_cast<Error_code>(12);
/// The border halfedge is null, or it is not a border halfedge of the mesh.
inline constexpr Error_code ERROR_INVALID_BORDER_HALFEDGE = static_cast<Error_code>(13);
/// The border distance policy could not measure the distance from the center to some
/// border vertex (a straightest geodesic that does not reach it, a geodesic distance that
/// is not positive and finite). The report of the call counts such vertices
/// (`Parameterization_report::unreachable_border_vertices`).
inline constexpr Error_code ERROR_DISTANCE_COMPUTATION_FAILED = static_cast<Error_code>(14);
/// A border polygon cannot be laid out:
/// - the measured border's polar map is degenerate: two consecutive border vertices are seen
///   in the same direction from the center (polar angles less than 1e-12 rad apart), or a
///   border distance is not a positive finite number;
/// - the conformal border cannot be built: a border edge has zero length, a target turning
///   angle is not finite, or the polygon cannot close (the edge directions do not span the
///   plane, or a closed edge length would not stay positive) even when blended to the convex
///   end of its path;
/// - a polygon has no extent to scale into \f$ [0,1]^2 \f$.
///
/// `Automatic_border` leaves out a member that cannot be built instead of failing. The
/// message of `get_measured_error_message()` is "The polar border map is degenerate" for
/// every cause.
inline constexpr Error_code ERROR_DEGENERATE_BORDER_MAP = static_cast<Error_code>(15);

/// @}

/// \ingroup PkgSurfaceMeshParameterizationMeasured
/// returns the message of any code returned by this package: CGAL's codes 0..9 (with the
/// correct message for each, unlike CGAL 5.5's `get_error_message()`) and the
/// package-specific codes 10..15 above.
inline const char* get_measured_error_message(int code)
{
  switch(code)
  {
  case OK:                               return "Success";
  case ERROR_EMPTY_MESH:                 return "Input mesh is empty";
  case ERROR_NON_TRIANGULAR_MESH:        return "Input mesh is not triangular";
  case ERROR_NO_TOPOLOGICAL_DISC:        return "Input mesh is not a topological disc";
  case ERROR_NO_TOPOLOGICAL_BALL:        return "Input mesh is not a topological ball";
  case ERROR_BORDER_TOO_SHORT:           return "This border parameterization requires a longer border";
  case ERROR_NON_CONVEX_BORDER:          return "This parameterization method requires a convex border";
  case ERROR_CANNOT_SOLVE_LINEAR_SYSTEM: return "Cannot solve linear system";
  case ERROR_NO_1_TO_1_MAPPING:          return "Parameterization failed: no one-to-one mapping";
  case ERROR_WRONG_PARAMETER:            return "A method received an unexpected parameter";
  case ERROR_DEGENERATE_FACE:            return "Input mesh has a face of zero area";
  case ERROR_NON_FINITE_COORDINATES:     return "Input mesh has a non-finite vertex coordinate";
  case ERROR_NO_INTERIOR_VERTEX:         return "Input mesh has no interior vertex to serve as center";
  case ERROR_INVALID_BORDER_HALFEDGE:    return "The given halfedge is null or not a border halfedge";
  case ERROR_DISTANCE_COMPUTATION_FAILED:return "The distance from the center to a border vertex could not be computed";
  case ERROR_DEGENERATE_BORDER_MAP:      return "The polar border map is degenerate";
  default:                               return "Unknown error";
  }
}

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_MEASURED_ERROR_CODE_H
