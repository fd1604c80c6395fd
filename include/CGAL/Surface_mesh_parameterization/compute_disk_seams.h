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

#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/internal/seams/cone_placement.h>
#include <CGAL/Surface_mesh_parameterization/internal/seams/cut_graph.h>
#include <CGAL/Surface_mesh_parameterization/Default_sparse_cholesky_traits.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_report.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/factorized_system.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Default.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgSurfaceMeshParameterizationMeasured
/// Options of `compute_disk_seams()`.
struct Disk_seams_options
{
  /// The number of cones on a closed surface of genus 0 when `number_of_cones` is negative.
  /// Chosen by measurement (`seam_comparison --sweep`, `benchmark/README.md`): on the closed
  /// meshes of genus 0 of the project, flattened with the conformal border, the median
  /// deviation of the log area ratios falls from 1.35 (2 cones) to 0.78 (4) and 0.39 (8),
  /// then only to 0.30 with 16 cones, for 15 to 30% more seam length; 8 is the smallest count
  /// within 1.3 times the 16-cone figure, and the angle distortion is below 0.05 on all three.
  static constexpr int default_number_of_cones = 8;

  /// Cones to place: the cut passes through that many vertices where the conformal scale
  /// factor is most extreme (see `compute_disk_seams()`). Negative (the default): automatic,
  /// `default_number_of_cones` on a closed surface of genus 0 (but no more than one vertex in
  /// 16, so that a small mesh keeps interior vertices: an octahedron gets 2) and none
  /// otherwise. A closed surface of genus 0 gets at least 2, the fewest a cut can end at.
  int number_of_cones = -1;
  /// Whether the cut joins every border loop (`true`, the default), or, on a surface of
  /// genus 0, leaves the holes (the border loops other than the longest) open for the
  /// parameterizer's virtual hole filling (`Parameterization_patch_3::build_disk()`). A
  /// surface with handles always gets its holes joined: its loops need the border to end on.
  bool join_holes = true;
  /// Whether each path of the cut between two branch points is replaced by a shorter path
  /// between the same points, on the same sides, when the cut stays a disk (default `true`).
  bool shorten = true;
  /// The most passes of shortening over all paths (default 3).
  int shortening_passes = 3;
};

/// \ingroup PkgSurfaceMeshParameterizationMeasured
/// What made `compute_disk_seams()` fail, or `NO_PROBLEM`.
enum Disk_seams_problem
{
  /// success
  NO_PROBLEM,
  /// the mesh has no face
  EMPTY_INPUT_MESH,
  /// a face is not a triangle (`problem_face` in the report)
  FACE_NOT_A_TRIANGLE,
  /// a vertex has two or more fans of faces, or an edge has no face (`problem_vertex`)
  NON_MANIFOLD_VERTEX,
  /// the faces form several connected components (`number_of_components`)
  SEVERAL_COMPONENTS,
  /// a vertex coordinate is infinite or NaN (`problem_vertex`)
  NON_FINITE_COORDINATE,
  /// a face has zero area, so the cone placement has no cotangent weights (`problem_face`)
  ZERO_AREA_FACE,
  /// the sparse solver of the cone placement failed
  SOLVER_FAILURE,
  /// the cut does not leave a disk (an internal failure; it should not happen)
  CUT_NOT_A_DISK
};

/// \ingroup PkgSurfaceMeshParameterizationMeasured
/// The result of `compute_disk_seams()`.
template <class TriangleMesh>
struct Disk_seams_report
{
  /// Vertex type of the mesh
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  /// Face type of the mesh
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor   face_descriptor;

