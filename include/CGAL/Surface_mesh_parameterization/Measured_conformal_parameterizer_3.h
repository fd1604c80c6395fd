// Copyright (c) 2026 The measured boundary parameterization authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// This file is part of the measured boundary parameterization package for CGAL.

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_MEASURED_CONFORMAL_PARAMETERIZER_3_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_MEASURED_CONFORMAL_PARAMETERIZER_3_H

/// \file Measured_conformal_parameterizer_3.h

#include <CGAL/Surface_mesh_parameterization/Measured_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_patch_3.h>
#include <CGAL/Surface_mesh_parameterization/Poisson_border_distance.h>
#include <CGAL/Surface_mesh_parameterization/Poisson_center_locator.h>
#include <CGAL/Surface_mesh_parameterization/internal/border_search.h>
#include <CGAL/Surface_mesh_parameterization/internal/fast_marching_solver.h>
#include <CGAL/Surface_mesh_parameterization/internal/polar_map.h>
#include <CGAL/Surface_mesh_parameterization/internal/repair.h>

#include <CGAL/boost/graph/properties.h>
#include <CGAL/Default.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <Eigen/Core>

#include <chrono>
#include <cmath>
#include <cstddef>
#include <future>
#include <limits>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

template <class TriangleMesh, class Method> class Geodesic_border_distance;

namespace internal {

// Whether a border distance policy is fast marching geodesics (then the automatic border's
// second member is the Poisson distance map instead).
template <class Policy>
struct Is_fast_marching_border : std::false_type {};

template <class TriangleMesh>
struct Is_fast_marching_border<Geodesic_border_distance<TriangleMesh, Fast_marching_geodesics> >
  : std::true_type {};

// A policy that chooses its distances at run time says so with an optional member
// `bool measures_fast_marching_geodesics() const`.
template <class Policy, class = void>
struct Has_fast_marching_query : std::false_type {};

template <class Policy>
struct Has_fast_marching_query<
  Policy, std::void_t<decltype(static_cast<bool>(std::declval<const Policy&>().measures_fast_marching_geodesics()))> >
  : std::true_type {};

template <class Policy>
bool measures_fast_marching_geodesics(const Policy& policy)
{
  if constexpr(Has_fast_marching_query<Policy>::value)
    return static_cast<bool>(policy.measures_fast_marching_geodesics());
  else
    return Is_fast_marching_border<Policy>::value;
}

} // namespace internal

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
template <class TriangleMesh_,
          class CenterLocator_ = Poisson_center_locator<TriangleMesh_>,
          class BorderDistance_ = Poisson_border_distance<TriangleMesh_>,
          class SolverTraits_ = Default>
class Measured_conformal_parameterizer_3
{
public:
  /// Triangle mesh type
  typedef TriangleMesh_                                                         Triangle_mesh;
  /// Triangle mesh type (CGAL's name in its parameterizers)
  typedef TriangleMesh_                                                         TriangleMesh;
  /// The border step, which also holds the policies.
  typedef Measured_border_parameterizer_3<TriangleMesh_, CenterLocator_,
                                          BorderDistance_, SolverTraits_>       Border_parameterizer;
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

  /// What to do when the measured parameterization is not one-to-one.
  enum Repair
  {
    /// fail with `ERROR_NO_1_TO_1_MAPPING` (nothing is written)
    NO_REPAIR,
    /// blend the border radii toward a circle, \f$ r_k(t) = (1-t) r_k + t \bar r \f$ (polar
    /// angles kept), as little as needed. Two interiors are tried: the discrete conformal
    /// map (each blend costs two back-substitutions with the same factorization) and the
    /// mean value coordinates map (positive weights; one sparse LU factorization, then two
    /// back-substitutions per blend). For each, the smallest valid \f$ t \f$ is searched
    /// among 0 (mean value only), 1/4, 1/2, 3/4, 1 and refined by three bisection steps;
    /// the valid candidate of lower angle distortion is kept. At \f$ t = 1 \f$ the border is
    /// convex, so the mean value map is valid (Floater's theorem): the repair always
    /// succeeds, up to rounding. The default.
    BLEND_TOWARD_CIRCLE
  };

  /// Which border the call lays out.
  enum Border_choice
  {
    /// the border of the `BorderDistance` policy (the paper's method). The default.
    MEASURED_BORDER,
    /// the best border of a family, by the paper's angle distortion (METHOD.md section 5) of
    /// the discrete conformal map it gives; see `set_border_choice()`.
    AUTOMATIC_BORDER
  };

