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
/// The checked, indexed disk that every step of the measured boundary parameterization works
/// on, with the Dirichlet systems the steps share.

#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/internal/checked_disk.h>
#include <CGAL/Surface_mesh_parameterization/internal/dirichlet_engine.h>
#include <CGAL/Surface_mesh_parameterization/internal/laplacian.h>
#include <CGAL/Surface_mesh_parameterization/internal/sparse_solver.h>

#include <CGAL/Default.h>

#include <Eigen/Core>

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
/// boundary parameterization (the *checked disk*, built once and then only read): the
/// vertices get dense local indices `0..n-1` (so generic code never relies on the mesh's own
/// vertex descriptors being integers), positions are copied as `double`, faces become index
/// triples, and, for a disk patch, the border loop is listed in the order of
/// `halfedges_around_face(bhd, mesh)` starting at `source(bhd)`.
///
/// The patch also owns the Dirichlet systems the steps share, each assembled and factorized
/// once on first use, then solved by back-substitution for any number of right-hand sides:
/// - the *interior system*: the cotangent Laplacian `L_II` with the border loop eliminated
///   (symmetric positive definite); it serves the boundary Poisson distance map, the
///   conformal border and the discrete conformal interior;
/// - the *spring system*, on request: the spring Laplacian grounded at one vertex, which
///   serves the Poisson distance map from any single source;
/// - the *mean value system*, on request (the repair): the mean value weights with the border
///   loop eliminated (not symmetric: a sparse LU).
///
/// `statistics()` counts the factorizations and back-substitutions done so far.
///
/// This class is the argument type of the `MeasuredCenterLocator` and
/// `MeasuredBorderDistance` concepts.
///
/// \tparam TriangleMesh a model of `FaceGraph` (`Surface_mesh`, `Polyhedron_3`, `Seam_mesh`, ...).
/// \tparam SolverTraits a model of `SparseLinearAlgebraWithFactorTraits_d`, used for every
///         symmetric system of the patch. %Default: `Default_sparse_cholesky_traits`
///         (Eigen's `SimplicialLDLT`). Each system default-constructs its own traits object.
///
/// A patch refers to the mesh it was built from: the mesh must outlive it and stay unchanged.
/// The systems are not thread-safe: use one patch from one thread at a time, except for
/// `shared_object()`.
template <class TriangleMesh, class SolverTraits = Default>
class Parameterization_patch_3 : public internal::Checked_disk<TriangleMesh>
{
  typedef internal::Checked_disk<TriangleMesh>                                  Disk;

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
  /// A factorized Dirichlet system of the patch.
  typedef internal::Dirichlet_engine<Solver_traits>                             Engine;

  /// creates an empty patch; fill it with `build_disk()` or `build_component()`.
  Parameterization_patch_3() = default;
  Parameterization_patch_3(const Parameterization_patch_3&) = delete;
  Parameterization_patch_3& operator=(const Parameterization_patch_3&) = delete;

  /// \name Construction
  /// @{

  /// builds the checked disk bounded by the border loop of `bhd` (see
  /// `internal::Checked_disk::build_disk()`: the checks, their error codes and the virtual
  /// filling of holes) and forgets every system.
  template <class VertexPointMap>
  Error_code build_disk(const TriangleMesh& tm, halfedge_descriptor bhd, VertexPointMap vpm,
                        bool fill_holes = true)
  {
    reset_systems();
    return Disk::build_disk(tm, bhd, vpm, fill_holes);
  }

  /// builds the checked component of face `seed`, with no main border (see
  /// `internal::Checked_disk::build_component()`), and forgets every system.
  template <class VertexPointMap>
  Error_code build_component(const TriangleMesh& tm, face_descriptor seed, VertexPointMap vpm)
  {
    reset_systems();
    return Disk::build_component(tm, seed, vpm);
  }

  /// @}

  /// \name The interior system (cotangent weights, border loop eliminated)
  /// @{

