// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_CONFORMAL_PARAMETERIZER_3_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_CONFORMAL_PARAMETERIZER_3_H

/// \file Conformal_parameterizer_3.h

#include <CGAL/Surface_mesh_parameterization/Automatic_border.h>
#include <CGAL/Surface_mesh_parameterization/Circular_border.h>
#include <CGAL/Surface_mesh_parameterization/Conformal_length_border.h>
#include <CGAL/Surface_mesh_parameterization/Default_sparse_cholesky_traits.h>
#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_report.h>
#include <CGAL/Surface_mesh_parameterization/internal/borders/border_evaluator.h>
#include <CGAL/Surface_mesh_parameterization/internal/borders/border_reports.h>
#include <CGAL/Surface_mesh_parameterization/internal/borders/border_search.h>
#include <CGAL/Surface_mesh_parameterization/internal/borders/border_step.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/concurrency.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/disk.h>

#include <CGAL/boost/graph/properties.h>
#include <CGAL/Default.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/tags.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <chrono>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgSurfaceMeshParameterizationMeasured
/// What `Conformal_parameterizer_3` does when the layout of its border is not one-to-one.
enum Repair
{
  /// fail with `ERROR_NO_1_TO_1_MAPPING` (nothing is written)
  NO_REPAIR,
  /// blend the border toward a convex border, as little as needed: the measured border's
  /// radii and angles toward the circle in polar coordinates, the conformal border's turning
  /// angles toward the circle's (lengths kept). Two interiors are tried: the discrete
  /// conformal map (each blend costs two back-substitutions with the same factorization) and
  /// the mean value coordinates map (positive weights; one sparse LU factorization, then two
  /// back-substitutions per blend). For each, the smallest valid blend \f$ t \f$ is found by
  /// five bisection steps between the member's own border and its convex border, \f$ 1 \f$
  /// (the mean value map also tries the member's own border; after `Automatic_border`, whose
  /// search already tried the discrete conformal blends, only the mean value map is left); the
  /// valid candidate of lowest angle distortion (for `Automatic_border`, of lowest rank by its
  /// `Distortion_bound`) is kept. At \f$ t = 1 \f$ the border is
  /// convex, so the mean value map is valid (Floater's theorem): the repair always succeeds,
  /// up to rounding. When rounding defeats it (the circle's mean value map folds, on a disk
  /// of extreme area distortion), the other members' mean value blends are not searched:
  /// they would fail the same way. The default.
  BLEND_TOWARD_CIRCLE
};

