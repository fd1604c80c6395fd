// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// Uses the installed headers: the measured border inside CGAL's DCP on a small generated disk;
// with the component Cholmod (MBP_WITH_CHOLMOD, set by the target MeasuredParameterization::Cholmod)
// also the complete method solved by CHOLMOD, which must give the same UVs as Eigen's LDLT.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_conformal_map_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Measured_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Measured_conformal_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#ifdef MBP_WITH_CHOLMOD
#include <CGAL/Surface_mesh_parameterization/Cholmod_supernodal_cholesky_traits.h>
#include <CGAL/Surface_mesh_parameterization/Measured_conformal_parameterizer_3.h>
#endif

#include <algorithm>
#include <cmath>
#include <iostream>

typedef CGAL::Simple_cartesian<double> K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
namespace SMP = CGAL::Surface_mesh_parameterization;

int main()
{
  // a fan of 12 triangles around a raised center, then a ring of 24 outer vertices
  Mesh m;
  std::vector<Mesh::Vertex_index> inner, outer;
  const Mesh::Vertex_index c = m.add_vertex(K::Point_3(0, 0, 0.3));
  for(int j = 0; j < 12; ++j)
    inner.push_back(m.add_vertex(K::Point_3(0.5 * std::cos(j * CGAL_PI / 6), 0.5 * std::sin(j * CGAL_PI / 6), 0.1)));
  for(int j = 0; j < 12; ++j)
    outer.push_back(m.add_vertex(K::Point_3(std::cos(j * CGAL_PI / 6), 1.5 * std::sin(j * CGAL_PI / 6), 0.)));
  for(int j = 0; j < 12; ++j)
  {
    const int n = (j + 1) % 12;
    m.add_face(c, inner[j], inner[n]);
    m.add_face(inner[j], outer[j], outer[n]);
    m.add_face(inner[j], outer[n], inner[n]);
  }
  auto uv = m.add_property_map<Mesh::Vertex_index, K::Point_2>("v:uv").first;
  Mesh::Halfedge_index bhd;
  for(auto h : m.halfedges())
    if(m.is_border(h))
      bhd = h;
  SMP::Discrete_conformal_map_parameterizer_3<Mesh, SMP::Measured_border_parameterizer_3<Mesh> > dcp;
  SMP::Error_code status = SMP::parameterize(m, dcp, bhd, uv);
  SMP::Parameterization_report report;  // the paper's method in one call, with its report
  if(status == SMP::OK)
    status = SMP::parameterize(m, SMP::Measured_conformal_parameterizer_3<Mesh>(), bhd, uv, &report);
  std::cout << SMP::get_measured_error_message(status) << ", center " << report.center << "\n";
  if(status != SMP::OK || !report.has_center || Mesh::Vertex_index(Mesh::size_type(report.center)) != c)
    return 1;
#ifdef MBP_WITH_CHOLMOD
  auto uv_ldlt = m.add_property_map<Mesh::Vertex_index, K::Point_2>("v:ldlt").first;
  auto uv_cholmod = m.add_property_map<Mesh::Vertex_index, K::Point_2>("v:cholmod").first;
  SMP::Measured_conformal_parameterizer_3<Mesh> ldlt;
  SMP::Measured_conformal_parameterizer_3<Mesh, SMP::Poisson_center_locator, SMP::Poisson_border_distance,
                                          SMP::Cholmod_supernodal_cholesky_traits> cholmod;
  if(SMP::parameterize(m, ldlt, bhd, uv_ldlt) != SMP::OK || SMP::parameterize(m, cholmod, bhd, uv_cholmod) != SMP::OK)
    return 1;
  double difference = 0.;
  for(Mesh::Vertex_index v : m.vertices())
    difference = (std::max)(difference, std::sqrt(CGAL::squared_distance(uv_ldlt[v], uv_cholmod[v])));
  std::cout << "CHOLMOD: largest UV difference to LDLT " << difference << "\n";
  if(!(difference <= 1e-9))
    return 1;
#endif
  return 0;
}
