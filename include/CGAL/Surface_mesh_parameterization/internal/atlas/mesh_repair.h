// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_ATLAS_MESH_REPAIR_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_ATLAS_MESH_REPAIR_H

// The mesh stage of the repair of a polygon soup for the atlas (soup_repair.h): the oriented
// soup made a mesh (CGAL), each component turned to the orientation of most of its input
// polygons (CGAL reverses), the polygons triangulated (CGAL, with a fan where CGAL refuses),
// and the zero-area triangles found and placed on an edge of a face kept, before they are
// removed. The working mesh carries, per face, the id of its working polygon and, per vertex,
// its merged point, so that every input corner finds a halfedge.

#include <CGAL/Surface_mesh_parameterization/internal/atlas/repaired_soup.h>
#include <CGAL/Surface_mesh_parameterization/internal/atlas/soup_cleaning.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/triangle_geometry.h>

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

template <class Point_3>
struct Working_mesh
{
  typedef CGAL::Surface_mesh<Point_3> Mesh;
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<Mesh>::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::graph_traits<Mesh>::face_descriptor face_descriptor;
  typedef Corner_source<Mesh> Source;
  // a face is kept, or of zero area and not yet placed, or of zero area and placed
  enum Face_state { KEPT, ZERO_AREA, PLACED };

  Mesh mesh;
  typename Mesh::template Property_map<face_descriptor, std::size_t> face_id;
  typename Mesh::template Property_map<vertex_descriptor, std::size_t> vertex_point;
  typename Mesh::template Property_map<face_descriptor, int> state;
  // per halfedge of a face: where the UV of the corner at its target comes from
  typename Mesh::template Property_map<halfedge_descriptor, Source> placement;

  Working_mesh()
  {
    face_id = mesh.template add_property_map<face_descriptor, std::size_t>("f:atlas_id", 0).first;
    vertex_point = mesh.template add_property_map<vertex_descriptor, std::size_t>("v:atlas_point", 0).first;
    state = mesh.template add_property_map<face_descriptor, int>("f:atlas_state", KEPT).first;
    placement = mesh.template add_property_map<halfedge_descriptor, Source>("h:atlas_placement").first;
  }

  bool is_kept(face_descriptor f) const { return get(state, f) == KEPT; }
  void remove_property_maps()
  {
    mesh.remove_property_map(face_id);
    mesh.remove_property_map(vertex_point);
    mesh.remove_property_map(state);
    mesh.remove_property_map(placement);
  }
  Eigen::Vector3d position(vertex_descriptor v) const
  {
    const Point_3& p = mesh.point(v);
    return Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  }
};

// The mesh of the oriented soup (CGAL). A fresh Surface_mesh numbers its vertices and faces in
// the order they are added, which polygon_soup_to_polygon_mesh() makes the order of the points
// (all of them) and of the polygons. False when it does not convert every polygon.
template <class Point_3>
bool convert_soup(const Working_soup<Point_3>& soup, Working_mesh<Point_3>& w)
{
#ifndef CGAL_NO_PRECONDITIONS
  // a precondition of polygon_soup_to_polygon_mesh() when CGAL's preconditions are on (not
  // with NDEBUG): without them, a polygon it cannot add is left out, which the counts show
  if(!Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(soup.polygons))
    return false;
#endif
  Polygon_mesh_processing::polygon_soup_to_polygon_mesh(soup.points, soup.polygons, w.mesh);
  return w.mesh.number_of_faces() == soup.polygons.size() && w.mesh.number_of_vertices() == soup.points.size();
}

// A soup that polygon_soup_to_polygon_mesh() does not convert whole (orient_polygon_soup()
// should leave none: its Euler::add_face() refuses a polygon that runs an edge the way another
// does, or that closes a vertex already closed), built here one polygon at a time: a polygon
// refused gets its own copies of its points. Pinched vertices left are split later
// (duplicate_non_manifold_vertices()). Returns the number of polygons so detached.
template <class Point_3>
std::size_t add_polygons_detaching(Working_soup<Point_3>& soup, Working_mesh<Point_3>& w)
{
  typedef typename Working_mesh<Point_3>::vertex_descriptor vertex_descriptor;
  std::vector<vertex_descriptor> vertices, corners;
  for(const Point_3& p : soup.points)
    vertices.push_back(w.mesh.add_vertex(p));
  std::size_t detached = 0;
  for(Soup_polygon& polygon : soup.polygons)
  {
    corners.clear();
    for(const std::size_t i : polygon)
      corners.push_back(vertices[i]);
    if(Euler::add_face(corners, w.mesh) != boost::graph_traits<typename Working_mesh<Point_3>::Mesh>::null_face())
      continue;
    ++detached;
    corners.clear();
    for(std::size_t& i : polygon)
    {
      const Point_3 p = soup.points[i];
      soup.points.push_back(p);
      soup.point_origin.push_back(soup.point_origin[i]);
      i = soup.points.size() - 1;
      vertices.push_back(w.mesh.add_vertex(p));
      corners.push_back(vertices.back());
    }
    Euler::add_face(corners, w.mesh);
  }
  return detached;
}