  /// The members of the border family of `AUTOMATIC_BORDER`.
  enum Border_family
  {
    /// the circle with arc-length angles (CGAL's circular border)
    CIRCLE,
    /// the `BorderDistance` policy's measured border, blended toward the circle
    POLICY_BORDER,
    /// the other measured border (fast marching geodesic distances, or the Poisson distance
    /// map when the policy is fast marching), blended toward the circle
    SECOND_BORDER
  };

  /// A border tried by `AUTOMATIC_BORDER`.
  struct Border_candidate
  {
    /// which member of the family
    Border_family family;
    /// the blend toward the circle (1 for the circle)
    double blend;
    /// whether the discrete conformal map of this border is one-to-one
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
    /// input checks and indexing of the component
    double preparation_seconds = 0.;
    /// step 1: factorizing L_II and locating the center (the border distance policy's
    /// `prepare()` step runs meanwhile in a second thread)
    double center_seconds = 0.;
    /// step 2: distances from the center to the border (including any wait for `prepare()`)
    double distance_seconds = 0.;
    /// step 3: polar border map
    double border_map_seconds = 0.;
    /// step 4: the two interior back-substitutions
    double interior_seconds = 0.;
    /// writing the UVs into the property maps
    double output_seconds = 0.;
    /// the whole call
    double total_seconds = 0.;
    /// factorizations and back-substitutions of the call, with their times
    typename Patch::Statistics statistics;
    /// whether the measured parameterization was one-to-one before any repair
    bool valid_before_repair = true;
    /// faces flipped by the measured border, before repair
    std::size_t flipped_faces_before_repair = 0;
    /// whether the result was repaired
    bool repaired = false;
    /// the blend toward the circle of the result (0: the measured border)
    double blend = 0.;
    /// whether the interior of the result is the mean value coordinates map (rather than
    /// the discrete conformal map)
    bool mean_value_interior = false;
    /// borders tried by the repair
    int repair_candidates = 0;
    /// time of the repair (validity check included)
    double repair_seconds = 0.;
    /// `AUTOMATIC_BORDER`: every border tried, in the order tried
    std::vector<Border_candidate> border_candidates;
    /// `AUTOMATIC_BORDER`: the index of the kept border in `border_candidates` (-1 when none
    /// was valid and the measured border was repaired instead)
    int chosen_candidate = -1;
    /// `AUTOMATIC_BORDER`: whether the second measured border is the Poisson distance map
    /// (rather than fast marching geodesics)
    bool second_border_is_poisson = false;
    /// `AUTOMATIC_BORDER`: time of the search (the second border's distances included)
    double search_seconds = 0.;
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
  ///         or `ERROR_CANNOT_SOLVE_LINEAR_SYSTEM`.
  template <class VertexUVmap, class VertexIndexMap, class VertexParameterizedMap>
  Error_code parameterize(const Triangle_mesh& mesh,
                          halfedge_descriptor bhd,
                          VertexUVmap uvmap,
                          VertexIndexMap /* vimap */,
                          VertexParameterizedMap vpmap)
  {
    typedef std::chrono::steady_clock Clock;
    auto seconds = [](Clock::time_point a, Clock::time_point b) {
      return std::chrono::duration<double>(b - a).count();
    };
    Report report;
    const Clock::time_point start = Clock::now();

    Patch patch;
    Error_code status = patch.build_disk(mesh, bhd, get(vertex_point, mesh));
    Clock::time_point t = Clock::now();
    report.preparation_seconds = seconds(start, t);

    std::vector<Eigen::Vector2d> border_uv;
    if(status == OK)
    {
      report.vertices = patch.number_of_real_vertices();
      report.faces = patch.number_of_real_faces();
      status = m_border.parameterize_border(patch, border_uv, true);
      const typename Border_parameterizer::Record& r = m_border.last_record();
      report.center_seconds = r.center_seconds;
      report.distance_seconds = r.distance_seconds;
      report.border_map_seconds = r.border_map_seconds;
      t = Clock::now();
    }

    std::vector<double> u, v;
    bool chosen = false;
    if(status == OK && m_border_choice == AUTOMATIC_BORDER)
    {
      status = choose_border(patch, border_uv, u, v, report);
      chosen = (status == OK);
      if(status == ERROR_NO_1_TO_1_MAPPING)  // no valid member: the measured border, repaired
        status = OK;
      const Clock::time_point t2 = Clock::now();
      report.search_seconds = seconds(t, t2);
      t = t2;
    }

    if(status == OK && !chosen)
    {
      status = solve_interior(patch, border_uv, u, v);
      const Clock::time_point t2 = Clock::now();
      report.interior_seconds = seconds(t, t2);
      t = t2;
    }

    if(status == OK && !chosen)
    {
      std::vector<Eigen::Vector2d> uv;
      internal::assemble_uv(patch, border_uv, u, v, uv);
      report.flipped_faces_before_repair = internal::count_flips(patch, uv);
      report.valid_before_repair = report.flipped_faces_before_repair == 0 &&
                                   internal::border_curves_are_valid(patch, uv);
      if(!report.valid_before_repair)
        status = (m_repair == NO_REPAIR) ? ERROR_NO_1_TO_1_MAPPING
                                         : blend_toward_circle(patch, border_uv, u, v, report);
      const Clock::time_point t2 = Clock::now();
      report.repair_seconds = seconds(t, t2);
      t = t2;
    }

    if(status == OK)
    {
      typedef typename boost::property_traits<VertexUVmap>::value_type Point_2;
      const std::vector<int>& border = patch.border();
      for(std::size_t k = 0; k < border.size(); ++k)
      {
        const vertex_descriptor vd = patch.vertex(static_cast<std::size_t>(border[k]));
        put(uvmap, vd, Point_2(border_uv[k].x(), border_uv[k].y()));
        put(vpmap, vd, true);
      }
      const std::vector<int>& interior = patch.interior_vertices();
      for(std::size_t r = 0; r < interior.size(); ++r)
      {
        if(patch.is_virtual(static_cast<std::size_t>(interior[r])))
          continue;  // the filling of a hole
        const vertex_descriptor vd = patch.vertex(static_cast<std::size_t>(interior[r]));
        put(uvmap, vd, Point_2(u[r], v[r]));
        put(vpmap, vd, true);
      }
      report.output_seconds = seconds(t, Clock::now());
    }

    report.status = status;
    report.statistics = patch.statistics();
    report.total_seconds = seconds(start, Clock::now());
    *m_report = report;
    return status;
  }

