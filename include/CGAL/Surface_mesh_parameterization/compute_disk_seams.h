// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_COMPUTE_DISK_SEAMS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_COMPUTE_DISK_SEAMS_H

/// \file compute_disk_seams.h
/// Automatic seams: the edges along which a closed, holed or higher-genus mesh is cut into a
/// topological disk, for `CGAL::Seam_mesh`.

#include <CGAL/Surface_mesh_parameterization/Default_sparse_cholesky_traits.h>
#include <CGAL/Surface_mesh_parameterization/Disk_seams_report.h>
#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/internal/seams/cut_graph.h>
#include <CGAL/Surface_mesh_parameterization/internal/seams/disk_cut.h>
#include <CGAL/Surface_mesh_parameterization/internal/seams/surface_indexing.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/property_map.h>
#include <CGAL/Named_function_parameters.h>

#include <chrono>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

namespace internal {

inline Error_code error_code_of(Disk_seams_problem problem)
{
  switch(problem)
  {
  case NO_PROBLEM:            return OK;
  case EMPTY_INPUT_MESH:      return ERROR_EMPTY_MESH;
  case FACE_NOT_A_TRIANGLE:   return ERROR_NON_TRIANGULAR_MESH;
  case NON_FINITE_COORDINATE: return ERROR_NON_FINITE_COORDINATES;
  case ZERO_AREA_FACE:        return ERROR_DEGENERATE_FACE;
  case SOLVER_FAILURE:        return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
  default:                    return ERROR_NO_TOPOLOGICAL_DISC;
  }
}

// The seams of a mesh into the maps and the report: the indexed surface, its cut, the maps.
template <class TriangleMesh, class VertexPointMap, class AvoidedEdgeMap, class SeamEdgeMap, class SeamVertexMap>
Disk_seams_problem cut_and_write_seams(const TriangleMesh& tm, VertexPointMap vpm, AvoidedEdgeMap avoided,
                                      SeamEdgeMap seam_edges, SeamVertexMap seam_vertices,
                                      const Disk_seams_options& options, Disk_seams_report& report)
{
  Indexed_surface s;
  Surface_indexer<TriangleMesh> indexer(tm, s, report);
  Disk_seams_problem problem = indexer.index(vpm);
  if(problem != NO_PROBLEM)
    return problem;
  indexer.avoid_edges(avoided);
  report.genus = s.genus();
  report.number_of_border_loops = s.border_loops.size();
  std::vector<char> cut;
  std::vector<int> cones;
  problem = cut_to_disk<Default_sparse_cholesky_traits>(s, options, cut, cones, report);
  if(problem == NO_PROBLEM)
    indexer.write_seams(cut, cones, seam_edges, seam_vertices);
  return problem;
}

} // namespace internal

