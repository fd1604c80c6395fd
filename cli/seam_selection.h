// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// Seams for CGAL::Seam_mesh: reading, checking and writing a CGAL selection file
// (*.selection.txt), and the topology of a mesh cut along its seams, for messages that say
// what is wrong.
// Shared by the programs measured_parameterization and seam_parameterization.
//
// A selection file has three lines: the selected vertices, the selected faces and the
// selected edges, each as 0-based indices in the mesh's file order; an edge is a pair of
// vertex indices. Only the third line makes seams; the first two are checked and ignored.

#ifndef MBP_CLI_SEAM_SELECTION_H
#define MBP_CLI_SEAM_SELECTION_H

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Dynamic_property_map.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstddef>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <numeric>
#include <set>
#include <sstream>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

namespace mbp_cli {

namespace detail {

// The whitespace-separated tokens of `line`.
inline std::vector<std::string> tokens_of(const std::string& line)
{
  std::istringstream in(line);
  std::vector<std::string> tokens;
  std::string t;
  while(in >> t)
    tokens.push_back(t);
  return tokens;
}

// Reads `token` as a non-negative integer (digits only). Returns an empty string, or why not.
inline std::string parse_index(const std::string& token, std::size_t& value)
{
  const char* first = token.data();
  const char* last = first + token.size();
  const std::from_chars_result r = std::from_chars(first, last, value);
  if(token.empty() || token[0] == '-' || token[0] == '+' || r.ptr != last || r.ec == std::errc::invalid_argument)
    return "'" + token + "' is not an index (a non-negative integer)";
  if(r.ec == std::errc::result_out_of_range)
    return "index " + token + " is too large";
  return std::string();
}

inline const std::string& selection_format()
{
  static const std::string format =
    "a selection file has three lines: the selected vertices, the selected faces, and the seam edges as pairs"
    " of vertex indices";
  return format;
}

// The lines of the selection file `path` (without a final '\r'), or why it cannot be read.
inline std::string selection_lines(const std::string& path, std::vector<std::string>& lines)
{
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if(!fs::exists(status))
    return "no such file";
  if(fs::is_directory(status))
    return "it is a directory, not a selection file";
  std::ifstream in(path, std::ios::binary);
  if(!in)
    return std::string("cannot open: ") + std::strerror(errno);
  for(std::string line; std::getline(in, line);)
  {
    if(!line.empty() && line.back() == '\r')
      line.pop_back();
    lines.push_back(line);
  }
  if(in.bad())
    return std::string("cannot read it: ") + std::strerror(errno);
  if(lines.empty())
    return "the file is empty (" + selection_format() + ")";
  return std::string();
}

// The indices of the three lines. Every line holds indices. Lines 1 and 2, selected vertices
// and faces (`nv` and `nf` of them in the mesh), are checked so that a selection of another
// mesh or a file of another kind is recognized.
inline std::string selection_indices(const std::vector<std::string>& lines, std::size_t nv, std::size_t nf,
                                     const std::string& vertex_range, std::vector<std::size_t> (&indices)[3])
{
  const std::string& format = selection_format();
  for(std::size_t l = 0; l < lines.size(); ++l)
    for(const std::string& token : tokens_of(lines[l]))
    {
      if(l >= 3)
        return "line " + std::to_string(l + 1) + ": unexpected text after the seam edges of line 3 (" + format + ")";
      std::size_t i = 0;
      const std::string error = parse_index(token, i);
      if(!error.empty())
        return "line " + std::to_string(l + 1) + ": " + error + " (" + format + ")";
      if(l == 0 && i >= nv)
        return "line 1: selected vertex " + token + " is out of range" + vertex_range + "; is the file for another mesh?";
      if(l == 1 && i >= nf)
        return "line 2: selected face " + token + " is out of range (the mesh has " + std::to_string(nf) +
               " faces); is the file for another mesh?";
      indices[l].push_back(i);
    }
  return std::string();
}

// The seam edges of the pairs of vertex indices `e` (line 3) into `seams`, or the first pair
// that is not an interior edge of `tm` given once.
template <class TriangleMesh>
std::string seam_edges(const std::vector<std::size_t>& e, const TriangleMesh& tm, const std::string& vertex_range,
                       std::vector<typename boost::graph_traits<TriangleMesh>::edge_descriptor>& seams)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::edge_descriptor   edge_descriptor;
  const std::vector<vertex_descriptor> by_index(vertices(tm).begin(), vertices(tm).end());
  const std::size_t nv = by_index.size();
  std::map<edge_descriptor, std::size_t> first_pair;  // edge -> its pair number (from 1)
  for(std::size_t k = 0; k < e.size(); k += 2)
  {
    const std::size_t a = e[k], b = e[k + 1], pair = k / 2 + 1;
    const std::string where = "line 3, seam edge " + std::to_string(pair) + " (" + std::to_string(a) + " " +
                              std::to_string(b) + "): ";
    if(a >= nv || b >= nv)
      return where + "vertex index " + std::to_string(a >= nv ? a : b) + " is out of range" + vertex_range;
    if(a == b)
      return where + "not an edge: both ends are vertex " + std::to_string(a);
    const std::pair<edge_descriptor, bool> ed = edge(by_index[a], by_index[b], tm);
    if(!ed.second)
      return where + "vertices " + std::to_string(a) + " and " + std::to_string(b) + " are not joined by an edge of the mesh";
    if(is_border(ed.first, tm))
      return where + "it is an edge of the mesh's border, which is already open; seams must be interior edges";
    const auto inserted = first_pair.emplace(ed.first, pair);
    if(!inserted.second)
      return where + "the same edge as seam edge " + std::to_string(inserted.first->second);
    seams.push_back(ed.first);
  }
  return std::string();
}

} // namespace detail

