// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// The options of the measured_parameterization program: parsing and help text. No CGAL here.

#include "options.h"
#include "text_output.h"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <system_error>

namespace mbp_cli {

namespace {

// The help text, in three parts: before the default mesh, before the default solver, and
// after it.
const char* const usage_synopsis =
    "usage: measured_parameterization [INPUT] [OUTPUT.obj] [--atlas] [--resolution=N] [--gutter=N]\n"
    "                                 [--max-area-spread=X] [--max-angle-distortion=X]\n"
    "                                 [--min-compactness=X] [--split=normals|scale]\n"
    "                                 [--output=FILE] [--svg=FILE] [--json] [--help]\n"
    "       measured_parameterization [INPUT] [OUTPUT.obj] --single-chart [--seams=FILE.selection.txt]\n"
    "                                 [--center=poisson|geodesic[:METHOD]|vertex:N]\n"
    "                                 [--distance=poisson|METHOD|straightest]\n"
    "                                 [--border=auto|conformal|conformal-lengths|measured|circle]\n"
    "                                 [--solver=cholmod|cholmod-nd|ldlt] [--output=FILE] [--svg=FILE] [--json]\n"
    "                                 [--write-seams=FILE.selection.txt]\n"
    "                                 [--no-repair] [--help]\n"
    "       measured_parameterization --batch=FOLDER|LIST|- --output-dir=DIR [--jobs=N] [--shard=I/N]\n"
    "                                 [--force] [the options of a mode] [--threads=N]\n"
    "\n"
    "By default (--atlas) makes a packed texture atlas of any mesh: the file is read as a polygon\n"
    "soup and repaired (equal points merged, duplicate and degenerate polygons, non-manifold\n"
    "edges and vertices, orientation, non-orientable pieces cut open, polygons triangulated,\n"
    "zero-area faces set aside); every connected component becomes a chart (a disk flattened with\n"
    "the automatic border, any other surface cut along automatic seams first), split into\n"
    "parts, recursively, where its map would not be one-to-one or misses the distortion bounds\n"
    "below;\n"
    "the charts are scaled to one texel density and packed into the unit square. Every corner of\n"
    "every input polygon gets a UV.\n"
    "\n"
    "With --single-chart (implied by each of its options: --border, --center, --distance,\n"
    "--seams, --write-seams, --solver, --no-repair) flattens one disk-like triangle mesh with\n"
    "the measured boundary parameterization of \"Measured boundary parameterization based on\n"
    "Poisson's equation\": the longest border is laid out around a center vertex at its measured\n"
    "distances from it, and the interior is the discrete conformal map with that border fixed.\n"
    "A mesh that is not a disk (closed, with holes or with handles) is first cut open into a\n"
    "disk along seams: those of --seams, or automatic seams (see --seams).\n"
    "\n"
    "  INPUT              .off, .obj, .ply or .stl. Atlas: any polygons, any number of\n"
    "                     connected components, defects repaired. --single-chart: a triangle\n"
    "                     mesh, one connected component with at least one border (holes are\n"
    "                     allowed; the longest border is mapped), or cut along --seams.\n"
    "                     Default: ";

const char* const usage_options =
    "\n"
    "                     (a generated curved disk when that file does not exist).\n"
    "  OUTPUT.obj         default: <INPUT file stem>_uv.obj in the current directory\n"
    "                     (curved_disk_uv.obj for the generated mesh).\n"
    "                     Atlas: the input's points as 'v' lines in input order (all of them),\n"
    "                     one 'vt' line per polygon corner (polygon after polygon), the input's\n"
    "                     polygons in their order as 'f v/vt ...', and 'g chart_K' before the\n"
    "                     polygons of chart K wherever the chart changes.\n"
    "                     --single-chart: the mesh with one UV per vertex: 'v' lines in input\n"
    "                     order, one 'vt' line per 'v' line, faces 'f a/a b/b c/c'. Vertices\n"
    "                     that are in no face are left out. With --seams: one 'vt' line per\n"
    "                     vertex of the cut mesh (a vertex on a seam gets one UV for each\n"
    "                     side), faces 'f a/i b/j c/k'.\n"
    "\n"
    "options:\n"
    "  --atlas            (default) a packed texture atlas, as above\n"
    "  --resolution=N     the atlas is packed for a square texture of N texels per side\n"
    "                     (default 1024, from 8 to 65536)\n"
    "  --gutter=N         texels kept free between two charts and between a chart and the\n"
    "                     border of the texture (default 2, at most N / 4 of --resolution)\n"
    "  --max-area-spread=X\n"
    "                     the bound on each chart's area spread (area-weighted mean of\n"
    "                     |log(UV area / 3D area)| after one scale of the chart; default 0.2,\n"
    "                     inf: one chart per component wherever its map is one-to-one). A\n"
    "                     chart that misses a bound is split, recursively: in two, or, cut\n"
    "                     open by seams with a one-to-one map r times over a bound, into\n"
    "                     1 + ceil(log2(r)) parts (2 to 8). With --single-chart and\n"
    "                     --border=auto: the bound that ranks the layouts (see --border=auto)\n"
    "  --max-angle-distortion=X\n"
    "                     the bound on each chart's angle distortion (the paper's; default\n"
    "                     0.2); with --single-chart, as --max-area-spread\n"
    "  --min-compactness=X\n"
    "                     the bound on each chart's compactness: its UV area over the square of\n"
    "                     its bounding box's longer side (default 0.3, 0 to 1; a chart that\n"
    "                     misses only this bound is cut across, its UVs kept; 0 keeps long\n"
    "                     strips and rings, which fill the texture badly)\n"
    "  --split=normals|scale\n"
    "                     how a chart that misses a bound is split: regions grown from the\n"
    "                     two faces farthest apart in normal turning plus distance (default) or\n"
    "                     from the smallest and largest conformal scale factors of its map, and\n"
    "                     from the faces farthest from the seeds so far for more parts; faces\n"
    "                     joined by smooth edges move together\n"
    "  --single-chart     the single-chart parameterization below; each of the following\n"
    "                     options implies it\n"
    "  --seams=FILE.selection.txt\n"
    "                     cut the mesh along seams before mapping it (CGAL::Seam_mesh): the\n"
    "                     third line of this CGAL selection file lists the seam edges as pairs\n"
    "                     of 0-based vertex indices in file order (lines 1 and 2, selected\n"
    "                     vertices and faces, are not used). Needed for a closed mesh. The seams\n"
    "                     must cut the surface into a disk (holes are allowed): a tree of edges\n"
    "                     on a closed surface of genus 0, 2g independent loops for genus g\n"
    "                     (for a torus, a meridian and a longitude through one vertex), and no\n"
    "                     closed loop that separates the surface.\n"
    "                     Without --seams, a mesh that is not a disk is cut automatically\n"
    "                     (compute_disk_seams): 2g short loops on a closed surface of genus g,\n"
    "                     arcs that join every border loop and cut every handle on a surface\n"
    "                     with border, and on a closed surface of genus 0 a tree through 8 cone\n"
    "                     vertices where the conformal scale factor is most extreme\n"
    "  --write-seams=FILE.selection.txt\n"
    "                     also write the seams of the cut (automatic or from --seams) as a CGAL\n"
    "                     selection file, to edit and reuse with --seams: line 1 lists the cone\n"
    "                     vertices, line 3 the seam edges (empty for a disk)\n"
    "  --center=poisson   center at the maximum of the boundary Poisson distance map (BPDM,\n"
    "                     default)\n"
    "  --center=geodesic[:METHOD]\n"
    "                     center at the maximum of the geodesic distance from the border (BGDM),\n"
    "                     computed with METHOD (default fast-marching)\n"
    "  --center=vertex:N  center at vertex N: 0-based, in file order (for STL, in order of first\n"
    "                     appearance); it must be in a face and not on the longest border or a\n"
    "                     seam\n"
    "  --distance=poisson distances from the center to the border by the Poisson distance map\n"
    "                     (default with --border=measured: the paper's method)\n"
    "  --distance=METHOD  geodesic distances from the center, computed with METHOD\n"
    "  --distance=straightest\n"
    "                     straightest geodesics (cutting planes through the center's normal);\n"
    "                     fails, naming the border vertex, when a plane curve misses its vertex\n"
    "                     METHOD: fast-marching, dijkstra (along edges), heat (heat method),\n"
    "                     heat-idt (heat method on the intrinsic Delaunay triangulation), exact\n"
    "  --border=auto      (default) the best border of a family, all solved with the one\n"
    "                     factorization of the interior: the circle (arc length), the measured\n"
    "                     border of --center and --distance (default distance: fast-marching,\n"
    "                     so that one matrix is factorized), the conformal border, where it\n"
    "                     overlaps itself the conformal-lengths border, and blends toward a\n"
    "                     convex border of the members whose own layout folds. Kept: the valid\n"
    "                     layout of lowest angle distortion among those within the bounds\n"
    "                     (--max-area-spread, --max-angle-distortion), otherwise of lowest\n"
    "                     product of angle distortion and area spread over their bounds; the\n"
    "                     summary names it, --json lists every candidate with both figures\n"
    "  --border=conformal the conformal border (Boundary First Flattening's border with\n"
    "                     boundary scale factors 0): near-conformal, one factorization\n"
    "  --border=conformal-lengths\n"
    "                     the conformal border, or where it overlaps itself its blend toward\n"
    "                     the circle with conformal lengths (one more factorization; far less\n"
    "                     angle distortion, can crush limbs)\n"
    "  --border=measured  the paper's measured border at the --distance distances\n"
    "  --border=circle    CGAL's circle with arc-length angles\n"
    "  --solver=NAME      sparse Cholesky factorization: cholmod (CHOLMOD supernodal, AMD\n"
    "                     ordering), cholmod-nd (CHOLMOD with METIS's nested dissection: a\n"
    "                     third less memory for the factor, a slower analysis; for meshes of\n"
    "                     millions of vertices) or ldlt (Eigen's SimplicialLDLT). Default: ";

const char* const usage_notes =
    "\n"
    "  --output=FILE      the same as OUTPUT.obj (for example with the default INPUT)\n"
    "  --svg=FILE         also write an SVG picture. Atlas: the unit square with the packed\n"
    "                     charts, each outlined, colored by its distortion against the bounds\n"
    "                     (the larger of area spread / bound and angle distortion / bound;\n"
    "                     with both bounds inf, each polygon by its area distortion).\n"
    "                     --single-chart: the UV layout, faces colored by their angle\n"
    "                     distortion, flipped faces in red\n"
    "  --json             print a JSON object on stdout instead of the one-line summary\n"
    "  --threads=N        threads of the BLAS under CHOLMOD (OpenBLAS; 0: leave the BLAS\n"
    "                     alone, e.g. to OPENBLAS_NUM_THREADS) and, from 2 on, of the package\n"
    "                     itself (a second thread for the --single-chart method). Default 1:\n"
    "                     the fastest on a busy machine (benchmark/README.md)\n"
    "  --no-repair        fail when the layout has flipped faces (by default the border is\n"
    "                     blended toward a circle, as little as needed, until none is left)\n"
    "  -h, --help         print this help and exit\n"
    "\n"
    "Batch mode: many meshes, each in a worker process running this program.\n"
    "  --batch=SOURCE     the inputs: a FOLDER (its .off, .obj, .ply and .stl files), a LIST\n"
    "                     file (one path a line, relative to the list's folder; empty lines\n"
    "                     and lines starting with # are skipped), or - (the list on stdin)\n"
    "  --output-dir=DIR   where DIR/<stem>_uv.obj of each input is written (created when\n"
    "                     missing; <name>_uv.obj with its extension when two inputs share a\n"
    "                     stem), and DIR/report.jsonl (DIR/report-shard-I-of-N.jsonl with\n"
    "                     --shard): one JSON object a line per mesh, {\"input\", \"outputs\",\n"
    "                     \"status\" (OK or FAILED), \"message\", \"figures\" (the --json\n"
    "                     document of the mesh), \"seconds\"}\n"
    "  --jobs=N           N worker processes at once (default 1), each with --threads\n"
    "  --shard=I/N        only the I-th of N slices of the sorted list of inputs (input K,\n"
    "                     from 0, is in slice K mod N + 1): N machines share a data set\n"
    "  --force            redo every mesh; by default a mesh whose outputs exist and whose\n"
    "                     last report line says OK is skipped\n"
    "The options of the atlas or of --single-chart apply to every mesh. A failed mesh never\n"
    "stops the batch. A progress bar is drawn on stderr when it is a terminal.\n"
    "\n"
    "The atlas summary gives the input's points and polygons, the charts, the utilization of the\n"
    "square (UV area of the charts over its area), the repairs made to the input, the area\n"
    "spread (area-weighted mean |log(UV area / 3D area)| after one global scale), the angle\n"
    "distortion and the time of each step. The --single-chart summary gives the number of\n"
    "vertices (V) and faces (F), with seams the number of seam edges (and of cones for\n"
    "automatic seams) and of UVs, the border (vertices, 3D length; a seam counts on both sides),\n"
    "the center (0-based index in the input), the time of each stage of the parameterization in\n"
    "seconds, the factorizations and back-substitutions, and the distortion: angle distortion\n"
    "(the paper's conformal distortion), Sander's L2 stretch (1 is optimal), the area-weighted\n"
    "mean quasi-conformal distortion s1/s2 (1 is conformal) and the number of flipped faces.\n"
    "\n"
    "The measured border need not be convex, so the layout can fold: flipped faces are then\n"
    "repaired by blending the border toward a circle (reported in the summary), or, with\n"
    "--no-repair, the program fails.\n"
    "\n"
    "Exit status: 0 on success; 1 when the input cannot be parameterized or an output file\n"
    "cannot be written (no output file is then left behind); 2 on a command-line error. A\n"
    "batch: 0 when every mesh is done, 1 when one failed or the report cannot be written.\n";

bool starts_with(const std::string& s, const std::string& prefix)
{
  return s.compare(0, prefix.size(), prefix) == 0;
}

// `--name=value`: the value, or an error for a missing or repeated option.
std::string value_of(const std::string& arg, const std::string& name, bool& seen, std::string& value)
{
  if(arg == name)
    return "option " + name + " needs a value: " + name + "=...";
  if(seen)
    return "option " + name + " is given twice";
  seen = true;
  value = arg.substr(name.size() + 1);
  return std::string();
}

// --center=vertex:N
std::string set_center_vertex(const std::string& value, Options& o)
{
  const std::string n = value.substr(7);
  unsigned long long index = 0;
  const auto r = std::from_chars(n.data(), n.data() + n.size(), index);
  if(n.empty() || n[0] == '+' || r.ptr != n.data() + n.size() || r.ec == std::errc::invalid_argument)
    return "bad vertex index '" + n + "' in --center=" + value + " (expected a non-negative integer)";
  if(r.ec == std::errc::result_out_of_range || index > static_cast<unsigned long long>(std::size_t(-1)))
    return "vertex index " + n + " in --center=" + value + " is out of range";
  o.fixed_center = true;
  o.center_vertex = static_cast<std::size_t>(index);
  return std::string();
}

std::string set_center(const std::string& value, Options& o)
{
  if(value == "poisson")
    o.fixed_center = false;
  else if(value == "geodesic" || starts_with(value, "geodesic:"))
  {
    const std::string method = (value == "geodesic") ? std::string("fast-marching") : value.substr(9);
    if(!is_geodesic_method(method))
      return "unknown geodesic method '" + method + "' in --center=" + value +
             " (expected fast-marching, dijkstra, heat, heat-idt or exact)";
    o.fixed_center = false;
    o.center = "geodesic:" + method;
  }
  else if(starts_with(value, "vertex:"))
    return set_center_vertex(value, o);
  else
    return "unknown value '" + value + "' of --center (expected poisson, geodesic[:METHOD] or vertex:N)";
  return std::string();
}

std::string set_distance(const std::string& value, Options& o)
{
  if(value != "poisson" && value != "straightest" && !is_geodesic_method(value))
    return "unknown value '" + value + "' of --distance (expected poisson, fast-marching, dijkstra, "
           "heat, heat-idt, exact or straightest)";
  o.distance = value;
  return std::string();
}

std::string set_border(const std::string& value, Options& o)
{
  for(Border b : {Border::automatic, Border::conformal, Border::conformal_lengths, Border::measured, Border::circle})
    if(value == border_name(b))
    {
      o.border = b;
      return std::string();
    }
  return "unknown value '" + value + "' of --border (expected auto, conformal, conformal-lengths, measured or circle)";
}

std::string set_solver(const std::string& value, Options& o)
{
  if(value == "ldlt")
    o.solver = Solver::ldlt;
  else if(value == "cholmod" || value == "cholmod-nd")
  {
    if(!has_cholmod())
      return "--solver=" + value + ": this build has no CHOLMOD (use --solver=ldlt)";
    o.solver = value == "cholmod" ? Solver::cholmod : Solver::cholmod_nd;
  }
  else
    return "unknown value '" + value + "' of --solver (expected cholmod, cholmod-nd or ldlt)";
  return std::string();
}

// --NAME=N, a whole number from `least` to `most`
std::string set_count(const std::string& value, const std::string& name, unsigned int least, unsigned int most,
                      unsigned int& n)
{
  unsigned long long x = 0;
  const auto r = std::from_chars(value.data(), value.data() + value.size(), x);
  const std::string expected = " (expected a whole number from " + std::to_string(least) + " to " +
                               std::to_string(most) + ")";
  if(value.empty() || r.ptr != value.data() + value.size() || r.ec == std::errc::invalid_argument)
    return "bad value '" + value + "' of " + name + expected;
  if(r.ec == std::errc::result_out_of_range || x < least || x > most)
    return "value " + value + " of " + name + " is out of range" + expected;
  n = static_cast<unsigned int>(x);
  return std::string();
}

// --NAME=X, a number from `least` to `most` (inf allowed where `most` is)
std::string set_number(const std::string& value, const std::string& name, double least, double most, double& x)
{
  const std::string expected = " (expected a number from " + rounded(least) + " to " +
                               (std::isinf(most) ? std::string("inf") : rounded(most)) + ")";
  char* end = nullptr;
  const double v = value.empty() ? 0. : std::strtod(value.c_str(), &end);
  if(value.empty() || end != value.c_str() + value.size() || std::isnan(v))
    return "bad value '" + value + "' of " + name + expected;
  if(v < least || v > most)
    return "value " + value + " of " + name + " is out of range" + expected;
  x = v;
  return std::string();
}

std::string set_split(const std::string& value, Options& o)
{
  if(value != "normals" && value != "scale")
    return "unknown value '" + value + "' of --split (expected normals or scale)";
  o.bounds.split = (value == "normals") ? CGAL::Surface_mesh_parameterization::SPLIT_BY_NORMALS
                                        : CGAL::Surface_mesh_parameterization::SPLIT_BY_SCALE;
  return std::string();
}

// --NAME=FILE: `file` is set, or the error for an empty name
std::string set_file(const std::string& value, const std::string& name, const char* placeholder, std::string& file)
{
  if(value.empty())
    return "option " + name + " needs a file name: " + name + "=" + placeholder;
  file = value;
  return std::string();
}

// --shard=I/N, 1 <= I <= N
std::string set_shard(const std::string& value, Options& o)
{
  const std::size_t slash = value.find('/');
  const std::string expected = " (expected I/N, whole numbers with 1 <= I <= N, e.g. --shard=2/3)";
  if(slash == std::string::npos)
    return "bad value '" + value + "' of --shard" + expected;
  unsigned int i = 0, n = 0;
  if(!set_count(value.substr(0, slash), "--shard", 1, 1u << 20, i).empty() ||
     !set_count(value.substr(slash + 1), "--shard", 1, 1u << 20, n).empty())
    return "bad value '" + value + "' of --shard" + expected;
  if(i > n)
    return "--shard=" + value + ": slice " + std::to_string(i) + " of " + std::to_string(n) +
           " does not exist" + expected;
  o.batch.shard = i;
  o.batch.shards = n;
  return std::string();
}

// An option with a value, `--name=value`.
struct Value_option
{
  const char* name;
  std::string (*set)(const std::string& value, Options& o);
  bool seen;
};

// The parsing of one command line: the arguments one by one, then `finish()`.
class Parser
{
public:
  explicit Parser(Options& o) : m_o(o) { }

