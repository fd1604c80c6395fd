// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_PARAMETERIZATION_PATCH_3_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_PARAMETERIZATION_PATCH_3_H

/// \file Parameterization_patch_3.h
/// The checked, indexed view of one connected component of a triangle mesh that every step
/// of the measured boundary parameterization works on.

#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/internal/laplacian.h>
#include <CGAL/Surface_mesh_parameterization/internal/sparse_solver.h>
#include <CGAL/Surface_mesh_parameterization/internal/triangle_adjacency.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <memory>
#include <mutex>
#include <typeindex>
#include <typeinfo>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgSurfaceMeshParameterizationMeasured
///
/// One connected component of a triangle mesh, checked and indexed for the measured
/// boundary parameterization: the vertices get dense local indices `0..n-1` (so generic code
/// never relies on the mesh's own vertex descriptors being integers), positions are copied
/// as `double`, faces become index triples, and, for a disk patch, the border loop is listed
/// in the order of `halfedges_around_face(bhd, mesh)` starting at `source(bhd)`.
///
/// The patch also owns the one numerical object that all steps share: the cotangent
/// Laplacian `L_II` restricted to the interior vertices (border loop eliminated, symmetric
/// positive definite). It is assembled and factorized on first use, and every later request
/// (the boundary Poisson distance map, the discrete conformal interior solve) reuses the
/// factorization by back-substitution. `statistics()` counts the factorizations and
/// back-substitutions done so far.
///
/// It also owns, on request, the factorization of the spring Laplacian grounded at one
/// vertex, which serves the Poisson distance map from any single source.
///
/// Concurrency: after `build_disk()` or `build_component()`, the interior system (with
/// `factorize_interior_laplacian()`, `solve_interior()`) and the spring system (with
/// `factorize_spring_laplacian()`, `solve_spring_poisson()`) may be used from two different
/// threads at the same time; everything else is read-only.
///
/// This class is the argument type of the `MeasuredCenterLocator` and
/// `MeasuredBorderDistance` concepts.
///
/// \tparam TriangleMesh a model of `FaceGraph` (`Surface_mesh`, `Polyhedron_3`, `Seam_mesh`, ...).
/// \tparam SolverTraits a model of `SparseLinearAlgebraWithFactorTraits_d`, used for every
///         linear system of the patch. %Default: `Default_sparse_cholesky_traits`
///         (Eigen's `SimplicialLDLT`). Each system default-constructs its own traits object.
///
/// A patch refers to the mesh it was built from: the mesh must outlive it and stay unchanged.
template <class TriangleMesh, class SolverTraits = Default>
class Parameterization_patch_3
{
public:
  /// The mesh type.
  typedef TriangleMesh                                                          Triangle_mesh;
  /// The solver traits type.
  typedef typename internal::Get_solver_traits<SolverTraits>::type              Solver_traits;
  /// Vertex type of the mesh.
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor         vertex_descriptor;
  /// Halfedge type of the mesh.
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor       halfedge_descriptor;
  /// Face type of the mesh.
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor           face_descriptor;
  /// Three local vertex indices, in the mesh's face orientation.
  typedef internal::Face_indices                                                Face;
  /// Counters of the numerical work done on this patch.
  typedef internal::Solver_statistics                                           Statistics;

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

  /// creates an empty patch; fill it with `build_disk()` or `build_component()`.
  Parameterization_patch_3() = default;
  Parameterization_patch_3(const Parameterization_patch_3&) = delete;
  Parameterization_patch_3& operator=(const Parameterization_patch_3&) = delete;
  Parameterization_patch_3(Parameterization_patch_3&&) = default;
  Parameterization_patch_3& operator=(Parameterization_patch_3&&) = default;

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
  /// non-manifold, or the component has handles), `ERROR_NON_FINITE_COORDINATES`,
  /// `ERROR_DEGENERATE_FACE`, `ERROR_NO_INTERIOR_VERTEX`. On failure the patch is empty.
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
  /// or `ERROR_DEGENERATE_FACE` on failure; the patch is then empty.
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
  /// the local index of `v`, or -1 when `v` is not a vertex of the patch.
  int index(vertex_descriptor v) const
  {
    if(m_vertices.empty())
      return -1;
    const int stored = get(m_index_map, v);  // local index + 1; 0 means "not in the patch"
    return stored - 1;
  }
  /// the position of local vertex `i`.
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