  /// chooses the border (default: `MEASURED_BORDER`). With `AUTOMATIC_BORDER` the call tries
  /// a family of borders on the one factorization of the interior Laplacian, each for two
  /// back-substitutions and one evaluation of the angle distortion, and keeps the valid one of
  /// lowest angle distortion. The family: the circle (arc-length angles); the policy's
  /// measured border and a second measured border (fast marching geodesic distances from the
  /// center, or the Poisson distance map when the policy uses fast marching: a policy that
  /// chooses its distances at run time tells with an optional member
  /// `bool measures_fast_marching_geodesics() const`); and their
  /// blends toward the circle in polar coordinates, angle and radius each
  /// \f$ (1 - t) \cdot \mathrm{measured} + t \cdot \mathrm{circle} \f$ after normalizing the
  /// mean radius. The search: \f$ t = 0, 1/2, 1 \f$ (the circle once) for both measured
  /// borders, then, for each, a golden-section search in the half interval around its best
  /// grid point: two points and two steps, four borders (when both points of a step fold,
  /// the step moves toward the circle, which is valid). 13 borders at most, evaluated in
  /// batches of multi-column back-substitutions. The circle and both pure measured borders are members, so the result is never
  /// worse than any of them by that measure. `last_report().border_candidates` lists every
  /// border tried. If no member is valid the measured border is repaired (`Repair`).
  void set_border_choice(Border_choice choice) { m_border_choice = choice; }
  /// see `set_border_choice()`.
  Border_choice border_choice() const { return m_border_choice; }

  /// chooses what to do when the result is not one-to-one (default: `BLEND_TOWARD_CIRCLE`).
  void set_repair(Repair repair) { m_repair = repair; }
  /// see `set_repair()`.
  Repair repair() const { return m_repair; }

  /// whether center-independent work runs in a second thread while the center is located
  /// (default: `true`; see `Measured_border_parameterizer_3::use_concurrency()`). Results do
  /// not depend on it.
  void use_concurrency(bool on) { m_border.use_concurrency(on); }