  std::string argument(const std::string& arg)
  {
    if(m_options_ended || arg.empty() || arg[0] != '-')
      m_positional.push_back(arg);
    else if(arg == "--")
      m_options_ended = true;
    else if(arg == "-h" || arg == "--help")
      m_o.help = true;
    else if(arg == "--json")
    {
      if(m_o.json)
        return "option --json is given twice";
      m_o.json = true;
    }
    else if(starts_with(arg, "--json="))
      return "option --json takes no value";
    else if(arg == "--no-repair")
    {
      if(!m_o.repair)
        return "option --no-repair is given twice";
      m_o.repair = false;
    }
    else if(arg == "--atlas" || arg == "--single-chart")
    {
      bool& seen = (arg == "--atlas") ? m_atlas : m_single_chart;
      if(seen)
        return "option " + arg + " is given twice";
      seen = true;
    }
    else if(starts_with(arg, "--atlas=") || starts_with(arg, "--single-chart="))
      return "option " + arg.substr(0, arg.find('=')) + " takes no value";
    else if(arg == "--force")
    {
      if(m_o.batch.force)
        return "option --force is given twice";
      m_o.batch.force = true;
    }
    else if(starts_with(arg, "--force="))
      return "option --force takes no value";
    else
      return value_option(arg);
    return std::string();
  }

