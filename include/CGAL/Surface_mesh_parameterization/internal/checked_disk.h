// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CHECKED_DISK_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CHECKED_DISK_H

// The checked, indexed disk: one connected component of a triangle mesh, checked (topology,
// finite coordinates, non-degenerate faces), indexed (dense local vertex indices, so that
// generic code never relies on the mesh's own vertex descriptors), with its holes filled
// virtually, and the geometry every step needs (half cotangents, row sums, mean edge lengths,
// the sparsity pattern of its vertex graph). Built once, then only read: the numerics that
// work on it (internal/dirichlet_engine.h) live in Parameterization_patch_3.

#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/internal/laplacian.h>
#include <CGAL/Surface_mesh_parameterization/internal/triangle_adjacency.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

template <class TriangleMesh>
class Checked_disk
{
public:
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor         vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor       halfedge_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor           face_descriptor;
  typedef internal::Face_indices                                                Face;

  /// Relative threshold below which a face counts as degenerate: `2A <= 1e-12 l_max^2`.
  static constexpr double degenerate_face_threshold() { return 1e-12; }

private:
  typedef typename boost::property_map<TriangleMesh,
            CGAL::dynamic_vertex_property_t<int> >::const_type                 Index_map;
  typedef typename boost::property_map<TriangleMesh,
            CGAL::dynamic_face_property_t<bool> >::const_type                  Face_flag_map;
  typedef typename boost::property_map<TriangleMesh,
            CGAL::dynamic_halfedge_property_t<bool> >::const_type              Halfedge_flag_map;

public:
  /// \name Construction
  /// @{

  /// creates an empty disk; fill it with `build_disk()` or `build_component()`.
  Checked_disk() = default;

  /// builds the disk patch bounded by the border loop of `bhd`: the connected component of
  /// `face(opposite(bhd))`. The border loop is the *main border*; every other vertex of the
  /// component (including the vertices of other border loops, i.e. holes) is *interior*.
  ///
  /// Holes (border loops other than the main one) are filled *virtually*: each gets one
  /// virtual vertex, placed at the centroid of its loop lifted by a fifth of the loop's mean
  /// radius along the loop's normal, joined to every loop edge by a virtual face. Every solve
  /// of the method then works on a topological disk, and a parameterization without flipped
  /// faces maps each hole to a simple polygon (star-shaped around its virtual vertex).
  /// Virtual vertices are interior, have no mesh vertex (`vertex(i)` is `null_vertex()`,
  /// `is_virtual(i)` is `true`) and come after the real ones; virtual faces come after the
  /// real faces. `fill_holes = false` keeps holes as free (natural) boundaries instead.
  ///
  /// Checks, in this order, and returns the first failure:
  /// `ERROR_EMPTY_MESH` (no face), `ERROR_INVALID_BORDER_HALFEDGE` (null or not a border
  /// halfedge), `ERROR_NON_TRIANGULAR_MESH`, `ERROR_BORDER_TOO_SHORT` (fewer than 3 border
  /// vertices), `ERROR_NO_TOPOLOGICAL_DISC` (the loop visits a vertex twice, a vertex is
  /// non-manifold: its faces do not form one fan, as at a pinched vertex where border loops
  /// touch; or the component has handles), `ERROR_NON_FINITE_COORDINATES`,
  /// `ERROR_DEGENERATE_FACE`, `ERROR_NO_INTERIOR_VERTEX`. On failure the disk is empty.
  ///
  /// \tparam VertexPointMap a model of `ReadablePropertyMap` from `vertex_descriptor` to a
  ///         CGAL 3D point type.
  template <class VertexPointMap>
  Error_code build_disk(const TriangleMesh& tm, halfedge_descriptor bhd, VertexPointMap vpm,
                        bool fill_holes = true)
  {
    clear();
    if(faces(tm).empty())
      return ERROR_EMPTY_MESH;
    if(bhd == boost::graph_traits<TriangleMesh>::null_halfedge() || !is_border(bhd, tm))
      return ERROR_INVALID_BORDER_HALFEDGE;

    Error_code status = collect_component(tm, face(opposite(bhd, tm), tm), vpm);
    if(status == OK) status = collect_border_loop(bhd);
    if(status == OK) status = check_disk_topology();
    if(status == OK) status = check_finite();
    if(status == OK) collect_hole_loops();
    if(status == OK && fill_holes) fill_holes_virtually();
    m_loops.clear();
    if(status == OK) status = check_geometry();
    if(status == OK && m_interior.empty()) status = ERROR_NO_INTERIOR_VERTEX;
    if(status != OK)
      clear();
    return status;
  }

