// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_MEASURED_BORDER_PARAMETERIZER_3_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_MEASURED_BORDER_PARAMETERIZER_3_H

/// \file Measured_border_parameterizer_3.h

#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_patch_3.h>
#include <CGAL/Surface_mesh_parameterization/Poisson_center_locator.h>
#include <CGAL/Surface_mesh_parameterization/Poisson_border_distance.h>
#include <CGAL/Surface_mesh_parameterization/internal/concurrency.h>
#include <CGAL/Surface_mesh_parameterization/internal/polar_map.h>

#include <CGAL/boost/graph/properties.h>
#include <CGAL/Default.h>
#include <CGAL/tags.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <chrono>
#include <cstddef>
#include <future>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

namespace internal {

// Whether a border distance policy has the optional `prepare(patch)` step.
template <class Policy, class Patch, class = void>
struct Has_prepare : std::false_type {};

template <class Policy, class Patch>
struct Has_prepare<Policy, Patch,
  std::void_t<decltype(std::declval<const Policy&>().prepare(std::declval<Patch&>()))> >
  : std::true_type {};

} // namespace internal

/// \ingroup PkgSurfaceMeshParameterizationMeasured
///
/// A border parameterizer that maps the border of a disk-like mesh onto the *measured*
/// polygon of the paper "Measured boundary parameterization based on Poisson's equation":
///
/// 1. a center vertex is found by the `CenterLocator` policy (default: the maximum of the
///    boundary Poisson distance map);
/// 2. the distance `r_k` from the center to every border vertex `b_k` is measured by the
///    `BorderDistance` policy (default: the Poisson distance map from the center);
/// 3. the border is laid out as a polar map around the center: the angle of `b_k` is
///    `-2 pi (theta_0 + ... + theta_{k-1}) / (theta_0 + ... + theta_{m-1})`, where `theta_l`
///    is the 3D angle at the center between `b_l` and `b_{l+1}`, and its radius is `r_k`.
///
/// The conventions are those of `Circular_border_arc_length_parameterizer_3`, so the class
/// is a drop-in replacement in every fixed border parameterizer of CGAL
/// (`Discrete_conformal_map_parameterizer_3`, `Mean_value_coordinates_parameterizer_3`,
/// `Barycentric_mapping_parameterizer_3`, `Discrete_authalic_parameterizer_3`): the loop
/// `halfedges_around_face(bhd)` is mapped with decreasing angles starting at `source(bhd)` at
/// angle 0, and the polygon is scaled uniformly so that its bounding box is centered in
/// \f$ [0,1]^2 \f$ with its longest side spanning \f$ [0,1] \f$.
///
/// The measured polygon is star-shaped around the center, hence simple, but in general not
/// convex. `is_border_convex()` reports whether the polygon of the last call was verified
/// strictly convex; CGAL's barycentric and mean value parameterizers skip their one-to-one
/// check only in that case.
///
/// The record of the last call (center, border vertices, distances, angles, work counters)
/// can be read back. Copies of a parameterizer share that record (as CGAL's
/// `Eigen_solver_traits` share their solver), so the object a user passes to
/// `Discrete_conformal_map_parameterizer_3`'s constructor sees the calls made through the
/// copy stored inside it. Do not use copies of one object concurrently.
///
/// \cgalModels `Parameterizer_3` (border parameterizer part, as CGAL's circular border
///             parameterizers)
///
/// \tparam TriangleMesh_ a model of `FaceGraph`.
/// \tparam CenterLocator_ a model of `MeasuredCenterLocator`. %Default:
///         `Poisson_center_locator<TriangleMesh_>`.
/// \tparam BorderDistance_ a model of `MeasuredBorderDistance`. %Default:
///         `Poisson_border_distance<TriangleMesh_>`.
/// \tparam SolverTraits_ a model of `SparseLinearAlgebraWithFactorTraits_d` for the linear
///         systems of the policies. %Default: `Default_sparse_cholesky_traits`.
/// \tparam ConcurrencyTag_ `CGAL::Sequential_tag` (default: no thread is started) or
///         `CGAL::Parallel_tag`: the border distance policy's `prepare()` step (for the
///         Poisson distances, the factorization of the spring Laplacian) runs in a second
///         thread while the center is located, and multi-column solves split their columns
///         over two threads. Results do not depend on it. The package never changes
///         process-wide settings: a threaded BLAS under CHOLMOD (OpenBLAS) uses its own
///         threads, set by the user (`OPENBLAS_NUM_THREADS`, or `openblas_set_num_threads()`).
///
/// `CGAL::Default` may be given for any policy to get its default.
template <class TriangleMesh_,
          class CenterLocator_ = Poisson_center_locator<TriangleMesh_>,
          class BorderDistance_ = Poisson_border_distance<TriangleMesh_>,
          class SolverTraits_ = Default,
          class ConcurrencyTag_ = CGAL::Sequential_tag>
