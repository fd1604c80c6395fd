// The command-line program of the package: flattens a disk-like triangle mesh with the
// measured boundary parameterization of "Measured boundary parameterization based on
// Poisson's equation" (Measured_conformal_parameterizer_3) and writes the UV layout.
//
//   measured_parameterization [INPUT] [OUTPUT.obj] [--center=poisson|vertex:N]
//                             [--distance=poisson] [--solver=cholmod|ldlt]
//                             [--svg=FILE] [--json] [--help]
//
// Reads OFF, OBJ, PLY or STL (default: a real mesh of the project's data, or a generated
// curved disk when that file is missing), maps the longest border, and writes an OBJ with
// one UV per vertex (default: <input file stem>_uv.obj), optionally an SVG picture, and a
// one-line summary or a JSON object with the times, the solver work and the distortion.
// On any failure it says why on stderr, exits with a non-zero status and leaves no output
// file. The library does no IO; this program is the IO layer (helpers in cli/).

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Surface_mesh_parameterization/Fixed_center.h>
#include <CGAL/Surface_mesh_parameterization/Geodesic_border_distance.h>
#include <CGAL/Surface_mesh_parameterization/Geodesic_center_locator.h>
#include <CGAL/Surface_mesh_parameterization/Measured_conformal_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/Poisson_border_distance.h>
#include <CGAL/Surface_mesh_parameterization/Poisson_center_locator.h>
#include <CGAL/Surface_mesh_parameterization/Straightest_geodesic_border_distance.h>
#include <CGAL/Surface_mesh_parameterization/measure_quality.h>
#ifdef MBP_WITH_CHOLMOD
#include <CGAL/Surface_mesh_parameterization/Cholmod_supernodal_cholesky_traits.h>
#endif

#include "cli/mesh_input.h"
#include "cli/options.h"
#include "cli/svg_layout.h"
#include "cli/text_output.h"

#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#ifndef MBP_DEFAULT_MESH
#define MBP_DEFAULT_MESH ""
#endif

typedef CGAL::Simple_cartesian<double>                    Kernel;
typedef Kernel::Point_2                                   Point_2;
typedef Kernel::Point_3                                   Point_3;
typedef CGAL::Surface_mesh<Point_3>                       Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor      vertex_descriptor;
typedef boost::graph_traits<Mesh>::halfedge_descriptor    halfedge_descriptor;
typedef boost::graph_traits<Mesh>::face_descriptor        face_descriptor;
typedef Mesh::Property_map<vertex_descriptor, Point_2>    UV_map;
typedef Mesh::Property_map<vertex_descriptor, bool>       Vertex_flag_map;

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace fs = std::filesystem;
typedef SMP::Heat_method_geodesics<CGAL::Heat_method_3::Direct>             Heat;
typedef SMP::Heat_method_geodesics<CGAL::Heat_method_3::Intrinsic_Delaunay> Heat_idt;

namespace {

const int exit_failure = 1;  // the input cannot be parameterized, or a file cannot be written
const int exit_usage = 2;    // command-line error

// The center locator of the command line (a model of `MeasuredCenterLocator`), chosen at run
// time among the user's vertex (`--center=vertex:N`, through `Fixed_center`), the Poisson
// center and the geodesic centers, so that the method is instantiated once per solver
// rather than once per solver, locator and distance.
class Command_line_center_locator
{
public:
  explicit Command_line_center_locator(const std::string& name = "poisson") : m_name(name) { }
  explicit Command_line_center_locator(vertex_descriptor v) : m_fixed(v), m_name("vertex") { }

  template <class Patch>
  SMP::Error_code locate_center(Patch& patch, std::size_t& center) const
  {
    if(m_name == "vertex")
      return m_fixed.locate_center(patch, center);
    if(m_name == "geodesic:fast-marching")
      return SMP::Geodesic_center_locator<Mesh, SMP::Fast_marching_geodesics>().locate_center(patch, center);
    if(m_name == "geodesic:dijkstra")
      return SMP::Geodesic_center_locator<Mesh, SMP::Dijkstra_geodesics>().locate_center(patch, center);
    if(m_name == "geodesic:heat")
      return SMP::Geodesic_center_locator<Mesh, Heat>().locate_center(patch, center);
    if(m_name == "geodesic:heat-idt")
      return SMP::Geodesic_center_locator<Mesh, Heat_idt>().locate_center(patch, center);
    if(m_name == "geodesic:exact")
      return SMP::Geodesic_center_locator<Mesh, SMP::Exact_geodesics>().locate_center(patch, center);
    return SMP::Poisson_center_locator<Mesh>().locate_center(patch, center);
  }

private:
  SMP::Fixed_center<Mesh> m_fixed;
  std::string m_name;
};

// The border distance of the command line (a model of `MeasuredBorderDistance`), chosen at
// run time: Poisson, a geodesic method, or straightest geodesics.
class Command_line_border_distance
{
public:
  explicit Command_line_border_distance(const std::string& name = "poisson") : m_name(name) { }

