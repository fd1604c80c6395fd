// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// Atlas packing (issue 22, item 3): the package's packer (internal/atlas/packing.h, a
// rasterized bitmap packer) against xatlas's packer and libnest2d, on the same charts: the
// charts of xatlas itself.
//
//   atlas_packing [--meshes=DIR] [--xatlas=PROGRAM] [--resolution=N] [--gutter=G]
//                 [--no-nest] [--nest-seconds=S] [--placer=bl|nfp] [--check] [--runs=N] [NAME...]
//
// For every mesh of DIR (default ../shared/data/atlas; NAME... restricts to those files),
// xatlas's program is run with its default options; its output OBJ has one v/vt pair per
// atlas vertex and faces `f a/a b/b c/c`, and every chart has its own vt: the charts are the
// connected components of the faces through shared vt indices. A chart's UVs are xatlas's vt
// times its atlas size (W x H texels: the vt are normalized per axis), its 3D area the sum
// of the areas of its faces from the v lines. Then:
//   xatlas     its printed utilization (texels of its charts / W x H, its own measure), the
//              exact one (UV area of its triangles / W x H) and the exact one in a square
//              of side max(W, H); its seconds: segmentation, parameterization and packing.
//   raster     pack_atlas_charts() on the same charts (square atlas, --resolution texels,
//              gutter --gutter texels): utilization (UV area / [0,1]^2), seconds (wall clock
//              and processor time, medians of --runs runs), attempts; --check adds the independent check of test/atlas_check.h
//              (overlapping pairs, pairs closer than the gutter, UVs outside [0,1]^2).
//   libnest2d  (built only when Debian's libnest2d-dev is found; --no-nest skips it) the
//              same normalization (one texel density, smallest box), the convex hull of each
//              chart as its item, libnest2d's BottomLeftPlacer (--placer=bl, 90-degree turns)
//              or NfpPlacer (--placer=nfp, 0/90/180/270 degrees, single-threaded) with
//              FirstFitSelection, min_obj_distance = gutter, a bin of the atlas less a gutter;
//              the largest density at which every chart goes into one bin, searched from the
//              package's density (down by 0.9, then bisection to the same tolerance). It stops
//              after --nest-seconds (default 120) with the best density found so far.

#include <CGAL/Surface_mesh_parameterization/internal/atlas/packing.h>

#include "../test/atlas_check.h"

#ifdef MBP_HAS_LIBNEST2D
#include <libnest2d/libnest2d.hpp>
#endif

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#ifndef MBP_ATLAS_MESH_DIR
#define MBP_ATLAS_MESH_DIR ""
#endif
#ifndef MBP_XATLAS_PROGRAM
#define MBP_XATLAS_PROGRAM ""
#endif

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace fs = std::filesystem;

namespace {

struct Options
{
  std::string meshes = MBP_ATLAS_MESH_DIR;
  std::string xatlas = MBP_XATLAS_PROGRAM;
  std::string cache;  // a folder that keeps xatlas's outputs between runs
  SMP::internal::Atlas_packing_options packing;
  bool nest = true;
  double nest_seconds = 120.;
  std::string placer = "bl";
  bool check = false;
  int runs = 3;
  std::vector<std::string> only;
};

// xatlas's printed line and the charts of its output.
struct Xatlas_run
{
  bool ok = false;
  std::map<std::string, std::string> fields;  // charts, atlas, utilization, seconds, ...
  int width = 0;
  int height = 0;
  std::vector<SMP::internal::Chart_to_pack> charts;
  double uv_texels = 0.;  // exact UV area of its triangles, in texels
};

struct Union_find
{
  std::vector<std::size_t> parent;
  explicit Union_find(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), std::size_t(0)); }
  std::size_t find(std::size_t x)
  {
    while(parent[x] != x)
      x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(std::size_t a, std::size_t b) { parent[find(a)] = find(b); }
};

double triangle_area_3(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c)
{
  return 0.5 * (b - a).cross(c - a).norm();
}