  /// the record of the last call.
  const Report& last_report() const { return *m_report; }
  /// the border step, with the record of its last call (center, border vertices, distances).
  const Border_parameterizer& border_parameterizer() const { return m_border; }
  /// the center vertex of the last call (`null_vertex()` after a failure).
  vertex_descriptor center() const { return m_border.center(); }

private:
  // Step 4: L_II u_I = -L_IB u_B and the same for v, with the patch's factorization (one
  // pass over it for both).
  static Error_code solve_interior(Patch& patch, const std::vector<Eigen::Vector2d>& border_uv,
                                   std::vector<double>& u, std::vector<double>& v)
  {
    Eigen::MatrixXd values(static_cast<Eigen::Index>(border_uv.size()), 2), rhs, x;
    for(std::size_t k = 0; k < border_uv.size(); ++k)
      values.row(static_cast<Eigen::Index>(k)) = border_uv[k].transpose();
    patch.interior_rhs_from_border(values, rhs);
    const Error_code status = patch.solve_interior(rhs, x);
    if(status != OK)
      return status;
    u.assign(x.col(0).data(), x.col(0).data() + x.rows());
    v.assign(x.col(1).data(), x.col(1).data() + x.rows());
    return OK;
  }

  // The repair of BLEND_TOWARD_CIRCLE: replaces border_uv, u, v by the kept candidate, or
  // returns ERROR_NO_1_TO_1_MAPPING.
  Error_code blend_toward_circle(Patch& patch, std::vector<Eigen::Vector2d>& border_uv,
                                 std::vector<double>& u, std::vector<double>& v, Report& report) const
  {
    const typename Border_parameterizer::Record& record = m_border.last_record();
    const int center = patch.index(record.center);
    if(center < 0)
      return ERROR_NO_1_TO_1_MAPPING;
    internal::Mean_value_interior mvc;

    struct Candidate
    {
      std::vector<Eigen::Vector2d> border_uv, uv;
      std::vector<double> u, v;
      double blend = -1.;
    };
    // the map for blend t; true when it is one-to-one
    auto evaluate = [&](double t, bool mean_value, Candidate& c) -> bool {
      ++report.repair_candidates;
      internal::Polar_border polar;
      if(internal::polar_border_map(patch, static_cast<std::size_t>(center),
                                    internal::blend_radii(record.border_distances, t), polar) != OK)
        return false;
      c.border_uv = polar.uv;
      const Error_code status = mean_value ? mvc.solve(patch, c.border_uv, c.u, c.v)
                                           : solve_interior(patch, c.border_uv, c.u, c.v);
      if(status != OK)
        return false;
      internal::assemble_uv(patch, c.border_uv, c.u, c.v, c.uv);
      c.blend = t;
      return internal::is_one_to_one(patch, c.uv);
    };
    // the valid candidate of smallest blend, if any
    auto search = [&](bool mean_value, Candidate& best) -> bool {
      double invalid = mean_value ? -1. : 0., valid = -1.;  // DCP at t = 0: the measured result
      Candidate c;
      for(double t : {0., 0.25, 0.5, 0.75, 1.})
      {
        if(t <= invalid)
          continue;
        if(evaluate(t, mean_value, c))
        {
          valid = t;
          best = c;
          break;
        }
        invalid = t;
      }
      if(valid < 0.)
        return false;
      for(int step = 0; step < 3 && invalid >= 0.; ++step)
      {
        const double mid = 0.5 * (invalid + valid);
        if(evaluate(mid, mean_value, c))
        {
          valid = mid;
          best = c;
        }
        else
          invalid = mid;
      }
      return true;
    };

    Candidate conformal, mean_value;
    const bool conformal_ok = search(false, conformal);
    const bool mean_value_ok = (mvc.factor(patch) == OK) && search(true, mean_value);
    if(!conformal_ok && !mean_value_ok)
      return ERROR_NO_1_TO_1_MAPPING;
    const internal::Angle_distortion_objective angle_distortion(patch);
    const bool use_mean_value =
      mean_value_ok && (!conformal_ok || angle_distortion(mean_value.uv) < angle_distortion(conformal.uv));
    const Candidate& kept = use_mean_value ? mean_value : conformal;
    border_uv = kept.border_uv;
    u = kept.u;
    v = kept.v;
    report.repaired = true;
    report.blend = kept.blend;
    report.mean_value_interior = use_mean_value;
    return OK;
  }

