// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// Texture atlases (issue 22, item 6): the command-line program's atlas against xatlas's, on
// every mesh of ../shared/data/atlas and on the meshes of ../shared/data/meshes that are not
// disks. Both programs run as whole processes; both output OBJ files are measured by the same
// code below, which uses none of the package's headers (CGAL is used only to read the input
// meshes and for the exact orientation predicate of the overlap test).
//
//   atlas_comparison [--only=NAME]... [--mesh=FILE]... [--xatlas-only] [--sweep=B,B,...] [--out=DIR]
//                    [--timeout=SECONDS] [--ours=PROGRAM] [--xatlas=PROGRAM]
//                    [--atlas-dir=DIR] [--meshes-dir=DIR]
//   atlas_comparison --disks [--only=NAME]... [--mesh=FILE]... [--out=DIR] [--timeout=SECONDS]
//                    [--ours=PROGRAM] [--bff=PROGRAM] [--meshes-dir=DIR]
//   atlas_comparison --self-test [--out=DIR]
//
//   --only=NAME     only the mesh of this file name (repeatable)
//   --mesh=FILE     also this mesh file (repeatable; e.g. a refined 1M-face scan)
//   --xatlas-only   run xatlas only (ours: "not run")
//   --sweep=B,...   also run ours at each of these bounds of --max-area-spread (e.g.
//                   0.05,0.1,0.4,inf). Ours always runs four times per mesh besides: at its
//                   defaults, with --split=scale, with every bound lifted (--max-area-spread=inf
//                   --max-angle-distortion=inf --min-compactness=0: the previous issue's one
//                   chart per component) and at xatlas's own area spread on the mesh (rounded
//                   up to 4 decimals); the "Bounds" table and the issue 23 summary compare them
//   --out=DIR       where the OBJs, the programs' stdout and stderr go (default /tmp/mbp-atlas)
//   --timeout=S     a run is killed after S seconds of wall time (default 600)
//   --ours=PROGRAM  our command-line program (default: measured_parameterization of this build)
//   --xatlas=PROGRAM  xatlas's driver (default: ../shared/peers/xatlas-atlas beside the project)
//   --disks         issue 23's disk target instead: ours at its defaults against Boundary First
//                   Flattening's command line on the disks of the meshes folder (those the other
//                   mode skips; the atlas folder is not used; a --mesh file is kept if it is a
//                   disk); --xatlas-only, --sweep, --xatlas and --atlas-dir have no effect
//   --bff=PROGRAM   BFF's command line for --disks (default: ../shared/peers/bff-command-line
//                   beside the project)
//   --self-test     checks the measures on hand-made OBJs with known answers; exit 1 on failure
//
// Meshes: every file of the atlas folder; of the meshes folder, those that are not disks, decided
// by the topology of the polygon soup as read (vertex indices as stored): a disk is one
// component, no edge used by more than two polygons, one border loop (border loops = connected
// components of the graph of edges used once) and Euler characteristic V - E + F = 1 (V: the
// vertices used by a polygon). The lists of kept and skipped meshes are printed.
//
// Programs: `ours IN OUT.obj --json` (stdout: NAME.ours.json, stderr: NAME.ours.log) and
// `xatlas-atlas IN OUT.obj` (stdout and stderr: NAME.xatlas.log), each through this program
// re-executed as a small trampoline (--spawn) that fork()s and exec()s it, so that wait4()'s
// ru_maxrss is the program's own peak resident set (a child of a large process would inherit
// its parent's resident set in that figure; the children the program starts are not counted).
// Time: wall clock around the process (fork to the end of wait4), reading, solving and writing
// included. A run that exceeds the timeout is killed with its process group and reported as
// "timeout"; a non-zero exit or a signal is reported as such, never measured.
//
// Measures, the same for both outputs. The OBJ is read (v, vt, f with v/vt corners, g);
// polygons are cut into triangles by ear clipping in UV (a fan from corner 0 would fold over a
// concave corner of a simple UV polygon) for every measure below; a polygon with a corner
// without vt gives no triangle. 3D positions and UVs are compared exactly (as doubles).
// A triangle has zero 3D area when its area <= 1e-12 * (its longest edge)^2, and zero UV area
// likewise in UV.
//   UV corners   ours: corners of the output polygons that have a vt, where output polygon i
//                has the size of input polygon i, over the input's corners (must be 100%);
//                xatlas (which writes triangles): 3 * its triangles with UVs over 3 * the input's
//                triangles (polygons fanned), at most 100%
//   UV out       corners of the output's faces whose UV is outside [0,1]^2 (or not finite)
//   charts (printed)  the program's own count: xatlas's `charts=N`, our JSON's "charts" (shown,
//                not used)
//   charts g     ours: the distinct `g` groups that hold a face
//   charts cc    connected components of the triangles, two triangles being connected when
//                they share an edge whose two endpoints have the same 3D position and the same
//                UV on both sides
//   seam/sqrt(A) total 3D length of the edges shared by exactly two triangles (keyed by the
//                exact 3D positions of their endpoints) whose endpoints' UVs differ on the two
//                sides, divided by sqrt(total 3D area)
//   area spread  sum_T A_T |log(s a_T / A_T)| / sum_T A_T over the triangles of nonzero 3D and
//                UV area, A_T the 3D area, a_T the UV area, s = sum A_T / sum a_T (one global scale)
//   angle        mean over the corners of the triangles of nonzero 3D area of |UV angle - 3D
//                angle|, in degrees
//   util         sum of the UV triangles' areas (the square [0,1]^2 has area 1); xatlas prints
//                another figure (texels covered by its rasterized charts over its atlas's W x H)
//   flips        in each chart (component above), the orientation of the majority of its
//                triangles of nonzero 3D and UV area; counted: the triangles of nonzero 3D area
//                of the other orientation or of zero UV area. On consistently oriented input
//                that is the sign of the UV area. Misoriented input polygons (which our OBJ
//                keeps as the input has them) are not flips: orientation is carried across
//                the chart's edges shared by exactly two triangles, a triangle that runs along
//                such an edge the same way as its neighbour counting with its sign reversed,
//                and the majority is taken per component across those edges (the chart itself
//                unless edges of 3+ triangles join parts of it)
//   overlaps     pairs of triangles of nonzero UV area whose interiors intersect, anywhere in
//                the atlas: a uniform grid over the UV bounding boxes, then an exact test (the
//                interiors are disjoint iff an edge line of one triangle has every vertex of the
//                other on its closed outer side; CGAL's exact orientation predicate), so
//                triangles touching at a shared edge or vertex are not overlaps
//   s, MB        wall-clock seconds and peak resident set (ru_maxrss) of the whole process
//
// Disks (--disks): `ours IN OUT.obj --json` as above and `bff-command-line IN.obj OUT.obj`
// (stdout and stderr: NAME.bff.log; no option: the conformal map with boundary scale factors 0,
// one chart, not checked for folds), through the same trampoline. BFF reads OBJ only: another
// input is written (points and polygons as read, %.17g) as NAME.bff-in.obj into --out first.
// Both OBJs are measured by the same code (BFF's: one vt per vertex, positions and UVs printed
// with 6 decimals; UVs outside [0,1]^2 are not a failure). Per disk the target is "met" when ours
// has 0 flips, 0 overlapping pairs, angle <= 1.25 x BFF's and area spread <= max(0.25, BFF's);
// a BFF failure is reported, never measured (the disk then misses: nothing to compare with).
// Its summary: the disks that meet the target, how many maps of each are one-to-one, the medians
// (angles, ratio, area spreads) over the disks both completed, the disks ours splits although
// BFF's one chart is one-to-one within 0.25 (informative only), and the missed disks with why.
//
// Summary: median utilization of each program (and on the meshes both completed), median time
// ratio ours / xatlas on the meshes of >= 10000 input polygons, the slowest mesh, and the
// meshes where a target of issue 22 is missed (every mesh: exit 0, 100% UV corners, 0 flips,
// 0 overlaps, 0 UVs outside; time <= 0.2x xatlas's from 10000 polygons on; median utilization
// >= xatlas's).

#include "../cli/text_output.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/enum.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <iterator>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <vector>

#ifndef MBP_ATLAS_DIR
#define MBP_ATLAS_DIR ""
#endif
#ifndef MBP_MESH_DIR
#define MBP_MESH_DIR ""
#endif
#ifndef MBP_XATLAS_PROGRAM
#define MBP_XATLAS_PROGRAM ""
#endif
#ifndef MBP_CLI_PROGRAM
#define MBP_CLI_PROGRAM ""
#endif
#ifndef MBP_BFF_PROGRAM
#define MBP_BFF_PROGRAM ""
#endif