// The v, vt and f lines of xatlas's OBJ (faces: 3D corners and vt corners, 0-based).
bool read_obj(const std::string& path, std::vector<Eigen::Vector3d>& v, std::vector<Eigen::Vector2d>& vt,
              std::vector<std::array<std::size_t, 6> >& f)
{
  std::ifstream in(path);
  std::string line;
  while(std::getline(in, line))
  {
    std::istringstream s(line);
    std::string tag;
    s >> tag;
    if(tag == "v")
    {
      Eigen::Vector3d p;
      s >> p.x() >> p.y() >> p.z();
      v.push_back(p);
    }
    else if(tag == "vt")
    {
      Eigen::Vector2d p;
      s >> p.x() >> p.y();
      vt.push_back(p);
    }
    else if(tag == "f")
    {
      std::array<std::size_t, 6> face{};
      for(int k = 0; k < 3; ++k)
      {
        std::string corner;
        s >> corner;
        face[std::size_t(k)] = std::stoul(corner) - 1;
        face[std::size_t(k + 3)] = std::stoul(corner.substr(corner.find('/') + 1)) - 1;
      }
      f.push_back(face);
    }
  }
  return !f.empty();
}

// The charts of xatlas's OBJ: components of faces through shared vt indices.
void group_charts(const std::vector<Eigen::Vector3d>& v, const std::vector<Eigen::Vector2d>& vt,
                  const std::vector<std::array<std::size_t, 6> >& f, Xatlas_run& run)
{
  Union_find sets(vt.size());
  for(const auto& face : f)
  {
    sets.unite(face[3], face[4]);
    sets.unite(face[4], face[5]);
  }
  std::map<std::size_t, std::size_t> chart_of_root;
  std::vector<std::size_t> local(vt.size(), std::size_t(-1));
  for(const auto& face : f)
  {
    const std::size_t root = sets.find(face[3]);
    const std::size_t c = chart_of_root.emplace(root, chart_of_root.size()).first->second;
    if(c == run.charts.size())
      run.charts.emplace_back();
    SMP::internal::Chart_to_pack& chart = run.charts[c];
    SMP::internal::Face_indices t;
    for(int k = 0; k < 3; ++k)
    {
      std::size_t& l = local[face[std::size_t(k + 3)]];
      if(l == std::size_t(-1))
      {
        l = chart.uv.size();
        const Eigen::Vector2d& p = vt[face[std::size_t(k + 3)]];
        chart.uv.emplace_back(p.x() * run.width, p.y() * run.height);
      }
      t[std::size_t(k)] = int(l);
    }
    chart.triangles.push_back(t);
    chart.area_3d += triangle_area_3(v[face[0]], v[face[1]], v[face[2]]);
  }
  for(const SMP::internal::Chart_to_pack& chart : run.charts)
    run.uv_texels += SMP::internal::triangle_set_area(chart.uv, chart.triangles);
}

// Runs xatlas on the mesh, parses its line, reads its charts.
Xatlas_run run_xatlas(const Options& options, const fs::path& mesh, const fs::path& work)
{
  Xatlas_run run;
  const fs::path obj = work / (mesh.stem().string() + ".obj"), log = work / (mesh.stem().string() + ".txt");
  const std::string command = "'" + options.xatlas + "' '" + mesh.string() + "' '" + obj.string() + "' > '" +
                              log.string() + "' 2>&1";
  const bool cached = !options.cache.empty() && fs::exists(obj) && fs::exists(log);
  if(!cached && std::system(command.c_str()) != 0)
    return run;
  std::ifstream in(log);
  std::string word;
  while(in >> word)
    if(word.find('=') != std::string::npos)
      run.fields[word.substr(0, word.find('='))] = word.substr(word.find('=') + 1);
  const std::string atlas = run.fields["atlas"];
  if(atlas.find('x') == std::string::npos)
    return run;
  run.width = std::stoi(atlas.substr(0, atlas.find('x')));
  run.height = std::stoi(atlas.substr(atlas.find('x') + 1));
  std::vector<Eigen::Vector3d> v;
  std::vector<Eigen::Vector2d> vt;
  std::vector<std::array<std::size_t, 6> > f;
  if(!read_obj(obj.string(), v, vt, f))
    return run;
  group_charts(v, vt, f, run);
  run.ok = true;
  return run;
}