  /// builds the patch of the connected component of face `seed`, with no main border (every
  /// vertex counts as interior). Any topology is accepted (closed, with holes, with handles).
  /// Returns `ERROR_EMPTY_MESH`, `ERROR_NON_TRIANGULAR_MESH`, `ERROR_NON_FINITE_COORDINATES`
  /// or `ERROR_DEGENERATE_FACE` on failure; the disk is then empty.
  template <class VertexPointMap>
  Error_code build_component(const TriangleMesh& tm, face_descriptor seed, VertexPointMap vpm)
  {
    clear();
    if(faces(tm).empty() || seed == boost::graph_traits<TriangleMesh>::null_face())
      return ERROR_EMPTY_MESH;
    Error_code status = collect_component(tm, seed, vpm);
    m_loops.clear();
    if(status == OK) status = check_finite();
    if(status == OK) status = check_geometry();
    if(status == OK)
    {
      m_interior_index.resize(m_vertices.size());
      m_interior.resize(m_vertices.size());
      for(std::size_t i = 0; i < m_vertices.size(); ++i)
      {
        m_interior_index[i] = static_cast<int>(i);
        m_interior[i] = static_cast<int>(i);
      }
    }
    if(status != OK)
      clear();
    return status;
  }

  /// @}

  /// \name Access
  /// @{

