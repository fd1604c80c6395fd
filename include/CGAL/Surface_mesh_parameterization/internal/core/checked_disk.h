// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CORE_CHECKED_DISK_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CORE_CHECKED_DISK_H

// The checked, indexed disk: one connected component of a triangle mesh, checked (topology,
// finite coordinates, non-degenerate faces), indexed (dense local vertex indices, so that
// generic code never relies on the mesh's own vertex descriptors), with its holes filled
// virtually, and the geometry every step needs (half cotangents, row sums, mean edge lengths,
// the sparsity pattern of its vertex graph). Built once, then only read.
//
// Indexed_disk holds the data (no mesh type: every numerical step works on it alone);
// Checked_disk<TriangleMesh> builds it from a mesh and maps local indices to descriptors.

#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/laplacian.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/mesh_indexer.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/triangle_adjacency.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/triangle_geometry.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Dynamic_property_map.h>

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

// The data of a checked disk, by local index. Real vertices come first (0..n_real-1), then
// the virtual vertices that fill holes; real faces come first, then the virtual ones.
class Indexed_disk
{
public:
  std::size_t number_of_vertices() const { return m_points.size(); }
  std::size_t number_of_real_vertices() const { return m_real_vertices; }
  bool is_virtual(std::size_t i) const { return i >= m_real_vertices; }
  std::size_t number_of_real_faces() const { return m_real_faces; }
  std::size_t number_of_faces() const { return m_faces.size(); }
  // the unit of the positions: point(i) is the mesh's position divided by this power of two,
  // chosen so that the largest coordinate lies in [1, 2) (exact; results do not depend on the
  // mesh's scale). Lengths measured on the disk are in this unit.
  double length_unit() const { return m_length_unit; }
  const Eigen::Vector3d& point(std::size_t i) const { return m_points[i]; }
  const std::vector<Eigen::Vector3d>& points() const { return m_points; }
  // the faces as local index triples, oriented as in the mesh
  const std::vector<Face_indices>& faces_indices() const { return m_faces; }
  // per face, bit k is set when the edge opposite corner k has no other face
  const std::vector<unsigned char>& single_edge_masks() const { return m_single_edges; }
  // per face, half the cotangent of the angle at each corner
  const std::vector<std::array<double, 3> >& half_cotangents() const { return m_half_cot; }
  // the main border loop, in the order of halfedges_around_face(bhd) from source(bhd); empty
  // for a component without a main border
  const std::vector<int>& border() const { return m_border; }
  bool is_on_border(std::size_t i) const { return m_interior_index[i] < 0; }
  // the interior vertices in increasing order, and the row of each vertex among them (-1 on
  // the main border)
  const std::vector<int>& interior_vertices() const { return m_interior; }
  int interior_index(std::size_t i) const { return m_interior_index[i]; }
  // border loops of the component in the mesh (the main border included)
  int number_of_border_loops() const { return m_border_loops; }
  // the holes (border loops but the main one), each in the order of its border halfedges
  const std::vector<std::vector<int> >& hole_loops() const { return m_hole_loops; }
  bool is_on_hole(std::size_t i) const { return i < m_on_hole.size() && m_on_hole[i]; }
  // d_i = sum_j w_ij for the cotangent weights
  const std::vector<double>& cotangent_row_sums() const { return m_cot_row_sums; }
  // g_i: mean length of the edges at each vertex (paper Eq. 1's right-hand side)
  const std::vector<double>& mean_spoke_lengths() const { return m_mean_spoke; }
  const Laplacian_pattern& pattern() const { return m_pattern; }

protected:
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