double median(std::vector<double> values)
{
  std::sort(values.begin(), values.end());
  return values.empty() ? 0. : values[values.size() / 2];
}

// The package's packer: the packing of the last run, the median time.
struct Raster_figures
{
  SMP::internal::Atlas_packing packing;
  double seconds = 0.;      // wall clock (the packer's own statistics)
  double cpu_seconds = 0.;  // processor time of this process
  std::string check;
};

Raster_figures run_raster(const Options& options, const std::vector<SMP::internal::Chart_to_pack>& charts)
{
  Raster_figures figures;
  std::vector<double> seconds, cpu;
  for(int r = 0; r < std::max(1, options.runs); ++r)
  {
    const std::clock_t start = std::clock();
    figures.packing = SMP::internal::pack_atlas_charts(charts, options.packing);
    cpu.push_back(double(std::clock() - start) / CLOCKS_PER_SEC);
    seconds.push_back(figures.packing.statistics.seconds);
  }
  figures.seconds = median(seconds);
  figures.cpu_seconds = median(cpu);
  if(options.check && figures.packing.status == SMP::OK)
  {
    std::vector<std::vector<SMP::internal::Face_indices> > faces;
    for(const SMP::internal::Chart_to_pack& chart : charts)
      faces.push_back(chart.triangles);
    const double gutter = double(options.packing.gutter) / double(options.packing.resolution);
    const mbp_atlas_check::Atlas_check c = mbp_atlas_check::check_atlas(figures.packing.uv, faces, gutter);
    std::ostringstream s;
    s << c.overlapping_pairs << "/" << c.close_pairs << "/" << c.outside << "/" << c.near_border << " (min "
      << std::setprecision(3)
      << c.min_distance * options.packing.resolution << " texels)";
    figures.check = s.str();
  }
  return figures;
}

#ifdef MBP_HAS_LIBNEST2D
// libnest2d on the convex hulls of the normalized charts.
struct Nest_figures
{
  double utilization = 0.;
  double seconds = 0.;
  int attempts = 0;
  bool stopped = false;  // the time limit ended the search
};

constexpr double nest_units = 1000.;  // libnest2d's integer units per texel

// The charts' normalized convex hulls, clockwise (libnest2d's orientation).
std::vector<std::vector<Eigen::Vector2d> > normalized_hulls(const std::vector<SMP::internal::Chart_to_pack>& charts,
                                                            const std::vector<SMP::internal::Packing_chart>& packed)
{
  std::vector<std::vector<Eigen::Vector2d> > hulls(charts.size());
  for(std::size_t c = 0; c < charts.size(); ++c)
  {
    std::vector<Eigen::Vector2d> points;
    for(const Eigen::Vector2d& p : charts[c].uv)
      points.push_back(packed[c].scale * packed[c].box.rotate(p) - packed[c].low);
    SMP::internal::convex_hull(points, hulls[c]);
    std::reverse(hulls[c].begin(), hulls[c].end());
  }
  return hulls;
}

// A chart's item at the global scale: its hull, or a one-texel square for a hull without area.
libnest2d::Item nest_item(const std::vector<Eigen::Vector2d>& hull, double texels_per_unit)
{
  ClipperLib::Path path;
  for(const Eigen::Vector2d& p : hull)
    path.emplace_back(ClipperLib::cInt(std::llround(p.x() * texels_per_unit * nest_units)),
                      ClipperLib::cInt(std::llround(p.y() * texels_per_unit * nest_units)));
  if(path.size() < 3 || std::abs(ClipperLib::Area(path)) < nest_units * nest_units)
  {
    const ClipperLib::cInt u = ClipperLib::cInt(nest_units);
    path = ClipperLib::Path{{0, 0}, {0, u}, {u, u}, {u, 0}};
  }
  path.push_back(path.front());
  return libnest2d::Item(path);
}

