// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_ATLAS_SOUP_REPAIR_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_ATLAS_SOUP_REPAIR_H

// The input of the atlas: a polygon soup as users have it (CGAL::IO::read_polygon_soup(): any
// points, polygons of any size) repaired into a triangle mesh whose connected components the
// parameterizers accept, with nothing lost: every corner of every input polygon knows where
// its UV comes from (repaired_soup.h). The steps, each a CGAL function where one does the job:
//  1. soup (soup_cleaning.h, soup_orientation.h): duplicate points merged, polygons passing
//     through a point twice simplified or split, degenerate polygons (fewer than 3 distinct
//     points) dropped, duplicate polygons merged, orientation made consistent with
//     non-manifold edges, pinched vertices and non-orientable pieces cut;
//  2. mesh (mesh_repair.h): built, each component turned to the orientation of the majority
//     of its input polygons, triangulated, its zero-area triangles placed on edges of faces
//     kept;
//  3. here: every input corner given its source, the zero-area triangles removed, the vertices
//     this pinches split, the mesh compacted, its components counted, the corners whose point
//     no face has attached to the nearest vertex.
// A triangle mesh given directly enters as a soup (face_graph_to_soup()).

#include <CGAL/Surface_mesh_parameterization/internal/atlas/mesh_repair.h>
#include <CGAL/Surface_mesh_parameterization/internal/atlas/repaired_soup.h>
#include <CGAL/Surface_mesh_parameterization/internal/atlas/soup_cleaning.h>
#include <CGAL/Surface_mesh_parameterization/internal/atlas/soup_orientation.h>
#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/Soup_repair_report.h>

#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>

#include <boost/iterator/function_output_iterator.hpp>

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <numeric>
#include <set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

template <class Point_3>
struct Corner_tables
{
  typedef typename Working_mesh<Point_3>::halfedge_descriptor halfedge_descriptor;
  // the corners (merged point, halfedge) of the faces of each id, those of the faces kept
  // first: [id_offset[id], id_offset[id + 1])
  std::vector<std::size_t> id_offset;
  std::vector<std::pair<std::size_t, halfedge_descriptor> > corners;
  // per merged point: a halfedge of a face at it, of a face kept when there is one
  std::vector<halfedge_descriptor> point_halfedge;
};

template <class Point_3>
void fill_corner_tables(const Working_soup<Point_3>& soup, const Working_mesh<Point_3>& w, Corner_tables<Point_3>& t)
{
  const auto null = boost::graph_traits<typename Working_mesh<Point_3>::Mesh>::null_halfedge();
  t.id_offset.assign(soup.id_input.size() + 1, 0);
  for(auto f : faces(w.mesh))
    t.id_offset[get(w.face_id, f) + 1] += degree(f, w.mesh);
  std::partial_sum(t.id_offset.begin(), t.id_offset.end(), t.id_offset.begin());
  std::vector<std::size_t> cursor(t.id_offset.begin(), t.id_offset.end() - 1);
  t.corners.resize(t.id_offset.back());
  t.point_halfedge.assign(soup.points.size(), null);
  for(int pass = 0; pass < 2; ++pass)
    for(auto f : faces(w.mesh))
      if(w.is_kept(f) == (pass == 0))
        for(auto h : halfedges_around_face(halfedge(f, w.mesh), w.mesh))
        {
          const std::size_t m = get(w.vertex_point, target(h, w.mesh));
          t.corners[cursor[get(w.face_id, f)]++] = std::make_pair(m, h);
          if(t.point_halfedge[m] == null)
            t.point_halfedge[m] = h;
        }
}

// The halfedge of a face of input polygon p (through the polygons kept in place of its
// duplicates) at merged point m; null when none has it.
template <class Point_3>
typename Working_mesh<Point_3>::halfedge_descriptor
find_corner(const Working_soup<Point_3>& soup, const Corner_tables<Point_3>& t, std::size_t p, std::size_t m)
{
  for(std::size_t id = soup.id_offset[p]; id < soup.id_offset[p + 1]; ++id)
    for(std::size_t k = t.id_offset[soup.id_kept[id]]; k < t.id_offset[soup.id_kept[id] + 1]; ++k)
      if(t.corners[k].first == m)
        return t.corners[k].second;
  return boost::graph_traits<typename Working_mesh<Point_3>::Mesh>::null_halfedge();
}

