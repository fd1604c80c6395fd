// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DISTANCES_SOURCE_COMPONENTS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DISTANCES_SOURCE_COMPONENTS_H

// The component loop shared by the distance-map functions: every connected component that
// holds a source is built as a patch and solved; results are written only when all succeed.

#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/disk.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <cstddef>
#include <iterator>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// `solve(patch, local_sources, values)` computes one value per patch vertex.
template <class SolverTraits, class TriangleMesh, class VertexRange, class VertexPointMap,
          class VertexDistanceMap, class Solve>
Error_code distance_map_over_source_components(const TriangleMesh& tm,
                                                const VertexRange& sources,
                                                VertexPointMap vpm,
                                                VertexDistanceMap distance_map,
                                                const Solve& solve)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor   vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor     face_descriptor;
  typedef typename boost::property_traits<VertexDistanceMap>::value_type  FT;

  const std::vector<vertex_descriptor> all_sources(std::begin(sources), std::end(sources));
  if(all_sources.empty())
    return ERROR_WRONG_PARAMETER;
  if(faces(tm).empty())
    return ERROR_EMPTY_MESH;

  std::vector<std::pair<vertex_descriptor, double> > results;
  std::vector<bool> done(all_sources.size(), false);
  for(std::size_t s = 0; s < all_sources.size(); ++s)
  {
    if(done[s])
      continue;
    face_descriptor seed = boost::graph_traits<TriangleMesh>::null_face();
    if(halfedge(all_sources[s], tm) != boost::graph_traits<TriangleMesh>::null_halfedge())
      for(halfedge_descriptor h : halfedges_around_target(halfedge(all_sources[s], tm), tm))
        if(!is_border(h, tm))
        {
          seed = face(h, tm);
          break;
        }
    if(seed == boost::graph_traits<TriangleMesh>::null_face())  // isolated vertex
    {
      results.emplace_back(all_sources[s], 0.);
      done[s] = true;
      continue;
    }

    Disk<TriangleMesh, SolverTraits> patch;
    Error_code status = patch.build_component(tm, seed, vpm);
    if(status != OK)
      return status;
    std::vector<int> local_sources;
    for(std::size_t t = s; t < all_sources.size(); ++t)
    {
      const int id = patch.index(all_sources[t]);
      if(id >= 0)
      {
        local_sources.push_back(id);
        done[t] = true;
      }
    }
    std::vector<double> values;
    status = solve(patch, local_sources, values);
    if(status != OK)
      return status;
    for(std::size_t i = 0; i < values.size(); ++i)  // in the mesh's unit of length
      results.emplace_back(patch.vertex(i), values[i] * patch.length_unit());
  }
  for(const auto& r : results)
    put(distance_map, r.first, FT(r.second));
  return OK;
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DISTANCES_SOURCE_COMPONENTS_H
