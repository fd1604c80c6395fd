// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// libFuzzer target over the input path of the command-line program (cli/): the bytes are a
// mesh file, read and checked by the program's own helpers (the streaming readers of
// cli/mesh_reader.cpp through read_mesh() of cli/mesh_input.h), then, when the mesh is valid
// and small, parameterized by Measured_conformal_parameterizer_3 with the program's defaults
// (Poisson center, Poisson border distances, repair on).
//
// The format is chosen from the content, as a user's file would be named: "OFF" in the first
// bytes -> .off, "ply" -> .ply, "solid" or a binary STL whose size matches its triangle count
// -> .stl, anything else -> .obj. The bytes are written to a temporary file of that extension
// (the program reads regular files by path).
//
// Invariants (a violation aborts, which libFuzzer reports as a crash):
//  - reading and the checks never crash, leak or hit undefined behaviour (ASan, UBSan);
//  - a failure always has a message;
//  - status OK => every parameterized vertex has a finite UV, every vertex of the (single)
//    component is parameterized, and the UV map is one-to-one (is_one_to_one_uv_map: no
//    flipped triangle, no overlap);
//  - status not OK => the library's message for the code is not empty.
//
//   fuzz_mesh_input -max_total_time=60 CORPUS_DIR      # fuzz
//   fuzz_mesh_input FILE...                            # run the given inputs once
//   MBP_FUZZ_VERBOSE=1 fuzz_mesh_input FILE...         # ... and print each outcome

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Surface_mesh_parameterization/Measured_conformal_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_report.h>
#include <CGAL/Surface_mesh_parameterization/measure_quality.h>

#include "cli/mesh_input.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace {

typedef CGAL::Simple_cartesian<double>                   Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3>              Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor     vertex_descriptor;
typedef boost::graph_traits<Mesh>::halfedge_descriptor   halfedge_descriptor;
namespace SMP = CGAL::Surface_mesh_parameterization;

// Meshes larger than this are read and checked but not parameterized (fast iterations).
const std::size_t max_vertices = 2000;
const std::size_t max_faces = 4000;

// With MBP_FUZZ_VERBOSE set, the outcome of every input is printed (to review the corpus).
void outcome(const std::string& what)
{
  static const bool verbose = std::getenv("MBP_FUZZ_VERBOSE") != nullptr;
  if(verbose)
    std::fprintf(stderr, "fuzz_mesh_input: %s\n", what.c_str());
}

[[noreturn]] void invariant_failed(const char* what, const std::string& detail = std::string())
{
  std::fprintf(stderr, "fuzz_mesh_input: invariant violated: %s%s%s\n", what, detail.empty() ? "" : ": ",
               detail.c_str());
  std::abort();
}

bool starts_with(const std::uint8_t* data, std::size_t size, const char* prefix)
{
  const std::size_t n = std::strlen(prefix);
  return size >= n && std::memcmp(data, prefix, n) == 0;
}

std::string extension_of(const std::uint8_t* data, std::size_t size)
{
  // OFF and its variants (COFF, NOFF, CNOFF, STOFF, 4OFF, nOFF...), possibly after blanks
  std::size_t i = 0;
  while(i < size && (data[i] == ' ' || data[i] == '\t' || data[i] == '\r' || data[i] == '\n'))
    ++i;
  for(std::size_t j = i; j + 3 <= size && j < i + 6; ++j)
    if(std::memcmp(data + j, "OFF", 3) == 0)
      return "off";
  if(starts_with(data, size, "ply"))
    return "ply";
  if(starts_with(data, size, "solid"))
    return "stl";
  if(size >= 84)
  {
    const std::uint32_t triangles = std::uint32_t(data[80]) | std::uint32_t(data[81]) << 8 |
                                    std::uint32_t(data[82]) << 16 | std::uint32_t(data[83]) << 24;
    if(std::uint64_t(size) == 84 + 50 * std::uint64_t(triangles))
      return "stl";
  }
  return "obj";
}

