// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_CONFORMAL_BORDER_PARAMETERIZER_3_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_CONFORMAL_BORDER_PARAMETERIZER_3_H

/// \file Conformal_border_parameterizer_3.h

#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_patch_3.h>
#include <CGAL/Surface_mesh_parameterization/internal/conformal_border.h>
#include <CGAL/Surface_mesh_parameterization/internal/polar_map.h>

#include <CGAL/boost/graph/properties.h>
#include <CGAL/Default.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <Eigen/Core>

#include <cstddef>
#include <memory>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgSurfaceMeshParameterizationMeasured
///
/// A border parameterizer that maps the border of a disk-like mesh onto the *conformal*
/// border: the border that Boundary First Flattening (Sawhney and Crane, ACM Transactions on
/// Graphics 37(1), 2017) computes with boundary scale factors 0, i.e. the border for which the
/// discrete conformal map of the interior has (to first order) the least angle distortion
/// while the border edges keep their 3D lengths. It needs one factorization of the interior
/// cotangent Laplacian \f$ L_{II} \f$ and one back-substitution:
///
/// 1. the angle sums \f$ s_i \f$ of the 3D corner angles; angle defects
///    \f$ \Omega_i = 2\pi - s_i \f$ of the interior vertices, geodesic curvature
///    \f$ \kappa_i = \pi - s_i \f$ of the border vertices;
/// 2. \f$ L_{II} u_I = \Omega_I \f$ (with \f$ u_B = 0 \f$) and \f$ h = L_{BI} u_I \f$, where
///    \f$ L = D - W \f$ is the cotangent Laplacian;
/// 3. the target turning angles \f$ \tilde\kappa_i = \kappa_i - h_i \f$, which sum to
///    \f$ 2\pi \f$ (discrete Gauss-Bonnet);
/// 4. the polygon with these turning angles and the 3D border edge lengths \f$ l \f$,
///    closed with the smallest change of lengths,
///    \f$ l^* = l - N^{-1} T^\top (T N^{-1} T^\top)^{-1} T l \f$, with \f$ T \f$ the
///    \f$ 2 \times m \f$ matrix of edge directions and \f$ N^{-1} = \mathrm{diag}(l) \f$.
///
/// A planar disk is reproduced exactly (up to a similarity), a developable one is unrolled.
/// The polygon is not star-shaped in general and can self-intersect (long, thin or
/// spiralling borders). It is checked, and when it is not simple the turning angles are
/// blended toward those of the arc-length circle, \f$ (1 - t) \tilde\kappa + t c \f$ with
/// \f$ c_i = \pi (l_{i-1} + l_i) / \sum l \f$, the lengths kept: the smallest \f$ t \f$ with a
/// simple polygon is found by bisection (at \f$ t = 1 \f$ every turning angle is positive,
/// so the polygon is convex). The record tells the blend.
///
/// Holes (border loops other than the one of `bhd`) are filled virtually as by
/// `Parameterization_patch_3::build_disk()`, so the border is that of the filled disk.
///
/// The conventions are those of `Circular_border_arc_length_parameterizer_3`, so the class
/// is a drop-in replacement in every fixed border parameterizer of CGAL
/// (`Discrete_conformal_map_parameterizer_3`, `Mean_value_coordinates_parameterizer_3`,
/// `Barycentric_mapping_parameterizer_3`, `Discrete_authalic_parameterizer_3`): the loop
/// `halfedges_around_face(bhd)` is mapped clockwise (faces keep a positive orientation), and
/// the polygon is scaled uniformly so that its bounding box is centered in \f$ [0,1]^2 \f$
/// with its longest side spanning \f$ [0,1] \f$. `is_border_convex()` tells whether the
/// polygon of the last call was verified strictly convex: CGAL's barycentric and mean value
/// parameterizers skip their one-to-one check only in that case. A fixed border map with a
/// non-convex border can fold (CGAL's parameterizers still return `OK`): check the result.
/// `Measured_conformal_parameterizer_3` with `CONFORMAL_BORDER` computes the same border and
/// its interior on one factorization, checks the result and repairs it.
///
/// The record of the last call can be read back; copies of a parameterizer share it (as
/// `Measured_border_parameterizer_3`).
///
/// \cgalModels `Parameterizer_3` (border parameterizer part, as CGAL's circular border
///             parameterizers)
///
/// \tparam TriangleMesh_ a model of `FaceGraph`.
/// \tparam SolverTraits_ a model of `SparseLinearAlgebraWithFactorTraits_d` for the
///         factorization of \f$ L_{II} \f$. %Default: `Default_sparse_cholesky_traits`.
template <class TriangleMesh_, class SolverTraits_ = Default>
class Conformal_border_parameterizer_3
{
public:
  /// Triangle mesh type
  typedef TriangleMesh_                                                          Triangle_mesh;
  /// Triangle mesh type (CGAL's name in its border parameterizers)
  typedef TriangleMesh_                                                          TriangleMesh;
  /// Solver traits type
  typedef typename internal::Get_solver_traits<SolverTraits_>::type              Solver_traits;
  /// The patch type the border is computed on
  typedef Parameterization_patch_3<TriangleMesh_, Solver_traits>                 Patch;
  /// Vertex type of the mesh
  typedef typename boost::graph_traits<Triangle_mesh>::vertex_descriptor         vertex_descriptor;
  /// Halfedge type of the mesh
  typedef typename boost::graph_traits<Triangle_mesh>::halfedge_descriptor       halfedge_descriptor;

  /// Bisection steps of the blend toward the circle when the conformal polygon is not simple.
  static constexpr int blend_bisection_steps() { return 20; }