/// \ingroup PkgSurfaceMeshParameterizationMeasured
///
/// The discrete conformal map of a disk-like mesh with the border of a border policy, on one
/// factorization, checked and repaired:
///
/// 1. the border: `BorderPolicy` (`Automatic_border` by default, `Conformal_border`,
///    `Conformal_length_border`, `Measured_border` for the paper's method, `Circular_border`),
///    computed with the interior cotangent Laplacian \f$ L_{II} \f$ (border eliminated,
///    symmetric positive definite), factorized once for the whole call
///    (`Conformal_length_border` factorizes the whole cotangent Laplacian too);
/// 2. the interior: \f$ L_{II} u_I = -L_{IB} u_B \f$, and the same for \f$ v \f$ (two
///    back-substitutions);
/// 3. the check: no flipped face over the disk, hole fillings included (holes are filled
///    virtually); with the simple border polygons of the policies this makes the map
///    one-to-one and every hole a simple polygon;
/// 4. the repair of an invalid layout (`Repair`, by default `BLEND_TOWARD_CIRCLE`).
///
/// With `Measured_border` and a direct solver the result equals that of CGAL's
/// `Discrete_conformal_map_parameterizer_3` with `Measured_border_parameterizer_3` before the
/// check, at a fraction of the cost: CGAL's fixed border parameterizers keep the border rows
/// in a non-symmetric system solved by BiCGSTAB by default. The paper's MBPPP is
/// `Measured_conformal_parameterizer_3` (this class with `Measured_border<>`).
///
/// `parameterize()` takes an optional `Parameterization_report*`: the center, the border
/// distances, the candidates tried, the work counters and the time of every stage. The object
/// holds no state of its calls: copies can run concurrently.
///
/// \cgalModels `Parameterizer_3`
///
/// \tparam TriangleMesh_ a model of `FaceGraph` (`Surface_mesh`, `Polyhedron_3`, `Seam_mesh`...).
/// \tparam BorderPolicy_ a model of `BorderPolicy`. %Default: `Automatic_border<>`.
/// \tparam SolverTraits_ a model of `SparseLinearAlgebraWithFactorTraits_d` for every
///         symmetric system. %Default: `Default_sparse_cholesky_traits` (Eigen's
///         `SimplicialLDLT`); CHOLMOD's supernodal Cholesky is available as
///         `Cholmod_supernodal_cholesky_traits`.
/// \tparam ConcurrencyTag_ `CGAL::Sequential_tag` (default: no thread is started) or
///         `CGAL::Parallel_tag`: the border distance policy's `prepare()` step runs in a
///         second thread while the center is located, and multi-column solves split their
///         columns over two threads. Results do not depend on it. The BLAS's threads under
///         CHOLMOD are not the package's: `Cholmod_supernodal_cholesky_traits` sets them
///         (its `blas_threads`, one by default).
template <class TriangleMesh_,
          class BorderPolicy_ = Automatic_border<>,
          class SolverTraits_ = Default,
          class ConcurrencyTag_ = CGAL::Sequential_tag>
class Conformal_parameterizer_3
{
public:
  /// Triangle mesh type
  typedef TriangleMesh_                                                         Triangle_mesh;
  /// Triangle mesh type (CGAL's name in its parameterizers)
  typedef TriangleMesh_                                                         TriangleMesh;
  /// Border policy type
  typedef typename Default::Get<BorderPolicy_, Automatic_border<> >::type       Border_policy;
  /// Solver traits type
  typedef Default_or_sparse_cholesky_traits<SolverTraits_>                     Solver_traits;
  /// Concurrency tag
  typedef ConcurrencyTag_                                                       Concurrency_tag;
  /// Vertex type of the mesh
  typedef typename boost::graph_traits<Triangle_mesh>::vertex_descriptor        vertex_descriptor;
  /// Halfedge type of the mesh
  typedef typename boost::graph_traits<Triangle_mesh>::halfedge_descriptor      halfedge_descriptor;

  /// creates a parameterizer with the given border policy, solver traits (copied once per
  /// system; see `Default_sparse_cholesky_traits`) and repair.
  explicit Conformal_parameterizer_3(Border_policy border = Border_policy(),
                                     Solver_traits solver_traits = Solver_traits(),
                                     Repair repair = BLEND_TOWARD_CIRCLE)
    : m_border(border), m_traits(solver_traits), m_repair(repair)
  { }

  /// creates a parameterizer with the given border policy and repair (default solver traits).
  Conformal_parameterizer_3(Border_policy border, Repair repair)
    : Conformal_parameterizer_3(border, Solver_traits(), repair)
  { }

  /// the border policy.
  const Border_policy& border_policy() const { return m_border; }
  /// the solver traits.
  const Solver_traits& solver_traits() const { return m_traits; }
  /// the repair.
  Repair repair() const { return m_repair; }

