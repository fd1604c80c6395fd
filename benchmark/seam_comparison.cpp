// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// Automatic seams (issue 16): every mesh that is not a disk, cut by compute_disk_seams() and
// flattened by the measured conformal parameterizer, against Boundary First Flattening's
// command line with the same number of cones.
//
//   seam_comparison [--meshes=DIR] [--bff=PROGRAM] [--only=NAME] [--sweep] [--work=DIR]
//                   [--border=conformal|automatic]
//
// The cut mesh is flattened by Conformal_parameterizer_3 with the conformal border (BFF's border
// with scale factor 0 on the border; default) or the automatic border.
// Meshes: the rows of DIR/PROVENANCE.md (default: ../shared/data/meshes, as configured) of the
// classes CLOSED, HOLES, OPEN g>0 (flattened) and MESSY (they must get a named error).
// --sweep: instead, on the closed meshes of genus 0, the figures for 2 to 16 cones (the
// measurement behind Disk_seams_options::default_number_of_cones).
//
// Figures of a flattening, all on the cut mesh (seam vertices are border vertices):
//   seam length   total 3D length of the seam edges (BFF: the cut edges of its output, the
//                 border edges of its UV mesh that are interior edges of the input), divided
//                 by sqrt(3D area) so that meshes compare
//   angle         the paper's angle distortion (measure_quality.h; user manual: Measuring a parameterization)
//   area          the area-weighted standard deviation of log(A_uv / A_3D) over the faces:
//                 sqrt(sum_T A_T (l_T - m)^2 / sum_T A_T), l_T = log(A_uv,T / A_3D,T),
//                 m = sum_T A_T l_T / sum_T A_T. A global scale of the layout adds a constant
//                 to every l_T, so the figure needs no normalization; 0 for a map that scales
//                 every face alike, and exp(area) is the typical factor of area change
//   flips         faces of signed UV area <= 0
//   overlap       whether two UV triangles overlap (is_one_to_one_uv_map)
//   time          ours: seams + flattening, in process; BFF: the whole process (reading the
//                 OBJ, cutting, flattening, writing the OBJ)
// BFF reads OBJ only: each mesh is written as OBJ (vertices in file order) and BFF's output
// OBJ is read back (one vertex per 'vt', the 3D point of its 'v') and measured by the same
// code. BFF is run with --nCones=N, N the number of cones of our cut; BFF raises N to 8 on a
// closed surface of genus 0 when N < 3 and says so, and the table shows the count it used.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Seam_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <CGAL/Surface_mesh_parameterization/Conformal_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/compute_disk_seams.h>
#include <CGAL/Surface_mesh_parameterization/measure_quality.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#ifndef MBP_MESH_DIR
#define MBP_MESH_DIR ""
#endif
#ifndef MBP_BFF_PROGRAM
#define MBP_BFF_PROGRAM ""
#endif

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace fs = std::filesystem;
typedef CGAL::Simple_cartesian<double>                               K;
typedef CGAL::Surface_mesh<K::Point_3>                               Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor                 vertex_descriptor;
typedef boost::graph_traits<Mesh>::halfedge_descriptor               halfedge_descriptor;
typedef boost::graph_traits<Mesh>::edge_descriptor                   edge_descriptor;
typedef boost::graph_traits<Mesh>::face_descriptor                   face_descriptor;
typedef Mesh::Property_map<edge_descriptor, bool>                    Seam_edge_map;
typedef Mesh::Property_map<vertex_descriptor, bool>                  Seam_vertex_map;
typedef CGAL::Seam_mesh<Mesh, Seam_edge_map, Seam_vertex_map>        Seam_mesh;
typedef std::chrono::steady_clock                                    Clock;