/// reads the seams of the CGAL selection file `path` for the mesh `tm`: the edges of its
/// third line, as pairs of 0-based vertex indices in the order of `vertices(tm)` (the file
/// order for a mesh read from a file, as in CGAL's `Seam_mesh::add_seams()`). On success,
/// returns an empty string and sets `seams` to the edges, in file order. Otherwise returns
/// the first problem, naming the line and the edge: no such file, not three lines, a token
/// that is not an index, an index out of range, an odd number of indices, no edge, a pair
/// that is not an edge of `tm`, an edge on the border of `tm` (already cut), an edge given
/// twice. The caller prefixes the file name.
///
/// \tparam TriangleMesh a model of `FaceListGraph` and `VertexListGraph`.
template <class TriangleMesh>
std::string read_seam_selection(const std::string& path, const TriangleMesh& tm,
                                std::vector<typename boost::graph_traits<TriangleMesh>::edge_descriptor>& seams)
{
  seams.clear();
  const std::string& format = detail::selection_format();
  std::vector<std::string> lines;
  std::string error = detail::selection_lines(path, lines);
  if(!error.empty())
    return error;
  const std::size_t nv = static_cast<std::size_t>(std::distance(vertices(tm).begin(), vertices(tm).end()));
  const std::size_t nf = static_cast<std::size_t>(std::distance(faces(tm).begin(), faces(tm).end()));
  const std::string vertex_range = " (the mesh has " + std::to_string(nv) + " vertices, numbered from 0 in file order)";
  std::vector<std::size_t> indices[3];
  error = detail::selection_indices(lines, nv, nf, vertex_range, indices);
  if(!error.empty())
    return error;
  // line 3: the seam edges
  if(lines.size() < 3)
    return "it has " + std::to_string(lines.size()) + (lines.size() == 1 ? " line" : " lines") +
           ", so no seam edges (" + format + ")";
  const std::vector<std::size_t>& e = indices[2];
  if(e.empty())
    return "line 3 lists no seam edge (" + format + ")";
  if(e.size() % 2 != 0)
    return "line 3 has an odd number of vertex indices (" + std::to_string(e.size()) +
           "): seam edges are pairs of vertex indices";
  return detail::seam_edges(e, tm, vertex_range, seams);
}

/// the text of the CGAL selection file of the seams `seams` (edges of `tm`), which
/// `read_seam_selection()` reads back: line 1 the selected vertices (`cones`), line 2 the
/// selected faces (none), line 3 the seam edges as pairs of 0-based vertex indices in the
/// order of `vertices(tm)`. The cones are given by their positions in `vertices(tm)` (as
/// `Disk_seams_report::cones`).
template <class TriangleMesh>
std::string seam_selection_text(const TriangleMesh& tm,
                                const std::vector<typename boost::graph_traits<TriangleMesh>::edge_descriptor>& seams,
                                const std::vector<std::size_t>& cones)
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  auto index = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
  std::size_t i = 0;
  for(vertex_descriptor v : vertices(tm))
    put(index, v, i++);
  std::string text;
  for(std::size_t k = 0; k < cones.size(); ++k)
    text += (k > 0 ? " " : "") + std::to_string(cones[k]);
  text += "\n\n";
  for(std::size_t k = 0; k < seams.size(); ++k)
    text += (k > 0 ? " " : "") + std::to_string(get(index, source(seams[k], tm))) + " " +
            std::to_string(get(index, target(seams[k], tm)));
  text += "\n";
  return text;
}

/// The topology of a triangle mesh, or of a `Seam_mesh` (a mesh cut along its seams), for
/// messages: the number of vertices in faces, of edges, faces, border loops and connected
/// components, the Euler characteristic and, for one component, the genus.
struct Mesh_topology
{
  std::size_t vertices = 0, edges = 0, faces = 0, border_loops = 0, components = 0;
  long euler_characteristic = 0;
  /// (2 c - chi - b) / 2 for c components: the genus of a single component
  long genus = 0;
};