  /// \name Shared numerics
  /// @{

  /// `d_i = sum_j w_ij` for the cotangent weights `w_ij = (cot a_ij + cot b_ij) / 2`.
  const std::vector<double>& cotangent_row_sums() const { return m_cot_row_sums; }

  /// `g_i`: mean length of the edges at each vertex (paper Eq. 1's right-hand side).
  const std::vector<double>& mean_spoke_lengths() const { return m_mean_spoke; }

  /// assembles and factorizes the interior cotangent Laplacian `L_II` unless it already is.
  /// Requires a disk patch (a main border); otherwise returns `ERROR_WRONG_PARAMETER`.
  Error_code factorize_interior_laplacian()
  {
    if(m_interior_system && m_interior_system->is_factorized())
      return OK;
    if(m_border.empty() || m_interior.empty())
      return ERROR_WRONG_PARAMETER;
    m_interior_system = std::make_unique<System>();
    Eigen::SparseMatrix<double> L;
    m_pattern.assemble(m_faces, m_interior_index, static_cast<int>(m_interior.size()),
                       internal::Cotangent_weight{&m_half_cot}, L);
    return m_interior_system->factor(L);
  }

  /// solves `L_II x = b` (one entry per interior vertex, in `interior_vertices()` order),
  /// factorizing `L_II` first if needed.
  Error_code solve_interior(const std::vector<double>& b, std::vector<double>& x)
  {
    const Error_code status = factorize_interior_laplacian();
    if(status != OK)
      return status;
    return m_interior_system->solve(b, x);
  }

  /// solves `L_II X = B` for every column of `B` (`interior_vertices().size()` rows), with one
  /// pass over the factorization for all columns when the solver allows it.
  Error_code solve_interior(const Eigen::MatrixXd& B, Eigen::MatrixXd& X)
  {
    const Error_code status = factorize_interior_laplacian();
    if(status != OK)
      return status;
    return m_interior_system->solve(B, X);
  }

  /// right-hand side of the interior Dirichlet problem for border values `border_values`
  /// (one per `border()` entry): `b_i = sum_{j in border} w_ij border_values_j`.
  void interior_rhs_from_border(const std::vector<double>& border_values,
                                std::vector<double>& b) const
  {
    b.assign(m_interior.size(), 0.);
    for(const Coupling& c : m_coupling)
      b[static_cast<std::size_t>(c.row)] += c.weight * border_values[static_cast<std::size_t>(c.border_index)];
  }

  /// the same for several border functions at once: column `j` of `border_values` (one row
  /// per `border()` entry) gives column `j` of `b`.
  void interior_rhs_from_border(const Eigen::MatrixXd& border_values, Eigen::MatrixXd& b) const
  {
    b.setZero(static_cast<Eigen::Index>(m_interior.size()), border_values.cols());
    for(const Coupling& c : m_coupling)
      b.row(c.row) += c.weight * border_values.row(c.border_index);
  }

  /// the border rows of the cotangent Laplacian \f$ L = D - W \f$ applied to a function that
  /// vanishes on the border: \f$ h = L_{BI} x \f$, i.e.
  /// \f$ h_k = -\sum_{i \in I} w_{b_k i} x_i \f$, one value per `border()` entry (`x` in
  /// `interior_vertices()` order). It is the transpose of `interior_rhs_from_border()`.
  void border_rows_times_interior(const std::vector<double>& x, std::vector<double>& h) const
  {
    h.assign(m_border.size(), 0.);
    for(const Coupling& c : m_coupling)
      h[static_cast<std::size_t>(c.border_index)] -= c.weight * x[static_cast<std::size_t>(c.row)];
  }

