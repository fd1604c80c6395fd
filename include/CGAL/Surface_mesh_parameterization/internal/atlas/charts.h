// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_ATLAS_CHARTS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_ATLAS_CHARTS_H

// The charts of an atlas on an indexed triangle set (the repaired mesh): a chart is a set of
// faces with a UV for each face corner. What is decided here needs no parameterizer: the
// face sets (components, and their split into parts when a chart is not one-to-one), the
// isometric unfolding of a small chart along a spanning tree of its faces, the validity of a
// chart (no flipped triangle, no two overlapping triangles) and its distortion figures.

#include <CGAL/Surface_mesh_parameterization/Atlas_report.h>

#include <CGAL/Surface_mesh_parameterization/internal/atlas/min_area_rectangle.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/angle_distortion.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/area_spread.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/triangle_adjacency.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/triangle_geometry.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/validity.h>

#include <boost/sort/spreadsort/integer_sort.hpp>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// An indexed triangle set: the repaired mesh as the atlas sees it.
struct Atlas_triangles
{
  std::vector<Eigen::Vector3d> points;
  std::vector<Face_indices> faces;
  std::vector<std::size_t> face_polygon;  // the input polygon of each face (empty: the face itself)

  std::size_t polygon(std::size_t f) const { return face_polygon.empty() ? f : face_polygon[f]; }
};

// Whether faces f and g (of the triangle set) triangulate one input polygon.
inline bool same_polygon(const Atlas_triangles& t, std::size_t f, std::size_t g)
{
  return t.polygon(f) == t.polygon(g);
}

// A chart: faces of the triangle set and the UV of each face corner (corner k of a face is
// its vertex faces[f][k]).
struct Atlas_chart
{
  std::vector<std::size_t> faces;
  std::vector<std::array<Eigen::Vector2d, 3> > corners;
  Chart_flattening flattening = DISK_CHART;
  double angle_distortion = 0.;  // the paper's, over the chart cut open along its seams
  bool angle_known = false;      // angle_distortion is computed for these UVs
  double area_spread = 0.;       // area-weighted mean |log(UV area / 3D area)| after one scale
  double compactness = 0.;       // UV area over the square of its smallest box's longer side
  double length = 0.;            // that side at the 3D scale (UV area scaled to the 3D area)
  double area_3d = 0., area_uv = 0.;
  Min_area_rectangle box;        // its smallest bounding rectangle (chart_compactness())
};

// The faces of `faces` (a subset of the triangle set) with the faces of the subset across each
// edge, in local indices; -1 on a border of the subset.
inline std::vector<std::array<int, 3> > subset_neighbors(const Atlas_triangles& t, const std::vector<std::size_t>& faces)
{
  std::vector<Face_indices> local(faces.size());
  for(std::size_t i = 0; i < faces.size(); ++i)
    local[i] = t.faces[faces[i]];
  const Triangle_adjacency adjacency(t.points.size(), local);
  std::vector<std::array<int, 3> > neighbors(faces.size());
  for(std::size_t i = 0; i < faces.size(); ++i)
    for(int k = 0; k < 3; ++k)
      neighbors[i][std::size_t(k)] = adjacency.neighbor(i, k);
  return neighbors;
}

// The connected components of a face subset (through shared edges), each as face indices.
inline std::vector<std::vector<std::size_t> > edge_components(const Atlas_triangles& t, const std::vector<std::size_t>& faces)
{
  const std::vector<std::array<int, 3> > neighbors = subset_neighbors(t, faces);
  std::vector<int> component(faces.size(), -1);
  std::vector<std::vector<std::size_t> > result;
  for(std::size_t seed = 0; seed < faces.size(); ++seed)
  {
    if(component[seed] >= 0)
      continue;
    result.emplace_back();
    std::vector<std::size_t> stack(1, seed);
    component[seed] = int(result.size() - 1);
    while(!stack.empty())
    {
      const std::size_t f = stack.back();
      stack.pop_back();
      result.back().push_back(faces[f]);
      for(int g : neighbors[f])
        if(g >= 0 && component[std::size_t(g)] < 0)
        {
          component[std::size_t(g)] = component[seed];
          stack.push_back(std::size_t(g));
        }
    }
  }
  return result;
}