// Corners of one input polygon that no face of its own has, placed on an edge of a face kept
// that has two of their points (found around one vertex of each point): a segment of one chart.
template <class Point_3>
bool place_on_shared_edge(const Working_soup<Point_3>& soup, const Working_mesh<Point_3>& w,
                          const Corner_tables<Point_3>& t, const std::vector<std::size_t>& missing,
                          std::vector<Corner_source<typename Working_mesh<Point_3>::Mesh> >& sources)
{
  typedef Corner_source<typename Working_mesh<Point_3>::Mesh> Source;
  std::set<std::size_t> points;
  for(const std::size_t c : missing)
    points.insert(soup.corner_point[c]);
  if(points.size() < 2)
    return false;
  for(const std::size_t a : points)
  {
    const auto h = t.point_halfedge[a];
    if(h == boost::graph_traits<typename Working_mesh<Point_3>::Mesh>::null_halfedge() || !w.is_kept(face(h, w.mesh)))
      continue;
    for(auto g : halfedges_around_target(h, w.mesh))
      if(!is_border(g, w.mesh) && w.is_kept(face(g, w.mesh)))
        for(auto k : halfedges_around_face(g, w.mesh))
        {
          const std::size_t b = get(w.vertex_point, target(k, w.mesh));
          if(k == g || points.count(b) == 0)
            continue;
          for(const std::size_t c : missing)
          {
            const std::size_t m = soup.corner_point[c];
            sources[c] = (m == a) ? Source{g, k, 0., Source::ON_SEGMENT}
                       : (m == b) ? Source{g, k, 1., Source::ON_SEGMENT} : Source{g, g, 0., Source::COLLAPSED};
          }
          return true;
        }
  }
  return false;
}

// Corners of one input polygon that no face of its own has (all corners of a degenerate
// polygon; the corners of a dropped piece of a split one): on an edge of a face kept that has
// two of their points, else all at the source of one of their points that a face has, else
// ISOLATED.
template <class Point_3>
void place_dropped_corners(const Working_soup<Point_3>& soup, const Working_mesh<Point_3>& w,
                           const Corner_tables<Point_3>& t, const std::vector<std::size_t>& missing,
                           std::vector<Corner_source<typename Working_mesh<Point_3>::Mesh> >& sources)
{
  typedef Corner_source<typename Working_mesh<Point_3>::Mesh> Source;
  if(place_on_shared_edge(soup, w, t, missing, sources))
    return;
  for(const std::size_t c : missing)
  {
    const auto h = t.point_halfedge[soup.corner_point[c]];
    if(h == boost::graph_traits<typename Working_mesh<Point_3>::Mesh>::null_halfedge() ||
       get(w.placement, h).kind == Source::ISOLATED)
      continue;
    for(const std::size_t d : missing)
    {
      sources[d] = get(w.placement, h);
      if(soup.corner_point[d] != soup.corner_point[c])
        sources[d].kind = Source::COLLAPSED;
    }
    return;
  }
}

// The source of every input corner, in halfedges of the working mesh: the placement of the
// halfedge of its polygon's face at its point, else (place_dropped_corners()).
template <class Point_3>
void place_input_corners(const Working_soup<Point_3>& soup, const Working_mesh<Point_3>& w,
                         std::vector<Corner_source<typename Working_mesh<Point_3>::Mesh> >& sources)
{
  Corner_tables<Point_3> t;
  fill_corner_tables(soup, w, t);
  sources.assign(soup.corner_point.size(), Corner_source<typename Working_mesh<Point_3>::Mesh>());
  std::vector<std::size_t> missing;
  for(std::size_t p = 0; p + 1 < soup.corner_offset.size(); ++p)
  {
    missing.clear();
    for(std::size_t c = soup.corner_offset[p]; c < soup.corner_offset[p + 1]; ++c)
    {
      const auto h = find_corner(soup, t, p, soup.corner_point[c]);
      if(h == boost::graph_traits<typename Working_mesh<Point_3>::Mesh>::null_halfedge())
        missing.push_back(c);
      else
        sources[c] = get(w.placement, h);
    }
    if(!missing.empty())
      place_dropped_corners(soup, w, t, missing, sources);
  }
}