  // the defaults that depend on other options, and the positional arguments
  std::string finish()
  {
    const std::string mode_problem = choose_mode();
    if(!mode_problem.empty())
      return mode_problem;
    // the automatic border's measured member: fast marching geodesics unless asked otherwise
    // (no second matrix to factorize); the measured border alone: the paper's Poisson distances
    if(!seen("--distance") && m_o.border == Border::automatic)
      m_o.distance = "fast-marching";
    const std::vector<std::string>& p = m_positional;
    const std::string batch_problem = check_batch();
    if(!batch_problem.empty())
      return batch_problem;
    if(p.size() > 2)
      return "too many arguments: '" + p[2] + "' (expected at most INPUT and OUTPUT.obj)";
    if(p.size() > 0)
      m_o.input = p[0];
    if(p.size() > 1)
    {
      if(seen("--output"))
        return "OUTPUT is given twice: '" + p[1] + "' and --output=" + m_o.output;
      m_o.output = p[1];
    }
    if(m_o.input.empty() && p.size() > 0)
      return "empty INPUT file name";
    if(m_o.output.empty() && p.size() > 1)
      return "empty OUTPUT file name";
    return std::string();
  }

private:
  // The mode: the atlas unless --single-chart or one of its options is given; the options of
  // one mode are refused in the other.
  std::string choose_mode()
  {
    std::string single_option = m_single_chart ? "--single-chart" : m_o.repair ? "" : "--no-repair";
    for(const char* name : {"--border", "--center", "--distance", "--seams", "--write-seams", "--solver"})
      if(single_option.empty() && seen(name))
        single_option = name;
    std::string atlas_option, bound_option;
    for(const char* name : {"--resolution", "--gutter", "--min-compactness", "--split"})
      if(atlas_option.empty() && seen(name))
        atlas_option = name;
    for(const char* name : {"--max-area-spread", "--max-angle-distortion"})  // also the automatic border's bound
      if(bound_option.empty() && seen(name))
        bound_option = name;
    if(single_option.empty())
    {
      m_o.mode = Mode::atlas;
      if(m_o.gutter > m_o.resolution / 4)
        return "--gutter=" + std::to_string(m_o.gutter) + " is too wide for --resolution=" +
               std::to_string(m_o.resolution) + " (at most " + std::to_string(m_o.resolution / 4) +
               " texels: a quarter of the resolution)";
      return std::string();
    }
    m_o.mode = Mode::single_chart;
    if(m_atlas)
      return "option --atlas cannot be combined with " + single_option +
             (single_option == "--single-chart" ? std::string() : " (an option of the single-chart mode)");
    if(!atlas_option.empty())
      return "option " + atlas_option + " (of the atlas) cannot be combined with " + single_option +
             (single_option == "--single-chart" ? std::string() : " (an option of the single-chart mode)");
    if(!bound_option.empty() && m_o.border != Border::automatic)
      return "option " + bound_option + " bounds the atlas's charts, or ranks the layouts of --border=auto: it cannot"
             " be combined with --border=" + border_name(m_o.border);
    return std::string();
  }