  // AUTOMATIC_BORDER: the valid member of lowest angle distortion, or ERROR_NO_1_TO_1_MAPPING.
  Error_code choose_border(Patch& patch, std::vector<Eigen::Vector2d>& border_uv,
                           std::vector<double>& u, std::vector<double>& v, Report& report) const
  {
    const typename Border_parameterizer::Record& record = m_border.last_record();
    const int center = patch.index(record.center);
    if(center < 0)
      return ERROR_WRONG_PARAMETER;

    // the second measured border's radii, computed in a second thread while the first
    // borders are evaluated (they do not need it)
    std::vector<double> second(patch.border().size());
    report.second_border_is_poisson = internal::measures_fast_marching_geodesics(m_border.border_distance());
    auto second_radii = [&patch, &second, center, poisson = report.second_border_is_poisson]() {
      std::vector<double> values;
      const Error_code status =
        poisson ? patch.solve_spring_poisson(static_cast<std::size_t>(center), 1., values)
                : internal::geodesic_distances<Fast_marching_geodesics>(patch, std::vector<int>(1, center), values);
      if(status == OK)
        for(std::size_t k = 0; k < second.size(); ++k)
          second[k] = values[static_cast<std::size_t>(patch.border()[k])];
      return status;
    };
    std::future<Error_code> second_ready = std::async(m_border.uses_concurrency() ? std::launch::async
                                                                                   : std::launch::deferred,
                                                      second_radii);

    const std::vector<double> circle = internal::arc_length_angles(patch);
    const internal::Angle_distortion_objective angle_distortion(patch);
    const std::vector<double>* radii[3] = {nullptr, &record.border_distances, &second};

    struct Solution
    {
      std::vector<Eigen::Vector2d> border_uv;
      std::vector<double> u, v;
    };
    Solution best;
    double best_objective = std::numeric_limits<double>::infinity();

    // evaluates a batch of borders with one multi-column solve; returns their objectives
    auto evaluate = [&](const std::vector<std::pair<Border_family, double> >& batch) {
      // validity and angle distortion of each candidate; two threads share the candidates
      struct Evaluation
      {
        Solution solution;
        bool valid = false;
        double objective = std::numeric_limits<double>::infinity();
      };
      std::vector<internal::Polar_border> borders(batch.size());
      std::vector<bool> placed(batch.size(), false);
      const Eigen::Index m = static_cast<Eigen::Index>(patch.border().size());
      Eigen::MatrixXd values(m, 2 * static_cast<Eigen::Index>(batch.size()));
      values.setZero();
      for(std::size_t i = 0; i < batch.size(); ++i)
      {
        const Border_family family = batch[i].first;
        const double t = (family == CIRCLE) ? 1. : batch[i].second;
        const std::vector<double>& r = (family == CIRCLE) ? record.border_distances : *radii[family];
        placed[i] = internal::blended_border(record.border_angles, r, circle, t, borders[i]) == OK;
        if(placed[i])
          for(Eigen::Index k = 0; k < m; ++k)
          {
            values(k, 2 * static_cast<Eigen::Index>(i)) = borders[i].uv[static_cast<std::size_t>(k)].x();
            values(k, 2 * static_cast<Eigen::Index>(i) + 1) = borders[i].uv[static_cast<std::size_t>(k)].y();
          }
      }
      Eigen::MatrixXd rhs, x;
      patch.interior_rhs_from_border(values, rhs);
      const bool solved = patch.solve_interior(rhs, x) == OK;
      std::vector<Evaluation> evaluations(batch.size());
      auto evaluate_range = [&](std::size_t first, std::size_t last) {
        for(std::size_t i = first; i < last; ++i)
        {
          if(!solved || !placed[i])
            continue;
          Evaluation& e = evaluations[i];
          e.solution.border_uv = borders[i].uv;
          const Eigen::Index column = 2 * static_cast<Eigen::Index>(i);
          e.solution.u.assign(x.col(column).data(), x.col(column).data() + x.rows());
          e.solution.v.assign(x.col(column + 1).data(), x.col(column + 1).data() + x.rows());
          std::vector<Eigen::Vector2d> uv;
          internal::assemble_uv(patch, e.solution.border_uv, e.solution.u, e.solution.v, uv);
          e.valid = internal::is_one_to_one(patch, uv);
          if(e.valid)
            e.objective = angle_distortion(uv);
        }
      };
      const std::size_t half = (batch.size() + 1) / 2;
      {
        std::future<void> other;
        if(m_border.uses_concurrency() && batch.size() > 1)
          other = std::async(std::launch::async, evaluate_range, half, batch.size());
        evaluate_range(0, other.valid() ? half : batch.size());
        if(other.valid())
          other.get();
      }
      std::vector<double> objectives(batch.size());
      for(std::size_t i = 0; i < batch.size(); ++i)
      {
        Evaluation& e = evaluations[i];
        report.border_candidates.push_back(
          Border_candidate{batch[i].first, (batch[i].first == CIRCLE) ? 1. : batch[i].second, e.valid, e.objective});
        if(e.valid && e.objective < best_objective)
        {
          best_objective = e.objective;
          best = std::move(e.solution);
          report.chosen_candidate = static_cast<int>(report.border_candidates.size()) - 1;
        }
        objectives[i] = e.objective;
      }
      return objectives;
    };

    // the grid: the circle, and t = 0, 1/2 for both measured borders
    std::vector<double> grid = evaluate({{CIRCLE, 1.}, {POLICY_BORDER, 0.}, {POLICY_BORDER, 0.5}});
    // without the second border's distances (an unreachable vertex, say) the search goes on
    // with the policy's border alone
    const bool have_second = (second_ready.get() == OK);
    if(have_second)
    {
      const std::vector<double> grid_second = evaluate({{SECOND_BORDER, 0.}, {SECOND_BORDER, 0.5}});
      grid.insert(grid.end(), grid_second.begin(), grid_second.end());
    }
    // golden-section search of each family around its best grid point, both in one batch
    struct Bracket
    {
      Border_family family;
      double a, b, x1, x2, f1, f2;
    };
    const double ratio = 0.5 * (std::sqrt(5.) - 1.);
    std::vector<Bracket> brackets;
    for(const Border_family family : {POLICY_BORDER, SECOND_BORDER})
    {
      if(family == SECOND_BORDER && !have_second)
        continue;
      const std::size_t first = (family == POLICY_BORDER) ? 1 : 3;
      const double f[3] = {grid[first], grid[first + 1], grid[0]};  // t = 0, 1/2, 1
      const int i = (f[1] <= f[0] && f[1] <= f[2]) ? 1 : (f[0] <= f[2] ? 0 : 2);
      const double a = (std::max)(0., 0.5 * i - 0.5), b = (std::min)(1., 0.5 * i + 0.5);
      brackets.push_back({family, a, b, b - ratio * (b - a), a + ratio * (b - a), 0., 0.});
    }
    {
      std::vector<std::pair<Border_family, double> > batch;
      for(const Bracket& br : brackets)
      {
        batch.emplace_back(br.family, br.x1);
        batch.emplace_back(br.family, br.x2);
      }
      const std::vector<double> f = evaluate(batch);
      for(std::size_t j = 0; j < brackets.size(); ++j)
      {
        brackets[j].f1 = f[2 * j];
        brackets[j].f2 = f[2 * j + 1];
      }
    }
    for(int step = 0; step < 2; ++step)
    {
      std::vector<std::pair<Border_family, double> > batch;
      std::vector<bool> new_is_x1;
      for(Bracket& br : brackets)
      {
        // two invalid points: the valid side is the circle's (t = 1 is convex, hence valid)
        const bool both_invalid = !std::isfinite(br.f1) && !std::isfinite(br.f2);
        new_is_x1.push_back(!both_invalid && br.f1 <= br.f2);
        if(new_is_x1.back())  // the minimum is in [a, x2]
        {
          br.b = br.x2;
          br.x2 = br.x1;
          br.f2 = br.f1;
          br.x1 = br.b - ratio * (br.b - br.a);
          batch.emplace_back(br.family, br.x1);
        }
        else  // in [x1, b]
        {
          br.a = br.x1;
          br.x1 = br.x2;
          br.f1 = br.f2;
          br.x2 = br.a + ratio * (br.b - br.a);
          batch.emplace_back(br.family, br.x2);
        }
      }
      const std::vector<double> f = evaluate(batch);
      for(std::size_t j = 0; j < brackets.size(); ++j)
        (new_is_x1[j] ? brackets[j].f1 : brackets[j].f2) = f[j];
    }

    if(report.chosen_candidate < 0)
      return ERROR_NO_1_TO_1_MAPPING;
    border_uv = std::move(best.border_uv);
    u = std::move(best.u);
    v = std::move(best.v);
    return OK;
  }

  Border_parameterizer m_border;
  std::shared_ptr<Report> m_report;
  Repair m_repair = BLEND_TOWARD_CIRCLE;
  Border_choice m_border_choice = MEASURED_BORDER;
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_MEASURED_CONFORMAL_PARAMETERIZER_3_H