// The working mesh of the oriented soup, with the id of every face and the merged point of
// every vertex.
template <class Point_3>
void build_mesh(Working_soup<Point_3>& soup, Working_mesh<Point_3>& w, Soup_repair_report& report)
{
  typedef typename Working_mesh<Point_3>::face_descriptor face_descriptor;
  typedef typename Working_mesh<Point_3>::vertex_descriptor vertex_descriptor;
  if(!convert_soup(soup, w))
  {
    w.mesh.clear_without_removing_property_maps();
    report.detached_polygons = add_polygons_detaching(soup, w);
  }
  for(std::size_t i = 0; i < soup.polygons.size(); ++i)
    put(w.face_id, face_descriptor(static_cast<typename face_descriptor::size_type>(i)), soup.polygons[i].id);
  for(std::size_t i = 0; i < soup.points.size(); ++i)
    put(w.vertex_point, vertex_descriptor(static_cast<typename vertex_descriptor::size_type>(i)),
        soup.point_origin[i]);
}

// orient_polygon_soup() keeps the orientation of the first polygon it meets in each piece;
// this turns each connected component to the orientation most of its input polygons had
// (CGAL's connected_components() and reverse_face_orientations(); the vote is written here).
template <class Point_3>
void keep_majority_orientation(Working_soup<Point_3>& soup, Working_mesh<Point_3>& w)
{
  typedef typename Working_mesh<Point_3>::face_descriptor face_descriptor;
  auto component = w.mesh.template add_property_map<face_descriptor, std::size_t>("f:atlas_component", 0).first;
  const std::size_t n = Polygon_mesh_processing::connected_components(w.mesh, component);
  std::vector<std::size_t> reversed(n, 0), total(n, 0);
  for(face_descriptor f : faces(w.mesh))
  {
    ++total[get(component, f)];
    reversed[get(component, f)] += soup.id_reversed[get(w.face_id, f)] ? 1 : 0;
  }
  std::vector<face_descriptor> flip;
  for(face_descriptor f : faces(w.mesh))
    if(2 * reversed[get(component, f)] > total[get(component, f)])
      flip.push_back(f);
  Polygon_mesh_processing::reverse_face_orientations(flip, w.mesh);
  for(face_descriptor f : flip)
    soup.id_reversed[get(w.face_id, f)] = !soup.id_reversed[get(w.face_id, f)];
  w.mesh.remove_property_map(component);
}

// The visitor of triangulate_faces(): every triangle of a polygon gets the polygon's id.
// CGAL's default visitor gives the members that CGAL 6 adds to the concept (the phases of its
// hole filling).
template <class Mesh>
struct Polygon_id_visitor : Polygon_mesh_processing::Triangulate_faces::Default_visitor<Mesh>
{
  typedef typename boost::graph_traits<Mesh>::face_descriptor face_descriptor;
  typedef typename Mesh::template Property_map<face_descriptor, std::size_t> Id_map;
  Id_map id;
  std::size_t current = 0;

  explicit Polygon_id_visitor(Id_map map) : id(map) { }

  void before_subface_creations(face_descriptor f) { current = get(id, f); }
  void after_subface_created(face_descriptor f) { put(id, f, current); }
  void after_subface_creations() {}
};

template <class Mesh>
std::vector<typename boost::graph_traits<Mesh>::face_descriptor> non_triangles(const Mesh& mesh)
{
  std::vector<typename boost::graph_traits<Mesh>::face_descriptor> result;
  for(auto f : faces(mesh))
    if(degree(f, mesh) > 3)
      result.push_back(f);
  return result;
}