  // Non-degenerate faces; computes the half cotangents, the row sums, the mean spoke lengths
  // and the pattern (once, so that the steps can read them concurrently).
  Error_code check_geometry()
  {
    m_half_cot.resize(m_faces.size());
    for(std::size_t f = 0; f < m_faces.size(); ++f)
    {
      const Eigen::Vector3d& p0 = point(static_cast<std::size_t>(m_faces[f][0]));
      const Eigen::Vector3d& p1 = point(static_cast<std::size_t>(m_faces[f][1]));
      const Eigen::Vector3d& p2 = point(static_cast<std::size_t>(m_faces[f][2]));
      if(is_degenerate_triangle(p0, p1, p2))
        return ERROR_DEGENERATE_FACE;
      m_half_cot[f] = internal::half_cotangents(p0, p1, p2);
    }
    laplacian_row_sums(m_faces, m_points.size(), Cotangent_weight{&m_half_cot}, m_cot_row_sums);
    internal::mean_spoke_lengths(m_faces, m_points, m_single_edges, m_mean_spoke);
    m_pattern = Laplacian_pattern(m_points.size(), m_faces);
    return OK;
  }

  // Every vertex interior (a component with no main border).
  void make_all_interior()
  {
    m_interior_index.resize(m_points.size());
    m_interior.resize(m_points.size());
    for(std::size_t i = 0; i < m_points.size(); ++i)
    {
      m_interior_index[i] = static_cast<int>(i);
      m_interior[i] = static_cast<int>(i);
    }
  }

  // Adds one virtual vertex and a fan of virtual faces in every hole: the vertex at the
  // centroid of its loop, lifted by a fifth of the loop's mean radius along its normal.
  void fill_holes_virtually()
  {
    for(const std::vector<int>& loop : m_hole_loops)
    {
      const int c = static_cast<int>(m_points.size());
      m_points.push_back(hole_filling_point(loop));
      m_interior_index.push_back(static_cast<int>(m_interior.size()));
      m_interior.push_back(c);
      // the border halfedge runs s -> t on the hole's side: the face (s, t, c) is oriented
      // as the mesh face across the edge, which holds t -> s
      for(std::size_t k = 0; k < loop.size(); ++k)
      {
        m_faces.push_back({{loop[k], loop[(k + 1) % loop.size()], c}});
        m_single_edges.push_back(0);
      }
    }
    if(!m_hole_loops.empty())
      update_single_edge_masks();  // the hole edges now have two faces
  }

  Eigen::Vector3d hole_filling_point(const std::vector<int>& loop) const
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
    return centroid + ((length > 0.) ? Eigen::Vector3d(0.2 * radius * normal / length) : Eigen::Vector3d::Zero());
  }

  void update_single_edge_masks()
  {
    const Triangle_adjacency adjacency(m_points.size(), m_faces);
    for(std::size_t f = 0; f < m_faces.size(); ++f)
    {
      unsigned char single = 0;
      for(int k = 0; k < 3; ++k)
        if(adjacency.neighbor(f, k) < 0)
          single |= static_cast<unsigned char>(1u << k);
      m_single_edges[f] = single;
    }
  }

  // Euler characteristic of the faces with `single_edges` counted once: V - E + F.
  long euler_characteristic() const
  {
    long single_edges = 0;
    for(unsigned char mask : m_single_edges)
      single_edges += (mask & 1) + ((mask >> 1) & 1) + ((mask >> 2) & 1);
    const long F = static_cast<long>(m_faces.size());
    return static_cast<long>(m_points.size()) - (3 * F + single_edges) / 2 + F;
  }

  std::vector<Eigen::Vector3d> m_points;
  std::vector<Face_indices> m_faces;
  std::vector<unsigned char> m_single_edges;
  std::vector<std::array<double, 3> > m_half_cot;
  std::vector<int> m_border;
  std::vector<int> m_interior;
  std::vector<int> m_interior_index;
  int m_border_loops = 0;
  std::vector<std::vector<int> > m_hole_loops;
  std::vector<bool> m_on_hole;
  std::size_t m_real_vertices = 0;
  std::size_t m_real_faces = 0;
  double m_length_unit = 1.;
  std::vector<double> m_cot_row_sums;
  std::vector<double> m_mean_spoke;
  Laplacian_pattern m_pattern;
};

template <class TriangleMesh>
class Checked_disk : public Indexed_disk
{
public:
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor         vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor       halfedge_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor           face_descriptor;