  /// `NO_PROBLEM`, or what failed
  Disk_seams_problem problem = NO_PROBLEM;
  /// the offending vertex (`NON_MANIFOLD_VERTEX`, `NON_FINITE_COORDINATE`)
  vertex_descriptor problem_vertex = boost::graph_traits<TriangleMesh>::null_vertex();
  /// the offending face (`FACE_NOT_A_TRIANGLE`, `ZERO_AREA_FACE`)
  face_descriptor problem_face = boost::graph_traits<TriangleMesh>::null_face();
  /// connected components of the faces
  std::size_t number_of_components = 0;
  /// genus of the mesh
  int genus = 0;
  /// border loops of the mesh
  std::size_t number_of_border_loops = 0;
  /// loops (closed surface: 2g) or arcs (with border: 2g + b - 1) of the greedy system
  int number_of_loops = 0;
  /// seam edges written
  std::size_t number_of_seam_edges = 0;
  /// total 3D length of the seam edges
  double seam_length = 0.;
  /// the cones, in the order they were placed
  std::vector<vertex_descriptor> cones;
  /// whether the border loops were joined by the cut (see `Disk_seams_options::join_holes`)
  bool holes_joined = false;
  /// cut paths replaced by shorter ones
  int shortened_paths = 0;
  /// factorizations and back-substitutions of the cone placement
  Solver_statistics statistics;
  /// time of the call (wall clock, seconds)
  double seconds = 0.;
};

/// \ingroup PkgSurfaceMeshParameterizationMeasured
/// the message of a `Disk_seams_problem`, naming the problem.
inline const char* disk_seams_problem_message(Disk_seams_problem problem)
{
  switch(problem)
  {
  case NO_PROBLEM:            return "no problem";
  case EMPTY_INPUT_MESH:      return "the mesh has no face";
  case FACE_NOT_A_TRIANGLE:   return "the mesh has a face that is not a triangle";
  case NON_MANIFOLD_VERTEX:   return "the mesh is not a manifold: a vertex joins two or more fans of faces";
  case SEVERAL_COMPONENTS:    return "the mesh has several connected components; cut each one separately";
  case NON_FINITE_COORDINATE: return "the mesh has a non-finite vertex coordinate";
  case ZERO_AREA_FACE:        return "the mesh has a face of zero area (the cone placement needs cotangent weights)";
  case SOLVER_FAILURE:        return "the sparse solver of the cone placement failed";
  case CUT_NOT_A_DISK:        return "internal error: the cut does not leave a disk";
  }
  return "unknown problem";
}

namespace internal {

// The mesh's descriptors and indices while it is indexed.
template <class TriangleMesh>
struct Surface_indexing
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typename boost::property_map<TriangleMesh, CGAL::dynamic_vertex_property_t<int> >::const_type vertex_index;
  typename boost::property_map<TriangleMesh, CGAL::dynamic_edge_property_t<int> >::const_type edge_index;
  typename boost::property_map<TriangleMesh, CGAL::dynamic_face_property_t<int> >::const_type face_index;
  std::vector<typename GT::vertex_descriptor> vertex_of;  // vertices in faces only
  std::vector<typename GT::edge_descriptor> edge_of;

  explicit Surface_indexing(const TriangleMesh& tm)
    : vertex_index(get(CGAL::dynamic_vertex_property_t<int>(), tm)),
      edge_index(get(CGAL::dynamic_edge_property_t<int>(), tm)),
      face_index(get(CGAL::dynamic_face_property_t<int>(), tm))
  { }
};

