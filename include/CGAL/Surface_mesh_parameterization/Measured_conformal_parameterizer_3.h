// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_MEASURED_CONFORMAL_PARAMETERIZER_3_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_MEASURED_CONFORMAL_PARAMETERIZER_3_H

/// \file Measured_conformal_parameterizer_3.h

#include <CGAL/Surface_mesh_parameterization/Measured_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_patch_3.h>
#include <CGAL/Surface_mesh_parameterization/Poisson_border_distance.h>
#include <CGAL/Surface_mesh_parameterization/Poisson_center_locator.h>
#include <CGAL/Surface_mesh_parameterization/internal/border_family.h>

#include <CGAL/boost/graph/properties.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Default.h>
#include <CGAL/tags.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgSurfaceMeshParameterizationMeasured
///
/// The complete measured boundary parameterization of the paper (MBPPP with the default
/// policies) in one call:
///
/// 1. the center (`CenterLocator`, default: maximum of the boundary Poisson distance map),
/// 2. the distance from the center to every border vertex (`BorderDistance`, default: the
///    Poisson distance map from the center),
/// 3. the polar border map (as `Measured_border_parameterizer_3`),
/// 4. the discrete conformal map of the interior with that border fixed:
///    \f$ L_{II} u_I = -L_{IB} u_B \f$, and the same for \f$ v \f$, where \f$ L \f$ is the
///    cotangent Laplacian.
///
/// The interior cotangent Laplacian \f$ L_{II} \f$ (border eliminated, symmetric positive
/// definite) is factorized once and serves step 1 and step 4: with the default policies a
/// call costs two factorizations (\f$ L_{II} \f$ and the spring Laplacian of step 2) and four
/// back-substitutions (paper sections 4.4 and 5.4). The result equals that of CGAL's
/// `Discrete_conformal_map_parameterizer_3` with `Measured_border_parameterizer_3` and a
/// direct solver, at a fraction of the cost: CGAL's fixed border parameterizers keep the
/// border rows in a non-symmetric system solved by BiCGSTAB by default.
///
/// The record of the last call (center, border distances, work counters, the time of every
/// stage) can be read back with `last_report()`. Copies of a parameterizer share that record,
/// so it is visible after `CGAL::Surface_mesh_parameterization::parameterize()`, which takes
/// the parameterizer by value. Do not use copies of one object concurrently.
///
/// Validity: a measured border is star-shaped but in general not convex, and cotangent
/// weights can be negative, so the discrete conformal interior can fold. Every result is
/// checked (no flipped face over the patch, hole fillings included; with the star-shaped
/// border this makes the map one-to-one and every hole a simple polygon) and, by default,
/// repaired by blending the border toward a circle (see `Repair`); `last_report()` says
/// whether and how. With `set_repair(NO_REPAIR)` an invalid result is an
/// `ERROR_NO_1_TO_1_MAPPING`.
///
/// \cgalModels `Parameterizer_3`
///
/// \tparam TriangleMesh_ a model of `FaceGraph`.
/// \tparam CenterLocator_ a model of `MeasuredCenterLocator`. %Default: `Poisson_center_locator`.
/// \tparam BorderDistance_ a model of `MeasuredBorderDistance`. %Default: `Poisson_border_distance`.
/// \tparam SolverTraits_ a model of `SparseLinearAlgebraWithFactorTraits_d` for every system
///         (factorization of symmetric positive definite matrices). %Default:
///         `Default_sparse_cholesky_traits` (Eigen's `SimplicialLDLT`); CHOLMOD's supernodal
///         Cholesky is available as `Cholmod_supernodal_cholesky_traits`.
/// \tparam ConcurrencyTag_ `CGAL::Sequential_tag` (default) or `CGAL::Parallel_tag`; see
///         `Measured_border_parameterizer_3`.
template <class TriangleMesh_,
          class CenterLocator_ = Poisson_center_locator<TriangleMesh_>,
          class BorderDistance_ = Poisson_border_distance<TriangleMesh_>,
          class SolverTraits_ = Default,
          class ConcurrencyTag_ = CGAL::Sequential_tag>