// A temporary file of this process, removed by the destructor.
struct Temporary_file
{
  std::string path;
  Temporary_file(const std::string& extension, const std::uint8_t* data, std::size_t size)
  {
    const char* tmp = std::getenv("TMPDIR");
    path = std::string(tmp != nullptr && *tmp != '\0' ? tmp : "/tmp") + "/mbp_fuzz_mesh_input_" +
           std::to_string(::getpid()) + "." + extension;
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
    if(!out.good())
      invariant_failed("cannot write the temporary file", path);
  }
  ~Temporary_file() { std::remove(path.c_str()); }
};

void parameterize_and_check(const Mesh& mesh, halfedge_descriptor bhd)
{
  typedef SMP::Measured_conformal_parameterizer_3<Mesh> Parameterizer;
  const Parameterizer parameterizer;
  SMP::Parameterization_report report;
  auto uvmap = get(CGAL::dynamic_vertex_property_t<Kernel::Point_2>(), mesh);
  auto parameterized = get(CGAL::dynamic_vertex_property_t<bool>(), mesh);
  for(vertex_descriptor v : vertices(mesh))
    put(parameterized, v, false);
  const SMP::Error_code status =
    parameterizer.parameterize(mesh, bhd, uvmap, get(CGAL::dynamic_vertex_property_t<int>(), mesh), parameterized,
                               &report);

  if(status != SMP::OK)
  {
    const char* message = SMP::get_measured_error_message(status);
    if(message == nullptr || *message == '\0')
      invariant_failed("a failure without a message", std::to_string(int(status)));
    // the program's explanations of some codes
    if(status == SMP::ERROR_DEGENERATE_FACE)
      (void)mbp_cli::find_degenerate_face(mesh, 1e-12);  // the package's test: 2A <= 1e-12 l^2
    else if(status == SMP::ERROR_NON_FINITE_COORDINATES)
      (void)mbp_cli::find_non_finite_vertex(mesh);
    outcome(std::string("parameterizer: ") + message);
    return;
  }

  // OK: one component (check_mesh), so every vertex in a face is parameterized, with a finite UV
  for(vertex_descriptor v : vertices(mesh))
  {
    if(mesh.is_isolated(v))
      continue;
    if(!get(parameterized, v))
      invariant_failed("status OK but a vertex of the component is not parameterized",
                       "vertex " + std::to_string(std::size_t(v)));
    const Kernel::Point_2& q = get(uvmap, v);
    if(!std::isfinite(q.x()) || !std::isfinite(q.y()))
      invariant_failed("status OK but a UV is not finite", "vertex " + std::to_string(std::size_t(v)));
  }
  if(!SMP::is_one_to_one_uv_map(mesh, faces(mesh), uvmap))
    invariant_failed("status OK but the UV map is not one-to-one (flipped or overlapping triangles)");
  outcome("parameterized: " + std::to_string(num_vertices(mesh)) + " vertices, one-to-one" +
          (report.repaired ? " (repaired)" : ""));
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const Temporary_file file(extension_of(data, size), data, size);

  // the program's input path: read_mesh, then check_mesh, then the longest border
  Mesh mesh;
  mbp_cli::Failure f = mbp_cli::read_mesh(file.path, mesh);
  if(f.failed())
  {
    if(f.message().empty())
      invariant_failed("a read failure without a message");
    outcome("read: " + f.message());
    return 0;
  }
  f = mbp_cli::check_mesh(mesh);
  if(f.failed())
  {
    if(f.message().empty())
      invariant_failed("a check failure without a message");
    outcome("check: " + f.message());
    return 0;
  }
  halfedge_descriptor bhd;
  double border_length = 0.;
  f = mbp_cli::find_longest_border(mesh, bhd, border_length);
  if(f.failed())
  {
    if(f.message().empty())
      invariant_failed("a border failure without a message");
    outcome("border: " + f.message());
    return 0;
  }
  if(num_vertices(mesh) > max_vertices || num_faces(mesh) > max_faces)
  {
    outcome("valid, too large to parameterize here");
    return 0;
  }

  parameterize_and_check(mesh, bhd);
  return 0;
}