// Triangulates what triangulate_faces() left. It refuses a face whose normal
// (compute_face_normal()) is zero: all points on a line, or a polygon whose signed areas
// cancel; and its 2D constrained Delaunay triangulation refuses a face whose projection is
// not simple. First CGAL's hole filling (no projection), then, for what is left, a fan from
// one vertex written here with Euler::split_face(): its triangles may have zero area, and are
// then removed like any other.
template <class Mesh>
void triangulate_rest(Mesh& mesh, Polygon_id_visitor<Mesh> visitor)
{
  for(auto f : non_triangles(mesh))
  {
    if(Polygon_mesh_processing::triangulate_face(
         f, mesh, parameters::visitor(visitor).use_2d_constrained_delaunay_triangulation(false)))
      continue;
    visitor.before_subface_creations(f);
    const auto h = halfedge(f, mesh);
    while(next(next(next(h, mesh), mesh), mesh) != h)
    {
      const auto cut = Euler::split_face(h, next(next(h, mesh), mesh), mesh);
      visitor.after_subface_created(face(cut, mesh));
      visitor.after_subface_created(face(opposite(cut, mesh), mesh));
    }
  }
}

// Triangulates the polygons (CGAL), each triangle keeping its polygon's id; counts the input
// polygons triangulated and the triangles made.
template <class Point_3>
void triangulate(const Working_soup<Point_3>& soup, Working_mesh<Point_3>& w, Soup_repair_report& report)
{
  typedef typename Working_mesh<Point_3>::Mesh Mesh;
  const auto polygons = non_triangles(w.mesh);
  if(polygons.empty())
    return;
  std::vector<bool> is_polygon(soup.id_input.size(), false), is_input(soup.id_offset.size(), false);
  for(auto f : polygons)
  {
    is_polygon[get(w.face_id, f)] = true;
    is_input[soup.id_input[get(w.face_id, f)]] = true;
  }
  Polygon_id_visitor<Mesh> visitor(w.face_id);
  if(!Polygon_mesh_processing::triangulate_faces(polygons, w.mesh, parameters::visitor(visitor)))
    triangulate_rest(w.mesh, visitor);
  report.triangulated_polygons = std::size_t(std::count(is_input.begin(), is_input.end(), true));
  for(auto f : faces(w.mesh))
    report.triangles_from_polygons += is_polygon[get(w.face_id, f)] ? 1 : 0;
}

// Marks the triangles of zero area with the test of the parameterizers (is_degenerate_triangle()).
template <class Point_3>
std::size_t mark_zero_area(Working_mesh<Point_3>& w)
{
  std::size_t count = 0;
  for(auto f : faces(w.mesh))
  {
    const auto h = halfedge(f, w.mesh);
    if(is_degenerate_triangle(w.position(source(h, w.mesh)), w.position(target(h, w.mesh)),
                              w.position(target(next(h, w.mesh), w.mesh))))
    {
      put(w.state, f, Working_mesh<Point_3>::ZERO_AREA);
      ++count;
    }
  }
  return count;
}

// The sources of the two ends of the edge of `o` (from w to u) in its face when that face is
// kept (the ends of the edge itself) or placed (the sources of its corners there, which lie on
// one segment): at_u and at_w, on one segment of a kept face. False when there is none.
template <class Point_3>
bool ends_across(const Working_mesh<Point_3>& w, typename Working_mesh<Point_3>::halfedge_descriptor o,
                 Corner_source<typename Working_mesh<Point_3>::Mesh>& at_u,
                 Corner_source<typename Working_mesh<Point_3>::Mesh>& at_w)
{
  typedef Corner_source<typename Working_mesh<Point_3>::Mesh> Source;
  if(is_border(o, w.mesh) || get(w.state, face(o, w.mesh)) == Working_mesh<Point_3>::ZERO_AREA)
    return false;
  const auto p = prev(o, w.mesh);
  if(w.is_kept(face(o, w.mesh)))
  {
    at_u = Source{o, p, 0., Source::ON_SEGMENT};
    at_w = Source{o, p, 1., Source::ON_SEGMENT};
    return true;
  }
  at_u = get(w.placement, o);
  at_w = get(w.placement, p);
  return true;
}

// Places the zero-area triangle of `g` on the segment its neighbour across `g` lends: its
// corners at source(g) and target(g) where the neighbour has them, its third corner at its
// projection on that edge (on it, up to rounding, when `g` is the longest edge).
template <class Point_3>
bool place_across(Working_mesh<Point_3>& w, typename Working_mesh<Point_3>::halfedge_descriptor g)
{
  typedef Corner_source<typename Working_mesh<Point_3>::Mesh> Source;
  Source at_u, at_w;
  if(!ends_across(w, opposite(g, w.mesh), at_u, at_w))
    return false;
  const Eigen::Vector3d u = w.position(source(g, w.mesh)), v = w.position(target(g, w.mesh));
  const Eigen::Vector3d c = w.position(target(next(g, w.mesh), w.mesh));
  const double length2 = (v - u).squaredNorm();
  const double s = length2 > 0. ? (std::min)(1., (std::max)(0., (c - u).dot(v - u) / length2)) : 0.;
  Source at_c = at_u;
  at_c.t = at_u.t + s * (at_w.t - at_u.t);
  at_c.kind = (at_u.from == at_u.to) ? Source::COLLAPSED : Source::ON_SEGMENT;
  put(w.placement, prev(g, w.mesh), at_u);
  put(w.placement, g, at_w);
  put(w.placement, next(g, w.mesh), at_c);
  put(w.state, face(g, w.mesh), Working_mesh<Point_3>::PLACED);
  return true;
}