  /// the mesh the patch was built from (`nullptr` for an empty patch).
  const TriangleMesh* mesh() const { return m_mesh; }
  /// number of vertices of the patch (virtual ones included).
  std::size_t number_of_vertices() const { return m_vertices.size(); }
  /// number of real vertices: the mesh's vertices, local indices `0..n-1`.
  std::size_t number_of_real_vertices() const { return m_real_vertices; }
  /// whether local vertex `i` is a virtual vertex (the filling of a hole).
  bool is_virtual(std::size_t i) const { return i >= m_real_vertices; }
  /// number of real faces (the mesh's faces, which come first in `faces_indices()`).
  std::size_t number_of_real_faces() const { return m_real_faces; }
  /// number of faces of the patch.
  std::size_t number_of_faces() const { return m_faces.size(); }
  /// the mesh vertex of local index `i` (`null_vertex()` for a virtual vertex).
  vertex_descriptor vertex(std::size_t i) const { return m_vertices[i]; }
  /// all mesh vertices, by local index.
  const std::vector<vertex_descriptor>& vertices() const { return m_vertices; }
  /// whether `v` is a vertex of the patch. Unlike `index()`, it accepts any descriptor
  /// value, also one that is not a vertex of the mesh (a user's input); O(n).
  bool contains(vertex_descriptor v) const
  {
    return v != boost::graph_traits<TriangleMesh>::null_vertex() &&
           std::find(m_vertices.begin(), m_vertices.end(), v) != m_vertices.end();
  }
  /// the local index of `v`, or -1 when `v` is not a vertex of the patch. `v` must be a
  /// vertex of the mesh (see `contains()`).
  int index(vertex_descriptor v) const
  {
    if(m_vertices.empty())
      return -1;
    const int stored = get(m_index_map, v);  // local index + 1; 0 means "not in the patch"
    return stored - 1;
  }
  /// the unit of the patch's positions: `point(i)` is the mesh's position divided by this
  /// power of two, chosen so that the largest coordinate lies in [1, 2). The division is
  /// exact, and it keeps every computation on the patch clear of underflow and overflow
  /// (squared lengths of a mesh of size 1e-150, say), so that results do not depend on the
  /// mesh's scale. Lengths measured on the patch are in this unit.
  double length_unit() const { return m_length_unit; }
  /// the position of local vertex `i`, in the unit `length_unit()`.
  const Eigen::Vector3d& point(std::size_t i) const { return m_points[i]; }
  /// all positions, by local index.
  const std::vector<Eigen::Vector3d>& points() const { return m_points; }
  /// the faces as local index triples, oriented as in the mesh.
  const std::vector<Face>& faces_indices() const { return m_faces; }
  /// per face, bit `k` is set when the edge opposite corner `k` has no other face.
  const std::vector<unsigned char>& single_edge_masks() const { return m_single_edges; }
  /// per face, half the cotangent of the angle at each corner (the face's share of the
  /// cotangent weight of the opposite edge).
  const std::vector<std::array<double, 3> >& half_cotangents() const { return m_half_cot; }
  /// the main border loop (local indices), in the order of `halfedges_around_face(bhd)`
  /// starting at `source(bhd)`; empty for a patch built by `build_component()`.
  const std::vector<int>& border() const { return m_border; }
  /// the halfedge the border loop was built from.
  halfedge_descriptor border_halfedge() const { return m_bhd; }
  /// whether local vertex `i` lies on the main border loop.
  bool is_on_border(std::size_t i) const { return m_interior_index[i] < 0; }
  /// the local indices of the interior vertices, in increasing order.
  const std::vector<int>& interior_vertices() const { return m_interior; }
  /// the row of local vertex `i` in the interior system, or -1 for a border vertex.
  int interior_index(std::size_t i) const { return m_interior_index[i]; }
  /// number of border loops of the component in the mesh (the main border included; holes
  /// count even when they are filled virtually).
  int number_of_border_loops() const { return m_border_loops; }
  /// the border loops other than the main one (holes), each as local indices in the order of
  /// its border halfedges (`source()` of each), i.e. counterclockwise around the hole as
  /// seen with the faces' orientation. Empty for a patch built by `build_component()`.
  const std::vector<std::vector<int> >& hole_loops() const { return m_hole_loops; }
  /// whether local vertex `i` lies on a hole (a border loop other than the main one).
  bool is_on_hole(std::size_t i) const { return i < m_on_hole.size() && m_on_hole[i]; }

  /// @}

  /// \name Geometry
  /// @{

  /// `d_i = sum_j w_ij` for the cotangent weights `w_ij = (cot a_ij + cot b_ij) / 2`.
  const std::vector<double>& cotangent_row_sums() const { return m_cot_row_sums; }

  /// `g_i`: mean length of the edges at each vertex (paper Eq. 1's right-hand side).
  const std::vector<double>& mean_spoke_lengths() const { return m_mean_spoke; }

  /// the sparsity pattern of the vertex graph, for the Laplacians of the disk.
  const internal::Laplacian_pattern& pattern() const { return m_pattern; }

  /// @}

private:
  void clear()
  {
    *this = Checked_disk();
  }