  /// What the last call computed. Border vertex `k` is `border_vertices[k]`; border edge `k`
  /// joins border vertices `k` and `k + 1` (modulo the loop's size).
  struct Record
  {
    /// status of the last call
    Error_code status = ERROR_WRONG_PARAMETER;
    /// the border loop, from `source(bhd)` (empty when the input was rejected)
    std::vector<vertex_descriptor> border_vertices;
    /// the border polygon: the UV of each border vertex (the values written in the map)
    std::vector<Eigen::Vector2d> border_uv;
    /// 3D length of each border edge
    std::vector<double> edge_lengths;
    /// the length of each border edge in the closed polygon, before its uniform scaling
    /// into \f$ [0,1]^2 \f$
    std::vector<double> closed_lengths;
    /// geodesic curvature \f$ \kappa_k = \pi - s_k \f$ of each border vertex
    std::vector<double> geodesic_curvatures;
    /// the correction \f$ h_k = (L_{BI} u_I)_k \f$
    std::vector<double> corrections;
    /// the target turning angle \f$ \tilde\kappa_k = \kappa_k - h_k \f$ (sum \f$ 2\pi \f$)
    std::vector<double> turning_angles;
    /// the blend toward the circle's turning angles (0: the conformal border was simple)
    double blend = 0.;
    /// whether the border polygon was verified strictly convex
    bool strictly_convex = false;
    /// factorizations and back-substitutions done by the call
    typename Patch::Statistics statistics;
  };

  /// creates a conformal border parameterizer.
  Conformal_border_parameterizer_3() : m_record(std::make_shared<Record>()) { }

  /// assigns to the border vertices of the loop of `bhd` their position on the conformal
  /// border, and marks them parameterized in `vpmap`. Nothing is written on failure.
  ///
  /// \tparam VertexUVmap a model of `ReadWritePropertyMap` with `vertex_descriptor` as key
  ///         and a 2D point type constructible from two `double` as value.
  /// \tparam VertexIndexMap a model of `ReadablePropertyMap` (unused: the patch indexes its
  ///         own vertices).
  /// \tparam VertexParameterizedMap a model of `ReadWritePropertyMap` with
  ///         `vertex_descriptor` as key and `bool` as value.
  ///
  /// \return `OK` or the first failure: see `Parameterization_patch_3::build_disk()` for the
  ///         input checks, then `ERROR_CANNOT_SOLVE_LINEAR_SYSTEM`,
  ///         `ERROR_DEGENERATE_BORDER_MAP` (no closed polygon).
  template <class VertexUVmap, class VertexIndexMap, class VertexParameterizedMap>
  Error_code parameterize(const Triangle_mesh& mesh,
                          halfedge_descriptor bhd,
                          VertexUVmap uvmap,
                          VertexIndexMap /* vimap */,
                          VertexParameterizedMap vpmap)
  {
    Patch patch;
    Error_code status = patch.build_disk(mesh, bhd, get(vertex_point, mesh));
    if(status != OK)
    {
      *m_record = Record();
      m_record->status = status;
      return status;
    }
    std::vector<Eigen::Vector2d> uv;
    status = parameterize_border(patch, uv);
    if(status != OK)
      return status;
    typedef typename boost::property_traits<VertexUVmap>::value_type Point_2;
    for(std::size_t k = 0; k < uv.size(); ++k)
    {
      const vertex_descriptor v = patch.vertex(static_cast<std::size_t>(patch.border()[k]));
      put(uvmap, v, Point_2(uv[k].x(), uv[k].y()));
      put(vpmap, v, true);
    }
    return OK;
  }

  /// the patch-level step: computes the conformal border of `patch` (a disk patch; its
  /// \f$ L_{II} \f$ is factorized unless it already is) and stores the border UVs, one per
  /// `patch.border()` entry, in `uv`. Updates the record.
  template <class AnyPatch>
  Error_code parameterize_border(AnyPatch& patch, std::vector<Eigen::Vector2d>& uv)
  {
    Record record;
    for(int b : patch.border())
      record.border_vertices.push_back(patch.vertex(static_cast<std::size_t>(b)));
    internal::Conformal_border_data data;
    Error_code status = internal::conformal_border_data(patch, data);
    if(status == OK)
      status = internal::smallest_simple_blend(data, blend_bisection_steps(), record.blend, uv,
                                               record.closed_lengths);
    record.status = status;
    record.statistics = patch.statistics();
    if(status == OK)
    {
      record.border_uv = uv;
      record.edge_lengths = data.lengths;  // in the mesh's unit of length
      for(std::vector<double>* l : {&record.edge_lengths, &record.closed_lengths})
        for(double& x : *l)
          x *= patch.length_unit();
      record.geodesic_curvatures = data.curvature;
      record.corrections = data.correction;
      record.turning_angles = data.turning;
      record.strictly_convex = internal::is_strictly_convex_clockwise(uv);
    }
    *m_record = record;
    return status;
  }

  /// whether the border polygon of the last successful call was verified strictly convex
  /// (`false` before any call and after a failure).
  bool is_border_convex() const { return m_record->status == OK && m_record->strictly_convex; }

  /// the record of the last call.
  const Record& last_record() const { return *m_record; }
  /// the border polygon of the last call (one UV per border vertex, from `source(bhd)`).
  const std::vector<Eigen::Vector2d>& border_polygon() const { return m_record->border_uv; }
  /// the border vertices of the last call, from `source(bhd)` along the loop.
  const std::vector<vertex_descriptor>& border_vertices() const { return m_record->border_vertices; }

private:
  std::shared_ptr<Record> m_record;
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_CONFORMAL_BORDER_PARAMETERIZER_3_H