namespace {

// The border policy of the flattening (--border=): Conformal_border or Automatic_border<>.
enum class Border
{
  conformal,
  automatic
};

double seconds_since(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

struct Figures
{
  std::string error;  // empty on success
  std::size_t seam_edges = 0;
  double seam_length = 0.;  // divided by sqrt(3D area)
  int cones = 0;
  double angle = 0., area = 0.;
  std::size_t flips = 0;
  bool overlap = false;
  double seconds = 0.;
};

// The area-weighted standard deviation of log(A_uv / A_3D) (header comment).
template <class TriangleMesh, class UVmap>
double log_area_deviation(const TriangleMesh& tm, UVmap uvmap)
{
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor F;
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor H;
  const auto vpm = get(CGAL::vertex_point, tm);
  std::vector<std::pair<double, double> > faces_areas;
  double total = 0., mean = 0.;
  for(F f : faces(tm))
  {
    const H h = halfedge(f, tm);
    const auto a = target(h, tm), b = target(next(h, tm), tm), c = source(h, tm);
    const double a3 = std::sqrt(CGAL::squared_area(get(vpm, a), get(vpm, b), get(vpm, c)));
    const double auv = std::abs(CGAL::area(get(uvmap, a), get(uvmap, b), get(uvmap, c)));
    if(!(a3 > 0.) || !(auv > 0.))
      return std::numeric_limits<double>::infinity();
    faces_areas.emplace_back(a3, std::log(auv / a3));
    total += a3;
    mean += a3 * std::log(auv / a3);
  }
  mean /= total;
  double variance = 0.;
  for(const auto& fa : faces_areas)
    variance += fa.first * (fa.second - mean) * (fa.second - mean);
  return std::sqrt(variance / total);
}

template <class TriangleMesh, class UVmap>
void measure(const TriangleMesh& tm, UVmap uvmap, Figures& out)
{
  const SMP::Parameterization_quality q = SMP::measure_quality(tm, faces(tm), uvmap);
  out.angle = q.angle_distortion;
  out.flips = q.flipped_faces;
  out.overlap = !SMP::is_one_to_one_uv_map(tm, faces(tm), uvmap);
  out.area = log_area_deviation(tm, uvmap);
}

double total_area(const Mesh& mesh)
{
  return CGAL::Polygon_mesh_processing::area(mesh);
}

// ---------------------------------------------------------------- ours

// The flattening of the cut mesh from its longest border with the border policy `border`.
template <class UVmap>
SMP::Error_code flatten(Seam_mesh& sm, Border border, UVmap uv)
{
  const auto bhd = CGAL::Polygon_mesh_processing::longest_border(sm).first;
  if(border == Border::automatic)
    return SMP::parameterize(sm, SMP::Conformal_parameterizer_3<Seam_mesh, SMP::Automatic_border<> >(), bhd, uv);
  return SMP::parameterize(sm, SMP::Conformal_parameterizer_3<Seam_mesh, SMP::Conformal_border>(), bhd, uv);
}

Figures run_ours(Mesh& mesh, const SMP::Disk_seams_options& options, Border border)
{
  Figures f;
  const Clock::time_point start = Clock::now();
  Seam_edge_map seam_edges = mesh.add_property_map<edge_descriptor, bool>("e:seam", false).first;
  Seam_vertex_map seam_vertices = mesh.add_property_map<vertex_descriptor, bool>("v:seam", false).first;
  SMP::Disk_seams_report seams;
  if(SMP::compute_disk_seams(mesh, seam_edges, seam_vertices, options, &seams) != SMP::OK)
    f.error = SMP::disk_seams_problem_message(seams.problem);
  else
  {
    f.seam_edges = seams.number_of_seam_edges;
    f.seam_length = seams.seam_length / std::sqrt(total_area(mesh));
    f.cones = static_cast<int>(seams.cones.size());
    Seam_mesh sm(mesh, seam_edges, seam_vertices);
    sm.set_seam_edges_number(seams.number_of_seam_edges);
    auto uv = get(CGAL::dynamic_vertex_property_t<K::Point_2>(), sm);
    const SMP::Error_code status = flatten(sm, border, uv);
    f.seconds = seconds_since(start);
    if(status != SMP::OK)
      f.error = SMP::get_measured_error_message(status);
    else
      measure(sm, uv, f);
  }
  mesh.remove_property_map(seam_edges);
  mesh.remove_property_map(seam_vertices);
  return f;
}

// ---------------------------------------------------------------- BFF

bool write_obj(const Mesh& mesh, const std::string& path)
{
  std::ofstream out(path);
  out.precision(17);
  std::map<vertex_descriptor, std::size_t> index;
  for(vertex_descriptor v : vertices(mesh))
  {
    index.emplace(v, index.size() + 1);
    out << "v " << mesh.point(v) << "\n";
  }
  for(face_descriptor f : faces(mesh))
  {
    out << "f";
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, mesh), mesh))
      out << " " << index[target(h, mesh)];
    out << "\n";
  }
  return static_cast<bool>(out);
}

