// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// The command-line program of the package. By default (--atlas) it makes a packed texture
// atlas of any mesh file: the file is read as a polygon soup, which the library repairs, cuts
// into charts (one per connected component, split where its map would not be one-to-one) and
// packs into the unit square (compute_atlas_of_polygon_soup()); every corner of every input
// polygon gets a UV. With --single-chart (implied by the options of that mode) it flattens a
// disk-like triangle mesh with the measured boundary parameterization of "Measured boundary
// parameterization based on Poisson's equation" (Conformal_parameterizer_3 with the border
// policy of --border: the paper's Measured_border, or by default Automatic_border).
//
//   measured_parameterization [INPUT] [OUTPUT.obj] [--atlas] [--resolution=N] [--gutter=N]
//                             [--output=FILE] [--svg=FILE] [--json] [--help]
//   measured_parameterization [INPUT] [OUTPUT.obj] --single-chart [--seams=FILE.selection.txt]
//                             [--center=poisson|geodesic[:METHOD]|vertex:N]
//                             [--distance=poisson|METHOD|straightest] [--border=auto|conformal|measured|circle]
//                             [--solver=cholmod|cholmod-nd|ldlt] [--svg=FILE] [--json] [--no-repair]
//                             [--write-seams=FILE.selection.txt]
//   measured_parameterization --batch=FOLDER|LIST|- --output-dir=DIR [--jobs=N] [--shard=I/N]
//                             [--force] [the options of a mode] [--threads=N]
//
// Reads OFF, OBJ, PLY or STL (default: a real mesh of the project's data, or a generated
// curved disk when that file is missing) and writes an OBJ (default: <input file stem>_uv.obj):
// for the atlas the input's points and polygons in their order with one UV per polygon corner
// and a group per chart; for a single chart one UV per vertex (with seams, one per side of a
// seam). Optionally an SVG picture, and a one-line summary or a JSON object with the times and
// the distortion. For a single chart, a mesh that is not a disk (closed, with holes or
// handles) is cut along seams: those of --seams, or automatic seams (compute_disk_seams);
// --write-seams=FILE writes the seams used as a CGAL selection file.
// On any failure it says why on stderr, exits with a non-zero status and leaves no output
// file. The library does no IO; this program is the IO layer: options.h (the command line),
// run.h (the mesh and its atlas or parameterization: the only code that calls the library),
// obj_writer.h, svg_writer.h, json_output.h and summary.h (the outputs), file_output.h (the
// files, all or nothing). --batch runs many meshes, each in a worker process that is this
// program run on one mesh (batch.h).

#include "batch.h"
#include "file_output.h"
#include "json_output.h"
#include "obj_writer.h"
#include "options.h"
#include "run.h"
#include "summary.h"
#include "svg_writer.h"

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>

