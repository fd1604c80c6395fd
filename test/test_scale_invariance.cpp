// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// Scale invariance (issue 15's edge, from test_edges.cpp): results do not depend on the mesh's
// scale, from 1e-150 to 1e150: the UVs of every border policy, the quality figures, the
// distance maps and the reports' lengths are scaled exactly for a power of two, to 1e-12
// relative otherwise.

#include <boost/test/unit_test.hpp>

#include "test_support.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Surface_mesh_parameterization/Conformal_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Conformal_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/geodesic_distance_map.h>
#include <CGAL/Surface_mesh_parameterization/main_border.h>
#include <CGAL/Surface_mesh_parameterization/measure_quality.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_report.h>
#include <CGAL/Surface_mesh_parameterization/poisson_distance_map.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

BOOST_AUTO_TEST_SUITE(scale_invariance)

namespace SMP = CGAL::Surface_mesh_parameterization;
typedef CGAL::Simple_cartesian<double>                          K;
typedef CGAL::Surface_mesh<K::Point_3>                          Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor            vertex_descriptor;
typedef boost::graph_traits<Mesh>::halfedge_descriptor          halfedge_descriptor;
typedef Mesh::Property_map<vertex_descriptor, K::Point_2>       UV_map;
typedef Mesh::Property_map<vertex_descriptor, double>           Distance_map;
typedef SMP::Measured_conformal_parameterizer_3<Mesh>           Full;  // the paper's method

using mbp_test::scaling;
using mbp_test::Transform;