class Measured_conformal_parameterizer_3
{
public:
  /// Triangle mesh type
  typedef TriangleMesh_                                                         Triangle_mesh;
  /// Triangle mesh type (CGAL's name in its parameterizers)
  typedef TriangleMesh_                                                         TriangleMesh;
  /// The border step, which also holds the policies.
  typedef Measured_border_parameterizer_3<TriangleMesh_, CenterLocator_, BorderDistance_,
                                          SolverTraits_, ConcurrencyTag_>      Border_parameterizer;
  /// Center locator type (`CenterLocator_`, or the default)
  typedef typename Border_parameterizer::Center_locator                         Center_locator;
  /// Border distance type (`BorderDistance_`, or the default)
  typedef typename Border_parameterizer::Border_distance                        Border_distance;
  /// Solver traits type (`SolverTraits_`, or the default)
  typedef typename Border_parameterizer::Solver_traits                          Solver_traits;
  /// The patch type the policies work on
  typedef typename Border_parameterizer::Patch                                  Patch;
  /// Vertex type of the mesh
  typedef typename boost::graph_traits<Triangle_mesh>::vertex_descriptor        vertex_descriptor;
  /// Halfedge type of the mesh
  typedef typename boost::graph_traits<Triangle_mesh>::halfedge_descriptor      halfedge_descriptor;

  /// What to do when the layout of the chosen border is not one-to-one.
  enum Repair
  {
    /// fail with `ERROR_NO_1_TO_1_MAPPING` (nothing is written)
    NO_REPAIR,
    /// blend the border toward a convex border, as little as needed: the measured border's
    /// radii and angles toward the circle in polar coordinates, the conformal border's
    /// turning angles toward the circle's (lengths kept). Two interiors are tried: the
    /// discrete conformal map (each blend costs two back-substitutions with the same
    /// factorization) and the mean value coordinates map (positive weights; one sparse LU
    /// factorization, then two back-substitutions per blend). For each, the smallest valid
    /// blend \f$ t \f$ is found by five bisection steps on \f$ (0, 1] \f$ (the mean value map
    /// also tries \f$ t = 0 \f$); the valid candidate of lowest angle distortion is kept. At
    /// \f$ t = 1 \f$ the border is convex, so the mean value map is valid (Floater's
    /// theorem): the repair always succeeds, up to rounding. The default.
    BLEND_TOWARD_CIRCLE
  };

  /// Which border the call lays out.
  enum Border_choice
  {
    /// the border of the `BorderDistance` policy around the center of the `CenterLocator`
    /// policy (the paper's method). The default.
    MEASURED_BORDER,
    /// the conformal border (Boundary First Flattening's border with boundary scale factors
    /// 0; see `Conformal_border_parameterizer_3`), from one more back-substitution of the
    /// interior Laplacian; no center, no distances: one factorization in all.
    CONFORMAL_BORDER,
    /// CGAL's circle with arc-length angles (`Circular_border_arc_length_parameterizer_3`);
    /// one factorization in all.
    CIRCULAR_BORDER,
    /// the best border of the family (the circle, the measured border, the conformal border
    /// and their blends toward a convex border) by the angle distortion of the discrete
    /// conformal map it gives; see `set_border_choice()`.
    AUTOMATIC_BORDER
  };

  /// The members of the border family; each is a path of borders from the member
  /// (blend 0) to a convex border (blend 1).
  enum Border_family
  {
    /// the circle with arc-length angles (CGAL's circular border); its blend is 1
    CIRCLE,
    /// the `BorderDistance` policy's measured border, blended toward the circle in polar
    /// coordinates (angle and normalized radius)
    MEASURED,
    /// the conformal border, blended toward the circle's turning angles (edge lengths kept)
    CONFORMAL
  };

  /// A candidate layout tried by the call.
  struct Border_candidate
  {
    /// which member of the family
    Border_family family;
    /// the blend toward the member's convex border (0: the member itself; 1 for the circle)
    double blend;
    /// whether the interior is the mean value coordinates map (a repair) rather than the
    /// discrete conformal map
    bool mean_value_interior;
    /// whether the layout is one-to-one
    bool valid;
    /// its angle distortion (`+infinity` when not valid)
    double objective;
  };