  template <class Patch>
  SMP::Error_code prepare(Patch& patch) const
  {
    return dispatch([&patch](const auto& policy) { return policy.prepare(patch); });
  }

  template <class Patch>
  SMP::Error_code compute_border_distances(Patch& patch, std::size_t center, std::vector<double>& distances) const
  {
    return dispatch([&](const auto& policy) { return policy.compute_border_distances(patch, center, distances); });
  }

  // the border vertices straightest geodesics could not reach in the last call
  const SMP::Straightest_geodesic_border_distance<Mesh>::Failure& straightest_failure() const
  {
    return m_straightest.last_failure();
  }

private:
  template <class F>
  SMP::Error_code dispatch(const F& f) const
  {
    if(m_name == "fast-marching")
      return f(SMP::Geodesic_border_distance<Mesh, SMP::Fast_marching_geodesics>());
    if(m_name == "dijkstra")
      return f(SMP::Geodesic_border_distance<Mesh, SMP::Dijkstra_geodesics>());
    if(m_name == "heat")
      return f(SMP::Geodesic_border_distance<Mesh, Heat>());
    if(m_name == "heat-idt")
      return f(SMP::Geodesic_border_distance<Mesh, Heat_idt>());
    if(m_name == "exact")
      return f(SMP::Geodesic_border_distance<Mesh, SMP::Exact_geodesics>());
    if(m_name == "straightest")
      return f(m_straightest);
    return f(SMP::Poisson_border_distance<Mesh>());
  }

  std::string m_name;
  SMP::Straightest_geodesic_border_distance<Mesh> m_straightest;  // its failure record is shared by copies
};

// What a parameterization produced, copied from the parameterizer's report and record
// (whose types depend on the solver).
struct Parameterization_result
{
  SMP::Error_code status = SMP::ERROR_WRONG_PARAMETER;
  vertex_descriptor center;
  std::vector<vertex_descriptor> border;  // the longest border loop, from source(bhd)
  bool border_convex = false;
  double preparation = 0., center_time = 0., distances = 0., border_map = 0., interior = 0., output = 0., total = 0.;
  int factorizations = 0, back_substitutions = 0;
  double factorization_seconds = 0., back_substitution_seconds = 0.;
  double degenerate_face_threshold = 0.;
  SMP::Straightest_geodesic_border_distance<Mesh>::Failure straightest_failure;
  std::size_t flipped_before_repair = 0;
  bool repaired = false, mean_value_interior = false;
  double blend = 0., repair_seconds = 0.;
  int repair_candidates = 0;
};

template <class SolverTraits>
Parameterization_result run_parameterization(const Mesh& mesh, halfedge_descriptor bhd,
                                             const Command_line_center_locator& locator,
                                             const Command_line_border_distance& distance, bool repair,
                                             UV_map uvmap, Vertex_flag_map parameterized)
{
  typedef SMP::Measured_conformal_parameterizer_3<Mesh, Command_line_center_locator,
                                                  Command_line_border_distance,
                                                  SolverTraits>                   Parameterizer;
  Parameterizer parameterizer(locator, distance);
  if(!repair)
    parameterizer.set_repair(Parameterizer::NO_REPAIR);
  Parameterization_result r;
  r.status = parameterizer.parameterize(mesh, bhd, uvmap, get(boost::vertex_index, mesh), parameterized);
  r.straightest_failure = distance.straightest_failure();

  const typename Parameterizer::Report& report = parameterizer.last_report();
  r.center = parameterizer.center();
  r.border = parameterizer.border_parameterizer().border_vertices();
  r.border_convex = parameterizer.border_parameterizer().is_border_convex();
  r.preparation = report.preparation_seconds;
  r.center_time = report.center_seconds;
  r.distances = report.distance_seconds;
  r.border_map = report.border_map_seconds;
  r.interior = report.interior_seconds;
  r.output = report.output_seconds;
  r.total = report.total_seconds;
  r.factorizations = report.statistics.factorizations;
  r.back_substitutions = report.statistics.back_substitutions;
  r.factorization_seconds = report.statistics.factorization_seconds;
  r.back_substitution_seconds = report.statistics.back_substitution_seconds;
  r.degenerate_face_threshold = Parameterizer::Patch::degenerate_face_threshold();
  r.flipped_before_repair = report.flipped_faces_before_repair;
  r.repaired = report.repaired;
  r.mean_value_interior = report.mean_value_interior;
  r.blend = report.blend;
  r.repair_seconds = report.repair_seconds;
  r.repair_candidates = report.repair_candidates;
  return r;
}

double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// A line of text for a comment of the OBJ file: no line breaks or other control characters.
std::string one_line(std::string s)
{
  for(char& c : s)
    if(static_cast<unsigned char>(c) < 0x20)
      c = '?';
  return s;
}

} // namespace