  /// computes the parameterization of the connected component bounded by the border loop of
  /// `bhd`, writes the UV of every vertex of that component into `uvmap` and marks it in
  /// `vpmap`. Nothing is written on failure.
  ///
  /// \tparam VertexUVmap a model of `ReadWritePropertyMap` with `vertex_descriptor` as key
  ///         and a 2D point type constructible from two `double` as value.
  /// \tparam VertexIndexMap a model of `ReadablePropertyMap` (unused: the component is
  ///         indexed by the parameterizer).
  /// \tparam VertexParameterizedMap a model of `ReadWritePropertyMap` with
  ///         `vertex_descriptor` as key and `bool` as value.
  /// \param mesh the mesh; the component of `bhd` must be a topological disk, possibly with
  ///        holes (filled virtually for the solves).
  /// \param bhd a border halfedge: its loop is the border laid out by the policy.
  /// \param uvmap receives the UV of every vertex of the component.
  /// \param vpmap receives `true` for every vertex of the component.
  /// \param report when not null, receives the report of the call (also after a failure:
  ///        its `status` and the fields of the steps that ran).
  /// \return `OK`, or the first failure: the input checks (`ERROR_EMPTY_MESH`,
  ///         `ERROR_INVALID_BORDER_HALFEDGE`, `ERROR_NON_TRIANGULAR_MESH`,
  ///         `ERROR_BORDER_TOO_SHORT`, `ERROR_NO_TOPOLOGICAL_DISC`,
  ///         `ERROR_NON_FINITE_COORDINATES`, `ERROR_DEGENERATE_FACE`,
  ///         `ERROR_NO_INTERIOR_VERTEX`), the policies' codes, `ERROR_DEGENERATE_BORDER_MAP`,
  ///         `ERROR_CANNOT_SOLVE_LINEAR_SYSTEM`, or `ERROR_NO_1_TO_1_MAPPING`.
  template <class VertexUVmap, class VertexIndexMap, class VertexParameterizedMap>
  Error_code parameterize(const Triangle_mesh& mesh, halfedge_descriptor bhd, VertexUVmap uvmap,
                          VertexIndexMap /* vimap */, VertexParameterizedMap vpmap,
                          Parameterization_report* report = nullptr) const
  {
    Stopwatch clock;
    Parameterization_report r;
    Disk disk(m_traits, internal::Is_parallel<Concurrency_tag>::value);
    Error_code status = disk.build_disk(mesh, bhd, get(vertex_point, mesh));
    r.preparation_seconds = clock.lap();
    if(status == OK)
    {
      r.vertices = disk.number_of_real_vertices();
      r.faces = disk.number_of_real_faces();
      internal::Border_step<Disk> step(disk, r, internal::Is_parallel<Concurrency_tag>::value, true);
      status = m_border.build(step);
      clock.lap();
      if(status == OK)
        status = lay_out(step, clock, uvmap, vpmap);
    }
    r.status = status;
    r.statistics = disk.statistics();
    r.total_seconds = clock.total();
    if(report)
      *report = r;
    return status;
  }

private:
  typedef internal::Disk<Triangle_mesh, Solver_traits> Disk;

  class Stopwatch
  {
  public:
    double lap()
    {
      const std::chrono::steady_clock::time_point now = std::chrono::steady_clock::now();
      const double s = std::chrono::duration<double>(now - m_last).count();
      m_last = now;
      return s;
    }
    double total() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count(); }

