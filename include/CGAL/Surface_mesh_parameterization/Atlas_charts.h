// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_ATLAS_CHARTS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_ATLAS_CHARTS_H

/// \file Atlas_charts.h
/// The charts of a texture atlas: each connected component of a repaired triangle set
/// flattened with the package's parameterizers, split where a chart is not one-to-one or
/// misses the distortion bound (`Atlas_options`).

#include <CGAL/Surface_mesh_parameterization/Conformal_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/compute_disk_seams.h>
#include <CGAL/Surface_mesh_parameterization/main_border.h>
#include <CGAL/Surface_mesh_parameterization/internal/atlas/chart_split.h>
#include <CGAL/Surface_mesh_parameterization/internal/atlas/charts.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Seam_mesh.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

typedef CGAL::Simple_cartesian<double>                        Atlas_kernel;
typedef CGAL::Surface_mesh<Atlas_kernel::Point_3>             Atlas_surface;
typedef Atlas_surface::Vertex_index                           Atlas_vertex;
typedef Atlas_surface::Face_index                             Atlas_face;

// A face subset as a Surface_mesh: vertex i is the local (fan) vertex i, face i the subset's
// face i; `corner_ids` gives the local vertex of each corner of each face. make_subset_surface()
// takes the subset's `neighbors` (subset_neighbors()), which the caller computes once per subset.
struct Subset_surface
{
  Atlas_surface mesh;
  std::vector<std::array<int, 3> > corner_ids;
  bool built = false;
};

inline Subset_surface make_subset_surface(const Atlas_triangles& t, const std::vector<std::size_t>& faces,
                                          const std::vector<std::array<int, 3> >& neighbors)
{
  Subset_surface s;
  std::vector<int> vertex_of;
  s.corner_ids = fan_vertex_ids(t, faces, neighbors, vertex_of);
  for(int v : vertex_of)
  {
    const Eigen::Vector3d& p = t.points[std::size_t(v)];
    s.mesh.add_vertex(Atlas_kernel::Point_3(p.x(), p.y(), p.z()));
  }
  s.built = true;
  for(const std::array<int, 3>& c : s.corner_ids)
    if(s.mesh.add_face(Atlas_vertex(Atlas_surface::size_type(c[0])), Atlas_vertex(Atlas_surface::size_type(c[1])),
                       Atlas_vertex(Atlas_surface::size_type(c[2]))) == Atlas_surface::null_face())
      s.built = false;  // not a manifold surface: the caller splits the subset
  return s;
}

// Whether a surface is a topological disk: one border loop and Euler characteristic 1.
inline bool is_topological_disk(const Atlas_surface& m)
{
  std::size_t loops = 0;
  auto seen = get(CGAL::dynamic_halfedge_property_t<bool>(), m);
  for(auto h : halfedges(m))
    put(seen, h, false);
  for(auto h : halfedges(m))
    if(is_border(h, m) && !get(seen, h))
    {
      ++loops;
      for(auto b : halfedges_around_face(h, m))
        put(seen, b, true);
    }
  const long chi = long(num_vertices(m)) - long(num_edges(m)) + long(num_faces(m));
  return loops == 1 && chi == 1;
}

// The corner UVs of face i of a subset from a UV map on the vertices of `graph` (the surface
// or its seam mesh); `vertex_at` gives, for halfedge h of face i, its target in `graph`.
template <class Graph, class UVmap, class FaceOf, class LocalVertex>
void corners_from_uv(const Graph& graph, const Subset_surface& s, UVmap uvmap, FaceOf face_of, LocalVertex local_vertex,
                     Atlas_chart& chart)
{
  chart.corners.resize(s.corner_ids.size());
  for(std::size_t i = 0; i < s.corner_ids.size(); ++i)
    for(auto h : halfedges_around_face(halfedge(face_of(i), graph), graph))
    {
      const std::size_t k = std::size_t(std::find(s.corner_ids[i].begin(), s.corner_ids[i].end(), local_vertex(h)) -
                                        s.corner_ids[i].begin());
      const auto& uv = get(uvmap, target(h, graph));
      if(k < 3)
        chart.corners[i][k] = Eigen::Vector2d(uv.x(), uv.y());
    }
}

// The complete parameterizer whose automatic border ranks its layouts by the charts' bound;
// a layout within it is extended holomorphically on a whole component (`whole`), not on the
// parts of a split: on the 30 meshes of the atlas benchmark the extension there changed no
// median (charts, spread, angle, utilization) and cost 5% of the time (Hand1 1.40 to 1.28 s),
// where a component kept whole gains (cylinder_locally_refined.off: 2.9 to 0.69 times Boundary
// First Flattening's angle error).
template <class Graph>
Conformal_parameterizer_3<Graph> chart_parameterizer(const Atlas_options& options, bool whole)
{
  return Conformal_parameterizer_3<Graph>(
    Automatic_border<>(Distortion_bound{options.max_angle_distortion, options.max_area_spread}, whole));
}