  // The batch's options go together, and exclude those naming the files of one run.
  std::string check_batch() const
  {
    if(!m_o.batch.active())
    {
      for(const char* name : {"--output-dir", "--jobs", "--shard"})
        if(seen(name))
          return std::string("option ") + name + " is an option of the batch mode: it needs --batch=FOLDER|LIST|-";
      if(m_o.batch.force)
        return "option --force is an option of the batch mode: it needs --batch=FOLDER|LIST|-";
      return std::string();
    }
    if(!seen("--output-dir"))
      return "--batch needs --output-dir=DIR (where the outputs and report.jsonl are written)";
    if(!m_positional.empty())
      return "--batch takes no INPUT or OUTPUT argument ('" + m_positional[0] +
             "'): the inputs are those of --batch=" + m_o.batch.source;
    for(const char* name : {"--output", "--svg", "--seams", "--write-seams"})
      if(seen(name))
        return std::string("option ") + name + " names the file of one run: it cannot be combined with --batch";
    if(m_o.json)
      return "option --json cannot be combined with --batch (the report file holds each mesh's JSON)";
    return std::string();
  }

  bool seen(const std::string& name) const
  {
    for(const Value_option& v : m_values)
      if(name == v.name)
        return v.seen;
    return false;
  }

  std::string value_option(const std::string& arg)
  {
    for(Value_option& v : m_values)
      if(arg == v.name || starts_with(arg, std::string(v.name) + "="))
      {
        std::string value;
        const std::string error = value_of(arg, v.name, v.seen, value);
        return error.empty() ? v.set(value, m_o) : error;
      }
    return "unknown option '" + arg + "'";  // the program adds the hint to --help
  }

