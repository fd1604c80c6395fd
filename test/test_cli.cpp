// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// The command-line program (cli/), run as a user runs it:
// its OBJ is the mesh with the library's UVs, its SVG and JSON are complete, and every kind
// of bad input ends with a message naming the problem, a non-zero exit and no output file.

#include <boost/test/unit_test.hpp>

#include "atlas_soups.h"
#include "test_support.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/border.h>

#include <CGAL/Surface_mesh_parameterization/Distortion_bound.h>
#include <CGAL/Surface_mesh_parameterization/Measured_conformal_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/main_border.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

BOOST_AUTO_TEST_SUITE(cli)

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace fs = std::filesystem;
typedef CGAL::Simple_cartesian<double>                     K;
typedef CGAL::Surface_mesh<K::Point_3>                     Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor       vertex_descriptor;
typedef boost::graph_traits<Mesh>::halfedge_descriptor     halfedge_descriptor;

namespace {

// ---------------------------------------------------------------- running the program

struct Run
{
  bool exited = false;  // false: killed by a signal (a crash)
  int code = -1;        // exit status
  int signal = 0;       // the signal that ended it (run_stopped)
  std::string out, err;
};

// A fresh directory for one run: `work` is the program's working directory (it holds the
// input files the test writes, and should hold nothing else after a failure), stdout and
// stderr are captured beside it. Removed at the end.
struct Scratch
{
  fs::path root, work;
  fs::path standard_input;  // when set, the program's stdin (otherwise the test's)

