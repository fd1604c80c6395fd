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

#include <charconv>
#include <system_error>

namespace mbp_cli {

namespace {

// The help text, in three parts: before the default mesh, before the default solver, and
// after it.
const char* const usage_synopsis =
    "usage: measured_parameterization [INPUT] [OUTPUT.obj] [--seams=FILE.selection.txt]\n"
    "                                 [--center=poisson|geodesic[:METHOD]|vertex:N]\n"
    "                                 [--distance=poisson|METHOD|straightest] [--border=auto|conformal|measured|circle]\n"
    "                                 [--solver=cholmod|cholmod-nd|ldlt] [--output=FILE] [--svg=FILE] [--json]\n"
    "                                 [--write-seams=FILE.selection.txt]\n"
    "                                 [--no-repair] [--help]\n"
    "\n"
    "Flattens a disk-like triangle mesh with the measured boundary parameterization of\n"
    "\"Measured boundary parameterization based on Poisson's equation\": the longest border is\n"
    "laid out around a center vertex at its measured distances from it, and the interior is\n"
    "the discrete conformal map with that border fixed. A mesh that is not a disk (closed, with\n"
    "holes or with handles) is first cut open into a disk along seams: those of --seams, or\n"
    "automatic seams (see --seams).\n"
    "\n"
    "  INPUT              a triangle mesh: .off, .obj, .ply or .stl, one connected component\n"
    "                     with at least one border (holes are allowed; the longest border is\n"
    "                     mapped), or cut along --seams. Default: ";

const char* const usage_options =
    "\n"
    "                     (a generated curved disk when that file does not exist).\n"
    "  OUTPUT.obj         the mesh with one UV per vertex: 'v' lines in input order, one 'vt'\n"
    "                     line per 'v' line, faces 'f a/a b/b c/c'. Vertices that are in no face\n"
    "                     are left out. Default: <INPUT file stem>_uv.obj in the current\n"
    "                     directory (curved_disk_uv.obj for the generated mesh).\n"
    "                     With --seams: one 'vt' line per vertex of the cut mesh (a vertex on a\n"
    "                     seam gets one UV for each side), faces 'f a/i b/j c/k'.\n"
    "\n"
    "options:\n"
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
    "                     so that one matrix is factorized), the conformal border, and blends\n"
    "                     toward a convex border of the members whose own layout folds. The\n"
    "                     valid layout of lowest angle distortion is kept; the summary names\n"
    "                     it, --json lists every candidate\n"
    "  --border=conformal the conformal border (Boundary First Flattening's border with\n"
    "                     boundary scale factors 0): near-conformal, one factorization\n"
    "  --border=measured  the paper's measured border at the --distance distances\n"
    "  --border=circle    CGAL's circle with arc-length angles\n"
    "  --solver=NAME      sparse Cholesky factorization: cholmod (CHOLMOD supernodal, AMD\n"
    "                     ordering), cholmod-nd (CHOLMOD with METIS's nested dissection: a\n"
    "                     third less memory for the factor, a slower analysis; for meshes of\n"
    "                     millions of vertices) or ldlt (Eigen's SimplicialLDLT). Default: ";

const char* const usage_notes =
    "\n"
    "  --output=FILE      the same as OUTPUT.obj (for example with the default INPUT)\n"
    "  --svg=FILE         also write an SVG picture of the UV layout, faces colored by their\n"
    "                     angle distortion, flipped faces in red\n"
    "  --json             print a JSON object on stdout instead of the one-line summary\n"
    "  --no-repair        fail when the layout has flipped faces (by default the border is\n"
    "                     blended toward a circle, as little as needed, until none is left)\n"
    "  -h, --help         print this help and exit\n"
    "\n"
    "The summary gives the number of vertices (V) and faces (F), with seams the number of seam\n"
    "edges (and of cones for automatic seams) and of UVs, the border (vertices, 3D length; a\n"
    "seam counts on both sides), the center (0-based index in the input), the time of each\n"
    "stage of the parameterization in\n"
    "seconds, the factorizations and back-substitutions, and the\n"
    "distortion: angle distortion (the paper's conformal distortion), Sander's L2 stretch\n"
    "(1 is optimal), the area-weighted mean quasi-conformal distortion s1/s2 (1 is\n"
    "conformal) and the number of flipped faces.\n"
    "\n"
    "The measured border need not be convex, so the layout can fold: flipped faces are then\n"
    "repaired by blending the border toward a circle (reported in the summary), or, with\n"
    "--no-repair, the program fails.\n"
    "\n"
    "Exit status: 0 on success; 1 when the input cannot be parameterized or an output file\n"
    "cannot be written (no output file is then left behind); 2 on a command-line error.\n";

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
  for(Border b : {Border::automatic, Border::conformal, Border::measured, Border::circle})
    if(value == border_name(b))
    {
      o.border = b;
      return std::string();
    }
  return "unknown value '" + value + "' of --border (expected auto, conformal, measured or circle)";
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

// --NAME=FILE: `file` is set, or the error for an empty name
std::string set_file(const std::string& value, const std::string& name, const char* placeholder, std::string& file)
{
  if(value.empty())
    return "option " + name + " needs a file name: " + name + "=" + placeholder;
  file = value;
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
    else
      return value_option(arg);
    return std::string();
  }

  // the defaults that depend on other options, and the positional arguments
  std::string finish()
  {
    // the automatic border's measured member: fast marching geodesics unless asked otherwise
    // (no second matrix to factorize); the measured border alone: the paper's Poisson distances
    if(!seen("--distance") && m_o.border == Border::automatic)
      m_o.distance = "fast-marching";
    const std::vector<std::string>& p = m_positional;
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
  Value_option m_values[8] = {
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
    {"--svg", [](const std::string& v, Options& o) { return set_file(v, "--svg", "FILE", o.svg); }, false}};
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
  return b == Border::conformal ? "conformal" : b == Border::measured ? "measured"
         : b == Border::circle  ? "circle"    : "auto";
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
