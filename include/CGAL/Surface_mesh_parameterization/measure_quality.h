// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_MEASURE_QUALITY_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_MEASURE_QUALITY_H

/// \file measure_quality.h
/// Distortion figures of a parameterization, and the global one-to-one test of a UV map.

#include <CGAL/Surface_mesh_parameterization/internal/core/angle_distortion.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/mesh_indexer.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/triangle_geometry.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/validity.h>

#include <CGAL/Bbox_2.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/number_type_config.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgSurfaceMeshParameterizationMeasured
///
/// Distortion figures of a piecewise linear map from a 3D triangle mesh to the plane.
/// For each face, `J` is the Jacobian of the map from the 3D triangle to its UV triangle and
/// `s1 >= s2` its singular values. Every figure is finite or `+infinity` (a UV triangle of
/// zero area), never NaN.
struct Parameterization_quality
{
  /// The paper's "conformal distortion" (Sheffer and de Sturler's angle error):
  /// \f$ \frac{1}{|V|}\sum_{\text{corners}} ((\alpha - \varphi)/\varphi)^2 \f$ where
  /// \f$ \alpha \f$ is the UV corner angle and \f$ \varphi \f$ ABF's optimal angle: the 3D
  /// corner angle, scaled at interior vertices so that the angles around the vertex sum to
  /// \f$ 2\pi \f$ (unchanged at border vertices). 0 for a conformal map of a flat mesh.
  double angle_distortion = 0.;
  /// Mean over all corners of \f$ ((\alpha - \beta)/\beta)^2 \f$, \f$ \beta \f$ the 3D angle.
  double angle_distortion_per_corner = 0.;
  /// Area-weighted (3D area) mean of \f$ s_1/s_2 \f$ (1 = conformal).
  double quasi_conformal_mean = 1.;
  /// Maximum of \f$ s_1/s_2 \f$.
  double quasi_conformal_max = 1.;
  /// Sander et al.'s \f$ L^2 \f$ stretch of the UV-to-3D map, normalised so that 1 is optimal:
  /// \f$ \sqrt{\sum_T A_T (\Gamma_T^2+\gamma_T^2)/2 / \sum_T A_T} \cdot
  /// \sqrt{\sum_T A^{uv}_T / \sum_T A_T} \f$ with \f$ \Gamma = 1/s_2 \f$, \f$ \gamma = 1/s_1 \f$
  /// and \f$ A_T \f$ the 3D area.
  double l2_stretch = 1.;
  /// Sander et al.'s \f$ L^\infty \f$ stretch, \f$ \max_T \Gamma_T \f$, same normalisation.
  double linf_stretch = 1.;
  /// Area-weighted mean of \f$ |\log(A^{uv}_T / A_T)| \f$ after scaling the UV areas to the
  /// same total as the 3D areas.
  double area_distortion_mean = 0.;
  /// Maximum of \f$ |\log(A^{uv}_T / A_T)| \f$, same normalisation.
  double area_distortion_max = 0.;
  /// Number of faces whose signed UV area is \f$ \le 0 \f$.
  std::size_t flipped_faces = 0;
  /// Number of faces measured.
  std::size_t number_of_faces = 0;
  /// Number of distinct vertices of the measured faces.
  std::size_t number_of_vertices = 0;
};

/// \ingroup PkgSurfaceMeshParameterizationMeasured
/// Distortion figures of one face (see `measure_quality_per_face()`).
struct Face_quality
{
  /// Mean over the face's three corners of \f$ ((\alpha - \varphi)/\varphi)^2 \f$, with the
  /// optimal angles \f$ \varphi \f$ of `Parameterization_quality::angle_distortion`.
  double angle_distortion = 0.;
  /// \f$ s_1/s_2 \f$ (`+infinity` for a UV triangle of zero area).
  double quasi_conformal = 1.;
  /// Signed area of the UV triangle (\f$ \le 0 \f$: flipped).
  double uv_area = 0.;
};