// Vertices (points, finite) and edges (ends, lengths, border flags) of the indexed surface.
template <class TriangleMesh, class VertexPointMap>
Disk_seams_problem index_vertices_and_edges(const TriangleMesh& tm, VertexPointMap vpm, Indexed_surface& s,
                                            Surface_indexing<TriangleMesh>& ix, Disk_seams_report<TriangleMesh>& report)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  for(typename GT::vertex_descriptor v : vertices(tm))
  {
    put(ix.vertex_index, v, -1);
    if(halfedge(v, tm) == GT::null_halfedge())
      continue;
    put(ix.vertex_index, v, static_cast<int>(ix.vertex_of.size()));
    ix.vertex_of.push_back(v);
    const auto& p = get(vpm, v);
    s.points.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    if(!s.points.back().allFinite())
    {
      report.problem_vertex = v;
      return NON_FINITE_COORDINATE;
    }
  }
  for(typename GT::edge_descriptor e : edges(tm))
  {
    put(ix.edge_index, e, static_cast<int>(ix.edge_of.size()));
    ix.edge_of.push_back(e);
    const typename GT::halfedge_descriptor h = halfedge(e, tm);
    const int a = get(ix.vertex_index, source(h, tm)), b = get(ix.vertex_index, target(h, tm));
    s.edge_vertices.push_back({{a, b}});
    s.edge_lengths.push_back((s.points[static_cast<std::size_t>(a)] - s.points[static_cast<std::size_t>(b)]).norm());
    s.edge_faces.push_back({{-1, -1}});
    s.border_edge.push_back(is_border(e, tm) ? 1 : 0);
    if(is_border(h, tm) && is_border(opposite(h, tm), tm))
    {
      report.problem_vertex = source(h, tm);
      return NON_MANIFOLD_VERTEX;  // an edge in no face
    }
  }
  return NO_PROBLEM;
}

// Faces (triangles only) and the faces of every edge.
template <class TriangleMesh>
Disk_seams_problem index_faces(const TriangleMesh& tm, Indexed_surface& s, Surface_indexing<TriangleMesh>& ix,
                               Disk_seams_report<TriangleMesh>& report)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  for(typename GT::face_descriptor f : faces(tm))
  {
    put(ix.face_index, f, static_cast<int>(s.faces.size()));
    std::array<int, 3> t, te;
    std::size_t k = 0;
    for(typename GT::halfedge_descriptor h : halfedges_around_face(halfedge(f, tm), tm))
    {
      if(k == 3)
        break;
      t[k] = get(ix.vertex_index, source(h, tm));
      te[k] = get(ix.edge_index, edge(h, tm));
      ++k;
    }
    if(k != 3 || next(next(next(halfedge(f, tm), tm), tm), tm) != halfedge(f, tm))
    {
      report.problem_face = f;
      return FACE_NOT_A_TRIANGLE;
    }
    s.faces.push_back(t);
    s.face_edges.push_back(te);
  }
  for(typename GT::edge_descriptor e : edges(tm))
  {
    const typename GT::halfedge_descriptor h = halfedge(e, tm);
    std::array<int, 2>& ef = s.edge_faces[static_cast<std::size_t>(get(ix.edge_index, e))];
    if(!is_border(h, tm))
      ef[0] = get(ix.face_index, face(h, tm));
    if(!is_border(opposite(h, tm), tm))
      ef[ef[0] < 0 ? 0 : 1] = get(ix.face_index, face(opposite(h, tm), tm));
  }
  return NO_PROBLEM;
}

// The rotation of edges around every vertex; a manifold vertex has one fan, so all its
// corners lie around one cycle of halfedges with at most one border gap.
template <class TriangleMesh>
Disk_seams_problem index_rotations(const TriangleMesh& tm, Indexed_surface& s, Surface_indexing<TriangleMesh>& ix,
                                   Disk_seams_report<TriangleMesh>& report)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  std::vector<int> corners(ix.vertex_of.size(), 0);
  for(const std::array<int, 3>& t : s.faces)
    for(int v : t)
      ++corners[static_cast<std::size_t>(v)];
  s.border_vertex.assign(ix.vertex_of.size(), 0);
  s.ring_offsets.assign(1, 0);
  for(std::size_t i = 0; i < ix.vertex_of.size(); ++i)
  {
    const typename GT::vertex_descriptor v = ix.vertex_of[i];
    int around = 0, gaps = 0;
    typename GT::halfedge_descriptor start = halfedge(v, tm);
    for(typename GT::halfedge_descriptor h : halfedges_around_target(halfedge(v, tm), tm))
    {
      if(is_border(h, tm))
      {
        ++gaps;
        start = h;
      }
      else
        ++around;
    }
    if(around != corners[i] || gaps > 1)
    {
      report.problem_vertex = v;
      return NON_MANIFOLD_VERTEX;
    }
    s.border_vertex[i] = (gaps == 1) ? 1 : 0;
    for(typename GT::halfedge_descriptor h : halfedges_around_target(start, tm))
      s.ring_edges.push_back(get(ix.edge_index, edge(h, tm)));
    s.ring_offsets.push_back(static_cast<int>(s.ring_edges.size()));
  }
  return NO_PROBLEM;
}