int main(int argc, char** argv)
{
  typedef std::chrono::steady_clock Clock;
  const std::string default_mesh = MBP_DEFAULT_MESH;

  // ------------------------------------------------------------------ command line
  mbp_cli::Options options;
  const std::string usage_error = mbp_cli::parse_options(argc, argv, options);
  if(!usage_error.empty())
  {
    std::cerr << "error: " << usage_error << "\n(run with --help for the usage)\n";
    return exit_usage;
  }
  if(options.help)
  {
    std::cout << mbp_cli::usage(default_mesh);
    return EXIT_SUCCESS;
  }

  // ------------------------------------------------------------------ input
  Mesh mesh;
  bool generated = false;
  Clock::time_point start = Clock::now();
  if(options.input.empty())
  {
    std::error_code ec;
    if(!default_mesh.empty() && fs::exists(default_mesh, ec))
      options.input = default_mesh;
    else
    {
      mbp_cli::make_curved_disk(mesh);
      generated = true;
      std::cerr << "note: "
                << (default_mesh.empty() ? std::string("no default mesh was configured")
                                         : "the default mesh '" + default_mesh + "' does not exist")
                << "; using a generated curved disk (" << num_vertices(mesh) << " vertices, "
                << num_faces(mesh) << " faces)\n";
    }
  }
  const std::string where = generated ? std::string("generated curved disk") : options.input;
  auto fail = [&where](const mbp_cli::Failure& f) {
    std::cerr << "error: " << where << ": " << f.message() << "\n";
    return exit_failure;
  };
  if(!generated)
  {
    const mbp_cli::Failure f = mbp_cli::read_mesh(options.input, mesh);
    if(f.failed())
      return fail(f);
  }
  const double read_seconds = seconds_since(start);

  // Output names, checked before the parameterization.
  if(options.output.empty())
    options.output = (generated ? std::string("curved_disk") : fs::path(options.input).stem().string()) + "_uv.obj";
  if(!options.svg.empty())
  {
    std::error_code ec_svg, ec_obj;
    const fs::path svg = fs::weakly_canonical(options.svg, ec_svg), obj = fs::weakly_canonical(options.output, ec_obj);
    if(options.svg == options.output || (!ec_svg && !ec_obj && svg == obj))
    {
      std::cerr << "error: OUTPUT and --svg name the same file '" << options.output << "'\n";
      return exit_usage;
    }
  }

  // ------------------------------------------------------------------ checks
  halfedge_descriptor bhd;
  double border_length = 0.;
  {
    const mbp_cli::Failure f = mbp_cli::check_mesh(mesh, bhd, border_length);
    if(f.failed())
      return fail(f);
  }

  Command_line_center_locator locator(options.center);
  const Command_line_border_distance distance(options.distance);
  if(options.fixed_center)
  {
    // Surface_mesh numbers the vertices in the order they were added: the file order.
    const std::size_t n = options.center_vertex;
    mbp_cli::Failure f;  // a check of the program: no library code
    if(n >= num_vertices(mesh))
      f.detail = "--center=vertex:" + std::to_string(n) + ": vertex index out of range (the mesh has " +
                 std::to_string(num_vertices(mesh)) + " vertices, numbered from 0)";
    else
    {
      const vertex_descriptor v(static_cast<Mesh::size_type>(n));
      if(mesh.is_isolated(v))
        f.detail = "--center=vertex:" + std::to_string(n) + ": the vertex is in no face";
      for(halfedge_descriptor h : CGAL::halfedges_around_face(bhd, mesh))
        if(target(h, mesh) == v)
          f.detail = "--center=vertex:" + std::to_string(n) +
                     ": the vertex lies on the border; the center must be an interior vertex";
      locator = Command_line_center_locator(v);
    }
    if(!f.detail.empty())
      return fail(f);
  }

  // ------------------------------------------------------------------ parameterization
  UV_map uvmap = mesh.add_property_map<vertex_descriptor, Point_2>("v:uv", Point_2(0., 0.)).first;
  Vertex_flag_map parameterized = mesh.add_property_map<vertex_descriptor, bool>("v:parameterized", false).first;
  Parameterization_result result;
#ifdef MBP_WITH_CHOLMOD
  if(options.solver == mbp_cli::Solver::cholmod)
    result = run_parameterization<SMP::Cholmod_supernodal_cholesky_traits>(mesh, bhd, locator, distance,
                                                                           options.repair, uvmap, parameterized);
  else
#endif
    result = run_parameterization<CGAL::Default>(mesh, bhd, locator, distance, options.repair, uvmap,
                                                 parameterized);

  if(result.status != SMP::OK)
  {
    mbp_cli::Failure f;
    f.code = result.status;
    if(result.status == SMP::ERROR_DEGENERATE_FACE)
      f.detail = mbp_cli::find_degenerate_face(mesh, result.degenerate_face_threshold);
    else if(result.status == SMP::ERROR_NON_FINITE_COORDINATES)
      f.detail = mbp_cli::find_non_finite_vertex(mesh);
    else if(result.status == SMP::ERROR_NO_TOPOLOGICAL_DISC)
      f.detail = "the longest border touches itself, a vertex is non-manifold, or the surface has handles";
    else if(result.status == SMP::ERROR_NO_1_TO_1_MAPPING)
      f.detail = std::to_string(result.flipped_before_repair) +
                 " faces are flipped by the measured border" +
                 (options.repair ? std::string(" and no blend toward a circle repairs them")
                                 : std::string(" (repair is off: --no-repair)"));
    else if(result.status == SMP::ERROR_DISTANCE_COMPUTATION_FAILED && options.distance == "straightest" &&
            result.straightest_failure.unreachable > 0)
      f.detail = "the straightest geodesic from the center (vertex " + std::to_string(std::size_t(result.center)) +
                 ") does not reach border vertex " + std::to_string(std::size_t(result.straightest_failure.vertex)) +
                 " (" + std::to_string(result.straightest_failure.unreachable) + " of " +
                 std::to_string(result.border.size()) + " border vertices are not reached)";
    return fail(f);
  }

  // The OBJ numbering: the vertices of the faces, in input order. (The checks above leave one
  // connected component, all of which is parameterized; only isolated vertices are left out.)
  std::vector<std::size_t> obj_index(num_vertices(mesh), std::size_t(-1));
  std::vector<vertex_descriptor> obj_vertices;
  for(vertex_descriptor v : vertices(mesh))
    if(get(parameterized, v))
    {
      const Point_2& p = get(uvmap, v);
      if(!std::isfinite(p.x()) || !std::isfinite(p.y()))
      {
        mbp_cli::Failure f;
        f.code = SMP::ERROR_CANNOT_SOLVE_LINEAR_SYSTEM;
        f.detail = "the solver gave a non-finite UV at vertex " + std::to_string(std::size_t(v));
        return fail(f);
      }
      obj_index[std::size_t(v)] = obj_vertices.size();
      obj_vertices.push_back(v);
    }
  const std::size_t isolated = num_vertices(mesh) - obj_vertices.size();

  // ------------------------------------------------------------------ quality
  start = Clock::now();
  auto face_quality = mesh.add_property_map<face_descriptor, SMP::Face_quality>("f:quality").first;
  const SMP::Parameterization_quality quality = SMP::measure_quality_per_face(mesh, faces(mesh), uvmap, face_quality);
  const double quality_seconds = seconds_since(start);

  // ------------------------------------------------------------------ output files
  start = Clock::now();
  const std::string mesh_name = generated ? std::string("curved disk (generated)")
                                          : fs::path(options.input).filename().string();
  const std::size_t center_index = std::size_t(result.center);
  std::string obj;
  obj.reserve(96 * obj_vertices.size() + 32 * num_faces(mesh));
  obj += "# UV layout by measured_parameterization: measured boundary parameterization (center: " +
         options.center_name() + ", border distances: " + options.distance + "), discrete conformal interior\n";
  obj += "# input: " + one_line(generated ? mesh_name : options.input) + "\n";
  obj += "# " + std::to_string(obj_vertices.size()) + " vertices, " + std::to_string(num_faces(mesh)) +
         " faces, center: input vertex " + std::to_string(center_index) + " (0-based)\n";
  for(vertex_descriptor v : obj_vertices)
  {
    const Point_3& p = mesh.point(v);
    obj += "v " + mbp_cli::exact(p.x()) + " " + mbp_cli::exact(p.y()) + " " + mbp_cli::exact(p.z()) + "\n";
  }
  for(vertex_descriptor v : obj_vertices)
  {
    const Point_2& q = get(uvmap, v);
    obj += "vt " + mbp_cli::exact(q.x()) + " " + mbp_cli::exact(q.y()) + "\n";
  }
  for(face_descriptor f : faces(mesh))
  {
    obj += "f";
    for(vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
    {
      const std::string i = std::to_string(obj_index[std::size_t(v)] + 1);
      obj += " " + i + "/" + i;
    }
    obj += "\n";
  }

  std::string svg;
  if(!options.svg.empty())
  {
    mbp_cli::Svg_layout layout;
    for(vertex_descriptor v : obj_vertices)
      layout.uv.push_back({get(uvmap, v).x(), get(uvmap, v).y()});
    for(face_descriptor f : faces(mesh))
    {
      std::array<std::size_t, 3> t;
      std::size_t k = 0;
      for(vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, mesh), mesh))
        t[k++] = obj_index[std::size_t(v)];
      layout.faces.push_back(t);
      const SMP::Face_quality& fq = get(face_quality, f);
      layout.face_angle_distortion.push_back(fq.angle_distortion);
      layout.face_flipped.push_back(!(fq.uv_area > 0.));
    }
    for(vertex_descriptor v : result.border)
      layout.border.push_back(obj_index[std::size_t(v)]);
    layout.center = obj_index[center_index];
    layout.center_label = "center (vertex " + std::to_string(center_index) + ")";
    layout.title = mesh_name;
    layout.caption.push_back(std::to_string(obj_vertices.size()) + " vertices, " + std::to_string(num_faces(mesh)) +
                             " faces, border of " + std::to_string(result.border.size()) + " vertices, center: " +
                             options.center_name() + " center, " + options.distance + " distances");
    layout.caption.push_back("angle distortion " + mbp_cli::rounded(quality.angle_distortion) + ",  L2 stretch " +
                             mbp_cli::rounded(quality.l2_stretch) + ",  quasi-conformal mean " +
                             mbp_cli::rounded(quality.quasi_conformal_mean) + ",  flipped faces " +
                             std::to_string(quality.flipped_faces));
    svg = mbp_cli::svg_document(layout);
  }

  {
    mbp_cli::Output_files files;
    std::string error = files.add(options.output, obj);
    if(error.empty() && !options.svg.empty())
      error = files.add(options.svg, svg);
    if(error.empty())
      error = files.commit();
    if(!error.empty())
    {
      std::cerr << "error: " << error << "\n";
      return exit_failure;
    }
  }
  const double write_seconds = seconds_since(start);

  // ------------------------------------------------------------------ report
  if(isolated > 0)
    std::cerr << "note: " << isolated << " vertices in no face were left out of " << options.output << "\n";
  if(quality.flipped_faces > 0)
    std::cerr << "warning: " << quality.flipped_faces << " of " << quality.number_of_faces
              << " faces are flipped in the UV layout: the map is not one-to-one"
              << (result.border_convex ? "" : " (the measured border is not convex)") << "\n";

  const Point_3& c = mesh.point(result.center);
  const Point_2& cuv = get(uvmap, result.center);
  if(options.json)
  {
    mbp_cli::Json_writer j;
    j.begin_object();
    if(generated)
      j.null_member("input");
    else
      j.member("input", options.input);
    j.member("generated_mesh", generated);
    j.member("mesh", mesh_name);
    j.member("output", options.output);
    if(options.svg.empty())
      j.null_member("svg");
    else
      j.member("svg", options.svg);
    j.member("solver", mbp_cli::solver_name(options.solver));
    j.member("center_locator", options.fixed_center ? std::string("vertex") : options.center);
    j.member("border_distance", options.distance);
    j.member("vertices", obj_vertices.size());
    j.member("faces", std::size_t(num_faces(mesh)));
    j.member("isolated_vertices", isolated);
    j.begin_object("border")
       .member("vertices", result.border.size())
       .member("length", border_length)
       .member("convex", result.border_convex)
       .end_object();
    j.begin_object("center").member("index", center_index);
    j.begin_array("point").element(c.x()).element(c.y()).element(c.z()).end_array();
    j.begin_array("uv").element(cuv.x()).element(cuv.y()).end_array();
    j.end_object();
    j.begin_object("times")
       .member("preparation", result.preparation)
       .member("center", result.center_time)
       .member("distances", result.distances)
       .member("border_map", result.border_map)
       .member("interior", result.interior)
       .member("output", result.output)
       .member("total", result.total)
       .end_object();
    j.begin_object("io_times")
       .member("read", read_seconds)
       .member("quality", quality_seconds)
       .member("write", write_seconds)
       .end_object();
    j.begin_object("repair")
       .member("enabled", options.repair)
       .member("flipped_faces_before", result.flipped_before_repair)
       .member("repaired", result.repaired)
       .member("blend", result.blend)
       .member("interior", result.mean_value_interior ? "mean value coordinates" : "discrete conformal")
       .member("candidates", result.repair_candidates)
       .member("seconds", result.repair_seconds)
       .end_object();
    j.begin_object("statistics")
       .member("factorizations", result.factorizations)
       .member("back_substitutions", result.back_substitutions)
       .member("factorization_seconds", result.factorization_seconds)
       .member("back_substitution_seconds", result.back_substitution_seconds)
       .end_object();
    j.begin_object("quality")
       .member("angle_distortion", quality.angle_distortion)
       .member("angle_distortion_per_corner", quality.angle_distortion_per_corner)
       .member("l2_stretch", quality.l2_stretch)
       .member("linf_stretch", quality.linf_stretch)
       .member("quasi_conformal_mean", quality.quasi_conformal_mean)
       .member("quasi_conformal_max", quality.quasi_conformal_max)
       .member("area_distortion_mean", quality.area_distortion_mean)
       .member("area_distortion_max", quality.area_distortion_max)
       .member("flipped_faces", quality.flipped_faces)
       .end_object();
    j.end_object();
    std::cout << j.text();
  }
  else
  {
    using mbp_cli::rounded;
    std::cout << mesh_name << ": V " << obj_vertices.size() << ", F " << num_faces(mesh)
              << " | border " << result.border.size() << " vertices, length " << rounded(border_length)
              << " | center " << center_index << " (" << options.center_name() << ")"
              << " | distances " << options.distance
              << " | seconds: preparation " << rounded(result.preparation, 3) << ", center "
              << rounded(result.center_time, 3) << ", distances " << rounded(result.distances, 3)
              << ", border map " << rounded(result.border_map, 3) << ", interior " << rounded(result.interior, 3)
              << ", total " << rounded(result.total, 3)
              << " | " << mbp_cli::solver_name(options.solver) << ": " << result.factorizations
              << " factorizations, " << result.back_substitutions << " back-substitutions"
              << " | angle distortion " << rounded(quality.angle_distortion) << ", L2 stretch "
              << rounded(quality.l2_stretch) << ", quasi-conformal mean " << rounded(quality.quasi_conformal_mean)
              << ", flipped faces " << quality.flipped_faces
              << (result.repaired ? " | repaired " + std::to_string(result.flipped_before_repair) +
                                        " flipped faces: blend " + rounded(result.blend, 3) +
                                        (result.mean_value_interior ? ", mean value interior" : "")
                                  : std::string())
              << " | wrote " << options.output << (options.svg.empty() ? std::string() : ", " + options.svg)
              << "\n";
  }
  return EXIT_SUCCESS;
}