// Whether every item goes into one bin at the global scale.
bool nest_at_scale(const std::vector<std::vector<Eigen::Vector2d> >& hulls, double texels_per_unit,
                   const Options& options)
{
  std::vector<libnest2d::Item> items;
  for(const auto& hull : hulls)
    items.push_back(nest_item(hull, texels_per_unit));
  // items are kept min_obj_distance / 2 from the bin's border: a bin of the atlas less one
  // gutter keeps the atlas's gutter to its border
  const libnest2d::Coord side =
      libnest2d::Coord((options.packing.resolution - options.packing.gutter) * nest_units);
  const libnest2d::Box bin(side, side, {side / 2, side / 2});
  const libnest2d::Coord distance = libnest2d::Coord(options.packing.gutter * nest_units);
  std::size_t bins = 0;
  if(options.placer == "nfp")
  {
    libnest2d::NestConfig<libnest2d::NfpPlacer, libnest2d::FirstFitSelection> config;
    config.placer_config.parallel = false;
    config.placer_config.rotations = {0., libnest2d::Pi / 2, libnest2d::Pi, 3 * libnest2d::Pi / 2};
    bins = libnest2d::nest<libnest2d::NfpPlacer, libnest2d::FirstFitSelection>(items, bin, distance, config);
  }
  else
  {
    libnest2d::NestConfig<libnest2d::BottomLeftPlacer, libnest2d::FirstFitSelection> config;
    config.placer_config.allow_rotations = true;
    bins = libnest2d::nest<libnest2d::BottomLeftPlacer, libnest2d::FirstFitSelection>(items, bin, distance, config);
  }
  for(const libnest2d::Item& item : items)
    if(item.binId() != 0)
      return false;
  return bins == 1;
}

// The largest density at which libnest2d puts every chart into one bin: from `seed` (the
// package's density, texels per unit), down by 0.9 until one fits, then bisection to the
// package's tolerance; stopped after --nest-seconds with the best density found.
Nest_figures run_nest(const Options& options, const std::vector<SMP::internal::Chart_to_pack>& charts, double seed)
{
  const auto start = std::chrono::steady_clock::now();
  const auto elapsed = [&start] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  std::vector<SMP::internal::Packing_chart> packed;
  double area = 0.;
  for(const SMP::internal::Chart_to_pack& chart : charts)
  {
    packed.push_back(SMP::internal::normalize_chart(chart));
    area += packed.back().degenerate ? 0. : chart.area_3d;
  }
  const std::vector<std::vector<Eigen::Vector2d> > hulls = normalized_hulls(charts, packed);
  Nest_figures figures;
  double low = 0., high = HUGE_VAL;
  for(double scale = seed; low == 0. && scale > 0.05 * seed && !figures.stopped; scale *= 0.9)
  {
    ++figures.attempts;
    (nest_at_scale(hulls, scale, options) ? low : high) = scale;
    figures.stopped = elapsed() > options.nest_seconds;
  }
  while(low > 0. && high > low * (1. + options.packing.density_tolerance) && !figures.stopped)
  {
    const double scale = high == HUGE_VAL ? low * 1.05 : std::sqrt(low * high);
    ++figures.attempts;
    (nest_at_scale(hulls, scale, options) ? low : high) = scale;
    figures.stopped = elapsed() > options.nest_seconds;
  }
  const double texel = low / options.packing.resolution;
  figures.utilization = area * texel * texel;
  figures.seconds = elapsed();
  return figures;
}
#endif

bool parse(int argc, char** argv, Options& options)
{
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    const auto value = [&a] { return a.substr(a.find('=') + 1); };
    if(a.rfind("--meshes=", 0) == 0)
      options.meshes = value();
    else if(a.rfind("--xatlas=", 0) == 0)
      options.xatlas = value();
    else if(a.rfind("--resolution=", 0) == 0)
      options.packing.resolution = std::stoi(value());
    else if(a.rfind("--gutter=", 0) == 0)
      options.packing.gutter = std::stoi(value());
    else if(a == "--no-nest")
      options.nest = false;
    else if(a.rfind("--nest-seconds=", 0) == 0)
      options.nest_seconds = std::stod(value());
    else if(a.rfind("--placer=", 0) == 0)
      options.placer = value();
    else if(a.rfind("--cache=", 0) == 0)
      options.cache = value();
    else if(a == "--check")
      options.check = true;
    else if(a.rfind("--runs=", 0) == 0)
      options.runs = std::stoi(value());
    else if(a.rfind("--", 0) == 0)
      return false;
    else
      options.only.push_back(a);
  }
  return !options.meshes.empty() && !options.xatlas.empty();
}

