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
// One factorization serves every cone: L restricted to V \ D (or, on a closed surface, L
// grounded at one vertex, the first cone's Dirichlet condition being a shift); adding a
// cone c to D is the rank-one update u <- u - u(c)/G(c,c) G(.,c), where G is the Green
// function of the current D, itself updated the same way (one back-substitution per cone).

#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/internal/seams/cut_graph.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/laplacian.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/factorized_system.h>

#include <CGAL/number_type_config.h>

#include <Eigen/Core>
#include <Eigen/Sparse>

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
  const std::size_t n = static_cast<std::size_t>(s.number_of_vertices());
  data.half_cotangents.resize(s.faces.size());
  data.angle_defects.assign(n, 2. * CGAL_PI);
  data.areas.assign(n, 0.);
  for(std::size_t f = 0; f < s.faces.size(); ++f)
  {
    const std::array<int, 3>& t = s.faces[f];
    const Eigen::Vector3d& p0 = s.points[static_cast<std::size_t>(t[0])];
    const Eigen::Vector3d& p1 = s.points[static_cast<std::size_t>(t[1])];
    const Eigen::Vector3d& p2 = s.points[static_cast<std::size_t>(t[2])];
    if(is_degenerate_triangle(p0, p1, p2))
      return ERROR_DEGENERATE_FACE;
    const double double_area = (p1 - p0).cross(p2 - p0).norm();
    for(int k = 0; k < 3; ++k)
    {
      const std::size_t v = static_cast<std::size_t>(t[static_cast<std::size_t>(k)]);
      const Eigen::Vector3d& p = s.points[v];
      const Eigen::Vector3d a = s.points[static_cast<std::size_t>(t[static_cast<std::size_t>((k + 1) % 3)])] - p;
      const Eigen::Vector3d b = s.points[static_cast<std::size_t>(t[static_cast<std::size_t>((k + 2) % 3)])] - p;
      data.half_cotangents[f][static_cast<std::size_t>(k)] = 0.5 * a.dot(b) / double_area;
      data.angle_defects[v] -= std::atan2(a.cross(b).norm(), a.dot(b));
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

  const Solver_statistics& statistics() const { return m_system.statistics(); }

  Error_code place(int count, std::vector<int>& cones)
  {
    if(count <= 0)
      return OK;
    Error_code status = curvature_data(m_surface, m_data);
    if(status != OK)
      return status;
    const std::size_t n = m_data.angle_defects.size();
    m_closed = std::find(m_fixed.begin(), m_fixed.end(), char(1)) == m_fixed.end();
    m_fixed_now = m_fixed;
    if((status = factor()) != OK)
      return status;

    std::vector<double> u;
    if(m_closed)
    {
      // the first cone: the extreme of the mean-corrected scale factor (zero weighted mean)
      const double total_defect = std::accumulate(m_data.angle_defects.begin(), m_data.angle_defects.end(), 0.);
      const double total_area = std::accumulate(m_data.areas.begin(), m_data.areas.end(), 0.);
      std::vector<double> f(n);
      for(std::size_t i = 0; i < n; ++i)
        f[i] = m_data.angle_defects[i] - m_data.areas[i] * total_defect / total_area;
      if((status = solve_grounded(f, u)) != OK)
        return status;
      double mean = 0.;
      for(std::size_t i = 0; i < n; ++i)
        mean += m_data.areas[i] * u[i] / total_area;
      for(double& x : u)
        x -= mean;
      m_first = extreme_vertex(u);
      cones.push_back(m_first);
      m_fixed_now[static_cast<std::size_t>(m_first)] = 1;
      --count;
    }
    if((status = solve(m_data.angle_defects, u)) != OK)
      return status;

    std::vector<std::vector<double> > green;  // G(., c_j) of the set before cone j
    std::vector<int> added;
    std::vector<double> e(n, 0.);
    for(; count > 0; --count)
    {
      const int c = extreme_vertex(u);
      if(c < 0 || !(std::abs(u[static_cast<std::size_t>(c)]) > 0.))
        break;
      e[static_cast<std::size_t>(c)] = 1.;
      std::vector<double> g;
      status = solve(e, g);
      e[static_cast<std::size_t>(c)] = 0.;
      if(status != OK)
        return status;
      for(std::size_t j = 0; j < green.size(); ++j)
      {
        const double ratio = green[j][static_cast<std::size_t>(c)] / green[j][static_cast<std::size_t>(added[j])];
        for(std::size_t i = 0; i < n; ++i)
          g[i] -= ratio * green[j][i];
      }
      const double gcc = g[static_cast<std::size_t>(c)];
      if(!(gcc > 0.) || !std::isfinite(gcc))
        break;  // numerically already fixed
      const double ratio = u[static_cast<std::size_t>(c)] / gcc;
      for(std::size_t i = 0; i < n; ++i)
        u[i] -= ratio * g[i];
      u[static_cast<std::size_t>(c)] = 0.;
      cones.push_back(c);
      m_fixed_now[static_cast<std::size_t>(c)] = 1;
      green.push_back(std::move(g));
      added.push_back(c);
    }
    m_scale_factors = std::move(u);
    return OK;
  }

  // u after the last cone (0 on D and at the cones).
  const std::vector<double>& scale_factors() const { return m_scale_factors; }

private:
  // L restricted to the unknowns: V \ D, or every vertex but one (the ground) on a closed
  // surface.
  Error_code factor()
  {
    const std::size_t n = m_fixed.size();
    m_row.assign(n, -1);
    int next = 0;
    for(std::size_t i = 0; i < n; ++i)
      if(m_closed ? i != 0 : !m_fixed[i])
        m_row[i] = next++;
    if(next == 0)
      return ERROR_NO_INTERIOR_VERTEX;
    const Laplacian_pattern pattern(n, m_surface.faces);
    Eigen::SparseMatrix<double> L;
    pattern.assemble(m_surface.faces, m_row, next, Cotangent_weight{&m_data.half_cotangents}, L);
    return m_system.factor(L);
  }

  // x with L x = f on the unknowns, 0 elsewhere.
  Error_code solve_grounded(const std::vector<double>& f, std::vector<double>& x)
  {
    std::vector<double> b(static_cast<std::size_t>(m_system.size())), y;
    for(std::size_t i = 0; i < f.size(); ++i)
      if(m_row[i] >= 0)
        b[static_cast<std::size_t>(m_row[i])] = f[i];
    const Error_code status = m_system.solve(b, y);
    if(status != OK)
      return status;
    x.assign(f.size(), 0.);
    for(std::size_t i = 0; i < f.size(); ++i)
      if(m_row[i] >= 0)
        x[i] = y[static_cast<std::size_t>(m_row[i])];
    return OK;
  }

  // The solution of L x = f off D0, x = 0 on D0, where D0 is `fixed`, or, on a closed surface,
  // the first cone: the cone takes the residual -sum(f) (then L x = f' has a solution, unique
  // up to a constant), and the constant makes x vanish there.
  Error_code solve(const std::vector<double>& f, std::vector<double>& x)
  {
    if(!m_closed)
      return solve_grounded(f, x);
    std::vector<double> g = f;
    g[static_cast<std::size_t>(m_first)] -= std::accumulate(f.begin(), f.end(), 0.);
    const Error_code status = solve_grounded(g, x);
    if(status != OK)
      return status;
    const double shift = x[static_cast<std::size_t>(m_first)];
    for(double& v : x)
      v -= shift;
    x[static_cast<std::size_t>(m_first)] = 0.;
    return OK;
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
  std::vector<int> m_row;
  bool m_closed = false;
  int m_first = -1;
  Factorized_system<SolverTraits> m_system;
  std::vector<double> m_scale_factors;
};

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_SEAMS_CONE_PLACEMENT_H