// BFF's output: one vertex per 'vt' with the 3D point of its 'v'; the UVs in `uv`; the
// input edges along which it cut, as pairs of 'v' indices.
struct Bff_output
{
  Mesh mesh;
  std::vector<K::Point_2> uv;
  std::set<std::pair<std::size_t, std::size_t> > cut_edges;
};

// The parts of an OBJ file that BFF writes: points, UVs, and faces as (v, vt) per corner.
struct Obj_file
{
  std::vector<K::Point_3> points;
  std::vector<K::Point_2> uv;
  std::vector<std::vector<std::pair<std::size_t, std::size_t> > > faces;
};

// The corners "v/vt" of an 'f' line (0-based); an error message, or empty.
std::string read_face_corners(std::istringstream& ls, Obj_file& obj)
{
  obj.faces.emplace_back();
  for(std::string corner; ls >> corner;)
  {
    std::size_t v = 0, t = 0;
    if(std::sscanf(corner.c_str(), "%zu/%zu", &v, &t) != 2 || v == 0 || t == 0 || v > obj.points.size() ||
       t > obj.uv.size())
      return "unreadable face corner '" + corner + "'";
    obj.faces.back().emplace_back(v - 1, t - 1);
  }
  return std::string();
}

std::string read_obj(const std::string& path, Obj_file& obj)
{
  std::ifstream in(path);
  if(!in)
    return "no output";
  for(std::string line; std::getline(in, line);)
  {
    std::istringstream ls(line);
    std::string tag;
    ls >> tag;
    double x = 0., y = 0., z = 0.;
    if(tag == "v")
    {
      ls >> x >> y >> z;
      obj.points.emplace_back(x, y, z);
    }
    else if(tag == "vt")
    {
      ls >> x >> y;
      obj.uv.emplace_back(x, y);
    }
    else if(tag == "f")
    {
      const std::string error = read_face_corners(ls, obj);
      if(!error.empty())
        return error;
    }
  }
  return std::string();
}

// The cut: the border edges of the UV mesh whose input edge has two faces, as pairs of input
// vertices.
void find_cut_edges(const Obj_file& obj, const std::vector<std::size_t>& point_of, Bff_output& out)
{
  std::map<std::pair<std::size_t, std::size_t>, int> input_edge_uses;  // per input edge
  for(const auto& f : obj.faces)
    for(std::size_t k = 0; k < 3; ++k)
    {
      const std::size_t a = f[k].first, b = f[(k + 1) % 3].first;
      ++input_edge_uses[std::make_pair((std::min)(a, b), (std::max)(a, b))];
    }
  for(halfedge_descriptor h : halfedges(out.mesh))
    if(is_border(h, out.mesh))
    {
      const std::size_t a = point_of[std::size_t(source(h, out.mesh))], b = point_of[std::size_t(target(h, out.mesh))];
      const auto key = std::make_pair((std::min)(a, b), (std::max)(a, b));
      if(input_edge_uses[key] == 2)
        out.cut_edges.insert(key);
    }
}