// The vertices of a face subset as a manifold surface sees them: one local id per fan of
// faces around a vertex (corners of one vertex in two faces that share an edge through it are
// the same local vertex), so that a vertex pinched in the subset becomes several. Returns the
// local id of each face corner; `vertex_of` gets the vertex of each local id.
inline std::vector<std::array<int, 3> > fan_vertex_ids(const Atlas_triangles& t, const std::vector<std::size_t>& faces,
                                                      const std::vector<std::array<int, 3> >& neighbors,
                                                      std::vector<int>& vertex_of)
{
  std::vector<std::array<int, 3> > ids(faces.size(), {{-1, -1, -1}});
  vertex_of.clear();
  for(std::size_t f = 0; f < faces.size(); ++f)
    for(int k = 0; k < 3; ++k)
    {
      if(ids[f][std::size_t(k)] >= 0)
        continue;
      const int v = t.faces[faces[f]][std::size_t(k)], id = int(vertex_of.size());
      vertex_of.push_back(v);
      std::vector<std::pair<std::size_t, int> > stack(1, {f, k});  // corners of v in this fan
      ids[f][std::size_t(k)] = id;
      while(!stack.empty())
      {
        const std::pair<std::size_t, int> c = stack.back();
        stack.pop_back();
        for(int e : {(c.second + 1) % 3, (c.second + 2) % 3})  // the two edges through the corner
        {
          const int g = neighbors[c.first][std::size_t(e)];
          if(g < 0)
            continue;
          const Face_indices& vg = t.faces[faces[std::size_t(g)]];
          const int kg = int(std::find(vg.begin(), vg.end(), v) - vg.begin());
          if(kg < 3 && ids[std::size_t(g)][std::size_t(kg)] < 0)
          {
            ids[std::size_t(g)][std::size_t(kg)] = id;
            stack.emplace_back(std::size_t(g), kg);
          }
        }
      }
    }
  return ids;
}

// The part of each face of a subset: the part `side` gives to the first face of its input
// polygon, so that no input polygon is split; when that leaves every face in one part, the
// polygon of the last face goes to another (or the last face alone, when the subset is one
// polygon).
inline std::vector<int> parts_keeping_polygons(const Atlas_triangles& t, const std::vector<std::size_t>& faces,
                                               const std::vector<int>& side)
{
  std::vector<std::pair<std::size_t, std::size_t> > order(faces.size());  // (polygon, face), sorted
  for(std::size_t i = 0; i < faces.size(); ++i)
    order[i] = {t.polygon(faces[i]), i};
  std::sort(order.begin(), order.end());
  std::vector<int> part(faces.size());
  std::size_t polygons = 0;
  for(std::size_t a = 0, b = 0; a < order.size(); a = b, ++polygons)
    for(b = a; b < order.size() && order[b].first == order[a].first; ++b)
      part[order[b].second] = side[order[a].second];  // the side of the polygon's first face
  if(faces.size() > 1 && std::all_of(part.begin(), part.end(), [&](int p) { return p == part[0]; }))
  {
    const bool one_polygon = polygons == 1;
    for(std::size_t i = 0; i < faces.size(); ++i)
      if(one_polygon ? i + 1 == faces.size() : same_polygon(t, faces[i], faces.back()))
        part[i] = part[i] == 0 ? 1 : 0;
  }
  return part;
}

// The UV triangle of a 3D triangle with its edge (p0, p1) along +u: an isometry.
inline std::array<Eigen::Vector2d, 3> isometric_triangle(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                                                         const Eigen::Vector3d& p2)
{
  const Eigen::Vector3d e = p1 - p0, g = p2 - p0;
  const double l = e.norm();
  const double x = (l > 0.) ? e.dot(g) / l : 0.;
  const double y = (l > 0.) ? e.cross(g).norm() / l : 0.;
  return {{Eigen::Vector2d(0., 0.), Eigen::Vector2d(l, 0.), Eigen::Vector2d(x, y)}};
}