  Checked_disk() = default;

  // Builds the disk bounded by the border loop of `bhd`: the connected component of
  // face(opposite(bhd)). The loop is the main border; every other vertex (holes included) is
  // interior. Holes are filled virtually (fill_holes_virtually()) unless `fill_holes` is false.
  // Checks, in this order: ERROR_EMPTY_MESH, ERROR_INVALID_BORDER_HALFEDGE,
  // ERROR_NON_TRIANGULAR_MESH, ERROR_BORDER_TOO_SHORT, ERROR_NO_TOPOLOGICAL_DISC (a pinched
  // loop, a non-manifold vertex, handles), ERROR_NON_FINITE_COORDINATES, ERROR_DEGENERATE_FACE,
  // ERROR_NO_INTERIOR_VERTEX. On failure the disk is empty.
  template <class VertexPointMap>
  Error_code build_disk(const TriangleMesh& tm, halfedge_descriptor bhd, VertexPointMap vpm, bool fill_holes = true)
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
    if(status == OK) collect_hole_loops(bhd);
    if(status == OK && fill_holes) fill_holes_virtually();
    m_loops.clear();
    if(status == OK) status = check_geometry();
    if(status == OK && m_interior.empty()) status = ERROR_NO_INTERIOR_VERTEX;
    if(status != OK)
      clear();
    return status;
  }

  // Builds the component of face `seed` with no main border (every vertex interior), of any
  // topology. ERROR_EMPTY_MESH, ERROR_NON_TRIANGULAR_MESH, ERROR_NON_FINITE_COORDINATES or
  // ERROR_DEGENERATE_FACE on failure; the disk is then empty.
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
      make_all_interior();
    else
      clear();
    return status;
  }

  const TriangleMesh* mesh() const { return m_mesh; }
  // the mesh vertex of local index i (null_vertex() for a virtual vertex)
  vertex_descriptor vertex(std::size_t i) const
  {
    return i < m_indexer.vertices().size() ? m_indexer.vertices()[i] : boost::graph_traits<TriangleMesh>::null_vertex();
  }
  // whether `v` is a vertex of the disk; unlike index(), any descriptor value is accepted
  // (a user's input); O(n)
  bool contains(vertex_descriptor v) const
  {
    const std::vector<vertex_descriptor>& all = m_indexer.vertices();
    return v != boost::graph_traits<TriangleMesh>::null_vertex() && std::find(all.begin(), all.end(), v) != all.end();
  }
  // the local index of `v`, or -1 when `v` is not a vertex of the disk (`v` must be a vertex
  // of the mesh: see contains())
  int index(vertex_descriptor v) const { return m_points.empty() ? -1 : m_indexer.index(v); }
  // the position of the mesh vertex of local index i in the range vertices(mesh); O(n)
  std::size_t position_in_mesh(std::size_t i) const
  {
    std::size_t position = 0;
    for(vertex_descriptor v : vertices(*m_mesh))
    {
      if(v == vertex(i))
        return position;
      ++position;
    }
    return position;
  }