/// the topology of `g`: vertices that are in a face, edges, faces, border loops (cycles of
/// border halfedges), connected components (faces joined across edges that are not on a
/// border), Euler characteristic `V - E + F`, and genus.
///
/// \tparam FaceGraph a model of `FaceListGraph` and `HalfedgeListGraph` (`Surface_mesh`,
///         `Seam_mesh`, ...)
template <class FaceGraph>
Mesh_topology mesh_topology(const FaceGraph& g)
{
  typedef typename boost::graph_traits<FaceGraph>::vertex_descriptor   vertex_descriptor;
  typedef typename boost::graph_traits<FaceGraph>::halfedge_descriptor halfedge_descriptor;
  typedef typename boost::graph_traits<FaceGraph>::face_descriptor     face_descriptor;
  Mesh_topology t;
  for(vertex_descriptor v : vertices(g))
    if(halfedge(v, g) != boost::graph_traits<FaceGraph>::null_halfedge())
      ++t.vertices;
  t.edges = static_cast<std::size_t>(std::distance(edges(g).begin(), edges(g).end()));

  // faces: numbered, then joined by union-find across the edges with a face on both sides
  auto number = get(CGAL::dynamic_face_property_t<std::size_t>(), g);
  for(face_descriptor f : faces(g))
    put(number, f, t.faces++);
  std::vector<std::size_t> parent(t.faces);
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  auto root = [&parent](std::size_t i) {
    while(parent[i] != i)
      i = parent[i] = parent[parent[i]];
    return i;
  };
  std::set<halfedge_descriptor> walked;  // border halfedges already on a counted loop
  for(halfedge_descriptor h : halfedges(g))
  {
    if(is_border(h, g))
    {
      if(walked.count(h) > 0)
        continue;
      ++t.border_loops;
      for(halfedge_descriptor b : CGAL::halfedges_around_face(h, g))
        walked.insert(b);
    }
    else if(!is_border(opposite(h, g), g))
      parent[root(get(number, face(h, g)))] = root(get(number, face(opposite(h, g), g)));
  }
  for(std::size_t i = 0; i < t.faces; ++i)
    t.components += (root(i) == i) ? 1 : 0;
  t.euler_characteristic = static_cast<long>(t.vertices) - static_cast<long>(t.edges) + static_cast<long>(t.faces);
  t.genus = (2 * static_cast<long>(t.components) - t.euler_characteristic - static_cast<long>(t.border_loops)) / 2;
  return t;
}

/// checks that the seams cut the mesh into one piece and open no new border loop, which the
/// parameterization would take for a hole (a closed loop of seams on a torus leaves a
/// cylinder; a seam path that does not reach the border leaves a slit). `input` is the
/// topology of the mesh, `cut` that of the mesh cut along the seams. Returns an empty
/// string, or the problem. Handles left uncut are found by the parameterizer
/// (`ERROR_NO_TOPOLOGICAL_DISC`, see `explain_cut()`).
inline std::string check_cut(const Mesh_topology& input, const Mesh_topology& cut)
{
  if(cut.components > 1)
    return "the seams cut the mesh into " + std::to_string(cut.components) +
           " pieces (a closed loop of seams separates the surface); give seams that do not separate it";
  const std::size_t allowed = (std::max)(std::size_t(1), input.border_loops);
  if(cut.border_loops <= allowed)
    return std::string();
  const std::string loops = "the mesh cut along the seams has " + std::to_string(cut.border_loops) + " border loops";
  if(input.border_loops == 0)
    return loops + ", not one, so it is not a disk (a single closed loop of seams, such as a meridian of a torus,"
           " leaves a cylinder; seams in separate pieces leave holes): the seams must form one cut graph, a tree"
           " on a closed surface of genus 0, or 2g independent loops through common vertices for genus g (for a"
           " torus, a meridian and a longitude through one vertex)";
  return loops + " where the mesh has " + std::to_string(input.border_loops) +
         ": a closed loop of seams, or seams that do not reach the border, open new holes; join every seam to"
         " the border";
}

/// the explanation of an `ERROR_NO_TOPOLOGICAL_DISC` for a mesh cut along seams: `input`
/// is the topology of the mesh, `cut` that of the mesh cut along the seams.
inline std::string explain_cut(const Mesh_topology& input, const Mesh_topology& cut)
{
  auto plural = [](std::size_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
  };
  if(cut.genus > 0)
    return "the seams do not cut every handle: the cut mesh still has genus " + std::to_string(cut.genus) +
           " (with " + plural(cut.border_loops, "border loop", "border loops") + "); the mesh has genus " +
           std::to_string(input.genus) + ", so the seams must contain " + std::to_string(2 * input.genus) +
           " independent loops (for a torus, a meridian and a longitude through one vertex)";
  return "the border of the cut mesh touches itself or a vertex is non-manifold";
}

} // namespace mbp_cli

#endif // MBP_CLI_SEAM_SELECTION_H
