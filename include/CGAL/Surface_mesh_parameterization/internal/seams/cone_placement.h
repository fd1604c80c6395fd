// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_SEAMS_CONE_PLACEMENT_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_SEAMS_CONE_PLACEMENT_H

// Greedy cone placement (Sawhney and Crane, "Boundary First Flattening", section on cone
// singularities; after Ben-Chen, Gotsman and Bunin 2008): the conformal scale factor u of a
// flattening that keeps u = 0 on a set D solves the Poisson equation of the angle defects
//
//     L u = Omega off D,   u = 0 on D,
//
// with L = D - W the cotangent Laplacian and Omega_i = 2 pi - (angle sum at i). log(area
// ratio) = 2u, so the area distortion is largest where |u| is. Cones are added one at a time
// at the vertex of largest |u|, each then joining D. D starts as the border and the cut
// computed so far; on a closed surface without cut, the first cone is where the scale factor
// of the mean-corrected problem (L u = Omega - A ΣOmega / ΣA, A the vertex areas) is most
// extreme.
//
// One factorization of the package's Dirichlet engine serves every cone: L restricted to
// V \ D (solve_scattered()), or, on a closed surface, L grounded at vertex 0, the first
// cone's Dirichlet condition being a shift (solve_with_zero_at()). Adding a cone c to D is
// the rank-one update u <- u - u(c)/G(c,c) G(.,c), where G is the Green function of the
// current D, itself updated the same way (one back-substitution per cone).

#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/dirichlet_engine.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/laplacian.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/triangle_geometry.h>
#include <CGAL/Surface_mesh_parameterization/internal/seams/cut_graph.h>

#include <CGAL/number_type_config.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// Per-vertex and per-face geometry of the Poisson problem.
struct Curvature_data
{
  std::vector<std::array<double, 3> > half_cotangents;  // per face corner
  std::vector<double> angle_defects;                     // 2 pi - angle sum
  std::vector<double> areas;                             // a third of the incident face areas
};

inline Error_code curvature_data(const Indexed_surface& s, Curvature_data& data)
{
  data.half_cotangents.resize(s.faces.size());
  data.angle_defects.assign(s.points.size(), 2. * CGAL_PI);
  data.areas.assign(s.points.size(), 0.);
  for(std::size_t f = 0; f < s.faces.size(); ++f)
  {
    const std::array<Eigen::Vector3d, 3> p = {{s.points[static_cast<std::size_t>(s.faces[f][0])],
                                              s.points[static_cast<std::size_t>(s.faces[f][1])],
                                              s.points[static_cast<std::size_t>(s.faces[f][2])]}};
    if(is_degenerate_triangle(p[0], p[1], p[2]))
      return ERROR_DEGENERATE_FACE;
    data.half_cotangents[f] = half_cotangents(p[0], p[1], p[2]);
    const double double_area = (p[1] - p[0]).cross(p[2] - p[0]).norm();
    for(int k = 0; k < 3; ++k)
    {
      const std::size_t v = static_cast<std::size_t>(s.faces[f][static_cast<std::size_t>(k)]);
      data.angle_defects[v] -= corner_angle(p, k);
      data.areas[v] += double_area / 6.;
    }
  }
  return OK;
}

// The greedy placement. `fixed` flags D (border and cut so far); `count` cones are placed
// (fewer if |u| vanishes first). Cones are appended to `cones`.
template <class SolverTraits>
class Cone_placement
{
public:
  Cone_placement(const Indexed_surface& s, const std::vector<char>& fixed) : m_surface(s), m_fixed(fixed) { }

  Solver_statistics statistics() const { return m_engine.statistics(); }

  Error_code place(int count, std::vector<int>& cones)
  {
    if(count <= 0)
      return OK;
    Error_code status = curvature_data(m_surface, m_data);
    if(status != OK)
      return status;
    m_closed = std::find(m_fixed.begin(), m_fixed.end(), char(1)) == m_fixed.end();
    m_fixed_now = m_fixed;
    if((status = build_engine()) != OK)
      return status;
    if(m_closed && (status = place_first_cone(cones)) != OK)
      return status;
    std::vector<double> u;
    if((status = solve(m_data.angle_defects, u)) != OK)
      return status;
    return place_by_updates(m_closed ? count - 1 : count, u, cones);
  }

private:
  // The engine on L restricted to the unknowns: V \ D, or every vertex but one (the ground,
  // vertex 0) on a closed surface.
  Error_code build_engine()
  {
    std::vector<int> fixed;
    for(std::size_t i = 0; i < m_fixed.size(); ++i)
      if(m_closed ? i == 0 : m_fixed[i] != 0)
        fixed.push_back(static_cast<int>(i));
    const Laplacian_pattern pattern(m_fixed.size(), m_surface.faces);
    const Error_code status = m_engine.build(pattern, m_surface.faces, m_fixed.size(), fixed,
                                             Cotangent_weight{&m_data.half_cotangents});
    if(status == OK && m_engine.number_of_free_vertices() == 0)
      return ERROR_NO_INTERIOR_VERTEX;
    return status;
  }