  /// assembles and factorizes, unless it already is for this `exponent`, the spring
  /// Laplacian (weights \f$ |x_i - x_j|^{-r} \f$, \f$ r \f$ = `exponent`) of the whole patch
  /// *grounded* at one vertex (`spring_ground()`), i.e. restricted to the other vertices.
  /// This factorization does not depend on the center, so it can be computed while the
  /// center is being located, and it serves the Poisson distance map from any single source
  /// (`solve_spring_poisson()`).
  Error_code factorize_spring_laplacian(double exponent)
  {
    if(m_spring_system && m_spring_system->is_factorized() && m_spring_exponent == exponent)
      return OK;
    if(m_vertices.size() < 2 || !std::isfinite(exponent))
      return ERROR_WRONG_PARAMETER;
    m_spring_exponent = exponent;
    m_spring_ground = m_border.empty() ? 0 : static_cast<std::size_t>(m_border.front());
    std::vector<int> unknown(m_vertices.size());
    int next = 0;
    for(std::size_t i = 0; i < unknown.size(); ++i)
      unknown[i] = (i == m_spring_ground) ? -1 : next++;
    const internal::Spring_weight weight{&m_faces, &m_points, &m_single_edges, exponent};
    internal::laplacian_row_sums(m_faces, m_vertices.size(), weight, m_spring_row_sums);
    Eigen::SparseMatrix<double> L;
    m_pattern.assemble(m_faces, unknown, next, weight, L);
    m_spring_system = std::make_unique<System>();
    return m_spring_system->factor(L);
  }

  /// the vertex at which the spring Laplacian is grounded.
  std::size_t spring_ground() const { return m_spring_ground; }

  /// the Poisson distance map (paper Eq. 1, spring weights with exponent `exponent`) from the
  /// single vertex `source`, one value per patch vertex, with one back-substitution of the
  /// grounded spring Laplacian (factorized first if needed).
  ///
  /// With \f$ b_i = d_i g_i \f$, the map \f$ f \f$ solves \f$ (L f)_i = b_i \f$ for
  /// \f$ i \neq s \f$ and \f$ f_s = 0 \f$. Set \f$ r = b \f$ off the source and
  /// \f$ r_s = -\sum_{i \neq s} b_i \f$: then \f$ \sum r = 0 \f$, so \f$ L g = r \f$ has the
  /// solutions \f$ g + c \mathbf{1} \f$, one of which the grounded system gives, and
  /// \f$ f = g - g_s \mathbf{1} \f$ (the solution is unique).
  Error_code solve_spring_poisson(std::size_t source, double exponent, std::vector<double>& values)
  {
    if(source >= m_vertices.size())
      return ERROR_WRONG_PARAMETER;
    Error_code status = factorize_spring_laplacian(exponent);
    if(status != OK)
      return status;
    const std::size_t n = m_vertices.size();
    std::vector<double> rhs;
    rhs.reserve(n - 1);
    double sum = 0.;
    for(std::size_t i = 0; i < n; ++i)
    {
      const double b = (i == source) ? 0. : m_spring_row_sums[i] * m_mean_spoke[i];
      sum += b;
      if(i != m_spring_ground)
        rhs.push_back(b);
    }
    if(source != m_spring_ground)
    {
      const std::size_t row = (source < m_spring_ground) ? source : source - 1;
      rhs[row] = -sum;
    }
    std::vector<double> g;
    status = m_spring_system->solve(rhs, g);
    if(status != OK)
      return status;
    values.resize(n);
    for(std::size_t i = 0, row = 0; i < n; ++i)
      values[i] = (i == m_spring_ground) ? 0. : g[row++];
    const double shift = values[source];
    for(double& f : values)
      f -= shift;
    values[source] = 0.;
    return OK;
  }

  /// the object of type `T` attached to this patch, constructed as `T(patch)` on the first
  /// request. Policies use it to share center-independent work on the same patch (for
  /// example a geodesic solver's precomputation serves both the center locator and the
  /// border distance). Thread-safe: a request made while the object is being constructed
  /// waits for it. The object lives as long as the patch's current content.
  template <class T>
  T& shared_object()
  {
    std::unique_lock<std::mutex> lock(*m_objects_mutex);
    std::shared_ptr<void>& slot = m_objects[std::type_index(typeid(T))];
    if(!slot)
      slot = std::make_shared<T>(static_cast<const Parameterization_patch_3&>(*this));
    return *static_cast<T*>(slot.get());
  }

