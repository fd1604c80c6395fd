// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DISTANCES_GEODESIC_SOLVERS_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DISTANCES_GEODESIC_SOLVERS_H

// One solver class per geodesic method, working on a checked disk. A solver does
// its source-independent work once in its constructor (adjacency, a triangle mesh copy, the
// heat method's factorizations) and then computes distances from any set of sources. The
// patch shares one solver per method between the center locator and the border distance
// (the disk's shared_object()).

#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/geodesic_method_tags.h>
#include <CGAL/Surface_mesh_parameterization/internal/distances/fast_marching_solver.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Heat_method_3/Surface_mesh_geodesic_distances_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_shortest_path.h>

#include <boost/graph/compressed_sparse_row_graph.hpp>
#include <boost/graph/dijkstra_shortest_paths.hpp>
#include <boost/property_map/property_map.hpp>

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// A Surface_mesh copy of the patch: vertex i is the patch's local vertex i.
template <class Point_3>
std::unique_ptr<CGAL::Surface_mesh<Point_3> > patch_surface_mesh(const std::vector<Eigen::Vector3d>& points,
                                                                 const std::vector<std::array<int, 3> >& faces)
{
  typedef CGAL::Surface_mesh<Point_3> SM;
  std::unique_ptr<SM> sm = std::make_unique<SM>();
  sm->reserve(static_cast<typename SM::size_type>(points.size()),
              static_cast<typename SM::size_type>(3 * faces.size()),
              static_cast<typename SM::size_type>(faces.size()));
  for(const Eigen::Vector3d& p : points)
    sm->add_vertex(Point_3(p.x(), p.y(), p.z()));
  for(const std::array<int, 3>& t : faces)
    sm->add_face(typename SM::Vertex_index(static_cast<typename SM::size_type>(t[0])),
                 typename SM::Vertex_index(static_cast<typename SM::size_type>(t[1])),
                 typename SM::Vertex_index(static_cast<typename SM::size_type>(t[2])));
  return sm;
}

// ---------------------------------------------------------------- Dijkstra along edges

template <>
class Geodesic_solver<Dijkstra_geodesics>
{
  typedef boost::compressed_sparse_row_graph<boost::directedS, boost::no_property,
                                             boost::property<boost::edge_weight_t, double> > Graph;

public:
  template <class Patch>
  explicit Geodesic_solver(const Patch& patch)
  {
    // every edge once per direction: a face halfedge (a, b) gives the arc a -> b, and a
    // border edge (no other face) also b -> a
    std::vector<std::pair<int, int> > arcs;
    std::vector<double> lengths;
    const auto& faces = patch.faces_indices();
    const auto& single = patch.single_edge_masks();
    arcs.reserve(3 * faces.size() + patch.border().size());
    lengths.reserve(arcs.capacity());
    for(std::size_t f = 0; f < faces.size(); ++f)
      for(int k = 0; k < 3; ++k)
      {
        const int a = faces[f][static_cast<std::size_t>((k + 1) % 3)];
        const int b = faces[f][static_cast<std::size_t>((k + 2) % 3)];
        const double l = (patch.point(static_cast<std::size_t>(a)) - patch.point(static_cast<std::size_t>(b))).norm();
        arcs.emplace_back(a, b);
        lengths.push_back(l);
        if((single[f] >> k) & 1)
        {
          arcs.emplace_back(b, a);
          lengths.push_back(l);
        }
      }
    m_graph = std::make_unique<Graph>(boost::edges_are_unsorted_multi_pass, arcs.begin(), arcs.end(),
                                      lengths.begin(), patch.number_of_vertices());
  }

  Error_code compute(const std::vector<int>& sources, std::vector<double>& distances) const
  {
    const std::size_t n = boost::num_vertices(*m_graph);
    distances.assign(n, std::numeric_limits<double>::infinity());
    std::vector<std::size_t> predecessor(n);
    std::vector<std::size_t> vertex_sources(sources.begin(), sources.end());
    boost::dijkstra_shortest_paths(*m_graph, vertex_sources.begin(), vertex_sources.end(),
      boost::make_iterator_property_map(predecessor.begin(), boost::get(boost::vertex_index, *m_graph)),
      boost::make_iterator_property_map(distances.begin(), boost::get(boost::vertex_index, *m_graph)),
      boost::get(boost::edge_weight, *m_graph), boost::get(boost::vertex_index, *m_graph),
      std::less<double>(), boost::closed_plus<double>(), std::numeric_limits<double>::infinity(), 0.,
      boost::default_dijkstra_visitor());
    return check_distances(distances);
  }

private:
  std::unique_ptr<Graph> m_graph;
};

// ---------------------------------------------------------------- heat method (CGAL)