// The connected components of the faces (one is required) and the border loops.
template <class TriangleMesh>
Disk_seams_problem index_components_and_borders(const TriangleMesh& tm, Indexed_surface& s,
                                                Surface_indexing<TriangleMesh>& ix,
                                                Disk_seams_report<TriangleMesh>& report)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  Disjoint_sets pieces(s.faces.size());
  std::size_t components = s.faces.size();
  for(const std::array<int, 2>& ef : s.edge_faces)
    if(ef[1] >= 0 && pieces.unite(static_cast<std::size_t>(ef[0]), static_cast<std::size_t>(ef[1])))
      --components;
  report.number_of_components = components;
  if(components > 1)
    return SEVERAL_COMPONENTS;
  auto walked = get(CGAL::dynamic_halfedge_property_t<bool>(), tm);
  for(typename GT::halfedge_descriptor h : halfedges(tm))
    put(walked, h, false);
  for(typename GT::halfedge_descriptor h : halfedges(tm))
  {
    if(!is_border(h, tm) || get(walked, h))
      continue;
    s.border_loops.emplace_back();
    for(typename GT::halfedge_descriptor b : halfedges_around_face(h, tm))
    {
      put(walked, b, true);
      s.border_loops.back().push_back(get(ix.vertex_index, source(b, tm)));
    }
  }
  return NO_PROBLEM;
}

// The indexed surface of a mesh (vertices in faces only), with the descriptors of its
// vertices and edges in `ix`; checks triangles, manifold vertices, one component and finite
// points, in this order of concern: coordinates, edges in no face, faces, vertices, components.
template <class TriangleMesh, class VertexPointMap>
Disk_seams_problem index_surface(const TriangleMesh& tm, VertexPointMap vpm, Indexed_surface& s,
                                 Surface_indexing<TriangleMesh>& ix, Disk_seams_report<TriangleMesh>& report)
{
  if(faces(tm).empty())
    return EMPTY_INPUT_MESH;
  Disk_seams_problem problem = index_vertices_and_edges(tm, vpm, s, ix, report);
  if(problem == NO_PROBLEM)
    problem = index_faces(tm, s, ix, report);
  if(problem == NO_PROBLEM)
    problem = index_rotations(tm, s, ix, report);
  if(problem == NO_PROBLEM)
    problem = index_components_and_borders(tm, s, ix, report);
  return problem;
}

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

// The longest border loop (3D length), or -1.
inline int longest_border_loop(const Indexed_surface& s)
{
  int best = -1;
  double best_length = -1.;
  for(std::size_t l = 0; l < s.border_loops.size(); ++l)
  {
    const std::vector<int>& loop = s.border_loops[l];
    double length = 0.;
    for(std::size_t k = 0; k < loop.size(); ++k)
      length += (s.points[static_cast<std::size_t>(loop[k])] - s.points[static_cast<std::size_t>(loop[(k + 1) % loop.size()])]).norm();
    if(length > best_length)
    {
      best_length = length;
      best = static_cast<int>(l);
    }
  }
  return best;
}

// Total length of the cut.
inline double cut_length(const Indexed_surface& s, const std::vector<char>& cut)
{
  double length = 0.;
  for(std::size_t e = 0; e < cut.size(); ++e)
    length += cut[e] ? s.edge_lengths[e] : 0.;
  return length;
}