class Measured_border_parameterizer_3
{
public:
  /// Triangle mesh type
  typedef TriangleMesh_                                                          Triangle_mesh;
  /// Triangle mesh type (CGAL's name in its border parameterizers)
  typedef TriangleMesh_                                                          TriangleMesh;
  /// Center locator type
  typedef typename Default::Get<CenterLocator_,
                                Poisson_center_locator<TriangleMesh_> >::type   Center_locator;
  /// Border distance type
  typedef typename Default::Get<BorderDistance_,
                                Poisson_border_distance<TriangleMesh_> >::type  Border_distance;
  /// Solver traits type
  typedef typename internal::Get_solver_traits<SolverTraits_>::type              Solver_traits;
  /// Concurrency tag
  typedef ConcurrencyTag_                                                        Concurrency_tag;
  /// The patch type the policies work on
  typedef Parameterization_patch_3<TriangleMesh_, Solver_traits>                 Patch;

  /// Vertex type of the mesh
  typedef typename boost::graph_traits<Triangle_mesh>::vertex_descriptor         vertex_descriptor;
  /// Halfedge type of the mesh
  typedef typename boost::graph_traits<Triangle_mesh>::halfedge_descriptor       halfedge_descriptor;

  /// What the last call computed.
  struct Record
  {
    /// status of the last call
    Error_code status = ERROR_WRONG_PARAMETER;
    /// the center vertex (also after a failure of a later step; `null_vertex()` when the
    /// call failed before the center was located)
    vertex_descriptor center = boost::graph_traits<Triangle_mesh>::null_vertex();
    /// the border loop, from `source(bhd)` (also after a failure of a later step; empty
    /// when the input was rejected)
    std::vector<vertex_descriptor> border_vertices;
    /// distance from the center to each border vertex (same order)
    std::vector<double> border_distances;
    /// polar angle `phi_k` in `[0, 2 pi)` of each border vertex (the UV angle is `-phi_k`)
    std::vector<double> border_angles;
    /// UV position of the polar origin: border vertex `k` is at
    /// `polar_origin + polar_scale * border_distances[k] * (cos(-phi_k), sin(-phi_k))`
    Eigen::Vector2d polar_origin = Eigen::Vector2d(0.5, 0.5);
    /// UV length per unit of distance (in the mesh's unit of length, as `border_distances`)
    double polar_scale = 1.;
    /// whether the border polygon was verified strictly convex
    bool strictly_convex = false;
    /// factorizations and back-substitutions done by the call
    typename Patch::Statistics statistics;
    ///@{
    /// wall-clock seconds of step 1 (center), step 2 (distances) and step 3 (polar map)
    double center_seconds = 0., distance_seconds = 0., border_map_seconds = 0.;
    ///@}
  };

  /// creates a border parameterizer with the given policies.
  explicit Measured_border_parameterizer_3(Center_locator center_locator = Center_locator(),
                                           Border_distance border_distance = Border_distance())
    : m_center_locator(center_locator),
      m_border_distance(border_distance),
      m_record(std::make_shared<Record>())
  { }

  /// assigns to the border vertices of the loop of `bhd` their position on the measured
  /// polygon, and marks them parameterized in `vpmap`. Nothing is written on failure.
  ///
  /// \tparam VertexUVmap a model of `ReadWritePropertyMap` with `vertex_descriptor` as key
  ///         and a 2D point type constructible from two `double` as value.
  /// \tparam VertexIndexMap a model of `ReadablePropertyMap` (unused: the patch indexes its
  ///         own vertices).
  /// \tparam VertexParameterizedMap a model of `ReadWritePropertyMap` with
  ///         `vertex_descriptor` as key and `bool` as value.
  ///
  /// \return `OK` or the first failure: see `Parameterization_patch_3::build_disk()` for
  ///         the input checks, then the policies' codes, then `ERROR_DEGENERATE_BORDER_MAP`.
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