// BFF's output OBJ as a mesh with one vertex per 'vt' (see Bff_output).
std::string read_bff_obj(const std::string& path, Bff_output& out)
{
  Obj_file obj;
  const std::string error = read_obj(path, obj);
  if(!error.empty())
    return error;
  out.uv = obj.uv;
  std::vector<std::size_t> point_of(obj.uv.size(), std::size_t(-1));
  for(const auto& f : obj.faces)
    for(const auto& c : f)
      point_of[c.second] = c.first;
  std::vector<vertex_descriptor> vertex(obj.uv.size());
  for(std::size_t t = 0; t < obj.uv.size(); ++t)
    vertex[t] = out.mesh.add_vertex(point_of[t] < obj.points.size() ? obj.points[point_of[t]] : K::Point_3(0, 0, 0));
  for(const auto& f : obj.faces)
  {
    if(f.size() != 3)
      return "a face is not a triangle";
    if(out.mesh.add_face(vertex[f[0].second], vertex[f[1].second], vertex[f[2].second]) == Mesh::null_face())
      return "the UV mesh is not manifold";
  }
  find_cut_edges(obj, point_of, out);
  return std::string();
}

Figures run_bff(const Mesh& mesh, int cones, const std::string& program, const fs::path& work, const std::string& name)
{
  Figures f;
  const std::string in = (work / (name + ".in.obj")).string(), out = (work / (name + ".bff.obj")).string(),
                    log = (work / (name + ".bff.log")).string();
  if(!write_obj(mesh, in))
  {
    f.error = "cannot write " + in;
    return f;
  }
  fs::remove(out);
  const std::string command = "'" + program + "' '" + in + "' '" + out + "' --nCones=" + std::to_string(cones) +
                              " > '" + log + "' 2>&1";
  const Clock::time_point start = Clock::now();
  const int code = std::system(command.c_str());
  f.seconds = seconds_since(start);
  f.cones = cones;
  std::ifstream lg(log);
  for(std::string line; std::getline(lg, line);)
    if(line.find("Setting nCones to ") != std::string::npos)
      f.cones = std::atoi(line.c_str() + line.find("Setting nCones to ") + 18);
  if(code != 0)
  {
    f.error = "BFF exit code " + std::to_string(code);
    return f;
  }
  Bff_output result;
  f.error = read_bff_obj(out, result);
  if(!f.error.empty())
    return f;
  auto uv = result.mesh.add_property_map<vertex_descriptor, K::Point_2>("v:uv").first;
  for(vertex_descriptor v : vertices(result.mesh))
    put(uv, v, result.uv[std::size_t(v)]);
  measure(result.mesh, uv, f);
  const std::vector<vertex_descriptor> by_index(vertices(mesh).begin(), vertices(mesh).end());
  double length = 0.;
  for(const auto& e : result.cut_edges)
    length += std::sqrt(CGAL::squared_distance(mesh.point(by_index[e.first]), mesh.point(by_index[e.second])));
  f.seam_edges = result.cut_edges.size();
  f.seam_length = length / std::sqrt(total_area(mesh));
  return f;
}

// ---------------------------------------------------------------- table

struct Entry
{
  std::string name, mesh_class;
};

// The meshes of PROVENANCE.md whose class starts with one of `classes`.
std::vector<Entry> provenance(const std::string& dir, const std::vector<std::string>& classes)
{
  std::vector<Entry> entries;
  std::ifstream in(dir + "/PROVENANCE.md");
  for(std::string line; std::getline(in, line);)
  {
    if(line.rfind("| `", 0) != 0)
      continue;
    const std::size_t a = line.find('`') + 1, b = line.find('`', a);
    const std::size_t c = line.find('|', b) + 1, d = line.find('|', c);
    std::string mesh_class = line.substr(c, d - c);
    mesh_class.erase(0, mesh_class.find_first_not_of(' '));
    mesh_class.erase(mesh_class.find_last_not_of(' ') + 1);
    for(const std::string& k : classes)
      if(mesh_class.rfind(k, 0) == 0)
        entries.push_back({line.substr(a, b - a), mesh_class});
  }
  return entries;
}