namespace internal {

struct No_face_visitor
{
  template <class Face>
  void operator()(Face, const Face_quality&) const { }
};

// The binary exponent of the largest finite coordinate of three points (0 when none is
// nonzero and finite).
template <class Point>
int largest_exponent(const std::array<Point, 3>& points)
{
  double largest = 0.;
  for(const Point& x : points)
    for(Eigen::Index c = 0; c < x.size(); ++c)
      if(std::isfinite(x[c]))
        largest = (std::max)(largest, std::abs(x[c]));
  return (largest > 0.) ? std::ilogb(largest) : 0;
}

// What the figures need of one face: its vertices (local indices), 3D and UV corner angles,
// 3D area, signed UV area, and the singular values s1 >= s2 of its Jacobian.
struct Face_figures
{
  std::array<int, 3> v{{0, 0, 0}};
  std::array<double, 3> beta{{0., 0., 0.}}, alpha{{0., 0., 0.}};
  double area = 0., uv_area = 0.;
  bool has_jacobian = false;  // false for a degenerate 3D face: no Jacobian, no weight
  double s1 = 0., s2 = 0.;
};

// The singular values of the Jacobian of 3D -> UV in an orthonormal frame of the 3D triangle,
// J = Q P^-1 with P = [[la, bx], [0, by]], without cancellation near s1 = s2:
// s1,2 = (|(j00 + j11, j10 - j01)| +- |(j00 - j11, j10 + j01)|) / 2.
inline void jacobian_figures(const std::array<Eigen::Vector3d, 3>& p, const std::array<Eigen::Vector2d, 3>& uv,
                             Face_figures& f)
{
  const Eigen::Vector3d e = p[1] - p[0], g = p[2] - p[0];
  const double la = e.norm();
  f.area = 0.5 * e.cross(g).norm();
  f.has_jacobian = f.area > 0. && la > 0.;
  if(!f.has_jacobian)
    return;
  const Eigen::Vector2d e1 = uv[1] - uv[0], e2 = uv[2] - uv[0];
  const double bx = e.dot(g) / la, by = 2. * f.area / la;
  const double j00 = e1.x() / la, j10 = e1.y() / la;
  const double j01 = (e2.x() - j00 * bx) / by, j11 = (e2.y() - j10 * bx) / by;
  const double pp = std::hypot(j00 + j11, j10 - j01), rr = std::hypot(j00 - j11, j10 + j01);
  f.s1 = 0.5 * (pp + rr);
  f.s2 = 0.5 * std::abs(pp - rr);
}

inline Face_figures face_figures(const std::array<Eigen::Vector3d, 3>& p, const std::array<Eigen::Vector2d, 3>& uv)
{
  Face_figures f;
  for(int c = 0; c < 3; ++c)
  {
    f.beta[std::size_t(c)] = corner_angle(p, c);
    f.alpha[std::size_t(c)] = corner_angle(uv, c);
  }
  const Eigen::Vector2d e1 = uv[1] - uv[0], e2 = uv[2] - uv[0];
  f.uv_area = 0.5 * (e1.x() * e2.y() - e1.y() * e2.x());
  jacobian_figures(p, uv, f);
  return f;
}

// The faces of a range, read once: their figures, and per vertex (a local index) the sum of
// its 3D angles and whether it lies on a border edge. Positions and UVs are divided by powers
// of two (exact) that bring the first face's largest coordinates into [1, 2): the figures are
// invariant under scaling, and squared lengths neither underflow nor overflow.
template <class TriangleMesh>
struct Measured_faces
{
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  std::vector<Face_figures> figures;
  std::vector<face_descriptor> faces;
  std::vector<double> angle_sums;
  std::vector<bool> on_border;