std::vector<fs::path> mesh_files(const Options& options)
{
  std::vector<fs::path> files;
  for(const auto& entry : fs::directory_iterator(options.meshes))
  {
    const std::string ext = entry.path().extension().string();
    const std::string name = entry.path().filename().string();
    const bool wanted = options.only.empty() ||
                        std::find(options.only.begin(), options.only.end(), name) != options.only.end();
    if(entry.is_regular_file() && ext != ".md" && name != "LICENSES" && wanted)
      files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

void print_header(const Options& options)
{
  std::cout << "resolution " << options.packing.resolution << ", gutter " << options.packing.gutter
            << " texels; libnest2d placer " << options.placer << "\n\n"
            << "| mesh | faces | charts | xatlas util (printed / exact / square) | xatlas s | raster util | "
               "raster s (raster + placement) | raster CPU s | attempts | libnest2d util | libnest2d s |"
            << (options.check ? " check (overlaps/close/outside/near border) |" : "") << "\n"
            << "|---|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|" << (options.check ? "---|" : "") << "\n";
}

// One row of the table.
void measure_mesh(const Options& options, const fs::path& mesh, const fs::path& work)
{
  const Xatlas_run x = run_xatlas(options, mesh, work);
  std::cout << "| " << mesh.filename().string() << " | ";
  if(!x.ok)
  {
    std::cout << "xatlas failed |\n";
    return;
  }
  const double w = x.width, h = x.height, side = std::max(w, h);
  const Raster_figures r = run_raster(options, x.charts);
  std::cout << std::fixed << x.fields.at("faces_out") << " | " << x.charts.size() << " | " << x.fields.at("utilization")
            << " / " << std::setprecision(4) << x.uv_texels / (w * h) << " / " << x.uv_texels / (side * side) << " | "
            << std::setprecision(3) << std::stod(x.fields.at("seconds")) << " | " << std::setprecision(4)
            << r.packing.utilization << (r.packing.status == SMP::OK ? "" : " (failed)") << " | "
            << std::setprecision(3) << r.seconds << " (" << r.packing.statistics.raster_seconds << " + "
            << r.packing.statistics.placement_seconds << ") | " << r.cpu_seconds << " | "
            << r.packing.statistics.attempts << " | ";
#ifdef MBP_HAS_LIBNEST2D
  if(options.nest)
  {
    const double seed = std::sqrt(r.packing.statistics.texel_density) * options.packing.resolution;
    const Nest_figures n = run_nest(options, x.charts, seed > 0. ? seed : 1.);
    std::cout << std::setprecision(4) << n.utilization << (n.stopped ? " (stopped)" : "") << " | "
              << std::setprecision(2) << n.seconds << " |";
  }
  else
    std::cout << "- | - |";
#else
  std::cout << "(no libnest2d) | - |";
#endif
  std::cout << (options.check ? " " + r.check + " |" : "") << std::endl;
}

} // namespace

int main(int argc, char** argv)
{
  Options options;
  if(!parse(argc, argv, options))
  {
    std::cerr << "usage: atlas_packing [--meshes=DIR] [--xatlas=PROGRAM] [--resolution=N] [--gutter=G] [--no-nest]\n"
                 "                     [--nest-seconds=S] [--placer=bl|nfp] [--check] [--runs=N] [NAME...]\n";
    return 2;
  }
  if(!fs::exists(options.xatlas) || !fs::is_directory(options.meshes))
  {
    std::cerr << "atlas_packing: xatlas (" << options.xatlas << ") or the meshes (" << options.meshes
              << ") not found\n";
    return 1;
  }
  const fs::path work = !options.cache.empty() ? fs::path(options.cache)
                        : fs::temp_directory_path() / ("mbp_atlas_packing_" + std::to_string(::getpid()));
  fs::create_directories(work);
  print_header(options);
  for(const fs::path& mesh : mesh_files(options))
    measure_mesh(options, mesh, work);
  std::error_code ec;
  if(options.cache.empty())
    fs::remove_all(work, ec);
  return 0;
}