template <class Point_3>
void record_zero_area(const Working_soup<Point_3>& soup, const Working_mesh<Point_3>& w,
                      std::vector<Zero_area_triangle<typename Working_mesh<Point_3>::Mesh> >& triangles)
{
  for(auto f : faces(w.mesh))
  {
    if(w.is_kept(f))
      continue;
    triangles.emplace_back();
    triangles.back().polygon = soup.id_input[get(w.face_id, f)];
    std::size_t k = 0;
    for(auto h : halfedges_around_face(halfedge(f, w.mesh), w.mesh))
    {
      triangles.back().points[k] = w.mesh.point(target(h, w.mesh));
      triangles.back().corners[k++] = get(w.placement, h);
    }
  }
}

// Removes the zero-area triangles (Euler::remove_face() also removes the vertices it
// isolates), splits the vertices this leaves pinched (duplicate_non_manifold_vertices()), and
// removes the vertices no face has (the isolated input points, the points of dropped polygons).
template <class Point_3>
void remove_zero_area(Working_mesh<Point_3>& w, Soup_repair_report& report)
{
  std::vector<typename Working_mesh<Point_3>::face_descriptor> removed;
  for(auto f : faces(w.mesh))
    if(!w.is_kept(f))
      removed.push_back(f);
  for(auto f : removed)
    Euler::remove_face(halfedge(f, w.mesh), w.mesh);
  report.vertices_split_after_removal = Polygon_mesh_processing::duplicate_non_manifold_vertices(w.mesh);
  Polygon_mesh_processing::remove_isolated_vertices(w.mesh);
}

template <class Kernel, class Point_3>
void copy_compacted(Working_mesh<Point_3>& w, Repaired_soup<Kernel>& out, std::vector<std::size_t>& face_id)
{
  typedef typename Working_mesh<Point_3>::halfedge_descriptor halfedge_descriptor;
  typedef typename Working_mesh<Point_3>::face_descriptor face_descriptor;
  typedef typename Repaired_soup<Kernel>::Source Source;
  auto copy = w.mesh.template add_property_map<halfedge_descriptor, halfedge_descriptor>("h:atlas_copy").first;
  std::vector<std::pair<face_descriptor, face_descriptor> > f2f;
  CGAL::copy_face_graph(w.mesh, out.mesh,
                        parameters::halfedge_to_halfedge_output_iterator(boost::make_function_output_iterator(
                          [&copy](const std::pair<halfedge_descriptor, halfedge_descriptor>& h2h) {
                            put(copy, h2h.first, h2h.second);
                          }))
                          .face_to_face_output_iterator(std::back_inserter(f2f)));
  face_id.assign(out.mesh.number_of_faces(), 0);
  for(const auto& f : f2f)
    face_id[std::size_t(f.second)] = get(w.face_id, f.first);
  auto move_over = [&copy](Source& s) {
    if(s.kind != Source::ISOLATED)
      s = Source{get(copy, s.from), get(copy, s.to), s.t, s.kind};
  };
  for(Source& s : out.corners)
    move_over(s);
  for(auto& z : out.zero_area_triangles)
    for(Source& s : z.corners)
      move_over(s);
}

// The working mesh without its removed elements, into the result: moved when nothing was
// removed, else copied (copy_face_graph(), which reports the copy of every halfedge and face)
// and the sources moved over to the copy. face_id: the id of each face of the result.
template <class Kernel, class Point_3>
void compact(const Working_soup<Point_3>& soup, Working_mesh<Point_3>& w, Repaired_soup<Kernel>& out,
             std::vector<std::size_t>& face_id)
{
  if(w.mesh.has_garbage())
    copy_compacted(w, out, face_id);
  else
  {
    face_id.resize(w.mesh.number_of_faces());
    for(auto f : faces(w.mesh))
      face_id[std::size_t(f)] = get(w.face_id, f);
    w.remove_property_maps();
    out.mesh = std::move(w.mesh);
  }
  out.face_polygon.resize(face_id.size());
  for(std::size_t f = 0; f < face_id.size(); ++f)
    out.face_polygon[f] = soup.id_input[face_id[f]];
}