  /// What the last call did and how long each stage took (wall-clock seconds).
  struct Report
  {
    /// status of the last call
    Error_code status = ERROR_WRONG_PARAMETER;
    ///@{
    /// number of vertices and faces of the parameterized component
    std::size_t vertices = 0, faces = 0;
    ///@}
    /// the border choice of the call
    Border_choice border_choice = MEASURED_BORDER;
    /// input checks and indexing of the component
    double preparation_seconds = 0.;
    /// step 1 (measured border): factorizing L_II and locating the center (the border
    /// distance policy's `prepare()` step runs meanwhile in a second thread)
    double center_seconds = 0.;
    /// step 2 (measured border): distances from the center to the border (including any
    /// wait for `prepare()`)
    double distance_seconds = 0.;
    /// step 3 (measured border): polar border map
    double border_map_seconds = 0.;
    /// the conformal border's turning angles (factorizing L_II if not done yet, one
    /// back-substitution)
    double conformal_border_seconds = 0.;
    /// the interior solves, validity checks and angle distortions of the candidates before
    /// any repair (for `AUTOMATIC_BORDER`, the whole search)
    double interior_seconds = 0.;
    /// writing the UVs into the property maps
    double output_seconds = 0.;
    /// the whole call
    double total_seconds = 0.;
    /// factorizations and back-substitutions of the call, with their times
    typename Patch::Statistics statistics;
    /// whether a layout of the chosen border (or, for `AUTOMATIC_BORDER`, of a member or a
    /// blend with the discrete conformal interior) was one-to-one before any repair
    bool valid_before_repair = true;
    /// faces flipped by the chosen border's layout before repair (for `AUTOMATIC_BORDER`: the
    /// fewest over the members' own borders)
    std::size_t flipped_faces_before_repair = 0;
    /// whether the result was repaired
    bool repaired = false;
    /// the member of the result
    Border_family kept_border = MEASURED;
    /// the blend of the result toward its member's convex border (0: the member itself)
    double blend = 0.;
    /// whether the interior of the result is the mean value coordinates map (rather than
    /// the discrete conformal map)
    bool mean_value_interior = false;
    /// layouts tried by the repair
    int repair_candidates = 0;
    /// time of the repair
    double repair_seconds = 0.;
    /// every layout tried, in the order tried (the repair's included)
    std::vector<Border_candidate> border_candidates;
    /// the index of the kept layout in `border_candidates` (-1 after a failure)
    int chosen_candidate = -1;
  };

  /// creates a parameterizer with the given policies.
  explicit Measured_conformal_parameterizer_3(Center_locator center_locator = Center_locator(),
                                              Border_distance border_distance = Border_distance())
    : m_border(center_locator, border_distance),
      m_report(std::make_shared<Report>())
  { }

  /// computes the parameterization of the connected component bounded by the border loop of
  /// `bhd`, writes the UV of every vertex of that component into `uvmap` and marks it in
  /// `vpmap`. Nothing is written on failure.
  ///
  /// \tparam VertexUVmap a model of `ReadWritePropertyMap` with `vertex_descriptor` as key
  ///         and a 2D point type constructible from two `double` as value.
  /// \tparam VertexIndexMap a model of `ReadablePropertyMap` (unused: the component is
  ///         indexed by the patch).
  /// \tparam VertexParameterizedMap a model of `ReadWritePropertyMap` with
  ///         `vertex_descriptor` as key and `bool` as value.
  /// \return `OK`, or the first failure (see `Measured_border_parameterizer_3::parameterize()`),
  ///         or `ERROR_CANNOT_SOLVE_LINEAR_SYSTEM`, or `ERROR_NO_1_TO_1_MAPPING`.
  template <class VertexUVmap, class VertexIndexMap, class VertexParameterizedMap>
  Error_code parameterize(const Triangle_mesh& mesh,
                          halfedge_descriptor bhd,
                          VertexUVmap uvmap,
                          VertexIndexMap /* vimap */,
                          VertexParameterizedMap vpmap)
  {
    Stopwatch clock;
    Report report;
    report.border_choice = m_border_choice;
    Patch patch;
    Error_code status = patch.build_disk(mesh, bhd, get(vertex_point, mesh));
    patch.set_parallel(internal::Is_parallel<ConcurrencyTag_>::value);
    report.preparation_seconds = clock.lap();
    if(status == OK)
    {
      report.vertices = patch.number_of_real_vertices();
      report.faces = patch.number_of_real_faces();
      internal::Border_family<Patch> family(patch);
      status = build_family(patch, family, report, clock);
      if(status == OK)
      {
        internal::Border_evaluator<Patch> evaluator(patch, family);
        status = choose(patch, family, evaluator, report, clock);
        if(status == OK)
          write_uv(patch, evaluator.best_solution(), uvmap, vpmap);
        report.output_seconds = clock.lap();
      }
    }
    report.status = status;
    report.statistics = patch.statistics();
    report.total_seconds = clock.total();
    *m_report = report;
    return status;
  }