namespace {

namespace fs = std::filesystem;
using namespace mbp_cli;
typedef std::chrono::steady_clock Clock;

const int exit_failure = 1;  // the input cannot be parameterized, or a file cannot be written
const int exit_usage = 2;    // command-line error

double seconds_since(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The end of a failed run: the message on stderr ("error: MESSAGE" and, for a command-line
// error, the hint to --help) and, with --json, the same on stdout as one JSON object
// (json_failure()). `error_code` is the library's Error_code of the failure, or 0.
int fail_with(const std::string& message, int status, bool json, int error_code = 0)
{
  std::cerr << "error: " << message << "\n";
  if(status == exit_usage)
    std::cerr << "(run with --help for the usage)\n";
  if(json)
    std::cout << json_failure(message, status, error_code);
  return status;
}

// A command-line error: the parsing stopped at the error, so --json may come after it.
int usage_error(const std::string& error, int argc, char** argv)
{
  bool json = false;
  for(int i = 1; i < argc; ++i)
    json = json || std::string(argv[i]) == "--json";
  return fail_with(error, exit_usage, json);
}

// Without INPUT: the default mesh, or the generated curved disk when that file is missing
// (then true).
bool resolve_default_input(Options& options, const std::string& default_mesh, Run& run)
{
  std::error_code ec;
  if(!options.input.empty())
    return false;
  if(!default_mesh.empty() && fs::exists(default_mesh, ec))
  {
    options.input = default_mesh;
    return false;
  }
  const std::array<std::size_t, 2> size = run.generate_curved_disk();
  std::cerr << "note: "
            << (default_mesh.empty() ? std::string("no default mesh was configured")
                                     : "the default mesh '" + default_mesh + "' does not exist")
            << "; using a generated curved disk (" << size[0] << " vertices, " << size[1] << " faces)\n";
  return true;
}

// The output names, checked before anything is read or computed: no output may be an input
// or another output, an existing output must be a regular file (file_output.h). Returns the
// error, with `usage` set when it is a command-line error.
std::string check_outputs(Options& options, bool generated, Output_files& files, bool& usage)
{
  if(options.output.empty())
    options.output = (generated ? std::string("curved_disk") : fs::path(options.input).stem().string()) + "_uv.obj";
  if(!generated)
    files.add_input(options.input, "the input");
  if(!options.seams.empty())
    files.add_input(options.seams, "the seam file");
  std::string error = files.add_target(options.output, "OUTPUT", usage);
  if(error.empty() && !options.svg.empty())
    error = files.add_target(options.svg, "--svg", usage);
  if(error.empty() && !options.write_seams.empty())
    error = files.add_target(options.write_seams, "--write-seams", usage);
  return error;
}

// Writes `text` into the temporary file of target `k`; false on failure (files.error()).
bool write_target(Output_files& files, std::size_t k, const std::string& text)
{
  Buffered_writer* out = files.begin(k);
  if(out == nullptr)
    return false;
  *out << text;
  return files.end(k);
}

// Writes every output (the OBJ, the SVG, the seams) into its temporary file, then publishes
// them all. Returns the error, or an empty string.
std::string write_outputs(const Run_facts& f, Output_files& files)
{
  Buffered_writer* obj = files.begin(0);  // the OBJ, written straight into its temporary file
  if(obj == nullptr)
    return files.error();
  write_obj(*obj, f);
  if(!files.end(0))
    return files.error();
  const Options& o = f.options;
  bool written = o.svg.empty() || write_target(files, 1, svg_picture(f));
  if(written && !o.write_seams.empty())
    written = write_target(files, o.svg.empty() ? 1 : 2, f.result.seams.selection);  // the order of add_target()
  // for the tests of interrupted and failed runs (test_cli): stop with every output written
  // to its temporary file, before any is published
  if(written && std::getenv("MBP_CLI_TEST_STOP_BEFORE_PUBLISH") != nullptr)
    std::raise(SIGSTOP);
  return written && files.publish() ? std::string() : files.error();
}

// The notes and warnings of a successful run, on stderr.
void print_notes(const Run_facts& f)
{
  const Run_result& r = f.result;
  if(f.options.mode == Mode::atlas)
  {
    if(r.atlas.empty_polygons > 0)
      std::cerr << "note: " << r.atlas.empty_polygons
                << (r.atlas.empty_polygons == 1 ? " polygon without vertices was" : " polygons without vertices were")
                << " left out of " << f.options.output << "\n";
    return;
  }
  const std::size_t isolated = r.input_vertices - r.layout.vertices.size();
  if(isolated > 0)
    std::cerr << "note: " << isolated << " vertices in no face were left out of " << f.options.output << "\n";
  if(!f.options.write_seams.empty() && !r.seams.cut)
    std::cerr << "note: the mesh is a disk, it needs no seams: " << f.options.write_seams << " lists none\n";
  if(r.quality.flipped_faces > 0)
    std::cerr << "warning: " << r.quality.flipped_faces << " of " << r.quality.number_of_faces
              << " faces are flipped in the UV layout: the map is not one-to-one"
              << (r.report.border_convex ? "" : " (the measured border is not convex)") << "\n";
}

} // namespace

int main(int argc, char** argv)
{
  const std::string default_mesh = mbp_cli::default_mesh;
  Options options;
  const std::string usage_problem = parse_options(argc, argv, options);
  if(!usage_problem.empty())
    return usage_error(usage_problem, argc, argv);
  if(options.help)
  {
    std::cout << usage(default_mesh);
    return EXIT_SUCCESS;
  }
  if(options.batch.active())
    return run_batch(options, argc, argv);

  // the input, the output names, then the mesh
  Run run;
  Clock::time_point start = Clock::now();
  const bool generated = resolve_default_input(options, default_mesh, run);
  Output_files files;
  bool usage = false;
  const std::string output_problem = check_outputs(options, generated, files, usage);
  if(!output_problem.empty())
    return fail_with(output_problem, usage ? exit_usage : exit_failure, options.json);
  if(!generated)
  {
    const Run_error e = run.read(options.input, options.mode);
    if(e.failed())
      return fail_with(e.message, exit_failure, options.json, e.error_code);
  }
  Run_facts facts(options, run.result());
  facts.read_seconds = seconds_since(start);
  facts.generated = generated;
  facts.mesh_name = generated ? std::string("curved disk (generated)") : fs::path(options.input).filename().string();

  // the atlas, or the single chart
  const Run_error e = run.parameterize(options);
  if(e.failed())
    return fail_with(e.message, exit_failure, options.json, e.error_code);

  // the outputs: the files, all or nothing, then the notes and the summary or JSON
  start = Clock::now();
  const std::string write_problem = write_outputs(facts, files);
  if(!write_problem.empty())
    return fail_with(write_problem, exit_failure, options.json);
  facts.write_seconds = seconds_since(start);
  print_notes(facts);
  std::cout << (options.json ? json_document(facts) : summary_line(facts));
  return EXIT_SUCCESS;
}