  Scratch()
  {
    static int counter = 0;
    root = fs::temp_directory_path() /
           ("mbp_test_cli_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    work = root / "work";
    fs::remove_all(root);
    fs::create_directories(work);
  }
  ~Scratch()
  {
    std::error_code ec;
    fs::remove_all(root, ec);
  }

  fs::path write(const std::string& name, const std::string& contents) const
  {
    std::ofstream out(work / name, std::ios::binary);
    out << contents;
    BOOST_REQUIRE(out.good());
    return work / name;
  }

  std::set<std::string> files() const
  {
    std::set<std::string> names;
    for(const auto& entry : fs::directory_iterator(work))
      names.insert(entry.path().filename().string());
    return names;
  }

  Run run(const std::vector<std::string>& args, const std::string& program = MBP_CLI_PROGRAM) const
  {
    return run_with(args, program, nullptr);
  }

  // Runs the program with MBP_CLI_TEST_STOP_BEFORE_PUBLISH set: it stops itself (SIGSTOP)
  // when every output is written to its temporary file, before any is published; then
  // `when_stopped(pid)` runs (it must continue or kill the program).
  Run run_stopped(const std::vector<std::string>& args, const std::function<void(pid_t)>& when_stopped) const
  {
    return run_with(args, MBP_CLI_PROGRAM, &when_stopped);
  }

  Run run_with(const std::vector<std::string>& args, const std::string& program,
               const std::function<void(pid_t)>* when_stopped) const
  {
    const std::string out = (root / "stdout.txt").string(), err = (root / "stderr.txt").string();
    const std::string cwd = work.string();
    std::vector<std::string> argv_strings{program};
    argv_strings.insert(argv_strings.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for(std::string& a : argv_strings)
      argv.push_back(&a[0]);
    argv.push_back(nullptr);

    const pid_t pid = ::fork();
    BOOST_REQUIRE(pid >= 0);
    if(pid == 0)
    {
      const int o = ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      const int e = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      if(o < 0 || e < 0 || ::chdir(cwd.c_str()) != 0 || ::dup2(o, 1) < 0 || ::dup2(e, 2) < 0)
        ::_exit(126);
      const int i = standard_input.empty() ? 0 : ::open(standard_input.c_str(), O_RDONLY);
      if(i < 0 || ::dup2(i, 0) < 0)
        ::_exit(126);
      if(when_stopped != nullptr)
        ::setenv("MBP_CLI_TEST_STOP_BEFORE_PUBLISH", "1", 1);
      ::alarm(600);  // a program that blocks (a FIFO) is killed instead of hanging the test
      ::execv(argv[0], argv.data());
      ::_exit(127);
    }
    int status = 0;
    if(when_stopped != nullptr)
    {
      BOOST_REQUIRE(::waitpid(pid, &status, WUNTRACED) == pid);
      if(WIFSTOPPED(status))
      {
        (*when_stopped)(pid);
        BOOST_REQUIRE(::waitpid(pid, &status, 0) == pid);
      }
    }
    else
      BOOST_REQUIRE(::waitpid(pid, &status, 0) == pid);
    Run r;
    r.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
    r.exited = WIFEXITED(status);
    r.code = r.exited ? WEXITSTATUS(status) : -1;
    r.out = read_text(out);
    r.err = read_text(err);
    BOOST_TEST_MESSAGE("ran " << program << " ... -> " << (r.exited ? "exit " + std::to_string(r.code) : "signal")
                       << "\nstderr: " << r.err);
    BOOST_REQUIRE_MESSAGE(r.exited || when_stopped != nullptr,
                          "the program was killed by signal " << WTERMSIG(status) << "\n" << r.err);
    BOOST_REQUIRE_MESSAGE(r.code != 126 && r.code != 127, "could not start " << program);
    return r;
  }

  static std::string read_text(const fs::path& path)
  {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }
};

std::string lower(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

bool contains(const std::string& text, const std::string& part)
{
  return lower(text).find(lower(part)) != std::string::npos;
}

// ---------------------------------------------------------------- reading the outputs

struct Obj
{
  std::vector<std::array<double, 3> > v;
  std::vector<std::array<double, 2> > vt;
  std::vector<std::array<std::size_t, 3> > f;   // 'v' indices, 0-based
  std::vector<std::array<std::size_t, 3> > ft;  // 'vt' indices, 0-based (equal to f without seams)
  std::size_t other_lines = 0;                  // lines that are not v, vt, f, comments or empty
};

// Reads the OBJ the program writes; every face corner must be "a/b" with valid indices, and
// "a/a" unless `seams` (one UV per vertex).
Obj read_obj(const fs::path& path, bool seams = false)
{
  std::ifstream in(path);
  BOOST_REQUIRE_MESSAGE(in.good(), "cannot open " << path);
  Obj obj;
  std::string line;
  while(std::getline(in, line))
  {
    std::istringstream s(line);
    std::string tag;
    if(!(s >> tag) || tag[0] == '#')
      continue;
    if(tag == "v")
    {
      std::array<double, 3> p;
      BOOST_REQUIRE_MESSAGE(s >> p[0] >> p[1] >> p[2], "bad line: " << line);
      obj.v.push_back(p);
    }
    else if(tag == "vt")
    {
      std::array<double, 2> q;
      BOOST_REQUIRE_MESSAGE(s >> q[0] >> q[1], "bad line: " << line);
      obj.vt.push_back(q);
    }
    else if(tag == "f")
    {
      std::array<std::size_t, 3> face, uv_face;
      std::string corner;
      for(std::size_t k = 0; k < 3; ++k)
      {
        BOOST_REQUIRE_MESSAGE(s >> corner, "face with fewer than 3 corners: " << line);
        const std::size_t slash = corner.find('/');
        BOOST_REQUIRE_MESSAGE(slash != std::string::npos, "corner without a UV index: " << line);
        const std::string a = corner.substr(0, slash), b = corner.substr(slash + 1);
        BOOST_REQUIRE_MESSAGE(seams || a == b, "v and vt indices differ: " << line);
        const long index = std::stol(a), uv_index = std::stol(b);
        BOOST_REQUIRE_MESSAGE(index >= 1 && uv_index >= 1, "bad index: " << line);
        face[k] = std::size_t(index - 1);
        uv_face[k] = std::size_t(uv_index - 1);
      }
      BOOST_REQUIRE_MESSAGE(!(s >> corner), "face with more than 3 corners: " << line);
      obj.f.push_back(face);
      obj.ft.push_back(uv_face);
    }
    else
      ++obj.other_lines;
  }
  for(std::size_t i = 0; i < obj.f.size(); ++i)
    for(std::size_t k = 0; k < 3; ++k)
      BOOST_REQUIRE(obj.f[i][k] < obj.v.size() && obj.ft[i][k] < obj.vt.size());
  return obj;
}

// the signed area of a UV triangle given by its 'vt' indices
double signed_uv_area(const Obj& obj, const std::array<std::size_t, 3>& f)
{
  const auto &a = obj.vt[f[0]], &b = obj.vt[f[1]], &c = obj.vt[f[2]];
  return 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
}

boost::property_tree::ptree parse_json(const std::string& text)
{
  boost::property_tree::ptree tree;
  std::istringstream in(text);
  BOOST_REQUIRE_NO_THROW(boost::property_tree::read_json(in, tree));
  return tree;
}

// ---------------------------------------------------------------- meshes

// The program's default mesh (MBP_CLI_DEFAULT_MESH of the top CMakeLists.txt).
std::string default_mesh_path()
{
  const std::string path = MBP_CLI_DEFAULT_MESH;
  BOOST_REQUIRE_MESSAGE(mbp_test::file_exists(path), "missing default mesh " << path);
  return path;
}

std::vector<vertex_descriptor> border_loop(const Mesh& mesh)
{
  std::vector<vertex_descriptor> loop;
  for(halfedge_descriptor h : CGAL::halfedges_around_face(mbp_test::longest_border(mesh), mesh))
    loop.push_back(target(h, mesh));
  return loop;
}

std::string off_text(const mbp_test::Soup& soup)
{
  std::ostringstream s;
  s.precision(17);
  s << "OFF\n" << soup.points.size() << " " << soup.faces.size() << " 0\n";
  for(const auto& p : soup.points)
    s << p[0] << " " << p[1] << " " << p[2] << "\n";
  for(const auto& f : soup.faces)
  {
    s << f.size();
    for(std::size_t i : f)
      s << " " << i;
    s << "\n";
  }
  return s.str();
}

// A 3x3 grid of the unit square split into 8 triangles; vertex 4 is the only interior vertex.
const char* grid_off = "OFF\n9 8 0\n0 0 0\n1 0 0\n2 0 0\n0 1 0\n1 1 0.3\n2 1 0\n0 2 0\n1 2 0\n2 2 0\n"
                       "3 0 1 4\n3 0 4 3\n3 1 2 5\n3 1 5 4\n3 3 4 7\n3 3 7 6\n3 4 5 8\n3 4 8 7\n";

// Checks the OBJ of a run against the input mesh: the vertices in input order with their
// exact coordinates, one UV per vertex inside [0,1]^2, the input's faces, no flipped face.
void check_obj_against_mesh(const Obj& obj, const Mesh& mesh)
{
  BOOST_TEST(obj.other_lines == 0u);
  BOOST_REQUIRE_EQUAL(obj.v.size(), num_vertices(mesh));
  BOOST_REQUIRE_EQUAL(obj.vt.size(), num_vertices(mesh));
  BOOST_REQUIRE_EQUAL(obj.f.size(), num_faces(mesh));
  std::size_t exact = 0;
  for(vertex_descriptor v : vertices(mesh))
  {
    const auto& p = mesh.point(v);
    const auto& q = obj.v[std::size_t(v)];
    exact += (q[0] == p.x() && q[1] == p.y() && q[2] == p.z()) ? 1 : 0;
  }
  BOOST_TEST(exact == num_vertices(mesh), "vertices written exactly and in input order: " << exact);

  // [0,1]^2 up to the rounding of the library's scaling
  const double eps = 1e-12;
  std::size_t outside = 0;
  for(const auto& q : obj.vt)
    outside += (std::isfinite(q[0]) && std::isfinite(q[1]) && q[0] >= -eps && q[0] <= 1. + eps &&
                q[1] >= -eps && q[1] <= 1. + eps) ? 0 : 1;
  BOOST_TEST(outside == 0u, outside << " UVs outside [0,1]^2");

  std::size_t same_faces = 0, flipped = 0;
  std::size_t i = 0;
  for(auto f : faces(mesh))
  {
    std::array<std::size_t, 3> t;
    std::size_t k = 0;
    for(vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
      t[k++] = std::size_t(v);
    same_faces += (t == obj.f[i]) ? 1 : 0;
    flipped += (signed_uv_area(obj, obj.f[i]) > 0.) ? 0 : 1;
    ++i;
  }
  BOOST_TEST(same_faces == num_faces(mesh), "faces written as in the input: " << same_faces);
  BOOST_TEST(flipped == 0u, flipped << " flipped faces");
}

} // namespace

// ---------------------------------------------------------------- successful runs

BOOST_AUTO_TEST_CASE(default_run_writes_obj_svg_and_summary)
{
  // the single chart of the default mesh (--single-chart: the program's default is the atlas,
  // default_run_is_an_atlas)
  const std::string path = default_mesh_path();
  Mesh mesh;
  mbp_test::read_mesh(path, mesh);
  const std::size_t border_size = border_loop(mesh).size();

  Scratch scratch;
  const Run r = scratch.run({"--svg=layout.svg", "--single-chart"});  // no INPUT, no OUTPUT
  BOOST_REQUIRE_EQUAL(r.code, 0);
  const std::string obj_name = fs::path(path).stem().string() + "_uv.obj";
  BOOST_TEST((scratch.files() == std::set<std::string>{obj_name, "layout.svg"}));

  // the summary: one line with V and F
  BOOST_TEST(std::count(r.out.begin(), r.out.end(), '\n') == 1);
  BOOST_TEST(contains(r.out, "V " + std::to_string(num_vertices(mesh))), r.out);
  BOOST_TEST(contains(r.out, "F " + std::to_string(num_faces(mesh))), r.out);
  BOOST_TEST(contains(r.out, "angle distortion"));
  BOOST_TEST(contains(r.out, "L2 stretch"));
  // the default: the automatic border with fast marching distances, one factorization and one
  // for the holomorphic extension of its layout (within the bound)
  BOOST_TEST(contains(r.out, " 2 factorizations, "), r.out);
  BOOST_TEST(contains(r.out, "| border auto: "), r.out);
  BOOST_TEST(!contains(r.out, "nan"));

  check_obj_against_mesh(read_obj(scratch.work / obj_name), mesh);

  // the SVG: a complete document with the border as a closed polyline of all its vertices,
  // the caption, the legend and the center; small for its number of faces
  const std::string svg = Scratch::read_text(scratch.work / "layout.svg");
  BOOST_TEST(svg.rfind("<?xml", 0) == 0u);
  BOOST_TEST(contains(svg, "<svg xmlns=\"http://www.w3.org/2000/svg\""));
  BOOST_TEST(svg.size() > 20u);
  BOOST_TEST(svg.substr(svg.size() - 7) == "</svg>\n");
  const std::size_t polygon = svg.find("<polygon");
  BOOST_REQUIRE(polygon != std::string::npos);
  const std::size_t points = svg.find("points=\"", polygon) + 8;
  const std::string point_list = svg.substr(points, svg.find('"', points) - points);
  BOOST_TEST(std::size_t(std::count(point_list.begin(), point_list.end(), ',')) == border_size);
  BOOST_TEST(contains(svg, fs::path(path).filename().string()));
  BOOST_TEST(contains(svg, "angle distortion"));
  BOOST_TEST(contains(svg, "flipped faces: 0"));
  BOOST_TEST(!contains(svg, "nan"));
  BOOST_TEST(svg.size() < 40 * num_faces(mesh) + 30000, "SVG of " << svg.size() << " bytes");

  // --output names the OBJ of the default input
  Scratch named;
  BOOST_REQUIRE_EQUAL(named.run({"--output=named.obj", "--single-chart"}).code, 0);
  BOOST_TEST((named.files() == std::set<std::string>{"named.obj"}));
  check_obj_against_mesh(read_obj(named.work / "named.obj"), mesh);
}

BOOST_AUTO_TEST_CASE(obj_holds_the_library_result)
{
  const std::string path = default_mesh_path();
  Mesh mesh;
  mbp_test::read_mesh(path, mesh);
  auto uv = mesh.add_property_map<vertex_descriptor, K::Point_2>("v:uv").first;
  SMP::Measured_conformal_parameterizer_3<Mesh> parameterizer;  // Eigen's LDLT
  auto marked = mesh.add_property_map<vertex_descriptor, bool>("v:marked", false).first;
  // the command line lays out the border of SMP::main_border()
  SMP::Parameterization_report report;
  BOOST_REQUIRE(parameterizer.parameterize(mesh, SMP::main_border(mesh).first, uv,
                                           get(boost::vertex_index, mesh), marked, &report) == SMP::OK);
  BOOST_REQUIRE(report.has_center);  // its position in vertices(mesh): the file order

  std::vector<std::string> solvers{"ldlt"};
#ifdef MBP_CLI_HAS_CHOLMOD
  solvers.push_back("cholmod");
  solvers.push_back("cholmod-nd");
#endif
  for(const std::string& solver : solvers)
  {
    BOOST_TEST_CONTEXT("--solver=" << solver)
    {
      Scratch scratch;
      const Run r = scratch.run({path, "out.obj", "--json", "--border=measured", "--solver=" + solver});
      BOOST_REQUIRE_EQUAL(r.code, 0);
      const boost::property_tree::ptree json = parse_json(r.out);
      BOOST_TEST(json.get<std::string>("solver") == solver);
      BOOST_TEST(json.get<std::size_t>("center.index") == report.center);
      const Obj obj = read_obj(scratch.work / "out.obj");
      check_obj_against_mesh(obj, mesh);
      // the same computation with LDLT; CHOLMOD's factorization differs in rounding only
      const double tolerance = (solver == "ldlt") ? 1e-12 : 1e-8;
      double worst = 0.;
      for(vertex_descriptor v : vertices(mesh))
      {
        const auto& q = obj.vt[std::size_t(v)];
        worst = (std::max)(worst, std::hypot(q[0] - get(uv, v).x(), q[1] - get(uv, v).y()));
      }
      BOOST_TEST(worst <= tolerance, "largest UV difference from the library: " << worst);
    }
  }
}

BOOST_AUTO_TEST_CASE(json_output_and_fixed_center)
{
  const std::string path = default_mesh_path();
  Mesh mesh;
  mbp_test::read_mesh(path, mesh);
  // an interior vertex far from the start of the file
  const std::vector<vertex_descriptor> loop = border_loop(mesh);
  std::size_t n = num_vertices(mesh) / 3;
  while(std::find(loop.begin(), loop.end(), vertex_descriptor(Mesh::size_type(n))) != loop.end())
    ++n;

  for(const bool fixed : {false, true})
  {
    BOOST_TEST_CONTEXT((fixed ? "--center=vertex:N" : "--center=poisson"))
    {
      Scratch scratch;
      std::vector<std::string> args{path, "out.obj", "--json", "--svg=out.svg", "--border=measured"};
      args.push_back(fixed ? "--center=vertex:" + std::to_string(n) : std::string("--center=poisson"));
      const Run r = scratch.run(args);
      BOOST_REQUIRE_EQUAL(r.code, 0);
      const boost::property_tree::ptree j = parse_json(r.out);
      // every figure is a finite number (the program writes null for an infinite one, which
      // these figures are not on this mesh)
      for(const char* group : {"times", "io_times", "statistics", "quality", "border", "center.point", "center.uv"})
        for(const auto& leaf : j.get_child(group))
        {
          if(leaf.second.empty() && leaf.first != "convex")
          {
            const boost::optional<double> x = leaf.second.get_value_optional<double>();
            BOOST_TEST((x && std::isfinite(*x)), group << "." << leaf.first << " = " << leaf.second.data());
          }
        }

      BOOST_TEST(j.get<std::string>("input") == path);
      BOOST_TEST(j.get<std::string>("output") == "out.obj");
      BOOST_TEST(j.get<std::string>("svg") == "out.svg");
      BOOST_TEST(j.get<std::size_t>("vertices") == num_vertices(mesh));
      BOOST_TEST(j.get<std::size_t>("faces") == num_faces(mesh));
      BOOST_TEST(j.get<std::size_t>("border.vertices") == loop.size());
      BOOST_TEST(j.get<double>("border.length") > 0.);
      for(const char* key : {"preparation", "center", "distances", "border_map", "interior", "total"})
        BOOST_TEST(j.get<double>(std::string("times.") + key) >= 0., key);
      BOOST_TEST(j.get<double>("times.total") >= j.get<double>("times.interior"));
      for(const char* key : {"angle_distortion", "l2_stretch", "quasi_conformal_mean"})
        BOOST_TEST(std::isfinite(j.get<double>(std::string("quality.") + key)), key);
      BOOST_TEST(j.get<double>("quality.l2_stretch") >= 1.);
      BOOST_TEST(j.get<double>("quality.quasi_conformal_mean") >= 1.);
      BOOST_TEST(j.get<std::size_t>("quality.flipped_faces") == 0u);
      // the paper's cost: 2 factorizations, 4 back-substitutions (3 when the center is given)
      BOOST_TEST(j.get<int>("statistics.factorizations") == 2);
      BOOST_TEST(j.get<int>("statistics.back_substitutions") == (fixed ? 3 : 4));

      const std::size_t center = j.get<std::size_t>("center.index");
      if(fixed)
        BOOST_TEST(center == n);
      // the center is the input's vertex of that index, given in file order
      BOOST_REQUIRE(center < num_vertices(mesh));
      const auto& p = mesh.point(vertex_descriptor(Mesh::size_type(center)));
      std::vector<double> point;
      for(const auto& child : j.get_child("center.point"))
        point.push_back(child.second.get_value<double>());
      BOOST_REQUIRE_EQUAL(point.size(), 3u);
      BOOST_TEST(point[0] == p.x());
      BOOST_TEST(point[1] == p.y());
      BOOST_TEST(point[2] == p.z());
      BOOST_TEST(contains(Scratch::read_text(scratch.work / "out.svg"), "center (vertex " + std::to_string(center) + ")"));
    }
  }
}

BOOST_AUTO_TEST_CASE(geodesic_centers_and_distances)
{
  // exact geodesics reproduce a flat star-shaped disk: no angle distortion, L2 stretch 1,
  // at the cost of one factorization and two back-substitutions (BGDM center)
  {
    Scratch scratch;
    scratch.write("ellipse.off", off_text(mbp_test::hex_disk(10, 2., 1.)));
    const Run r = scratch.run({"ellipse.off", "out.obj", "--json", "--border=measured", "--center=geodesic:exact",
                               "--distance=exact"});
    BOOST_REQUIRE_EQUAL(r.code, 0);
    const boost::property_tree::ptree j = parse_json(r.out);
    BOOST_TEST(j.get<std::string>("center_locator") == "geodesic:exact");
    BOOST_TEST(j.get<std::string>("border_distance") == "exact");
    BOOST_TEST(j.get<std::size_t>("center.index") == 0u);  // the ellipse's center
    BOOST_TEST(j.get<double>("quality.angle_distortion") < 1e-9);
    BOOST_TEST(std::abs(j.get<double>("quality.l2_stretch") - 1.) < 1e-9);
    BOOST_TEST(j.get<int>("statistics.factorizations") == 1);
    BOOST_TEST(j.get<int>("statistics.back_substitutions") == 2);
  }
  // on a real open patch every method runs, and geodesic borders beat the Poisson border
  // (the paper's Table 1: MBPGP below MBPPP)
  const std::string path = default_mesh_path();
  double poisson = 0.;
  for(const std::string d : {"poisson", "fast-marching", "dijkstra", "heat", "heat-idt", "exact"})
    BOOST_TEST_CONTEXT("--distance=" << d)
    {
      Scratch scratch;
      const Run r = scratch.run({path, "out.obj", "--json", "--border=measured", "--distance=" + d,
                                 "--center=geodesic:heat"});
      BOOST_REQUIRE_EQUAL(r.code, 0);
      const boost::property_tree::ptree j = parse_json(r.out);
      BOOST_TEST(j.get<std::size_t>("quality.flipped_faces") == 0u);
      const double angle = j.get<double>("quality.angle_distortion");
      if(d == "poisson")
        poisson = angle;
      else if(d != "dijkstra")
        BOOST_TEST(angle < poisson);
    }
}

BOOST_AUTO_TEST_CASE(automatic_border)
{
  // --border=auto (the default of --single-chart): every layout tried is listed, the kept one is the valid
  // candidate of lowest angle distortion, it is the layout written, and it is never worse
  // than the circle or the paper's measured border run on its own
  const std::string path = default_mesh_path();
  Scratch scratch;
  const Run r = scratch.run({path, "out.obj", "--json", "--single-chart"});
  BOOST_REQUIRE_EQUAL(r.code, 0);
  const boost::property_tree::ptree j = parse_json(r.out);
  BOOST_TEST(j.get<std::string>("mode") == "single-chart");
  BOOST_TEST(j.get<std::string>("border_choice.mode") == "auto");
  BOOST_TEST(j.get<std::string>("border_distance") == "fast-marching");  // auto's measured member
  const boost::property_tree::ptree& candidates = j.get_child("border_choice.candidates");
  BOOST_TEST(candidates.size() >= 2u);
  BOOST_TEST(candidates.size() <= 15u);
  double best = std::numeric_limits<double>::infinity(), circle = -1., conformal = -1.;
  int best_index = -1, index = 0;
  for(const auto& c : candidates)
  {
    const std::string kind = c.second.get<std::string>("kind");
    const double blend = c.second.get<double>("blend");
    BOOST_TEST(blend >= 0.);
    BOOST_TEST(blend <= 1.);
    if(c.second.get<bool>("valid"))
    {
      const double d = c.second.get<double>("angle_distortion");
      if(d < best)
      {
        best = d;
        best_index = index;
      }
      if(kind == "circle")
        circle = d;
      if(kind == "conformal" && !c.second.get<bool>("holomorphic_extension"))
        conformal = d;
    }
    else
      BOOST_TEST(c.second.get<std::string>("angle_distortion") == "null");
    ++index;
  }
  BOOST_TEST(circle > 0.);     // the circle is always tried and valid here
  BOOST_TEST(conformal >= 0.); // the conformal layout of the default mesh is valid
  BOOST_TEST(j.get<int>("border_choice.chosen.index") == best_index);
  BOOST_TEST(j.get<std::string>("border_choice.chosen.kind") == "conformal");
  BOOST_TEST(j.get<double>("border_choice.chosen.angle_distortion") == best);
  // the search's one factorization, and the whole cotangent Laplacian's for the holomorphic
  // extension of the kept layout (within the bound here), tried last
  BOOST_TEST(j.get<int>("statistics.factorizations") == 2);
  BOOST_TEST(candidates.back().second.get<bool>("holomorphic_extension"));
  BOOST_TEST(best <= circle);
  // near-conformal: far below the circle on this curved patch (measured: 0.11x on CGAL's
  // nefertiti.off, the default mesh of a user's clone; 0.009x on the project's Nefertiti)
  BOOST_TEST(best < 0.2 * circle);
  // the objective is the paper's angle distortion of the written layout
  BOOST_TEST(std::abs(j.get<double>("quality.angle_distortion") - best) <= 1e-9 * best + 1e-15);
  // and the chosen candidate's area spread is the written layout's
  const double spread = j.get<double>("quality.area_distortion_mean");
  BOOST_TEST(std::abs(j.get<double>("border_choice.chosen.area_spread") - spread) <= 1e-9 * spread);
  BOOST_TEST(j.get<std::size_t>("quality.flipped_faces") == 0u);
  // the paper's measured border, run on its own, is not better
  const Run m = scratch.run({path, "measured.obj", "--json", "--border=measured"});
  BOOST_REQUIRE_EQUAL(m.code, 0);
  const boost::property_tree::ptree mj = parse_json(m.out);
  BOOST_TEST(mj.get<std::string>("border_choice.mode") == "measured");
  BOOST_TEST(mj.get<std::string>("border_distance") == "poisson");
  BOOST_TEST(mj.get<int>("statistics.factorizations") == 2);
  BOOST_TEST(best <= mj.get<double>("quality.angle_distortion"));
  // --border=conformal and --border=circle give the members alone, with one factorization
  for(const std::string b : {"conformal", "circle"})
  {
    const Run o = scratch.run({path, b + ".obj", "--json", "--border=" + b});
    BOOST_REQUIRE_EQUAL(o.code, 0);
    const boost::property_tree::ptree oj = parse_json(o.out);
    BOOST_TEST(oj.get<int>("statistics.factorizations") == 1);
    BOOST_TEST(oj.get<std::string>("border_choice.chosen.kind") == b);
    const double d = oj.get<double>("quality.angle_distortion");
    BOOST_TEST(std::abs(d - (b == "circle" ? circle : conformal)) <= 1e-9 * d + 1e-15);
  }
  // --border=conformal-lengths: where the conformal polygon is simple (here), the conformal
  // border itself, after one more factorization (the whole cotangent Laplacian's)
  const Run cl = scratch.run({path, "conformal-lengths.obj", "--json", "--border=conformal-lengths"});
  BOOST_REQUIRE_EQUAL(cl.code, 0);
  const boost::property_tree::ptree clj = parse_json(cl.out);
  BOOST_TEST(clj.get<int>("statistics.factorizations") == 2);
  BOOST_TEST(clj.get<std::string>("border_choice.chosen.kind") == "conformal-lengths");
  BOOST_TEST(std::abs(clj.get<double>("quality.angle_distortion") - conformal) <= 1e-9 * conformal + 1e-15);
  BOOST_TEST(clj.get<double>("times.conformal_lengths") > 0.);
  // the summary names the kept border; the OBJ says how it was chosen
  const Run t = scratch.run({path, "text.obj", "--single-chart"});
  BOOST_REQUIRE_EQUAL(t.code, 0);
  BOOST_TEST(contains(t.out, "| border auto: conformal"), t.out);
  BOOST_TEST(contains(t.out, std::to_string(candidates.size()) + " layouts tried"), t.out);
  BOOST_TEST(contains(Scratch::read_text(scratch.work / "text.obj"), "# border: --border=auto, kept conformal"));
  // a bad value is a usage error
  Scratch bad;
  const Run b = bad.run({path, "bad.obj", "--border=convex"});
  BOOST_TEST(b.code == 2);
  BOOST_TEST(contains(b.err, "--border"));
  BOOST_TEST(bad.files().empty());
}

BOOST_AUTO_TEST_CASE(reads_off_obj_ply_and_stl)
{
  Mesh mesh;
  mbp_test::soup_to_mesh(mbp_test::bumpy_disk(), mesh);
  std::size_t reference_center = 0;
  for(const std::string ext : {"off", "obj", "ply", "stl"})
  {
    BOOST_TEST_CONTEXT("." << ext)
    {
      Scratch scratch;
      const fs::path input = scratch.work / ("disk." + ext);
      BOOST_REQUIRE(CGAL::IO::write_polygon_mesh(input.string(), mesh, CGAL::parameters::stream_precision(17)));
      const Run r = scratch.run({input.filename().string(), "--json", "--border=measured"});
      BOOST_REQUIRE_EQUAL(r.code, 0);
      BOOST_TEST(fs::exists(scratch.work / "disk_uv.obj"));  // default OUTPUT
      const boost::property_tree::ptree j = parse_json(r.out);
      BOOST_TEST(j.get<std::size_t>("vertices") == num_vertices(mesh));
      BOOST_TEST(j.get<std::size_t>("faces") == num_faces(mesh));
      BOOST_TEST(j.get<std::size_t>("quality.flipped_faces") == 0u);
      const std::size_t center = j.get<std::size_t>("center.index");
      if(ext == "off")
        reference_center = center;
      else if(ext != "stl")  // STL numbers its vertices in order of first appearance
        BOOST_TEST(center == reference_center);
      const Obj obj = read_obj(scratch.work / "disk_uv.obj");
      BOOST_TEST(obj.v.size() == num_vertices(mesh));
      BOOST_TEST(obj.vt.size() == num_vertices(mesh));
      BOOST_TEST(obj.f.size() == num_faces(mesh));
    }
  }
}

BOOST_AUTO_TEST_CASE(generated_mesh_when_the_default_mesh_is_missing)
{
  Scratch scratch;
  const Run r = scratch.run({"--json", "--single-chart"}, MBP_CLI_NO_DEFAULT_MESH_PROGRAM);
  BOOST_REQUIRE_EQUAL(r.code, 0);
  BOOST_TEST(contains(r.err, "does not exist"));
  BOOST_TEST(contains(r.err, "generated"));
  BOOST_TEST((scratch.files() == std::set<std::string>{"curved_disk_uv.obj"}));
  const boost::property_tree::ptree j = parse_json(r.out);
  BOOST_TEST(j.get<bool>("generated_mesh"));
  const Obj obj = read_obj(scratch.work / "curved_disk_uv.obj");
  BOOST_TEST(obj.v.size() == j.get<std::size_t>("vertices"));
  BOOST_TEST(obj.vt.size() == obj.v.size());
  BOOST_TEST(obj.f.size() == j.get<std::size_t>("faces"));
  BOOST_TEST(obj.f.size() > 1000u);
  // a curved surface: not all z are equal
  double zmin = obj.v[0][2], zmax = obj.v[0][2];
  for(const auto& p : obj.v)
  {
    zmin = (std::min)(zmin, p[2]);
    zmax = (std::max)(zmax, p[2]);
  }
  BOOST_TEST(zmax - zmin > 0.1);
  std::size_t flipped = 0;
  for(const auto& f : obj.f)
    flipped += (signed_uv_area(obj, f) > 0.) ? 0 : 1;
  BOOST_TEST(flipped == 0u);
}

BOOST_AUTO_TEST_CASE(isolated_vertices_are_left_out)
{
  // the grid plus an unused vertex 9
  std::string off = grid_off;
  off.replace(off.find("9 8 0"), 5, "10 8 0");
  off.insert(off.find("3 0 1 4"), "5 5 5\n");
  Scratch scratch;
  scratch.write("grid.off", off);
  Run r = scratch.run({"grid.off", "out.obj", "--json", "--single-chart"});
  BOOST_REQUIRE_EQUAL(r.code, 0);
  BOOST_TEST(contains(r.err, "in no face"));
  BOOST_TEST(parse_json(r.out).get<std::size_t>("isolated_vertices") == 1u);
  const Obj obj = read_obj(scratch.work / "out.obj");
  BOOST_TEST(obj.v.size() == 9u);
  BOOST_TEST(obj.vt.size() == 9u);
  BOOST_TEST(obj.f.size() == 8u);
  // the unused vertex cannot be the center
  r = scratch.run({"grid.off", "out2.obj", "--center=vertex:9"});
  BOOST_TEST(r.code == 1);
  BOOST_TEST(contains(r.err, "in no face"));
  BOOST_TEST(!fs::exists(scratch.work / "out2.obj"));
}

BOOST_AUTO_TEST_CASE(help)
{
  Scratch scratch;
  const Run r = scratch.run({"--help"});
  BOOST_TEST(r.code == 0);
  BOOST_TEST(contains(r.out, "usage: measured_parameterization"));
  for(const char* option : {"--center=vertex:N", "--distance=poisson", "--svg=FILE", "--json", "--solver", "_uv.obj",
                            "--seams=FILE.selection.txt", "Seam_mesh", "--border=auto", "--atlas", "--single-chart",
                            "--resolution=N", "--gutter=N", "g chart_K"})
    BOOST_TEST(contains(r.out, option), option);
  BOOST_TEST(scratch.files().empty());
}


// ---------------------------------------------------------------- seams

namespace {

// The seam files of the examples (examples/data).
std::string example_data(const std::string& name) { return std::string(MBP_EXAMPLE_DATA_DIR) + "/" + name; }

// A closed torus of radii 2 and 0.7: an n x m grid (i around the axis, j around the tube),
// each quad split along the diagonal from (i, j) to (i + 1, j + 1); vertex (i, j) is i * m + j.
mbp_test::Soup closed_torus(int n, int m)
{
  mbp_test::Soup s;
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < m; ++j)
    {
      const double u = 2. * CGAL_PI * i / n, v = 2. * CGAL_PI * j / m;
      s.points.push_back({(2. + 0.7 * std::cos(v)) * std::cos(u), (2. + 0.7 * std::cos(v)) * std::sin(u),
                          0.7 * std::sin(v)});
    }
  auto id = [&](int i, int j) { return static_cast<std::size_t>(((i + n) % n) * m + (j + m) % m); };
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < m; ++j)
    {
      s.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      s.faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return s;
}

// A selection file whose third line holds the edges.
std::string selection_text(const std::vector<std::pair<std::size_t, std::size_t> >& edges)
{
  std::string s = "\n\n";
  for(const auto& e : edges)
    s += std::to_string(e.first) + " " + std::to_string(e.second) + " ";
  return s + "\n";
}

// The seam edges of the third line of a selection file.
std::vector<std::pair<std::size_t, std::size_t> > read_selection_edges(const std::string& path)
{
  std::ifstream in(path);
  std::string line;
  for(int l = 0; l < 3; ++l)
    BOOST_REQUIRE_MESSAGE(std::getline(in, line), "cannot read line " << l + 1 << " of " << path);
  std::istringstream numbers(line);
  std::vector<std::pair<std::size_t, std::size_t> > edges;
  std::size_t a = 0, b = 0;
  while(numbers >> a >> b)
    edges.emplace_back(a, b);
  return edges;
}

// Checks the OBJ of a run with seams on a closed mesh: the mesh's vertices ('v', exactly,
// input order) and faces, one 'vt' per seam mesh vertex (a vertex of seam degree d has d
// copies), grouped by vertex, each 'vt' used by one vertex, the copies of a seam vertex apart,
// every UV in [0,1]^2 and no flipped face. Returns the number of 'vt' lines.
std::size_t check_seam_obj(const Obj& obj, const Mesh& mesh, const std::vector<std::pair<std::size_t, std::size_t> >& seams)
{
  BOOST_TEST(obj.other_lines == 0u);
  BOOST_REQUIRE_EQUAL(obj.v.size(), num_vertices(mesh));
  BOOST_REQUIRE_EQUAL(obj.f.size(), num_faces(mesh));
  std::size_t exact = 0;
  for(vertex_descriptor v : vertices(mesh))
  {
    const auto& p = mesh.point(v);
    const auto& q = obj.v[std::size_t(v)];
    exact += (q[0] == p.x() && q[1] == p.y() && q[2] == p.z()) ? 1 : 0;
  }
  BOOST_TEST(exact == num_vertices(mesh), "vertices written exactly and in input order: " << exact);

  // one 'vt' per seam mesh vertex
  std::vector<std::size_t> seam_degree(num_vertices(mesh), 0);
  for(const auto& e : seams)
  {
    ++seam_degree[e.first];
    ++seam_degree[e.second];
  }
  std::size_t expected_uvs = num_vertices(mesh);
  for(std::size_t d : seam_degree)
    expected_uvs += (d > 0) ? d - 1 : 0;
  BOOST_TEST(obj.vt.size() == expected_uvs);
  BOOST_TEST(obj.vt.size() > obj.v.size());

  // the faces of the mesh; each 'vt' belongs to one 'v', and the 'vt' lines are grouped by 'v'
  std::vector<std::size_t> vertex_of_uv(obj.vt.size(), std::size_t(-1));
  std::size_t same_faces = 0, inconsistent = 0, repeated = 0, flipped = 0;
  std::size_t i = 0;
  for(auto f : faces(mesh))
  {
    std::array<std::size_t, 3> t;
    std::size_t k = 0;
    for(vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
      t[k++] = std::size_t(v);
    same_faces += (t == obj.f[i]) ? 1 : 0;
    const auto& uv = obj.ft[i];
    repeated += (uv[0] == uv[1] || uv[1] == uv[2] || uv[0] == uv[2]) ? 1 : 0;
    for(k = 0; k < 3; ++k)
    {
      std::size_t& owner = vertex_of_uv[uv[k]];
      if(owner == std::size_t(-1))
        owner = obj.f[i][k];
      inconsistent += (owner == obj.f[i][k]) ? 0 : 1;
    }
    flipped += (signed_uv_area(obj, uv) > 0.) ? 0 : 1;
    ++i;
  }
  BOOST_TEST(same_faces == num_faces(mesh), "faces written as in the input: " << same_faces);
  BOOST_TEST(repeated == 0u, repeated << " faces use one 'vt' twice");
  BOOST_TEST(inconsistent == 0u, inconsistent << " corners use a 'vt' of another vertex");
  BOOST_TEST(std::count(vertex_of_uv.begin(), vertex_of_uv.end(), std::size_t(-1)) == 0, "unused 'vt' lines");
  BOOST_TEST(std::is_sorted(vertex_of_uv.begin(), vertex_of_uv.end()), "'vt' lines grouped by vertex");
  BOOST_TEST(flipped == 0u, flipped << " flipped faces");

  // every vertex has as many UVs as its seam degree (at least one), apart from each other
  std::vector<std::vector<std::size_t> > uvs_of(num_vertices(mesh));
  for(std::size_t u = 0; u < vertex_of_uv.size(); ++u)
    if(vertex_of_uv[u] < uvs_of.size())
      uvs_of[vertex_of_uv[u]].push_back(u);
  std::size_t wrong_count = 0, close = 0;
  for(std::size_t v = 0; v < uvs_of.size(); ++v)
  {
    wrong_count += (uvs_of[v].size() == (std::max)(std::size_t(1), seam_degree[v])) ? 0 : 1;
    for(std::size_t a = 0; a < uvs_of[v].size(); ++a)
      for(std::size_t b = a + 1; b < uvs_of[v].size(); ++b)
      {
        const auto &p = obj.vt[uvs_of[v][a]], &q = obj.vt[uvs_of[v][b]];
        close += (std::hypot(p[0] - q[0], p[1] - q[1]) > 1e-6) ? 0 : 1;
      }
  }
  BOOST_TEST(wrong_count == 0u, wrong_count << " vertices without one UV per side of their seams");
  BOOST_TEST(close == 0u, close << " pairs of copies of a seam vertex at the same UV");

  const double eps = 1e-12;
  std::size_t outside = 0;
  for(const auto& q : obj.vt)
    outside += (std::isfinite(q[0]) && std::isfinite(q[1]) && q[0] >= -eps && q[0] <= 1. + eps &&
                q[1] >= -eps && q[1] <= 1. + eps) ? 0 : 1;
  BOOST_TEST(outside == 0u, outside << " UVs outside [0,1]^2");
  return obj.vt.size();
}

} // namespace

BOOST_AUTO_TEST_CASE(seams_cut_a_closed_mesh)
{
  // fandisk.off (closed, genus 0) cut along the shortest edge path of the example's seams
  const std::string path = mbp_test::core_mesh("fandisk.off");
  const std::string selection = example_data("fandisk.selection.txt");
  Mesh mesh;
  mbp_test::read_mesh(path, mesh);
  const std::vector<std::pair<std::size_t, std::size_t> > seams = read_selection_edges(selection);
  BOOST_REQUIRE(!seams.empty());

  Scratch scratch;
  const Run r = scratch.run({path, "out.obj", "--seams=" + selection, "--json", "--svg=out.svg", "--border=measured"});
  BOOST_REQUIRE_EQUAL(r.code, 0);
  BOOST_TEST((scratch.files() == std::set<std::string>{"out.obj", "out.svg"}));
  const std::size_t uvs = check_seam_obj(read_obj(scratch.work / "out.obj", true), mesh, seams);

  const boost::property_tree::ptree j = parse_json(r.out);
  BOOST_TEST(j.get<std::string>("seams") == selection);
  BOOST_TEST(j.get<std::size_t>("seam_edges") == seams.size());
  BOOST_TEST(j.get<std::size_t>("uvs") == uvs);
  BOOST_TEST(j.get<std::size_t>("vertices") == num_vertices(mesh));
  BOOST_TEST(j.get<std::size_t>("faces") == num_faces(mesh));
  BOOST_TEST(j.get<std::size_t>("border.vertices") == 2 * seams.size());  // a path: both sides
  BOOST_TEST(j.get<std::size_t>("quality.flipped_faces") == 0u);
  // the center is interior: not on a seam
  const std::size_t center = j.get<std::size_t>("center.index");
  for(const auto& e : seams)
    BOOST_TEST((e.first != center && e.second != center));
  const std::string svg = Scratch::read_text(scratch.work / "out.svg");
  BOOST_TEST(svg.substr(svg.size() - 7) == "</svg>\n");
  BOOST_TEST(contains(svg, std::to_string(seams.size()) + " seam edges"));

  // the one-line summary names the seams
  Scratch summary;
  const Run s = summary.run({path, "out.obj", "--seams=" + selection});
  BOOST_REQUIRE_EQUAL(s.code, 0);
  BOOST_TEST(contains(s.out, "seams " + std::to_string(seams.size()) + " edges, " + std::to_string(uvs) + " UVs"),
             s.out);

  // without seams the JSON says so, with one UV per vertex
  Scratch plain;
  plain.write("grid.off", grid_off);
  const Run p = plain.run({"grid.off", "--json", "--single-chart"});
  BOOST_REQUIRE_EQUAL(p.code, 0);
  const boost::property_tree::ptree pj = parse_json(p.out);
  BOOST_TEST(pj.get<std::string>("seams") == "null");
  BOOST_TEST(pj.get<std::size_t>("seam_edges") == 0u);
  BOOST_TEST(pj.get<std::size_t>("uvs") == 9u);
}

MBP_TIERED_TEST_CASE(messy_real_meshes_fail_cleanly)
{
  // messy meshes with --single-chart: a message naming the problem, exit 1, nothing written
  // (closed, holed and higher-genus meshes get automatic seams:
  // not_a_disk_real_meshes_get_automatic_seams; the atlas takes them all:
  // messy_real_meshes_get_an_atlas).
  // Core tier: CGAL's data meshes; extended tier: the other MESSY meshes of the project's
  // meshes (PROVENANCE.md there; the others are copies of CGAL's).
  // doc/Surface_mesh_parameterization/hardening.md has the table.
  const std::vector<std::pair<std::string, std::string> > cases = (tier == mbp_test::Tier::core)
    ? std::vector<std::pair<std::string, std::string> >{
        {"mask_cone.off", "not a topological disc: it has 2 connected components"},
        {"polygon_mesh.off", "automatic seams: the mesh is not a manifold: a vertex joins two or more fans of faces"}}
    : std::vector<std::pair<std::string, std::string> >{
        {"ogre.obj", "not a topological disc: it has 45 connected components"}};
  for(const auto& c : cases)
  {
    BOOST_TEST_CONTEXT("mesh: " << c.first)
    {
      const std::string path = mbp_test::tier_mesh(tier, c.first);
      Scratch scratch;
      const Run r = scratch.run({path, "out.obj", "--svg=out.svg", "--json", "--single-chart"});
      BOOST_TEST(r.code == 1);
      BOOST_TEST(contains(r.err, "error: " + path + ": "), r.err);
      BOOST_TEST(contains(r.err, c.second), r.err);
      // --json: the same error as a JSON object on stdout
      const boost::property_tree::ptree j = parse_json(r.out);
      BOOST_TEST(contains(j.get<std::string>("error"), c.second), r.out);
      BOOST_TEST(j.get<int>("code") == 1);
      BOOST_TEST(scratch.files().empty());
    }
  }
}

BOOST_AUTO_TEST_CASE(seams_on_a_torus)
{
  // genus 1: a meridian and a longitude through one vertex cut it into a disk; a meridian
  // path that closes no loop leaves the handle (the parameterizer's ERROR_NO_TOPOLOGICAL_DISC),
  // and the whole meridian loop alone leaves a cylinder (two border loops)
  const int n = 16, m = 10;
  const mbp_test::Soup soup = closed_torus(n, m);
  Mesh mesh;
  mbp_test::soup_to_mesh(soup, mesh);
  auto id = [&](int i, int j) { return static_cast<std::size_t>(((i + n) % n) * m + (j + m) % m); };
  std::vector<std::pair<std::size_t, std::size_t> > meridian, longitude;
  for(int j = 0; j < m; ++j)
    meridian.emplace_back(id(0, j), id(0, j + 1));
  for(int i = 0; i < n; ++i)
    longitude.emplace_back(id(i, 0), id(i + 1, 0));
  std::vector<std::pair<std::size_t, std::size_t> > cut_graph = meridian;
  cut_graph.insert(cut_graph.end(), longitude.begin(), longitude.end());
  const std::vector<std::pair<std::size_t, std::size_t> > path(meridian.begin(), meridian.end() - 1);

  {
    Scratch scratch;
    scratch.write("torus.off", off_text(soup));
    scratch.write("cut.selection.txt", selection_text(cut_graph));
    const Run r = scratch.run({"torus.off", "out.obj", "--seams=cut.selection.txt", "--json"});
    BOOST_REQUIRE_EQUAL(r.code, 0);
    const std::size_t uvs = check_seam_obj(read_obj(scratch.work / "out.obj", true), mesh, cut_graph);
    BOOST_TEST(uvs == std::size_t(n * m + 3 + (n - 1) + (m - 1)));  // vertex 0 four times, the others twice
    const boost::property_tree::ptree j = parse_json(r.out);
    BOOST_TEST(j.get<std::size_t>("seam_edges") == std::size_t(n + m));
    BOOST_TEST(j.get<std::size_t>("uvs") == uvs);
    BOOST_TEST(j.get<std::size_t>("border.vertices") == std::size_t(2 * (n + m)));
  }
  {
    Scratch scratch;
    scratch.write("torus.off", off_text(soup));
    scratch.write("path.selection.txt", selection_text(path));
    const Run r = scratch.run({"torus.off", "out.obj", "--seams=path.selection.txt", "--svg=out.svg"});
    BOOST_TEST(r.code == 1);
    BOOST_TEST(contains(r.err, "error: torus.off cut along path.selection.txt: input mesh is not a topological disc"),
               r.err);
    BOOST_TEST(contains(r.err, "the seams do not cut every handle"), r.err);
    BOOST_TEST(contains(r.err, "still has genus 1"), r.err);
    BOOST_TEST(contains(r.err, "a meridian and a longitude through one vertex"), r.err);
    BOOST_TEST(r.out.empty());
    BOOST_TEST((scratch.files() == std::set<std::string>{"torus.off", "path.selection.txt"}));
  }
  {
    Scratch scratch;
    scratch.write("torus.off", off_text(soup));
    scratch.write("loop.selection.txt", selection_text(meridian));
    const Run r = scratch.run({"torus.off", "out.obj", "--seams=loop.selection.txt"});
    BOOST_TEST(r.code == 1);
    BOOST_TEST(contains(r.err, "not a topological disc"), r.err);
    BOOST_TEST(contains(r.err, "2 border loops"), r.err);
    BOOST_TEST(contains(r.err, "cylinder"), r.err);
    BOOST_TEST((scratch.files() == std::set<std::string>{"torus.off", "loop.selection.txt"}));
  }
  {
    // without seams: automatic seams (two loops)
    Scratch scratch;
    scratch.write("torus.off", off_text(soup));
    const Run r = scratch.run({"torus.off", "out.obj", "--single-chart"});
    BOOST_TEST(r.code == 0);
    BOOST_TEST(contains(r.out, "| automatic seams "), r.out);
    BOOST_TEST((scratch.files() == std::set<std::string>{"torus.off", "out.obj"}));
  }
}

// ---------------------------------------------------------------- bad input

namespace {

struct Bad_case
{
  std::string name;
  std::vector<std::pair<std::string, std::string> > files;  // written into the work directory
  std::vector<std::string> args;
  int code;                                                 // expected exit status
  std::vector<std::string> messages;                        // expected in stderr (any case)
};

// A binary little-endian PLY of the grid, with the x coordinate of vertex 4 set to NaN
// (CGAL's binary reader lets it through: the library must reject it).
std::string binary_ply_with_nan()
{
  std::string s = "ply\nformat binary_little_endian 1.0\nelement vertex 9\nproperty float x\n"
                  "property float y\nproperty float z\nelement face 8\n"
                  "property list uchar int vertex_indices\nend_header\n";
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float p[9][3] = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {nan, 1, 0.3f},
                         {2, 1, 0}, {0, 2, 0}, {1, 2, 0}, {2, 2, 0}};
  const std::int32_t f[8][3] = {{0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}, {3, 4, 7}, {3, 7, 6}, {4, 5, 8}, {4, 8, 7}};
  BOOST_REQUIRE(std::uint32_t(1) == *reinterpret_cast<const unsigned char*>(&f[0][1]));  // little-endian host
  for(const auto& q : p)
    s.append(reinterpret_cast<const char*>(q), sizeof(q));
  for(const auto& t : f)
  {
    s += char(3);
    s.append(reinterpret_cast<const char*>(t), sizeof(t));
  }
  return s;
}

// The header of an ASCII PLY with 3 vertices and `faces` faces, whose index lists have a
// count of type `count_type`.
std::string ply_header(int faces, const std::string& count_type)
{
  return "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
         "element face " + std::to_string(faces) + "\nproperty list " + count_type + " int vertex_indices\n"
         "end_header\n";
}

std::vector<Bad_case> bad_cases()
{
  const std::string grid = grid_off;
  std::string zero_area = grid;  // vertex 4 moved onto the edge (0, 1): face 0 has no area
  zero_area.replace(zero_area.find("1 1 0.3"), 7, "0.5 0 0");
  std::string nan_grid = grid;
  nan_grid.replace(nan_grid.find("1 1 0.3"), 7, "nan 1 0.3");
  std::string inf_obj = "v 0 0 0\nv 1 0 0\nv 0 1 inf\nv 1 1 0\nf 1 2 3\nf 2 4 3\n";
  const std::string quads = "OFF\n9 4 0\n0 0 0\n1 0 0\n2 0 0\n0 1 0\n1 1 0\n2 1 0\n0 2 0\n1 2 0\n2 2 0\n"
                            "4 0 1 4 3\n4 1 2 5 4\n4 3 4 7 6\n4 4 5 8 7\n";
  const std::string octahedron = "OFF\n6 8 0\n1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1\n0 0 -1\n"
                                 "3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n3 3 1 5\n3 0 3 5\n";
  // three triangles on one edge
  const std::string non_manifold = "OFF\n5 3 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 -1 1\n3 0 1 2\n3 0 2 3\n3 0 2 4\n";
  // the grid and a separate triangle
  std::string two_components = grid;
  two_components.replace(two_components.find("9 8 0"), 5, "12 9 0");
  two_components.insert(two_components.find("3 0 1 4"), "5 0 0\n6 0 0\n5 1 0\n");
  two_components += "3 9 10 11\n";

  const std::vector<std::string> out{"out.obj", "--svg=out.svg"};
  auto with = [&out](std::vector<std::string> args) {
    args.insert(args.end(), out.begin(), out.end());
    return args;
  };
  std::vector<Bad_case> cases = {
    // what --single-chart refuses and the atlas repairs (atlas_of_soups_with_defects)
    {"quad mesh", {{"quads.off", quads}}, with({"quads.off", "--single-chart"}), 1, {"not triangular", "4 vertices"}},
    {"NaN coordinate (text)", {{"nan.off", nan_grid}}, with({"nan.off"}), 1, {"non-finite", "'nan'", "line 7"}},
    {"NaN coordinate (binary)", {{"nan.ply", binary_ply_with_nan()}}, with({"nan.ply"}), 1, {"non-finite", "vertex 4"}},
    {"infinite coordinate", {{"inf.obj", inf_obj}}, with({"inf.obj"}), 1, {"non-finite", "'inf'"}},
    {"zero-area triangle", {{"flat.off", zero_area}}, with({"flat.off", "--single-chart"}), 1, {"zero area", "face 0"}},
    {"nonexistent file", {}, with({"missing.off"}), 1, {"missing.off", "no such file"}},
    {"directory", {}, with({"."}), 1, {"directory"}},
    {"empty file", {{"empty.off", ""}}, with({"empty.off"}), 1, {"empty"}},
    {"not a mesh file", {{"text.off", "hello world\n"}}, with({"text.off"}), 1, {"cannot read it", "OFF keyword"}},
    {"unsupported extension", {{"grid.xyz", grid}}, with({"grid.xyz"}), 1, {"unsupported", ".xyz"}},
    {"no faces", {{"points.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n"}}, with({"points.off"}), 1, {"no faces"}},
    {"non-manifold", {{"fin.off", non_manifold}}, with({"fin.off", "--single-chart"}), 1, {"not a polygon mesh", "manifold"}},
    {"two components", {{"two.off", two_components}}, with({"two.off", "--single-chart"}), 1, {"2 connected components"}},
    // found by fuzzing (test/fuzz): CGAL 5.5 builds the mesh with unchecked indices, and sizes
    // its containers from the counts of the file
    {"face index out of range (OBJ)", {{"far.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n"}}, with({"far.obj"}), 1,
     {"face 0 uses vertex index 4 (1-based)", "3 vertices"}},
    {"negative face index out of range (OBJ)", {{"neg.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n"}},
     with({"neg.obj"}), 1, {"line 4", "relative vertex index -4 refers to before the first vertex"}},
    {"face index out of range (PLY)", {{"far.ply", ply_header(1, "uchar") + "0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"}},
     with({"far.ply"}), 1, {"face 0 uses vertex index 7 (0-based)"}},
    {"PLY list longer than the file", {{"long.ply", ply_header(1, "uint") + "0 0 0\n1 0 0\n0 1 0\n4000000000 0 1 2\n"}},
     with({"long.ply"}), 1, {"a list of 4000000000 entries", "corrupt"}},
    {"OFF header count larger than the file", {{"huge.off", "OFF\n1000000000 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"}},
     with({"huge.off"}), 1, {"announces 1000000000 vertices and 1 faces", "more than the", "bytes after it can hold"}},
    {"OFF counts spread over lines", {{"mid.off", "OFF\n 00\n3 0 66666666666 0 0 0\n3 0 1 2\n"}},
     with({"mid.off"}), 1, {"cannot read it", "line 2", "the OFF counts line '00' has 1 number"}},
    {"OFF face size larger than its line", {{"size.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n66666666666 0 1 2\n"}},
     with({"size.off"}), 1, {"line 6", "face 0 announces 66666666666 vertices, more than its line holds"}},
    {"OFF keyword with trailing characters", {{"coff.off", "COFF-\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"}},
     with({"coff.off"}), 1, {"OFF keyword", "COFF-"}},
    {"PLY list count with trailing characters",
     {{"suffix.ply", ply_header(1, "uint") + "0 0 0\n1 0 0\n0 1 0\n4000000000x 0 1 2\n"}}, with({"suffix.ply"}), 1,
     {"line 13", "'4000000000x' is not an integer"}},
    {"unknown option", {{"grid.off", grid}}, with({"grid.off", "--frobnicate"}), 2, {"unknown option", "--frobnicate"}},
    {"unknown center", {{"grid.off", grid}}, with({"grid.off", "--center=middle"}), 2, {"--center", "middle"}},
    {"bad vertex index", {{"grid.off", grid}}, with({"grid.off", "--center=vertex:4x"}), 2, {"bad vertex index"}},
    {"unknown distance", {{"grid.off", grid}}, with({"grid.off", "--distance=geodesic"}), 2, {"--distance", "geodesic"}},
    {"unknown geodesic method", {{"grid.off", grid}}, with({"grid.off", "--center=geodesic:sloppy"}), 2,
     {"geodesic method", "sloppy"}},
    {"straightest geodesic misses a border vertex", {{"c.off", off_text(mbp_test::c_shape())}},
     with({"c.off", "--border=measured", "--distance=straightest"}), 1, {"straightest geodesic", "does not reach border vertex"}},
    {"unknown solver", {{"grid.off", grid}}, with({"grid.off", "--solver=lu"}), 2, {"--solver", "lu"}},
    {"svg without file", {{"grid.off", grid}}, {"grid.off", "out.obj", "--svg"}, 2, {"--svg"}},
    {"too many arguments", {{"grid.off", grid}}, with({"grid.off", "a.obj", "b.obj"}), 2, {"too many arguments"}},
    {"center on the border", {{"grid.off", grid}}, with({"grid.off", "--center=vertex:0"}), 1, {"vertex:0", "border"}},
    {"center out of range", {{"grid.off", grid}}, with({"grid.off", "--center=vertex:9"}), 1, {"vertex:9", "out of range"}},
    {"huge center index", {{"grid.off", grid}}, with({"grid.off", "--center=vertex:99999999999999999999999"}), 2, {"out of range"}},
    {"output directory missing", {{"grid.off", grid}}, {"grid.off", "no/such/dir/out.obj", "--svg=out.svg"}, 1, {"cannot write", "no/such/dir/out.obj"}},
    {"svg directory missing", {{"grid.off", grid}}, {"grid.off", "out.obj", "--svg=no/dir/out.svg"}, 1, {"cannot write", "no/dir/out.svg"}},
    {"output is a directory", {{"grid.off", grid}}, {"grid.off", ".", "--svg=out.svg"}, 1, {"cannot write", "directory"}},
    {"same output and svg", {{"grid.off", grid}}, {"grid.off", "out.obj", "--svg=out.obj"}, 2, {"same file"}},
    {"output given twice", {{"grid.off", grid}}, {"grid.off", "a.obj", "--output=b.obj"}, 2, {"given twice"}},
    // seams (octahedron: vertices +-x 0 1, +-y 2 3, +-z 4 5; 0 and 1 are not joined)
    {"seam file missing", {{"octahedron.off", octahedron}}, with({"octahedron.off", "--seams=none.selection.txt"}), 1,
     {"none.selection.txt", "no such file"}},
    {"seam file is a directory", {{"octahedron.off", octahedron}}, with({"octahedron.off", "--seams=."}), 1,
     {"directory"}},
    {"not a selection file", {{"octahedron.off", octahedron}, {"s.selection.txt", "OFF\n6 8 0\n"}},
     with({"octahedron.off", "--seams=s.selection.txt"}), 1, {"s.selection.txt", "line 1", "'OFF' is not an index"}},
    {"selection file with two lines", {{"octahedron.off", octahedron}, {"s.selection.txt", "0 4\n\n"}},
     with({"octahedron.off", "--seams=s.selection.txt"}), 1, {"2 lines", "three lines"}},
    {"seam index out of range", {{"octahedron.off", octahedron}, {"s.selection.txt", "\n\n4 0 0 6\n"}},
     with({"octahedron.off", "--seams=s.selection.txt"}), 1,
     {"line 3, seam edge 2 (0 6)", "vertex index 6 is out of range", "6 vertices"}},
    {"seam pair not an edge", {{"octahedron.off", octahedron}, {"s.selection.txt", "\n\n4 0 0 1\n"}},
     with({"octahedron.off", "--seams=s.selection.txt"}), 1, {"seam edge 2 (0 1)", "not joined by an edge"}},
    {"seam pair of one vertex", {{"octahedron.off", octahedron}, {"s.selection.txt", "\n\n4 4\n"}},
     with({"octahedron.off", "--seams=s.selection.txt"}), 1, {"not an edge", "vertex 4"}},
    {"odd number of seam indices", {{"octahedron.off", octahedron}, {"s.selection.txt", "\n\n4 0 5\n"}},
     with({"octahedron.off", "--seams=s.selection.txt"}), 1, {"odd number"}},
    {"no seam edge", {{"octahedron.off", octahedron}, {"s.selection.txt", "0\n\n\n"}},
     with({"octahedron.off", "--seams=s.selection.txt"}), 1, {"no seam edge"}},
    {"seam edge twice", {{"octahedron.off", octahedron}, {"s.selection.txt", "\n\n4 0 0 5 0 4\n"}},
     with({"octahedron.off", "--seams=s.selection.txt"}), 1, {"seam edge 3 (0 4)", "same edge as seam edge 1"}},
    {"text after the seams", {{"octahedron.off", octahedron}, {"s.selection.txt", "\n\n4 0\n1 2\n"}},
     with({"octahedron.off", "--seams=s.selection.txt"}), 1, {"line 4", "unexpected"}},
    {"selected vertex of another mesh", {{"octahedron.off", octahedron}, {"s.selection.txt", "17\n\n4 0\n"}},
     with({"octahedron.off", "--seams=s.selection.txt"}), 1, {"line 1", "out of range", "another mesh"}},
    {"seam on the border", {{"grid.off", grid}, {"s.selection.txt", "\n\n0 1\n"}},
     with({"grid.off", "--seams=s.selection.txt"}), 1, {"seam edge 1 (0 1)", "border"}},
    {"seams that separate", {{"octahedron.off", octahedron}, {"s.selection.txt", "\n\n0 2 2 1 1 3 3 0\n"}},
     with({"octahedron.off", "--seams=s.selection.txt"}), 1, {"cut along s.selection.txt", "2 pieces"}},
    {"center on a seam", {{"octahedron.off", octahedron}, {"s.selection.txt", "\n\n4 0 0 5\n"}},
     with({"octahedron.off", "--seams=s.selection.txt", "--center=vertex:0"}), 1, {"vertex:0", "on a seam"}},
    {"seams without file", {{"octahedron.off", octahedron}}, with({"octahedron.off", "--seams="}), 2, {"--seams"}},
    {"seams given twice", {{"octahedron.off", octahedron}}, with({"octahedron.off", "--seams=a", "--seams=b"}), 2,
     {"--seams", "twice"}},
  };
  return cases;
}

} // namespace

BOOST_AUTO_TEST_CASE(bad_input_fails_cleanly)
{
  for(const Bad_case& c : bad_cases())
  {
    BOOST_TEST_CONTEXT("case: " << c.name)
    {
      Scratch scratch;
      std::set<std::string> inputs;
      for(const auto& f : c.files)
      {
        scratch.write(f.first, f.second);
        inputs.insert(f.first);
      }
      const Run r = scratch.run(c.args);
      BOOST_TEST(r.code == c.code);
      BOOST_TEST(contains(r.err, "error:"), r.err);
      for(const std::string& m : c.messages)
        BOOST_TEST(contains(r.err, m), "'" << m << "' not in: " << r.err);
      BOOST_TEST(r.out.empty(), r.out);
      const std::set<std::string> left = scratch.files();
      std::string listing;
      for(const std::string& f : left)
        listing += " " + f;
      BOOST_TEST((left == inputs), "files in the working directory:" << listing);
    }
  }
}

// ---------------------------------------------------------------- files: inputs and outputs
// (issue 14: every case below failed before the streaming readers and file_output.h)

namespace {

std::string text_of(const fs::path& path) { return Scratch::read_text(path); }

// the temporary files of the program (file_output.h: ".mbp-PID-K.tmp", ".mbp-PID-K.old")
std::size_t temporaries_in(const fs::path& directory)
{
  std::size_t n = 0;
  for(const auto& entry : fs::directory_iterator(directory))
  {
    const std::string name = entry.path().filename().string();
    n += (name.rfind(".mbp-", 0) == 0 || name.find(".tmp") != std::string::npos) ? 1 : 0;
  }
  return n;
}

mode_t file_type(const fs::path& path)
{
  struct stat st;
  BOOST_REQUIRE(::lstat(path.c_str(), &st) == 0);
  return st.st_mode & S_IFMT;
}

// the shortest text that reads back as `x` exactly
std::string exact_text(double x)
{
  char buffer[32];
  return std::string(buffer, std::to_chars(buffer, buffer + sizeof(buffer), x).ptr);
}

std::string exact_off_text(const mbp_test::Soup& soup)
{
  std::string s = "OFF\n" + std::to_string(soup.points.size()) + " " + std::to_string(soup.faces.size()) + " 0\n";
  for(const auto& p : soup.points)
    s += exact_text(p[0]) + " " + exact_text(p[1]) + " " + exact_text(p[2]) + "\n";
  for(const auto& f : soup.faces)
  {
    s += std::to_string(f.size());
    for(std::size_t i : f)
      s += " " + std::to_string(i);
    s += "\n";
  }
  return s;
}

// a value in the byte order of a binary PLY file
template <class T>
void put_binary(std::string& s, T value, bool big_endian)
{
  char b[sizeof(T)];
  std::memcpy(b, &value, sizeof(T));
  const std::uint16_t one = 1;
  const bool host_little = *reinterpret_cast<const unsigned char*>(&one) == 1;
  if(big_endian == host_little)
    std::reverse(b, b + sizeof(T));
  s.append(b, sizeof(T));
}

// a binary PLY of `soup`: double coordinates, an extra float property per vertex, uchar/uint lists
std::string binary_ply(const mbp_test::Soup& soup, bool big_endian)
{
  std::string s = std::string("ply\nformat ") + (big_endian ? "binary_big_endian" : "binary_little_endian") +
                  " 1.0\ncomment written by test_cli\nelement vertex " + std::to_string(soup.points.size()) +
                  "\nproperty double x\nproperty double y\nproperty double z\nproperty float quality\nelement face " +
                  std::to_string(soup.faces.size()) + "\nproperty list uchar uint vertex_indices\nend_header\n";
  for(const auto& p : soup.points)
  {
    for(double c : p)
      put_binary(s, c, big_endian);
    put_binary(s, 0.5f, big_endian);
  }
  for(const auto& f : soup.faces)
  {
    s += char(f.size());
    for(std::size_t i : f)
      put_binary(s, std::uint32_t(i), big_endian);
  }
  return s;
}

// a binary STL of `soup` (float coordinates, little-endian)
std::string binary_stl(const mbp_test::Soup& soup)
{
  std::string s(80, ' ');
  s.replace(0, 5, "solid");  // a binary header may start with "solid": the size decides
  put_binary(s, std::uint32_t(soup.faces.size()), false);
  for(const auto& f : soup.faces)
  {
    for(int k = 0; k < 3; ++k)
      put_binary(s, 0.f, false);
    for(std::size_t i : f)
      for(double c : soup.points[i])
        put_binary(s, float(c), false);
    s += std::string(2, '\0');
  }
  return s;
}

} // namespace

BOOST_AUTO_TEST_CASE(reads_binary_ply_and_stl)
{
  // the binary readers give the same mesh as the OFF: the same vertices in the same order,
  // hence the same OBJ (binary PLY of doubles); STL (floats, vertices merged by position) gives
  // the float-rounded vertices
  const mbp_test::Soup soup = mbp_test::bumpy_disk();
  Scratch scratch;
  scratch.write("disk.off", exact_off_text(soup));
  scratch.write("little.ply", binary_ply(soup, false));
  scratch.write("big.ply", binary_ply(soup, true));
  scratch.write("disk.stl", binary_stl(soup));
  // a single chart (--single-chart): one UV per vertex (the atlas: atlas_of_soups_with_defects)
  BOOST_REQUIRE_EQUAL(scratch.run({"disk.off", "off.obj", "--single-chart"}).code, 0);
  const std::string reference = text_of(scratch.work / "off.obj");
  auto body = [](const std::string& obj) { return obj.substr(obj.find("\nv ")); };  // without the comments
  for(const std::string name : {"little.ply", "big.ply"})
    BOOST_TEST_CONTEXT(name)
    {
      const Run r = scratch.run({name, name + ".obj", "--single-chart"});
      BOOST_REQUIRE_EQUAL(r.code, 0);
      BOOST_TEST(body(text_of(scratch.work / (name + ".obj"))) == body(reference));
    }
  const Run r = scratch.run({"disk.stl", "stl.obj", "--json", "--single-chart"});
  BOOST_REQUIRE_EQUAL(r.code, 0);
  const Obj obj = read_obj(scratch.work / "stl.obj");
  BOOST_TEST(obj.v.size() == soup.points.size());
  BOOST_TEST(obj.f.size() == soup.faces.size());
  // vertices in order of first appearance, float-rounded
  std::vector<std::size_t> first;
  std::vector<bool> seen(soup.points.size(), false);
  for(const auto& f : soup.faces)
    for(std::size_t i : f)
      if(!seen[i])
      {
        seen[i] = true;
        first.push_back(i);
      }
  BOOST_REQUIRE_EQUAL(first.size(), obj.v.size());
  std::size_t exact = 0;
  for(std::size_t k = 0; k < first.size(); ++k)
  {
    const auto& p = soup.points[first[k]];
    exact += (obj.v[k][0] == double(float(p[0])) && obj.v[k][1] == double(float(p[1])) &&
              obj.v[k][2] == double(float(p[2]))) ? 1 : 0;
  }
  BOOST_TEST(exact == first.size());

  // 400 separate triangles: 1200 distinct vertices, more than the vertex table of a binary STL
  // sized for 400 triangles holds at first (it grows); read whole, then refused as 400 pieces
  mbp_test::Soup separate;
  for(int t = 0; t < 400; ++t)
  {
    const double x = 3. * t;
    separate.points.push_back({x, 0., 0.});
    separate.points.push_back({x + 1., 0., 0.});
    separate.points.push_back({x, 1., 0.});
    separate.faces.push_back({std::size_t(3 * t), std::size_t(3 * t + 1), std::size_t(3 * t + 2)});
  }
  scratch.write("separate.stl", binary_stl(separate));
  const Run s = scratch.run({"separate.stl", "separate.obj", "--single-chart"});
  BOOST_TEST(s.code == 1);
  BOOST_TEST(contains(s.err, "it has 400 connected components"), s.err);
}

BOOST_AUTO_TEST_CASE(messages_name_the_actual_problem)
{
  // each input once gave a message about something else (in parentheses)
  std::string one_point = grid_off;  // all nine vertices at (1, 1, 1) (was: "the mesh is closed")
  {
    const std::size_t begin = one_point.find("0 0 0\n"), end = one_point.find("3 0 1 4");
    std::string points;
    for(int i = 0; i < 9; ++i)
      points += "1 1 1\n";
    one_point.replace(begin, end - begin, points);
  }
  struct Case
  {
    std::string name, file, contents;
    std::vector<std::string> expected, wrong;
    bool single_chart = false;  // a problem of --single-chart (the atlas repairs it)
  };
  const std::vector<Case> cases = {
    {"all vertices at one point", "point.off", one_point,
     {"all 9 vertices of its faces coincide (at 1 1 1)", "no extent"}, {"closed", "zero area"}},
    {"OBJ face index 0 (was: a different index)", "zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n",
     {"line 4", "face 0: vertex index 0 is invalid in OBJ (indices start at 1"}, {"uses vertex index"}},
    {"overflowing OBJ index (was: not a 2-manifold)", "overflow.obj",
     "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999999999999999999\n",
     {"line 4", "vertex index 99999999999999999999 is out of range"}, {"manifold"}},
    {"OBJ index beyond 32 bits", "large.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4294967299\n",
     {"vertex index 4294967299 is out of range"}, {"manifold", "uses vertex index 3 "}},
    {"OFF header with two counts (was: more than the three counts)", "two.off",
     "OFF\n3 1\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
     {"line 2", "the OFF counts line '3 1' has 2 numbers; it needs exactly three"}, {"more than the three"}},
    {"face using a vertex twice", "twice.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 0 1\n",
     {"not a polygon mesh", "face 1 uses vertex 0 twice"}, {}, true},
    {"inconsistent orientation", "flip.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 3 2\n",
     {"not a polygon mesh", "faces 0 and 1 traverse the edge 2-0 in the same direction"}, {}, true},
    {"edge of three faces", "fin.off", "OFF\n5 3 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 -1 1\n3 0 1 2\n3 0 2 3\n3 0 2 4\n",
     {"the edge 0-2 has more than two faces (faces 0, 1 and 2)"}, {}, true},
    {"unknown OBJ statement", "text.obj", "v 0 0 0\nhello world\n", {"line 2", "'hello' is not an OBJ statement"}, {}},
    {"binary STL of the wrong size", "short.stl", std::string(84, '\0') + "xx",
     {"has 84 bytes, but this one has 86"}, {}},
    {"PLY without end_header", "open.ply", "ply\nformat ascii 1.0\nelement vertex 0\n", {"no 'end_header'"}, {}},
    {"coordinate beyond double", "big.obj", "v 0 0 1e400\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
     {"non-finite", "'1e400' is too large for a double"}, {}},
  };
  for(const Case& c : cases)
    BOOST_TEST_CONTEXT(c.name)
    {
      Scratch scratch;
      scratch.write(c.file, c.contents);
      std::vector<std::string> args{c.file, "out.obj", "--svg=out.svg"};
      if(c.single_chart)
        args.push_back("--single-chart");
      const Run r = scratch.run(args);
      BOOST_TEST(r.code == 1);
      BOOST_TEST(contains(r.err, "error: " + c.file + ": "), r.err);
      for(const std::string& m : c.expected)
        BOOST_TEST(contains(r.err, m), "'" << m << "' not in: " << r.err);
      for(const std::string& m : c.wrong)
        BOOST_TEST(!contains(r.err, m), "'" << m << "' in: " << r.err);
      BOOST_TEST((scratch.files() == std::set<std::string>{c.file}));
    }
}

BOOST_AUTO_TEST_CASE(huge_and_tiny_coordinates_are_parameterized)
{
  // a conformal map does not depend on the scale: coordinates near 1e300 (squared lengths
  // overflow) or 1e-300 (they underflow) give the layout of the unscaled mesh (was: "face of
  // zero area"), and the OBJ keeps the input's coordinates exactly
  const mbp_test::Soup soup = mbp_test::bumpy_disk();
  Scratch scratch;
  scratch.write("unit.off", exact_off_text(soup));
  BOOST_REQUIRE_EQUAL(scratch.run({"unit.off", "unit.obj", "--single-chart"}).code, 0);
  const Obj reference = read_obj(scratch.work / "unit.obj");
  for(const double scale : {1e300, 1e-300, 3e160})
    BOOST_TEST_CONTEXT("scale " << scale)
    {
      mbp_test::Soup scaled = soup;
      for(auto& p : scaled.points)
        for(double& c : p)
          c *= scale;
      scratch.write("scaled.off", exact_off_text(scaled));
      const Run r = scratch.run({"scaled.off", "scaled.obj", "--json", "--single-chart"});
      BOOST_REQUIRE_EQUAL(r.code, 0);
      const Obj obj = read_obj(scratch.work / "scaled.obj");
      BOOST_REQUIRE_EQUAL(obj.v.size(), scaled.points.size());
      std::size_t exact = 0;
      for(std::size_t i = 0; i < obj.v.size(); ++i)
        exact += (obj.v[i][0] == scaled.points[i][0] && obj.v[i][1] == scaled.points[i][1] &&
                  obj.v[i][2] == scaled.points[i][2]) ? 1 : 0;
      BOOST_TEST(exact == obj.v.size());
      BOOST_REQUIRE_EQUAL(obj.vt.size(), reference.vt.size());
      double worst = 0.;
      for(std::size_t i = 0; i < obj.vt.size(); ++i)
        worst = (std::max)(worst, std::hypot(obj.vt[i][0] - reference.vt[i][0], obj.vt[i][1] - reference.vt[i][1]));
      BOOST_TEST(worst < 1e-9, "largest UV difference from the unscaled mesh: " << worst);
      BOOST_TEST(parse_json(r.out).get<std::size_t>("quality.flipped_faces") == 0u);
    }
}

BOOST_AUTO_TEST_CASE(output_that_is_an_input_is_refused)
{
  // was: the input overwritten by the result (also with --svg=INPUT)
  const std::string octahedron = "OFF\n6 8 0\n1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1\n0 0 -1\n"
                                 "3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n3 3 1 5\n3 0 3 5\n";
  const std::vector<std::vector<std::string> > runs = {
    {"grid.off", "grid.off"}, {"grid.off", "./grid.off"}, {"grid.off", "out.obj", "--svg=grid.off"},
    {"grid.off", "out.obj", "--svg=sub/../grid.off"}, {"grid.off", "hard.obj"}, {"grid.off", "--output=grid.off"}};
  for(const auto& args : runs)
    BOOST_TEST_CONTEXT(args[1] << (args.size() > 2 ? " " + args[2] : std::string()))
    {
      Scratch scratch;
      scratch.write("grid.off", grid_off);
      fs::create_directory(scratch.work / "sub");
      fs::create_hard_link(scratch.work / "grid.off", scratch.work / "hard.obj");
      const Run r = scratch.run(args);
      BOOST_TEST(r.code == 2);
      BOOST_TEST(contains(r.err, "is the input 'grid.off' (the same file)"), r.err);
      BOOST_TEST(text_of(scratch.work / "grid.off") == grid_off);
      BOOST_TEST((scratch.files() == std::set<std::string>{"grid.off", "hard.obj", "sub"}));
    }
  // the seam file is an input too
  Scratch scratch;
  scratch.write("octahedron.off", octahedron);
  scratch.write("s.selection.txt", "\n\n4 0 0 5\n");
  const Run r = scratch.run({"octahedron.off", "s.selection.txt", "--seams=s.selection.txt"});
  BOOST_TEST(r.code == 2);
  BOOST_TEST(contains(r.err, "is the seam file 's.selection.txt'"), r.err);
  BOOST_TEST(text_of(scratch.work / "s.selection.txt") == "\n\n4 0 0 5\n");
  // two outputs that are one file through different names
  Scratch same;
  same.write("grid.off", grid_off);
  const Run s = same.run({"grid.off", "out.obj", "--svg=./out.obj"});
  BOOST_TEST(s.code == 2);
  BOOST_TEST(contains(s.err, "name the same file"), s.err);
  BOOST_TEST((same.files() == std::set<std::string>{"grid.off"}));
}

BOOST_AUTO_TEST_CASE(non_regular_output_targets_are_refused)
{
  // was: a FIFO, a device node or a symbolic link replaced by a regular file
  Scratch scratch;
  scratch.write("grid.off", grid_off);
  scratch.write("real.obj", "previous\n");
  BOOST_REQUIRE(::mkfifo((scratch.work / "fifo.obj").c_str(), 0644) == 0);
  fs::create_symlink("real.obj", scratch.work / "link.obj");
  fs::create_symlink("nowhere/missing.obj", scratch.work / "dangling.obj");
  const bool device = ::mknod((scratch.work / "null.obj").c_str(), S_IFCHR | 0666, makedev(1, 3)) == 0;
  struct Case { std::vector<std::string> args; std::string message, target; mode_t type; };
  std::vector<Case> cases = {
    {{"grid.off", "fifo.obj"}, "it is a FIFO (named pipe), not a regular file", "fifo.obj", S_IFIFO},
    {{"grid.off", "out.obj", "--svg=fifo.obj"}, "it is a FIFO (named pipe), not a regular file", "fifo.obj", S_IFIFO},
    {{"grid.off", "link.obj"}, "it is a symbolic link; the program does not replace a link", "link.obj", S_IFLNK},
    {{"grid.off", "out.obj", "--svg=link.obj"}, "it is a symbolic link", "link.obj", S_IFLNK},
    {{"grid.off", "dangling.obj"}, "it is a symbolic link", "dangling.obj", S_IFLNK},
  };
  if(device)
    cases.push_back({{"grid.off", "null.obj"}, "it is a character device, not a regular file", "null.obj", S_IFCHR});
  else
    BOOST_TEST_MESSAGE("no device node case: mknod is not permitted here");
  const std::set<std::string> before = scratch.files();
  for(const Case& c : cases)
    BOOST_TEST_CONTEXT(c.args.back())
    {
      const Run r = scratch.run(c.args);
      BOOST_TEST(r.code == 1);
      BOOST_TEST(contains(r.err, "cannot write"), r.err);
      BOOST_TEST(contains(r.err, c.message), r.err);
      BOOST_TEST(file_type(scratch.work / c.target) == c.type);
      BOOST_TEST(text_of(scratch.work / "real.obj") == "previous\n");
      BOOST_TEST(scratch.files() == before);
    }
}

BOOST_AUTO_TEST_CASE(non_regular_inputs_are_refused)
{
  // was: a FIFO blocked forever; a link to /dev/zero grew memory until std::bad_alloc
  Scratch scratch;
  scratch.write("octahedron.off", "OFF\n6 8 0\n1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1\n0 0 -1\n"
                                  "3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n3 3 1 5\n3 0 3 5\n");
  BOOST_REQUIRE(::mkfifo((scratch.work / "fifo.off").c_str(), 0644) == 0);
  BOOST_REQUIRE(::mkfifo((scratch.work / "fifo.selection.txt").c_str(), 0644) == 0);
  fs::create_symlink("/dev/zero", scratch.work / "zero.obj");
  fs::create_symlink("/dev/urandom", scratch.work / "random.off");
  const std::set<std::string> before = scratch.files();
  const std::vector<std::pair<std::vector<std::string>, std::string> > cases = {
    {{"fifo.off", "out.obj"}, "it is a FIFO (named pipe), not a regular file"},
    {{"zero.obj", "out.obj"}, "it is a character device, not a regular file"},
    {{"random.off", "out.obj"}, "it is a character device, not a regular file"},
    {{"octahedron.off", "out.obj", "--seams=fifo.selection.txt"}, "it is a FIFO (named pipe)"}};
  for(const auto& c : cases)
    BOOST_TEST_CONTEXT(c.first[0] << " " << c.first.back())
    {
      const Run r = scratch.run(c.first);
      BOOST_TEST(r.code == 1);
      BOOST_TEST(contains(r.err, c.second), r.err);
      BOOST_TEST(scratch.files() == before);
    }
}

BOOST_AUTO_TEST_CASE(failed_publish_keeps_previous_outputs)
{
  // the SVG cannot be published (its directory was moved away while the program ran): the
  // OBJ already renamed gets its previous contents back (was: the user's OBJ deleted)
  Scratch scratch;
  scratch.write("grid.off", grid_off);
  scratch.write("out.obj", "previous obj\n");
  fs::create_directory(scratch.work / "pictures");
  scratch.write("pictures/out.svg", "previous svg\n");
  const Run r = scratch.run_stopped({"grid.off", "out.obj", "--svg=pictures/out.svg", "--single-chart"}, [&](pid_t pid) {
    BOOST_TEST(temporaries_in(scratch.work) == 1u);  // the OBJ's; the SVG's is in pictures/
    fs::rename(scratch.work / "pictures", scratch.work / "moved");
    ::kill(pid, SIGCONT);
  });
  BOOST_TEST(r.exited);
  BOOST_TEST(r.code == 1);
  BOOST_TEST(contains(r.err, "cannot write --svg 'pictures/out.svg'"), r.err);
  BOOST_TEST(text_of(scratch.work / "out.obj") == "previous obj\n");
  BOOST_TEST(text_of(scratch.work / "moved/out.svg") == "previous svg\n");
  BOOST_TEST((scratch.files() == std::set<std::string>{"grid.off", "out.obj", "moved"}));

  // a new OBJ (none before) is removed again
  Scratch fresh;
  fresh.write("grid.off", grid_off);
  fs::create_directory(fresh.work / "pictures");
  const Run n = fresh.run_stopped({"grid.off", "new.obj", "--svg=pictures/out.svg", "--single-chart"}, [&](pid_t pid) {
    fs::rename(fresh.work / "pictures", fresh.work / "moved");
    ::kill(pid, SIGCONT);
  });
  BOOST_TEST(n.code == 1);
  BOOST_TEST((fresh.files() == std::set<std::string>{"grid.off", "moved"}));

  // the same run not interrupted publishes both
  const Run ok = scratch.run_stopped({"grid.off", "out.obj", "--svg=moved/out.svg", "--single-chart"},
                                     [](pid_t pid) { ::kill(pid, SIGCONT); });
  BOOST_TEST(ok.code == 0);
  BOOST_TEST(read_obj(scratch.work / "out.obj").f.size() == 8u);
  BOOST_TEST(contains(text_of(scratch.work / "moved/out.svg"), "</svg>"));
  BOOST_TEST((scratch.files() == std::set<std::string>{"grid.off", "out.obj", "moved"}));
}

BOOST_AUTO_TEST_CASE(interrupted_run_leaves_no_temporary_file)
{
  // killed with every output in its temporary file: the temporaries are removed, the previous
  // outputs are left as they were (was: a hidden partial temporary file left behind)
  for(const int sig : {SIGTERM, SIGINT, SIGHUP})
    BOOST_TEST_CONTEXT("signal " << sig)
    {
      Scratch scratch;
      scratch.write("grid.off", grid_off);
      scratch.write("out.obj", "previous\n");
      const Run r = scratch.run_stopped({"grid.off", "out.obj", "--svg=out.svg"}, [&](pid_t pid) {
        BOOST_TEST(temporaries_in(scratch.work) == 2u);
        ::kill(pid, sig);
        ::kill(pid, SIGCONT);
      });
      BOOST_TEST(!r.exited);
      BOOST_TEST(r.signal == sig);
      BOOST_TEST(temporaries_in(scratch.work) == 0u);
      BOOST_TEST((scratch.files() == std::set<std::string>{"grid.off", "out.obj"}));
      BOOST_TEST(text_of(scratch.work / "out.obj") == "previous\n");
    }
}

BOOST_AUTO_TEST_CASE(long_output_names)
{
  // names of 250 bytes are legal (NAME_MAX 255) (was: "File name too long", the temporary
  // name being longer than the target's)
  const std::string obj = std::string(246, 'o') + ".obj", svg = std::string(246, 's') + ".svg";
  Scratch scratch;
  scratch.write("grid.off", grid_off);
  const Run r = scratch.run({"grid.off", obj, "--svg=" + svg, "--single-chart"});
  BOOST_REQUIRE_EQUAL(r.code, 0);
  BOOST_TEST((scratch.files() == std::set<std::string>{"grid.off", obj, svg}));
  BOOST_TEST(read_obj(scratch.work / obj).f.size() == 8u);
}

// ---------------------------------------------------------------- failures with --json, the
// border and repair in the summary and the SVG, the usage hint (issue 12)

namespace {

std::size_t occurrences(const std::string& text, const std::string& part)
{
  std::size_t n = 0;
  for(std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + part.size()))
    ++n;
  return n;
}

// The text of stderr after "error: ", without the final line break(s) and usage hint.
std::string error_message(const std::string& err)
{
  const std::size_t at = err.find("error: ");
  if(at == std::string::npos)
    return std::string();
  const std::size_t end = err.find('\n', at);
  return err.substr(at + 7, end == std::string::npos ? std::string::npos : end - at - 7);
}

} // namespace

BOOST_AUTO_TEST_CASE(json_failures_are_json_on_stdout)
{
  // --json: a failure prints {"error": ..., "code": ..., "error_code": ...} on stdout (the
  // same message as on stderr; code = the exit status), and writes no file
  struct Case
  {
    std::string name;
    std::vector<std::string> args;
    int code;
    std::string message;  // a part of the message
  };
  const std::vector<Case> cases = {
    {"missing input", {"missing.off", "out.obj", "--json"}, 1, "missing.off"},
    {"bad option value, --json first", {"--json", "grid.off", "--border=convex"}, 2, "--border"},
    {"unknown option, --json after it", {"grid.off", "--frobnicate", "--json"}, 2, "unknown option '--frobnicate'"},
    {"center on the border", {"grid.off", "out.obj", "--center=vertex:0", "--json"}, 1, "--center=vertex:0"},
  };
  for(const Case& c : cases)
    BOOST_TEST_CONTEXT(c.name)
    {
      Scratch scratch;
      scratch.write("grid.off", grid_off);
      const Run r = scratch.run(c.args);
      BOOST_TEST(r.code == c.code);
      BOOST_TEST(contains(r.err, c.message), r.err);
      const boost::property_tree::ptree j = parse_json(r.out);
      BOOST_TEST(j.get<std::string>("error") == error_message(r.err), r.out);
      BOOST_TEST(contains(j.get<std::string>("error"), c.message), r.out);
      BOOST_TEST(j.get<int>("code") == c.code);
      const std::string error_code = j.get<std::string>("error_code");
      BOOST_TEST((error_code == "null" || std::stoi(error_code) > 0), error_code);
      BOOST_TEST((scratch.files() == std::set<std::string>{"grid.off"}));
      // without --json nothing on stdout
      std::vector<std::string> plain;
      for(const std::string& a : c.args)
        if(a != "--json")
          plain.push_back(a);
      const Run p = scratch.run(plain);
      BOOST_TEST(p.code == c.code);
      BOOST_TEST(p.out.empty(), p.out);
    }
}

BOOST_AUTO_TEST_CASE(usage_hint_is_printed_once)
{
  for(const std::vector<std::string>& args : {std::vector<std::string>{"--frobnicate"},
                                              std::vector<std::string>{"--border=convex"},
                                              std::vector<std::string>{"--center=nowhere"}})
    BOOST_TEST_CONTEXT(args[0])
    {
      Scratch scratch;
      const Run r = scratch.run(args);
      BOOST_TEST(r.code == 2);
      BOOST_TEST(occurrences(r.err, "--help") == 1u, r.err);
      BOOST_TEST(occurrences(r.err, "error: ") == 1u, r.err);
      BOOST_TEST(scratch.files().empty());
    }
}

BOOST_AUTO_TEST_CASE(summary_and_svg_name_the_border_kept_and_the_repair)
{
  // a layout that needs no repair: the kept border and "no repair needed"
  {
    Scratch scratch;
    scratch.write("grid.off", grid_off);
    const Run r = scratch.run({"grid.off", "out.obj", "--svg=out.svg", "--border=measured"});
    BOOST_REQUIRE_EQUAL(r.code, 0);
    BOOST_TEST(contains(r.out, "| border measured: measured"), r.out);
    BOOST_TEST(contains(r.out, "| no repair needed"), r.out);
    const std::string svg = Scratch::read_text(scratch.work / "out.svg");
    BOOST_TEST(contains(svg, "border measured: kept measured"), svg.substr(0, 2000));
    BOOST_TEST(contains(svg, "no repair needed"));
    const Run off = scratch.run({"grid.off", "off.obj", "--svg=off.svg", "--no-repair"});
    BOOST_REQUIRE_EQUAL(off.code, 0);
    BOOST_TEST(contains(off.out, "| repair off"), off.out);
    BOOST_TEST(contains(Scratch::read_text(scratch.work / "off.svg"), "repair off"));
  }
  // a layout that folds: the C-shaped flat domain seen from a vertex of its top arm with exact
  // geodesic radii (test_validity: generated_fold_is_repaired_or_rejected) is repaired, and
  // both the summary and the SVG say so, with the number of flipped faces before the repair
  const mbp_test::Soup soup = mbp_test::c_shape();
  std::size_t center = soup.points.size();
  for(std::size_t i = 0; i < soup.points.size(); ++i)
    if(std::abs(soup.points[i][0] - 1.5) < 1e-12 && std::abs(soup.points[i][1] - 13. / 6.) < 1e-12)
      center = i;
  BOOST_REQUIRE(center < soup.points.size());
  Scratch scratch;
  scratch.write("c.off", off_text(soup));
  const std::vector<std::string> args{"c.off", "c.obj", "--svg=c.svg", "--border=measured",
                                      "--center=vertex:" + std::to_string(center), "--distance=exact"};
  const Run r = scratch.run(args);
  BOOST_REQUIRE_EQUAL(r.code, 0);
  BOOST_TEST(contains(r.out, "| repaired "), r.out);
  BOOST_TEST(contains(r.out, " flipped faces: blend "), r.out);
  const std::string svg = Scratch::read_text(scratch.work / "c.svg");
  BOOST_TEST(contains(svg, "border measured: kept "));
  BOOST_TEST(contains(svg, "repaired "));
  std::vector<std::string> json_args = args;
  json_args[1] = "c_json.obj";
  json_args[2] = "--json";
  const Run j = scratch.run(json_args);
  BOOST_REQUIRE_EQUAL(j.code, 0);
  const boost::property_tree::ptree tree = parse_json(j.out);
  BOOST_TEST(tree.get<bool>("repair.repaired"));
  BOOST_TEST(contains(r.out, "| repaired " + std::to_string(tree.get<std::size_t>("repair.flipped_faces_before")) +
                               " flipped faces"), r.out);
  // without repair the same run fails, with the library's code in the JSON
  json_args.push_back("--no-repair");
  const Run n = scratch.run(json_args);
  BOOST_TEST(n.code == 1);
  BOOST_TEST(parse_json(n.out).get<int>("error_code") == int(SMP::ERROR_NO_1_TO_1_MAPPING), n.out);
}

// ---------------------------------------------------------------- automatic seams (issue 16)

namespace {

// The mesh of `path`, cut by the program along automatic seams with --write-seams: checks the
// run (exit 0, the summary or JSON, the seams file, no flipped face, with `target` the issue's
// angle distortion target) and returns the JSON.
boost::property_tree::ptree run_automatic_seams(const std::string& path, bool closed, bool target)
{
  Mesh mesh;
  mbp_test::read_mesh(path, mesh);
  Scratch scratch;
  const Run r = scratch.run({path, "out.obj", "--svg=out.svg", "--write-seams=out.selection.txt", "--json"});
  BOOST_REQUIRE_EQUAL(r.code, 0);
  BOOST_TEST((scratch.files() == std::set<std::string>{"out.obj", "out.svg", "out.selection.txt"}));
  const boost::property_tree::ptree j = parse_json(r.out);
  const std::vector<std::pair<std::size_t, std::size_t> > seams =
    read_selection_edges((scratch.work / "out.selection.txt").string());
  BOOST_TEST(j.get<std::string>("seams") == "null");
  BOOST_TEST(j.get<std::size_t>("seam_edges") == seams.size());
  BOOST_TEST(j.get<std::size_t>("automatic_seams.seam_edges") == seams.size());
  BOOST_TEST(seams.size() > 0u);
  BOOST_TEST(j.get<std::size_t>("quality.flipped_faces") == 0u);
  if(target)  // issue 16's target on the project's meshes
    BOOST_TEST(j.get<double>("quality.angle_distortion") <= 0.05);
  // every seam is an edge of the mesh
  const std::vector<vertex_descriptor> by_index(vertices(mesh).begin(), vertices(mesh).end());
  for(const auto& e : seams)
    BOOST_TEST(edge(by_index[e.first], by_index[e.second], mesh).second);
  if(closed)
    check_seam_obj(read_obj(scratch.work / "out.obj", true), mesh, seams);
  // the SVG draws both sides of every seam edge, and its legend counts them
  const std::string svg = Scratch::read_text(scratch.work / "out.svg");
  BOOST_TEST(contains(svg, "seams (" + std::to_string(seams.size()) + " edges, both sides)"));
  const std::size_t path_start = svg.find("stroke=\"#e66100\"");
  BOOST_REQUIRE(path_start != std::string::npos);
  const std::size_t path_end = svg.find("/>", path_start);
  BOOST_TEST(occurrences(svg.substr(path_start, path_end - path_start), "M") == 2 * seams.size());
  return j;
}

} // namespace

MBP_TIERED_TEST_CASE(not_a_disk_real_meshes_get_automatic_seams)
{
  // closed (genus 0: 8 cones; higher genus: loops), holed and open higher-genus meshes,
  // flattened without a seam file. Core tier: CGAL's data meshes; extended tier: the other
  // meshes of the classes CLOSED, HOLES and OPEN g>0 of the project's meshes. Every one of
  // those classes is held to issue 16's angle distortion target (<= 0.05); CGAL's eight.off,
  // coarse (315 vertices) and not among them, gets 0.064.
  struct Case
  {
    std::string name;
    bool closed;
    int genus, cones;
  };
  const std::vector<Case> cases = (tier == mbp_test::Tier::core)
    ? std::vector<Case>{{"fandisk.off", true, 0, 8}, {"bear.off", true, 0, 8}, {"hand.off", true, 0, 8},
                        {"eight.off", true, 2, 0}, {"holes.off", false, 0, 0}, {"head.off", false, 0, 0},
                        {"lion.off", false, 0, 0}, {"mech-holes-shark.off", false, 0, 0}, {"blade.off", false, 0, 0}}
    : std::vector<Case>{{"kitten.obj", true, 1, 0}, {"Hand1.off", false, 1, 0}, {"punctured-torus.obj", false, 1, 0},
                        {"nefertiti-entire.off", false, 0, 0}};
  for(const Case& c : cases)
  {
    BOOST_TEST_CONTEXT("mesh: " << c.name)
    {
      const boost::property_tree::ptree j =
        run_automatic_seams(mbp_test::tier_mesh(tier, c.name), c.closed, c.name != "eight.off");
      BOOST_TEST(j.get<int>("automatic_seams.genus") == c.genus);
      BOOST_TEST(j.get<int>("automatic_seams.cones") == c.cones);
      const int borders = j.get<int>("automatic_seams.border_loops");
      BOOST_TEST(j.get<int>("automatic_seams.loops") == (borders == 0 ? 2 * c.genus : 2 * c.genus + borders - 1));
      BOOST_TEST(j.get_child("automatic_seams.cone_vertices").size() == std::size_t(c.cones));
    }
  }
}

BOOST_AUTO_TEST_CASE(automatic_seams_summary_and_written_seams_reused)
{
  // a generated torus: two loops. The summary says so; --write-seams gives a selection file
  // that --seams reads back, to the same layout
  const mbp_test::Soup soup = closed_torus(16, 10);
  Scratch scratch;
  scratch.write("torus.off", off_text(soup));
  const Run r = scratch.run({"torus.off", "auto.obj", "--write-seams=cut.selection.txt"});
  BOOST_REQUIRE_EQUAL(r.code, 0);
  const std::vector<std::pair<std::size_t, std::size_t> > seams =
    read_selection_edges((scratch.work / "cut.selection.txt").string());
  BOOST_TEST(contains(r.out, "| automatic seams " + std::to_string(seams.size()) + " edges, 0 cones, "), r.out);
  Mesh mesh;
  mbp_test::soup_to_mesh(soup, mesh);
  const Obj automatic = read_obj(scratch.work / "auto.obj", true);
  check_seam_obj(automatic, mesh, seams);

  const Run again = scratch.run({"torus.off", "again.obj", "--seams=cut.selection.txt"});
  BOOST_REQUIRE_EQUAL(again.code, 0);
  BOOST_TEST(contains(again.out, "| seams " + std::to_string(seams.size()) + " edges, "), again.out);
  const Obj reused = read_obj(scratch.work / "again.obj", true);
  BOOST_TEST((reused.vt == automatic.vt));
  BOOST_TEST((reused.ft == automatic.ft));

  // a closed genus-0 mesh: the cones are the selected vertices of line 1, each on a seam
  Scratch sphere;
  const std::string fandisk = mbp_test::core_mesh("fandisk.off");
  const Run f = sphere.run({fandisk, "f.obj", "--write-seams=f.selection.txt"});
  BOOST_REQUIRE_EQUAL(f.code, 0);
  std::ifstream in(sphere.work / "f.selection.txt");
  std::string cone_line;
  BOOST_REQUIRE(std::getline(in, cone_line));
  std::istringstream cone_numbers(cone_line);
  std::set<std::size_t> cones;
  for(std::size_t c = 0; cone_numbers >> c;)
    cones.insert(c);
  BOOST_TEST(cones.size() == 8u);
  std::set<std::size_t> on_seam;
  for(const auto& e : read_selection_edges((sphere.work / "f.selection.txt").string()))
  {
    on_seam.insert(e.first);
    on_seam.insert(e.second);
  }
  for(std::size_t c : cones)
    BOOST_TEST(on_seam.count(c) == 1u);
  BOOST_TEST(contains(f.out, "| automatic seams "), f.out);
  BOOST_TEST(contains(f.out, " edges, 8 cones, "), f.out);
}

BOOST_AUTO_TEST_CASE(small_closed_and_punctured_meshes_get_automatic_seams)
{
  // an octahedron (6 vertices): 2 cones at opposite vertices (8 would leave no interior
  // vertex), joined through a third vertex: 2 seam edges
  Scratch scratch;
  scratch.write("octahedron.off", "OFF\n6 8 0\n1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1\n0 0 -1\n"
                                  "3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n3 3 1 5\n3 0 3 5\n");
  const Run r = scratch.run({"octahedron.off", "out.obj", "--json", "--single-chart"});
  BOOST_REQUIRE_EQUAL(r.code, 0);
  const boost::property_tree::ptree j = parse_json(r.out);
  BOOST_TEST(j.get<int>("automatic_seams.cones") == 2);
  BOOST_TEST(j.get<std::size_t>("seam_edges") == 2u);
  BOOST_TEST(j.get<std::size_t>("uvs") == 7u);  // the middle vertex twice, the cones once
  BOOST_TEST(j.get<std::size_t>("quality.flipped_faces") == 0u);
  // a punctured torus: two arcs from its border around the handle
  scratch.write("torus.off", off_text(mbp_test::punctured_torus()));
  const Run t = scratch.run({"torus.off", "torus.obj", "--json", "--single-chart"});
  BOOST_REQUIRE_EQUAL(t.code, 0);
  const boost::property_tree::ptree tj = parse_json(t.out);
  BOOST_TEST(tj.get<int>("automatic_seams.genus") == 1);
  BOOST_TEST(tj.get<int>("automatic_seams.loops") == 2);
  BOOST_TEST(tj.get<std::size_t>("quality.flipped_faces") == 0u);
}

BOOST_AUTO_TEST_CASE(write_seams_of_a_disk_lists_none)
{
  Scratch scratch;
  scratch.write("grid.off", grid_off);
  const Run r = scratch.run({"grid.off", "out.obj", "--write-seams=none.selection.txt", "--json"});
  BOOST_REQUIRE_EQUAL(r.code, 0);
  BOOST_TEST(contains(r.err, "note: the mesh is a disk, it needs no seams"), r.err);
  BOOST_TEST(Scratch::read_text(scratch.work / "none.selection.txt") == "\n\n\n");
  const boost::property_tree::ptree j = parse_json(r.out);
  BOOST_TEST(j.get<std::string>("automatic_seams") == "null");
  BOOST_TEST(j.get<std::size_t>("seam_edges") == 0u);
  // a bad --write-seams is a command-line error
  const Run bad = scratch.run({"grid.off", "out2.obj", "--write-seams="});
  BOOST_TEST(bad.code == 2);
  BOOST_TEST(contains(bad.err, "option --write-seams needs a file name"), bad.err);
  // and the target is checked before the run like the other outputs: not the input
  const Run same = scratch.run({"grid.off", "out3.obj", "--write-seams=grid.off"});
  BOOST_TEST(same.code != 0);
  BOOST_TEST(Scratch::read_text(scratch.work / "grid.off") == grid_off);
}

BOOST_AUTO_TEST_CASE(equal_border_loops_are_chosen_by_the_library_rule)
{
  // An open tube whose two end loops have exactly the same length. The program takes the
  // library's main_border() (through find_longest_border()): among loops of equal length the
  // one of the vertex that comes first in the file, from that vertex; so the tube and its
  // copies scaled, mirrored, translated or rotated give the same border loop from the same
  // vertex (the longest loop alone is a matter of rounding, and its start was the first
  // border halfedge found). With --border=circle the start is the vertex at angle 0 of the
  // circle, the largest u.
  const int n = 31, rows = 5;
  const mbp_test::Soup tube = mbp_test::tube(n, rows, 2. / rows, false);
  const double c = std::cos(1.), s = std::sin(1.);
  const std::vector<std::pair<std::string, std::function<std::array<double, 3>(const std::array<double, 3>&)> > > transforms{
    {"identity", [](const std::array<double, 3>& p) { return p; }},
    {"scaled by 1e-6", [](const std::array<double, 3>& p) { return std::array<double, 3>{{p[0] * 1e-6, p[1] * 1e-6, p[2] * 1e-6}}; }},
    {"mirrored", [](const std::array<double, 3>& p) { return std::array<double, 3>{{-p[0], p[1], p[2]}}; }},
    {"translated by 1e6", [](const std::array<double, 3>& p) { return std::array<double, 3>{{p[0] + 1e6, p[1] + 1e6, p[2] + 1e6}}; }},
    {"rotated", [c, s](const std::array<double, 3>& p) { return std::array<double, 3>{{c * p[0] - s * p[2], p[1], s * p[0] + c * p[2]}}; }}};
  Scratch scratch;
  std::size_t first_count = 0, first_start = 0;
  for(const auto& transform : transforms)
    BOOST_TEST_CONTEXT(transform.first)
    {
      mbp_test::Soup moved = tube;
      for(auto& p : moved.points)
        p = transform.second(p);
      scratch.write("tube.off", exact_off_text(moved));
      const Run r = scratch.run({"tube.off", "tube.obj", "--json", "--border=circle"});
      BOOST_REQUIRE_EQUAL(r.code, 0);
      const std::size_t count = parse_json(r.out).get<std::size_t>("border.vertices");
      const Obj obj = read_obj(scratch.work / "tube.obj", true);
      BOOST_REQUIRE_EQUAL(obj.v.size(), tube.points.size());
      // the input vertex of every 'vt'
      std::vector<std::size_t> vertex_of(obj.vt.size(), 0);
      for(std::size_t f = 0; f < obj.f.size(); ++f)
        for(std::size_t k = 0; k < 3; ++k)
          vertex_of[obj.ft[f][k]] = obj.f[f][k];
      std::size_t start = 0;
      for(std::size_t i = 0; i < obj.vt.size(); ++i)
        if(obj.vt[i][0] > obj.vt[start][0])
          start = i;
      start = vertex_of[start];
      BOOST_TEST_MESSAGE("border of " << count << " vertices from vertex " << start << ", " << obj.vt.size() << " UVs");
      if(obj.vt.size() == obj.v.size())  // not cut: the bottom loop
        BOOST_TEST(count == std::size_t(n));
      BOOST_TEST(start == 0u);  // vertex 0 comes first
      if(transform.first == "identity")
      {
        first_count = count;
        first_start = start;
      }
      BOOST_TEST(count == first_count);
      BOOST_TEST(start == first_start);
    }
}

// ---------------------------------------------------------------- the atlas (issue 22, item 5)

namespace {

// The OBJ of an atlas, read here independently of the program: 'v', 'vt', 'f' with any number
// of corners, each "v/vt", and the groups 'g chart_K'.
struct Atlas_obj
{
  std::vector<std::array<double, 3> > v;
  std::vector<std::array<double, 2> > vt;
  std::vector<std::vector<std::size_t> > f, ft;  // per polygon: 'v' and 'vt' indices, 0-based
  std::vector<long> chart;                        // per polygon: K of the last 'g chart_K' before it (-1: none)
  std::size_t groups = 0;                         // 'g' lines
  std::size_t repeated_groups = 0;                // 'g' lines naming the chart of the group before them
  std::size_t other_lines = 0;                    // lines that are not v, vt, f, g, comments or empty
};

Atlas_obj read_atlas_obj(const fs::path& path)
{
  std::ifstream in(path);
  BOOST_REQUIRE_MESSAGE(in.good(), "cannot open " << path);
  Atlas_obj obj;
  long chart = -1;
  std::string line;
  while(std::getline(in, line))
  {
    std::istringstream s(line);
    std::string tag;
    if(!(s >> tag) || tag[0] == '#')
      continue;
    if(tag == "v")
    {
      std::array<double, 3> p;
      BOOST_REQUIRE_MESSAGE(s >> p[0] >> p[1] >> p[2], "bad line: " << line);
      obj.v.push_back(p);
    }
    else if(tag == "vt")
    {
      std::array<double, 2> q;
      BOOST_REQUIRE_MESSAGE(s >> q[0] >> q[1], "bad line: " << line);
      obj.vt.push_back(q);
    }
    else if(tag == "g")
    {
      std::string name, more;
      BOOST_REQUIRE_MESSAGE(s >> name && !(s >> more) && name.rfind("chart_", 0) == 0 && name.size() > 6 &&
                              name.find_first_not_of("0123456789", 6) == std::string::npos,
                            "not a group 'g chart_K': " << line);
      const long k = std::stol(name.substr(6));
      obj.repeated_groups += (k == chart) ? 1 : 0;
      chart = k;
      ++obj.groups;
    }
    else if(tag == "f")
    {
      std::vector<std::size_t> face, uv_face;
      for(std::string corner; s >> corner;)
      {
        const std::size_t slash = corner.find('/');
        BOOST_REQUIRE_MESSAGE(slash != std::string::npos && corner.find('/', slash + 1) == std::string::npos,
                              "corner not 'v/vt': " << line);
        const long index = std::stol(corner.substr(0, slash)), uv_index = std::stol(corner.substr(slash + 1));
        BOOST_REQUIRE_MESSAGE(index >= 1 && uv_index >= 1, "bad index: " << line);
        face.push_back(std::size_t(index - 1));
        uv_face.push_back(std::size_t(uv_index - 1));
      }
      obj.f.push_back(face);
      obj.ft.push_back(uv_face);
      obj.chart.push_back(chart);
    }
    else
      ++obj.other_lines;
  }
  for(std::size_t i = 0; i < obj.f.size(); ++i)
    for(std::size_t k = 0; k < obj.f[i].size(); ++k)
      BOOST_REQUIRE(obj.f[i][k] < obj.v.size() && obj.ft[i][k] < obj.vt.size());
  return obj;
}

typedef std::array<std::array<double, 2>, 3> Uv_triangle;

// Whether the interiors of two UV triangles overlap by more than `eps` (a separating axis
// among their edge normals, projections that touch or overlap by less than `eps` count as
// apart): an independent test, in plain double arithmetic.
bool uv_triangles_overlap(const Uv_triangle& a, const Uv_triangle& b, double eps)
{
  for(const Uv_triangle* t : {&a, &b})
    for(std::size_t k = 0; k < 3; ++k)
    {
      const std::array<double, 2>& p = (*t)[k];
      const std::array<double, 2>& q = (*t)[(k + 1) % 3];
      const double length = std::hypot(q[0] - p[0], q[1] - p[1]);
      if(!(length > 0.))
        continue;
      const double nx = (q[1] - p[1]) / length, ny = (p[0] - q[0]) / length;
      double lo[2] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
      double hi[2] = {-lo[0], -lo[1]};
      for(int s = 0; s < 2; ++s)
        for(const std::array<double, 2>& r : (s == 0 ? a : b))
        {
          const double x = nx * r[0] + ny * r[1];
          lo[s] = (std::min)(lo[s], x);
          hi[s] = (std::max)(hi[s], x);
        }
      if(hi[0] <= lo[1] + eps || hi[1] <= lo[0] + eps)
        return false;
    }
  return true;
}

double twice_signed_area(const std::array<double, 2>& a, const std::array<double, 2>& b, const std::array<double, 2>& c)
{
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

// The triangles of a UV polygon by ear clipping (a fan would fold over a concave corner);
// the rest as a fan when no ear is left (a polygon that is not simple).
std::vector<Uv_triangle> uv_triangles(std::vector<std::array<double, 2> > p)
{
  double area = 0.;
  for(std::size_t k = 1; k + 1 < p.size(); ++k)
    area += twice_signed_area(p[0], p[k], p[k + 1]);
  const double side = area < 0. ? -1. : 1.;
  std::vector<Uv_triangle> triangles;
  while(p.size() > 3)
  {
    std::size_t ear = p.size();
    for(std::size_t k = 0; k < p.size() && ear == p.size(); ++k)
    {
      const std::array<double, 2>& a = p[(k + p.size() - 1) % p.size()];
      const std::array<double, 2>& b = p[k];
      const std::array<double, 2>& c = p[(k + 1) % p.size()];
      if(!(side * twice_signed_area(a, b, c) > 0.))
        continue;
      bool empty = true;
      for(const std::array<double, 2>& q : p)
        if(q != a && q != b && q != c && side * twice_signed_area(a, b, q) >= 0. &&
           side * twice_signed_area(b, c, q) >= 0. && side * twice_signed_area(c, a, q) >= 0.)
          empty = false;
      if(empty)
        ear = k;
    }
    if(ear == p.size())
      break;
    triangles.push_back({p[(ear + p.size() - 1) % p.size()], p[ear], p[(ear + 1) % p.size()]});
    p.erase(p.begin() + std::ptrdiff_t(ear));
  }
  for(std::size_t k = 1; k + 1 < p.size(); ++k)
    triangles.push_back({p[0], p[k], p[k + 1]});
  return triangles;
}

// The pairs of UV triangles of different charts whose interiors overlap (each polygon cut
// into triangles by ear clipping; triangles of no area left out, and polygons through a point
// twice, whose pieces may lie in different charts): every pair whose boxes share a cell of a
// 64 x 64 grid of the unit square is tested.
std::size_t overlapping_chart_pairs(const Atlas_obj& obj)
{
  std::vector<Uv_triangle> triangles;
  std::vector<long> chart;
  for(std::size_t i = 0; i < obj.ft.size(); ++i)
  {
    if(obj.ft[i].size() < 3 || std::set<std::size_t>(obj.f[i].begin(), obj.f[i].end()).size() != obj.f[i].size())
      continue;
    std::vector<std::array<double, 2> > polygon;
    for(std::size_t uv : obj.ft[i])
      polygon.push_back(obj.vt[uv]);
    for(const Uv_triangle& t : uv_triangles(polygon))
      if(twice_signed_area(t[0], t[1], t[2]) != 0.)
      {
        triangles.push_back(t);
        chart.push_back(obj.chart[i]);
      }
  }
  const int n = 64;
  std::vector<std::vector<std::size_t> > cells(std::size_t(n * n));
  auto cell = [n](double x) { return std::clamp(int(std::floor(x * n)), 0, n - 1); };
  for(std::size_t t = 0; t < triangles.size(); ++t)
  {
    const Uv_triangle& u = triangles[t];
    const int x0 = cell((std::min)({u[0][0], u[1][0], u[2][0]})), x1 = cell((std::max)({u[0][0], u[1][0], u[2][0]}));
    const int y0 = cell((std::min)({u[0][1], u[1][1], u[2][1]})), y1 = cell((std::max)({u[0][1], u[1][1], u[2][1]}));
    for(int x = x0; x <= x1; ++x)
      for(int y = y0; y <= y1; ++y)
        cells[std::size_t(y * n + x)].push_back(t);
  }
  std::set<std::pair<std::size_t, std::size_t> > overlapping;
  for(const std::vector<std::size_t>& c : cells)
    for(std::size_t a = 0; a < c.size(); ++a)
      for(std::size_t b = a + 1; b < c.size(); ++b)
        if(chart[c[a]] != chart[c[b]] && uv_triangles_overlap(triangles[c[a]], triangles[c[b]], 1e-9))
          overlapping.insert({(std::min)(c[a], c[b]), (std::max)(c[a], c[b])});
  for(const auto& o : overlapping)
    BOOST_TEST_MESSAGE("overlap: charts " << chart[o.first] << " and " << chart[o.second]);
  return overlapping.size();
}

// Checks the atlas of `input` (the soup as the program reads it: points and polygons in file
// order) from its OBJ and JSON: the input's points (exactly, with `exact_points`) and
// polygons in their order, one 'vt' per corner in polygon order, every UV in [0,1]^2, the
// groups, no overlap between charts, the JSON's counts. Returns the number of charts.
std::size_t check_atlas(const Atlas_obj& obj, const boost::property_tree::ptree& j, const mbp_test::Soup& input,
                        bool exact_points = true)
{
  BOOST_TEST(obj.other_lines == 0u);
  BOOST_REQUIRE_EQUAL(obj.v.size(), input.points.size());
  std::size_t moved = 0;
  for(std::size_t i = 0; i < obj.v.size() && exact_points; ++i)
    moved += (obj.v[i] == input.points[i]) ? 0 : 1;
  BOOST_TEST(moved == 0u, moved << " 'v' lines differ from the input's points");

  BOOST_REQUIRE_EQUAL(obj.f.size(), input.faces.size());
  std::size_t corner = 0, other_polygons = 0, other_uvs = 0, outside = 0;
  for(std::size_t i = 0; i < obj.f.size(); ++i)
  {
    other_polygons += (obj.f[i] == input.faces[i]) ? 0 : 1;
    for(std::size_t uv : obj.ft[i])
      other_uvs += (uv == corner++) ? 0 : 1;
  }
  BOOST_TEST(other_polygons == 0u, other_polygons << " polygons differ from the input's (size or points)");
  BOOST_TEST(other_uvs == 0u, other_uvs << " corners without their own 'vt' in polygon order");
  BOOST_TEST(obj.vt.size() == corner);
  for(const auto& q : obj.vt)
    outside += (std::isfinite(q[0]) && std::isfinite(q[1]) && q[0] >= 0. && q[0] <= 1. && q[1] >= 0. && q[1] <= 1.)
                 ? 0 : 1;
  BOOST_TEST(outside == 0u, outside << " UVs outside [0,1]^2");

  // the groups: every polygon in one, named by an id of the JSON's charts, one line per change
  BOOST_TEST(j.get<std::string>("mode") == "atlas");
  const std::size_t charts = j.get<std::size_t>("chart_count");
  BOOST_TEST(charts >= 1u);
  BOOST_TEST(j.get_child("charts").size() == charts);
  std::set<long> used;
  for(long c : obj.chart)
  {
    BOOST_TEST((c >= 0 && std::size_t(c) < charts), "polygon in group chart_" << c << " of " << charts << " charts");
    used.insert(c);
  }
  BOOST_TEST(obj.groups >= used.size());
  BOOST_TEST(obj.repeated_groups == 0u);
  BOOST_TEST(overlapping_chart_pairs(obj) == 0u);

  BOOST_TEST(j.get<std::size_t>("points") == input.points.size());
  BOOST_TEST(j.get<std::size_t>("polygons") == input.faces.size());
  BOOST_TEST(j.get<std::size_t>("corners") == corner);
  BOOST_TEST(j.get<std::size_t>("repair.input_polygons") == input.faces.size());
  const double utilization = j.get<double>("utilization");
  BOOST_TEST((utilization > 0. && utilization <= 1.), "utilization " << utilization);
  BOOST_TEST(j.get<double>("texel_density") > 0.);
  for(const auto& c : j.get_child("charts"))
  {
    BOOST_TEST(c.second.get<std::size_t>("faces") > 0u);
    BOOST_TEST(c.second.get<double>("area_uv") >= 0.);
    const std::string flattening = c.second.get<std::string>("flattening");
    BOOST_TEST((flattening == "disk" || flattening == "seamed" || flattening == "unfolded"), flattening);
  }
  for(const char* time : {"read", "repair", "charts", "packing", "total", "write"})
    BOOST_TEST(j.get<double>(std::string("times.") + time) >= 0., time);
  return charts;
}

// A soup as an OBJ file ('v' and 'f' lines, exact coordinates).
std::string obj_text(const mbp_test::Soup& soup)
{
  std::string s = "# a test soup\n";
  for(const auto& p : soup.points)
    s += "v " + exact_text(p[0]) + " " + exact_text(p[1]) + " " + exact_text(p[2]) + "\n";
  for(const auto& f : soup.faces)
  {
    s += "f";
    for(std::size_t i : f)
      s += " " + std::to_string(i + 1);
    s += "\n";
  }
  return s;
}

// A soup as an ASCII PLY file (exact coordinates).
std::string ascii_ply_text(const mbp_test::Soup& soup)
{
  std::string s = "ply\nformat ascii 1.0\nelement vertex " + std::to_string(soup.points.size()) +
                  "\nproperty double x\nproperty double y\nproperty double z\nelement face " +
                  std::to_string(soup.faces.size()) + "\nproperty list uchar int vertex_indices\nend_header\n";
  for(const auto& p : soup.points)
    s += exact_text(p[0]) + " " + exact_text(p[1]) + " " + exact_text(p[2]) + "\n";
  for(const auto& f : soup.faces)
  {
    s += std::to_string(f.size());
    for(std::size_t i : f)
      s += " " + std::to_string(i);
    s += "\n";
  }
  return s;
}

// The soup a binary STL of the triangle soup `soup` gives: float coordinates, equal points
// merged, in order of first appearance.
mbp_test::Soup as_read_from_stl(const mbp_test::Soup& soup)
{
  mbp_test::Soup read;
  std::map<std::array<double, 3>, std::size_t> index;
  for(const auto& f : soup.faces)
  {
    std::vector<std::size_t> face;
    for(std::size_t i : f)
    {
      const std::array<double, 3> p = {double(float(soup.points[i][0])), double(float(soup.points[i][1])),
                                       double(float(soup.points[i][2]))};
      const auto inserted = index.insert({p, read.points.size()});
      if(inserted.second)
        read.points.push_back(p);
      face.push_back(inserted.first->second);
    }
    read.faces.push_back(face);
  }
  return read;
}

// The text of every <text> element of an SVG document and its position, against the
// document's size: (x, y) of each, and width, height.
struct Svg_texts
{
  long width = 0, height = 0;
  std::vector<std::array<long, 2> > positions;
};

Svg_texts svg_texts(const std::string& svg)
{
  Svg_texts t;
  const std::size_t box = svg.find("viewBox=\"0 0 ");
  BOOST_REQUIRE(box != std::string::npos);
  std::istringstream size(svg.substr(box + 13, 40));
  size >> t.width >> t.height;
  for(std::size_t at = svg.find("<text x=\""); at != std::string::npos; at = svg.find("<text x=\"", at + 1))
  {
    std::istringstream x(svg.substr(at + 9, 20));
    long px = 0, py = 0;
    x >> px;
    const std::size_t y = svg.find("y=\"", at);
    std::istringstream yy(svg.substr(y + 3, 20));
    yy >> py;
    t.positions.push_back({px, py});
  }
  return t;
}

} // namespace

BOOST_AUTO_TEST_CASE(atlas_of_soups_with_defects)
{
  // generated soups with a defect each, in every format the program reads, get an atlas by
  // default: exit 0, the input's points and polygons with a UV on every corner, groups per
  // chart, no overlap between charts, and the repair reported
  struct Case
  {
    std::string name, file;
    mbp_test::Soup soup;
    std::string repair;     // a count of the JSON's repair that must be positive
    std::size_t charts;     // at least this many charts
  };
  mbp_test::Soup two_components = mbp_test::grid(3);
  mbp_test::append(two_components, mbp_test::square(5.));
  mbp_test::Soup far_apart = mbp_test::grid(2);  // for STL: two components of triangles
  mbp_test::append(far_apart, mbp_test::with_reversed_faces(mbp_test::grid(2), 0, 1));
  for(std::size_t i = far_apart.points.size() / 2; i < far_apart.points.size(); ++i)
    far_apart.points[i][2] = 3.;
  const std::vector<Case> cases = {
    {"two components (OBJ)", "two.obj", two_components, "components", 2},
    {"quads and a pentagon (PLY)", "polygons.ply", mbp_test::quads_and_a_pentagon_soup(), "triangulated_polygons", 1},
    {"flipped faces (OFF)", "flipped.off", mbp_test::with_reversed_faces(mbp_test::grid(4), 1, 3), "reoriented_polygons", 1},
    {"zero-area face (OFF)", "sliver.off", mbp_test::zero_area_face_on_an_edge_soup(), "zero_area_triangles", 1},
    {"edge with three faces (OFF)", "fin.off", mbp_test::edge_with_three_faces_soup(), "non_manifold_edges", 1},
    {"two cones at a vertex (OFF)", "cones.off", mbp_test::two_cones(), "pinched_vertices", 1},
    {"Moebius strip (OFF)", "moebius.off", mbp_test::moebius_strip_soup(24), "non_orientable_components", 1},
    {"polygons through a point twice (OBJ)", "twice.obj", mbp_test::polygons_through_a_point_twice_soup(),
     "degenerate_polygons", 1},
    {"two components (STL)", "two.stl", far_apart, "components", 2},
  };
  for(const Case& c : cases)
    BOOST_TEST_CONTEXT(c.name)
    {
      Scratch scratch;
      const std::string ext = fs::path(c.file).extension().string();
      scratch.write(c.file, ext == ".obj" ? obj_text(c.soup) : ext == ".ply" ? ascii_ply_text(c.soup)
                            : ext == ".stl" ? binary_stl(c.soup) : exact_off_text(c.soup));
      const Run r = scratch.run({c.file, "out.obj", "--svg=out.svg", "--json"});
      BOOST_REQUIRE_EQUAL(r.code, 0);
      BOOST_TEST((scratch.files() == std::set<std::string>{c.file, "out.obj", "out.svg"}));
      const boost::property_tree::ptree j = parse_json(r.out);
      const mbp_test::Soup input = (ext == ".stl") ? as_read_from_stl(c.soup) : c.soup;
      const std::size_t charts = check_atlas(read_atlas_obj(scratch.work / "out.obj"), j, input);
      BOOST_TEST(charts >= c.charts);
      BOOST_TEST(j.get<std::size_t>("repair." + c.repair) > 0u, c.repair);
      BOOST_TEST(j.get<std::size_t>("repair.input_corners") == j.get<std::size_t>("corners"));
      if(c.repair == "components")
        BOOST_TEST(j.get<std::size_t>("repair.components") == 2u);

      // the SVG: a complete document of the packed square, the charts outlined, every text
      // inside the picture
      const std::string svg = Scratch::read_text(scratch.work / "out.svg");
      BOOST_TEST(svg.rfind("<?xml", 0) == 0u);
      BOOST_TEST(svg.substr(svg.size() - 7) == "</svg>\n");
      BOOST_TEST(contains(svg, c.file));
      BOOST_TEST(contains(svg, "chart outlines (" + std::to_string(charts) + ")"));
      BOOST_TEST(contains(svg, "distortion per chart against the bounds"));
      BOOST_TEST(contains(svg, "utilization"));
      BOOST_TEST(!contains(svg, "nan"));
      const Svg_texts texts = svg_texts(svg);
      BOOST_TEST(texts.positions.size() >= 6u);
      for(const auto& p : texts.positions)
        BOOST_TEST((p[0] >= 0 && p[0] < texts.width && p[1] > 0 && p[1] < texts.height),
                   "text at " << p[0] << " " << p[1] << " in " << texts.width << " x " << texts.height);
    }
}

// The charts' bounds from the command line: the strip wound 1.5 turns around a cone cannot be
// one undistorted chart. By default every chart is within the bounds the JSON echoes (and the
// summary names); with every bound lifted it is one chart (the JSON writes an infinite bound
// as null), distorted beyond the default bounds; --split=scale is echoed and kept too.
BOOST_AUTO_TEST_CASE(charts_within_bounds)
{
  Scratch scratch;
  const mbp_test::Soup strip = mbp_test::strip_around_a_cone(60);
  scratch.write("strip.off", exact_off_text(strip));
  for(const std::string split : {"normals", "scale"})
    BOOST_TEST_CONTEXT(split)
    {
      const Run r = scratch.run({"strip.off", "strip.obj", "--json", "--split=" + split});
      BOOST_REQUIRE_EQUAL(r.code, 0);
      const boost::property_tree::ptree j = parse_json(r.out);
      check_atlas(read_atlas_obj(scratch.work / "strip.obj"), j, strip);
      BOOST_TEST(j.get<std::string>("bounds.split") == split);
      BOOST_TEST(j.get<double>("bounds.max_area_spread") == 0.2);
      BOOST_TEST(j.get<std::size_t>("chart_count") >= 2u);
      BOOST_TEST(j.get<std::size_t>("splits") >= 1u);
      for(const auto& c : j.get_child("charts"))
      {
        BOOST_TEST(c.second.get<double>("area_spread") <= 0.2);
        BOOST_TEST(c.second.get<double>("angle_distortion") <= 0.2);
      }
    }
  const Run one = scratch.run({"strip.off", "one.obj", "--json", "--max-area-spread=inf", "--max-angle-distortion=inf",
                               "--min-compactness=0", "--svg=one.svg"});
  BOOST_REQUIRE_EQUAL(one.code, 0);
  const boost::property_tree::ptree j = parse_json(one.out);
  BOOST_TEST(j.get<std::size_t>("chart_count") == 1u);
  BOOST_TEST(j.get<std::string>("bounds.max_area_spread") == "null");
  // without bounds the picture colors each polygon by its own area distortion
  BOOST_TEST(contains(Scratch::read_text(scratch.work / "one.svg"), "area distortion per polygon"));
  const boost::property_tree::ptree& chart = j.get_child("charts").begin()->second;
  BOOST_TEST((chart.get<double>("area_spread") > 0.2 || chart.get<double>("angle_distortion") > 0.2),
             "the one chart is within the default bounds: area spread " << chart.get<double>("area_spread")
                                                                         << ", angle distortion "
                                                                         << chart.get<double>("angle_distortion"));
  const Run summary = scratch.run({"strip.off", "summary.obj", "--max-area-spread=0.3"});
  BOOST_REQUIRE_EQUAL(summary.code, 0);
  BOOST_TEST(contains(summary.out, "| bounds: area spread <= 0.3 (largest "), summary.out);
}

// With --single-chart the two bounds rank the automatic border's layouts: the spiral ramp's
// conformal polygon overlaps itself, so the conformal-lengths member is tried; by angle alone
// it is kept, and the kept layout has the lowest rank of the bound (Distortion_bound, an
// independent computation from the JSON's figures) whatever the bound.
BOOST_AUTO_TEST_CASE(single_chart_bounds_rank_the_automatic_border)
{
  Scratch scratch;
  scratch.write("ramp.off", exact_off_text(mbp_test::spiral_ramp()));
  const double inf = std::numeric_limits<double>::infinity();
  for(const auto& bound : {std::array<std::string, 2>{"inf", "inf"}, {"0.2", "0.2"}, {"inf", "0.01"}})
    BOOST_TEST_CONTEXT(bound[0] << ", " << bound[1])
    {
      const Run r = scratch.run({"ramp.off", "ramp.obj", "--json", "--single-chart",
                                 "--max-angle-distortion=" + bound[0], "--max-area-spread=" + bound[1]});
      BOOST_REQUIRE_EQUAL(r.code, 0);
      const boost::property_tree::ptree j = parse_json(r.out);
      const SMP::Distortion_bound b{bound[0] == "inf" ? inf : std::stod(bound[0]),
                                    bound[1] == "inf" ? inf : std::stod(bound[1])};
      const auto rank = [&](const boost::property_tree::ptree& c) {
        return c.get<bool>("valid") ? b.rank(c.get<double>("angle_distortion"), c.get<double>("area_spread")) : inf;
      };
      const double kept = rank(j.get_child("border_choice.chosen"));
      bool lengths = false;
      for(const auto& c : j.get_child("border_choice.candidates"))
      {
        BOOST_TEST(kept <= rank(c.second));
        lengths = lengths || c.second.get<std::string>("kind") == "conformal-lengths";
      }
      BOOST_TEST(lengths);
      if(bound[0] == "inf" && bound[1] == "inf")
        BOOST_TEST(j.get<std::string>("border_choice.chosen.kind") == "conformal-lengths");
    }
}

BOOST_AUTO_TEST_CASE(default_run_is_an_atlas)
{
  // no option: the atlas; the grid is a disk: one chart
  Mesh grid;
  {
    std::istringstream in(grid_off);
    BOOST_REQUIRE(CGAL::IO::read_OFF(in, grid));
  }
  Scratch scratch;
  scratch.write("grid.off", grid_off);
  const Run r = scratch.run({"grid.off", "--json"});
  BOOST_REQUIRE_EQUAL(r.code, 0);
  BOOST_TEST((scratch.files() == std::set<std::string>{"grid.off", "grid_uv.obj"}));
  const boost::property_tree::ptree j = parse_json(r.out);
  mbp_test::Soup soup;
  for(vertex_descriptor v : vertices(grid))
    soup.points.push_back({grid.point(v).x(), grid.point(v).y(), grid.point(v).z()});
  for(auto f : faces(grid))
  {
    soup.faces.emplace_back();
    for(vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, grid), grid))
      soup.faces.back().push_back(std::size_t(v));
  }
  const Atlas_obj atlas = read_atlas_obj(scratch.work / "grid_uv.obj");
  BOOST_TEST(check_atlas(atlas, j, soup) == 1u);
  BOOST_TEST(atlas.groups == 1u);
  BOOST_TEST(j.get_child("charts").begin()->second.get<std::string>("flattening") == "disk");
  BOOST_TEST(j.get<std::string>("repair.merged_points") == "0");
  // the summary: charts, utilization, repairs, time
  const Run s = scratch.run({"grid.off", "summary.obj"});
  BOOST_REQUIRE_EQUAL(s.code, 0);
  BOOST_TEST(std::count(s.out.begin(), s.out.end(), '\n') == 1);
  for(const char* part : {"grid.off: 9 points, 8 polygons", "| 1 chart, utilization ", "(1024 texels, gutter 2)",
                          "| repairs: none", "| seconds: repair ", "total ", "| wrote summary.obj"})
    BOOST_TEST(contains(s.out, part), part << " not in " << s.out);