  /// chooses the border (default: `MEASURED_BORDER`, the paper's method).
  ///
  /// `CONFORMAL_BORDER` and `CIRCULAR_BORDER` need no center and no distances: the interior
  /// Laplacian \f$ L_{II} \f$ is the only matrix factorized.
  ///
  /// With `AUTOMATIC_BORDER` the call evaluates a family of borders on the one
  /// factorization of \f$ L_{II} \f$, each for two back-substitutions, a validity check and
  /// one evaluation of the angle distortion, and keeps the valid layout of lowest angle
  /// distortion. The search, deterministic:
  /// 1. the circle and the conformal border (at its smallest simple blend toward the circle:
  ///    0 unless the conformal polygon self-intersects), in one batch;
  /// 2. only when the conformal layout is not one-to-one: the measured member (the policies'
  ///    center and distances; the spring Laplacian of the Poisson distance map is factorized
  ///    only when the `BorderDistance` policy asks for it). On the 23 real disks of the
  ///    benchmark (`benchmark/README.md`) the measured member never had less angle distortion
  ///    than a valid conformal layout, and building it costs a center search and a distance
  ///    map;
  /// 3. for each member whose own layout is not one-to-one but whose angle distortion (of the
  ///    invalid layout) is lower than the best valid one so far, the smallest valid blend
  ///    toward its convex border, by five bisection steps (all such members in one batch per
  ///    step); along a member the distortion grows as the border moves toward the convex one,
  ///    so the smallest valid blend is the member's best;
  /// 4. when no layout is valid, the repair (`Repair`).
  ///
  /// The circle is convex and the conformal border at blend 1 is convex, so the search always
  /// has a simple, convex end point. `last_report().border_candidates` lists every layout
  /// tried.
  void set_border_choice(Border_choice choice) { m_border_choice = choice; }
  /// see `set_border_choice()`.
  Border_choice border_choice() const { return m_border_choice; }

  /// chooses what to do when the result is not one-to-one (default: `BLEND_TOWARD_CIRCLE`).
  void set_repair(Repair repair) { m_repair = repair; }
  /// see `set_repair()`.
  Repair repair() const { return m_repair; }

  /// the record of the last call.
  const Report& last_report() const { return *m_report; }
  /// the border step of the measured border, with the record of its last call (center,
  /// border vertices, distances). Not run by `CONFORMAL_BORDER` and `CIRCULAR_BORDER`.
  const Border_parameterizer& border_parameterizer() const { return m_border; }
  /// the center vertex of the last call (`null_vertex()` after a failure, or when the border
  /// choice needs no center).
  vertex_descriptor center() const { return m_border.center(); }

private:
  typedef internal::Border_member Member;

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

  // The members the border choice needs before any layout is evaluated: the measured member
  // for MEASURED_BORDER, the conformal one for CONFORMAL_BORDER and AUTOMATIC_BORDER (which
  // builds its measured member later, only if needed). For AUTOMATIC_BORDER a member that
  // cannot be built (a distance policy that does not reach the border, say) is left out.
  Error_code build_family(Patch& patch, internal::Border_family<Patch>& family, Report& report, Stopwatch& clock)
  {
    m_border.clear_record();
    if(m_border_choice == MEASURED_BORDER)
      return build_measured(patch, family, report, clock);
    if(m_border_choice == CONFORMAL_BORDER || m_border_choice == AUTOMATIC_BORDER)
    {
      const Error_code status = family.add_conformal(patch);
      report.conformal_border_seconds = clock.lap();
      if(status != OK && (m_border_choice == CONFORMAL_BORDER || status == ERROR_CANNOT_SOLVE_LINEAR_SYSTEM))
        return status;
    }
    return OK;
  }