  template <class FaceRange, class VertexPointMap, class VertexUVMap>
  Measured_faces(const TriangleMesh& tm, const FaceRange& face_range, VertexPointMap vpm, VertexUVMap uvmap)
  {
    Mesh_indexer<TriangleMesh> indexer(tm);
    bool scaled = false;
    int exponent3 = 0, exponent2 = 0;
    for(face_descriptor f : face_range)
    {
      std::array<Eigen::Vector3d, 3> p;
      std::array<Eigen::Vector2d, 3> uv;
      std::array<int, 3> v;
      read_face(tm, f, vpm, uvmap, indexer, p, uv, v);
      if(!scaled)
      {
        exponent3 = largest_exponent(p);
        exponent2 = largest_exponent(uv);
        scaled = true;
      }
      for(int c = 0; c < 3; ++c)
      {
        p[std::size_t(c)] = Eigen::Vector3d(std::ldexp(p[std::size_t(c)].x(), -exponent3), std::ldexp(p[std::size_t(c)].y(), -exponent3),
                                            std::ldexp(p[std::size_t(c)].z(), -exponent3));
        uv[std::size_t(c)] = Eigen::Vector2d(std::ldexp(uv[std::size_t(c)].x(), -exponent2), std::ldexp(uv[std::size_t(c)].y(), -exponent2));
      }
      figures.push_back(face_figures(p, uv));
      figures.back().v = v;
      faces.push_back(f);
      for(int c = 0; c < 3; ++c)
        angle_sums[std::size_t(v[std::size_t(c)])] += figures.back().beta[std::size_t(c)];
    }
  }

  std::size_t number_of_vertices() const { return angle_sums.size(); }