std::string number(double x, int precision = 3)
{
  if(!std::isfinite(x))
    return "inf";
  std::ostringstream s;
  s << std::setprecision(precision) << x;
  return s.str();
}

std::string cells(const Figures& f)
{
  if(!f.error.empty())
    return f.error + " | | | | | |";
  return std::to_string(f.cones) + " | " + number(f.seam_length) + " | " + number(f.angle) + " | " +
         number(f.area) + " | " + std::to_string(f.flips) + (f.overlap ? " / yes" : " / no") + " | " +
         number(f.seconds, 2);
}

double median(std::vector<double> v)
{
  if(v.empty())
    return std::numeric_limits<double>::quiet_NaN();
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return (n % 2) ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

bool read(const std::string& path, Mesh& mesh)
{
  return CGAL::IO::read_polygon_mesh(path, mesh) && !faces(mesh).empty();
}

struct Arguments
{
  std::string meshes = MBP_MESH_DIR, bff = MBP_BFF_PROGRAM, only;
  fs::path work = fs::temp_directory_path() / "mbp_seam_comparison";
  bool sweep = false;
  Border border = Border::conformal;
};

// The figures of the flattened meshes (holes joined), for the medians.
struct Column
{
  std::vector<double> area, angle, length, time;

  void add(const Figures& f)
  {
    area.push_back(f.area);
    angle.push_back(f.angle);
    length.push_back(f.seam_length);
    time.push_back(f.seconds);
  }
};

struct Medians
{
  Column ours, bff;
  std::vector<double> ratio;  // of the areas, ours / BFF
};

// The option sets a mesh is cut with: the defaults, and for a mesh with holes also the holes
// kept for the virtual filling.
std::vector<std::pair<std::string, SMP::Disk_seams_options> > variants_of(const Entry& e)
{
  const bool holes = e.mesh_class.rfind("HOLES", 0) == 0;
  std::vector<std::pair<std::string, SMP::Disk_seams_options> > variants(1);
  variants[0].first = holes ? "holes joined" : "";
  if(holes)
  {
    variants.emplace_back("virtual filling", SMP::Disk_seams_options());
    variants.back().second.join_holes = false;
  }
  return variants;
}

// The rows of one mesh: ours and BFF's figures for each option set.
void compare_mesh(const Arguments& args, const Entry& e, Mesh& mesh, Medians& medians)
{
  const bool with_bff = !args.bff.empty() && fs::exists(args.bff);
  const bool messy = e.mesh_class.rfind("MESSY", 0) == 0;
  for(const auto& variant : variants_of(e))
  {
    const Figures ours = run_ours(mesh, variant.second, args.border);
    std::cout << "| " << e.name << (variant.first.empty() ? "" : " (" + variant.first + ")") << " | "
              << e.mesh_class << " | " << num_vertices(mesh) << " | " << cells(ours) << " | ";
    Figures bff;
    if(with_bff && ours.error.empty())
    {
      bff = run_bff(mesh, ours.cones, args.bff, args.work, fs::path(e.name).stem().string());
      std::cout << cells(bff) << " |\n";
    }
    else
      std::cout << (messy ? "not run (input error)" : "not run") << " | | | | | |\n";
    if(messy || !ours.error.empty() || variant.first == "virtual filling")
      continue;
    medians.ours.add(ours);
    if(with_bff && bff.error.empty())
    {
      medians.bff.add(bff);
      medians.ratio.push_back(ours.area / bff.area);
    }
  }
}

int comparison(const Arguments& args)
{
  std::cout << "| mesh | class | V | ours: cones | seam length | angle | area | flips / overlap | time (s) |"
            << " BFF: cones | seam length | angle | area | flips / overlap | time (s) |\n"
            << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  Medians m;
  for(const Entry& e : provenance(args.meshes, {"CLOSED", "HOLES", "OPEN g", "MESSY"}))
  {
    if(!args.only.empty() && e.name != args.only)
      continue;
    Mesh mesh;
    if(read(args.meshes + "/" + e.name, mesh))
      compare_mesh(args, e, mesh, m);
    else
      std::cout << "| " << e.name << " | " << e.mesh_class << " | | not readable as a polygon mesh |\n";
  }
  std::cout << "\nMedians over the flattened meshes (holes joined): ours: area " << number(median(m.ours.area))
            << ", angle " << number(median(m.ours.angle)) << ", seam length " << number(median(m.ours.length))
            << ", time " << number(median(m.ours.time), 2) << " s; BFF: area " << number(median(m.bff.area))
            << ", angle " << number(median(m.bff.angle)) << ", seam length " << number(median(m.bff.length))
            << ", time " << number(median(m.bff.time), 2) << " s; median of the area ratio ours/BFF "
            << number(median(m.ratio)) << "\n";
  return EXIT_SUCCESS;
}

// The figures for 2..16 cones on the closed meshes of genus 0.
int sweep(const Arguments& args)
{
  const bool with_bff = !args.bff.empty() && fs::exists(args.bff);
  std::cout << "| mesh | cones | ours: seam length | angle | area | flips / overlap | BFF: cones | seam length | angle"
            << " | area | flips / overlap |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
  for(const Entry& e : provenance(args.meshes, {"CLOSED g=0"}))
  {
    if(!args.only.empty() && e.name != args.only)
      continue;
    Mesh mesh;
    if(!read(args.meshes + "/" + e.name, mesh))
      continue;
    for(int cones : {2, 3, 4, 5, 6, 8, 10, 12, 16})
    {
      SMP::Disk_seams_options options;
      options.number_of_cones = cones;
      const Figures ours = run_ours(mesh, options, args.border);
      std::cout << "| " << e.name << " | " << cones << " | " << number(ours.seam_length) << " | " << number(ours.angle)
                << " | " << number(ours.area) << " | " << ours.flips << (ours.overlap ? " / yes" : " / no") << " | ";
      if(with_bff && cones >= 3)
      {
        const Figures bff = run_bff(mesh, cones, args.bff, args.work, fs::path(e.name).stem().string());
        std::cout << cells(bff).substr(0, cells(bff).rfind('|')) << "|\n";
      }
      else
        std::cout << "| | | | |\n";
    }
  }
  return EXIT_SUCCESS;
}

} // namespace