  // Walks the faces of the component of `seed`, indexing vertices on first sight.
  // Walks the faces of the component of `seed`, indexing vertices on first sight.
  template <class VertexPointMap>
  Error_code collect_component(const TriangleMesh& tm, face_descriptor seed, VertexPointMap vpm)
  {
    m_mesh = &tm;
    m_index_map = get(CGAL::dynamic_vertex_property_t<int>(), tm);
    Face_flag_map visited = get(CGAL::dynamic_face_property_t<bool>(), tm);
    Halfedge_flag_map loop_seen = get(CGAL::dynamic_halfedge_property_t<bool>(), tm);

    std::vector<face_descriptor> stack(1, seed);
    put(visited, seed, true);
    while(!stack.empty())
    {
      const face_descriptor f = stack.back();
      stack.pop_back();

      Face t;
      unsigned char single = 0;
      int degree = 0;
      for(halfedge_descriptor h : halfedges_around_face(halfedge(f, tm), tm))
      {
        if(degree == 3)
          return ERROR_NON_TRIANGULAR_MESH;
        // corner `degree` is target(h); h itself is the edge opposite corner (degree+1)%3
        const vertex_descriptor v = target(h, tm);
        int id = get(m_index_map, v) - 1;
        if(id < 0)
        {
          id = static_cast<int>(m_vertices.size());
          put(m_index_map, v, id + 1);
          m_vertices.push_back(v);
          const auto& p = get(vpm, v);
          m_points.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()),
                                CGAL::to_double(p.z()));
        }
        t[static_cast<std::size_t>(degree)] = id;

        const halfedge_descriptor o = opposite(h, tm);
        const face_descriptor g = face(o, tm);
        if(g == boost::graph_traits<TriangleMesh>::null_face())
        {
          single |= static_cast<unsigned char>(1u << ((degree + 1) % 3));
          if(!get(loop_seen, o))  // a border loop not walked yet
          {
            ++m_border_loops;
            m_loops.emplace_back();
            for(halfedge_descriptor b : halfedges_around_face(o, tm))
            {
              put(loop_seen, b, true);
              m_loops.back().push_back(b);
            }
          }
        }
        else if(!get(visited, g))
        {
          put(visited, g, true);
          stack.push_back(g);
        }
        ++degree;
      }
      if(degree != 3)
        return ERROR_NON_TRIANGULAR_MESH;
      m_faces.push_back(t);
      m_single_edges.push_back(single);
    }
    m_real_vertices = m_vertices.size();
    normalize_scale();
    m_real_faces = m_faces.size();
    return OK;
  }

  // The holes: every border loop but the main one, as local indices.
  void collect_hole_loops()
  {
    const TriangleMesh& tm = *m_mesh;
    for(const std::vector<halfedge_descriptor>& loop : m_loops)
    {
      bool main = false;
      for(halfedge_descriptor b : loop)
        main = main || (b == m_bhd);
      if(main)
        continue;
      m_hole_loops.emplace_back();
      m_on_hole.resize(m_vertices.size(), false);
      for(halfedge_descriptor b : loop)
      {
        const int i = index(source(b, tm));
        m_hole_loops.back().push_back(i);
        m_on_hole[static_cast<std::size_t>(i)] = true;
      }
    }
  }

  // Adds one virtual vertex and a fan of virtual faces in every hole.
  void fill_holes_virtually()
  {
    for(const std::vector<int>& loop : m_hole_loops)
    {
      const std::size_t m = loop.size();
      Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
      for(int i : loop)
        centroid += point(static_cast<std::size_t>(i));
      centroid /= double(m);
      Eigen::Vector3d normal = Eigen::Vector3d::Zero();
      double radius = 0.;
      for(std::size_t k = 0; k < m; ++k)
      {
        const Eigen::Vector3d a = point(static_cast<std::size_t>(loop[k])) - centroid;
        const Eigen::Vector3d c = point(static_cast<std::size_t>(loop[(k + 1) % m])) - centroid;
        normal += a.cross(c);
        radius += a.norm();
      }
      radius /= double(m);
      const double length = normal.norm();
      const Eigen::Vector3d lift = (length > 0.) ? Eigen::Vector3d(0.2 * radius * normal / length)
                                                 : Eigen::Vector3d::Zero();
      const int c = static_cast<int>(m_vertices.size());
      m_vertices.push_back(boost::graph_traits<TriangleMesh>::null_vertex());
      m_points.push_back(centroid + lift);
      m_interior_index.push_back(static_cast<int>(m_interior.size()));
      m_interior.push_back(c);
      // the border halfedge runs s -> t on the hole's side: the face (s, t, c) is oriented
      // as the mesh face across the edge, which holds t -> s
      for(std::size_t k = 0; k < m; ++k)
      {
        m_faces.push_back({{loop[k], loop[(k + 1) % m], c}});
        m_single_edges.push_back(0);
      }
    }
    if(m_hole_loops.empty())
      return;
    // the hole edges now have two faces
    const internal::Triangle_adjacency adjacency(m_vertices.size(), m_faces);
    for(std::size_t f = 0; f < m_faces.size(); ++f)
    {
      unsigned char single = 0;
      for(int k = 0; k < 3; ++k)
        if(adjacency.neighbor(f, k) < 0)
          single |= static_cast<unsigned char>(1u << k);
      m_single_edges[f] = single;
    }
  }

  Error_code collect_border_loop(halfedge_descriptor bhd)
  {
    const TriangleMesh& tm = *m_mesh;
    m_bhd = bhd;
    m_interior_index.assign(m_vertices.size(), 0);
    for(halfedge_descriptor h : halfedges_around_face(bhd, tm))
    {
      const int id = index(source(h, tm));
      if(id < 0)  // the loop leaves the component through a pinched vertex
        return ERROR_NO_TOPOLOGICAL_DISC;
      if(m_interior_index[static_cast<std::size_t>(id)] < 0)  // second visit: pinched loop
        return ERROR_NO_TOPOLOGICAL_DISC;
      m_interior_index[static_cast<std::size_t>(id)] = -1;
      m_border.push_back(id);
    }
    if(m_border.size() < 3)
      return ERROR_BORDER_TOO_SHORT;
    int next = 0;
    for(std::size_t i = 0; i < m_vertices.size(); ++i)
      if(m_interior_index[i] == 0)
      {
        m_interior_index[i] = next++;
        m_interior.push_back(static_cast<int>(i));
      }
    return OK;
  }

  // A disk with holes: every vertex has a single umbrella (all its faces in this component,
  // forming one fan: at most one border gap) and the Euler characteristic is
  // 2 - (number of border loops), i.e. genus 0.
  //
  // A pinched vertex (its faces form several fans, so that border loops touch there) is
  // rejected. The halfedge structure pairs the border halfedges at such a vertex in an order
  // set by the order in which the faces were added: the same surface can come as several loops
  // that touch, or as one loop through the vertex several times. Rejecting every pinched
  // vertex keeps the answer independent of that order; splitting the vertex
  // (`Polygon_mesh_processing::duplicate_non_manifold_vertices()`) makes such a mesh a disk.
  Error_code check_disk_topology() const
  {
    const TriangleMesh& tm = *m_mesh;
    std::vector<int> corners(m_vertices.size(), 0);
    for(const Face& t : m_faces)
      for(int id : t)
        ++corners[static_cast<std::size_t>(id)];
    for(std::size_t i = 0; i < m_vertices.size(); ++i)
    {
      int around = 0, gaps = 0;
      for(halfedge_descriptor h : halfedges_around_target(halfedge(m_vertices[i], tm), tm))
        ++(is_border(h, tm) ? gaps : around);
      if(around != corners[i] || gaps > 1)  // faces of another component, or a pinched vertex
        return ERROR_NO_TOPOLOGICAL_DISC;
    }
    long single_edges = 0;
    for(unsigned char mask : m_single_edges)
      single_edges += (mask & 1) + ((mask >> 1) & 1) + ((mask >> 2) & 1);
    const long F = static_cast<long>(m_faces.size());
    const long E = (3 * F + single_edges) / 2;
    const long V = static_cast<long>(m_vertices.size());
    const long chi = V - E + F;
    if(chi != 2 - m_border_loops)
      return ERROR_NO_TOPOLOGICAL_DISC;
    return OK;
  }

  // Divides the positions by the power of two that brings the largest coordinate into [1, 2).
  void normalize_scale()
  {
    double largest = 0.;
    for(const Eigen::Vector3d& p : m_points)
      largest = (std::max)(largest, p.cwiseAbs().maxCoeff());
    if(!(largest > 0.) || !std::isfinite(largest))
      return;  // all at the origin, or not finite: check_finite() and check_geometry() reject it
    const int exponent = std::ilogb(largest);
    m_length_unit = std::ldexp(1., exponent);
    for(Eigen::Vector3d& p : m_points)
      for(int c = 0; c < 3; ++c)
        p[c] = std::ldexp(p[c], -exponent);
  }

  Error_code check_finite() const
  {
    for(const Eigen::Vector3d& p : m_points)
      if(!p.allFinite())
        return ERROR_NON_FINITE_COORDINATES;
    return OK;
  }

  // Non-degenerate faces; computes the half cotangents and the row sums.
  Error_code check_geometry()
  {

    m_half_cot.resize(m_faces.size());
    for(std::size_t f = 0; f < m_faces.size(); ++f)
    {
      const Face& t = m_faces[f];
      double longest2 = 0.;
      for(int k = 0; k < 3; ++k)
        longest2 = (std::max)(longest2, (point(static_cast<std::size_t>(t[(k + 1) % 3])) -
                                         point(static_cast<std::size_t>(t[(k + 2) % 3]))).squaredNorm());
      const Eigen::Vector3d& p0 = point(static_cast<std::size_t>(t[0]));
      const double double_area = (point(static_cast<std::size_t>(t[1])) - p0)
                                   .cross(point(static_cast<std::size_t>(t[2])) - p0).norm();
      if(!(double_area > degenerate_face_threshold() * longest2) || !std::isfinite(double_area))
        return ERROR_DEGENERATE_FACE;
      for(int k = 0; k < 3; ++k)
      {
        const Eigen::Vector3d& pk = point(static_cast<std::size_t>(t[k]));
        const Eigen::Vector3d a = point(static_cast<std::size_t>(t[(k + 1) % 3])) - pk;
        const Eigen::Vector3d b = point(static_cast<std::size_t>(t[(k + 2) % 3])) - pk;
        m_half_cot[f][static_cast<std::size_t>(k)] = 0.5 * a.dot(b) / double_area;
      }
    }
    // computed here, once, so that the steps can read them concurrently
    internal::laplacian_row_sums(m_faces, m_vertices.size(),
                                 internal::Cotangent_weight{&m_half_cot}, m_cot_row_sums);
    internal::mean_spoke_lengths(m_faces, m_points, m_single_edges, m_mean_spoke);
    m_pattern = internal::Laplacian_pattern(m_vertices.size(), m_faces);
    return OK;
  }

  const TriangleMesh* m_mesh = nullptr;
  halfedge_descriptor m_bhd = halfedge_descriptor();
  Index_map m_index_map;
  std::vector<vertex_descriptor> m_vertices;
  std::vector<Eigen::Vector3d> m_points;
  std::vector<Face> m_faces;
  std::vector<unsigned char> m_single_edges;
  std::vector<std::array<double, 3> > m_half_cot;
  std::vector<int> m_border;
  std::vector<int> m_interior;
  std::vector<int> m_interior_index;
  int m_border_loops = 0;
  std::vector<std::vector<halfedge_descriptor> > m_loops;  // during construction only
  std::vector<std::vector<int> > m_hole_loops;
  std::vector<bool> m_on_hole;
  std::size_t m_real_vertices = 0;
  double m_length_unit = 1.;
  std::size_t m_real_faces = 0;
  std::vector<double> m_cot_row_sums;
  std::vector<double> m_mean_spoke;
  internal::Laplacian_pattern m_pattern;
};

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CHECKED_DISK_H