  // ABF's optimal angle of corner c of face f
  double optimal_angle(const Face_figures& f, int c) const
  {
    const std::size_t v = std::size_t(f.v[std::size_t(c)]);
    return optimal_angle_scale(angle_sums[v], on_border[v]) * f.beta[std::size_t(c)];
  }

private:
  template <class VertexPointMap, class VertexUVMap>
  void read_face(const TriangleMesh& tm, face_descriptor f, VertexPointMap vpm, VertexUVMap uvmap,
                 Mesh_indexer<TriangleMesh>& indexer, std::array<Eigen::Vector3d, 3>& p,
                 std::array<Eigen::Vector2d, 3>& uv, std::array<int, 3>& v)
  {
    p.fill(Eigen::Vector3d::Zero());
    uv.fill(Eigen::Vector2d::Zero());
    v.fill(0);
    std::size_t k = 0;
    for(auto h : halfedges_around_face(halfedge(f, tm), tm))
    {
      if(k == 3)
        break;
      v[k] = indexer.add(target(h, tm), vpm);
      p[k] = indexer.points()[std::size_t(v[k])];
      const auto& y = get(uvmap, target(h, tm));
      uv[k] = Eigen::Vector2d(CGAL::to_double(y.x()), CGAL::to_double(y.y()));
      if(is_border(opposite(h, tm), tm))  // the edge into v[k] is on a border
      {
        const int s = indexer.add(source(h, tm), vpm);  // (may index a new vertex: resize after)
        on_border.resize(indexer.points().size(), false);
        on_border[std::size_t(v[k])] = on_border[std::size_t(s)] = true;
      }
      ++k;
    }
    angle_sums.resize(indexer.points().size(), 0.);
    on_border.resize(indexer.points().size(), false);
  }
};

// The area distortion figures, after scaling the UV areas to the 3D total.
template <class TriangleMesh>
void area_distortion(const Measured_faces<TriangleMesh>& m, Parameterization_quality& q)
{
  const double inf = std::numeric_limits<double>::infinity();
  double area3 = 0., area_uv = 0., sum = 0.;
  for(const Face_figures& f : m.figures)
  {
    area3 += f.area;
    area_uv += std::abs(f.uv_area);
  }
  const double log_scale = (area_uv > 0.) ? std::log(area3 / area_uv) : inf;
  for(const Face_figures& f : m.figures)
  {
    if(!f.has_jacobian)
      continue;
    const double log_ratio = (f.uv_area != 0.) ? std::log(std::abs(f.uv_area) / f.area) : -inf;
    const double d = std::abs(log_ratio + log_scale);
    sum += f.area * d;
    q.area_distortion_max = (std::max)(q.area_distortion_max, d);
  }
  if(area3 > 0.)
    q.area_distortion_mean = sum / area3;
}

// The stretch and quasi-conformal figures, from the singular values.
template <class TriangleMesh>
void stretch_figures(const Measured_faces<TriangleMesh>& m, Parameterization_quality& q)
{
  const double inf = std::numeric_limits<double>::infinity();
  double area3 = 0., area_uv = 0., qc_sum = 0., l2_sum = 0., max_G = 0.;
  for(const Face_figures& f : m.figures)
  {
    area3 += f.area;
    area_uv += std::abs(f.uv_area);
    q.flipped_faces += (f.uv_area > 0.) ? 0 : 1;
    if(!f.has_jacobian)
      continue;
    const double qc = (f.s2 > 0.) ? f.s1 / f.s2 : inf;
    const double G = (f.s2 > 0.) ? 1. / f.s2 : inf, g = (f.s1 > 0.) ? 1. / f.s1 : inf;
    qc_sum += f.area * qc;
    q.quasi_conformal_max = (std::max)(q.quasi_conformal_max, qc);
    l2_sum += f.area * 0.5 * (G * G + g * g);
    max_G = (std::max)(max_G, G);
  }
  if(!(area3 > 0.))
    return;
  const double norm = (area_uv > 0.) ? std::sqrt(area_uv / area3) : 0.;
  q.quasi_conformal_mean = qc_sum / area3;
  q.l2_stretch = (norm > 0.) ? std::sqrt(l2_sum / area3) * norm : inf;
  q.linf_stretch = (norm > 0.) ? max_G * norm : inf;
}

// The angle figures (core/angle_distortion.h), and each face's for the visitor.
template <class TriangleMesh, class FaceVisitor>
void angle_figures(const Measured_faces<TriangleMesh>& m, Parameterization_quality& q, const FaceVisitor& visit)
{
  const double inf = std::numeric_limits<double>::infinity();
  double paper = 0., per_corner = 0.;
  for(std::size_t i = 0; i < m.figures.size(); ++i)
  {
    const Face_figures& f = m.figures[i];
    Face_quality fq;
    fq.uv_area = f.uv_area;
    fq.quasi_conformal = (f.has_jacobian && f.s2 > 0.) ? f.s1 / f.s2 : inf;
    for(int c = 0; c < 3; ++c)
    {
      const double error = corner_angle_error(f.alpha[std::size_t(c)], m.optimal_angle(f, c));
      paper += error;
      fq.angle_distortion += error / 3.;
      per_corner += corner_angle_error(f.alpha[std::size_t(c)], f.beta[std::size_t(c)]);
    }
    visit(m.faces[i], fq);
  }
  q.angle_distortion = paper / double(q.number_of_vertices);
  q.angle_distortion_per_corner = per_corner / double(3 * q.number_of_faces);
}

template <class TriangleMesh, class FaceRange, class VertexUVMap, class NamedParameters, class FaceVisitor>
Parameterization_quality measure_quality(const TriangleMesh& tm, const FaceRange& face_range, VertexUVMap uvmap,
                                         const NamedParameters& np, const FaceVisitor& visit)
{
  const auto vpm = parameters::choose_parameter(parameters::get_parameter(np, internal_np::vertex_point),
                                                get_const_property_map(vertex_point, tm));
  const Measured_faces<TriangleMesh> measured(tm, face_range, vpm, uvmap);
  Parameterization_quality q;
  q.number_of_faces = measured.figures.size();
  q.number_of_vertices = measured.number_of_vertices();
  if(q.number_of_faces == 0)
    return q;
  stretch_figures(measured, q);
  area_distortion(measured, q);
  angle_figures(measured, q, visit);
  return q;
}

} // namespace internal