  private:
    std::chrono::steady_clock::time_point m_start = std::chrono::steady_clock::now(), m_last = m_start;
  };

  // Chooses among the candidates, repairs if needed and writes the kept layout.
  template <class VertexUVmap, class VertexParameterizedMap>
  Error_code lay_out(internal::Border_step<Disk>& step, Stopwatch& clock, VertexUVmap uvmap,
                     VertexParameterizedMap vpmap) const
  {
    Parameterization_report& r = step.report;
    internal::Border_evaluator<Disk> evaluator(step.disk, step.members);
    Error_code status = internal::choose_border(m_border, step, evaluator);
    const double measured = r.center_seconds + r.distance_seconds + r.border_map_seconds;
    r.interior_seconds = clock.lap() - (Border_policy::searches ? measured : 0.);
    if(status != OK)
      return status;
    const std::size_t tried = evaluator.trials().size();
    if(evaluator.best() < 0 && m_repair == BLEND_TOWARD_CIRCLE)
      internal::repair_by_blending(evaluator, step.repairable, !Border_policy::searches);
    r.repair_seconds = clock.lap();
    r.repair_candidates = static_cast<int>(evaluator.trials().size() - tried);
    status = internal::report_choice(evaluator, Border_policy::searches, r);
    if(status == OK)
    {
      write_uv(step.disk, evaluator.best_solution(), uvmap, vpmap);
      internal::report_border(evaluator.best_solution().border_uv, r);
    }
    r.output_seconds = clock.lap();
    return status;
  }

  template <class VertexUVmap, class VertexParameterizedMap>
  static void write_uv(const Disk& disk, const internal::Border_solution& s, VertexUVmap uvmap,
                       VertexParameterizedMap vpmap)
  {
    typedef typename boost::property_traits<VertexUVmap>::value_type Point_2;
    const std::vector<int>& border = disk.border();
    for(std::size_t k = 0; k < border.size(); ++k)
    {
      const vertex_descriptor vd = disk.vertex(static_cast<std::size_t>(border[k]));
      put(uvmap, vd, Point_2(s.border_uv[k].x(), s.border_uv[k].y()));
      put(vpmap, vd, true);
    }
    const std::vector<int>& interior = disk.interior_vertices();
    for(std::size_t r = 0; r < interior.size(); ++r)
    {
      if(disk.is_virtual(static_cast<std::size_t>(interior[r])))
        continue;  // the filling of a hole
      const vertex_descriptor vd = disk.vertex(static_cast<std::size_t>(interior[r]));
      put(uvmap, vd, Point_2(s.u[r], s.v[r]));
      put(vpmap, vd, true);
    }
  }

  Border_policy m_border;
  Solver_traits m_traits;
  Repair m_repair;
};

/// \ingroup PkgSurfaceMeshParameterizationMeasured
///
/// computes the parameterization of the connected component bounded by the border loop of
/// `bhd` with `parameterizer` and writes the UVs into `uvmap`: CGAL's
/// `parameterize(mesh, parameterizer, bhd, uvmap)` for this parameterizer (overload
/// resolution picks this more specialized function), without the work that CGAL's function
/// does for parameterizers that need it: the vertex index map of the component (a set of its
/// faces, O(F log F), about 14% of a call on a 45k-vertex mesh: the parameterizer indexes the
/// component itself) and its preconditions (a bad `bhd` is the error code
/// `ERROR_INVALID_BORDER_HALFEDGE`, not an assertion). `report`, when not null, receives the
/// report of the call.
template <class TriangleMesh, class BorderPolicy, class SolverTraits, class ConcurrencyTag,
          class HalfedgeDescriptor, class VertexUVmap>
Error_code parameterize(TriangleMesh& mesh,
                        Conformal_parameterizer_3<TriangleMesh, BorderPolicy, SolverTraits, ConcurrencyTag> parameterizer,
                        HalfedgeDescriptor bhd,
                        VertexUVmap uvmap,
                        Parameterization_report* report = nullptr)
{
  return parameterizer.parameterize(mesh, bhd, uvmap, get(CGAL::dynamic_vertex_property_t<int>(), mesh),
                                    get(CGAL::dynamic_vertex_property_t<bool>(), mesh), report);
}

/// \ingroup PkgSurfaceMeshParameterizationMeasured
///
/// The paper's measured boundary parameterization (MBPPP with the default policies):
/// `Conformal_parameterizer_3` with the border policy `Measured_border<CenterLocator,
/// BorderDistance>`.
template <class TriangleMesh, class CenterLocator = Poisson_center_locator,
          class BorderDistance = Poisson_border_distance, class SolverTraits = Default,
          class ConcurrencyTag = CGAL::Sequential_tag>
using Measured_conformal_parameterizer_3 = Conformal_parameterizer_3<TriangleMesh,
  Measured_border<CenterLocator, BorderDistance>, SolverTraits, ConcurrencyTag>;

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_CONFORMAL_PARAMETERIZER_3_H