// The greedy system of loops or arcs, pruned and shortened, into `cut` (all zero); returns
// the number of loops or arcs. On a closed surface, the greedy system is the shortest
// system of loops through its root (Erickson and Whittlesey), and the root matters: the
// system is computed from vertex 0, then from one end of each closing edge of that system
// (the point of its loop farthest from the root, where a better root often lies: on a torus
// rooted on the outer equator, the meridian's far point is on the inner equator, the root of
// the shortest system), at most 8 roots; the shortest system is kept.
inline int shortest_system(const Indexed_surface& s, const Disk_seams_options& options,
                           const std::vector<char>& terminal, std::vector<char>& cut, int& shortened)
{
  auto system_from = [&](int root, std::vector<char>& c, std::vector<int>* closing, int& replaced) {
    const int loops = greedy_system_of_cuts(s, root, c, closing);
    prune_cut(s, terminal, c);
    replaced = options.shorten ? shorten_cut(s, terminal, 1, options.shortening_passes, c) : 0;
    return loops;
  };
  std::vector<int> closing;
  const int loops = system_from(0, cut, &closing, shortened);
  if(!s.border_loops.empty())
    return loops;
  double best = cut_length(s, cut);
  std::vector<char> other;
  for(std::size_t k = 0; k < closing.size() && k < 7; ++k)
  {
    other.assign(cut.size(), 0);
    int replaced = 0;
    system_from(s.edge_vertices[static_cast<std::size_t>(closing[k])][0], other, nullptr, replaced);
    const double length = cut_length(s, other);
    if(length < best)
    {
      best = length;
      cut.swap(other);
      shortened = replaced;
    }
  }
  return loops;
}