  /// assembles and factorizes `L_II` unless it already is. Requires a disk patch (a main
  /// border and an interior vertex); otherwise returns `ERROR_WRONG_PARAMETER`.
  Error_code factorize_interior_laplacian()
  {
    if(m_interior)
      return m_interior_status;
    if(this->border().empty() || this->interior_vertices().empty())
      return ERROR_WRONG_PARAMETER;
    m_interior = make_engine();
    m_interior_status = m_interior->build(this->pattern(), this->faces_indices(), this->number_of_vertices(),
                                          this->border(), internal::Cotangent_weight{&this->half_cotangents()});
    return m_interior_status;
  }

  /// the interior system, factorized if needed (`nullptr` when it cannot be).
  Engine* interior_system()
  {
    return factorize_interior_laplacian() == OK ? m_interior.get() : nullptr;
  }

  /// solves `L_II x = b` (one entry per interior vertex, in `interior_vertices()` order).
  Error_code solve_interior(const std::vector<double>& b, std::vector<double>& x)
  {
    Engine* e = interior_system();
    return e ? e->solve(b, x) : m_interior_status_or_wrong();
  }

  /// solves `L_II X = B` for every column of `B`, with one pass over the factorization for
  /// all columns when the solver allows it.
  Error_code solve_interior(const Eigen::MatrixXd& B, Eigen::MatrixXd& X)
  {
    Engine* e = interior_system();
    return e ? e->solve(B, X) : m_interior_status_or_wrong();
  }

  /// right-hand side of the interior Dirichlet problem for border values (one row per
  /// `border()` entry, one column per problem): `b_i = sum_{j in border} w_ij values_j`.
  /// Requires the interior system (`factorize_interior_laplacian()`).
  void interior_rhs_from_border(const Eigen::MatrixXd& border_values, Eigen::MatrixXd& b)
  {
    if(Engine* e = interior_system())
      e->rhs_from_fixed(border_values, b);
  }

  /// the border rows of the cotangent Laplacian \f$ L = D - W \f$ applied to a function that
  /// vanishes on the border: \f$ h = L_{BI} x \f$, i.e.
  /// \f$ h_k = -\sum_{i \in I} w_{b_k i} x_i \f$, one value per `border()` entry (`x` in
  /// `interior_vertices()` order). It is the transpose of `interior_rhs_from_border()`.
  void border_rows_times_interior(const std::vector<double>& x, std::vector<double>& h)
  {
    if(Engine* e = interior_system())
      e->fixed_rows_times_free(x, h);
  }

  /// @}

  /// \name The spring system (the paper's Poisson distance map from one source)
  /// @{

  /// assembles and factorizes, unless it already is for this `exponent`, the spring
  /// Laplacian (weights \f$ |x_i - x_j|^{-r} \f$, \f$ r \f$ = `exponent`) of the whole patch
  /// *grounded* at one vertex (`spring_ground()`), i.e. restricted to the other vertices.
  /// This factorization does not depend on the center, so it can be computed while the
  /// center is being located, and it serves the Poisson distance map from any single source
  /// (`solve_spring_poisson()`).
  Error_code factorize_spring_laplacian(double exponent)
  {
    if(m_spring && m_spring_exponent == exponent)
      return m_spring_status;
    if(this->number_of_vertices() < 2 || !std::isfinite(exponent))
      return ERROR_WRONG_PARAMETER;
    release_spring_laplacian();
    m_spring_exponent = exponent;
    m_spring_ground = this->border().empty() ? 0 : static_cast<std::size_t>(this->border().front());
    m_spring = make_engine();
    const internal::Spring_weight weight{&this->faces_indices(), &this->points(), &this->single_edge_masks(), exponent};
    m_spring_status = m_spring->build(this->pattern(), this->faces_indices(), this->number_of_vertices(),
                                      std::vector<int>(1, static_cast<int>(m_spring_ground)), weight);
    return m_spring_status;
  }