  /// the patch-level step: runs the two policies and the polar map on `patch` (a disk patch)
  /// and stores the border UVs, one per `patch.border()` entry, in `uv`. Updates the record.
  /// `Measured_conformal_parameterizer_3` calls this with its own patch so that the policies
  /// share its factorization, and with `factorize_interior` set so that the interior
  /// cotangent Laplacian is factorized (if the locator does not do it anyway) while the
  /// border distance policy prepares.
  ///
  /// When the border distance policy has a `prepare(patch)` step (center-independent work,
  /// such as a factorization) and `ConcurrencyTag_` is `CGAL::Parallel_tag`, that step runs
  /// in a second thread while the center is located.
  template <class AnyPatch>
  Error_code parameterize_border(AnyPatch& patch, std::vector<Eigen::Vector2d>& uv,
                                 bool factorize_interior = false)
  {
    typedef std::chrono::steady_clock Clock;
    Record record;
    std::size_t center = 0;
    std::vector<double> distances;
    internal::Polar_border polar;
    Clock::time_point t0 = Clock::now();

    Error_code prepared = OK;
    Error_code status = OK;
    bool located = false;
    {
      patch.set_parallel(internal::Is_parallel<Concurrency_tag>::value);
      std::future<Error_code> preparing;
      if constexpr(internal::Has_prepare<Border_distance, AnyPatch>::value)
      {
        if constexpr(internal::Is_parallel<Concurrency_tag>::value)
          preparing = internal::start_thread([this, &patch] { return m_border_distance.prepare(patch); });
        else
          prepared = m_border_distance.prepare(patch);
      }
      if(factorize_interior)
        status = patch.factorize_interior_laplacian();
      if(status == OK)
        status = m_center_locator.locate_center(patch, center);
      located = (status == OK);
      if(preparing.valid())
        prepared = preparing.get();
    }
    Clock::time_point t1 = Clock::now();
    record.center_seconds = std::chrono::duration<double>(t1 - t0).count();
    if(status == OK)
      status = prepared;
    if(status == OK)
    {
      status = m_border_distance.compute_border_distances(patch, center, distances);
      patch.release_spring_laplacian();  // only one factor stays alive: the interior system's
      t0 = Clock::now();
      record.distance_seconds = std::chrono::duration<double>(t0 - t1).count();
    }
    if(status == OK)
    {
      status = internal::polar_border_map(patch, center, distances, polar);
      record.border_map_seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    }

    record.status = status;
    record.statistics = patch.statistics();
    record.border_vertices.reserve(patch.border().size());
    for(int b : patch.border())
      record.border_vertices.push_back(patch.vertex(static_cast<std::size_t>(b)));
    if(located)
      record.center = patch.vertex(center);
    if(status == OK)
    {
      record.border_distances = distances;  // in the mesh's unit of length
      for(double& d : record.border_distances)
        d *= patch.length_unit();
      record.border_angles = polar.angles;
      record.polar_origin = polar.origin;
      record.polar_scale = polar.scale / patch.length_unit();  // per unit of the mesh's length
      record.strictly_convex = polar.strictly_convex;
      uv = polar.uv;
    }
    *m_record = record;
    return status;
  }

  /// whether the border polygon of the last successful call was verified strictly convex
  /// (`false` before any call and after a failure).
  bool is_border_convex() const { return m_record->status == OK && m_record->strictly_convex; }

  /// the record of the last call.
  const Record& last_record() const { return *m_record; }
  /// forgets the last call (its record becomes that of a call not made yet).
  void clear_record() { *m_record = Record(); }
  /// the center vertex of the last call (`null_vertex()` when it failed before locating it).
  vertex_descriptor center() const { return m_record->center; }
  /// the border vertices of the last call, from `source(bhd)` along the loop.
  const std::vector<vertex_descriptor>& border_vertices() const { return m_record->border_vertices; }
  /// the distance from the center to each border vertex in the last call.
  const std::vector<double>& border_distances() const { return m_record->border_distances; }
  /// the polar angle of each border vertex in the last call.
  const std::vector<double>& border_angles() const { return m_record->border_angles; }

  /// the center locator.
  const Center_locator& center_locator() const { return m_center_locator; }
  /// the border distance policy.
  const Border_distance& border_distance() const { return m_border_distance; }

private:
  Center_locator m_center_locator;
  Border_distance m_border_distance;
  std::shared_ptr<Record> m_record;
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_MEASURED_BORDER_PARAMETERIZER_3_H