/// \ingroup PkgSurfaceMeshParameterizationMeasured
///
/// measures the map given by `uvmap` on the faces of `face_range` (triangles), for example
/// `faces(tm)`.
/// A vertex is *interior* when `CGAL::is_border(v, tm)` is empty.
///
/// \tparam FaceRange a range of `face_descriptor`.
/// \tparam VertexUVMap a model of `ReadablePropertyMap` from `vertex_descriptor` to a 2D
///         point type with `x()` and `y()`.
/// \param tm the triangle mesh.
/// \param face_range the faces measured.
/// \param uvmap the UV of every vertex of these faces.
/// \param np optional named parameter `vertex_point_map`.
template <class TriangleMesh, class FaceRange, class VertexUVMap,
          class NamedParameters = parameters::Default_named_parameters>
Parameterization_quality measure_quality(const TriangleMesh& tm,
                                         const FaceRange& face_range,
                                         VertexUVMap uvmap,
                                         const NamedParameters& np = parameters::default_values())
{
  return internal::measure_quality(tm, face_range, uvmap, np, internal::No_face_visitor());
}

/// \ingroup PkgSurfaceMeshParameterizationMeasured
///
/// as `measure_quality()`, and also writes the figures of every face of `face_range` into
/// `face_figures` (for example to color a picture of the UV layout).
///
/// \tparam FaceQualityMap a model of `WritablePropertyMap` with `face_descriptor` as key and
///         `Face_quality` as value.
template <class TriangleMesh, class FaceRange, class VertexUVMap, class FaceQualityMap,
          class NamedParameters = parameters::Default_named_parameters>
Parameterization_quality measure_quality_per_face(const TriangleMesh& tm,
                                                  const FaceRange& face_range,
                                                  VertexUVMap uvmap,
                                                  FaceQualityMap face_figures,
                                                  const NamedParameters& np = parameters::default_values())
{
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  return internal::measure_quality(tm, face_range, uvmap, np,
                                   [&](face_descriptor f, const Face_quality& fq) { put(face_figures, f, fq); });
}


/// \ingroup PkgSurfaceMeshParameterizationMeasured
///
/// the global overlap test: whether the map given by `uvmap` on the faces of `face_range` is
/// one-to-one, i.e. every UV triangle is counterclockwise (none flipped or degenerate) and no
/// two UV triangles overlap (which a map without flipped triangles can still do when it winds
/// over itself). Pairs of triangles whose bounding boxes intersect (CGAL's
/// `box_self_intersection_d()`) are tested with exact predicates, \f$ O(F \log F) \f$
/// typically. The same test as the `is_one_to_one_mapping()` member functions of CGAL's
/// parameterizers, for any face range and any 2D point type of `uvmap`.
template <class TriangleMesh, class FaceRange, class VertexUVMap>
bool is_one_to_one_uv_map(const TriangleMesh& tm, const FaceRange& face_range, VertexUVMap uvmap)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor   vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor     face_descriptor;
  typedef internal::Validity_kernel                                         EK;

  internal::Mesh_indexer<TriangleMesh> ids(tm);
  std::vector<std::array<std::size_t, 3> > triangle_vertices;
  std::vector<std::array<EK::Point_2, 3> > corners;
  for(face_descriptor f : face_range)
  {
    std::array<std::size_t, 3> vs;
    std::array<EK::Point_2, 3> q;
    std::size_t k = 0;
    for(halfedge_descriptor h : halfedges_around_face(halfedge(f, tm), tm))
    {
      if(k == 3)
        return false;  // not a triangle
      const vertex_descriptor v = target(h, tm);
      vs[k] = static_cast<std::size_t>(ids.add(v));
      const auto& p = get(uvmap, v);
      q[k++] = EK::Point_2(CGAL::to_double(p.x()), CGAL::to_double(p.y()));
    }
    if(k != 3 || CGAL::orientation(q[0], q[1], q[2]) != CGAL::LEFT_TURN)
      return false;
    triangle_vertices.push_back(vs);
    corners.push_back(q);
  }
  return !internal::any_uv_triangles_overlap(triangle_vertices, corners);
}

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_MEASURE_QUALITY_H