// The angle distortion of the layout the parameterizer kept (the paper's, over the disk or the
// surface cut open along its seams: the chart's, which measure_chart() then need not compute).
inline void keep_angle_distortion(const Parameterization_report& report, Atlas_chart& chart)
{
  chart.angle_distortion = report.border_candidates[std::size_t(report.chosen_candidate)].objective;
  chart.angle_known = true;
}

// The disk flattened by the complete parameterizer (automatic border).
inline bool flatten_disk(Subset_surface& s, const Atlas_options& options, bool whole, Atlas_chart& chart)
{
  auto uv = s.mesh.add_property_map<Atlas_vertex, Atlas_kernel::Point_2>("v:atlas_uv").first;
  const auto bhd = main_border(s.mesh).first;
  Parameterization_report report;
  if(parameterize(s.mesh, chart_parameterizer<Atlas_surface>(options, whole), bhd, uv, &report) != OK)
    return false;
  keep_angle_distortion(report, chart);
  chart.flattening = DISK_CHART;
  corners_from_uv(s.mesh, s, uv, [](std::size_t i) { return Atlas_face(Atlas_surface::size_type(i)); },
                  [&s](Atlas_surface::Halfedge_index h) { return int(target(h, s.mesh)); }, chart);
  return true;
}

// The edges inside an input polygon (between two of its triangles) of the subset `faces` of
// `t` (face i of `s` is faces[i]): the seams avoid them, so that every input polygon keeps one
// UV per corner.
inline Atlas_surface::Property_map<Atlas_surface::Edge_index, bool>
polygon_diagonals(Subset_surface& s, const Atlas_triangles& t, const std::vector<std::size_t>& faces)
{
  auto polygon = [&](Atlas_face f) { return t.polygon(faces[std::size_t(f)]); };
  auto diagonal = s.mesh.add_property_map<Atlas_surface::Edge_index, bool>("e:atlas_diagonal", false).first;
  for(auto e : edges(s.mesh))
    if(!is_border(e, s.mesh))
    {
      const auto h = halfedge(e, s.mesh);
      diagonal[e] = polygon(face(h, s.mesh)) == polygon(face(opposite(h, s.mesh), s.mesh));
    }
  return diagonal;
}

// Any other surface (the subset `faces` of `t`) cut open along automatic seams (around the
// input polygons) into a disk, then flattened.
inline bool flatten_with_seams(Subset_surface& s, const Atlas_triangles& t, const std::vector<std::size_t>& faces,
                               const Atlas_options& options, bool whole, Atlas_chart& chart)
{
  typedef Atlas_surface::Property_map<Atlas_surface::Edge_index, bool>  Seam_edges;
  typedef Atlas_surface::Property_map<Atlas_vertex, bool>               Seam_vertices;
  typedef CGAL::Seam_mesh<Atlas_surface, Seam_edges, Seam_vertices>     Seam_mesh;
  Seam_edges edges_map = s.mesh.add_property_map<Atlas_surface::Edge_index, bool>("e:atlas_seam", false).first;
  Seam_vertices vertices_map = s.mesh.add_property_map<Atlas_vertex, bool>("v:atlas_seam", false).first;
  Disk_seams_report seams;
  if(compute_disk_seams(s.mesh, edges_map, vertices_map, Disk_seams_options(), &seams,
                        parameters::edge_is_constrained_map(polygon_diagonals(s, t, faces))) != OK)
    return false;
  Seam_mesh seam_mesh(s.mesh, edges_map, vertices_map);
  seam_mesh.set_seam_edges_number(seams.number_of_seam_edges);
  auto uv = get(CGAL::dynamic_vertex_property_t<Atlas_kernel::Point_2>(), seam_mesh);
  const auto bhd = main_border(seam_mesh).first;
  Parameterization_report report;
  if(parameterize(seam_mesh, chart_parameterizer<Seam_mesh>(options, whole), bhd, uv, &report) != OK)
    return false;
  keep_angle_distortion(report, chart);
  chart.flattening = SEAMED_CHART;
  typedef typename boost::graph_traits<Seam_mesh>::halfedge_descriptor Seam_halfedge;
  corners_from_uv(seam_mesh, s, uv, [](std::size_t i) { return Atlas_face(Atlas_surface::size_type(i)); },
                  [&s](Seam_halfedge h) { return int(target(h.tmhd, s.mesh)); }, chart);
  return true;
}