  // --single-chart, or an option of that mode, keeps the single chart of before: one UV per
  // vertex, the same OBJ with --single-chart as with --border=auto
  for(const std::string option : {"--single-chart", "--border=auto", "--border=measured"})
    BOOST_TEST_CONTEXT(option)
    {
      const Run o = scratch.run({"grid.off", option.substr(2) + ".obj", option, "--json"});
      BOOST_REQUIRE_EQUAL(o.code, 0);
      BOOST_TEST(parse_json(o.out).get<std::string>("mode") == "single-chart");
      check_obj_against_mesh(read_obj(scratch.work / (option.substr(2) + ".obj")), grid);
    }
  BOOST_TEST(Scratch::read_text(scratch.work / "single-chart.obj") == Scratch::read_text(scratch.work / "border=auto.obj"));

  // no INPUT: the default mesh, a disk, is one chart
  {
    Scratch d;
    Mesh mesh;
    mbp_test::read_mesh(default_mesh_path(), mesh);
    const Run m = d.run({"--json"});
    BOOST_REQUIRE_EQUAL(m.code, 0);
    const boost::property_tree::ptree mj = parse_json(m.out);
    BOOST_TEST(mj.get<std::string>("mode") == "atlas");
    BOOST_TEST(mj.get<std::size_t>("chart_count") == 1u);
    BOOST_TEST(mj.get<std::size_t>("polygons") == num_faces(mesh));
    const std::string obj_name = fs::path(default_mesh_path()).stem().string() + "_uv.obj";
    BOOST_TEST((d.files() == std::set<std::string>{obj_name}));
    BOOST_TEST(read_atlas_obj(d.work / obj_name).vt.size() == 3 * num_faces(mesh));
  }
  // the generated curved disk too
  Scratch generated;
  const Run g = generated.run({"--json"}, MBP_CLI_NO_DEFAULT_MESH_PROGRAM);
  BOOST_REQUIRE_EQUAL(g.code, 0);
  const boost::property_tree::ptree gj = parse_json(g.out);
  BOOST_TEST(gj.get<bool>("generated_mesh"));
  BOOST_TEST(gj.get<std::size_t>("chart_count") == 1u);
  const Atlas_obj disk = read_atlas_obj(generated.work / "curved_disk_uv.obj");
  BOOST_TEST(disk.f.size() == gj.get<std::size_t>("polygons"));
  BOOST_TEST(overlapping_chart_pairs(disk) == 0u);
}

BOOST_AUTO_TEST_CASE(atlas_options_and_failures)
{
  mbp_test::Soup two = mbp_test::grid(3);
  mbp_test::append(two, mbp_test::square(5.));
  // --resolution and --gutter: in the JSON, the OBJ header and the summary
  {
    Scratch scratch;
    scratch.write("two.off", exact_off_text(two));
    const Run r = scratch.run({"two.off", "out.obj", "--json", "--resolution=256", "--gutter=4", "--atlas"});
    BOOST_REQUIRE_EQUAL(r.code, 0);
    const boost::property_tree::ptree j = parse_json(r.out);
    BOOST_TEST(j.get<int>("resolution") == 256);
    BOOST_TEST(j.get<int>("gutter") == 4);
    const Atlas_obj obj = read_atlas_obj(scratch.work / "out.obj");
    check_atlas(obj, j, two);
    BOOST_TEST(contains(Scratch::read_text(scratch.work / "out.obj"), "(256 texels, gutter 4)"));
    // the gutter kept to the border of the square: 4 texels of 1/256
    std::size_t in_gutter = 0;
    for(const auto& q : obj.vt)
      for(double x : q)
        in_gutter += (x >= 4. / 256. - 1e-9 && x <= 1. - 4. / 256. + 1e-9) ? 0 : 1;
    BOOST_TEST(in_gutter == 0u, in_gutter << " UV coordinates within 4 texels of the border");
  }
  // coordinates so large (or small) that squared lengths overflow (or underflow): an atlas all
  // the same, the OBJ with the input's coordinates, the texel density in the input's unit
  {
    Scratch scratch;
    scratch.write("unit.off", exact_off_text(two));
    const Run u = scratch.run({"unit.off", "unit.obj", "--json"});
    BOOST_REQUIRE_EQUAL(u.code, 0);
    const double density = parse_json(u.out).get<double>("texel_density");
    for(const double scale : {1e300, 1e-300})
      BOOST_TEST_CONTEXT("scale " << scale)
      {
        mbp_test::Soup scaled = two;
        for(auto& p : scaled.points)
          for(double& x : p)
            x *= scale;
        scratch.write("scaled.off", exact_off_text(scaled));
        const Run r = scratch.run({"scaled.off", "scaled.obj", "--json"});
        BOOST_REQUIRE_EQUAL(r.code, 0);
        const boost::property_tree::ptree j = parse_json(r.out);
        check_atlas(read_atlas_obj(scratch.work / "scaled.obj"), j, scaled);
        BOOST_TEST(std::abs(j.get<double>("texel_density") * scale / density - 1.) < 0.02);  // the packing's search
      }
  }
  // command-line errors: exit 2, the message, no file
  const std::vector<std::pair<std::vector<std::string>, std::string> > usage = {
    {{"two.off", "--atlas", "--border=measured"}, "option --atlas cannot be combined with --border"},
    {{"two.off", "--atlas", "--single-chart"}, "option --atlas cannot be combined with --single-chart"},
    {{"two.off", "--single-chart", "--resolution=512"}, "option --resolution (of the atlas) cannot be combined with --single-chart"},
    {{"two.off", "--gutter=1", "--seams=s.txt"}, "option --gutter (of the atlas) cannot be combined with --seams"},
    {{"two.off", "--resolution=7"}, "value 7 of --resolution is out of range (expected a whole number from 8 to 65536)"},
    {{"two.off", "--resolution=1k"}, "bad value '1k' of --resolution"},
    {{"two.off", "--gutter=-1"}, "bad value '-1' of --gutter"},
    {{"two.off", "--resolution=64", "--gutter=17"}, "--gutter=17 is too wide for --resolution=64 (at most 16 texels"},
    {{"two.off", "--resolution"}, "option --resolution needs a value"},
    {{"two.off", "--atlas=yes"}, "option --atlas takes no value"},
    {{"two.off", "--single-chart", "--single-chart"}, "option --single-chart is given twice"},
    {{"two.off", "--max-area-spread=-1"}, "value -1 of --max-area-spread is out of range (expected a number from 0 to inf)"},
    {{"two.off", "--max-angle-distortion=nan"}, "bad value 'nan' of --max-angle-distortion"},
    {{"two.off", "--max-area-spread=0.1x"}, "bad value '0.1x' of --max-area-spread"},
    {{"two.off", "--min-compactness=2"}, "value 2 of --min-compactness is out of range (expected a number from 0 to 1)"},
    {{"two.off", "--split=curvature"}, "unknown value 'curvature' of --split (expected normals or scale)"},
    {{"two.off", "--single-chart", "--min-compactness=0.1"},
     "option --min-compactness (of the atlas) cannot be combined with --single-chart"},
    {{"two.off", "--border=measured", "--max-area-spread=0.1"},
     "option --max-area-spread bounds the atlas's charts, or ranks the layouts of --border=auto: it cannot be combined "
     "with --border=measured"},
  };
  for(const auto& u : usage)
    BOOST_TEST_CONTEXT(u.first.back())
    {
      Scratch scratch;
      scratch.write("two.off", exact_off_text(two));
      const Run r = scratch.run(u.first);
      BOOST_TEST(r.code == 2);
      BOOST_TEST(contains(r.err, "error: " + u.second), r.err);
      BOOST_TEST((scratch.files() == std::set<std::string>{"two.off"}));
    }
  // inputs that cannot be textured: exit 1, a message naming the problem, no file; with
  // --json the same error on stdout
  std::string nan_grid = grid_off;
  nan_grid.replace(nan_grid.find("1 1 0.3"), 7, "nan 1 0.3");
  mbp_test::Soup flat;  // polygons of no area: a segment, a repeated point
  flat.points = {{{0., 0., 0.}}, {{1., 0., 0.}}, {{2., 0., 0.}}};
  flat.faces = {{0, 1, 2}, {1, 1, 1}, {0, 2}};
  mbp_test::Soup many;  // 100 separate triangles: more charts than 8 x 8 texels hold with a gutter of 2
  for(std::size_t t = 0; t < 100; ++t)
  {
    many.points.push_back({{3. * double(t), 0., 0.}});
    many.points.push_back({{3. * double(t) + 1., 0., 0.}});
    many.points.push_back({{3. * double(t), 1., 0.}});
    many.faces.push_back({3 * t, 3 * t + 1, 3 * t + 2});
  }
  struct Failure_case
  {
    std::string name, file, contents;
    std::vector<std::string> args, messages;
    int error_code;  // the library's Error_code in the JSON, 0: null
  };
  const std::vector<Failure_case> failures = {
    {"empty file", "empty.off", "", {}, {"empty.off: the file is empty"}, 0},
    {"no polygon", "points.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n", {}, {"points.off: ", "it has no faces (3 vertices)"},
     int(SMP::ERROR_EMPTY_MESH)},
    {"NaN coordinate (text)", "nan.off", nan_grid, {}, {"non-finite", "'nan'", "line 7"}, int(SMP::ERROR_NON_FINITE_COORDINATES)},
    {"NaN coordinate (binary)", "nan.ply", binary_ply_with_nan(), {}, {"non-finite", "vertex 4"},
     int(SMP::ERROR_NON_FINITE_COORDINATES)},
    {"polygons of no area", "flat.obj", obj_text(flat), {},
     {"no polygon has three distinct points and a nonzero area (3 polygons)"}, int(SMP::ERROR_EMPTY_MESH)},
    {"charts that do not fit", "many.off", exact_off_text(many), {"--resolution=8", "--gutter=2"},
     {"the charts do not fit into a texture of 8 x 8 texels with a gutter of 2 texels"}, int(SMP::ERROR_WRONG_PARAMETER)},
  };
  for(const Failure_case& c : failures)
    BOOST_TEST_CONTEXT(c.name)
    {
      Scratch scratch;
      scratch.write(c.file, c.contents);
      std::vector<std::string> args{c.file, "out.obj", "--svg=out.svg"};
      args.insert(args.end(), c.args.begin(), c.args.end());
      const Run r = scratch.run(args);
      BOOST_TEST(r.code == 1);
      for(const std::string& m : c.messages)
        BOOST_TEST(contains(r.err, m), "'" << m << "' not in: " << r.err);
      BOOST_TEST(r.out.empty());
      BOOST_TEST((scratch.files() == std::set<std::string>{c.file}));
      args.push_back("--json");
      const Run jr = scratch.run(args);
      BOOST_TEST(jr.code == 1);
      const boost::property_tree::ptree j = parse_json(jr.out);
      BOOST_TEST(j.get<std::string>("error") == error_message(jr.err));
      BOOST_TEST(j.get<std::string>("error_code") == (c.error_code == 0 ? std::string("null") : std::to_string(c.error_code)));
      BOOST_TEST((scratch.files() == std::set<std::string>{c.file}));
    }
}

MBP_TIERED_TEST_CASE(messy_real_meshes_get_an_atlas)
{
  // the meshes --single-chart refuses (messy_real_meshes_fail_cleanly) get an atlas: several
  // components, a non-manifold vertex. Core tier: CGAL's data meshes; extended tier: the
  // project's ogre (45 components) and five of the meshes of issue 22 (../atlas beside the
  // project's meshes: components, non-manifold edges, a binary STL with a face using a vertex
  // twice, polygons, a Moebius strip).
  const std::vector<std::string> names = (tier == mbp_test::Tier::core)
    ? std::vector<std::string>{"mask_cone.off", "polygon_mesh.off"}
    : std::vector<std::string>{"ogre.obj", "../atlas/Gravgen.obj", "../atlas/cycloidal.ply",
                               "../atlas/Spider_binary.stl", "../atlas/lion_vase_poly.off", "../atlas/moebius.obj"};
  for(const std::string& name : names)
    BOOST_TEST_CONTEXT("mesh: " << name)
    {
      const std::string path = name.rfind("../", 0) == 0 ? mbp_test::shared_mesh_dir() + "/" + name
                                                         : mbp_test::tier_mesh(tier, name);
      std::vector<K::Point_3> points;
      mbp_test::Soup soup;
      BOOST_REQUIRE(CGAL::IO::read_polygon_soup(path, points, soup.faces));
      for(const K::Point_3& p : points)
        soup.points.push_back({p.x(), p.y(), p.z()});
      Scratch scratch;
      const Run r = scratch.run({path, "out.obj", "--svg=out.svg", "--json"});
      BOOST_REQUIRE_EQUAL(r.code, 0);
      const boost::property_tree::ptree j = parse_json(r.out);
      const std::size_t charts = check_atlas(read_atlas_obj(scratch.work / "out.obj"), j, soup);
      BOOST_TEST_MESSAGE(name << ": " << charts << " charts, utilization " << j.get<double>("utilization"));
      BOOST_TEST(contains(Scratch::read_text(scratch.work / "out.svg"), "chart outlines (" + std::to_string(charts) + ")"));
    }
}

// ---------------------------------------------------------------- the batch mode (issue 24)

namespace {

// The lines of a batch report, parsed, by input.
std::map<std::string, boost::property_tree::ptree> read_report(const fs::path& path)
{
  std::map<std::string, boost::property_tree::ptree> lines;
  std::ifstream in(path);
  BOOST_REQUIRE_MESSAGE(in.good(), "cannot open " << path);
  std::string line;
  while(std::getline(in, line))
  {
    const boost::property_tree::ptree json = parse_json(line);
    BOOST_TEST(lines.count(json.get<std::string>("input")) == 0u, "two lines for " << json.get<std::string>("input"));
    lines[json.get<std::string>("input")] = json;
  }
  return lines;
}

// A line appended to the outputs of a batch: a run that writes an output again replaces the
// file, and the line is gone. (Inode numbers would not do: a freed inode is reused.)
const std::string not_rewritten = "# not written again\n";

void mark(const fs::path& path)
{
  std::ofstream out(path, std::ios::app | std::ios::binary);
  out << not_rewritten;
  BOOST_REQUIRE(out.good());
}

bool marked(const fs::path& path)
{
  const std::string text = Scratch::read_text(path);
  return text.size() >= not_rewritten.size() &&
         text.compare(text.size() - not_rewritten.size(), not_rewritten.size(), not_rewritten) == 0;
}

// Generated disks of different shapes, written as OFF into `folder` ("disk_K.off").
std::vector<std::string> write_generated_disks(const Scratch& scratch, const std::string& folder, int count)
{
  fs::create_directories(scratch.work / folder);
  std::vector<std::string> names;
  for(int k = 0; k < count; ++k)
  {
    const mbp_test::Soup soup = (k % 3 == 0)   ? mbp_test::polar_disk(4 + k % 4, 14 + 2 * k, 1., 0.6 + 0.05 * k)
                                : (k % 3 == 1) ? mbp_test::bumpy_disk(4 + k % 3, 16 + k)
                                               : mbp_test::hex_disk(3 + k % 3, 1., 0.8);
    names.push_back("disk_" + std::to_string(k) + ".off");
    scratch.write(folder + "/" + names.back(), off_text(soup));
  }
  return names;
}

} // namespace

// A batch over generated meshes, one of them unreadable and the worker of another killed
// (SIGKILL, sent by the batch itself when MBP_CLI_TEST_KILL_INPUT names the input: the test
// aid of cli/batch.cpp): every other mesh is done, each failure is reported on its own line;
// a second run skips what is done (the outputs are not written again) and redoes the
// failures; --force redoes everything.
BOOST_AUTO_TEST_CASE(batch_reports_every_mesh_and_resumes)
{
  Scratch scratch;
  const std::vector<std::string> good = write_generated_disks(scratch, "in", 4);
  scratch.write("in/bad.off", "OFF\nthis is not a mesh\n");
  scratch.write("in/killed.off", off_text(mbp_test::polar_disk(5, 16, 1., 0.7)));
  scratch.write("in/notes.txt", "not an input: not a mesh file name");
  const std::vector<std::string> batch{"--batch=in", "--output-dir=out", "--jobs=2"};

  ::setenv("MBP_CLI_TEST_KILL_INPUT", "killed.off", 1);
  const Run first = scratch.run(batch);
  ::unsetenv("MBP_CLI_TEST_KILL_INPUT");
  BOOST_TEST(first.code == 1);  // a mesh failed, the batch went on
  BOOST_TEST(contains(first.out, "6 meshes: 4 done, 0 skipped, 2 failed"), first.out);
  std::map<std::string, boost::property_tree::ptree> report = read_report(scratch.work / "out/report.jsonl");
  BOOST_TEST(report.size() == 6u);
  for(const std::string& name : good)
  {
    const boost::property_tree::ptree& line = report["in/" + name];
    BOOST_TEST(line.get<std::string>("status") == "OK", name);
    const std::string output = "out/" + fs::path(name).stem().string() + "_uv.obj";
    BOOST_TEST(line.get_child("outputs").size() == 1u);
    BOOST_TEST(line.get_child("outputs").front().second.get_value<std::string>() == output);
    BOOST_TEST(line.get<std::string>("figures.mode") == "atlas");
    BOOST_TEST(line.get<double>("seconds") > 0.);
    const Obj obj = read_obj(scratch.work / output, true);
    BOOST_TEST(obj.v.size() == line.get<std::size_t>("figures.points"));
    BOOST_TEST(obj.vt.size() == 3 * obj.f.size());  // a UV per corner
    mark(scratch.work / output);
  }
  BOOST_TEST(report["in/bad.off"].get<std::string>("status") == "FAILED");
  BOOST_TEST(contains(report["in/bad.off"].get<std::string>("message"), "cannot read"));
  BOOST_TEST(report["in/killed.off"].get<std::string>("status") == "FAILED");
  BOOST_TEST(contains(report["in/killed.off"].get<std::string>("message"), "killed by signal 9"));
  BOOST_TEST(report["in/killed.off"].get_child("outputs").empty());
  BOOST_TEST(!fs::exists(scratch.work / "out/bad_uv.obj"));
  BOOST_TEST(!fs::exists(scratch.work / "out/killed_uv.obj"));
  BOOST_TEST(contains(first.err, "killed.off: the worker was killed by signal 9"));

  // the second run: the four done are skipped (their files are not republished), the killed
  // one is done, the unreadable one fails again
  const Run second = scratch.run(batch);
  BOOST_TEST(second.code == 1);
  BOOST_TEST(contains(second.out, "6 meshes: 1 done, 4 skipped, 1 failed"), second.out);
  report = read_report(scratch.work / "out/report.jsonl");
  BOOST_TEST(report.size() == 6u);
  for(const std::string& name : good)
    BOOST_TEST(marked(scratch.work / ("out/" + fs::path(name).stem().string() + "_uv.obj")), name << " was written again");
  BOOST_TEST(report["in/killed.off"].get<std::string>("status") == "OK");
  BOOST_TEST(fs::exists(scratch.work / "out/killed_uv.obj"));
  BOOST_TEST(report["in/bad.off"].get<std::string>("status") == "FAILED");

  // a done mesh whose output was removed is done again; --force redoes every mesh
  fs::remove(scratch.work / ("out/" + fs::path(good[0]).stem().string() + "_uv.obj"));
  BOOST_TEST(contains(scratch.run(batch).out, "6 meshes: 1 done, 4 skipped, 1 failed"));
  std::vector<std::string> forced = batch;
  forced.push_back("--force");
  BOOST_TEST(contains(scratch.run(forced).out, "6 meshes: 5 done, 0 skipped, 1 failed"));
  for(const std::string& name : good)
    BOOST_TEST(!marked(scratch.work / ("out/" + fs::path(name).stem().string() + "_uv.obj")), name << " was not redone");
  BOOST_TEST(read_report(scratch.work / "out/report.jsonl").size() == 6u);
}

// --shard=I/N: the slices partition the sorted inputs (input K in slice K mod N + 1), the
// union of their outputs is the unsharded run's, byte for byte; a list file (in any order,
// with comments and empty lines) or the same list on stdin gives the same slices as the folder.
BOOST_AUTO_TEST_CASE(batch_shards_partition_the_inputs)
{
  Scratch scratch;
  std::vector<std::string> names = write_generated_disks(scratch, "in", 7);
  std::sort(names.begin(), names.end());
  const Run all = scratch.run({"--batch=in", "--output-dir=all", "--jobs=2"});
  BOOST_REQUIRE_EQUAL(all.code, 0);
  BOOST_TEST(contains(all.out, "7 meshes: 7 done"));
  std::set<std::string> seen;
  for(int i = 1; i <= 3; ++i)
  {
    const std::string dir = "shard" + std::to_string(i), shard = "--shard=" + std::to_string(i) + "/3";
    const Run r = scratch.run({"--batch=in", "--output-dir=" + dir, shard});
    BOOST_REQUIRE_EQUAL(r.code, 0);
    const std::map<std::string, boost::property_tree::ptree> report =
      read_report(scratch.work / dir / ("report-shard-" + std::to_string(i) + "-of-3.jsonl"));
    std::set<std::string> expected;
    for(std::size_t k = i - 1; k < names.size(); k += 3)
      expected.insert("in/" + names[k]);
    std::set<std::string> got;
    for(const auto& line : report)
      got.insert(line.first);
    BOOST_TEST((got == expected), shard);
    for(const std::string& input : got)
    {
      BOOST_TEST(seen.insert(input).second, input << " is in two slices");
      const std::string obj = fs::path(input).stem().string() + "_uv.obj";
      BOOST_TEST(Scratch::read_text(scratch.work / dir / obj) == Scratch::read_text(scratch.work / "all" / obj),
                 obj << " differs from the unsharded run");
    }
  }
  BOOST_TEST(seen.size() == names.size());

  std::string list = "# the inputs, shuffled\n\n";
  for(std::size_t k = names.size(); k-- > 0;)
    list += "in/" + names[k] + "\n";
  scratch.write("list.txt", list);
  const Run listed = scratch.run({"--batch=list.txt", "--output-dir=listed", "--shard=2/3"});
  BOOST_REQUIRE_EQUAL(listed.code, 0);
  std::set<std::string> from_list;
  for(const auto& line : read_report(scratch.work / "listed/report-shard-2-of-3.jsonl"))
    from_list.insert(fs::path(line.first).filename().string());
  BOOST_TEST((from_list == std::set<std::string>{names[1], names[4]}));

  // the same list on stdin (--batch=-): relative paths from the working directory
  scratch.standard_input = scratch.work / "list.txt";
  const Run piped = scratch.run({"--batch=-", "--output-dir=piped", "--shard=3/3"});
  scratch.standard_input.clear();
  BOOST_REQUIRE_EQUAL(piped.code, 0);
  std::set<std::string> from_stdin;
  for(const auto& line : read_report(scratch.work / "piped/report-shard-3-of-3.jsonl"))
    from_stdin.insert(fs::path(line.first).filename().string());
  BOOST_TEST((from_stdin == std::set<std::string>{names[2], names[5]}));
}

// Wrong batch options: a specific message, exit status 2, no output folder.
BOOST_AUTO_TEST_CASE(batch_option_errors)
{
  Scratch scratch;
  write_generated_disks(scratch, "in", 1);
  fs::create_directories(scratch.work / "empty");
  const std::vector<std::pair<std::vector<std::string>, std::string> > cases = {
    {{"--batch=missing", "--output-dir=out"}, "--batch=missing: no such folder or list file"},
    {{"--batch=empty", "--output-dir=out"}, "--batch=empty: no input"},
    {{"--batch=in", "--output-dir=out", "--shard=4/3"}, "slice 4 of 3 does not exist"},
    {{"--batch=in", "--output-dir=out", "--shard=0/3"}, "bad value '0/3' of --shard"},
    {{"--batch=in", "--output-dir=out", "--shard=2"}, "bad value '2' of --shard"},
    {{"--batch=in", "--output-dir=out", "--jobs=0"}, "value 0 of --jobs is out of range"},
    {{"--batch=in"}, "--batch needs --output-dir=DIR"},
    {{"--output-dir=out", "--jobs=2"}, "option --output-dir is an option of the batch mode"},
    {{"in/disk_0.off", "--force"}, "option --force is an option of the batch mode"},
    {{"--batch=in", "--output-dir=out", "in/disk_0.off"}, "--batch takes no INPUT or OUTPUT argument"},
    {{"--batch=in", "--output-dir=out", "--svg=x.svg"}, "option --svg names the file of one run"},
    {{"--batch=in", "--output-dir=out", "--json"}, "option --json cannot be combined with --batch"},
    {{"--batch=in", "--output-dir=in"}, "is the input folder"},
    {{"--batch=in", "--output-dir=out", "--threads=300"}, "value 300 of --threads is out of range"}};
  for(const auto& c : cases)
  {
    const Run r = scratch.run(c.first);
    BOOST_TEST(r.code == 2, c.second);
    BOOST_TEST(contains(r.err, c.second), "expected '" << c.second << "' in: " << r.err);
    BOOST_TEST(!fs::exists(scratch.work / "out"), c.second);
    BOOST_TEST(!fs::exists(scratch.work / "in/report.jsonl"));
  }
}

// --threads=N sets the BLAS threads under CHOLMOD and, from 2 on, the package's own threads
// (CGAL::Parallel_tag): the UVs do not depend on it.
BOOST_AUTO_TEST_CASE(threads_give_the_same_uvs)
{
  Scratch scratch;
  scratch.write("disk.off", off_text(mbp_test::bumpy_disk(14, 48)));
#ifdef MBP_CLI_HAS_CHOLMOD
  const std::string solver = "--solver=cholmod";
#else
  const std::string solver = "--solver=ldlt";
#endif
  std::vector<Obj> objs;
  for(const std::string threads : {"", "--threads=1", "--threads=2", "--threads=0"})
  {
    std::vector<std::string> args{"disk.off", "out.obj", solver};
    if(!threads.empty())
      args.push_back(threads);
    const Run r = scratch.run(args);
    BOOST_REQUIRE_MESSAGE(r.code == 0, threads << ": " << r.err);
    objs.push_back(read_obj(scratch.work / "out.obj"));
  }
  for(std::size_t k = 1; k < objs.size(); ++k)
  {
    BOOST_REQUIRE_EQUAL(objs[k].vt.size(), objs[0].vt.size());
    double worst = 0.;
    for(std::size_t i = 0; i < objs[0].vt.size(); ++i)
      worst = (std::max)(worst, std::hypot(objs[k].vt[i][0] - objs[0].vt[i][0], objs[k].vt[i][1] - objs[0].vt[i][1]));
    BOOST_TEST(worst <= 1e-12, "run " << k << ": largest UV difference from the default " << worst);
  }
}

BOOST_AUTO_TEST_SUITE_END()
