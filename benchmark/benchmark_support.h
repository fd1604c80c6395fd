// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// Helpers shared by the benchmark programs.

#ifndef MBP_BENCHMARK_SUPPORT_H
#define MBP_BENCHMARK_SUPPORT_H

#include "../cli/text_output.h"

#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Dynamic_property_map.h>
#include <CGAL/number_utils.h>

#include <boost/graph/graph_traits.hpp>

#include <Eigen/Core>
#include <Eigen/Sparse>

#include <algorithm>
#include <array>
#include <cstddef>
#include <filesystem>
#include <iterator>
#include <string>
#include <system_error>
#include <vector>

namespace mbp_benchmark {

// The mesh files (.off, .obj, .ply, .stl) of the folder `dir`, sorted; when `only` is not
// empty, those of its file names only. Empty when the folder cannot be read.
inline std::vector<std::filesystem::path> mesh_files_in(const std::string& dir,
                                                        const std::vector<std::string>& only = {})
{
  std::error_code ec;
  std::vector<std::filesystem::path> files = mbp_cli::mesh_files_in(dir, ec);
  if(ec)
    files.clear();
  files.erase(std::remove_if(files.begin(), files.end(),
                             [&only](const std::filesystem::path& p) {
                               return !only.empty() &&
                                      std::find(only.begin(), only.end(), p.filename().string()) == only.end();
                             }),
              files.end());
  return files;
}

// Why the mesh is not a single disk ("2 components", "closed", "3 borders", "genus 1"), or an
// empty string when it is one.
template <class TriangleMesh>
std::string not_a_disk(TriangleMesh& mesh)
{
  auto fcc = get(CGAL::dynamic_face_property_t<std::size_t>(), mesh);
  const std::size_t components = CGAL::Polygon_mesh_processing::connected_components(mesh, fcc);
  if(components != 1)
    return std::to_string(components) + " components";
  std::vector<typename boost::graph_traits<TriangleMesh>::halfedge_descriptor> borders;
  CGAL::Polygon_mesh_processing::extract_boundary_cycles(mesh, std::back_inserter(borders));
  if(borders.empty())
    return "closed";
  if(borders.size() > 1)
    return std::to_string(borders.size()) + " borders";
  const long chi = long(num_vertices(mesh)) - long(num_edges(mesh)) + long(num_faces(mesh));
  if(chi != 1)
    return "genus " + std::to_string((1 - chi) / 2);
  return "";
}

// (CGAL::Surface_mesh)
// 1-to-4 midpoint subdivision: every edge split at its midpoint, every triangle into four.
// The surface does not move. Returns false on a non-triangle face.
template <class Mesh>
bool midpoint_subdivision(const Mesh& in, Mesh& out)
{
  out.clear();
  out.reserve(num_vertices(in) + num_edges(in), 2 * num_edges(in) + 3 * num_faces(in), 4 * num_faces(in));
  std::vector<typename Mesh::Vertex_index> corner(in.number_of_vertices() + in.number_of_removed_vertices());
  std::vector<typename Mesh::Vertex_index> middle(in.number_of_edges() + in.number_of_removed_edges());
  for(typename Mesh::Vertex_index v : vertices(in))
    corner[v.idx()] = out.add_vertex(in.point(v));
  for(auto e : edges(in))
    middle[e.idx()] = out.add_vertex(CGAL::midpoint(in.point(source(halfedge(e, in), in)),
                                                    in.point(target(halfedge(e, in), in))));
  for(auto f : faces(in))
  {
    const typename Mesh::Halfedge_index h0 = halfedge(f, in), h1 = next(h0, in), h2 = next(h1, in);
    if(next(h2, in) != h0)
      return false;
    const typename Mesh::Vertex_index a = corner[source(h0, in).idx()], b = corner[source(h1, in).idx()],
                            c = corner[source(h2, in).idx()];
    const typename Mesh::Vertex_index ab = middle[edge(h0, in).idx()], bc = middle[edge(h1, in).idx()],
                            ca = middle[edge(h2, in).idx()];
    if(out.add_face(a, ab, ca) == Mesh::null_face() || out.add_face(ab, b, bc) == Mesh::null_face() ||
       out.add_face(ca, bc, c) == Mesh::null_face() || out.add_face(ab, bc, ca) == Mesh::null_face())
      return false;
  }
  return true;
}

// The interior cotangent Laplacian L_II of the disk bounded by the border loop of `bhd`: the
// matrix that Conformal_parameterizer_3 factorizes once per call, here for the benchmarks'
// factorization floors, assembled from the mesh with Eigen (the package's own assembly is
// internal). L = D - W with w_ij = (cot a_ij + cot b_ij) / 2 over the faces of the component
// of face(opposite(bhd)); its rows and columns are the vertices not on the loop of `bhd`,
// numbered as the package numbers them: vertices in the order first seen by a depth-first walk
// of the faces from face(opposite(bhd)) (each face's corners in the order of its halfedges'
// targets), then one vertex per hole, which the package adds to fill it virtually (at the
// centroid of the hole's loop lifted by a fifth of the loop's mean radius along its normal),
// joined to the loop by a fan of triangles. The package also scales the mesh by a power of
// two, which changes no weight. Returns false when a face is not a triangle or `bhd` is not a
// border halfedge.
template <class TriangleMesh>
bool interior_cotangent_laplacian(const TriangleMesh& mesh,
                                  typename boost::graph_traits<TriangleMesh>::halfedge_descriptor bhd,
                                  Eigen::SparseMatrix<double>& A)
{
  typedef boost::graph_traits<TriangleMesh>               Traits;
  typedef typename Traits::halfedge_descriptor            halfedge_descriptor;
  typedef typename Traits::face_descriptor                face_descriptor;
  if(bhd == Traits::null_halfedge() || !is_border(bhd, mesh))
    return false;
  const auto vpm = get(CGAL::vertex_point, mesh);
  auto index = get(CGAL::dynamic_vertex_property_t<int>(), mesh);
  auto visited = get(CGAL::dynamic_face_property_t<bool>(), mesh);
  auto seen = get(CGAL::dynamic_halfedge_property_t<bool>(), mesh);
  for(auto v : vertices(mesh)) put(index, v, -1);
  for(face_descriptor f : faces(mesh)) put(visited, f, false);
  for(halfedge_descriptor h : halfedges(mesh)) put(seen, h, false);

  // the depth-first walk: vertices, triangles, and the border loops met
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<int, 3> > triangles;
  std::vector<halfedge_descriptor> loops;
  std::vector<face_descriptor> stack(1, face(opposite(bhd, mesh), mesh));
  put(visited, stack.back(), true);
  while(!stack.empty())
  {
    const face_descriptor f = stack.back();
    stack.pop_back();
    std::array<int, 3> t;
    std::size_t degree = 0;
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
    {
      if(degree == 3)
        return false;
      if(get(index, target(h, mesh)) < 0)
      {
        put(index, target(h, mesh), int(points.size()));
        const auto& p = get(vpm, target(h, mesh));
        points.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
      }
      t[degree++] = get(index, target(h, mesh));
      const halfedge_descriptor o = opposite(h, mesh);
      if(is_border(o, mesh) && !get(seen, o))
      {
        loops.push_back(o);
        for(halfedge_descriptor b : CGAL::halfedges_around_face(o, mesh))
          put(seen, b, true);
      }
      else if(!is_border(o, mesh) && !get(visited, face(o, mesh)))
      {
        put(visited, face(o, mesh), true);
        stack.push_back(face(o, mesh));
      }
    }
    if(degree != 3)
      return false;
    triangles.push_back(t);
  }
  if(!get(seen, bhd))
    return false;

  // the rows: every vertex but those of the loop of bhd, then one vertex per hole
  std::vector<int> row(points.size(), 0);
  for(halfedge_descriptor h : CGAL::halfedges_around_face(bhd, mesh))
    row[std::size_t(get(index, source(h, mesh)))] = -1;
  int rows = 0;
  for(int& r : row)
    if(r == 0)
      r = rows++;
  for(halfedge_descriptor o : loops)
  {
    bool main_loop = false;
    std::vector<int> loop;
    for(halfedge_descriptor b : CGAL::halfedges_around_face(o, mesh))
    {
      main_loop = main_loop || b == bhd;
      loop.push_back(get(index, source(b, mesh)));
    }
    if(main_loop)
      continue;
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero(), normal = Eigen::Vector3d::Zero();
    for(int i : loop)
      centroid += points[std::size_t(i)];
    centroid /= double(loop.size());
    double radius = 0.;
    for(std::size_t k = 0; k < loop.size(); ++k)
    {
      const Eigen::Vector3d a = points[std::size_t(loop[k])] - centroid;
      normal += a.cross(points[std::size_t(loop[(k + 1) % loop.size()])] - centroid);
      radius += a.norm() / double(loop.size());
    }
    const int c = int(points.size());
    points.push_back(normal.norm() > 0. ? Eigen::Vector3d(centroid + 0.2 * radius * normal.normalized()) : centroid);
    row.push_back(rows++);
    for(std::size_t k = 0; k < loop.size(); ++k)
      triangles.push_back({{loop[k], loop[(k + 1) % loop.size()], c}});
  }

  // w = half the cotangent of the opposite corner, from each face of the edge
  std::vector<Eigen::Triplet<double> > entries;
  entries.reserve(12 * triangles.size());
  for(const std::array<int, 3>& t : triangles)
  {
    const Eigen::Vector3d& p0 = points[std::size_t(t[0])];
    const double double_area = (points[std::size_t(t[1])] - p0).cross(points[std::size_t(t[2])] - p0).norm();
    for(std::size_t k = 0; k < 3; ++k)
    {
      const Eigen::Vector3d& p = points[std::size_t(t[k])];
      const int i = row[std::size_t(t[(k + 1) % 3])], j = row[std::size_t(t[(k + 2) % 3])];
      const double w = 0.5 * (points[std::size_t(t[(k + 1) % 3])] - p).dot(points[std::size_t(t[(k + 2) % 3])] - p) /
                       double_area;
      if(i >= 0) entries.emplace_back(i, i, w);
      if(j >= 0) entries.emplace_back(j, j, w);
      if(i >= 0 && j >= 0)
      {
        entries.emplace_back(i, j, -w);
        entries.emplace_back(j, i, -w);
      }
    }
  }
  A.resize(rows, rows);
  A.setFromTriplets(entries.begin(), entries.end());
  A.makeCompressed();
  return true;
}

} // namespace mbp_benchmark

#endif // MBP_BENCHMARK_SUPPORT_H