// One chart of a connected face subset when the parameterizers (or, failing them, the
// isometric unfolding) give a one-to-one map; false when the subset must be split. The
// parameterizer's own check (no flipped face, a simple border: a one-to-one map) needs no
// second one here, unless corners were welded (weld_rounded_corners()); its border must keep
// the clearance still (chart_border_is_clear()), which the packing's rounding needs.
inline bool flatten_subset(const Atlas_triangles& t, const std::vector<std::size_t>& faces,
                           const std::vector<std::array<int, 3> >& neighbors, const Atlas_options& options, bool whole,
                           Atlas_chart& chart)
{
  Subset_surface s = make_subset_surface(t, faces, neighbors);
  chart.faces = faces;
  if(s.built && (is_topological_disk(s.mesh) ? flatten_disk(s, options, whole, chart)
                                             : flatten_with_seams(s, t, faces, options, whole, chart)))
  {
    if(!weld_rounded_corners(t, chart))
      return chart_border_is_clear(t, chart);
    if(!is_one_to_one_chart(t, chart))
      return false;
    chart_angle_distortion(t, chart);  // of the moved UVs
    return true;
  }
  chart = unfold_isometrically(t, faces);
  return is_one_to_one_chart(t, chart);
}

// The bounds of the charts: the options', and the length under which a chart is short enough
// to need no compactness (half the side of a square of the whole mesh's area: such a chart
// fits into the gaps of the packing, whatever its shape).
struct Chart_bounds
{
  const Atlas_options& options;
  double short_length;
};

// Whether a chart meets the distortion bounds (area spread and angle distortion).
inline bool within_distortion_bounds(const Atlas_chart& chart, const Chart_bounds& bounds)
{
  return chart.area_spread <= bounds.options.max_area_spread && chart.angle_distortion <= bounds.options.max_angle_distortion;
}

// Whether a chart meets the compactness bound (or is short enough to need none).
inline bool compact_enough(const Atlas_chart& chart, const Chart_bounds& bounds)
{
  return chart.compactness >= bounds.options.min_compactness || chart.length <= bounds.short_length;
}

// The figures of a one-to-one chart that the bounds read; returns whether it meets the
// distortion bounds. Its areas and area spread; its angle distortion, unless the parameterizer
// gave it (angle_known: a flattened chart, whose angle distortion split_count() reads) or the
// area spread misses its bound (a piece of a split, then flattened again); its compactness
// (and smallest box) when it meets the distortion bounds (the only charts kept, or cut across).
inline bool measure_chart(const Atlas_triangles& t, Atlas_chart& chart, const Chart_bounds& bounds)
{
  chart_area_figures(t, chart);
  if(chart.area_spread > bounds.options.max_area_spread)
    return false;
  if(!chart.angle_known)
    chart_angle_distortion(t, chart);
  if(!within_distortion_bounds(chart, bounds))
    return false;
  chart_compactness(chart);
  return true;
}

// One-to-one pieces of a chart's map (cut_across(), or the UV islands of the parts of a
// split), each kept when it meets the bounds (a single face: the distortion bounds) and cut
// across again (cut_across(): nothing is flattened) when it misses only the compactness; a
// piece that misses a distortion bound, or whose border misses the clearance
// (chart_border_is_clear()), goes back to `pending` to be flattened anew. `splits` counts the
// cuts.
inline void settle_pieces(const Atlas_triangles& t, std::vector<Atlas_chart> pieces, const Chart_bounds& bounds,
                          std::vector<Atlas_chart>& charts, std::vector<std::vector<std::size_t> >& pending,
                          std::size_t& splits)
{
  while(!pieces.empty())
  {
    Atlas_chart piece = std::move(pieces.back());
    pieces.pop_back();
    if(!measure_chart(t, piece, bounds) || !chart_border_is_clear(t, piece))
      pending.push_back(std::move(piece.faces));
    else if(piece.faces.size() == 1 || compact_enough(piece, bounds))
      charts.push_back(std::move(piece));
    else
    {
      ++splits;
      for(Atlas_chart& smaller : cut_across(t, piece))
        pieces.push_back(std::move(smaller));
    }
  }
}

