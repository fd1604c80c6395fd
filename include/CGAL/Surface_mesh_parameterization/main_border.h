// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_MAIN_BORDER_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_MAIN_BORDER_H

/// \file main_border.h

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>

#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {

namespace internal {

// A border loop: its length, its number of edges, and the border halfedge whose source comes
// first in vertices(tm).
template <class HalfedgeDescriptor>
struct Border_loop
{
  HalfedgeDescriptor first;
  double length = 0.;
  std::size_t size = 0, first_rank = 0;
};

// |q - p|, hypot-like, so that no square underflows or overflows at extreme scales.
template <class Point>
double scaled_distance(const Point& p, const Point& q)
{
  const double dx = CGAL::to_double(q.x()) - CGAL::to_double(p.x());
  const double dy = CGAL::to_double(q.y()) - CGAL::to_double(p.y());
  const double dz = CGAL::to_double(q.z()) - CGAL::to_double(p.z());
  const double m = (std::max)({std::abs(dx), std::abs(dy), std::abs(dz)});
  return (m > 0.) ? m * std::sqrt((dx / m) * (dx / m) + (dy / m) * (dy / m) + (dz / m) * (dz / m)) : 0.;
}

template <class TriangleMesh, class RankMap, class SeenMap>
Border_loop<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor>
walk_border_loop(const TriangleMesh& tm, typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h,
                 const RankMap& rank, SeenMap& seen)
{
  Border_loop<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor> loop;
  loop.first = h;
  loop.first_rank = get(rank, source(h, tm));
  const auto vpm = get(CGAL::vertex_point, tm);
  for(auto b : halfedges_around_face(h, tm))
  {
    put(seen, b, true);
    loop.length += scaled_distance(get(vpm, source(b, tm)), get(vpm, target(b, tm)));
    ++loop.size;
    if(get(rank, source(b, tm)) < loop.first_rank)
    {
      loop.first_rank = get(rank, source(b, tm));
      loop.first = b;
    }
  }
  return loop;
}

} // namespace internal

/// \ingroup PkgSurfaceMeshParameterizationMeasured
///
/// the border loop to parameterize: a border halfedge of the longest border loop of `tm`,
/// with its length (CGAL's `Polygon_mesh_processing::longest_border()` with a documented
/// rule for ties, so that the choice does not depend on rounding).
///
/// Loops whose lengths differ by at most `1e-9` of the longer one are *tied*. A tie goes to
/// the loop with more vertices, then to the loop that has the vertex coming first in
/// `vertices(tm)` (the input's order). The choice is therefore the same for the mesh moved
/// rigidly, mirrored, translated or scaled (every rule is invariant under them); only a
/// renumbering of the vertices can change it, between loops that no rule based on the
/// geometry could tell apart (an open tube with two equal ends, say).
///
/// The returned halfedge is the border halfedge whose source is that first vertex of the
/// loop in `vertices(tm)` order, so the loop's starting vertex follows the same rule.
///
/// \tparam TriangleMesh a model of `FaceGraph`.
/// \return the halfedge (`null_halfedge()` when `tm` has no border) and the loop's length.
template <class TriangleMesh>
std::pair<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor, double>
main_border(const TriangleMesh& tm)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor   vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;

  // the rank of every vertex in vertices(tm) order
  auto rank = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
  std::size_t r = 0;
  for(vertex_descriptor v : vertices(tm))
    put(rank, v, r++);
  auto seen = get(CGAL::dynamic_halfedge_property_t<bool>(), tm);
  for(halfedge_descriptor h : halfedges(tm))
    put(seen, h, false);
  std::vector<internal::Border_loop<halfedge_descriptor> > loops;
  for(halfedge_descriptor h : halfedges(tm))
    if(is_border(h, tm) && !get(seen, h))
      loops.push_back(internal::walk_border_loop(tm, h, rank, seen));
  if(loops.empty())
    return {boost::graph_traits<TriangleMesh>::null_halfedge(), 0.};
  const auto* best = &loops.front();
  for(const auto& l : loops)
  {
    const double longer = (std::max)(l.length, best->length);
    const bool tied = std::abs(l.length - best->length) <= 1e-9 * longer;
    if(tied ? (l.size > best->size || (l.size == best->size && l.first_rank < best->first_rank))
            : l.length > best->length)
      best = &l;
  }
  return {best->first, best->length};
}

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_MAIN_BORDER_H