int main(int argc, char** argv)
{
  Arguments args;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto value = [&a](const std::string& key) { return a.rfind(key, 0) == 0 ? a.substr(key.size()) : std::string(); };
    if(a == "--sweep")
      args.sweep = true;
    else if(!value("--meshes=").empty())
      args.meshes = value("--meshes=");
    else if(!value("--bff=").empty())
      args.bff = value("--bff=");
    else if(!value("--only=").empty())
      args.only = value("--only=");
    else if(!value("--work=").empty())
      args.work = value("--work=");
    else if(a == "--border=automatic")
      args.border = Border::automatic;
    else if(a == "--border=conformal")
      args.border = Border::conformal;
    else
    {
      std::cerr << "usage: seam_comparison [--meshes=DIR] [--bff=PROGRAM] [--only=NAME] [--sweep] [--work=DIR]"
                   " [--border=conformal|automatic]\n";
      return EXIT_FAILURE;
    }
  }
  if(!fs::exists(args.meshes + "/PROVENANCE.md"))
  {
    std::cerr << "error: no PROVENANCE.md in '" << args.meshes << "'\n";
    return EXIT_FAILURE;
  }
  std::error_code ec;
  fs::create_directories(args.work, ec);
  if(args.bff.empty() || !fs::exists(args.bff))
    std::cerr << "note: no BFF program ('" << args.bff << "'): its columns stay empty\n";
  return args.sweep ? sweep(args) : comparison(args);
}
