// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_BORDERS_CONFORMAL_BORDER_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_BORDERS_CONFORMAL_BORDER_H

// The conformal border: the border of Boundary First Flattening (Sawhney and Crane 2017)
// with boundary scale factors 0, computed with the interior cotangent Laplacian L_II that the
// measured method factorizes anyway (one more back-substitution).
//
//   1. angle sums s_i; angle defects Omega_i = 2 pi - s_i (interior vertices), geodesic
//      curvature k_i = pi - s_i (border vertices);
//   2. L_II u_I = Omega_I with u_B = 0; h = L_BI u_I (the border rows of L u);
//   3. target turning angles k~_i = k_i - h_i (they sum to 2 pi: discrete Gauss-Bonnet);
//   4. border edge lengths l_i = |b_{i+1} - b_i| (kept: u_B = 0), directions
//      phi_i = phi_{i-1} - k~_i (clockwise, as CGAL's circle: faces keep a positive
//      orientation);
//   5. closing: the smallest change of lengths, l* = l - N^-1 T^T (T N^-1 T^T)^-1 T l with
//      N^-1 = diag(l), T the 2 x m matrix of directions.
//
// A blend toward the circle keeps the lengths and mixes the turning angles,
// k_i(t) = (1 - t) k~_i + t c_i with c_i = pi (l_{i-1} + l_i) / sum l (the turning angles of
// the arc-length circle): every member closes, and at t = 1 every turning angle is positive,
// so the polygon is convex.
//
// The conformal-length member (conformal_length_data()) keeps those turning angles and scales
// the lengths by the conformal factors of the whole cotangent Laplacian: one more
// factorization (the grounded cotangent system of the disk), built only for that member.

#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/internal/borders/polar_map.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/triangle_geometry.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/validity.h>

#include <CGAL/number_type_config.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// What the conformal border is made of, one entry per border vertex b_k (patch.border()
// order); edge k joins b_k and b_{k+1}.
struct Conformal_border_data
{
  std::vector<double> lengths;     // l_k, 3D length of border edge k
  std::vector<double> curvature;   // k_k = pi - s_k, the geodesic curvature
  std::vector<double> correction;  // h_k = (L_BI u_I)_k
  std::vector<double> turning;     // target turning angles k~_k = k_k - h_k
  std::vector<double> circle;      // c_k = pi (l_{k-1} + l_k) / sum l
};

// The 3D lengths of the border edges and the turning angles of the arc-length circle.
template <class Disk>
Error_code border_lengths(const Disk& patch, Conformal_border_data& out)
{
  const std::vector<int>& border = patch.border();
  const std::size_t m = border.size();
  if(m < 3)
    return ERROR_BORDER_TOO_SHORT;
  out.lengths.resize(m);
  double total = 0.;
  for(std::size_t k = 0; k < m; ++k)
  {
    out.lengths[k] = (patch.point(static_cast<std::size_t>(border[(k + 1) % m])) -
                      patch.point(static_cast<std::size_t>(border[k]))).norm();
    if(!(out.lengths[k] > 0.))
      return ERROR_DEGENERATE_BORDER_MAP;
    total += out.lengths[k];
  }
  out.circle.resize(m);
  for(std::size_t k = 0; k < m; ++k)
    out.circle[k] = CGAL_PI * (out.lengths[(k + m - 1) % m] + out.lengths[k]) / total;
  return OK;
}

// Steps 1-3: the target turning angles, with one back-substitution of L_II (factorized by
// the patch if it is not yet).
template <class Disk>
Error_code conformal_border_data(Disk& patch, Conformal_border_data& out)
{
  Error_code status = border_lengths(patch, out);
  if(status != OK)
    return status;
  std::vector<double> sums;
  angle_sums(patch.points(), patch.faces_indices(), sums);
  const std::vector<int>& interior = patch.interior_vertices();
  std::vector<double> defects(interior.size()), u;
  for(std::size_t r = 0; r < interior.size(); ++r)
    defects[r] = 2. * CGAL_PI - sums[static_cast<std::size_t>(interior[r])];
  status = patch.solve_interior(defects, u);
  if(status != OK)
    return status;
  patch.systems().interior()->fixed_rows_times_free(u, out.correction);
  const std::vector<int>& border = patch.border();
  out.curvature.resize(border.size());
  out.turning.resize(border.size());
  for(std::size_t k = 0; k < border.size(); ++k)
  {
    out.curvature[k] = CGAL_PI - sums[static_cast<std::size_t>(border[k])];
    out.turning[k] = out.curvature[k] - out.correction[k];
    if(!std::isfinite(out.turning[k]))
      return ERROR_DEGENERATE_BORDER_MAP;
  }
  return OK;
}