namespace {

struct Reference
{
  std::map<std::string, std::vector<K::Point_2> > uv;  // per border policy, by vertex index
  std::map<std::string, SMP::Parameterization_quality> quality;
  std::map<std::string, std::pair<bool, std::size_t> > center;  // (has_center, center) of the report
  std::vector<double> bpdm, pdm, geodesic, border_distances, edge_lengths, closed_lengths;
  double polar_scale = 0.;                            // UV length per unit of the mesh's length
};

// the border policies compared (the complete parameterizer with each)
const std::string choices[] = {"measured", "conformal", "automatic"};

// every figure of `a` against `b`, relative (the angle distortions, which vanish for a
// conformal map of a flat mesh, with a floor)
void check_same_quality(const SMP::Parameterization_quality& a, const SMP::Parameterization_quality& b, double tolerance)
{
  auto same = [tolerance](double x, double y) {
    return std::abs(x - y) <= tolerance * (std::max)({std::abs(x), std::abs(y), 1e-3});
  };
  BOOST_TEST(same(a.angle_distortion, b.angle_distortion), a.angle_distortion << " vs " << b.angle_distortion);
  BOOST_TEST(same(a.angle_distortion_per_corner, b.angle_distortion_per_corner));
  BOOST_TEST(same(a.quasi_conformal_mean, b.quasi_conformal_mean));
  BOOST_TEST(same(a.quasi_conformal_max, b.quasi_conformal_max));
  BOOST_TEST(same(a.l2_stretch, b.l2_stretch), a.l2_stretch << " vs " << b.l2_stretch);
  BOOST_TEST(same(a.linf_stretch, b.linf_stretch));
  // the area distortions are logarithms of ratios: an absolute difference is a relative one
  // of the ratios
  auto same_log = [tolerance](double x, double y) { return std::abs(x - y) <= tolerance * (std::max)({std::abs(x), std::abs(y), 1.}); };
  BOOST_TEST(same_log(a.area_distortion_mean, b.area_distortion_mean), a.area_distortion_mean << " vs " << b.area_distortion_mean);
  BOOST_TEST(same_log(a.area_distortion_max, b.area_distortion_max), a.area_distortion_max << " vs " << b.area_distortion_max);
  BOOST_TEST(a.flipped_faces == b.flipped_faces);
  BOOST_TEST(a.number_of_faces == b.number_of_faces);
  BOOST_TEST(a.number_of_vertices == b.number_of_vertices);
}

// One border policy on `m`: its UVs, figures and center into `r`, and its report.
template <class BorderPolicy>
SMP::Parameterization_report measure_policy(Mesh& m, halfedge_descriptor bhd, const std::string& name, Reference& r)
{
  UV_map uv = mbp_test::new_uv_map(m, "v:uv");
  const SMP::Conformal_parameterizer_3<Mesh, BorderPolicy> p;
  SMP::Parameterization_report report;
  BOOST_REQUIRE_EQUAL(SMP::parameterize(m, p, bhd, uv, &report), SMP::OK);
  for(vertex_descriptor v : vertices(m))
    r.uv[name].push_back(uv[v]);
  r.quality[name] = SMP::measure_quality(m, faces(m), uv);
  r.center[name] = std::make_pair(report.has_center, report.center);
  if(std::is_same<BorderPolicy, SMP::Measured_border<> >::value)
  {
    // the report's polar map gives the border UVs: origin + scale * distance * direction
    const std::vector<vertex_descriptor> border = mbp_test::border_loop_vertices(m, bhd);
    BOOST_REQUIRE_EQUAL(report.border_distances.size(), border.size());
    BOOST_REQUIRE_EQUAL(report.border_angles.size(), border.size());
    for(std::size_t k = 0; k < border.size(); ++k)
    {
      const double radius = report.polar_scale * report.border_distances[k];
      const K::Point_2 q = uv[border[k]];
      BOOST_TEST(std::abs(q.x() - (report.polar_origin[0] + radius * std::cos(-report.border_angles[k]))) <= 1e-12);
      BOOST_TEST(std::abs(q.y() - (report.polar_origin[1] + radius * std::sin(-report.border_angles[k]))) <= 1e-12);
    }
  }
  m.remove_property_map(uv);
  return report;
}

// Everything the package measures on `m` (the border policies' UVs and figures, the distance
// maps, the reports' lengths).
Reference measure_everything(Mesh& m)
{
  Reference r;
  const halfedge_descriptor bhd = SMP::main_border(m).first;
  const SMP::Parameterization_report measured = measure_policy<SMP::Measured_border<> >(m, bhd, "measured", r);
  r.border_distances = measured.border_distances;
  r.polar_scale = measured.polar_scale;
  measure_policy<SMP::Conformal_border>(m, bhd, "conformal", r);
  measure_policy<SMP::Automatic_border<> >(m, bhd, "automatic", r);

  // the drop-in conformal border parameterizer's report
  SMP::Conformal_border_parameterizer_3<Mesh> conformal;
  UV_map uv = mbp_test::new_uv_map(m, "v:border");
  auto done = m.add_property_map<vertex_descriptor, bool>("v:done", false).first;
  auto index = m.add_property_map<vertex_descriptor, int>("v:index", 0).first;
  SMP::Parameterization_report report;
  BOOST_REQUIRE_EQUAL(conformal.parameterize(m, bhd, uv, index, done, &report), SMP::OK);
  r.edge_lengths = report.edge_lengths;
  r.closed_lengths = report.closed_lengths;
  m.remove_property_map(uv);
  m.remove_property_map(done);
  m.remove_property_map(index);

  Distance_map f = mbp_test::new_distance_map(m, "v:f");
  const std::vector<vertex_descriptor> source(1, vertex_descriptor(0));
  BOOST_REQUIRE_EQUAL(SMP::boundary_poisson_distance_map(m, bhd, f), SMP::OK);
  for(vertex_descriptor v : vertices(m))
    r.bpdm.push_back(f[v]);
  BOOST_REQUIRE_EQUAL(SMP::poisson_distance_map(m, source, f), SMP::OK);
  for(vertex_descriptor v : vertices(m))
    r.pdm.push_back(f[v]);
  BOOST_REQUIRE_EQUAL(SMP::geodesic_distance_map(m, source, f), SMP::OK);
  for(vertex_descriptor v : vertices(m))
    r.geodesic.push_back(f[v]);
  m.remove_property_map(f);
  return r;
}

// `scaled` against `factor` times `reference`: exactly for a power of two, to 1e-12
// relative otherwise
void check_scaled_lengths(const std::vector<double>& scaled, const std::vector<double>& reference, double factor,
                          bool power_of_two, const std::string& what)
{
  BOOST_TEST_CONTEXT(what)
  {
    BOOST_REQUIRE_EQUAL(scaled.size(), reference.size());
    double largest = 0., worst = 0.;
    for(std::size_t i = 0; i < scaled.size(); ++i)
    {
      largest = (std::max)(largest, std::abs(reference[i]));
      worst = (std::max)(worst, std::abs(scaled[i] / factor - reference[i]));
      if(power_of_two)
        BOOST_TEST(scaled[i] == factor * reference[i]);
    }
    BOOST_TEST(largest > 0.);
    BOOST_TEST(worst <= 1e-12 * largest, "largest relative difference " << worst / largest);
  }
}

} // namespace