namespace {

namespace fs = std::filesystem;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef std::array<double, 3> P3;
typedef std::array<double, 2> P2;
typedef std::chrono::steady_clock Clock;

const double zero_area_ratio = 1e-12;  // zero area: area <= ratio * (longest edge)^2
const double pi = 3.14159265358979323846;

double seconds_since(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// ---------------------------------------------------------------------------------------
// Small geometry

P3 minus(const P3& a, const P3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
P2 minus(const P2& a, const P2& b) { return {a[0] - b[0], a[1] - b[1]}; }
double dot(const P3& a, const P3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double dot(const P2& a, const P2& b) { return a[0] * b[0] + a[1] * b[1]; }
P3 cross(const P3& a, const P3& b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double cross(const P2& a, const P2& b) { return a[0] * b[1] - a[1] * b[0]; }
double norm(const P3& a) { return std::sqrt(dot(a, a)); }
double length(const P3& a, const P3& b) { return norm(minus(a, b)); }

// The angle at corner a of the triangle (a, b, c), in radians (0 when an edge is degenerate).
double angle_3(const P3& a, const P3& b, const P3& c)
{
  const P3 u = minus(b, a), v = minus(c, a);
  return std::atan2(norm(cross(u, v)), dot(u, v));
}
double angle_2(const P2& a, const P2& b, const P2& c)
{
  const P2 u = minus(b, a), v = minus(c, a);
  return std::atan2(std::abs(cross(u, v)), dot(u, v));
}

// Longest squared edge of a triangle.
template <class P>
double longest_squared_edge(const P& a, const P& b, const P& c)
{
  const P ab = minus(b, a), bc = minus(c, b), ca = minus(a, c);
  return std::max({dot(ab, ab), dot(bc, bc), dot(ca, ca)});
}

// ---------------------------------------------------------------------------------------
// Union-find over 32-bit indices

struct Union_find
{
  std::vector<std::uint32_t> parent;
  explicit Union_find(std::size_t n) : parent(n)
  {
    for(std::size_t i = 0; i < n; ++i)
      parent[i] = std::uint32_t(i);
  }
  std::uint32_t find(std::uint32_t i)
  {
    while(parent[i] != i)
      i = parent[i] = parent[parent[i]];
    return i;
  }
  void unite(std::uint32_t a, std::uint32_t b) { parent[find(a)] = find(b); }
};

// ---------------------------------------------------------------------------------------
// The input mesh, read with CGAL's polygon soup reader (OFF, OBJ, PLY, STL), and its topology

struct Input
{
  std::vector<K::Point_3> points;
  std::vector<std::vector<std::size_t> > polygons;
  std::size_t corners = 0;
  std::size_t triangles = 0;  // polygons fanned
};

bool read_input(const std::string& path, Input& in)
{
  if(!CGAL::IO::read_polygon_soup(path, in.points, in.polygons) || in.polygons.empty())
    return false;
  for(const std::vector<std::size_t>& polygon : in.polygons)
  {
    for(std::size_t v : polygon)
      if(v >= in.points.size())
        return false;
    in.corners += polygon.size();
    in.triangles += polygon.size() >= 3 ? polygon.size() - 2 : 0;
  }
  return true;
}

struct Topology
{
  std::size_t components = 0;
  std::size_t border_loops = 0;       // components of the graph of edges used once
  std::size_t nonmanifold_edges = 0;  // edges used by more than two polygons
  long euler = 0;                     // V - E + F, V = vertices used by a polygon
};

// The polygons' sides as sorted (min, max) vertex pairs.
std::vector<std::pair<std::uint32_t, std::uint32_t> > sorted_sides(const Input& in)
{
  std::vector<std::pair<std::uint32_t, std::uint32_t> > sides;
  sides.reserve(in.corners);
  for(const std::vector<std::size_t>& polygon : in.polygons)
    for(std::size_t i = 0; i < polygon.size(); ++i)
    {
      const std::uint32_t a = std::uint32_t(polygon[i]), b = std::uint32_t(polygon[(i + 1) % polygon.size()]);
      sides.emplace_back(std::min(a, b), std::max(a, b));
    }
  std::sort(sides.begin(), sides.end());
  return sides;
}

std::size_t count_roots(Union_find& uf, const std::vector<char>& member)
{
  std::size_t roots = 0;
  for(std::size_t i = 0; i < member.size(); ++i)
    roots += (member[i] && uf.find(std::uint32_t(i)) == i) ? 1 : 0;
  return roots;
}

Topology soup_topology(const Input& in)
{
  const std::size_t n = in.points.size();
  Topology t;
  Union_find all(n), border(n);
  std::vector<char> used(n, 0), on_border(n, 0);
  const auto sides = sorted_sides(in);
  std::size_t edges = 0;
  for(std::size_t i = 0, j = 0; i < sides.size(); i = j)
  {
    for(j = i; j < sides.size() && sides[j] == sides[i]; ++j) { }
    const auto [a, b] = sides[i];
    ++edges;
    all.unite(a, b);
    used[a] = used[b] = 1;
    if(j - i == 1)
    {
      border.unite(a, b);
      on_border[a] = on_border[b] = 1;
    }
    t.nonmanifold_edges += (j - i > 2) ? 1 : 0;
  }
  t.components = count_roots(all, used);
  t.border_loops = count_roots(border, on_border);
  t.euler = long(std::count(used.begin(), used.end(), 1)) - long(edges) + long(in.polygons.size());
  return t;
}

bool is_disk(const Topology& t)
{
  return t.components == 1 && t.nonmanifold_edges == 0 && t.border_loops == 1 && t.euler == 1;
}

std::string describe(const Topology& t)
{
  std::ostringstream s;
  s << t.components << (t.components == 1 ? " component, " : " components, ") << t.border_loops
    << " border loop(s), chi " << t.euler;
  if(t.nonmanifold_edges > 0)
    s << ", " << t.nonmanifold_edges << " edges in 3+ polygons";
  return s.str();
}

// ---------------------------------------------------------------------------------------
// An OBJ file: v, vt, f (v, v/vt, v/vt/vn, v//vn corners; negative indices), g

struct Obj
{
  std::vector<P3> v;
  std::vector<P2> vt;
  std::vector<long> corner_v, corner_vt;       // 0-based; corner_vt -1: no UV
  std::vector<std::size_t> first_corner{0};    // polygon p: corners [first_corner[p], first_corner[p + 1])
  std::vector<int> group;                      // polygon p's group, -1 before any g line
  std::unordered_map<std::string, int> group_ids;
  int current_group = -1;
  std::size_t polygons() const { return first_corner.size() - 1; }
};

bool load_file(const std::string& path, std::string& text)
{
  std::ifstream in(path, std::ios::binary);
  if(!in)
    return false;
  std::ostringstream s;
  s << in.rdbuf();
  text = s.str();
  return true;
}

// Reads n numbers at s (a null-terminated line); false when one is missing.
bool parse_numbers(const char* s, double* out, int n)
{
  for(int i = 0; i < n; ++i)
  {
    char* end = nullptr;
    out[i] = std::strtod(s, &end);
    if(end == s)
      return false;
    s = end;
  }
  return true;
}

// Resolves an OBJ index (1-based, or negative: relative to the count so far) to 0-based.
long resolve_index(long i, std::size_t count) { return i < 0 ? long(count) + i : i - 1; }

// Reads the corners of an f line (s: after "f").
bool parse_face(const char* s, Obj& obj)
{
  std::size_t corners = 0;
  while(true)
  {
    while(*s == ' ' || *s == '\t' || *s == '\r')
      ++s;
    if(*s == '\0')
      break;
    char* end = nullptr;
    const long v = std::strtol(s, &end, 10);
    if(end == s || v == 0)
      return false;
    long vt = 0;
    if(*end == '/' && end[1] != '/')
      vt = std::strtol(end + 1, &end, 10);
    obj.corner_v.push_back(resolve_index(v, obj.v.size()));
    obj.corner_vt.push_back(vt == 0 ? -1 : resolve_index(vt, obj.vt.size()));
    ++corners;
    for(s = end; *s != '\0' && *s != ' ' && *s != '\t' && *s != '\r'; ++s) { }
  }
  obj.first_corner.push_back(obj.corner_v.size());
  obj.group.push_back(obj.current_group);
  return corners >= 3;
}

void set_group(const char* s, Obj& obj)
{
  std::string name(s);
  while(!name.empty() && std::isspace(static_cast<unsigned char>(name.back())))
    name.pop_back();
  name.erase(0, name.find_first_not_of(" \t"));
  const auto inserted = obj.group_ids.emplace(name, int(obj.group_ids.size()));
  obj.current_group = inserted.first->second;
}

// One line; false on a malformed v, vt or f line.
bool parse_line(const char* s, Obj& obj)
{
  if(s[0] == 'v' && (s[1] == ' ' || s[1] == '\t'))
  {
    obj.v.emplace_back();
    return parse_numbers(s + 2, obj.v.back().data(), 3);
  }
  if(s[0] == 'v' && s[1] == 't' && (s[2] == ' ' || s[2] == '\t'))
  {
    obj.vt.emplace_back();
    return parse_numbers(s + 3, obj.vt.back().data(), 2);
  }
  if(s[0] == 'f' && (s[1] == ' ' || s[1] == '\t'))
    return parse_face(s + 2, obj);
  if(s[0] == 'g' && (s[1] == ' ' || s[1] == '\t'))
    set_group(s + 2, obj);
  return true;
}

// Every corner's indices in range.
bool indices_valid(const Obj& obj)
{
  for(std::size_t c = 0; c < obj.corner_v.size(); ++c)
    if(obj.corner_v[c] < 0 || obj.corner_v[c] >= long(obj.v.size()) || obj.corner_vt[c] < -1 ||
       obj.corner_vt[c] >= long(obj.vt.size()))
      return false;
  return true;
}

// Reads an OBJ; returns an error message, empty on success.
std::string read_obj(const std::string& path, Obj& obj)
{
  std::string text;
  if(!load_file(path, text))
    return "cannot read " + path;
  std::string line;
  std::size_t number = 0;
  for(std::size_t pos = 0; pos < text.size(); ++number)
  {
    std::size_t end = text.find('\n', pos);
    if(end == std::string::npos)
      end = text.size();
    line.assign(text, pos, end - pos);
    pos = end + 1;
    if(!parse_line(line.c_str(), obj))
      return "line " + std::to_string(number + 1) + " malformed: " + line.substr(0, 60);
  }
  if(!indices_valid(obj))
    return "an index out of range";
  return "";
}

// ---------------------------------------------------------------------------------------
// The atlas: the output's triangles with UVs on every corner, 3D positions and UVs welded
// (identical values, one index)

struct Atlas
{
  std::vector<P3> points;
  std::vector<P2> uvs;
  std::vector<std::array<std::uint32_t, 3> > p, u;  // per triangle: position and UV indices
  std::size_t corners = 0;          // corners of the output's polygons
  std::size_t corners_uv = 0;       // of which with a vt
  std::size_t corners_outside = 0;  // of which with a UV outside [0,1]^2
  std::size_t groups = 0;           // distinct g groups holding a face
};

template <std::size_t N>
struct Array_hash
{
  std::size_t operator()(const std::array<double, N>& a) const
  {
    std::size_t h = 0;
    for(double x : a)
      h = h * 1000003u ^ std::hash<double>()(x);
    return h;
  }
};

// The index of each value among the distinct values (exact comparison).
template <std::size_t N>
std::vector<std::uint32_t> weld(const std::vector<std::array<double, N> >& values,
                                std::vector<std::array<double, N> >& distinct)
{
  std::unordered_map<std::array<double, N>, std::uint32_t, Array_hash<N> > index;
  index.reserve(values.size());
  std::vector<std::uint32_t> id(values.size());
  for(std::size_t i = 0; i < values.size(); ++i)
  {
    const auto inserted = index.emplace(values[i], std::uint32_t(distinct.size()));
    if(inserted.second)
      distinct.push_back(values[i]);
    id[i] = inserted.first->second;
  }
  return id;
}

bool inside_unit_square(const P2& uv) { return uv[0] >= 0. && uv[0] <= 1. && uv[1] >= 0. && uv[1] <= 1.; }

// Twice the signed area of the UV triangle of corners a, b, c.
double uv_cross(const Obj& obj, std::size_t a, std::size_t b, std::size_t c)
{
  const P2 &p = obj.vt[obj.corner_vt[a]], &q = obj.vt[obj.corner_vt[b]], &r = obj.vt[obj.corner_vt[c]];
  return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
}

// The triangles of the polygon of corners [first, end) by ear clipping in UV: a simple UV
// polygon (as a one-to-one chart gives, convex or not) gets triangles that do not overlap,
// where a fan from corner 0 would fold over a concave corner. The fan finishes a polygon
// without an ear (not simple in UV).
std::vector<std::array<std::size_t, 3> > triangulate_in_uv(const Obj& obj, std::size_t first, std::size_t end)
{
  std::vector<std::size_t> ring;
  double orientation = 0.;
  for(std::size_t c = first; c < end; ++c)
  {
    ring.push_back(c);
    orientation += c + 2 < end ? uv_cross(obj, first, c + 1, c + 2) : 0.;
  }
  std::vector<std::array<std::size_t, 3> > triangles;
  while(ring.size() > 3)
  {
    const std::size_t n = ring.size();
    std::size_t ear = n;
    for(std::size_t i = 0; i < n && ear == n; ++i)
    {
      const std::size_t a = ring[(i + n - 1) % n], b = ring[i], c = ring[(i + 1) % n];
      bool empty = uv_cross(obj, a, b, c) * orientation > 0.;
      for(std::size_t k = 0; k < n && empty; ++k)
      {
        const std::size_t d = ring[k];
        if(d != a && d != b && d != c)
          empty = !(uv_cross(obj, a, b, d) * orientation >= 0. && uv_cross(obj, b, c, d) * orientation >= 0. &&
                    uv_cross(obj, c, a, d) * orientation >= 0.);
      }
      ear = empty ? i : n;
    }
    if(ear == n)
      break;
    triangles.push_back({ring[(ear + n - 1) % n], ring[ear], ring[(ear + 1) % n]});
    ring.erase(ring.begin() + std::ptrdiff_t(ear));
  }
  for(std::size_t i = 1; i + 1 < ring.size(); ++i)
    triangles.push_back({ring[0], ring[i], ring[i + 1]});
  return triangles;
}

// Counts the corners of polygon `f` and triangulates it (in UV) when every corner has a UV.
void add_polygon(const Obj& obj, std::size_t f, const std::vector<std::uint32_t>& pid,
                 const std::vector<std::uint32_t>& uid, Atlas& atlas)
{
  const std::size_t first = obj.first_corner[f], end = obj.first_corner[f + 1];
  std::size_t with_uv = 0;
  for(std::size_t c = first; c < end; ++c)
    if(obj.corner_vt[c] >= 0)
    {
      ++with_uv;
      atlas.corners_outside += inside_unit_square(obj.vt[obj.corner_vt[c]]) ? 0 : 1;
    }
  atlas.corners += end - first;
  atlas.corners_uv += with_uv;
  if(with_uv != end - first)
    return;
  for(const std::array<std::size_t, 3>& t : triangulate_in_uv(obj, first, end))
  {
    atlas.p.push_back({pid[obj.corner_v[t[0]]], pid[obj.corner_v[t[1]]], pid[obj.corner_v[t[2]]]});
    atlas.u.push_back({uid[obj.corner_vt[t[0]]], uid[obj.corner_vt[t[1]]], uid[obj.corner_vt[t[2]]]});
  }
}

Atlas make_atlas(const Obj& obj)
{
  Atlas atlas;
  const std::vector<std::uint32_t> pid = weld(obj.v, atlas.points);
  const std::vector<std::uint32_t> uid = weld(obj.vt, atlas.uvs);
  std::vector<char> group_used(obj.group_ids.size(), 0);
  for(std::size_t f = 0; f < obj.polygons(); ++f)
  {
    add_polygon(obj, f, pid, uid, atlas);
    if(obj.group[f] >= 0)
      group_used[obj.group[f]] = 1;
  }
  atlas.groups = std::size_t(std::count(group_used.begin(), group_used.end(), 1));
  return atlas;
}

// ---------------------------------------------------------------------------------------
// Measures of the atlas

// Areas and orientation of one triangle.
struct Shape
{
  double area_3 = 0.;
  double area_uv = 0.;  // unsigned
  int sign = 0;         // orientation in UV: +1, -1, or 0 for zero UV area
  bool flat_3 = false;  // zero 3D area
};

Shape shape_of(const Atlas& atlas, std::size_t t)
{
  const std::array<std::uint32_t, 3>& p = atlas.p[t];
  const std::array<std::uint32_t, 3>& u = atlas.u[t];
  const P3 &a = atlas.points[p[0]], &b = atlas.points[p[1]], &c = atlas.points[p[2]];
  const P2 &x = atlas.uvs[u[0]], &y = atlas.uvs[u[1]], &z = atlas.uvs[u[2]];
  Shape s;
  s.area_3 = 0.5 * norm(cross(minus(b, a), minus(c, a)));
  s.flat_3 = !(s.area_3 > zero_area_ratio * longest_squared_edge(a, b, c));
  const double twice_uv = cross(minus(y, x), minus(z, x));
  s.area_uv = 0.5 * std::abs(twice_uv);
  const bool zero_uv = !(s.area_uv > zero_area_ratio * longest_squared_edge(x, y, z));
  s.sign = zero_uv ? 0 : (twice_uv > 0. ? 1 : -1);
  return s;
}

std::vector<Shape> shapes_of(const Atlas& atlas)
{
  std::vector<Shape> shapes(atlas.p.size());
  for(std::size_t t = 0; t < shapes.size(); ++t)
    shapes[t] = shape_of(atlas, t);
  return shapes;
}

// One side of a triangle edge: its endpoints' positions (p0 <= p1) and their UVs; `backward`:
// the triangle's corner order goes from p1 to p0.
struct Edge_side
{
  std::uint32_t p0, p1, u0, u1, triangle;
  bool backward;
  bool same_3d(const Edge_side& o) const { return p0 == o.p0 && p1 == o.p1; }
  bool same_uv(const Edge_side& o) const { return same_3d(o) && u0 == o.u0 && u1 == o.u1; }
  bool operator<(const Edge_side& o) const
  {
    return std::tie(p0, p1, u0, u1, triangle) < std::tie(o.p0, o.p1, o.u0, o.u1, o.triangle);
  }
};

// Every side of every triangle, sorted: sides of one 3D edge are consecutive, and among them
// the sides with the same UVs.
std::vector<Edge_side> sorted_edge_sides(const Atlas& atlas)
{
  std::vector<Edge_side> sides;
  sides.reserve(3 * atlas.p.size());
  for(std::size_t t = 0; t < atlas.p.size(); ++t)
    for(int i = 0; i < 3; ++i)
    {
      Edge_side s{atlas.p[t][i], atlas.p[t][(i + 1) % 3], atlas.u[t][i], atlas.u[t][(i + 1) % 3],
                  std::uint32_t(t), false};
      if(s.p1 < s.p0 || (s.p1 == s.p0 && s.u1 < s.u0))
      {
        std::swap(s.p0, s.p1);
        std::swap(s.u0, s.u1);
        s.backward = true;
      }
      sides.push_back(s);
    }
  std::sort(sides.begin(), sides.end());
  return sides;
}

// Union-find that also keeps, for each element, whether its corner order is reversed relative to
// its root's ("reversed": parity relative to the parent, path compression keeps it relative to
// the root).
struct Oriented_union_find
{
  std::vector<std::uint32_t> parent;
  std::vector<char> reversed;
  explicit Oriented_union_find(std::size_t n) : parent(Union_find(n).parent), reversed(n, 0) { }
  std::uint32_t find(std::uint32_t i, bool& to_root)
  {
    std::uint32_t root = i;
    to_root = false;
    for(; parent[root] != root; root = parent[root])
      to_root ^= reversed[root] != 0;
    for(bool q = to_root; parent[i] != root && parent[i] != i;)
    {
      const std::uint32_t next = parent[i];
      const bool q_next = q ^ (reversed[i] != 0);
      parent[i] = root;
      reversed[i] = q;
      i = next;
      q = q_next;
    }
    return root;
  }
  // joins a and b, b's corner order being reversed relative to a's when `relative` is true
  void unite(std::uint32_t a, std::uint32_t b, bool relative)
  {
    bool pa = false, pb = false;
    const std::uint32_t ra = find(a, pa), rb = find(b, pb);
    if(ra != rb)
    {
      parent[ra] = rb;
      reversed[ra] = pa ^ pb ^ relative;
    }
  }
};

// The charts: components of the triangles across edges with the same positions and UVs on both
// sides. Orientation patches: the components across such edges shared by exactly two
// triangles, reversed[t] telling whether triangle t's corner order is reversed relative to its
// patch's (it runs along such an edge the same way as its neighbour: a misoriented input polygon).
struct Charts
{
  std::size_t count = 0, patches = 0;
  std::vector<std::uint32_t> label, patch;  // 0 .. count - 1, 0 .. patches - 1
  std::vector<char> reversed;
};

// Compact labels 0 .. n - 1 of the roots of the triangles; `reversed` filled when `oriented`.
template <class Find>
std::vector<std::uint32_t> component_labels(std::size_t triangles, Find find, std::size_t& n,
                                            std::vector<char>* reversed)
{
  std::vector<std::uint32_t> label(triangles), root_label(triangles, std::uint32_t(-1));
  n = 0;
  for(std::size_t t = 0; t < triangles; ++t)
  {
    bool flipped = false;
    const std::uint32_t r = find(std::uint32_t(t), flipped);
    if(root_label[r] == std::uint32_t(-1))
      root_label[r] = std::uint32_t(n++);
    label[t] = root_label[r];
    if(reversed)
      (*reversed)[t] = flipped;
  }
  return label;
}

Charts find_charts(const std::vector<Edge_side>& sides, std::size_t triangles)
{
  Union_find charts_uf(triangles);
  Oriented_union_find patches_uf(triangles);
  for(std::size_t i = 0, j = 0; i < sides.size(); i = j)
  {
    for(j = i + 1; j < sides.size() && sides[j].same_uv(sides[i]); ++j)
      charts_uf.unite(sides[j].triangle, sides[i].triangle);
    if(j - i == 2)
      patches_uf.unite(sides[i].triangle, sides[i + 1].triangle, sides[i].backward == sides[i + 1].backward);
  }
  Charts c;
  c.reversed.resize(triangles);
  c.label = component_labels(
    triangles, [&](std::uint32_t t, bool&) { return charts_uf.find(t); }, c.count, nullptr);
  c.patch = component_labels(
    triangles, [&](std::uint32_t t, bool& r) { return patches_uf.find(t, r); }, c.patches, &c.reversed);
  return c;
}

// Total 3D length of the edges shared by exactly two triangles whose UVs differ on the two sides.
double seam_length(const std::vector<Edge_side>& sides, const Atlas& atlas)
{
  double total = 0.;
  for(std::size_t i = 0, j = 0; i < sides.size(); i = j)
  {
    for(j = i; j < sides.size() && sides[j].same_3d(sides[i]); ++j) { }
    if(j - i == 2 && !sides[i].same_uv(sides[i + 1]))
      total += length(atlas.points[sides[i].p0], atlas.points[sides[i].p1]);
  }
  return total;
}

// Flipped triangles inside the charts (see the file's header): the majority orientation is taken
// per orientation patch, each triangle's UV orientation in its patch's corner order.
std::size_t count_flips(const std::vector<Shape>& shapes, const Charts& charts)
{
  std::vector<std::size_t> positive(charts.patches, 0), negative(charts.patches, 0);
  std::size_t zero = 0;
  for(std::size_t t = 0; t < shapes.size(); ++t)
  {
    if(shapes[t].flat_3)
      continue;
    const int sign = charts.reversed[t] ? -shapes[t].sign : shapes[t].sign;
    positive[charts.patch[t]] += sign > 0 ? 1 : 0;
    negative[charts.patch[t]] += sign < 0 ? 1 : 0;
    zero += sign == 0 ? 1 : 0;
  }
  std::size_t flips = zero;
  for(std::size_t c = 0; c < charts.patches; ++c)
    flips += std::min(positive[c], negative[c]);
  return flips;
}

// Area-weighted mean |log(s a / A)| over the triangles of nonzero 3D and UV area.
double area_spread(const std::vector<Shape>& shapes)
{
  double sum_3 = 0., sum_uv = 0.;
  for(const Shape& s : shapes)
    if(!s.flat_3 && s.sign != 0)
    {
      sum_3 += s.area_3;
      sum_uv += s.area_uv;
    }
  if(!(sum_3 > 0.) || !(sum_uv > 0.))
    return std::numeric_limits<double>::quiet_NaN();
  const double scale = sum_3 / sum_uv;
  double spread = 0.;
  for(const Shape& s : shapes)
    if(!s.flat_3 && s.sign != 0)
      spread += s.area_3 * std::abs(std::log(scale * s.area_uv / s.area_3));
  return spread / sum_3;
}

// Mean over the corners of the triangles of nonzero 3D area of |UV angle - 3D angle|, degrees.
double angle_distortion(const Atlas& atlas, const std::vector<Shape>& shapes)
{
  double sum = 0.;
  std::size_t corners = 0;
  for(std::size_t t = 0; t < shapes.size(); ++t)
  {
    if(shapes[t].flat_3)
      continue;
    for(int i = 0; i < 3; ++i)
    {
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      const std::array<std::uint32_t, 3>&p = atlas.p[t], &u = atlas.u[t];
      const double a3 = angle_3(atlas.points[p[i]], atlas.points[p[j]], atlas.points[p[k]]);
      const double a2 = angle_2(atlas.uvs[u[i]], atlas.uvs[u[j]], atlas.uvs[u[k]]);
      sum += std::abs(a2 - a3);
      ++corners;
    }
  }
  return corners == 0 ? std::numeric_limits<double>::quiet_NaN() : sum / double(corners) * 180. / pi;
}

// ---------------------------------------------------------------------------------------
// Overlapping pairs: a uniform grid over the UV bounding boxes, then an exact test

typedef std::array<K::Point_2, 3> Triangle_2;

// True when an edge line of `a` has every vertex of `b` on its closed outer side.
bool separated_by_an_edge_of(const Triangle_2& a, const Triangle_2& b)
{
  const CGAL::Orientation inside = CGAL::orientation(a[0], a[1], a[2]);
  for(int i = 0; i < 3; ++i)
  {
    const K::Point_2 &p = a[i], &q = a[(i + 1) % 3];
    if(CGAL::orientation(p, q, b[0]) != inside && CGAL::orientation(p, q, b[1]) != inside &&
       CGAL::orientation(p, q, b[2]) != inside)
      return true;
  }
  return false;
}

// The interiors of two triangles of nonzero area intersect (exact).
bool interiors_intersect(const Triangle_2& a, const Triangle_2& b)
{
  return !separated_by_an_edge_of(a, b) && !separated_by_an_edge_of(b, a);
}

struct Box
{
  double x0, y0, x1, y1;
};

bool boxes_overlap(const Box& a, const Box& b)  // open boxes
{
  return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}

// A uniform n x n grid over [x0, x0 + n cell) x [y0, y0 + n cell): the items of cell c are
// items[start[c] .. start[c + 1]).
struct Grid
{
  double x0 = 0., y0 = 0., cell = 1.;
  std::size_t n = 1;
  std::vector<std::size_t> start;
  std::vector<std::uint32_t> items;
  std::size_t column(double x) const { return std::min(n - 1, std::size_t(std::max(0., (x - x0) / cell))); }
  std::size_t row(double y) const { return std::min(n - 1, std::size_t(std::max(0., (y - y0) / cell))); }
  std::size_t cell_of(double x, double y) const { return row(y) * n + column(x); }
};

// Calls f(cell) for every cell that box b covers.
template <class F>
void for_each_cell(const Grid& g, const Box& b, F f)
{
  for(std::size_t r = g.row(b.y0); r <= g.row(b.y1); ++r)
    for(std::size_t c = g.column(b.x0); c <= g.column(b.x1); ++c)
      f(r * g.n + c);
}

// The grid: about one cell per box, over the boxes' bounds; false when the boxes cover more
// than `max_items` cells in all (degenerate layouts: the count would take too long).
bool build_grid(const std::vector<Box>& boxes, std::size_t max_items, Grid& g)
{
  Box all{boxes[0].x0, boxes[0].y0, boxes[0].x1, boxes[0].y1};
  for(const Box& b : boxes)
    all = {std::min(all.x0, b.x0), std::min(all.y0, b.y0), std::max(all.x1, b.x1), std::max(all.y1, b.y1)};
  g.n = std::max<std::size_t>(1, std::min<std::size_t>(4096, std::size_t(std::sqrt(double(boxes.size())))));
  g.x0 = all.x0;
  g.y0 = all.y0;
  g.cell = std::max({all.x1 - all.x0, all.y1 - all.y0, 1e-300}) / double(g.n);
  std::vector<std::size_t> count(g.n * g.n + 1, 0);
  std::size_t total = 0;
  for(const Box& b : boxes)
    for_each_cell(g, b, [&](std::size_t c) { ++count[c + 1]; ++total; });
  if(total > max_items)
    return false;
  for(std::size_t c = 1; c < count.size(); ++c)
    count[c] += count[c - 1];
  g.start = count;
  g.items.resize(total);
  for(std::size_t i = 0; i < boxes.size(); ++i)
    for_each_cell(g, boxes[i], [&](std::size_t c) { g.items[count[c]++] = std::uint32_t(i); });
  return true;
}

struct Overlaps
{
  std::size_t pairs = 0;
  bool complete = true;  // false: the layout is too degenerate for the grid (pairs: a lower bound)
};

// The pairs of cell c whose open boxes overlap and whose boxes' intersection starts in c (so
// that each pair is tested once), tested exactly; stops after `max_tests` tests in all.
void count_in_cell(const Grid& g, std::size_t c, const std::vector<Box>& boxes,
                   const std::vector<Triangle_2>& triangles, Overlaps& result, std::size_t& tests,
                   std::size_t max_tests)
{
  for(std::size_t i = g.start[c]; i < g.start[c + 1] && tests <= max_tests; ++i)
    for(std::size_t j = i + 1; j < g.start[c + 1]; ++j)
    {
      const Box &a = boxes[g.items[i]], &b = boxes[g.items[j]];
      if(!boxes_overlap(a, b) || g.cell_of(std::max(a.x0, b.x0), std::max(a.y0, b.y0)) != c)
        continue;
      ++tests;
      if(interiors_intersect(triangles[g.items[i]], triangles[g.items[j]]))
        ++result.pairs;
    }
}

Overlaps count_overlaps(const Atlas& atlas, const std::vector<Shape>& shapes)
{
  std::vector<Triangle_2> triangles;
  std::vector<Box> boxes;
  for(std::size_t t = 0; t < shapes.size(); ++t)
  {
    if(shapes[t].sign == 0)
      continue;  // no interior
    const std::array<std::uint32_t, 3>& u = atlas.u[t];
    Triangle_2 tri;
    for(int i = 0; i < 3; ++i)
      tri[i] = K::Point_2(atlas.uvs[u[i]][0], atlas.uvs[u[i]][1]);
    triangles.push_back(tri);
    boxes.push_back({std::min({tri[0].x(), tri[1].x(), tri[2].x()}), std::min({tri[0].y(), tri[1].y(), tri[2].y()}),
                     std::max({tri[0].x(), tri[1].x(), tri[2].x()}), std::max({tri[0].y(), tri[1].y(), tri[2].y()})});
  }
  Overlaps result;
  Grid g;
  if(boxes.empty() || !build_grid(boxes, 64 * boxes.size() + 1000000, g))
  {
    result.complete = boxes.empty();
    return result;
  }
  const std::size_t max_tests = 200 * boxes.size() + 10000000;
  std::size_t tests = 0;
  for(std::size_t c = 0; c + 1 < g.start.size() && tests <= max_tests; ++c)
    count_in_cell(g, c, boxes, triangles, result, tests, max_tests);
  result.complete = tests <= max_tests;
  return result;
}

// ---------------------------------------------------------------------------------------
// All measures of one OBJ

struct Metrics
{
  std::size_t polygons = 0, triangles = 0;
  std::size_t corners = 0, corners_uv = 0, corners_outside = 0;
  std::size_t groups = 0, charts = 0;
  double seam_ratio = 0., area_spread = 0., angle = 0., utilization = 0.;
  std::size_t flips = 0;
  Overlaps overlaps;
  double seconds = 0.;  // time to measure
};

Metrics measure(const Obj& obj)
{
  const Clock::time_point start = Clock::now();
  const Atlas atlas = make_atlas(obj);
  Metrics m;
  m.polygons = obj.polygons();
  m.triangles = atlas.p.size();
  m.corners = atlas.corners;
  m.corners_uv = atlas.corners_uv;
  m.corners_outside = atlas.corners_outside;
  m.groups = atlas.groups;
  const std::vector<Shape> shapes = shapes_of(atlas);
  const std::vector<Edge_side> sides = sorted_edge_sides(atlas);
  const Charts charts = find_charts(sides, atlas.p.size());
  m.charts = charts.count;
  double area_3 = 0.;
  for(const Shape& s : shapes)
  {
    area_3 += s.area_3;
    m.utilization += s.area_uv;
  }
  m.seam_ratio = area_3 > 0. ? seam_length(sides, atlas) / std::sqrt(area_3) : 0.;
  m.area_spread = area_spread(shapes);
  m.angle = angle_distortion(atlas, shapes);
  m.flips = count_flips(shapes, charts);
  m.overlaps = count_overlaps(atlas, shapes);
  m.seconds = seconds_since(start);
  return m;
}

// Ours: the corners with a UV of the output polygons that have the size of the input's polygon
// of the same rank; `mismatched`: input polygons whose output polygon is missing or has other
// vertex indices.
std::size_t corners_with_uv_of_input(const Input& in, const Obj& obj, std::size_t& mismatched)
{
  std::size_t covered = 0;
  mismatched = 0;
  for(std::size_t f = 0; f < std::min(in.polygons.size(), obj.polygons()); ++f)
  {
    const std::vector<std::size_t>& polygon = in.polygons[f];
    const std::size_t first = obj.first_corner[f];
    if(obj.first_corner[f + 1] - first != polygon.size())
    {
      ++mismatched;
      continue;
    }
    bool same = true;
    for(std::size_t i = 0; i < polygon.size(); ++i)
    {
      covered += obj.corner_vt[first + i] >= 0 ? 1 : 0;
      same = same && obj.corner_v[first + i] == long(polygon[i]);
    }
    mismatched += same ? 0 : 1;
  }
  mismatched += std::max(in.polygons.size(), obj.polygons()) - std::min(in.polygons.size(), obj.polygons());
  return covered;
}

// ---------------------------------------------------------------------------------------
// Running a program: this program re-executed as a trampoline (--spawn) fork()s and exec()s it
// and wait4()s for it, so that ru_maxrss is the program's own.

// In the trampoline's child: its own process group (a timeout kills the program's children
// too), stdout and stderr to files, then exec.
[[noreturn]] void exec_program(const char* out, const char* err, char** args, const sigset_t& blocked)
{
  ::setpgid(0, 0);
  sigprocmask(SIG_UNBLOCK, &blocked, nullptr);
  const int o = ::open(out, O_WRONLY | O_CREAT | O_TRUNC, 0644);
  const int e = std::strcmp(out, err) == 0 ? o : ::open(err, O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if(o < 0 || e < 0 || ::dup2(o, 1) < 0 || ::dup2(e, 2) < 0)
    ::_exit(126);
  ::execv(args[0], args);
  ::_exit(127);
}

// Waits (SIGCHLD blocked) until the child exits or the timeout passes (then kills it); true
// when it exited in time. The child is not reaped.
bool wait_for_exit(pid_t pid, const sigset_t& chld, double timeout)
{
  const Clock::time_point deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                                        std::chrono::duration<double>(timeout));
  while(true)
  {
    siginfo_t info;
    std::memset(&info, 0, sizeof(info));
    if(::waitid(P_PID, id_t(pid), &info, WEXITED | WNOHANG | WNOWAIT) == 0 && info.si_pid == pid)
      return true;
    const double left = std::chrono::duration<double>(deadline - Clock::now()).count();
    if(left <= 0.)
    {
      ::kill(-pid, SIGKILL);
      ::kill(pid, SIGKILL);
      return false;
    }
    timespec ts;
    ts.tv_sec = time_t(std::min(left, 60.));
    ts.tv_nsec = long((std::min(left, 60.) - double(ts.tv_sec)) * 1e9);
    ::sigtimedwait(&chld, nullptr, &ts);
  }
}

// --spawn RESULT TIMEOUT STDOUT STDERR PROGRAM ARGS...: writes "exit signal timed_out seconds
// maxrss_kb" to RESULT.
int spawn_main(int argc, char** argv)
{
  if(argc < 7)
    return 2;
  sigset_t chld;
  sigemptyset(&chld);
  sigaddset(&chld, SIGCHLD);
  sigprocmask(SIG_BLOCK, &chld, nullptr);
  const Clock::time_point start = Clock::now();
  const pid_t pid = ::fork();
  if(pid < 0)
    return 1;
  if(pid == 0)
    exec_program(argv[4], argv[5], argv + 6, chld);
  ::setpgid(pid, pid);  // also here, so that a timeout cannot come before the child's own call
  const bool in_time = wait_for_exit(pid, chld, std::atof(argv[3]));
  int status = 0;
  rusage usage;
  std::memset(&usage, 0, sizeof(usage));
  while(::wait4(pid, &status, 0, &usage) < 0)
    if(errno != EINTR)
      return 1;
  const double seconds = seconds_since(start);
  std::ofstream result(argv[2]);
  result << (WIFEXITED(status) ? WEXITSTATUS(status) : -1) << ' ' << (WIFSIGNALED(status) ? WTERMSIG(status) : 0)
         << ' ' << (in_time ? 0 : 1) << ' ' << seconds << ' ' << usage.ru_maxrss << '\n';
  return result ? 0 : 1;
}

struct Process
{
  bool ran = false;  // the trampoline reported
  int exit_code = -1;
  int signal = 0;
  bool timed_out = false;
  double seconds = 0.;
  double peak_mb = 0.;
  std::string status() const
  {
    if(!ran)
      return "not run";
    if(timed_out)
      return "timeout";
    if(signal != 0)
      return "signal " + std::to_string(signal);
    return std::to_string(exit_code) + (exit_code == 127 ? " (cannot execute)" : "");
  }
  bool ok() const { return ran && !timed_out && signal == 0 && exit_code == 0; }
};

// Runs `command` (program and arguments) through the trampoline; stdout to `out`, stderr to `err`.
Process run_process(const std::vector<std::string>& command, const std::string& out, const std::string& err,
                    double timeout)
{
  const std::string result_file = out + ".run";
  std::vector<std::string> words = {"/proc/self/exe", "--spawn", result_file, std::to_string(timeout), out, err};
  words.insert(words.end(), command.begin(), command.end());
  std::vector<char*> args;
  for(std::string& w : words)
    args.push_back(w.data());
  args.push_back(nullptr);
  std::error_code ec;
  fs::remove(result_file, ec);
  std::fflush(stdout);
  std::cout.flush();
  const pid_t pid = ::fork();
  if(pid == 0)
  {
    ::execv(args[0], args.data());
    ::_exit(127);
  }
  int status = 0;
  while(pid > 0 && ::waitpid(pid, &status, 0) < 0 && errno == EINTR) { }
  Process p;
  long maxrss_kb = 0;
  int timed_out = 0;
  std::ifstream result(result_file);
  p.ran = bool(result >> p.exit_code >> p.signal >> timed_out >> p.seconds >> maxrss_kb);
  p.timed_out = timed_out != 0;
  p.peak_mb = double(maxrss_kb) / 1024.;
  return p;
}

// ---------------------------------------------------------------------------------------
// The meshes

struct Mesh_entry
{
  std::string name;  // file name
  std::string path;
  std::string why;   // why it is in the benchmark ("atlas folder", or its topology)
  std::size_t polygons = 0, triangles = 0;
  std::size_t vertices = 0;  // points as read
};

struct Options
{
  std::vector<std::string> only, extra;
  std::vector<std::string> sweep;  // --sweep: bounds of --max-area-spread
  bool xatlas_only = false, self_test = false;
  bool disks = false;  // --disks: the disks against BFF
  std::string out = "/tmp/mbp-atlas";
  double timeout = 600.;
  std::string ours = MBP_CLI_PROGRAM, xatlas = MBP_XATLAS_PROGRAM, bff = MBP_BFF_PROGRAM;
  std::string atlas_dir = MBP_ATLAS_DIR, meshes_dir = MBP_MESH_DIR;
};

bool selected(const Options& o, const std::string& name)
{
  return o.only.empty() || std::find(o.only.begin(), o.only.end(), name) != o.only.end();
}

// Adds the mesh when it can be read and is kept (`disks`: when it is a disk; otherwise when it
// is in the atlas folder or not a disk); prints the decision.
void consider(const fs::path& file, bool atlas_folder, bool disks, std::vector<Mesh_entry>& meshes)
{
  Input in;
  Mesh_entry e{file.filename().string(), file.string(), "", 0, 0, 0};
  if(!read_input(file.string(), in))
  {
    std::cout << "- " << e.name << ": cannot be read, skipped\n";
    return;
  }
  const Topology t = soup_topology(in);
  e.polygons = in.polygons.size();
  e.triangles = in.triangles;
  e.vertices = in.points.size();
  e.why = describe(t);
  const bool keep = disks ? is_disk(t) : atlas_folder || !is_disk(t);
  std::cout << "- " << e.name << ": " << e.polygons << " polygons, " << e.why
            << (keep ? ": kept" : is_disk(t) ? ": disk, skipped" : ": not a disk, skipped") << "\n";
  if(keep)
    meshes.push_back(e);
}

std::vector<Mesh_entry> list_meshes(const Options& o)
{
  std::vector<Mesh_entry> meshes;
  std::vector<std::pair<std::string, bool> > folders = {{o.atlas_dir, true}, {o.meshes_dir, false}};
  if(o.disks)
    folders.erase(folders.begin());  // no atlas folder
  for(const auto& [dir, atlas_folder] : folders)
  {
    const char* kept = o.disks ? "Project meshes (disks kept)" : "Project meshes (non-disks kept)";
    std::cout << "\n" << (atlas_folder ? "Atlas meshes" : kept) << ": " << dir << "\n\n";
    std::error_code ec;  // an unreadable folder lists no mesh
    for(const fs::path& file : mbp_cli::mesh_files_in(dir, ec))
      if(selected(o, file.filename().string()))
        consider(file, atlas_folder, o.disks, meshes);
  }
  if(!o.extra.empty())
    std::cout << "\nExtra meshes (--mesh)\n\n";
  for(const std::string& file : o.extra)
    consider(fs::path(file), true, o.disks, meshes);
  return meshes;
}

// ---------------------------------------------------------------------------------------
// One mesh, one program

struct Side
{
  std::string program;  // "ours", "xatlas" or "BFF"
  Process process;
  bool measured = false;
  std::string problem;  // why it was not measured, or a warning
  Metrics metrics;
  double uv_corner_share = 0.;  // see "UV corners" in the file's header
  std::size_t uv_corners_missing = 0;
  std::string reported_charts;  // the program's own count, from its stdout
};

// The number of elements of the JSON array that starts at text[at] ('['), or "" when unclosed.
std::string json_array_size(const std::string& text, std::size_t at)
{
  std::size_t elements = 0, depth = 0;
  bool in_string = false, escaped = false, empty = true;
  for(std::size_t i = at; i < text.size(); ++i)
  {
    const char c = text[i];
    if(in_string)
    {
      in_string = escaped || c != '"';
      escaped = !escaped && c == '\\';
      continue;
    }
    if(depth == 1 && c != ']' && !std::isspace(static_cast<unsigned char>(c)))
      empty = false;
    if(c == '"')
      in_string = true;
    else if(c == '[' || c == '{')
      ++depth;
    else if((c == ']' || c == '}') && --depth == 0)
      return std::to_string(empty ? 0 : elements + 1);
    else if(c == ',' && depth == 1)
      ++elements;
  }
  return "";
}

// The chart count a program printed: `charts=N` (xatlas), or our JSON's "charts" (a number, or
// an array: its size); empty when there is none.
std::string reported_charts(const std::string& stdout_file)
{
  std::string text;
  if(!load_file(stdout_file, text))
    return "";
  for(const std::string key : {"\"charts\"", "charts="})
  {
    std::size_t at = text.find(key);
    if(at == std::string::npos)
      continue;
    at = text.find_first_not_of(" \t\r\n:", at + key.size());
    if(at != std::string::npos && text[at] == '[')
      return json_array_size(text, at);
    const std::size_t end = at == std::string::npos ? at : text.find_first_not_of("0123456789", at);
    return at == std::string::npos || end == at ? "" : text.substr(at, end - at);
  }
  return "";
}

// Reads and measures the program's OBJ; ours is checked polygon by polygon against the input.
void measure_output(const Mesh_entry& mesh, const std::string& obj_path, Side& side)
{
  Obj obj;
  side.problem = read_obj(obj_path, obj);
  if(!side.problem.empty())
    return;
  Input in;
  if(!read_input(mesh.path, in))
  {
    side.problem = "input unreadable";
    return;
  }
  side.metrics = measure(obj);
  side.measured = true;
  std::size_t expected = 3 * in.triangles, covered = std::min(side.metrics.corners_uv, expected);
  if(side.program == "ours")
  {
    std::size_t mismatched = 0;
    expected = in.corners;
    covered = corners_with_uv_of_input(in, obj, mismatched);
    if(mismatched > 0)
      side.problem = std::to_string(mismatched) + " output polygons differ from the input's";
  }
  side.uv_corner_share = expected == 0 ? 0. : double(covered) / double(expected);
  side.uv_corners_missing = expected - covered;
}

// Writes the input (points and polygons as read) as an OBJ at full precision.
bool write_input_obj(const Input& in, const std::string& path)
{
  std::FILE* f = std::fopen(path.c_str(), "w");
  if(!f)
    return false;
  for(const K::Point_3& p : in.points)
    std::fprintf(f, "v %.17g %.17g %.17g\n", p.x(), p.y(), p.z());
  for(const std::vector<std::size_t>& polygon : in.polygons)
  {
    std::fputc('f', f);
    for(std::size_t v : polygon)
      std::fprintf(f, " %zu", v + 1);
    std::fputc('\n', f);
  }
  return std::fclose(f) == 0;
}

// BFF's input (it reads OBJ only): the mesh's file when it is an OBJ, otherwise the input
// written as NAME.bff-in.obj into --out; empty when that fails.
std::string bff_input(const Mesh_entry& mesh, const Options& o)
{
  std::string extension = fs::path(mesh.path).extension().string();
  for(char& c : extension)
    c = char(std::tolower(static_cast<unsigned char>(c)));
  if(extension == ".obj")
    return mesh.path;
  Input in;
  const std::string path = (fs::path(o.out) / (mesh.name + ".bff-in.obj")).string();
  return read_input(mesh.path, in) && write_input_obj(in, path) ? path : "";
}

// One run: xatlas, BFF, or ours with `args` added (`label` names its files: NAME.LABEL.obj).
Side run_side(const std::string& program, const Mesh_entry& mesh, const Options& o, const std::string& label,
              const std::vector<std::string>& args = {})
{
  Side side;
  side.program = program;
  const std::string base = (fs::path(o.out) / (mesh.name + "." + label)).string();
  const std::string obj = base + ".obj";
  std::error_code ec;
  fs::remove(obj, ec);
  const std::string input = program == "BFF" ? bff_input(mesh, o) : mesh.path;
  if(input.empty())
  {
    side.problem = "the input could not be written as OBJ";
    return side;
  }
  const std::string out = base + (program == "ours" ? ".json" : ".log");
  std::vector<std::string> command = {program == "ours" ? o.ours : program == "BFF" ? o.bff : o.xatlas, input, obj};
  if(program == "ours")
    command.push_back("--json");
  command.insert(command.end(), args.begin(), args.end());
  side.process = run_process(command, out, program == "ours" ? base + ".log" : out, o.timeout);
  side.reported_charts = reported_charts(out);
  if(!side.process.ok())
    side.problem = "see " + base + ".log";
  else if(!fs::exists(obj))
    side.problem = "no OBJ written";
  else
    measure_output(mesh, obj, side);
  return side;
}

// ---------------------------------------------------------------------------------------
// The table and the summary

// A run of ours at another setting: the bound of --max-area-spread ("one chart": the previous
// issue's atlas, one chart per component wherever its map is one-to-one).
struct Sweep_run
{
  std::string bound;
  Side side;
};

struct Row
{
  Mesh_entry mesh;
  Side ours, xatlas;
  Sweep_run one_chart, at_xatlas;  // at_xatlas: the bound set to xatlas's area spread
  Sweep_run by_scale;              // the default bounds, split by the conformal scale
  std::vector<Sweep_run> sweep;
};

std::string fixed(double x, int digits)
{
  if(!std::isfinite(x))
    return "-";
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.*f", digits, x);
  return buffer;
}

std::string uv_corners_cell(const Side& s)
{
  if(s.uv_corners_missing == 0)
    return "100%";
  return fixed(100. * s.uv_corner_share, 2) + "% (" + std::to_string(s.uv_corners_missing) + " missing)";
}

std::string overlaps_cell(const Overlaps& o)
{
  return std::to_string(o.pairs) + (o.complete ? "" : "+ (stopped)");
}

std::vector<std::string> split_list(const std::string& text)
{
  std::vector<std::string> items;
  std::stringstream in(text);
  for(std::string item; std::getline(in, item, ',');)
    if(!item.empty())
      items.push_back(item);
  return items;
}

// The arguments of ours at an area-spread bound; "one chart" lifts every bound.
std::vector<std::string> bound_arguments(const std::string& bound)
{
  if(bound == "one chart")
    return {"--max-area-spread=inf", "--max-angle-distortion=inf", "--min-compactness=0"};
  if(bound == "split by scale")
    return {"--split=scale"};
  return {"--max-area-spread=" + bound};
}

Sweep_run sweep_run(const Mesh_entry& mesh, const Options& o, const std::string& bound, const std::string& label)
{
  return Sweep_run{bound, run_side("ours", mesh, o, label, bound_arguments(bound))};
}

// The previous issue's atlas, the bound at xatlas's own area spread, and the --sweep bounds.
void run_sweep(const Mesh_entry& mesh, const Options& o, Row& r)
{
  r.one_chart = sweep_run(mesh, o, "one chart", "one-chart");
  r.by_scale = sweep_run(mesh, o, "split by scale", "by-scale");
  if(r.xatlas.measured)
    r.at_xatlas = sweep_run(mesh, o, fixed(std::max(std::ceil(1e4 * r.xatlas.metrics.area_spread), 1.) / 1e4, 4),
                            "at-xatlas");
  for(const std::string& bound : o.sweep)
    r.sweep.push_back(sweep_run(mesh, o, bound, "bound-" + bound));
}

void print_table_header()
{
  std::cout << "| mesh | F | program | exit | UV corners | UV out | charts (printed) | charts g | charts cc"
               " | seam/sqrt(A) | area spread | angle (deg) | util | flips | overlaps | time (s) | peak (MB) |\n"
               "|---|--:|---|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n";
}

void print_cells(const std::vector<std::string>& cells)
{
  for(const std::string& c : cells)
    std::cout << "| " << c << " ";
  std::cout << "|\n";
}

void print_side(const Mesh_entry& mesh, const Side& s)
{
  std::vector<std::string> cells = {mesh.name, std::to_string(mesh.polygons), s.program, s.process.status()};
  const std::string time = s.process.ran ? fixed(s.process.seconds, 2) : "";
  const std::string peak = s.process.ran ? fixed(s.process.peak_mb, 0) : "";
  if(!s.measured)
  {
    if(s.process.ok())
      cells.back() += " (" + s.problem + ")";
    cells.resize(cells.size() + 11);
    cells.insert(cells.end(), {time, peak});
    print_cells(cells);
    return;
  }
  const Metrics& m = s.metrics;
  cells.insert(cells.end(), {uv_corners_cell(s), std::to_string(m.corners_outside),
                             s.reported_charts.empty() ? "-" : s.reported_charts, s.program == "ours" ? std::to_string(m.groups) : "-", std::to_string(m.charts),
                             fixed(m.seam_ratio, 2), fixed(m.area_spread, 3), fixed(m.angle, 2),
                             fixed(m.utilization, 3), std::to_string(m.flips), overlaps_cell(m.overlaps), time, peak});
  print_cells(cells);
}

double median(std::vector<double> x)
{
  if(x.empty())
    return std::numeric_limits<double>::quiet_NaN();
  std::sort(x.begin(), x.end());
  const std::size_t n = x.size();
  return n % 2 == 1 ? x[n / 2] : 0.5 * (x[n / 2 - 1] + x[n / 2]);
}

// The per-mesh targets of issue 22 that `s` misses (time: against `peer`, from 10k polygons on).
std::vector<std::string> missed_targets(const Mesh_entry& mesh, const Side& s, const Side* peer)
{
  std::vector<std::string> missed;
  if(!s.process.ok())
    return {"exit " + s.process.status()};
  if(!s.measured)
    return {"output not measured (" + s.problem + ")"};
  const Metrics& m = s.metrics;
  if(s.uv_corners_missing > 0)
    missed.push_back(std::to_string(s.uv_corners_missing) + " corners without UV");
  if(m.flips > 0)
    missed.push_back(std::to_string(m.flips) + " flips");
  if(m.overlaps.pairs > 0 || !m.overlaps.complete)
    missed.push_back(overlaps_cell(m.overlaps) + " overlapping pairs");
  if(m.corners_outside > 0)
    missed.push_back(std::to_string(m.corners_outside) + " UVs outside [0,1]^2");
  if(peer && peer->process.ok() && mesh.polygons >= 10000 && s.process.seconds > 0.2 * peer->process.seconds)
    missed.push_back("time " + fixed(s.process.seconds / peer->process.seconds, 2) + "x xatlas's");
  return missed;
}

void print_missed(const std::vector<Row>& rows, bool ours)
{
  std::size_t count = 0;
  for(const Row& r : rows)
  {
    const std::vector<std::string> missed =
      ours ? missed_targets(r.mesh, r.ours, &r.xatlas) : missed_targets(r.mesh, r.xatlas, nullptr);
    if(missed.empty())
      continue;
    std::cout << "  - " << r.mesh.name << ":";
    for(std::size_t i = 0; i < missed.size(); ++i)
      std::cout << (i == 0 ? " " : "; ") << missed[i];
    std::cout << "\n";
    ++count;
  }
  if(count == 0)
    std::cout << "  - none\n";
}

// "NAME (S s)" of the slowest completed run of a program.
std::string slowest(const std::vector<Row>& rows, bool ours)
{
  const Row* worst = nullptr;
  for(const Row& r : rows)
  {
    const Side& s = ours ? r.ours : r.xatlas;
    if(s.process.ok() && (!worst || s.process.seconds > (ours ? worst->ours : worst->xatlas).process.seconds))
      worst = &r;
  }
  if(!worst)
    return "-";
  return worst->mesh.name + " (" + fixed((ours ? worst->ours : worst->xatlas).process.seconds, 2) + " s)";
}

void print_utilization(const std::vector<Row>& rows)
{
  std::vector<double> ours, xatlas, ours_both, xatlas_both;
  for(const Row& r : rows)
  {
    if(r.ours.measured)
      ours.push_back(r.ours.metrics.utilization);
    if(r.xatlas.measured)
      xatlas.push_back(r.xatlas.metrics.utilization);
    if(r.ours.measured && r.xatlas.measured)
    {
      ours_both.push_back(r.ours.metrics.utilization);
      xatlas_both.push_back(r.xatlas.metrics.utilization);
    }
  }
  std::cout << "- median utilization: ours " << fixed(median(ours), 3) << " (" << ours.size() << " meshes), xatlas "
            << fixed(median(xatlas), 3) << " (" << xatlas.size() << " meshes); on the " << ours_both.size()
            << " meshes both completed: ours " << fixed(median(ours_both), 3) << ", xatlas "
            << fixed(median(xatlas_both), 3)
            << (ours_both.empty() ? "" : median(ours_both) >= median(xatlas_both) ? " (target met)" : " (target missed)")
            << "\n";
}

void print_times(const std::vector<Row>& rows)
{
  std::vector<double> ratios;
  for(const Row& r : rows)
    if(r.mesh.polygons >= 10000 && r.ours.process.ok() && r.xatlas.process.ok())
      ratios.push_back(r.ours.process.seconds / r.xatlas.process.seconds);
  std::cout << "- median time ratio ours / xatlas on the meshes of >= 10000 polygons: " << fixed(median(ratios), 3)
            << " (" << ratios.size() << " meshes; target <= 0.2 on every one)\n"
            << "- slowest mesh: ours " << slowest(rows, true) << ", xatlas " << slowest(rows, false) << "\n";
}

void print_summary(const std::vector<Row>& rows, const Options& o)
{
  std::cout << "\n### Summary\n\n";
  print_utilization(rows);
  print_times(rows);
  std::cout << "- meshes where ours misses a target:\n";
  if(o.xatlas_only)
    std::cout << "  - ours not run (--xatlas-only)\n";
  else
    print_missed(rows, true);
  std::cout << "- for reference, the same per-mesh targets (without time) applied to xatlas:\n";
  print_missed(rows, false);
  std::cout << "\nProblems:\n";
  std::size_t problems = 0;
  for(const Row& r : rows)
    for(const Side* s : {&r.ours, &r.xatlas})
      if(!s->problem.empty())
      {
        std::cout << "- " << r.mesh.name << ", " << s->program << ": " << s->problem << "\n";
        ++problems;
      }
  if(problems == 0)
    std::cout << "- none\n";
}

// ---------------------------------------------------------------------------------------
// Issue 23: charts within a bound

void print_sweep_side(const Mesh_entry& mesh, const std::string& setting, const Side& s)
{
  std::vector<std::string> cells = {mesh.name, setting};
  if(!s.measured)
  {
    cells.push_back(s.process.status() + (s.problem.empty() ? "" : " (" + s.problem + ")"));
    cells.resize(cells.size() + 7);
    print_cells(cells);
    return;
  }
  const Metrics& m = s.metrics;
  cells.insert(cells.end(), {std::to_string(m.charts), fixed(m.area_spread, 3), fixed(m.angle, 2), fixed(m.utilization, 3),
                             std::to_string(m.flips), overlaps_cell(m.overlaps), fixed(s.process.seconds, 2),
                             fixed(s.process.peak_mb, 0)});
  print_cells(cells);
}

// Per mesh: xatlas, ours at the default bounds, the previous issue's one chart per component,
// ours at xatlas's area spread, and the --sweep bounds.
void print_sweep_table(const std::vector<Row>& rows)
{
  std::cout << "\n### Bounds (issue 23)\n\n"
               "| mesh | setting | charts cc | area spread | angle (deg) | util | flips | overlaps | time (s) | peak (MB) |\n"
               "|---|---|--:|--:|--:|--:|--:|--:|--:|--:|\n";
  for(const Row& r : rows)
  {
    print_sweep_side(r.mesh, "xatlas", r.xatlas);
    print_sweep_side(r.mesh, "ours (default)", r.ours);
    print_sweep_side(r.mesh, "ours, one chart", r.one_chart.side);
    print_sweep_side(r.mesh, "ours, --split=scale", r.by_scale.side);
    if(r.at_xatlas.side.process.ran)
      print_sweep_side(r.mesh, "ours <= xatlas's spread " + r.at_xatlas.bound, r.at_xatlas.side);
    for(const Sweep_run& w : r.sweep)
      print_sweep_side(r.mesh, "ours <= " + w.bound, w.side);
  }
}

// The medians of a figure over the meshes where both sides were measured.
template <class Figure>
std::array<double, 2> medians(const std::vector<Row>& rows, Figure figure)
{
  std::vector<double> ours, xatlas;
  for(const Row& r : rows)
    if(r.ours.measured && r.xatlas.measured)
    {
      ours.push_back(figure(r.ours.metrics));
      xatlas.push_back(figure(r.xatlas.metrics));
    }
  return {{median(ours), median(xatlas)}};
}

void print_bound_targets(const std::vector<Row>& rows)
{
  const auto spread = medians(rows, [](const Metrics& m) { return m.area_spread; });
  const auto angle = medians(rows, [](const Metrics& m) { return m.angle; });
  const auto charts = medians(rows, [](const Metrics& m) { return double(m.charts); });
  const auto util = medians(rows, [](const Metrics& m) { return m.utilization; });
  auto verdict = [](bool met) { return met ? " (target met)" : " (target missed)"; };
  std::cout << "\n### Summary of the bounds (issue 23 targets)\n\n"
            << "- median area spread: ours " << fixed(spread[0], 3) << ", xatlas " << fixed(spread[1], 3)
            << verdict(spread[0] <= 0.25) << " (target <= 0.25)\n"
            << "- median angle (deg): ours " << fixed(angle[0], 2) << ", xatlas " << fixed(angle[1], 2)
            << verdict(angle[0] <= angle[1]) << "\n"
            << "- median charts: ours " << fixed(charts[0], 1) << ", xatlas " << fixed(charts[1], 1) << " (ratio "
            << fixed(charts[0] / charts[1], 3) << ")" << verdict(charts[0] <= 0.25 * charts[1]) << " (target <= 0.25x)\n"
            << "- median utilization: ours " << fixed(util[0], 3) << ", xatlas " << fixed(util[1], 3)
            << verdict(util[0] >= util[1]) << "\n";
  std::vector<double> at_xatlas, time_ratio;
  std::vector<std::string> slow;
  for(const Row& r : rows)
  {
    if(r.at_xatlas.side.measured && r.xatlas.measured && r.xatlas.metrics.charts > 0)
      at_xatlas.push_back(double(r.at_xatlas.side.metrics.charts) / double(r.xatlas.metrics.charts));
    if(r.ours.process.ok() && r.one_chart.side.process.ok() && r.one_chart.side.process.seconds > 0.)
    {
      time_ratio.push_back(r.ours.process.seconds / r.one_chart.side.process.seconds);
      if(time_ratio.back() > 2.)
        slow.push_back(r.mesh.name + " " + fixed(time_ratio.back(), 2) + "x");
    }
  }
  std::cout << "- at a bound set to xatlas's area spread: median of ours' charts over xatlas's "
            << fixed(median(at_xatlas), 3) << " (" << at_xatlas.size() << " meshes)" << verdict(median(at_xatlas) <= 0.5)
            << " (target <= 0.5)\n"
            << "- time of the default over one chart per component (the previous issue's atlas): median "
            << fixed(median(time_ratio), 2) << "x; over 2x on " << slow.size() << " of " << time_ratio.size()
            << " meshes";
  for(std::size_t i = 0; i < slow.size(); ++i)
    std::cout << (i == 0 ? ": " : ", ") << slow[i];
  std::cout << "\n";
}

// ---------------------------------------------------------------------------------------
// Issue 23: every disk against Boundary First Flattening (--disks)

struct Disk_row
{
  Mesh_entry mesh;
  Side ours, bff;
};

bool one_to_one(const Side& s)
{
  return s.measured && s.metrics.flips == 0 && s.metrics.overlaps.pairs == 0 && s.metrics.overlaps.complete;
}

// "exit N" of a run that failed, or why its output was not measured.
std::string not_measured(const Side& s)
{
  return s.process.ok() ? "not measured (" + s.problem + ")" : "exit " + s.process.status();
}

// The parts of the disk target that ours misses against BFF; empty: met.
std::vector<std::string> disk_misses(const Disk_row& r)
{
  if(!r.ours.measured)
    return {"ours " + not_measured(r.ours)};
  const Metrics &m = r.ours.metrics, &b = r.bff.metrics;
  std::vector<std::string> missed;
  if(m.flips > 0)
    missed.push_back(std::to_string(m.flips) + " flips");
  if(m.overlaps.pairs > 0 || !m.overlaps.complete)
    missed.push_back(overlaps_cell(m.overlaps) + " overlapping pairs");
  if(!r.bff.measured)
    missed.push_back("nothing to compare with: BFF " + not_measured(r.bff));
  else if(!(m.angle <= 1.25 * b.angle))
    missed.push_back("angle " + fixed(m.angle / b.angle, 3) + "x BFF's (> 1.25x)");
  if(r.bff.measured && !(m.area_spread <= std::max(0.25, b.area_spread)))
    missed.push_back("area spread " + fixed(m.area_spread, 3) + " > max(0.25, BFF's " + fixed(b.area_spread, 3) + ")");
  return missed;
}

std::string joined(const std::vector<std::string>& parts, const std::string& separator)
{
  std::string text;
  for(std::size_t i = 0; i < parts.size(); ++i)
    text += (i == 0 ? "" : separator) + parts[i];
  return text;
}

std::string disk_verdict(const Disk_row& r)
{
  const std::vector<std::string> missed = disk_misses(r);
  return missed.empty() ? "met" : "missed: " + joined(missed, "; ");
}

// `digits` significant digits (angles of developable disks are far below 0.01 degree).
std::string significant(double x, int digits)
{
  if(!std::isfinite(x))
    return "-";
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.*g", digits, x);
  return buffer;
}

// Flips, overlapping pairs, area spread, angle and time of one side (ours: charts first).
void append_disk_side(const Side& s, bool charts, std::vector<std::string>& cells)
{
  const std::string time = s.process.ran ? fixed(s.process.seconds, 2) : "-";
  if(!s.measured)
  {
    cells.push_back(not_measured(s));
    cells.resize(cells.size() + (charts ? 4 : 3));
    cells.push_back(time);
    return;
  }
  const Metrics& m = s.metrics;
  if(charts)
    cells.push_back(std::to_string(m.charts));
  cells.insert(cells.end(), {std::to_string(m.flips), overlaps_cell(m.overlaps), fixed(m.area_spread, 3),
                             significant(m.angle, 3), time});
}

void print_disk_table(const std::vector<Disk_row>& rows)
{
  std::cout << "\n### Disks against Boundary First Flattening (issue 23)\n\n"
               "angle: the mean over the triangles' corners of |UV angle - 3D angle|, in degrees, measured by this"
               " program on both output OBJs (not the paper's angle distortion); area spread: the area-weighted mean"
               " |log| of the UV / 3D area ratio at one global scale; charts: connected components of the output."
               " BFF prints its positions and UVs with 6 decimals (ours: full precision), so its angle on a"
               " developable disk does not reach 0."
               " Target: 0 flips, 0 overlapping pairs, angle <= 1.25 x BFF's, area spread <= max(0.25, BFF's).\n\n"
               "| disk | V | ours: charts | ours: flips | ours: overlapping pairs | ours: area spread | ours: angle (deg)"
               " | ours: time (s) | BFF: flips | BFF: overlapping pairs | BFF: area spread | BFF: angle (deg)"
               " | BFF: time (s) | angle ours / BFF | verdict |\n"
               "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|---|\n";
  for(const Disk_row& r : rows)
  {
    std::vector<std::string> cells = {r.mesh.name, std::to_string(r.mesh.vertices)};
    append_disk_side(r.ours, true, cells);
    append_disk_side(r.bff, false, cells);
    const bool both = r.ours.measured && r.bff.measured;
    cells.push_back(both ? significant(r.ours.metrics.angle / r.bff.metrics.angle, 3) : "-");
    cells.push_back(disk_verdict(r));
    print_cells(cells);
  }
}

// Medians over the disks where both sides were measured.
void print_disk_medians(const std::vector<Disk_row>& rows)
{
  std::vector<double> angle_ours, angle_bff, ratio, spread_ours, spread_bff;
  for(const Disk_row& r : rows)
    if(r.ours.measured && r.bff.measured)
    {
      angle_ours.push_back(r.ours.metrics.angle);
      angle_bff.push_back(r.bff.metrics.angle);
      ratio.push_back(r.ours.metrics.angle / r.bff.metrics.angle);
      spread_ours.push_back(r.ours.metrics.area_spread);
      spread_bff.push_back(r.bff.metrics.area_spread);
    }
  std::cout << "- medians over the " << ratio.size() << " disks where both were measured: angle (deg) ours "
            << fixed(median(angle_ours), 2) << ", BFF " << fixed(median(angle_bff), 2) << "; angle ours / BFF "
            << fixed(median(ratio), 3) << " (the median of the per-disk ratios); area spread ours "
            << fixed(median(spread_ours), 3) << ", BFF " << fixed(median(spread_bff), 3) << "\n";
}

// Disks ours splits although BFF's one chart is one-to-one within the 0.25 area spread (not part
// of the verdict: ours' own one chart is another map).
void print_disk_splits(const std::vector<Disk_row>& rows)
{
  std::vector<std::string> split;
  for(const Disk_row& r : rows)
    if(r.ours.measured && r.ours.metrics.charts > 1 && one_to_one(r.bff) && r.bff.metrics.area_spread <= 0.25)
      split.push_back(r.mesh.name + " (" + std::to_string(r.ours.metrics.charts) + " charts; BFF's area spread " +
                      fixed(r.bff.metrics.area_spread, 3) + ")");
  std::cout << "- split by ours although BFF's one chart is one-to-one with area spread <= 0.25 (not part of the"
               " verdict): "
            << (split.empty() ? "none" : joined(split, ", ")) << "\n";
}

void print_disk_summary(const std::vector<Disk_row>& rows)
{
  std::size_t met = 0, ours_one_to_one = 0, bff_one_to_one = 0;
  for(const Disk_row& r : rows)
  {
    met += disk_misses(r).empty() ? 1 : 0;
    ours_one_to_one += one_to_one(r.ours) ? 1 : 0;
    bff_one_to_one += one_to_one(r.bff) ? 1 : 0;
  }
  std::cout << "\n### Summary of the disks (issue 23 target)\n\n"
            << "- target met on " << met << " of " << rows.size() << " disks\n"
            << "- one-to-one (0 flips, 0 overlapping pairs): ours on " << ours_one_to_one << ", BFF on "
            << bff_one_to_one << " of " << rows.size() << " (BFF does not check for folds)\n";
  print_disk_medians(rows);
  print_disk_splits(rows);
  std::cout << "- angle is the mean |UV angle - 3D angle| in degrees, measured by this program on both outputs"
               " (not the paper's angle distortion)\n"
            << "- disks where the target is missed:\n";
  for(const Disk_row& r : rows)
    if(!disk_misses(r).empty())
      std::cout << "  - " << r.mesh.name << ": " << joined(disk_misses(r), "; ") << "\n";
  if(met == rows.size())
    std::cout << "  - none\n";
}

void print_disk_problems(const std::vector<Disk_row>& rows)
{
  std::cout << "\nProblems:\n";
  std::size_t problems = 0;
  for(const Disk_row& r : rows)
    for(const Side* s : {&r.ours, &r.bff})
    {
      std::string problem = s->problem;
      if(s->measured && s->uv_corners_missing > 0)
        problem += (problem.empty() ? "" : "; ") + uv_corners_cell(*s) + " UV corners";
      if(!problem.empty())
        std::cout << "- " << r.mesh.name << ", " << s->program << ": " << problem << "\n";
      problems += problem.empty() ? 0 : 1;
    }
  if(problems == 0)
    std::cout << "- none\n";
}

// ---------------------------------------------------------------------------------------
// Self test: measures of hand-made OBJs with known answers

// Expected values; NaN: not checked; `positive`: checked to be > 0.
const double unchecked = std::numeric_limits<double>::quiet_NaN();
const double positive = -1.;

struct Case
{
  std::string name, obj;
  double charts = unchecked, groups = unchecked, seam = unchecked, spread = unchecked, angle = unchecked,
         utilization = unchecked, flips = unchecked, overlaps = unchecked, outside = unchecked,
         corners_uv = unchecked;
};

bool check(const std::string& what, double got, double expected)
{
  if(std::isnan(expected))
    return true;
  const bool ok = expected == positive ? got > 0. : std::abs(got - expected) <= 1e-9 * std::max(1., std::abs(expected));
  if(!ok)
    std::cout << "    " << what << ": got " << got << ", expected " << (expected == positive ? "> 0" : fixed(expected, 9))
              << "\n";
  return ok;
}

bool run_case(const Case& c, const std::string& dir)
{
  const std::string path = (fs::path(dir) / (c.name + ".obj")).string();
  std::ofstream(path) << c.obj;
  Obj obj;
  const Clock::time_point start = Clock::now();
  const std::string error = read_obj(path, obj);
  const double read_seconds = seconds_since(start);
  if(!error.empty())
  {
    std::cout << "FAIL " << c.name << ": " << error << "\n";
    return false;
  }
  const Metrics m = measure(obj);
  const std::vector<bool> checks = {
    check("charts cc", double(m.charts), c.charts), check("charts g", double(m.groups), c.groups),
    check("seam/sqrt(A)", m.seam_ratio, c.seam), check("area spread", m.area_spread, c.spread),
    check("angle", m.angle, c.angle), check("utilization", m.utilization, c.utilization),
    check("flips", double(m.flips), c.flips), check("overlaps", double(m.overlaps.pairs), c.overlaps),
    check("UV out", double(m.corners_outside), c.outside),
    check("corners with UV", double(m.corners_uv), c.corners_uv),
    check("overlap count complete", m.overlaps.complete ? 1. : 0., 1.)};
  const bool ok = std::find(checks.begin(), checks.end(), false) == checks.end();
  std::cout << (ok ? "pass " : "FAIL ") << c.name << " (" << m.triangles << " triangles; read in "
            << fixed(read_seconds, 3) << " s, measured in " << fixed(m.seconds, 3) << " s)\n";
  return ok;
}

// The unit square of 3D as two triangles (1 2 3), (1 3 4); UVs given per corner.
std::string square(const std::string& vt, const std::string& faces)
{
  return "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n" + vt + faces;
}

std::vector<Case> small_cases()
{
  std::vector<Case> cases;
  Case one{"one_chart", square("vt 0 0\nvt 0.5 0\nvt 0.5 0.5\nvt 0 0.5\n", "g chart_0\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n")};
  one.charts = 1; one.groups = 1; one.seam = 0; one.spread = 0; one.angle = 0; one.utilization = 0.25;
  one.flips = 0; one.overlaps = 0; one.outside = 0; one.corners_uv = 6;
  cases.push_back(one);
  // the diagonal cut: two charts touching at one UV point only, seam sqrt(2) / sqrt(1)
  Case two{"two_charts_seam", square("vt 0 0\nvt 0.5 0\nvt 0.5 0.5\nvt 1 1\nvt 0.5 1\n",
                                     "g chart_0\nf 1/1 2/2 3/3\ng chart_1\nf 1/3 3/4 4/5\n")};
  two.charts = 2; two.groups = 2; two.seam = std::sqrt(2.); two.spread = 0; two.angle = 0; two.utilization = 0.25;
  two.flips = 0; two.overlaps = 0; two.outside = 0;
  cases.push_back(two);
  // the second triangle's apex mirrored across the shared diagonal: it covers the first one
  Case flip{"flipped", square("vt 0 0\nvt 0.5 0\nvt 0.5 0.5\n", "f 1/1 2/2 3/3\nf 1/1 3/3 4/2\n")};
  flip.charts = 1; flip.groups = 0; flip.seam = 0; flip.flips = 1; flip.overlaps = 1;
  cases.push_back(flip);
  // the second triangle's corners listed the other way (a misoriented polygon), same UVs: no flip
  Case misoriented{"misoriented_not_flipped", square("vt 0 0\nvt 0.5 0\nvt 0.5 0.5\nvt 0 0.5\n",
                                                     "f 1/1 2/2 3/3\nf 4/4 3/3 1/1\n")};
  misoriented.charts = 1; misoriented.flips = 0; misoriented.overlaps = 0; misoriented.utilization = 0.25;
  cases.push_back(misoriented);
  // misoriented and folded (its apex mirrored across the diagonal): one flip
  Case both{"misoriented_and_flipped", square("vt 0 0\nvt 0.5 0\nvt 0.5 0.5\n", "f 1/1 2/2 3/3\nf 4/2 3/3 1/1\n")};
  both.charts = 1; both.flips = 1; both.overlaps = 1;
  cases.push_back(both);
  Case overlap{"two_overlapping", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 5 0 0\nv 6 0 0\nv 5 1 0\n"
                                  "vt 0 0\nvt 0.5 0\nvt 0 0.5\nvt 0.1 0.1\nvt 0.6 0.1\nvt 0.1 0.6\n"
                                  "f 1/1 2/2 3/3\nf 4/4 5/5 6/6\n"};
  overlap.charts = 2; overlap.seam = 0; overlap.flips = 0; overlap.overlaps = 1; overlap.utilization = 0.25;
  cases.push_back(overlap);
  return cases;
}

std::vector<Case> touching_cases()
{
  std::vector<Case> cases;
  const std::string two_triangles = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 5 0 0\nv 6 0 0\nv 5 1 0\n";
  // different 3D triangles whose UV triangles share a hypotenuse: touching, no overlap
  Case edge{"touching_edge", two_triangles + "vt 0 0\nvt 0.5 0\nvt 0 0.5\nvt 0.5 0.5\nf 1/1 2/2 3/3\nf 4/4 5/3 6/2\n"};
  edge.charts = 2; edge.overlaps = 0; edge.flips = 0; edge.utilization = 0.25;
  cases.push_back(edge);
  // a vertex on the middle of the other's hypotenuse (a T), and one across it: 0 then 1 overlap
  Case t{"touching_T", two_triangles + "vt 0 0\nvt 0.5 0\nvt 0 0.5\nvt 0.25 0.25\nvt 0.9 0.6\nvt 0.6 0.9\n"
                                       "f 1/1 2/2 3/3\nf 4/4 5/5 6/6\n"};
  t.overlaps = 0;
  cases.push_back(t);
  Case across{"across_T", two_triangles + "vt 0 0\nvt 0.5 0\nvt 0 0.5\nvt 0.24 0.25\nvt 0.9 0.6\nvt 0.6 0.9\n"
                                          "f 1/1 2/2 3/3\nf 4/4 5/5 6/6\n"};
  across.overlaps = 1;
  cases.push_back(across);
  return cases;
}

std::vector<Case> distortion_cases()
{
  std::vector<Case> cases;
  // a right isosceles triangle mapped to an equilateral one: |90-60| + |45-60| + |45-60| over 3
  Case angle{"angle_20_degrees", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 0.5 0\nvt 0.25 0.4330127018922193\n"
                                 "f 1/1 2/2 3/3\n"};
  angle.angle = 20.;
  angle.spread = 0.;
  cases.push_back(angle);
  // two triangles of equal 3D area, UV areas 1:4: after the global scale, mean |log| = log 2
  Case spread{"area_spread_log2", square("vt 0 0\nvt 0.2 0\nvt 0.2 0.2\nvt 0.3 0.3\nvt 0.7 0.7\nvt 0.3 0.7\n",
                                         "f 1/1 2/2 3/3\nf 1/4 3/5 4/6\n")};
  spread.spread = std::log(2.);
  spread.charts = 2;
  spread.seam = std::sqrt(2.);
  cases.push_back(spread);
  // a quad (two triangles), a triangle without UV, one UV outside the square, a zero-area face
  Case mixed{"polygons_and_missing_uv", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 3 0 0\n"
                                        "vt 0 0\nvt 0.5 0\nvt 0.5 0.5\nvt 0 0.5\nvt 1.5 0.2\nvt 0.9 0.9\n"
                                        "f 1/1 2/2 3/3 4/4\nf 2 5 3\nf 2/6 5/6 6/5\n"};
  mixed.corners_uv = 7; mixed.outside = 1; mixed.charts = 2; mixed.flips = 0; mixed.overlaps = 0;
  mixed.utilization = 0.25;
  cases.push_back(mixed);
  return cases;
}

// An n x n grid of squares in 3D (a bumpy height field), two triangles each; UVs: the grid's
// vertices moved at random by up to a fifth of a cell (no fold), scaled into [0,1]^2; `fold`:
// one interior vertex's UV moved across its neighbours.
std::string grid_obj(std::size_t n, bool fold)
{
  std::mt19937 random(7);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  std::ostringstream s;
  s.precision(17);
  for(std::size_t j = 0; j <= n; ++j)
    for(std::size_t i = 0; i <= n; ++i)
      s << "v " << double(i) << ' ' << double(j) << ' ' << std::sin(0.3 * double(i)) * std::cos(0.2 * double(j)) << '\n';
  for(std::size_t j = 0; j <= n; ++j)
    for(std::size_t i = 0; i <= n; ++i)
    {
      const bool inner = i > 0 && j > 0 && i < n && j < n;
      double x = double(i) + (inner ? jitter(random) : 0.), y = double(j) + (inner ? jitter(random) : 0.);
      if(fold && i == n / 2 && j == n / 2)
        x += 2.5;
      s << "vt " << x / double(n) << ' ' << y / double(n) << '\n';
    }
  for(std::size_t j = 0; j < n; ++j)
    for(std::size_t i = 0; i < n; ++i)
    {
      const std::size_t a = j * (n + 1) + i + 1, b = a + 1, c = a + n + 2, d = a + n + 1;
      s << "f " << a << '/' << a << ' ' << b << '/' << b << ' ' << c << '/' << c << '\n';
      s << "f " << a << '/' << a << ' ' << c << '/' << c << ' ' << d << '/' << d << '\n';
    }
  return s.str();
}

std::vector<Case> grid_cases()
{
  std::vector<Case> cases;
  Case jittered{"grid_200_jittered", grid_obj(200, false)};
  jittered.charts = 1; jittered.seam = 0; jittered.flips = 0; jittered.overlaps = 0; jittered.outside = 0;
  jittered.utilization = 1.;
  cases.push_back(jittered);
  Case folded{"grid_200_folded", grid_obj(200, true)};
  folded.charts = 1; folded.flips = positive; folded.overlaps = positive;
  cases.push_back(folded);
  // about one million triangles: the measures must take seconds
  Case large{"grid_707_jittered", grid_obj(707, false)};
  large.charts = 1; large.flips = 0; large.overlaps = 0; large.utilization = 1.;
  cases.push_back(large);
  return cases;
}

// Random triangles in the unit square (many overlapping): the grid's count against all pairs.
bool grid_matches_brute_force()
{
  std::mt19937 random(11);
  std::uniform_real_distribution<double> where(0., 1.), size(-0.03, 0.03);
  Atlas atlas;
  for(std::uint32_t t = 0; t < 3000; ++t)
  {
    const double x = where(random), y = where(random);
    for(int i = 0; i < 3; ++i)
    {
      atlas.points.push_back({double(3 * t + i), 0., double(i == 2)});
      atlas.uvs.push_back({x + size(random), y + size(random)});
    }
    atlas.p.push_back({3 * t, 3 * t + 1, 3 * t + 2});
    atlas.u.push_back(atlas.p.back());
  }
  const std::vector<Shape> shapes = shapes_of(atlas);
  const Overlaps grid = count_overlaps(atlas, shapes);
  std::size_t brute = 0;
  for(std::size_t a = 0; a < shapes.size(); ++a)
    for(std::size_t b = a + 1; b < shapes.size(); ++b)
    {
      Triangle_2 ta, tb;
      for(int i = 0; i < 3; ++i)
      {
        ta[i] = K::Point_2(atlas.uvs[atlas.u[a][i]][0], atlas.uvs[atlas.u[a][i]][1]);
        tb[i] = K::Point_2(atlas.uvs[atlas.u[b][i]][0], atlas.uvs[atlas.u[b][i]][1]);
      }
      brute += (shapes[a].sign != 0 && shapes[b].sign != 0 && interiors_intersect(ta, tb)) ? 1 : 0;
    }
  const bool ok = grid.complete && grid.pairs == brute && brute > 0;
  std::cout << (ok ? "pass " : "FAIL ") << "grid_against_all_pairs (3000 random triangles: " << grid.pairs
            << " overlapping pairs by the grid, " << brute << " by testing all pairs)\n";
  return ok;
}

// The programs' printed chart counts: xatlas's line, our JSON with "charts" a number or an array.
bool printed_charts_read(const std::string& dir)
{
  const std::vector<std::pair<std::string, std::string> > cases = {
    {"charts=108 atlas=1204x1294 utilization=0.5473", "108"},
    {"{\n  \"charts\": 56,\n  \"utilization\": 0.66\n}", "56"},
    {"{\"charts\": [ {\"id\": 0, \"d\": [1, 2]}, {\"id\": 1, \"name\": \"a,]\\\"\"} ], \"utilization\": 1}", "2"},
    {"{\"charts\": [ ], \"utilization\": 0}", "0"}};
  bool ok = true;
  for(const auto& [text, expected] : cases)
  {
    const std::string path = (fs::path(dir) / "printed.txt").string();
    std::ofstream(path) << text;
    const std::string got = reported_charts(path);
    if(got != expected)
      std::cout << "    printed charts of " << text << ": got '" << got << "', expected " << expected << "\n";
    ok = ok && got == expected;
  }
  std::cout << (ok ? "pass " : "FAIL ") << "printed_chart_counts (xatlas's line, our JSON)\n";
  return ok;
}

int self_test(const Options& o)
{
  const std::string dir = (fs::path(o.out) / "self-test").string();
  std::error_code ec;
  fs::create_directories(dir, ec);
  std::cout << "Self test (OBJs in " << dir << ")\n";
  std::size_t failures = 0, count = 0;
  for(const auto& make : {small_cases, touching_cases, distortion_cases, grid_cases})
    for(const Case& c : make())
    {
      ++count;
      failures += run_case(c, dir) ? 0 : 1;
    }
  count += 2;
  failures += grid_matches_brute_force() ? 0 : 1;
  failures += printed_charts_read(dir) ? 0 : 1;
  std::cout << (failures == 0 ? "self test passed: " : "self test FAILED: ") << count - failures << " of " << count
            << " cases\n";
  return failures == 0 ? 0 : 1;
}

// ---------------------------------------------------------------------------------------
// Main

bool parse_options(int argc, char** argv, Options& o)
{
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto value = [&](const char* prefix) { return a.rfind(prefix, 0) == 0 ? a.substr(std::strlen(prefix)) : ""; };
    if(a == "--xatlas-only") o.xatlas_only = true;
    else if(a == "--self-test") o.self_test = true;
    else if(!value("--only=").empty()) o.only.push_back(value("--only="));
    else if(!value("--sweep=").empty()) o.sweep = split_list(value("--sweep="));
    else if(!value("--mesh=").empty()) o.extra.push_back(value("--mesh="));
    else if(!value("--out=").empty()) o.out = value("--out=");
    else if(!value("--timeout=").empty()) o.timeout = std::atof(value("--timeout=").c_str());
    else if(!value("--ours=").empty()) o.ours = value("--ours=");
    else if(!value("--xatlas=").empty()) o.xatlas = value("--xatlas=");
    else if(a == "--disks") o.disks = true;
    else if(!value("--bff=").empty()) o.bff = value("--bff=");
    else if(!value("--atlas-dir=").empty()) o.atlas_dir = value("--atlas-dir=");
    else if(!value("--meshes-dir=").empty()) o.meshes_dir = value("--meshes-dir=");
    else
    {
      std::cerr << "unknown option " << a << " (see the header of benchmark/atlas_comparison.cpp)\n";
      return false;
    }
  }
  return o.timeout > 0.;
}

// The setup's last lines: where the outputs go, the timeout, the load average at the start.
void print_outputs_and_load(const Options& o)
{
  std::cout << "- outputs: " << o.out << "; timeout " << o.timeout << " s per run\n";
  std::ifstream load("/proc/loadavg");
  std::string load_1;
  if(load >> load_1)
    std::cout << "- 1-minute load average at the start: " << load_1 << "\n";
}

void print_setup(const Options& o)
{
  std::cout << "# Atlas comparison (issue 22): ours against xatlas\n\n"
            << "- ours: " << (o.xatlas_only ? "not run (--xatlas-only)" : o.ours + " IN OUT.obj --json") << "\n"
            << "- xatlas: " << o.xatlas << " IN OUT.obj\n";
  print_outputs_and_load(o);
}

int main_benchmark(const Options& o)
{
  std::error_code ec;
  fs::create_directories(o.out, ec);
  print_setup(o);
  const std::vector<Mesh_entry> meshes = list_meshes(o);
  std::vector<Row> rows;
  for(const Mesh_entry& mesh : meshes)
  {
    Row r;
    r.mesh = mesh;
    r.ours.program = "ours";
    if(!o.xatlas_only)
      r.ours = run_side("ours", mesh, o, "ours");
    r.xatlas = run_side("xatlas", mesh, o, "xatlas");
    if(!o.xatlas_only)
      run_sweep(mesh, o, r);
    std::cerr << mesh.name << ": ours " << r.ours.process.status() << ", xatlas " << r.xatlas.process.status()
              << " (" << fixed(r.xatlas.process.seconds, 2) << " s; measured in "
              << fixed(r.xatlas.metrics.seconds + r.ours.metrics.seconds, 2) << " s)\n";
    rows.push_back(r);
  }
  std::cout << "\n";
  print_table_header();
  for(const Row& r : rows)
  {
    if(!o.xatlas_only)
      print_side(r.mesh, r.ours);
    print_side(r.mesh, r.xatlas);
  }
  print_summary(rows, o);
  if(!o.xatlas_only)
  {
    print_sweep_table(rows);
    print_bound_targets(rows);
  }
  return 0;
}

void print_disk_setup(const Options& o)
{
  std::cout << "# Disks (issue 23): ours against Boundary First Flattening\n\n"
            << "- ours: " << o.ours << " IN OUT.obj --json (its defaults)\n"
            << "- BFF: " << o.bff << " IN.obj OUT.obj (no option: boundary scale factors 0; an input that is not"
            << " OBJ is written as OBJ first)\n";
  print_outputs_and_load(o);
}

int main_disks(const Options& o)
{
  std::error_code ec;
  fs::create_directories(o.out, ec);
  print_disk_setup(o);
  std::vector<Disk_row> rows;
  for(const Mesh_entry& mesh : list_meshes(o))
  {
    rows.push_back(Disk_row{mesh, run_side("ours", mesh, o, "ours"), run_side("BFF", mesh, o, "bff")});
    std::cerr << mesh.name << ": ours " << rows.back().ours.process.status() << ", BFF "
              << rows.back().bff.process.status() << "\n";
  }
  print_disk_table(rows);
  print_disk_summary(rows);
  print_disk_problems(rows);
  return 0;
}

}  // namespace

int main(int argc, char** argv)
{
  if(argc > 1 && std::strcmp(argv[1], "--spawn") == 0)
    return spawn_main(argc, argv);
  Options o;
  if(!parse_options(argc, argv, o))
    return 2;
  if(o.self_test)
    return self_test(o);
  if((o.disks || !o.xatlas_only) && o.ours.empty())
  {
    std::cerr << "our program is unknown (the build has no measured_parameterization_cli): give --ours=PROGRAM"
                 " or --xatlas-only\n";
    return 2;
  }
  return o.disks ? main_disks(o) : main_benchmark(o);
}