// Places corner `k` of a triangle with corners k+1, k+2 known in UV: the 3D triangle moved
// by the similarity (a rotation and translation, of scale 1 when the UV edge keeps its 3D
// length) that takes its edge (k+1, k+2) onto the UV edge, on the left of it.
inline Eigen::Vector2d place_third_corner(const std::array<Eigen::Vector3d, 3>& p, int k, const Eigen::Vector2d& a,
                                          const Eigen::Vector2d& b)
{
  const std::size_t i = std::size_t((k + 1) % 3), j = std::size_t((k + 2) % 3);
  const std::array<Eigen::Vector2d, 3> flat = isometric_triangle(p[i], p[j], p[std::size_t(k)]);
  const Eigen::Vector2d d = b - a;
  const double l = d.norm();
  if(!(l > 0.) || !(flat[1].x() > 0.))
    return a;
  const Eigen::Vector2d u = d / l, v(-u.y(), u.x());
  return a + (flat[2].x() * u + flat[2].y() * v) * (l / flat[1].x());
}

// Face g laid out across the edge opposite corner k of the placed face f.
inline void unfold_across(const Atlas_triangles& t, const std::vector<std::size_t>& faces, std::size_t f, int k,
                          std::size_t g, const std::array<Eigen::Vector3d, 3>& pg, Atlas_chart& chart)
{
  const Face_indices& vf = t.faces[faces[f]];
  const Face_indices& vg = t.faces[faces[g]];
  const int a = vf[std::size_t((k + 1) % 3)], b = vf[std::size_t((k + 2) % 3)];
  int kg = 0;  // the corner of g off the shared edge
  while(vg[std::size_t(kg)] == a || vg[std::size_t(kg)] == b)
    ++kg;
  // g holds the edge as (b, a): its corners kg+1 and kg+2 are b and a
  const Eigen::Vector2d& ua = chart.corners[f][std::size_t((k + 1) % 3)];
  const Eigen::Vector2d& ub = chart.corners[f][std::size_t((k + 2) % 3)];
  chart.corners[g][std::size_t((kg + 1) % 3)] = ub;
  chart.corners[g][std::size_t((kg + 2) % 3)] = ua;
  chart.corners[g][std::size_t(kg)] = place_third_corner(pg, kg, ub, ua);
}

// The corners of a chart (3 i + k: corner k of face i) in the order of their vertices in `t`,
// the corners of one vertex in increasing order: the sorted (vertex, corner) keys, sorted by
// Boost's integer_sort (a radix-based hybrid), where std::sort took a few percent of the
// atlas's time (two sorts per chart flattened: the weld and the UV vertices).
inline std::vector<std::uint32_t> corners_by_vertex(const Atlas_triangles& t, const Atlas_chart& chart)
{
  const std::size_t n = 3 * chart.faces.size();
  std::vector<std::uint64_t> keys(n);  // (vertex, corner)
  for(std::size_t c = 0; c < n; ++c)
    keys[c] = (std::uint64_t(std::uint32_t(t.faces[chart.faces[c / 3]][c % 3])) << 32) | std::uint64_t(c);
  boost::sort::spreadsort::integer_sort(keys.begin(), keys.end());
  std::vector<std::uint32_t> corners(n);
  for(std::size_t i = 0; i < n; ++i)
    corners[i] = std::uint32_t(keys[i] & 0xffffffffu);
  return corners;
}

