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

inline double corner_angle_3(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

inline double corner_angle_2(const Eigen::Vector2d& a, const Eigen::Vector2d& b)
{
  return std::atan2(std::abs(a.x() * b.y() - a.y() * b.x()), a.dot(b));
}

// Per vertex: the sum of its 3D corner angles beta, and of d = alpha / beta - 1 and d^2 over
// its corners (count: those with beta > 0), so that the paper's angle error
// sum ((alpha - phi) / phi)^2, with phi = c beta (c = 2 pi / sum beta at interior vertices,
// 1 at border vertices), is [sum d^2 - 2 (c - 1) sum d + count (c - 1)^2] / c^2, known once
// every corner was seen. (Centered at 1: no cancellation for nearly flat, nearly conformal
// maps, whose error is then exact to rounding.)
struct Vertex_angles
{
  double beta = 0., d = 0., d2 = 0.;
  int corners = 0, count = 0;
  bool border = false;
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

template <class TriangleMesh, class FaceRange, class VertexUVMap, class NamedParameters, class FaceVisitor>
Parameterization_quality measure_quality(const TriangleMesh& tm,
                                         const FaceRange& face_range,
                                         VertexUVMap uvmap,
                                         const NamedParameters& np,
                                         const FaceVisitor& visit)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor   vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor     face_descriptor;
  constexpr bool per_face = !std::is_same<FaceVisitor, No_face_visitor>::value;

  const auto vpm = parameters::choose_parameter(parameters::get_parameter(np, internal_np::vertex_point),
                                                get_const_property_map(vertex_point, tm));
  const double inf = std::numeric_limits<double>::infinity();
  auto angles = get(CGAL::dynamic_vertex_property_t<Vertex_angles>(), tm);
  for(face_descriptor f : face_range)
    for(halfedge_descriptor h : halfedges_around_face(halfedge(f, tm), tm))
      put(angles, target(h, tm), Vertex_angles());

  // What the per-face figures still need once the faces are seen: the 3D area and the log of
  // the area ratio (for the global area normalization), and, with a face visitor, the face,
  // its vertices and r of each corner.
  struct Face_record
  {
    double area, log_ratio;
  };
  struct Visited_face
  {
    face_descriptor f;
    std::array<vertex_descriptor, 3> v;
    std::array<double, 3> r;
    Face_quality fq;
  };
  std::vector<Face_record> records;
  std::vector<Visited_face> visited;

  // The one pass over the faces. Positions and UVs are divided by powers of two (exact) that
  // bring the first face's largest coordinates into [1, 2): the figures are invariant under
  // scaling, and squared lengths neither underflow nor overflow at extreme scales.
  bool scaled = false;
  int exponent3 = 0, exponent2 = 0;
  Parameterization_quality q;
  double area3 = 0., area_uv = 0., angle_sum_corner = 0., qc_sum = 0., l2_sum = 0., max_G = 0.;
  for(face_descriptor f : face_range)
  {
    std::array<vertex_descriptor, 3> v;
    v.fill(boost::graph_traits<TriangleMesh>::null_vertex());
    std::array<Eigen::Vector3d, 3> p;
    p.fill(Eigen::Vector3d::Zero());
    std::array<Eigen::Vector2d, 3> uv;
    uv.fill(Eigen::Vector2d::Zero());
    int k = 0;
    for(halfedge_descriptor h : halfedges_around_face(halfedge(f, tm), tm))
    {
      if(k == 3)
        break;
      v[k] = target(h, tm);
      const auto& x = get(vpm, v[k]);
      p[k] = Eigen::Vector3d(CGAL::to_double(x.x()), CGAL::to_double(x.y()), CGAL::to_double(x.z()));
      const auto& y = get(uvmap, v[k]);
      uv[k] = Eigen::Vector2d(CGAL::to_double(y.x()), CGAL::to_double(y.y()));
      if(is_border(opposite(h, tm), tm))  // the edge into v[k] is on a border
        for(vertex_descriptor b : {v[k], source(h, tm)})
        {
          Vertex_angles a = get(angles, b);
          a.border = true;
          put(angles, b, a);
        }
      ++k;
    }
    if(!scaled)
    {
      exponent3 = largest_exponent(p);
      exponent2 = largest_exponent(uv);
      scaled = true;
    }
    for(int c = 0; c < 3; ++c)
    {
      p[c] = Eigen::Vector3d(std::ldexp(p[c].x(), -exponent3), std::ldexp(p[c].y(), -exponent3),
                             std::ldexp(p[c].z(), -exponent3));
      uv[c] = Eigen::Vector2d(std::ldexp(uv[c].x(), -exponent2), std::ldexp(uv[c].y(), -exponent2));
    }
    ++q.number_of_faces;
    Visited_face vf;
    vf.f = f;
    vf.v = v;
    for(int c = 0; c < 3; ++c)
    {
      const double beta = corner_angle_3(p[(c + 1) % 3] - p[c], p[(c + 2) % 3] - p[c]);
      const double alpha = corner_angle_2(uv[(c + 1) % 3] - uv[c], uv[(c + 2) % 3] - uv[c]);
      Vertex_angles a = get(angles, v[c]);
      if(a.corners++ == 0)
        ++q.number_of_vertices;
      a.beta += beta;
      vf.r[c] = (beta > 0.) ? alpha / beta : 0.;
      if(beta > 0.)
      {
        const double d = vf.r[c] - 1.;
        a.d += d;
        a.d2 += d * d;
        ++a.count;
        angle_sum_corner += d * d;
      }
      put(angles, v[c], a);
    }
    const Eigen::Vector3d e = p[1] - p[0], g = p[2] - p[0];
    const double la = e.norm(), A3 = 0.5 * e.cross(g).norm();
    const Eigen::Vector2d e1 = uv[1] - uv[0], e2 = uv[2] - uv[0];
    const double signed_uv = 0.5 * (e1.x() * e2.y() - e1.y() * e2.x());
    area3 += A3;
    area_uv += std::abs(signed_uv);
    if(!(signed_uv > 0.))
      ++q.flipped_faces;
    vf.fq.uv_area = signed_uv;
    vf.fq.quasi_conformal = inf;
    if(A3 > 0. && la > 0.)  // otherwise a degenerate 3D face: no Jacobian, no weight
    {
      // Jacobian of 3D -> UV in an orthonormal frame of the 3D triangle: J = Q P^-1 with
      // P = [[la, bx], [0, by]]; its singular values without cancellation near s1 = s2:
      // s1,2 = (|(j00 + j11, j10 - j01)| +- |(j00 - j11, j10 + j01)|) / 2
      const double bx = e.dot(g) / la, by = 2. * A3 / la;
      const double j00 = e1.x() / la, j10 = e1.y() / la;
      const double j01 = (e2.x() - j00 * bx) / by, j11 = (e2.y() - j10 * bx) / by;
      const double pp = std::hypot(j00 + j11, j10 - j01), rr = std::hypot(j00 - j11, j10 + j01);
      const double s1 = 0.5 * (pp + rr), s2 = 0.5 * std::abs(pp - rr);
      const double qc = (s2 > 0.) ? s1 / s2 : inf;
      const double G = (s2 > 0.) ? 1. / s2 : inf, gg = (s1 > 0.) ? 1. / s1 : inf;
      vf.fq.quasi_conformal = qc;
      qc_sum += A3 * qc;
      q.quasi_conformal_max = (std::max)(q.quasi_conformal_max, qc);
      l2_sum += A3 * 0.5 * (G * G + gg * gg);
      max_G = (std::max)(max_G, G);
      records.push_back({A3, (signed_uv != 0.) ? std::log(std::abs(signed_uv) / A3) : -inf});
    }
    if constexpr(per_face)
      visited.push_back(vf);
  }
  if(q.number_of_faces == 0)
    return q;

  // The angle error, per vertex.
  auto scale_of = [](const Vertex_angles& a) {  // c: optimal angle = c * 3D angle
    return (!a.border && a.beta > 0.) ? 2. * CGAL_PI / a.beta : 1.;
  };
  double angle_sum_paper = 0.;
  for(vertex_descriptor vd : vertices(tm))
  {
    const Vertex_angles& a = get(angles, vd);
    if(a.corners == 0)
      continue;
    const double c = scale_of(a), s = c - 1.;
    angle_sum_paper += (std::max)(0., (a.d2 - 2. * s * a.d + double(a.count) * s * s) / (c * c));
  }
  // The area distortion, after scaling the UV areas to the 3D total.
  const double log_scale = (area_uv > 0.) ? std::log(area3 / area_uv) : inf;
  double area_log_sum = 0.;
  for(const Face_record& r : records)
  {
    const double d = std::abs(r.log_ratio + log_scale);
    area_log_sum += r.area * d;
    q.area_distortion_max = (std::max)(q.area_distortion_max, d);
  }
  if constexpr(per_face)
    for(Visited_face& vf : visited)
    {
      for(int c = 0; c < 3; ++c)
      {
        const double x = vf.r[c] / scale_of(get(angles, vf.v[c])) - 1.;
        vf.fq.angle_distortion += (vf.r[c] > 0. ? x * x : 0.) / 3.;
      }
      visit(vf.f, vf.fq);
    }

  q.angle_distortion = angle_sum_paper / double(q.number_of_vertices);
  q.angle_distortion_per_corner = angle_sum_corner / double(3 * q.number_of_faces);
  if(area3 > 0.)
  {
    const double norm = (area_uv > 0.) ? std::sqrt(area_uv / area3) : 0.;
    q.quasi_conformal_mean = qc_sum / area3;
    q.l2_stretch = (norm > 0.) ? std::sqrt(l2_sum / area3) * norm : inf;
    q.linf_stretch = (norm > 0.) ? max_G * norm : inf;
    q.area_distortion_mean = area_log_sum / area3;
  }
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


namespace internal {

// The UV triangles of the faces of a range, with exact predicates, for the overlap test.
struct Uv_triangles
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel EK;
  typedef CGAL::Box_intersection_d::Box_with_info_d<double, 2, std::size_t,
                                                    CGAL::Box_intersection_d::ID_FROM_BOX_ADDRESS> Box;
  std::vector<std::array<std::size_t, 3> > vertices;  // vertex ids (index into the range)
  std::vector<std::array<EK::Point_2, 3> > corners;

  // whether the interiors of the UV triangles i and j overlap (or touch beyond the vertices
  // and edge they share in the mesh); both are counterclockwise
  bool overlap(std::size_t i, std::size_t j) const
  {
    const std::array<std::size_t, 3>& a = vertices[i];
    const std::array<std::size_t, 3>& b = vertices[j];
    int shared = 0, ka = 0, kb = 0;
    for(int k = 0; k < 3; ++k)
      for(int l = 0; l < 3; ++l)
        if(a[std::size_t(k)] == b[std::size_t(l)])
        {
          ++shared;
          ka = k;
          kb = l;
        }
    const std::array<EK::Point_2, 3>& p = corners[i];
    const std::array<EK::Point_2, 3>& q = corners[j];
    if(shared >= 2)
    {
      // a shared edge: the two third vertices must lie on opposite sides of it
      int ia = 0, ib = 0;
      for(int k = 0; k < 3; ++k)
      {
        if(std::find(b.begin(), b.end(), a[std::size_t(k)]) == b.end())
          ia = k;
        if(std::find(a.begin(), a.end(), b[std::size_t(k)]) == a.end())
          ib = k;
      }
      const EK::Point_2& e0 = p[std::size_t((ia + 1) % 3)];
      const EK::Point_2& e1 = p[std::size_t((ia + 2) % 3)];
      return shared > 2 || CGAL::orientation(e0, e1, p[std::size_t(ia)]) ==
                             CGAL::orientation(e0, e1, q[std::size_t(ib)]);
    }
    if(shared == 1)
    {
      // a shared vertex: the interiors overlap near it iff the edge opposite to it in one
      // triangle meets the other triangle
      const EK::Segment_2 sa(p[std::size_t((ka + 1) % 3)], p[std::size_t((ka + 2) % 3)]);
      const EK::Segment_2 sb(q[std::size_t((kb + 1) % 3)], q[std::size_t((kb + 2) % 3)]);
      return CGAL::do_intersect(EK::Triangle_2(p[0], p[1], p[2]), sb) ||
             CGAL::do_intersect(EK::Triangle_2(q[0], q[1], q[2]), sa);
    }
    return CGAL::do_intersect(EK::Triangle_2(p[0], p[1], p[2]), EK::Triangle_2(q[0], q[1], q[2]));
  }
};

} // namespace internal

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
  typedef internal::Uv_triangles::EK                                       EK;
  typedef internal::Uv_triangles::Box                                      Box;

  typedef typename boost::property_map<TriangleMesh, CGAL::dynamic_vertex_property_t<std::size_t> >::const_type
    Vertex_ids;
  const Vertex_ids ids = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
  const std::size_t unset = (std::numeric_limits<std::size_t>::max)();
  for(face_descriptor f : face_range)
    for(vertex_descriptor v : vertices_around_face(halfedge(f, tm), tm))
      put(ids, v, unset);

  internal::Uv_triangles triangles;
  std::vector<Box> boxes;
  std::size_t next_id = 0;
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
      if(get(ids, v) == unset)
        put(ids, v, next_id++);
      vs[k] = get(ids, v);
      const auto& p = get(uvmap, v);
      q[k++] = EK::Point_2(CGAL::to_double(p.x()), CGAL::to_double(p.y()));
    }
    if(k != 3 || CGAL::orientation(q[0], q[1], q[2]) != CGAL::LEFT_TURN)
      return false;
    boxes.emplace_back(q[0].bbox() + q[1].bbox() + q[2].bbox(), triangles.corners.size());
    triangles.vertices.push_back(vs);
    triangles.corners.push_back(q);
  }
  // pointers: the boxes' ids are their addresses, which the algorithm's copies keep
  std::vector<const Box*> box_pointers;
  box_pointers.reserve(boxes.size());
  for(const Box& b : boxes)
    box_pointers.push_back(&b);
  bool overlap = false;
  CGAL::box_self_intersection_d(box_pointers.begin(), box_pointers.end(), [&](const Box* a, const Box* b) {
    if(!overlap && triangles.overlap(a->info(), b->info()))
      overlap = true;
  });
  return !overlap;
}

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_MEASURE_QUALITY_H