// The turning angles of the blend toward the circle: (1 - t) k~ + t c.
inline std::vector<double> blended_turning_angles(const Conformal_border_data& data, double t)
{
  std::vector<double> k(data.turning.size());
  for(std::size_t i = 0; i < k.size(); ++i)
    k[i] = (1. - t) * data.turning[i] + t * data.circle[i];
  return k;
}

// Step 5: the lengths closest to `lengths` (weights 1 / l) for which the edges of directions
// `phi` close: l* = l - diag(l) T^T (T diag(l) T^T)^-1 T l. False when the directions do not
// span the plane or a length would not stay positive.
inline bool close_lengths(const std::vector<double>& phi, const std::vector<double>& lengths,
                          std::vector<double>& closed)
{
  const std::size_t m = phi.size();
  double a = 0., b = 0., c = 0., rx = 0., ry = 0., total = 0.;  // M = [a b; b c], r = T l
  for(std::size_t k = 0; k < m; ++k)
  {
    const double x = std::cos(phi[k]), y = std::sin(phi[k]), l = lengths[k];
    a += l * x * x;
    b += l * x * y;
    c += l * y * y;
    rx += l * x;
    ry += l * y;
    total += l;
  }
  const double det = a * c - b * b;
  if(!(det > 1e-12 * total * total))
    return false;
  const double lx = (c * rx - b * ry) / det, ly = (a * ry - b * rx) / det;  // M^-1 r
  closed.resize(m);
  for(std::size_t k = 0; k < m; ++k)
  {
    closed[k] = lengths[k] * (1. - (std::cos(phi[k]) * lx + std::sin(phi[k]) * ly));
    if(!(closed[k] > 0.) || !std::isfinite(closed[k]))
      return false;
  }
  return true;
}

// Steps 4-5 and CGAL's placement: the closed polygon b_0..b_{m-1} with turning angles `turning`
// (turning[k] at b_k, between edges k-1 and k) and edge lengths as close as possible to
// `lengths`, traversed clockwise, scaled into [0,1]^2. Edge 0 has the direction of the
// circle's first chord, so that the blend at t = 1 is the arc-length circle's orientation.
inline Error_code polygon_from_turning_angles(const std::vector<double>& turning,
                                              const std::vector<double>& lengths,
                                              std::vector<Eigen::Vector2d>& polygon,
                                              std::vector<double>* closed_lengths = nullptr)
{
  const std::size_t m = turning.size();
  if(m < 3 || lengths.size() != m)
    return ERROR_WRONG_PARAMETER;
  double total = 0.;
  for(double l : lengths)
    total += l;
  std::vector<double> phi(m), closed;
  phi[0] = -0.5 * CGAL_PI - CGAL_PI * lengths[0] / total;
  for(std::size_t k = 1; k < m; ++k)
    phi[k] = phi[k - 1] - turning[k];
  if(!close_lengths(phi, lengths, closed))
    return ERROR_DEGENERATE_BORDER_MAP;
  polygon.resize(m);
  Eigen::Vector2d x(0., 0.);
  for(std::size_t k = 0; k < m; ++k)
  {
    polygon[k] = x;
    x += closed[k] * Eigen::Vector2d(std::cos(phi[k]), std::sin(phi[k]));
  }
  Eigen::Vector2d origin;
  double scale = 1.;
  if(!fit_into_unit_square(polygon, origin, scale))
    return ERROR_DEGENERATE_BORDER_MAP;
  if(closed_lengths)
    *closed_lengths = std::move(closed);
  return OK;
}

// The conformal-length member (METHOD.md section 8): the same turning angles
// k(t) = (1 - t) k~ + t c, with the lengths made conformal too. On the whole cotangent
// Laplacian L (one vertex pinned; the right-hand side sums to 0 by discrete Gauss-Bonnet)
// L u = [Omega_I ; k_B - c], the mean of u removed; border edge k of member t has the length
// l_k exp(-t (u_k + u_{k+1}) / 2). With this u (L u = Omega - Omega~ for the target angles),
// exp(-u) is the conformal scale of lengths: exp(+u) makes the family diverge. u_B is linear
// in t, so the one solve serves every t.
template <class Disk>
Error_code conformal_length_data(Disk& patch, const Conformal_border_data& conformal, std::vector<double>& scale)
{
  const std::vector<int>& border = patch.border();
  if(border.size() < 3 || conformal.curvature.size() != border.size() || conformal.circle.size() != border.size())
    return ERROR_WRONG_PARAMETER;
  std::vector<double> f, u;
  angle_sums(patch.points(), patch.faces_indices(), f);
  for(double& x : f)
    x = 2. * CGAL_PI - x;  // Omega_i on the interior rows
  for(std::size_t k = 0; k < border.size(); ++k)
    f[static_cast<std::size_t>(border[k])] = conformal.curvature[k] - conformal.circle[k];
  const Error_code status = patch.solve_cotangent_poisson(f, u);
  if(status != OK)
    return status;
  if(u.empty())
    return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
  double mean = 0.;
  for(double x : u)
    mean += x;
  mean /= double(u.size());
  scale.resize(border.size());
  for(std::size_t k = 0; k < border.size(); ++k)
  {
    scale[k] = u[static_cast<std::size_t>(border[k])] - mean;
    if(!std::isfinite(scale[k]))
      return ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
  }
  return OK;
}

