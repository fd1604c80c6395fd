// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_BORDER_PARAMETERIZER_3_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_BORDER_PARAMETERIZER_3_H

/// \file Border_parameterizer_3.h

#include <CGAL/Surface_mesh_parameterization/Default_sparse_cholesky_traits.h>
#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_report.h>
#include <CGAL/Surface_mesh_parameterization/internal/borders/border_reports.h>
#include <CGAL/Surface_mesh_parameterization/internal/borders/border_step.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/concurrency.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/disk.h>

#include <CGAL/boost/graph/properties.h>
#include <CGAL/tags.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <Eigen/Core>

#include <chrono>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgSurfaceMeshParameterizationMeasured
///
/// A border parameterizer that lays out the border of a disk-like mesh with a border policy
/// (`Measured_border`, `Conformal_border`, `Conformal_length_border` or `Circular_border`),
/// for CGAL's fixed border parameterizers: `Measured_border_parameterizer_3` and `Conformal_border_parameterizer_3`
/// are this class with the measured and the conformal border.
///
/// The conventions are those of `Circular_border_arc_length_parameterizer_3`, so the class
/// is a drop-in replacement in every fixed border parameterizer of CGAL
/// (`Discrete_conformal_map_parameterizer_3`, `Mean_value_coordinates_parameterizer_3`,
/// `Barycentric_mapping_parameterizer_3`, `Discrete_authalic_parameterizer_3`): the loop
/// `halfedges_around_face(bhd)` is mapped clockwise (faces keep a positive orientation) from
/// `source(bhd)`, and the polygon is scaled uniformly so that its bounding box is centered in
/// \f$ [0,1]^2 \f$ with its longest side spanning \f$ [0,1] \f$. `is_border_convex()` tells
/// whether the polygon of this object's last call was verified strictly convex: CGAL's
/// barycentric and mean value parameterizers skip their one-to-one check only in that case.
/// A fixed border map with a non-convex border can fold (CGAL's parameterizers still return
/// `OK`): check the result, or use `Conformal_parameterizer_3`, which computes the same border
/// and its interior on one factorization, checks the result and repairs it.
///
/// Holes (border loops other than the one of `bhd`) are filled virtually, so the border is
/// that of the filled disk.
///
/// \cgalModels `Parameterizer_3` (border parameterizer part, as CGAL's circular border
///             parameterizers)
///
/// \tparam TriangleMesh_ a model of `FaceGraph`.
/// \tparam BorderPolicy_ `Measured_border<...>`, `Conformal_border`, `Conformal_length_border` or
/// `Circular_border`.
/// \tparam SolverTraits_ a model of `SparseLinearAlgebraWithFactorTraits_d` for the systems
///         of the policies. %Default: `Default_sparse_cholesky_traits`.
/// \tparam ConcurrencyTag_ `CGAL::Sequential_tag` (default) or `CGAL::Parallel_tag` (see
///         `Conformal_parameterizer_3`).
template <class TriangleMesh_, class BorderPolicy_, class SolverTraits_ = Default,
          class ConcurrencyTag_ = CGAL::Sequential_tag>
class Border_parameterizer_3
{
public:
  /// Triangle mesh type
  typedef TriangleMesh_                                                          Triangle_mesh;
  /// Triangle mesh type (CGAL's name in its border parameterizers)
  typedef TriangleMesh_                                                          TriangleMesh;
  /// Border policy type
  typedef BorderPolicy_                                                          Border_policy;
  /// Solver traits type
  typedef Default_or_sparse_cholesky_traits<SolverTraits_>                      Solver_traits;
  /// Vertex type of the mesh
  typedef typename boost::graph_traits<Triangle_mesh>::vertex_descriptor         vertex_descriptor;
  /// Halfedge type of the mesh
  typedef typename boost::graph_traits<Triangle_mesh>::halfedge_descriptor       halfedge_descriptor;

  static_assert(!Border_policy::searches, "a border parameterizer lays out one border: use Conformal_parameterizer_3");

  /// creates a border parameterizer with the given policy and solver traits.
  ///
  /// CGAL's fixed border parameterizers call the copy of the border parameterizer they hold
  /// without a report: to read the report of those calls, give `report_sink`, where every
  /// call of this object or of its copies that is made without a report of its own writes
  /// its report (the caller owns it; it must outlive the copies).
  explicit Border_parameterizer_3(Border_policy border = Border_policy(), Solver_traits solver_traits = Solver_traits(),
                                  Parameterization_report* report_sink = nullptr)
    : m_border(border), m_traits(solver_traits), m_report_sink(report_sink)
  { }