// The connected components of the result, and how many of them hold a cut of a
// non-orientable piece.
template <class Kernel, class Point_3>
void count_components(const Working_soup<Point_3>& soup, const std::vector<std::size_t>& face_id,
                      Repaired_soup<Kernel>& out)
{
  typedef typename Repaired_soup<Kernel>::Mesh Mesh;
  typedef typename boost::graph_traits<Mesh>::face_descriptor face_descriptor;
  auto component = out.mesh.template add_property_map<face_descriptor, std::size_t>("f:atlas_component", 0).first;
  out.report.components = Polygon_mesh_processing::connected_components(out.mesh, component);
  out.face_component.assign(out.mesh.number_of_faces(), 0);
  for(face_descriptor f : faces(out.mesh))
    out.face_component[std::size_t(f)] = get(component, f);
  out.mesh.remove_property_map(component);
  std::vector<bool> is_cut(soup.id_input.size(), false);
  for(const std::size_t id : soup.cut_ids)
    is_cut[id] = true;
  std::vector<bool> cut_component(out.report.components, false);
  for(std::size_t f = 0; f < face_id.size(); ++f)
    if(is_cut[face_id[f]])
      cut_component[out.face_component[f]] = true;
  out.report.non_orientable_components = std::size_t(std::count(cut_component.begin(), cut_component.end(), true));
}

template <class Kernel, class Point_3>
void count_result(const Working_soup<Point_3>& soup, Repaired_soup<Kernel>& out)
{
  typedef typename Repaired_soup<Kernel>::Source Source;
  std::vector<bool> reversed(soup.id_offset.size(), false);  // per input polygon
  for(const Soup_polygon& polygon : soup.polygons)
    if(soup.id_reversed[polygon.id])
      reversed[soup.id_input[polygon.id]] = true;
  out.report.reoriented_polygons = std::size_t(std::count(reversed.begin(), reversed.end(), true));
  out.report.vertices = out.mesh.number_of_vertices();
  out.report.faces = out.mesh.number_of_faces();
  for(const Source& s : out.corners)
  {
    out.report.collapsed_corners += (s.kind == Source::COLLAPSED) ? 1 : 0;
    out.report.isolated_corners += (s.kind == Source::ISOLATED) ? 1 : 0;
  }
}

// A halfedge of a face at the vertex of `mesh` nearest to `p` (CGAL's k-d tree), for the
// corners whose point no face has.
template <class Mesh>
class Nearest_face_corner
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::property_map<Mesh, vertex_point_t>::const_type Point_map;
  typedef typename Kernel_traits<typename Mesh::Point>::Kernel Kernel;
  typedef Search_traits_adapter<vertex_descriptor, Point_map, Search_traits_3<Kernel> > Traits;
  typedef Orthogonal_k_neighbor_search<Traits> Search;

  const Mesh& m_mesh;
  typename Search::Tree m_tree;

public:
  explicit Nearest_face_corner(const Mesh& mesh)
    : m_mesh(mesh), m_tree(vertices(mesh).begin(), vertices(mesh).end(), typename Search::Tree::Splitter(),
                           Traits(get(vertex_point, mesh)))
  {}
  typename boost::graph_traits<Mesh>::halfedge_descriptor operator()(const typename Mesh::Point& p) const
  {
    const Search search(m_tree, p, 1, 0, true, typename Search::Distance(get(vertex_point, m_mesh)));
    for(auto h : halfedges_around_target(search.begin()->first, m_mesh))
      if(!is_border(h, m_mesh))
        return h;
    return boost::graph_traits<Mesh>::null_halfedge();  // (no isolated vertex in the result)
  }
};