template <class Mode>
class Geodesic_solver<Heat_method_geodesics<Mode> >
{
  typedef CGAL::Simple_cartesian<double>::Point_3                            Point_3;
  typedef CGAL::Surface_mesh<Point_3>                                        SM;
  typedef CGAL::Heat_method_3::Surface_mesh_geodesic_distances_3<SM, Mode>   Heat;

public:
  // builds the mesh copy and the heat method's matrices and factorizations
  template <class Patch>
  explicit Geodesic_solver(const Patch& patch)
    : m_mesh(patch_surface_mesh<Point_3>(patch.points(), patch.faces_indices())),
      m_heat(std::make_unique<Heat>(*m_mesh))
  { }

  Error_code compute(const std::vector<int>& sources, std::vector<double>& distances) const
  {
    std::vector<typename SM::Vertex_index> vs;
    for(int s : sources)
      vs.emplace_back(static_cast<typename SM::size_type>(s));
    m_heat->clear_sources();
    m_heat->add_sources(vs);
    distances.assign(m_mesh->number_of_vertices(), 0.);
    m_heat->estimate_geodesic_distances(boost::make_iterator_property_map(
      distances.begin(), get(boost::vertex_index, *m_mesh)));
    for(int s : sources)  // the heat method's sources are at ~0 up to its normalisation
      distances[static_cast<std::size_t>(s)] = 0.;
    return check_distances(distances);
  }

private:
  std::unique_ptr<SM> m_mesh;
  std::unique_ptr<Heat> m_heat;
};

// ---------------------------------------------------------------- exact (CGAL)

template <>
class Geodesic_solver<Exact_geodesics>
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel                K;
  typedef CGAL::Surface_mesh<K::Point_3>                                     SM;
  typedef CGAL::Surface_mesh_shortest_path_traits<K, SM>                     Traits;
  typedef CGAL::Surface_mesh_shortest_path<Traits>                           Shortest_path;

public:
  template <class Patch>
  explicit Geodesic_solver(const Patch& patch)
    : m_mesh(patch_surface_mesh<K::Point_3>(patch.points(), patch.faces_indices())),
      m_paths(std::make_unique<Shortest_path>(*m_mesh)),
      m_neighbors(patch.number_of_vertices())
  {
    // every edge once: from its interior side, or from its only face
    const auto& faces = patch.faces_indices();
    const auto& single = patch.single_edge_masks();
    for(std::size_t f = 0; f < faces.size(); ++f)
      for(int k = 0; k < 3; ++k)
      {
        const int a = faces[f][static_cast<std::size_t>((k + 1) % 3)];
        const int b = faces[f][static_cast<std::size_t>((k + 2) % 3)];
        if(((single[f] >> k) & 1) || a < b)
        {
          m_neighbors[static_cast<std::size_t>(a)].push_back(b);
          m_neighbors[static_cast<std::size_t>(b)].push_back(a);
        }
      }
  }

  // CGAL 5.5's Surface_mesh_shortest_path fails (an assertion, or undefined behaviour when
  // assertions are off) when two sources are the ends of one edge (CGAL issue #8499): of a
  // border edge, and also of an interior edge joining two border vertices (an ear triangle),
  // which the sanitizer build with assertions on found on a flat hexagonal disk. The sources
  // are therefore split into groups without such a pair (greedy colouring), one sequence tree
  // per group, and the distance is the minimum over the groups.
  Error_code compute(const std::vector<int>& sources, std::vector<double>& distances) const
  {
    const std::size_t n = m_mesh->number_of_vertices();
    std::vector<int> group_of(n, -1);
    std::vector<std::vector<int> > groups;
    for(int s : sources)
    {
      if(group_of[static_cast<std::size_t>(s)] >= 0)
        continue;  // repeated source
      int g = 0;
      for(bool clash = true; clash; )
      {
        clash = false;
        for(int b : m_neighbors[static_cast<std::size_t>(s)])
          if(group_of[static_cast<std::size_t>(b)] == g)
          {
            clash = true;
            ++g;
            break;
          }
      }
      group_of[static_cast<std::size_t>(s)] = g;
      if(static_cast<std::size_t>(g) >= groups.size())
        groups.resize(static_cast<std::size_t>(g) + 1);
      groups[static_cast<std::size_t>(g)].push_back(s);
    }

    distances.assign(n, std::numeric_limits<double>::infinity());
    for(const std::vector<int>& group : groups)
    {
      m_paths->remove_all_source_points();
      for(int s : group)
        m_paths->add_source_point(typename SM::Vertex_index(static_cast<typename SM::size_type>(s)));
      m_paths->build_sequence_tree();
      for(typename SM::Vertex_index v : m_mesh->vertices())
      {
        const double d = CGAL::to_double(m_paths->shortest_distance_to_source_points(v).first);
        if(d >= 0. && d < distances[static_cast<std::size_t>(v)])
          distances[static_cast<std::size_t>(v)] = d;
      }
    }
    return check_distances(distances);
  }

private:
  std::unique_ptr<SM> m_mesh;
  std::unique_ptr<Shortest_path> m_paths;
  std::vector<std::vector<int> > m_neighbors;  // the vertices joined to each by an edge
};

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_DISTANCES_GEODESIC_SOLVERS_H
