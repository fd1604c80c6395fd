// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// The packing of an atlas (internal/atlas/packing.h, issue 22): on generated charts (many
// small squares, long thin strips, degenerate charts, one huge chart among tiny ones,
// L-shapes) and on real charts (CGAL's fandisk cut into small isometrically unfolded charts),
// every packing is checked with test/atlas_check.h, which knows nothing of the packer: no two
// triangles of different charts meet, any two charts and every UV and the border of [0,1]^2
// are at least the gutter apart, every UV is in [0,1]^2, every chart is a similarity of its
// input (edge length ratios, no reflection), and UV area / 3D area is the same for every
// chart of positive areas.

#include <boost/test/unit_test.hpp>

#include "atlas_check.h"
#include "test_support.h"

#include <CGAL/Surface_mesh.h>
#include <CGAL/Simple_cartesian.h>

#include <CGAL/Surface_mesh_parameterization/internal/atlas/chart_split.h>
#include <CGAL/Surface_mesh_parameterization/internal/atlas/charts.h>
#include <CGAL/Surface_mesh_parameterization/internal/atlas/min_area_rectangle.h>
#include <CGAL/Surface_mesh_parameterization/internal/atlas/packing.h>

#include <Eigen/Core>

#include <algorithm>
#include <bitset>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

BOOST_AUTO_TEST_SUITE(atlas_packing)

namespace SMP = CGAL::Surface_mesh_parameterization;
typedef SMP::internal::Chart_to_pack          Chart;
typedef SMP::internal::Atlas_packing_options  Options;
typedef SMP::internal::Atlas_packing          Packing;
typedef SMP::internal::Face_indices           Face;