  Options& m_o;
  std::vector<std::string> m_positional;
  bool m_options_ended = false;
  bool m_atlas = false, m_single_chart = false;  // --atlas, --single-chart
  Value_option m_values[19] = {
    {"--center", set_center, false},
    {"--distance", set_distance, false},
    {"--border", set_border, false},
    {"--solver", set_solver, false},
    {"--output", [](const std::string& v, Options& o) { return set_file(v, "--output", "FILE", o.output); }, false},
    {"--seams", [](const std::string& v, Options& o) { return set_file(v, "--seams", "FILE.selection.txt", o.seams); },
     false},
    {"--write-seams",
     [](const std::string& v, Options& o) { return set_file(v, "--write-seams", "FILE.selection.txt", o.write_seams); },
     false},
    {"--svg", [](const std::string& v, Options& o) { return set_file(v, "--svg", "FILE", o.svg); }, false},
    {"--resolution",
     [](const std::string& v, Options& o) { return set_count(v, "--resolution", 8, 1u << 16, o.resolution); }, false},
    {"--gutter", [](const std::string& v, Options& o) { return set_count(v, "--gutter", 0, 1u << 14, o.gutter); },
     false},
    {"--max-area-spread",
     [](const std::string& v, Options& o) {
       return set_number(v, "--max-area-spread", 0., HUGE_VAL, o.bounds.max_area_spread);
     }, false},
    {"--max-angle-distortion",
     [](const std::string& v, Options& o) {
       return set_number(v, "--max-angle-distortion", 0., HUGE_VAL, o.bounds.max_angle_distortion);
     }, false},
    {"--min-compactness",
     [](const std::string& v, Options& o) { return set_number(v, "--min-compactness", 0., 1., o.bounds.min_compactness); },
     false},
    {"--split", set_split, false},
    {"--threads", [](const std::string& v, Options& o) { return set_count(v, "--threads", 0, 256, o.threads); },
     false},
    {"--batch", [](const std::string& v, Options& o) { return set_file(v, "--batch", "FOLDER|LIST|-", o.batch.source); },
     false},
    {"--output-dir",
     [](const std::string& v, Options& o) { return set_file(v, "--output-dir", "DIR", o.batch.output_dir); }, false},
    {"--jobs", [](const std::string& v, Options& o) { return set_count(v, "--jobs", 1, 256, o.batch.jobs); }, false},
    {"--shard", set_shard, false}};
};

} // namespace

bool has_cholmod()
{
#ifdef MBP_WITH_CHOLMOD
  return true;
#else
  return false;
#endif
}

const char* solver_name(Solver s)
{
  return s == Solver::cholmod ? "cholmod" : s == Solver::cholmod_nd ? "cholmod-nd" : "ldlt";
}

const char* border_name(Border b)
{
  return b == Border::conformal           ? "conformal"
         : b == Border::conformal_lengths ? "conformal-lengths"
         : b == Border::measured          ? "measured"
         : b == Border::circle            ? "circle"
                                          : "auto";
}

const char* mode_name(Mode m)
{
  return m == Mode::atlas ? "atlas" : "single-chart";
}

const std::vector<std::string>& geodesic_methods()
{
  static const std::vector<std::string> names = {"fast-marching", "dijkstra", "heat", "heat-idt", "exact"};
  return names;
}

bool is_geodesic_method(const std::string& name)
{
  for(const std::string& m : geodesic_methods())
    if(m == name)
      return true;
  return false;
}

std::string usage(const std::string& default_mesh)
{
  return usage_synopsis + (default_mesh.empty() ? std::string("none configured") : default_mesh) + usage_options +
         (has_cholmod() ? "cholmod" : "ldlt (this build has no CHOLMOD)") + usage_notes;
}

std::string parse_options(int argc, char** argv, Options& o)
{
  Parser parser(o);
  for(int i = 1; i < argc; ++i)
  {
    const std::string error = parser.argument(argv[i]);
    if(!error.empty())
      return error;
    if(o.help)  // --help stops the parsing
      return std::string();
  }
  return parser.finish();
}

} // namespace mbp_cli