// Corners of one vertex whose UVs differ by rounding only (a vertex reached along two paths
// of an unfolding's spanning tree, a vertex pinched in the chart whose two copies the map puts
// at one place) are given one UV, the first: two faces that meet there in 3D then meet exactly
// in UV, instead of overlapping by a sliver one rounding wide once the packing has moved them.
// Returns whether a UV moved.
inline bool weld_rounded_corners(const Atlas_triangles& t, Atlas_chart& chart)
{
  Eigen::AlignedBox2d box;
  for(const std::array<Eigen::Vector2d, 3>& c : chart.corners)
    box.extend(c[0]).extend(c[1]).extend(c[2]);
  const double tolerance = 1e-9 * box.diagonal().norm();
  const std::vector<std::uint32_t> corners = corners_by_vertex(t, chart);
  auto uv = [&chart](std::size_t c) -> Eigen::Vector2d& { return chart.corners[c / 3][c % 3]; };
  auto vertex = [&](std::size_t c) { return t.faces[chart.faces[c / 3]][c % 3]; };
  bool moved = false;
  for(std::size_t first = 0; first < corners.size();)
  {
    std::size_t end = first;
    while(end < corners.size() && vertex(corners[end]) == vertex(corners[first]))
      ++end;
    for(std::size_t a = first; a < end; ++a)
      for(std::size_t b = first; b < a; ++b)
        if((uv(corners[a]) - uv(corners[b])).norm() <= tolerance)
        {
          moved = moved || uv(corners[a]) != uv(corners[b]);
          uv(corners[a]) = uv(corners[b]);
          break;
        }
    first = end;
  }
  return moved;
}

// The isometric unfolding of a face subset along a breadth-first spanning tree of its faces:
// each face is laid out across the edge it shares with its parent. Consistent (every vertex
// placed once per face) and exact in angles and lengths; it may overlap itself, which the
// caller checks.
inline Atlas_chart unfold_isometrically(const Atlas_triangles& t, const std::vector<std::size_t>& faces)
{
  const std::vector<std::array<int, 3> > neighbors = subset_neighbors(t, faces);
  Atlas_chart chart;
  chart.flattening = UNFOLDED_CHART;
  chart.faces = faces;
  chart.corners.resize(faces.size());
  std::vector<bool> placed(faces.size(), false);
  auto points = [&](std::size_t f) {
    const Face_indices& v = t.faces[faces[f]];
    return std::array<Eigen::Vector3d, 3>{{t.points[std::size_t(v[0])], t.points[std::size_t(v[1])], t.points[std::size_t(v[2])]}};
  };
  for(std::size_t seed = 0; seed < faces.size(); ++seed)
  {
    if(placed[seed])
      continue;
    const std::array<Eigen::Vector3d, 3> p = points(seed);
    chart.corners[seed] = isometric_triangle(p[0], p[1], p[2]);
    placed[seed] = true;
    std::vector<std::size_t> queue(1, seed);
    for(std::size_t q = 0; q < queue.size(); ++q)
      for(int k = 0; k < 3; ++k)
      {
        const int g = neighbors[queue[q]][std::size_t(k)];
        if(g < 0 || placed[std::size_t(g)])
          continue;
        unfold_across(t, faces, queue[q], k, std::size_t(g), points(std::size_t(g)), chart);
        placed[std::size_t(g)] = true;
        queue.push_back(std::size_t(g));
      }
  }
  weld_rounded_corners(t, chart);
  return chart;
}

// The UV vertex of each corner of a chart (3 i + k: corner k of face i), numbered in the order
// of first appearance: two corners are one UV vertex when they have the same vertex and the
// same UV. Returns their number. The corners are sorted by vertex (corners_by_vertex()), then
// the corners of each vertex compared pairwise (quadratic in a vertex's corners in the chart: a
// million comparisons for a fan of a thousand triangles), where a map keyed by (vertex, UV),
// one node per corner, took about a tenth of the atlas's time on large meshes.
inline std::size_t number_uv_vertices(const Atlas_triangles& t, const Atlas_chart& chart, std::vector<std::size_t>& id)
{
  const std::size_t n = 3 * chart.faces.size();
  const std::vector<std::uint32_t> keys = corners_by_vertex(t, chart);
  auto uv = [&](std::size_t c) -> const Eigen::Vector2d& { return chart.corners[c / 3][c % 3]; };
  auto vertex = [&](std::size_t c) { return t.faces[chart.faces[c / 3]][c % 3]; };
  std::vector<std::size_t> first(n);  // the first corner of each corner's UV vertex
  for(std::size_t a = 0, b = 0; a < n; a = b)
  {
    for(b = a + 1; b < n && vertex(keys[b]) == vertex(keys[a]); ++b) {}
    for(std::size_t i = a; i < b; ++i)  // the corners of one vertex, in corner order
    {
      std::size_t j = a;
      while(j < i && uv(keys[j]) != uv(keys[i]))
        ++j;
      first[keys[i]] = (j < i) ? first[keys[j]] : keys[i];
    }
  }
  id.resize(n);
  std::size_t count = 0;
  for(std::size_t c = 0; c < n; ++c)
    id[c] = (first[c] == c) ? count++ : id[first[c]];
  return count;
}