// The halfedges of a triangle, longest edge first.
template <class Point_3>
std::array<typename Working_mesh<Point_3>::halfedge_descriptor, 3>
by_decreasing_length(const Working_mesh<Point_3>& w, typename Working_mesh<Point_3>::face_descriptor f)
{
  const auto h = halfedge(f, w.mesh);
  std::array<typename Working_mesh<Point_3>::halfedge_descriptor, 3> e = {{h, next(h, w.mesh), prev(h, w.mesh)}};
  auto length2 = [&w](typename Working_mesh<Point_3>::halfedge_descriptor g) {
    return (w.position(target(g, w.mesh)) - w.position(source(g, w.mesh))).squaredNorm();
  };
  std::stable_sort(e.begin(), e.end(), [&](auto a, auto b) { return length2(a) > length2(b); });
  return e;
}

// One sweep over the zero-area triangles not yet placed: each placed across its longest edge,
// or (any_edge) across its first edge, longest first, whose other face is kept or placed.
template <class Point_3>
bool sweep(Working_mesh<Point_3>& w, std::vector<typename Working_mesh<Point_3>::face_descriptor>& pending,
           bool any_edge)
{
  bool progress = false;
  for(auto f : pending)
  {
    const auto edges = by_decreasing_length(w, f);
    for(std::size_t k = 0; k < (any_edge ? 3u : 1u); ++k)
      if(place_across(w, edges[k]))
      {
        progress = true;
        break;
      }
  }
  pending.erase(std::remove_if(pending.begin(), pending.end(),
                               [&w](auto f) { return get(w.state, f) != Working_mesh<Point_3>::ZERO_AREA; }),
                pending.end());
  return progress;
}

// A zero-area triangle that shares no edge with a face kept or placed: all its corners at one
// of its vertices that a face kept has (a point of that face's chart). False when none has.
template <class Point_3>
bool collapse_on_vertex(Working_mesh<Point_3>& w, typename Working_mesh<Point_3>::face_descriptor f)
{
  typedef Corner_source<typename Working_mesh<Point_3>::Mesh> Source;
  for(auto h : halfedges_around_face(halfedge(f, w.mesh), w.mesh))
    for(auto g : halfedges_around_target(h, w.mesh))
      if(!is_border(g, w.mesh) && w.is_kept(face(g, w.mesh)))
      {
        for(auto k : halfedges_around_face(h, w.mesh))
          put(w.placement, k, Source{g, g, 0., k == h ? Source::ON_HALFEDGE : Source::COLLAPSED});
        put(w.state, f, Working_mesh<Point_3>::PLACED);
        return true;
      }
  return false;
}

// Places every zero-area triangle: the corners of a face kept are their own sources; a
// zero-area triangle takes a segment from a neighbour across an edge (its longest edge first),
// repeatedly, then, where none is reachable, a vertex; the rest stay ISOLATED.
template <class Point_3>
void place_zero_area_faces(Working_mesh<Point_3>& w)
{
  typedef Corner_source<typename Working_mesh<Point_3>::Mesh> Source;
  std::vector<typename Working_mesh<Point_3>::face_descriptor> pending;
  for(auto f : faces(w.mesh))
  {
    if(!w.is_kept(f))
    {
      pending.push_back(f);
      continue;
    }
    for(auto h : halfedges_around_face(halfedge(f, w.mesh), w.mesh))
      put(w.placement, h, Source{h, h, 0., Source::ON_HALFEDGE});
  }
  while(!pending.empty())
  {
    if(sweep(w, pending, false) || sweep(w, pending, true))
      continue;
    bool collapsed = false;
    for(auto f : pending)
      collapsed = collapse_on_vertex(w, f) || collapsed;
    if(!collapsed)
      break;
    sweep(w, pending, true);
  }
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_ATLAS_MESH_REPAIR_H