// The cut on the indexed surface: the greedy system of loops or arcs, the cones joined to it,
// pruned and shortened. `cut` gets one flag per edge, `cones` the cone vertices.
template <class SolverTraits, class TriangleMesh>
Disk_seams_problem cut_to_disk(const Indexed_surface& s, const Disk_seams_options& options,
                               std::vector<char>& cut, std::vector<int>& cones,
                               Disk_seams_report<TriangleMesh>& report)
{
  const std::size_t n = static_cast<std::size_t>(s.number_of_vertices());
  const std::size_t b = s.border_loops.size();
  const int genus = s.genus();
  const bool join = options.join_holes || genus > 0;
  std::vector<char> terminal(n, 0);
  const long holes = join ? 0 : (b >= 2 ? long(b) - 1 : 0);
  cut.assign(static_cast<std::size_t>(s.number_of_edges()), 0);
  if(genus > 0 || (join && b >= 2))
    report.number_of_loops = shortest_system(s, options, terminal, cut, report.shortened_paths);

  const int count = (options.number_of_cones >= 0) ? options.number_of_cones
                    : (b == 0 && genus == 0)
                      ? (std::min)(Disk_seams_options::default_number_of_cones, static_cast<int>(n / 16))
                      : 0;
  const int wanted = (b == 0 && genus == 0) ? (std::max)(count, 2) : count;
  // on a genus-0 surface whose holes stay open, the cut ends on the longest border only
  std::vector<char> main_border(n, 0), avoided(n, 0);
  const int main_loop = longest_border_loop(s);
  for(std::size_t l = 0; l < b; ++l)
    for(int v : s.border_loops[l])
      (join || static_cast<int>(l) == main_loop ? main_border : avoided)[static_cast<std::size_t>(v)] = 1;
  if(wanted > 0)
  {
    std::vector<char> fixed(n, 0);
    for(int e = 0; e < s.number_of_edges(); ++e)
      if(cut[static_cast<std::size_t>(e)])
        for(int v : s.edge_vertices[static_cast<std::size_t>(e)])
          fixed[static_cast<std::size_t>(v)] = 1;
    for(std::size_t v = 0; v < n; ++v)
      fixed[v] = fixed[v] || s.border_vertex[v];
    Cone_placement<SolverTraits> placement(s, fixed);
    const Error_code status = placement.place(wanted, cones);
    report.statistics = placement.statistics();
    if(status == ERROR_DEGENERATE_FACE)
      return ZERO_AREA_FACE;
    if(status != OK)
      return SOLVER_FAILURE;
    std::vector<char> connected(n, 0);
    for(std::size_t v = 0; v < n; ++v)
      connected[v] = (fixed[v] && !avoided[v]) || main_border[v];
    if(!cones.empty() && std::find(connected.begin(), connected.end(), char(1)) == connected.end())
      connected[static_cast<std::size_t>(cones.front())] = 1;  // closed genus 0: start at a cone
    for(int c : cones)
      terminal[static_cast<std::size_t>(c)] = 1;
    if(!connect_terminals(s, cones, avoided, connected, cut))
      return CUT_NOT_A_DISK;
    prune_cut(s, terminal, cut);
  }
  if(options.shorten && !cones.empty())
    report.shortened_paths += shorten_cut(s, terminal, 1 - holes, options.shortening_passes, cut);
  report.holes_joined = join && b >= 2;
  if(!is_disk_cut(s, cut, 1 - holes))
    return CUT_NOT_A_DISK;
  return NO_PROBLEM;
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
/// \param report the counts, the cones and the seam length, or what failed.
/// \param options the number of cones, the treatment of holes, the shortening.
/// \param np optional named parameter `vertex_point_map`.
/// \return `OK`; `ERROR_EMPTY_MESH`, `ERROR_NON_TRIANGULAR_MESH`,
///         `ERROR_NON_FINITE_COORDINATES`, `ERROR_DEGENERATE_FACE` (with cones),
///         `ERROR_CANNOT_SOLVE_LINEAR_SYSTEM`, or `ERROR_NO_TOPOLOGICAL_DISC` for a
///         non-manifold mesh or several components. `report.problem` names the problem
///         precisely (`disk_seams_problem_message()`).
template <class TriangleMesh, class SeamEdgeMap, class SeamVertexMap,
          class NamedParameters = parameters::Default_named_parameters>
Error_code compute_disk_seams(const TriangleMesh& tm, SeamEdgeMap seam_edges, SeamVertexMap seam_vertices,
                              Disk_seams_report<TriangleMesh>& report,
                              const Disk_seams_options& options = Disk_seams_options(),
                              const NamedParameters& np = parameters::default_values())
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::edge_descriptor   edge_descriptor;
  typedef std::chrono::steady_clock                                     Clock;
  const Clock::time_point start = Clock::now();
  report = Disk_seams_report<TriangleMesh>();
  const auto vpm = parameters::choose_parameter(parameters::get_parameter(np, internal_np::vertex_point),
                                                get_const_property_map(vertex_point, tm));
  internal::Indexed_surface s;
  internal::Surface_indexing<TriangleMesh> ix(tm);
  report.problem = internal::index_surface(tm, vpm, s, ix, report);
  std::vector<char> cut;
  std::vector<int> cones;
  if(report.problem == NO_PROBLEM)
  {
    report.genus = s.genus();
    report.number_of_border_loops = s.border_loops.size();
    report.problem = internal::cut_to_disk<Default_sparse_cholesky_traits>(s, options, cut, cones, report);
  }
  report.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  if(report.problem != NO_PROBLEM)
    return internal::error_code_of(report.problem);

  for(edge_descriptor e : edges(tm))
    put(seam_edges, e, false);
  for(vertex_descriptor v : vertices(tm))
    put(seam_vertices, v, false);
  for(std::size_t e = 0; e < cut.size(); ++e)
  {
    if(!cut[e])
      continue;
    put(seam_edges, ix.edge_of[e], true);
    for(int v : s.edge_vertices[e])
      put(seam_vertices, ix.vertex_of[static_cast<std::size_t>(v)], true);
    ++report.number_of_seam_edges;
    report.seam_length += s.edge_lengths[e];
  }
  for(int c : cones)
    report.cones.push_back(ix.vertex_of[static_cast<std::size_t>(c)]);
  report.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return OK;
}

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_COMPUTE_DISK_SEAMS_H