// The UV vertices of a chart (number_uv_vertices()): `vertices` gets each face's, `uv` each
// UV vertex's UV.
inline void chart_uv_vertices(const Atlas_triangles& t, const Atlas_chart& chart,
                              std::vector<std::array<std::size_t, 3> >& vertices, std::vector<Eigen::Vector2d>& uv)
{
  std::vector<std::size_t> id;
  uv.resize(number_uv_vertices(t, chart, id));
  vertices.resize(chart.faces.size());
  for(std::size_t c = 0; c < id.size(); ++c)
  {
    vertices[c / 3][c % 3] = id[c];
    uv[id[c]] = chart.corners[c / 3][c % 3];
  }
}

// The clearance of a chart's border, relative to the diagonal of its UV bounding box: far
// above the rounding of the packing's rotation and scale (about 1e-13 of a chart of a
// thousandth of the atlas), far below any gap a map means.
constexpr double chart_clearance = 1e-10;

// Whether the border of a one-to-one chart (its edges used by one face) keeps the clearance
// from itself (segments_within_clearance()). Two triangles of a one-to-one map that come near
// each other away from their shared vertices bring the border near itself there (a T-junction
// of a CAD mesh unfolds to a border vertex on a border edge), which the packing's rotation
// and scale could round into an overlap.
inline bool chart_border_is_clear(const std::vector<std::array<std::size_t, 3> >& vertices,
                                  const std::vector<Eigen::Vector2d>& uv)
{
  std::vector<std::pair<std::size_t, std::size_t> > edges;  // each face's UV edges, sorted
  edges.reserve(3 * vertices.size());
  for(const std::array<std::size_t, 3>& v : vertices)
    for(std::size_t k = 0; k < 3; ++k)
      edges.push_back(std::minmax(v[k], v[(k + 1) % 3]));
  std::sort(edges.begin(), edges.end());
  std::vector<std::array<int, 2> > border;
  Eigen::AlignedBox2d box;
  for(std::size_t a = 0, b = 0; a < edges.size(); a = b)
  {
    for(b = a + 1; b < edges.size() && edges[b] == edges[a]; ++b) {}
    if(b == a + 1)  // an edge of one face
    {
      const std::pair<std::size_t, std::size_t>& e = edges[a];
      border.push_back({{int(e.first), int(e.second)}});
      box.extend(uv[e.first]).extend(uv[e.second]);
    }
  }
  return border.empty() || !segments_within_clearance(uv, border, chart_clearance * box.diagonal().norm());
}

// Whether a parameterizer's chart, one-to-one by the parameterizer's exact check, keeps the
// clearance of its border.
inline bool chart_border_is_clear(const Atlas_triangles& t, const Atlas_chart& chart)
{
  std::vector<std::array<std::size_t, 3> > vertices;
  std::vector<Eigen::Vector2d> uv;
  chart_uv_vertices(t, chart, vertices, uv);
  return chart_border_is_clear(vertices, uv);
}