// The edge lengths of member t: l_k exp(-t (u_k + u_{k+1}) / 2), with min(u_B) subtracted
// first (a uniform scale, removed by the placement) so that no factor exceeds 1. False when
// a length is not positive and finite (u_B spanning more than ~1400 units).
inline bool conformal_lengths(const std::vector<double>& lengths, const std::vector<double>& scale, double t,
                              std::vector<double>& out)
{
  const std::size_t m = lengths.size();
  if(scale.size() != m || m == 0)
    return false;
  const double low = *std::min_element(scale.begin(), scale.end());
  out.resize(m);
  for(std::size_t k = 0; k < m; ++k)
  {
    out[k] = lengths[k] * std::exp(-0.5 * t * ((scale[k] - low) + (scale[(k + 1) % m] - low)));
    if(!(out[k] > 0.) || !std::isfinite(out[k]))
      return false;
  }
  return true;
}

// The polygon of the conformal-length member t (at t = 0: the conformal border exactly).
inline Error_code conformal_length_polygon(const Conformal_border_data& data, const std::vector<double>& scale,
                                           double t, std::vector<Eigen::Vector2d>& polygon,
                                           std::vector<double>* closed_lengths = nullptr)
{
  std::vector<double> lengths;
  if(!conformal_lengths(data.lengths, scale, t, lengths))
    return ERROR_DEGENERATE_BORDER_MAP;
  return polygon_from_turning_angles(blended_turning_angles(data, t), lengths, polygon, closed_lengths);
}

// Bisection steps of the blend toward the circle when the conformal polygon is not simple.
constexpr int simple_blend_bisection_steps = 20;

// The smallest blend t in [0, 1] at which the polygon of a member, `polygon_at(t, polygon,
// closed)` (an Error_code), is simple: t = 0 when it is simple there, otherwise found by
// simple_blend_bisection_steps bisection steps (t = 1 is convex for the conformal members).
// Fails only when the polygon at t = 1 is not simple or does not close.
template <class PolygonAt>
Error_code smallest_simple_blend_of(const PolygonAt& polygon_at, double& t, std::vector<Eigen::Vector2d>& polygon,
                                    std::vector<double>& closed)
{
  auto build = [&polygon_at](double blend, std::vector<Eigen::Vector2d>& p, std::vector<double>& l) {
    return polygon_at(blend, p, l) == OK && is_simple_polygon(p);
  };
  t = 0.;
  if(build(0., polygon, closed))
    return OK;
  t = 1.;
  if(!build(1., polygon, closed))
    return ERROR_DEGENERATE_BORDER_MAP;
  double invalid = 0.;
  std::vector<Eigen::Vector2d> p;
  std::vector<double> l;
  for(int step = 0; step < simple_blend_bisection_steps; ++step)
  {
    const double mid = 0.5 * (invalid + t);
    if(build(mid, p, l))
    {
      t = mid;
      polygon.swap(p);
      closed.swap(l);
    }
    else
      invalid = mid;
  }
  return OK;
}

// The conformal member's smallest simple blend (lengths kept).
inline Error_code smallest_simple_blend(const Conformal_border_data& data, double& t,
                                        std::vector<Eigen::Vector2d>& polygon, std::vector<double>& closed)
{
  auto polygon_at = [&data](double blend, std::vector<Eigen::Vector2d>& p, std::vector<double>& l) {
    return polygon_from_turning_angles(blended_turning_angles(data, blend), data.lengths, p, &l);
  };
  return smallest_simple_blend_of(polygon_at, t, polygon, closed);
}

// The conformal-length member's smallest simple blend.
inline Error_code smallest_simple_length_blend(const Conformal_border_data& data, const std::vector<double>& scale,
                                               double& t, std::vector<Eigen::Vector2d>& polygon,
                                               std::vector<double>& closed)
{
  auto polygon_at = [&data, &scale](double blend, std::vector<Eigen::Vector2d>& p, std::vector<double>& l) {
    return conformal_length_polygon(data, scale, blend, p, &l);
  };
  return smallest_simple_blend_of(polygon_at, t, polygon, closed);
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_BORDERS_CONFORMAL_BORDER_H