/// \ingroup PkgSurfaceMeshParameterizationMeasured
///
/// computes seams that cut the connected manifold triangle mesh `tm` into a topological disk,
/// and writes them into the maps that `CGAL::Seam_mesh` takes: `seam_edges` gets `true` for
/// every seam edge and `false` for every other edge, `seam_vertices` `true` for every vertex
/// of a seam edge and `false` for the others. Border edges are never seams (they are cut
/// already). Nothing is written on failure.
///
/// The options and the report are optional arguments before the named parameters (which come
/// last, as in CGAL); they are defined in Disk_seams_report.h. A call with a report:
/// \code
/// SMP::Disk_seams_report report;
/// SMP::compute_disk_seams(tm, seam_edges, seam_vertices, SMP::Disk_seams_options(), &report);
/// \endcode
/// After `Seam_mesh seam_mesh(tm, seam_edges, seam_vertices)`, call
/// `seam_mesh.set_seam_edges_number(report.number_of_seam_edges)` (the seam mesh counts the
/// seams that `add_seam()` marks, not those found in the maps), then parameterize it with its
/// longest border: `CGAL::Polygon_mesh_processing::longest_border(seam_mesh).first`.
///
/// The cut, for a surface of genus \f$ g \f$ with \f$ b \f$ border loops:
/// - **handles and border loops**: the greedy system of \f$ 2g \f$ loops (closed surface) or
///   \f$ 2g + b - 1 \f$ arcs from border to border (Erickson and Whittlesey, "Greedy optimal
///   homotopy and homology generators", 2005): Eppstein's tree-cotree decomposition with the
///   shortest path tree (Dijkstra on the edges, from a vertex on a closed surface, from the
///   whole border otherwise) as the primal tree, and the maximum spanning tree of the dual
///   graph, weighted by the length of the loop each edge closes, as the cotree. The arcs join
///   every hole to the others and to the outer border by short paths; with
///   `join_holes = false` a surface of genus 0 keeps its holes instead. Dangling trees are
///   then pruned.
/// - **cones**: on a closed surface of genus 0 the cut passes through a few cone vertices,
///   `Disk_seams_options::default_number_of_cones` by default, placed greedily where the
///   conformal scale factor is most extreme (Sawhney and Crane, "Boundary First Flattening",
///   2017, cone placement): \f$ L u = \Omega \f$ with \f$ L \f$ the cotangent Laplacian,
///   \f$ \Omega \f$ the angle defects, \f$ u = 0 \f$ on the border, the cut and the cones
///   placed so far (the first cone of a closed surface: the extreme of the mean-corrected
///   problem). One sparse Cholesky factorization, then one back-substitution per cone.
///   The cones are joined to the cut by shortest edge paths, nearest first (a greedy Steiner
///   tree). A conformal flattening that keeps the border lengths (scale factor 0 on the
///   border) has \f$ \log(A_{uv}/A_{3D}) = 2u \f$: cutting through the extremes of
///   \f$ u \f$ lowers the area distortion.
/// - **shortening**: each path of the cut between two branch points, cones or border
///   vertices is replaced by the shortest edge path between the same points that leaves and
///   enters them on the same sides and meets the rest of the cut nowhere else, when it is
///   shorter and the cut stays a disk.
///
/// The result is deterministic (ties go to the lowest index in the order of `vertices(tm)`
/// and `edges(tm)`) and does not depend on rigid motions of the mesh, up to rounding.
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`.
/// \tparam SeamEdgeMap a model of `WritablePropertyMap` with `edge_descriptor` as key and
///         `bool` as value.
/// \tparam SeamVertexMap a model of `WritablePropertyMap` with `vertex_descriptor` as key and
///         `bool` as value.
/// \param tm the mesh to cut: connected, manifold, made of triangles.
/// \param seam_edges receives `true` for every seam edge, `false` for every other edge.
/// \param seam_vertices receives `true` for every vertex of a seam edge, `false` for the others.
/// \param options the number of cones, the treatment of holes, the shortening.
/// \param report when not null, receives the report of the call: the counts, the cones and the
///        seam length, or what failed (`report->problem`, `disk_seams_problem_message()`).
/// \param np an optional sequence of named parameters among the ones listed below:
///   - `vertex_point_map`: a model of `ReadablePropertyMap` from `vertex_descriptor` to a 3D
///     point type of a CGAL kernel; default: `get(CGAL::vertex_point, tm)`.
///   - `edge_is_constrained_map`: a model of `ReadablePropertyMap` from `edge_descriptor` to
///     `bool`: the edges the seams avoid (the diagonals that triangulate a polygon of the
///     user's mesh, say). A constrained edge counts, in every length the cut compares, as
///     longer than all the other edges together: a seam runs along one only where every cut
///     of the surface would cross more (never when the constrained edges are the diagonals of
///     polygons, since a cut can go around a polygon). Default: no edge is constrained.
/// \return `OK`; `ERROR_EMPTY_MESH`, `ERROR_NON_TRIANGULAR_MESH`,
///         `ERROR_NON_FINITE_COORDINATES`, `ERROR_DEGENERATE_FACE` (with cones),
///         `ERROR_CANNOT_SOLVE_LINEAR_SYSTEM`, or `ERROR_NO_TOPOLOGICAL_DISC` for a
///         non-manifold mesh or several components. The report's `problem` names the problem
///         precisely.
template <class TriangleMesh, class SeamEdgeMap, class SeamVertexMap,
          class NamedParameters = parameters::Default_named_parameters>
Error_code compute_disk_seams(const TriangleMesh& tm, SeamEdgeMap seam_edges, SeamVertexMap seam_vertices,
                              const Disk_seams_options& options = Disk_seams_options(),
                              Disk_seams_report* report = nullptr,
                              const NamedParameters& np = parameters::default_values())
{
  typedef std::chrono::steady_clock Clock;
  const Clock::time_point start = Clock::now();
  Disk_seams_report local_report;
  Disk_seams_report& r = report ? *report : local_report;
  r = Disk_seams_report();
  const auto vpm = parameters::choose_parameter(parameters::get_parameter(np, internal_np::vertex_point),
                                                get_const_property_map(vertex_point, tm));
  typedef typename boost::graph_traits<TriangleMesh>::edge_descriptor edge_descriptor;
  const auto avoided = parameters::choose_parameter(parameters::get_parameter(np, internal_np::edge_is_constrained),
                                                    Constant_property_map<edge_descriptor, bool>(false));
  r.problem = internal::cut_and_write_seams(tm, vpm, avoided, seam_edges, seam_vertices, options, r);
  r.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return internal::error_code_of(r.problem);
}

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_COMPUTE_DISK_SEAMS_H