// The number of parts of a split of a chart whose one-to-one map misses the distortion
// bounds by the factor `over` (the larger of its area spread and its angle distortion over
// their bounds): 1 + ceil(log2(over)), so that a chart far from the bounds is not halved and
// flattened again level after level; from 2 to 8 for a chart cut open by seams (a closed or
// higher-genus part: SEAMED_CHART), from 2 to 3 for a disk (or an unfolded chart), and 2 for
// a disk less than 4 times over. Split into more, a part of a disk may surround another and be
// flattened with seams, with more angle distortion (lion-head.off against Boundary First
// Flattening, every disk split into 1 + ceil(log2(over)) parts); a disk 4 times over or more
// is a long limb or a tube cut open, and three parts there save flattenings (Hand1.off: 1.35
// to 1.24 s) and keep the angle distortion (lion-head.off: the paper's 0.022 to 0.008).
// Chosen by measurement (benchmark/README.md, *Bounds*, eighth run).
inline std::size_t split_count(const Atlas_chart& chart, const Chart_bounds& bounds)
{
  const double over = (std::max)(chart.area_spread / bounds.options.max_area_spread,
                                 chart.angle_distortion / bounds.options.max_angle_distortion);
  const bool seamed = chart.flattening == SEAMED_CHART;
  if(!seamed && !(over >= 4.))
    return 2u;  // NaN (0 / 0) too
  const double parts = (std::min)(1. + std::ceil(std::log2(over)), seamed ? 8. : 3.);
  return (parts > 2.) ? std::size_t(parts) : 2u;  // NaN: 2
}

// The pieces of the split of a chart with a one-to-one map (split_sides(), into
// split_count() parts) that keep the map (settle_pieces()): the UV islands of each part that
// is in as many islands as it has components on the surface. A part that the chart's seams
// cut into more islands goes back to `pending` whole: flattened again, it may stay one chart.
inline std::vector<Atlas_chart> pieces_of_split(const Atlas_triangles& t, const Atlas_chart& chart,
                                                const std::vector<std::array<int, 3> >& neighbors,
                                                std::vector<std::vector<std::size_t> >& pending, const Chart_bounds& bounds)
{
  const std::vector<int> side = split_sides(t, chart.faces, neighbors, bounds.options.split, &chart, split_count(chart, bounds));
  std::vector<int> island_part;
  std::vector<Atlas_chart> islands = uv_islands(t, chart, side, neighbors, &island_part);
  std::vector<std::vector<std::size_t> > faces(std::size_t(*std::max_element(side.begin(), side.end())) + 1);
  for(std::size_t i = 0; i < chart.faces.size(); ++i)
    faces[std::size_t(side[i])].push_back(chart.faces[i]);
  std::vector<std::size_t> count(faces.size(), 0);
  for(int p : island_part)
    ++count[std::size_t(p)];
  std::vector<bool> keep(faces.size(), true);
  for(std::size_t p = 0; p < faces.size(); ++p)
    if(count[p] > 1 && count[p] > edge_components(t, faces[p]).size())
    {
      keep[p] = false;
      pending.push_back(std::move(faces[p]));
    }
  std::vector<Atlas_chart> kept;
  for(std::size_t i = 0; i < islands.size(); ++i)
    if(keep[std::size_t(island_part[i])])
      kept.push_back(std::move(islands[i]));
  return kept;
}

// The charts of a face subset: each connected part one chart when its map is one-to-one and
// within the bounds; cut across when it misses only the compactness bound (settle_pieces());
// otherwise split (split_sides(): into split_count() parts when it has a one-to-one map, in two
// when not), the parts of a one-to-one map kept with their UVs where they meet the bounds
// (settle_pieces()), the others flattened again, and so on (a stack of face sets, not a
// recursion: a split may peel off little, and the depth is not bounded by a logarithm); a
// single triangle always unfolds, undistorted. `splits` counts the splits and cuts.
inline void flatten_face_set(const Atlas_triangles& t, const std::vector<std::size_t>& faces, const Chart_bounds& bounds,
                             std::vector<Atlas_chart>& charts, std::size_t& splits)
{
  std::vector<std::vector<std::size_t> > pending(1, faces);
  for(bool whole = true; !pending.empty(); whole = false)  // `faces` first, then the parts of splits
  {
    const std::vector<std::size_t> set = std::move(pending.back());
    pending.pop_back();
    for(const std::vector<std::size_t>& part : edge_components(t, set))
    {
      Atlas_chart chart;
      const std::vector<std::array<int, 3> > neighbors = subset_neighbors(t, part);
      const bool one_to_one = flatten_subset(t, part, neighbors, bounds.options, whole, chart) || part.size() == 1;
      const bool within = one_to_one && measure_chart(t, chart, bounds);
      if(one_to_one && (part.size() == 1 || (within && compact_enough(chart, bounds))))
      {
        charts.push_back(std::move(chart));
        continue;
      }
      ++splits;
      if(one_to_one)
      {
        settle_pieces(t, within ? cut_across(t, chart) : pieces_of_split(t, chart, neighbors, pending, bounds),
                      bounds, charts, pending, splits);
        continue;
      }
      std::array<std::vector<std::size_t>, 2> halves = split_for_bound(t, part, neighbors, bounds.options.split, nullptr);
      pending.push_back(std::move(halves[1]));
      pending.push_back(std::move(halves[0]));
    }
  }
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_ATLAS_CHARTS_H