  // The measured member: center, distances, polar map (steps 1-3 of the paper).
  Error_code build_measured(Patch& patch, internal::Border_family<Patch>& family, Report& report, Stopwatch& clock)
  {
    std::vector<Eigen::Vector2d> border_uv;
    const Error_code status = m_border.parameterize_border(patch, border_uv, true);
    const typename Border_parameterizer::Record& r = m_border.last_record();
    report.center_seconds = r.center_seconds;
    report.distance_seconds = r.distance_seconds;
    report.border_map_seconds = r.border_map_seconds;
    clock.lap();
    if(status == OK)
      family.add_measured(r.border_angles, r.border_distances);
    return status;
  }

  // Evaluates the border choice's candidates, then repairs if needed; the evaluator keeps the
  // result. Fills the report's border fields.
  Error_code choose(Patch& patch, internal::Border_family<Patch>& family, internal::Border_evaluator<Patch>& evaluator,
                    Report& report, Stopwatch& clock)
  {
    std::vector<Member> members;  // the members that can be repaired, best first
    Error_code status = OK;
    if(m_border_choice == AUTOMATIC_BORDER)
      status = search_automatic(patch, family, evaluator, report, clock, members);
    else
    {
      const Member member = (m_border_choice == MEASURED_BORDER) ? internal::MEASURED_MEMBER
                          : (m_border_choice == CONFORMAL_BORDER) ? internal::CONFORMAL_MEMBER
                                                                  : internal::CIRCLE_MEMBER;
      const internal::Border_trial trial = evaluator.evaluate({{member, family.own_blend(member)}}, false).front();
      report.valid_before_repair = trial.valid;
      report.flipped_faces_before_repair = trial.flipped_faces;
      members.push_back(member);
    }
    if(status != OK)
      return status;
    report.interior_seconds += clock.lap();
    const std::size_t tried = evaluator.trials().size();
    if(evaluator.best() < 0 && m_repair == BLEND_TOWARD_CIRCLE)
      repair(evaluator, members, m_border_choice != AUTOMATIC_BORDER);
    report.repair_seconds = clock.lap();
    report.repair_candidates = static_cast<int>(evaluator.trials().size() - tried);
    for(const internal::Border_trial& t : evaluator.trials())
      report.border_candidates.push_back(
        Border_candidate{static_cast<Border_family>(t.member), t.blend, t.mean_value, t.valid, t.objective});
    report.chosen_candidate = evaluator.best();
    if(evaluator.best() < 0)
      return ERROR_NO_1_TO_1_MAPPING;
    const Border_candidate& kept = report.border_candidates[static_cast<std::size_t>(evaluator.best())];
    report.kept_border = kept.family;
    report.blend = kept.blend;
    report.mean_value_interior = kept.mean_value_interior;
    report.repaired = kept.mean_value_interior ||
                      (m_border_choice != AUTOMATIC_BORDER &&
                       kept.blend > family.own_blend(static_cast<Member>(kept.family)));
    return OK;
  }

  // Steps 1 and 2 of AUTOMATIC_BORDER (see set_border_choice()). `members`: the members in
  // the order of their own layouts' angle distortion, for the repair.
  Error_code search_automatic(Patch& patch, internal::Border_family<Patch>& family,
                              internal::Border_evaluator<Patch>& evaluator, Report& report, Stopwatch& clock,
                              std::vector<Member>& members)
  {
    std::vector<typename internal::Border_evaluator<Patch>::Request> batch(1, {internal::CIRCLE_MEMBER, 1.});
    if(family.has(internal::CONFORMAL_MEMBER))
      batch.emplace_back(internal::CONFORMAL_MEMBER, family.own_blend(internal::CONFORMAL_MEMBER));
    std::vector<internal::Border_trial> own = evaluator.evaluate(batch, false);
    if(!own.back().valid)  // no valid conformal layout: the measured member too
    {
      report.interior_seconds += clock.lap();
      const Error_code status = build_measured(patch, family, report, clock);
      if(status == ERROR_CANNOT_SOLVE_LINEAR_SYSTEM)
        return status;
      if(status == OK)
        own.push_back(evaluator.evaluate({{internal::MEASURED_MEMBER, 0.}}, false).front());
    }
    bool first = true;
    for(const internal::Border_trial& t : own)
      if(std::isfinite(t.estimate))
      {
        report.flipped_faces_before_repair =
          first ? t.flipped_faces : (std::min)(report.flipped_faces_before_repair, t.flipped_faces);
        first = false;
      }
    std::vector<Member> search;
    for(const internal::Border_trial& t : own)
      if(!t.valid && t.member != internal::CIRCLE_MEMBER && t.estimate < evaluator.best_objective())
        search.push_back(t.member);
    if(!search.empty())
      internal::search_smallest_valid_blend(evaluator, search, false);
    report.valid_before_repair = evaluator.best() >= 0;
    std::stable_sort(own.begin(), own.end(), [](const internal::Border_trial& a, const internal::Border_trial& b) {
      return a.estimate < b.estimate;
    });
    for(const internal::Border_trial& t : own)
      members.push_back(t.member);
    return OK;
  }