  /// frees the spring system's factorization (its work stays in `statistics()`).
  void release_spring_laplacian()
  {
    if(m_spring)
      m_released.add(m_spring->statistics());
    m_spring.reset();
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
    if(source >= this->number_of_vertices())
      return ERROR_WRONG_PARAMETER;
    Error_code status = factorize_spring_laplacian(exponent);
    if(status != OK)
      return status;
    const std::size_t n = this->number_of_vertices();
    const std::vector<double>& d = m_spring->row_sums();
    const std::vector<double>& g = this->mean_spoke_lengths();
    std::vector<double> rhs(m_spring->number_of_free_vertices(), 0.);
    double sum = 0.;
    for(std::size_t i = 0; i < n; ++i)
    {
      const double b = (i == source) ? 0. : d[i] * g[i];
      sum += b;
      if(m_spring->row(i) >= 0)
        rhs[static_cast<std::size_t>(m_spring->row(i))] = b;
    }
    if(source != m_spring_ground)
      rhs[static_cast<std::size_t>(m_spring->row(source))] = -sum;
    std::vector<double> x;
    status = m_spring->solve(rhs, x);
    if(status != OK)
      return status;
    values.resize(n);
    for(std::size_t i = 0; i < n; ++i)
      values[i] = (m_spring->row(i) < 0) ? 0. : x[static_cast<std::size_t>(m_spring->row(i))];
    const double shift = values[source];
    for(double& f : values)
      f -= shift;
    values[source] = 0.;
    return OK;
  }

  /// @}

  /// \name The mean value system (border loop eliminated), for the repair
  /// @{

  /// the mean value system, assembled and factorized (sparse LU) on first use; `nullptr`
  /// when it cannot be.
  Engine* mean_value_system()
  {
    if(!m_mean_value && !this->border().empty() && !this->interior_vertices().empty())
    {
      m_mean_value = make_engine();
      m_mean_value_status = m_mean_value->build(this->pattern(), this->faces_indices(), this->number_of_vertices(),
                                                this->border(),
                                                internal::Mean_value_weight{&this->faces_indices(), &this->points()});
    }
    return (m_mean_value && m_mean_value_status == OK) ? m_mean_value.get() : nullptr;
  }

  /// @}

  /// \name Shared objects and statistics
  /// @{

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
  void add_statistics(const Statistics& s) { m_released.add(s); }

  /// factorizations and back-substitutions done so far on this patch.
  Statistics statistics() const
  {
    Statistics s = m_released;
    for(const std::unique_ptr<Engine>* e : {&m_interior, &m_spring, &m_mean_value})
      if(*e)
        s.add((*e)->statistics());
    return s;
  }

  /// whether multi-column solves may use a second thread (CGAL's `Parallel_tag`; default:
  /// no). Results do not depend on it.
  void set_parallel(bool parallel) { m_parallel = parallel; }

  /// @}

private:
  std::unique_ptr<Engine> make_engine() const
  {
    std::unique_ptr<Engine> e = std::make_unique<Engine>();
    e->set_parallel(m_parallel);
    return e;
  }

  Error_code m_interior_status_or_wrong() const
  {
    return m_interior ? m_interior_status : ERROR_WRONG_PARAMETER;
  }

  void reset_systems()
  {
    m_interior.reset();
    m_spring.reset();
    m_mean_value.reset();
    m_interior_status = m_spring_status = m_mean_value_status = OK;
    m_spring_exponent = 0.;
    m_spring_ground = 0;
    m_released = Statistics();
    m_objects.clear();
  }

  std::unique_ptr<Engine> m_interior, m_spring, m_mean_value;
  Error_code m_interior_status = OK, m_spring_status = OK, m_mean_value_status = OK;
  double m_spring_exponent = 0.;
  std::size_t m_spring_ground = 0;
  Statistics m_released;
  bool m_parallel = false;
  std::unique_ptr<std::mutex> m_objects_mutex = std::make_unique<std::mutex>();
  std::map<std::type_index, std::shared_ptr<void> > m_objects;
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_PARAMETERIZATION_PATCH_3_H