  // The first cone of a closed surface: the extreme of the mean-corrected scale factor (zero
  // weighted mean), with the grounded system.
  Error_code place_first_cone(std::vector<int>& cones)
  {
    const std::size_t n = m_data.angle_defects.size();
    const double total_defect = std::accumulate(m_data.angle_defects.begin(), m_data.angle_defects.end(), 0.);
    const double total_area = std::accumulate(m_data.areas.begin(), m_data.areas.end(), 0.);
    std::vector<double> f(n), u;
    for(std::size_t i = 0; i < n; ++i)
      f[i] = m_data.angle_defects[i] - m_data.areas[i] * total_defect / total_area;
    const Error_code status = m_engine.solve_scattered(f, u);
    if(status != OK)
      return status;
    double mean = 0.;
    for(std::size_t i = 0; i < n; ++i)
      mean += m_data.areas[i] * u[i] / total_area;
    for(double& x : u)
      x -= mean;
    m_first = extreme_vertex(u);
    cones.push_back(m_first);
    m_fixed_now[static_cast<std::size_t>(m_first)] = 1;
    return OK;
  }

  // Adds up to `count` cones at the extremes of u, updating u after each one.
  Error_code place_by_updates(int count, std::vector<double>& u, std::vector<int>& cones)
  {
    std::vector<std::vector<double> > green;  // G(., c_j) of the set before cone j
    std::vector<int> added;
    for(; count > 0; --count)
    {
      const int c = extreme_vertex(u);
      if(c < 0 || !(std::abs(u[static_cast<std::size_t>(c)]) > 0.))
        break;
      std::vector<double> g;
      const Error_code status = green_function(c, green, added, g);
      if(status != OK)
        return status;
      const double gcc = g[static_cast<std::size_t>(c)];
      if(!(gcc > 0.) || !std::isfinite(gcc))
        break;  // numerically already fixed
      const double ratio = u[static_cast<std::size_t>(c)] / gcc;
      for(std::size_t i = 0; i < u.size(); ++i)
        u[i] -= ratio * g[i];
      u[static_cast<std::size_t>(c)] = 0.;
      cones.push_back(c);
      m_fixed_now[static_cast<std::size_t>(c)] = 1;
      green.push_back(std::move(g));
      added.push_back(c);
    }
    return OK;
  }

  // g = G(., c) for the set D0 and the cones `added` (whose Green functions are `green`):
  // one back-substitution, then the rank-one updates of the cones in order.
  Error_code green_function(int c, const std::vector<std::vector<double> >& green, const std::vector<int>& added,
                            std::vector<double>& g)
  {
    std::vector<double> e(m_data.angle_defects.size(), 0.);
    e[static_cast<std::size_t>(c)] = 1.;
    const Error_code status = solve(e, g);
    if(status != OK)
      return status;
    for(std::size_t j = 0; j < green.size(); ++j)
    {
      const double ratio = green[j][static_cast<std::size_t>(c)] / green[j][static_cast<std::size_t>(added[j])];
      for(std::size_t i = 0; i < g.size(); ++i)
        g[i] -= ratio * green[j][i];
    }
    return OK;
  }

  // The solution of L x = f off D0, x = 0 on D0, where D0 is `fixed`, or, on a closed surface,
  // the first cone.
  Error_code solve(const std::vector<double>& f, std::vector<double>& x)
  {
    if(!m_closed)
      return m_engine.solve_scattered(f, x);
    return m_engine.solve_with_zero_at(static_cast<std::size_t>(m_first), f, x);
  }

  // The vertex off D of largest |u|; ties (within 1e-9 relative) go to the smallest index.
  int extreme_vertex(const std::vector<double>& u) const
  {
    double largest = -1.;
    for(std::size_t i = 0; i < u.size(); ++i)
      if(!m_fixed_now[i])
        largest = (std::max)(largest, std::abs(u[i]));
    if(largest < 0.)
      return -1;
    for(std::size_t i = 0; i < u.size(); ++i)
      if(!m_fixed_now[i] && std::abs(u[i]) >= largest * (1. - 1e-9))
        return static_cast<int>(i);
    return -1;
  }

  const Indexed_surface& m_surface;
  const std::vector<char>& m_fixed;
  std::vector<char> m_fixed_now;
  Curvature_data m_data;
  bool m_closed = false;
  int m_first = -1;
  Dirichlet_engine<SolverTraits> m_engine;
};

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_SEAMS_CONE_PLACEMENT_H