  /// records the work of a system that a policy solved on its own (for example the spring
  /// Laplacian of a multi-source Poisson distance map), so that `statistics()` tells the
  /// whole cost.
  void add_statistics(const Statistics& s) { m_other_stats.add(s); }

  /// factorizations and back-substitutions done so far on this patch (times are summed
  /// over systems, also when two were factorized concurrently).
  Statistics statistics() const
  {
    Statistics s = m_other_stats;
    if(m_interior_system)
      s.add(m_interior_system->statistics());
    if(m_spring_system)
      s.add(m_spring_system->statistics());
    return s;
  }

  /// @}

private:
  typedef internal::Factorized_system<Solver_traits> System;

  void clear()
  {
    m_mesh = nullptr;
    m_bhd = halfedge_descriptor();
    m_vertices.clear();
    m_points.clear();
    m_faces.clear();
    m_single_edges.clear();
    m_half_cot.clear();
    m_border.clear();
    m_interior.clear();
    m_interior_index.clear();
    m_cot_row_sums.clear();
    m_mean_spoke.clear();
    m_pattern = internal::Laplacian_pattern();
    m_coupling.clear();
    m_spring_row_sums.clear();
    m_border_loops = 0;
    m_loops.clear();
    m_hole_loops.clear();
    m_on_hole.clear();
    m_real_vertices = 0;
    m_real_faces = 0;
    m_interior_system.reset();
    m_spring_system.reset();
    m_spring_exponent = 0.;
    m_spring_ground = 0;
    m_objects.clear();
    m_other_stats = Statistics();
  }

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

  // A disk with holes: every vertex has a single umbrella and the Euler characteristic is
  // 2 - (number of border loops), i.e. genus 0.
  Error_code check_disk_topology() const
  {
    const TriangleMesh& tm = *m_mesh;
    std::vector<int> corners(m_vertices.size(), 0);
    for(const Face& t : m_faces)
      for(int id : t)
        ++corners[static_cast<std::size_t>(id)];
    for(std::size_t i = 0; i < m_vertices.size(); ++i)
    {
      int around = 0;
      for(halfedge_descriptor h : halfedges_around_target(halfedge(m_vertices[i], tm), tm))
        if(!is_border(h, tm))
          ++around;
      if(around != corners[i])
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
    // the cotangent weights between interior vertices and the main border loop
    if(!m_border.empty())
    {
      std::vector<int> position(m_vertices.size(), -1);
      for(std::size_t k = 0; k < m_border.size(); ++k)
        position[static_cast<std::size_t>(m_border[k])] = static_cast<int>(k);
      for(std::size_t f = 0; f < m_faces.size(); ++f)
        for(int k = 0; k < 3; ++k)
        {
          const std::size_t a = static_cast<std::size_t>(m_faces[f][(k + 1) % 3]);
          const std::size_t c = static_cast<std::size_t>(m_faces[f][(k + 2) % 3]);
          const double w = m_half_cot[f][static_cast<std::size_t>(k)];
          if(m_interior_index[a] >= 0 && position[c] >= 0)
            m_coupling.push_back({m_interior_index[a], position[c], w});
          if(m_interior_index[c] >= 0 && position[a] >= 0)
            m_coupling.push_back({m_interior_index[c], position[a], w});
        }
    }
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
  std::size_t m_real_faces = 0;
  std::vector<double> m_cot_row_sums;
  std::vector<double> m_mean_spoke;
  internal::Laplacian_pattern m_pattern;
  struct Coupling
  {
    int row;           // interior row
    int border_index;  // position in m_border
    double weight;
  };
  std::vector<Coupling> m_coupling;
  std::unique_ptr<System> m_interior_system;
  std::unique_ptr<System> m_spring_system;
  std::vector<double> m_spring_row_sums;
  double m_spring_exponent = 0.;
  std::size_t m_spring_ground = 0;
  Statistics m_other_stats;
  std::unique_ptr<std::mutex> m_objects_mutex = std::make_unique<std::mutex>();
  std::map<std::type_index, std::shared_ptr<void> > m_objects;
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_PARAMETERIZATION_PATCH_3_H