  /// the border policy.
  const Border_policy& border_policy() const { return m_border; }

  /// assigns to the border vertices of the loop of `bhd` their position on the border of the
  /// policy, and marks them parameterized in `vpmap`. Nothing is written on failure.
  ///
  /// \tparam VertexUVmap a model of `ReadWritePropertyMap` with `vertex_descriptor` as key
  ///         and a 2D point type constructible from two `double` as value.
  /// \tparam VertexIndexMap a model of `ReadablePropertyMap` (unused: the parameterizer
  ///         indexes the component itself).
  /// \tparam VertexParameterizedMap a model of `ReadWritePropertyMap` with
  ///         `vertex_descriptor` as key and `bool` as value.
  /// \param mesh the mesh; the component of `bhd` must be a topological disk, possibly with
  ///        holes (filled virtually).
  /// \param bhd a border halfedge: its loop is laid out.
  /// \param uvmap receives the UV of every vertex of the loop of `bhd`.
  /// \param vpmap receives `true` for every vertex of the loop of `bhd`.
  /// \param report when not null, receives the report of the call (the border step's
  ///        fields: center, distances and polar placement, or the conformal border's
  ///        quantities; `border_uv`, `border_convex`). CGAL's fixed border parameterizers
  ///        call this function without it: to read the report of that call, derive from this
  ///        class and forward a report pointer of yours (see the user manual, section *The
  ///        measured border inside CGAL's parameterizers*).
  /// \return `OK` or the first failure: the input checks (see
  ///         `Conformal_parameterizer_3::parameterize()`), the policies' codes,
  ///         `ERROR_CANNOT_SOLVE_LINEAR_SYSTEM`, `ERROR_DEGENERATE_BORDER_MAP`.
  template <class VertexUVmap, class VertexIndexMap, class VertexParameterizedMap>
  Error_code parameterize(const Triangle_mesh& mesh, halfedge_descriptor bhd, VertexUVmap uvmap,
                          VertexIndexMap /* vimap */, VertexParameterizedMap vpmap,
                          Parameterization_report* report = nullptr)
  {
    const std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
    Parameterization_report r;
    const bool parallel = internal::Is_parallel<ConcurrencyTag_>::value;
    Disk disk(m_traits, parallel);
    Error_code status = disk.build_disk(mesh, bhd, get(vertex_point, mesh));
    r.preparation_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if(status == OK)
    {
      r.vertices = disk.number_of_real_vertices();
      r.faces = disk.number_of_real_faces();
      internal::Border_step<Disk> step(disk, r, parallel, false);
      status = m_border.build(step);
      if(status == OK)
        status = write_border(step, uvmap, vpmap);
    }
    r.status = status;
    r.statistics = disk.statistics();
    r.total_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    m_convex = (status == OK && r.border_convex);
    if(report != nullptr || m_report_sink != nullptr)
      *(report != nullptr ? report : m_report_sink) = r;
    return status;
  }

  /// whether the border polygon of this object's last successful call was verified strictly
  /// convex (`false` before any call and after a failure).
  bool is_border_convex() const { return m_convex; }

private:
  typedef internal::Disk<Triangle_mesh, Solver_traits> Disk;

  template <class VertexUVmap, class VertexParameterizedMap>
  static Error_code write_border(internal::Border_step<Disk>& step, VertexUVmap uvmap, VertexParameterizedMap vpmap)
  {
    typedef typename boost::property_traits<VertexUVmap>::value_type Point_2;
    std::vector<Eigen::Vector2d> uv;
    const Border_family member = Border_policy::member;
    if(!step.members.border(member, step.members.own_blend(member), uv))
      return ERROR_DEGENERATE_BORDER_MAP;
    internal::report_border(uv, step.report);
    for(std::size_t k = 0; k < uv.size(); ++k)
    {
      const vertex_descriptor v = step.disk.vertex(static_cast<std::size_t>(step.disk.border()[k]));
      put(uvmap, v, Point_2(uv[k].x(), uv[k].y()));
      put(vpmap, v, true);
    }
    return OK;
  }

  Border_policy m_border;
  Solver_traits m_traits;
  Parameterization_report* m_report_sink;
  bool m_convex = false;
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_BORDER_PARAMETERIZER_3_H