// The ISOLATED corners (of input polygons and of zero-area triangles) given a halfedge: all
// those of one polygon at the nearest corner of a face to the point of the first of them, so
// that every corner gets its UV in a chart. Then the face of each zero-area triangle.
template <class Kernel, class Point_3>
void attach_isolated_corners(const Working_soup<Point_3>& soup, Repaired_soup<Kernel>& out)
{
  typedef typename Repaired_soup<Kernel>::Source Source;
  auto is_isolated = [](const Source& s) { return s.kind == Source::ISOLATED; };
  const bool any = std::any_of(out.corners.begin(), out.corners.end(), is_isolated) ||
                   std::any_of(out.zero_area_triangles.begin(), out.zero_area_triangles.end(), [&](const auto& z) {
                     return std::any_of(z.corners.begin(), z.corners.end(), is_isolated);
                   });
  if(any)
  {
    const Nearest_face_corner<typename Repaired_soup<Kernel>::Mesh> nearest(out.mesh);
    for(std::size_t p = 0; p + 1 < out.corner_offset.size(); ++p)
    {
      const std::size_t begin = out.corner_offset[p], end = out.corner_offset[p + 1];
      const auto first = std::find_if(out.corners.begin() + begin, out.corners.begin() + end, is_isolated);
      if(first == out.corners.begin() + end)
        continue;
      const auto h = nearest(soup.points[soup.corner_point[std::size_t(first - out.corners.begin())]]);
      std::replace_if(first, out.corners.begin() + end, is_isolated, Source{h, h, 0., Source::ISOLATED});
    }
    for(auto& z : out.zero_area_triangles)
      if(std::any_of(z.corners.begin(), z.corners.end(), is_isolated))
      {
        const auto h = nearest(z.points[0]);
        std::replace_if(z.corners.begin(), z.corners.end(), is_isolated, Source{h, h, 0., Source::ISOLATED});
      }
  }
  for(auto& z : out.zero_area_triangles)
    z.face = face(z.corners[0].from, out.mesh);
}

// The steps of repair_soup_for_atlas(), into `out`, which is left partial on an error.
template <class Kernel, class PointRange, class PolygonRange>
Error_code repair_steps(const PointRange& points, const PolygonRange& polygons, Repaired_soup<Kernel>& out)
{
  typedef typename Kernel::Point_3 Point_3;
  Working_soup<Point_3> soup;
  const Error_code loaded = load_soup(points, polygons, soup, out.report);
  if(loaded != OK)
    return loaded;
  merge_points(soup, out.report);
  simplify_polygons(soup, out.report);
  if(soup.polygons.empty())
    return ERROR_EMPTY_MESH;
  merge_polygons(soup, out.report);
  orient_soup(soup, out.report);
  Working_mesh<Point_3> w;
  build_mesh(soup, w, out.report);
  keep_majority_orientation(soup, w);
  triangulate(soup, w, out.report);
  out.report.zero_area_triangles = mark_zero_area(w);
  place_zero_area_faces(w);
  place_input_corners(soup, w, out.corners);
  record_zero_area(soup, w, out.zero_area_triangles);
  remove_zero_area(w, out.report);
  std::vector<std::size_t> face_id;
  compact(soup, w, out, face_id);
  if(out.mesh.number_of_faces() == 0)
    return ERROR_EMPTY_MESH;
  out.corner_offset = soup.corner_offset;
  count_components(soup, face_id, out);
  count_result(soup, out);
  attach_isolated_corners(soup, out);
  return OK;
}

// Repairs the soup `points`, `polygons` (the user's data as read by CGAL's readers: points with
// three coordinates p[0], p[1], p[2]; polygons as ranges of point indices, of any size) into
// `out` (repaired_soup.h). Returns OK, or ERROR_NON_FINITE_COORDINATES (a point is infinite or
// NaN), ERROR_WRONG_PARAMETER (an index out of range), ERROR_EMPTY_MESH (no face is left: no
// polygon with 3 distinct points, or all of zero area). On an error nothing is output: `out`
// is empty but for its report, filled up to the error (the input counts, the repairs found).
template <class Kernel, class PointRange, class PolygonRange>
Error_code repair_soup_for_atlas(const PointRange& points, const PolygonRange& polygons, Repaired_soup<Kernel>& out)
{
  Repaired_soup<Kernel> result;
  const Error_code error = repair_steps(points, polygons, result);
  out = Repaired_soup<Kernel>();
  if(error == OK)
    out = std::move(result);
  else
    out.report = result.report;
  return error;
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_ATLAS_SOUP_REPAIR_H