namespace {

// ---------------------------------------------------------------- generated charts

// A polygon given by its corners (counterclockwise, star-shaped from its first corner), fanned
// from that corner, turned by `angle`, moved by `shift`, with the 3D area `area_3d`.
Chart polygon_chart(const std::vector<Eigen::Vector2d>& corners, double angle, const Eigen::Vector2d& shift,
                    double area_3d)
{
  Chart c;
  const double co = std::cos(angle), si = std::sin(angle);
  for(const Eigen::Vector2d& p : corners)
    c.uv.push_back(Eigen::Vector2d(co * p.x() - si * p.y(), si * p.x() + co * p.y()) + shift);
  for(int i = 1; i + 1 < int(corners.size()); ++i)
    c.triangles.push_back(Face{{0, i, i + 1}});
  c.area_3d = area_3d;
  return c;
}

std::vector<Eigen::Vector2d> rectangle(double w, double h)
{
  return {Eigen::Vector2d(0., 0.), Eigen::Vector2d(w, 0.), Eigen::Vector2d(w, h), Eigen::Vector2d(0., h)};
}

// An L: a square of side 2 without its upper right quarter (fanned from its reentrant corner).
std::vector<Eigen::Vector2d> l_shape()
{
  return {Eigen::Vector2d(1., 1.), Eigen::Vector2d(0., 2.), Eigen::Vector2d(0., 0.), Eigen::Vector2d(2., 0.),
          Eigen::Vector2d(2., 1.)};
}

double uniform(std::mt19937& rng, double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }

// ---------------------------------------------------------------- the checks

struct Check_options
{
  Options packing;
  bool utilization_floor = false;  // whether `min_utilization` is asserted
  double min_utilization = 0.;
};

// Whether a chart has positive 3D and UV areas (the charts that share the texel density).
bool regular_chart(const Chart& c) { return c.area_3d > 0. && mbp_atlas_check::uv_area(c.uv, c.triangles) > 0.; }

void check_overlaps_and_gutters(const std::vector<Chart>& charts, const Packing& packing, const Options& options)
{
  std::vector<std::vector<Face> > faces;
  for(const Chart& c : charts)
    faces.push_back(c.triangles);
  const double gutter = double(options.gutter) / double(options.resolution);
  const mbp_atlas_check::Atlas_check c = mbp_atlas_check::check_atlas(packing.uv, faces, gutter);
  BOOST_TEST(c.non_finite == 0u);
  BOOST_TEST(c.outside == 0u);
  BOOST_TEST(c.near_border == 0u);
  BOOST_TEST(c.overlapping_pairs == 0u);
  BOOST_TEST(c.close_pairs == 0u);
  if(charts.size() > 1)
    BOOST_TEST(c.min_distance >= gutter - 1e-12);
}

// Every chart a similarity of its input; the charts of positive areas at one texel density.
void check_similarities_and_density(const std::vector<Chart>& charts, const Packing& packing)
{
  double density = 0.;
  for(std::size_t i = 0; i < charts.size(); ++i)
    BOOST_TEST_CONTEXT("chart " << i)
    {
      const mbp_atlas_check::Shape_check s =
          mbp_atlas_check::check_shape(charts[i].uv, packing.uv[i], charts[i].triangles, 1e-12);
      BOOST_TEST(s.reflected == 0u);
      BOOST_TEST(s.max_deviation <= 1e-9);
      if(!regular_chart(charts[i]))
        continue;
      const double d = mbp_atlas_check::uv_area(packing.uv[i], charts[i].triangles) / charts[i].area_3d;
      if(density == 0.)
        density = d;
      BOOST_TEST(std::abs(d / density - 1.) <= 1e-9);
    }
}

// Packs the charts and checks the result; returns the packing.
Packing pack_and_check(const std::vector<Chart>& charts, const Check_options& check = Check_options())
{
  const Packing packing = SMP::internal::pack_atlas_charts(charts, check.packing);
  BOOST_REQUIRE(packing.status == SMP::OK);
  BOOST_REQUIRE(packing.uv.size() == charts.size());
  BOOST_REQUIRE(packing.transforms.size() == charts.size());
  for(std::size_t i = 0; i < charts.size(); ++i)
    BOOST_REQUIRE(packing.uv[i].size() == charts[i].uv.size());
  check_overlaps_and_gutters(charts, packing, check.packing);
  check_similarities_and_density(charts, packing);
  double area = 0.;
  for(std::size_t i = 0; i < charts.size(); ++i)
    area += mbp_atlas_check::uv_area(packing.uv[i], charts[i].triangles);
  BOOST_TEST(std::abs(area - packing.utilization) <= 1e-9);
  BOOST_TEST(packing.utilization <= 1.);
  if(check.utilization_floor)
    BOOST_TEST(packing.utilization >= check.min_utilization);
  return packing;
}

// The box of a placed chart's UVs: (width, height).
Eigen::Vector2d placed_box(const std::vector<Eigen::Vector2d>& uv)
{
  Eigen::Vector2d low = uv.front(), high = uv.front();
  for(const Eigen::Vector2d& p : uv)
  {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  return high - low;
}

// ---------------------------------------------------------------- real charts

typedef CGAL::Simple_cartesian<double>     Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;

SMP::internal::Atlas_triangles triangles_of(const Mesh& mesh)
{
  SMP::internal::Atlas_triangles t;
  for(auto v : vertices(mesh))
    t.points.emplace_back(mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z());
  for(auto f : faces(mesh))
  {
    Face face{{0, 0, 0}};
    int k = 0;
    for(auto v : vertices_around_face(halfedge(f, mesh), mesh))
      face[std::size_t(k++)] = int(v);
    t.faces.push_back(face);
  }
  return t;
}

// Small charts of a face set: its parts of at most `largest` faces unfolded isometrically
// along a spanning tree (charts.h), each part split in two until its unfolding is one-to-one.
void unfolded_charts(const SMP::internal::Atlas_triangles& t, const std::vector<std::size_t>& faces,
                     std::size_t largest, std::vector<SMP::internal::Atlas_chart>& charts)
{
  for(const std::vector<std::size_t>& part : SMP::internal::edge_components(t, faces))
  {
    if(part.size() <= largest)
    {
      SMP::internal::Atlas_chart chart = SMP::internal::unfold_isometrically(t, part);
      if(part.size() == 1 || SMP::internal::is_one_to_one_chart(t, chart))
      {
        SMP::internal::chart_area_figures(t, chart);
        charts.push_back(chart);
        continue;
      }
    }
    const std::vector<std::array<int, 3> > neighbors = SMP::internal::subset_neighbors(t, part);
    for(const std::vector<std::size_t>& half : SMP::internal::split_for_bound(t, part, neighbors, SMP::SPLIT_BY_NORMALS, nullptr))
      unfolded_charts(t, half, largest, charts);
  }
}

} // namespace

// ---------------------------------------------------------------- tests

BOOST_AUTO_TEST_CASE(many_small_squares)
{
  // 600 squares of 3D areas 0.5 to 2 given at UV scales 0.1 to 10, turned at random: one
  // density, each square placed as an axis-aligned square (its smallest box)
  std::mt19937 rng(7);
  std::vector<Chart> charts;
  for(int i = 0; i < 600; ++i)
    charts.push_back(polygon_chart(rectangle(1., 1.), uniform(rng, 0., 6.3),
                                   Eigen::Vector2d(uniform(rng, -5., 5.), 0.), uniform(rng, 0.5, 2.)));
  for(std::size_t i = 0; i < charts.size(); ++i)
    for(Eigen::Vector2d& p : charts[i].uv)
      p *= std::pow(10., double(i % 3) - 1.);
  Check_options check;
  check.utilization_floor = true;
  check.min_utilization = 0.5;
  const Packing packing = pack_and_check(charts, check);
  for(std::size_t i = 0; i < charts.size(); ++i)
  {
    const Eigen::Vector2d box = placed_box(packing.uv[i]);
    BOOST_TEST(box.x() * box.y() == mbp_atlas_check::uv_area(packing.uv[i], charts[i].triangles),
               boost::test_tools::tolerance(1e-9));
  }
}

BOOST_AUTO_TEST_CASE(long_thin_strips_are_turned_to_their_smallest_box)
{
  // 40 strips 1 x 40 at random angles: placed axis-aligned (box aspect 40), so their boxes
  // do not waste the square
  std::mt19937 rng(11);
  std::vector<Chart> charts;
  for(int i = 0; i < 40; ++i)
    charts.push_back(polygon_chart(rectangle(40., 1.), uniform(rng, 0.1, 1.4), Eigen::Vector2d::Zero(), 40.));
  Check_options check;
  check.utilization_floor = true;
  check.min_utilization = 0.5;
  const Packing packing = pack_and_check(charts, check);
  for(std::size_t i = 0; i < charts.size(); ++i)
  {
    const Eigen::Vector2d box = placed_box(packing.uv[i]);
    BOOST_TEST(std::max(box.x(), box.y()) / std::min(box.x(), box.y()) == 40., boost::test_tools::tolerance(1e-6));
  }
}

BOOST_AUTO_TEST_CASE(degenerate_charts_get_finite_uvs_inside_the_square)
{
  std::vector<Chart> charts;
  for(int i = 0; i < 20; ++i)
    charts.push_back(polygon_chart(rectangle(2., 1.), 0.3 * i, Eigen::Vector2d::Zero(), 2.));
  charts.push_back(polygon_chart(rectangle(1., 1.), 0.2, Eigen::Vector2d::Zero(), 0.));  // no 3D area
  Chart collinear;  // no UV area, positive 3D area
  collinear.uv = {Eigen::Vector2d(0., 0.), Eigen::Vector2d(1., 1.), Eigen::Vector2d(3., 3.)};
  collinear.triangles = {Face{{0, 1, 2}}};
  collinear.area_3d = 1.;
  charts.push_back(collinear);
  Chart point;  // one UV, no triangle
  point.uv = {Eigen::Vector2d(5., -2.)};
  charts.push_back(point);
  Chart pinched;  // a triangle whose three corners are one point
  pinched.uv = {Eigen::Vector2d(1., 1.), Eigen::Vector2d(1., 1.), Eigen::Vector2d(1., 1.)};
  pinched.triangles = {Face{{0, 1, 2}}};
  charts.push_back(pinched);
  charts.push_back(Chart());  // no UV at all
  const Packing packing = pack_and_check(charts);
  BOOST_TEST(packing.statistics.degenerate_charts == 5u);
  for(std::size_t i = 20; i < charts.size(); ++i)
    BOOST_TEST(packing.transforms[i].degenerate);
  const Eigen::Vector2d zero_area_box = placed_box(packing.uv[20]);  // of zero 3D area: a point
  BOOST_TEST(zero_area_box.norm() == 0.);
  const double texel = 1. / double(Options().resolution);
  BOOST_TEST(placed_box(packing.uv[21]).maxCoeff() <= 4. * texel);  // scaled into half a texel, then grown
}

BOOST_AUTO_TEST_CASE(one_huge_chart_and_many_tiny_ones)
{
  std::mt19937 rng(3);
  std::vector<Chart> charts;
  charts.push_back(polygon_chart(rectangle(3., 2.), 0.7, Eigen::Vector2d::Zero(), 1e4));
  for(int i = 0; i < 400; ++i)
    charts.push_back(polygon_chart(rectangle(1., uniform(rng, 0.2, 1.)), uniform(rng, 0., 3.), Eigen::Vector2d::Zero(),
                                   uniform(rng, 1e-4, 1e-2)));
  const Packing packing = pack_and_check(charts);
  BOOST_TEST(packing.utilization >= 0.5);  // the huge chart alone is most of the atlas
}

BOOST_AUTO_TEST_CASE(l_shapes)
{
  std::mt19937 rng(5);
  std::vector<Chart> charts;
  for(int i = 0; i < 80; ++i)
    charts.push_back(polygon_chart(l_shape(), uniform(rng, 0., 6.3), Eigen::Vector2d(1., 2.), uniform(rng, 1., 9.)));
  Check_options check;
  check.utilization_floor = true;
  check.min_utilization = 0.45;
  pack_and_check(charts, check);
}

BOOST_AUTO_TEST_CASE(other_resolutions_and_gutters)
{
  std::mt19937 rng(13);
  std::vector<Chart> charts;
  for(int i = 0; i < 60; ++i)
    charts.push_back(i % 2 == 0 ? polygon_chart(l_shape(), uniform(rng, 0., 6.3), Eigen::Vector2d::Zero(), 3.)
                                : polygon_chart(rectangle(5., 1.), uniform(rng, 0., 6.3), Eigen::Vector2d::Zero(), 5.));
  // no gutter; a wide gutter at a small resolution; a resolution above the rasters' (their
  // gutter rounded up); an odd resolution
  const std::vector<std::pair<int, int> > cases = {{1024, 0}, {256, 4}, {4096, 3}, {1000, 1}, {64, 1}};
  for(const std::pair<int, int>& c : cases)
    BOOST_TEST_CONTEXT("resolution " << c.first << ", gutter " << c.second)
    {
      Check_options check;
      check.packing.resolution = c.first;
      check.packing.gutter = c.second;
      pack_and_check(charts, check);
    }
  Check_options no_turns;
  no_turns.packing.quarter_turns = false;
  BOOST_TEST(pack_and_check(charts, no_turns).statistics.turned_charts == 0u);
}

BOOST_AUTO_TEST_CASE(the_packing_depends_only_on_the_input)
{
  std::mt19937 rng(17);
  std::vector<Chart> charts;
  for(int i = 0; i < 200; ++i)
    charts.push_back(polygon_chart(i % 3 == 0 ? l_shape() : rectangle(uniform(rng, 1., 4.), 1.), uniform(rng, 0., 6.3),
                                   Eigen::Vector2d::Zero(), uniform(rng, 0.1, 3.)));
  const Packing first = SMP::internal::pack_atlas_charts(charts);
  const Packing second = SMP::internal::pack_atlas_charts(charts);
  BOOST_REQUIRE(first.status == SMP::OK);
  BOOST_TEST(first.utilization == second.utilization);
  bool same = true;
  for(std::size_t i = 0; i < charts.size(); ++i)
    same = same && first.uv[i] == second.uv[i];
  BOOST_TEST(same);
}

BOOST_AUTO_TEST_CASE(rotating_calipers_find_the_smallest_box)
{
  // against the smallest box over 100000 angles of [0, pi/2)
  std::mt19937 rng(19);
  for(int trial = 0; trial < 20; ++trial)
    BOOST_TEST_CONTEXT("point set " << trial)
    {
      std::vector<Eigen::Vector2d> points;
      for(int i = 0; i < 30; ++i)
        points.emplace_back(uniform(rng, -1., 1.) * (1. + trial), uniform(rng, -1., 1.));
      const SMP::internal::Min_area_rectangle box = SMP::internal::min_area_rectangle(points);
      double sampled = HUGE_VAL;
      for(int k = 0; k < 100000; ++k)
      {
        const double a = 1.5707963267948966 * k / 100000., c = std::cos(a), s = std::sin(a);
        Eigen::Vector2d low(HUGE_VAL, HUGE_VAL), high(-HUGE_VAL, -HUGE_VAL);
        for(const Eigen::Vector2d& p : points)
        {
          const Eigen::Vector2d q(c * p.x() - s * p.y(), s * p.x() + c * p.y());
          low = low.cwiseMin(q);
          high = high.cwiseMax(q);
        }
        sampled = std::min(sampled, (high - low).prod());
      }
      BOOST_TEST(box.width * box.height <= sampled * (1. + 1e-12));
      BOOST_TEST(box.width * box.height >= sampled * (1. - 1e-3));
      BOOST_TEST(box.width >= box.height);
      Eigen::Vector2d low(HUGE_VAL, HUGE_VAL), high(-HUGE_VAL, -HUGE_VAL);  // the rotation gives the box
      for(const Eigen::Vector2d& p : points)
      {
        low = low.cwiseMin(box.rotate(p));
        high = high.cwiseMax(box.rotate(p));
      }
      BOOST_TEST((high - low).x() == box.width, boost::test_tools::tolerance(1e-12));
      BOOST_TEST((high - low).y() == box.height, boost::test_tools::tolerance(1e-12));
    }
}

BOOST_AUTO_TEST_CASE(invalid_input_is_refused)
{
  const std::vector<Chart> square{polygon_chart(rectangle(1., 1.), 0., Eigen::Vector2d::Zero(), 1.)};
  Options bad_resolution, bad_gutter;
  bad_resolution.resolution = 0;
  bad_gutter.gutter = -1;
  BOOST_TEST(SMP::internal::pack_atlas_charts(square, bad_resolution).status == SMP::ERROR_WRONG_PARAMETER);
  BOOST_TEST(SMP::internal::pack_atlas_charts(square, bad_gutter).status == SMP::ERROR_WRONG_PARAMETER);
  std::vector<Chart> out_of_range = square, not_finite = square, negative_area = square;
  out_of_range[0].triangles.push_back(Face{{0, 1, 4}});
  not_finite[0].uv[1].x() = std::nan("");
  negative_area[0].area_3d = -1.;
  BOOST_TEST(SMP::internal::pack_atlas_charts(out_of_range).status == SMP::ERROR_WRONG_PARAMETER);
  BOOST_TEST(SMP::internal::pack_atlas_charts(not_finite).status == SMP::ERROR_NON_FINITE_COORDINATES);
  BOOST_TEST(SMP::internal::pack_atlas_charts(negative_area).status == SMP::ERROR_NON_FINITE_COORDINATES);
  // more charts than a 16-texel square holds with a gutter of 2 texels (a chart and its
  // gutter take 5 x 5 texels at least)
  std::vector<Chart> crowd(20, square[0]);
  Options small;
  small.resolution = 16;
  BOOST_TEST(SMP::internal::pack_atlas_charts(crowd, small).status == SMP::ERROR_WRONG_PARAMETER);
  BOOST_TEST(SMP::internal::pack_atlas_charts(std::vector<Chart>()).status == SMP::OK);
}

BOOST_AUTO_TEST_CASE(real_charts_of_fandisk)
{
  // CGAL's fandisk cut into charts of at most 60 faces, each unfolded isometrically: real
  // triangle shapes, the charts of charts.h through chart_to_pack()
  Mesh mesh;
  mbp_test::read_mesh(mbp_test::core_mesh("fandisk.off"), mesh);
  const SMP::internal::Atlas_triangles t = triangles_of(mesh);
  std::vector<std::size_t> all(t.faces.size());
  for(std::size_t f = 0; f < all.size(); ++f)
    all[f] = f;
  std::vector<SMP::internal::Atlas_chart> atlas;
  unfolded_charts(t, all, 60, atlas);
  BOOST_REQUIRE(atlas.size() > 100u);
  std::vector<Chart> charts;
  for(const SMP::internal::Atlas_chart& c : atlas)
    charts.push_back(SMP::internal::chart_to_pack(c));
  Check_options check;
  check.utilization_floor = true;
  check.min_utilization = 0.5;
  const Packing packing = pack_and_check(charts, check);
  BOOST_TEST_MESSAGE("fandisk: " << charts.size() << " charts, utilization " << packing.utilization << ", "
                                 << packing.statistics.attempts << " attempts, " << packing.statistics.seconds << " s");
}

// The occupancy (placement.h) against a plain grid of booleans: masks made of random
// rectangles, placed one after the other, each at the first position (lowest row, then
// leftmost column) where every cell of the mask is free, which find() must report exactly
// (also when there is none). Sizes across one and several 64-bit words, bands up to 2^4 rows.
BOOST_AUTO_TEST_CASE(the_occupancy_finds_the_first_free_position)
{
  std::mt19937 random(7);
  for(int size : {37, 64, 100, 300})
    BOOST_TEST_CONTEXT("size " << size)
    {
      SMP::internal::Atlas_occupancy occupancy;
      occupancy.reset(size, 4);
      const std::vector<int> forever(occupancy.table_count(), std::numeric_limits<int>::max());
      occupancy.start(forever, forever);
      std::vector<char> taken(std::size_t(size) * std::size_t(size), 0);
      int placed = 0, refused = 0;
      for(int trial = 0; trial < 400 && refused < 5; ++trial)
      {
        std::uniform_int_distribution<int> side(1, std::max(2, size / 3));
        const int w = side(random), h = side(random);
        const int words = SMP::internal::words_for_bits(w);
        std::vector<std::uint64_t> bits(std::size_t(h) * std::size_t(words), 0);
        const SMP::internal::Raster_view cells{w, h, words, bits.data()};
        for(int k = 0; k < 3; ++k)  // a union of three rectangles in the w x h frame
        {
          std::uniform_int_distribution<int> x0(0, w - 1), y0(0, h - 1);
          const int xa = x0(random), ya = y0(random);
          const int xb = std::uniform_int_distribution<int>(xa, w - 1)(random);
          const int yb = std::uniform_int_distribution<int>(ya, h - 1)(random);
          for(int y = (k == 0 ? 0 : ya); y <= yb; ++y)
            for(int x = xa; x <= xb; ++x)
              cells.row(y)[x >> 6] |= std::uint64_t(1) << (x & 63);
        }
        std::vector<SMP::internal::Mask_run> runs;
        std::vector<SMP::internal::Mask_band> bands;
        std::vector<int> begin, end;
        SMP::internal::compute_mask_runs(cells, runs);
        SMP::internal::compute_mask_bands(cells, 4, bands, begin, end);
        const SMP::internal::Chart_mask mask{runs.data(), int(runs.size()), bands.data(), int(bands.size())};
        auto fits = [&](int px, int py) {
          for(int y = 0; y < h; ++y)
            for(int x = 0; x < w; ++x)
              if(cells.test(x, y) && taken[std::size_t(py + y) * std::size_t(size) + std::size_t(px + x)])
                return false;
          return true;
        };
        int ex = -1, ey = -1;
        for(int py = 0; py + h <= size && ex < 0; ++py)
          for(int px = 0; px + w <= size && ex < 0; ++px)
            if(fits(px, py))
              ex = px, ey = py;
        int reach = 0;
        const SMP::internal::Frame_position found = occupancy.find(mask, size - w, size - h, 0, reach);
        BOOST_TEST_REQUIRE(found.x == ex, "trial " << trial << ": x " << found.x << " against " << ex);
        if(ex < 0)
        {
          ++refused;
          continue;
        }
        BOOST_TEST_REQUIRE(found.y == ey, "trial " << trial << ": y " << found.y << " against " << ey);
        occupancy.place(cells, found.x, found.y);
        for(int y = 0; y < h; ++y)
          for(int x = 0; x < w; ++x)
            if(cells.test(x, y))
              taken[std::size_t(found.y + y) * std::size_t(size) + std::size_t(found.x + x)] = 1;
        ++placed;
      }
      BOOST_TEST(placed > 10);
      BOOST_TEST(refused > 0);  // the atlas filled up
    }
}

// The cells that rasterize_region() marks from a chart's border (chart_border(): equal UVs
// welded) against the union of rasterize_triangle() over its triangles, bit for bit: jittered
// grids with triangles down to a hundredth of a texel, each face with its own three UVs (as
// chart_to_pack() gives them), an annulus (a hole: a clockwise border loop), and grids with
// some triangles flipped (clockwise) or collapsed to a segment or a point.
BOOST_AUTO_TEST_CASE(a_region_rasterized_by_its_border_marks_the_cells_of_its_triangles)
{
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(0., 1.);
  int compared = 0, flipped_sets = 0;
  for(int trial = 0; trial < 60; ++trial)
  {
    const int n = 2 + trial % 7, width = 5 + int(unit(random) * 120.), height = 5 + int(unit(random) * 90.);
    const bool annulus = trial % 5 == 3, spoil = trial % 4 == 1;
    // the (n + 1) x (n + 1) grid points, jittered, in [1, width - 1] x [1, height - 1]
    std::vector<Eigen::Vector2d> grid;
    for(int i = 0; i <= n; ++i)
      for(int j = 0; j <= n; ++j)
      {
        const double a = (i + 0.3 * (unit(random) - 0.5) * (i > 0 && i < n)) / n;
        const double b = (j + 0.3 * (unit(random) - 0.5) * (j > 0 && j < n)) / n;
        const double r = annulus ? 0.4 + 0.6 * b : 0., t = 2. * CGAL_PI * a;
        const double x = annulus ? 0.5 + 0.5 * r * std::cos(t) : a, y = annulus ? 0.5 + 0.5 * r * std::sin(t) : b;
        grid.emplace_back(1. + x * (width - 2), 1. + y * (height - 2));
      }
    auto id = [n, annulus](int i, int j) { return (annulus ? i % n : i) * (n + 1) + j; };  // a ring closes
    Chart chart;  // each face its own three UVs
    for(int i = 0; i < n; ++i)
      for(int j = 0; j < n; ++j)
        for(const std::array<int, 3>& f : {std::array<int, 3>{{id(i, j), id(i + 1, j), id(i + 1, j + 1)}},
                                           std::array<int, 3>{{id(i, j), id(i + 1, j + 1), id(i, j + 1)}}})
        {
          const int first = int(chart.uv.size());
          for(int k : f)
            chart.uv.push_back(grid[std::size_t(k)]);
          chart.triangles.push_back({{first, first + 1, first + 2}});
        }
    if(spoil)  // flip a few triangles, collapse others to a segment or a point
    {
      ++flipped_sets;
      for(std::size_t f = 0; f < chart.triangles.size(); f += 5)
      {
        Face& t = chart.triangles[f];
        if(f % 3 == 0)
          std::swap(t[1], t[2]);
        else if(f % 3 == 1)
          chart.uv[std::size_t(t[2])] = 0.5 * (chart.uv[std::size_t(t[0])] + chart.uv[std::size_t(t[1])]);
        else
          chart.uv[std::size_t(t[1])] = chart.uv[std::size_t(t[2])] = chart.uv[std::size_t(t[0])];
      }
    }
    const int words = SMP::internal::words_for_bits(width);
    std::vector<std::uint64_t> by_border(std::size_t(height) * std::size_t(words), 0), by_triangles = by_border;
    const SMP::internal::Raster_view a{width, height, words, by_border.data()}, b{width, height, words, by_triangles.data()};
    std::vector<double> points;
    for(const Eigen::Vector2d& p : chart.uv)
    {
      points.push_back(p.x());
      points.push_back(p.y());
    }
    SMP::internal::Row_crossings rows;
    SMP::internal::rasterize_region(a, SMP::internal::chart_border(chart), chart.triangles, points.data(), rows);
    for(const Face& t : chart.triangles)
      SMP::internal::rasterize_triangle(b, &points[2 * std::size_t(t[0])], &points[2 * std::size_t(t[1])],
                                        &points[2 * std::size_t(t[2])]);
    std::size_t set = 0;
    for(std::size_t k = 0; k < by_border.size(); ++k)
      set += std::bitset<64>(by_triangles[k]).count();
    BOOST_TEST_REQUIRE((by_border == by_triangles), "trial " << trial << " (" << width << " x " << height << ", n " << n
                                                           << (annulus ? ", annulus" : "") << (spoil ? ", spoiled" : "") << ")");
    BOOST_TEST(set > 0u);
    ++compared;
  }
  BOOST_TEST(compared == 60);
  BOOST_TEST(flipped_sets == 15);
}

BOOST_AUTO_TEST_SUITE_END()