  // BLEND_TOWARD_CIRCLE: along each member, the smallest valid blend with the discrete
  // conformal interior (unless the automatic search did it), then with the mean value
  // interior; the evaluator keeps the best.
  static void repair(internal::Border_evaluator<Patch>& evaluator, const std::vector<Member>& members,
                     bool conformal_search)
  {
    std::vector<Member> blendable;
    for(Member m : members)
      if(m != internal::CIRCLE_MEMBER)
        blendable.push_back(m);
    if(conformal_search && !blendable.empty())
      internal::search_smallest_valid_blend(evaluator, blendable, false);
    std::vector<typename internal::Border_evaluator<Patch>::Request> batch;
    for(Member m : members)
      batch.emplace_back(m, evaluator.family().own_blend(m));
    const std::vector<internal::Border_trial> own = evaluator.evaluate(batch, true);
    std::vector<Member> search;
    for(const internal::Border_trial& t : own)
      if(!t.valid && t.member != internal::CIRCLE_MEMBER)
        search.push_back(t.member);
    if(!search.empty())
      internal::search_smallest_valid_blend(evaluator, search, true);
  }

  template <class VertexUVmap, class VertexParameterizedMap>
  static void write_uv(const Patch& patch, const internal::Border_solution& s, VertexUVmap uvmap,
                       VertexParameterizedMap vpmap)
  {
    typedef typename boost::property_traits<VertexUVmap>::value_type Point_2;
    const std::vector<int>& border = patch.border();
    for(std::size_t k = 0; k < border.size(); ++k)
    {
      const vertex_descriptor vd = patch.vertex(static_cast<std::size_t>(border[k]));
      put(uvmap, vd, Point_2(s.border_uv[k].x(), s.border_uv[k].y()));
      put(vpmap, vd, true);
    }
    const std::vector<int>& interior = patch.interior_vertices();
    for(std::size_t r = 0; r < interior.size(); ++r)
    {
      if(patch.is_virtual(static_cast<std::size_t>(interior[r])))
        continue;  // the filling of a hole
      const vertex_descriptor vd = patch.vertex(static_cast<std::size_t>(interior[r]));
      put(uvmap, vd, Point_2(s.u[r], s.v[r]));
      put(vpmap, vd, true);
    }
  }

  Border_parameterizer m_border;
  std::shared_ptr<Report> m_report;
  Repair m_repair = BLEND_TOWARD_CIRCLE;
  Border_choice m_border_choice = MEASURED_BORDER;
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
/// `ERROR_INVALID_BORDER_HALFEDGE`, not an assertion).
template <class TriangleMesh, class CenterLocator, class BorderDistance, class SolverTraits, class ConcurrencyTag,
          class HalfedgeDescriptor, class VertexUVmap>
Error_code parameterize(TriangleMesh& mesh,
                        Measured_conformal_parameterizer_3<TriangleMesh, CenterLocator, BorderDistance,
                                                           SolverTraits, ConcurrencyTag> parameterizer,
                        HalfedgeDescriptor bhd,
                        VertexUVmap uvmap)
{
  return parameterizer.parameterize(mesh, bhd, uvmap, get(CGAL::dynamic_vertex_property_t<int>(), mesh),
                                    get(CGAL::dynamic_vertex_property_t<bool>(), mesh));
}

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_MEASURED_CONFORMAL_PARAMETERIZER_3_H