private:
  void clear() { *this = Checked_disk(); }

  // Walks the faces of the component of `seed`, indexing vertices on first sight and noting
  // the border loops met.
  template <class VertexPointMap>
  Error_code collect_component(const TriangleMesh& tm, face_descriptor seed, VertexPointMap vpm)
  {
    m_mesh = &tm;
    m_indexer = Mesh_indexer<TriangleMesh>(tm);
    auto visited = get(CGAL::dynamic_face_property_t<bool>(), tm);
    auto loop_seen = get(CGAL::dynamic_halfedge_property_t<bool>(), tm);
    std::vector<face_descriptor> stack(1, seed);
    put(visited, seed, true);
    while(!stack.empty())
    {
      const face_descriptor f = stack.back();
      stack.pop_back();
      if(!collect_face(tm, f, vpm, visited, loop_seen, stack))
        return ERROR_NON_TRIANGULAR_MESH;
    }
    m_points = std::move(m_indexer.points());
    m_real_vertices = m_points.size();
    normalize_scale();
    m_real_faces = m_faces.size();
    return OK;
  }

  // One face: its corners (corner k is target(h) of its k-th halfedge h; h is the edge
  // opposite corner k+1), its single edges, the border loops and faces it leads to.
  template <class VertexPointMap, class FaceFlags, class HalfedgeFlags>
  bool collect_face(const TriangleMesh& tm, face_descriptor f, VertexPointMap vpm, FaceFlags& visited,
                    HalfedgeFlags& loop_seen, std::vector<face_descriptor>& stack)
  {
    Face_indices t;
    unsigned char single = 0;
    int degree = 0;
    for(halfedge_descriptor h : halfedges_around_face(halfedge(f, tm), tm))
    {
      if(degree == 3)
        return false;
      t[static_cast<std::size_t>(degree)] = m_indexer.add(target(h, tm), vpm);
      const halfedge_descriptor o = opposite(h, tm);
      const face_descriptor g = face(o, tm);
      if(g == boost::graph_traits<TriangleMesh>::null_face())
      {
        single |= static_cast<unsigned char>(1u << ((degree + 1) % 3));
        if(!get(loop_seen, o))
          note_border_loop(tm, o, loop_seen);
      }
      else if(!get(visited, g))
      {
        put(visited, g, true);
        stack.push_back(g);
      }
      ++degree;
    }
    if(degree != 3)
      return false;
    m_faces.push_back(t);
    m_single_edges.push_back(single);
    return true;
  }

  template <class HalfedgeFlags>
  void note_border_loop(const TriangleMesh& tm, halfedge_descriptor o, HalfedgeFlags& loop_seen)
  {
    ++m_border_loops;
    m_loops.emplace_back();
    for(halfedge_descriptor b : halfedges_around_face(o, tm))
    {
      put(loop_seen, b, true);
      m_loops.back().push_back(b);
    }
  }

  Error_code collect_border_loop(halfedge_descriptor bhd)
  {
    const TriangleMesh& tm = *m_mesh;
    m_interior_index.assign(m_points.size(), 0);
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
    for(std::size_t i = 0; i < m_points.size(); ++i)
      if(m_interior_index[i] == 0)
      {
        m_interior_index[i] = next++;
        m_interior.push_back(static_cast<int>(i));
      }
    return OK;
  }

  // The holes: every border loop but the main one, as local indices.
  void collect_hole_loops(halfedge_descriptor bhd)
  {
    const TriangleMesh& tm = *m_mesh;
    for(const std::vector<halfedge_descriptor>& loop : m_loops)
    {
      if(std::find(loop.begin(), loop.end(), bhd) != loop.end())
        continue;
      m_hole_loops.emplace_back();
      m_on_hole.resize(m_points.size(), false);
      for(halfedge_descriptor b : loop)
      {
        const int i = index(source(b, tm));
        m_hole_loops.back().push_back(i);
        m_on_hole[static_cast<std::size_t>(i)] = true;
      }
    }
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
    std::vector<int> corners(m_points.size(), 0);
    for(const Face_indices& t : m_faces)
      for(int id : t)
        ++corners[static_cast<std::size_t>(id)];
    for(std::size_t i = 0; i < m_points.size(); ++i)
    {
      int around = 0, gaps = 0;
      for(halfedge_descriptor h : halfedges_around_target(halfedge(vertex(i), tm), tm))
        ++(is_border(h, tm) ? gaps : around);
      if(around != corners[i] || gaps > 1)  // faces of another component, or a pinched vertex
        return ERROR_NO_TOPOLOGICAL_DISC;
    }
    return euler_characteristic() == 2 - m_border_loops ? OK : ERROR_NO_TOPOLOGICAL_DISC;
  }

  const TriangleMesh* m_mesh = nullptr;
  Mesh_indexer<TriangleMesh> m_indexer;
  std::vector<std::vector<halfedge_descriptor> > m_loops;  // during construction only
};

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CORE_CHECKED_DISK_H