BOOST_AUTO_TEST_CASE(results_do_not_depend_on_the_scale_of_the_mesh)
{
  const std::vector<std::pair<double, bool> > factors{
    {std::ldexp(1., -490), true}, {std::ldexp(1., -270), true}, {std::ldexp(1., 260), true},
    {std::ldexp(1., 495), true}, {1e-150, false}, {1e-80, false}, {1e-6, false}, {1e6, false},
    {1e78, false}, {1e150, false}};
  for(const auto& named : {std::make_pair(std::string("planar grid"), mbp_test::square_grid(10)),
                           std::make_pair(std::string("curved disk"), mbp_test::bumpy_disk(6, 20))})
  {
    Mesh unit = mbp_test::make_mesh<Mesh>(named.second);
    const Reference reference = measure_everything(unit);
    for(const auto& [factor, power_of_two] : factors)
      BOOST_TEST_CONTEXT(named.first << " scaled by " << factor)
      {
        Mesh m = mbp_test::make_mesh<Mesh>(named.second, scaling(factor));
        const Reference scaled = measure_everything(m);
        for(const std::string& choice : choices)
          BOOST_TEST_CONTEXT("border " << choice)
          {
            BOOST_TEST((scaled.center.at(choice) == reference.center.at(choice)));
            double worst = 0.;
            CGAL::Bbox_2 box;
            for(std::size_t i = 0; i < num_vertices(m); ++i)
            {
              const K::Point_2 &a = scaled.uv.at(choice)[i], &b = reference.uv.at(choice)[i];
              worst = (std::max)(worst, std::hypot(a.x() - b.x(), a.y() - b.y()));
              box += b.bbox();
            }
            const double diameter = std::hypot(box.xmax() - box.xmin(), box.ymax() - box.ymin());
            BOOST_TEST(worst <= 1e-12 * diameter, "UV difference " << worst / diameter << " of the diameter");
            if(power_of_two)
              BOOST_TEST(worst == 0.);
            check_same_quality(scaled.quality.at(choice), reference.quality.at(choice), 1e-12);
          }
        check_scaled_lengths(scaled.bpdm, reference.bpdm, factor, power_of_two, "boundary Poisson distance map");
        check_scaled_lengths(scaled.pdm, reference.pdm, factor, power_of_two, "Poisson distance map");
        check_scaled_lengths(scaled.geodesic, reference.geodesic, factor, power_of_two, "geodesic distance map");
        check_scaled_lengths(scaled.border_distances, reference.border_distances, factor, power_of_two,
                             "measured border report: border distances");
        check_scaled_lengths(std::vector<double>(1, 1. / scaled.polar_scale), std::vector<double>(1, 1. / reference.polar_scale),
                             factor, power_of_two, "measured border report: polar scale (UV length per unit of length)");
        check_scaled_lengths(scaled.edge_lengths, reference.edge_lengths, factor, power_of_two,
                             "conformal border report: edge lengths");
        check_scaled_lengths(scaled.closed_lengths, reference.closed_lengths, factor, power_of_two,
                             "conformal border report: closed lengths");
      }
  }
}

BOOST_AUTO_TEST_CASE(quality_figures_do_not_depend_on_the_scale_of_the_mesh_or_of_the_uvs)
{
  Mesh unit = mbp_test::make_mesh<Mesh>(mbp_test::bumpy_disk(6, 20));
  UV_map uv = mbp_test::new_uv_map(unit, "v:uv");
  const Full p;
  BOOST_REQUIRE_EQUAL(SMP::parameterize(unit, p, SMP::main_border(unit).first, uv), SMP::OK);
  const SMP::Parameterization_quality reference = SMP::measure_quality(unit, faces(unit), uv);
  BOOST_TEST(reference.angle_distortion > 1e-3);  // a curved disk: the figures are not trivial
  for(double mesh_factor : {1e-150, 1e-80, 1., 1e78, 1e150})
    for(double uv_factor : {1e-150, 1e-6, 1., 1e150})
      BOOST_TEST_CONTEXT("mesh scaled by " << mesh_factor << ", UVs by " << uv_factor)
      {
        Mesh m = mbp_test::make_mesh<Mesh>(mbp_test::bumpy_disk(6, 20), scaling(mesh_factor));
        UV_map scaled = mbp_test::new_uv_map(m, "v:uv");
        for(vertex_descriptor v : vertices(m))
          scaled[v] = K::Point_2(uv[v].x() * uv_factor, uv[v].y() * uv_factor);
        check_same_quality(SMP::measure_quality(m, faces(m), scaled), reference, 1e-12);
      }
}

BOOST_AUTO_TEST_SUITE_END()