// Whether a chart is one-to-one: every UV triangle counterclockwise, no two overlapping, and
// its border clear of itself (chart_border_is_clear()).
inline bool is_one_to_one_chart(const Atlas_triangles& t, const Atlas_chart& chart)
{
  std::vector<std::array<std::size_t, 3> > vertices;
  std::vector<Eigen::Vector2d> uv;
  chart_uv_vertices(t, chart, vertices, uv);
  std::vector<std::array<Validity_kernel::Point_2, 3> > corners(chart.faces.size());
  for(std::size_t i = 0; i < chart.faces.size(); ++i)
  {
    for(std::size_t k = 0; k < 3; ++k)
      corners[i][k] = exact_point(chart.corners[i][k]);
    if(CGAL::orientation(corners[i][0], corners[i][1], corners[i][2]) != CGAL::LEFT_TURN)
      return false;
  }
  return !any_uv_triangles_overlap(vertices, corners) && chart_border_is_clear(vertices, uv);
}

// The area spread (area_spread.h) and the areas of a chart.
inline void chart_area_figures(const Atlas_triangles& t, Atlas_chart& chart)
{
  std::vector<double> area3(chart.faces.size()), area2(chart.faces.size());
  chart.area_3d = chart.area_uv = 0.;
  for(std::size_t i = 0; i < chart.faces.size(); ++i)
  {
    const Face_indices& v = t.faces[chart.faces[i]];
    area3[i] = 0.5 * (t.points[std::size_t(v[1])] - t.points[std::size_t(v[0])])
                       .cross(t.points[std::size_t(v[2])] - t.points[std::size_t(v[0])]).norm();
    area2[i] = uv_triangle_area(chart.corners[i][0], chart.corners[i][1], chart.corners[i][2]);
    chart.area_3d += area3[i];
    chart.area_uv += area2[i];
  }
  chart.area_spread = area_spread(area3, area2);
}

// The compactness of a chart: its UV area over the square of the longer side of its smallest
// bounding rectangle (pi / 4 for a disk, 1 / n for a straight strip n times as long as wide),
// the share of the square a lone chart can fill.
inline void chart_compactness(Atlas_chart& chart)
{
  std::vector<Eigen::Vector2d> corners;
  corners.reserve(3 * chart.corners.size());
  for(const std::array<Eigen::Vector2d, 3>& c : chart.corners)
    corners.insert(corners.end(), c.begin(), c.end());
  chart.box = min_area_rectangle(corners);
  const double side = chart.box.width;
  chart.compactness = (side > 0.) ? (std::min)(chart.area_uv / (side * side), 1.) : 0.;
  chart.length = (chart.area_uv > 0.) ? side * std::sqrt(chart.area_3d / chart.area_uv) : 0.;
}

// The paper's angle distortion of a chart over the chart cut open along its seams: a vertex is
// a border vertex of the chart when one of its UV vertices lies on the chart's border.
inline void chart_angle_distortion(const Atlas_triangles& t, Atlas_chart& chart)
{
  std::vector<std::size_t> id;
  const std::size_t count = number_uv_vertices(t, chart, id);
  std::vector<Eigen::Vector3d> points(count);
  std::vector<Eigen::Vector2d> uv(count);
  std::vector<Face_indices> faces(chart.faces.size());
  for(std::size_t c = 0; c < id.size(); ++c)
  {
    faces[c / 3][c % 3] = int(id[c]);
    points[id[c]] = t.points[std::size_t(t.faces[chart.faces[c / 3]][c % 3])];
    uv[id[c]] = chart.corners[c / 3][c % 3];
  }
  const Triangle_adjacency adjacency(points.size(), faces);
  std::vector<bool> on_border(points.size(), false);
  for(std::size_t i = 0; i < faces.size(); ++i)
    for(int k = 0; k < 3; ++k)
      if(adjacency.neighbor(i, k) < 0)
        on_border[std::size_t(faces[i][std::size_t((k + 1) % 3)])] = on_border[std::size_t(faces[i][std::size_t((k + 2) % 3)])] = true;
  chart.angle_distortion = Angle_distortion(points, faces, on_border, points.size())(uv);
  chart.angle_known = true;
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_ATLAS_CHARTS_H
