// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// The fill-reducing ordering of CHOLMOD for the package's interior cotangent Laplacian L_II:
// AMD against METIS's nested dissection and SuiteSparse's own (NESDIS), with Eigen's
// SimplicialLDLT (AMD) as a reference.
//
//   cholmod_ordering [MESH:LEVELS ...]
//
// Each argument is a mesh file refined LEVELS times by 1-to-4 midpoint subdivision (default:
// bimba_i.obj:0 bimba_i.obj:1 bimba_i.obj:2 mask.off:3 from MESH_DIR, i.e. 45k, 179k, 714k
// and 2M vertices). Per mesh and solver: the first factorization (analysis + numeric), a
// second factorization of a matrix with the same pattern (CHOLMOD reuses its analysis), the
// nonzeros of the factor and the time of a two-column solve; minimum of 3 runs.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include <CGAL/Surface_mesh_parameterization/Cholmod_supernodal_cholesky_traits.h>

#include "benchmark_support.h"

#include <Eigen/Core>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#ifndef MBP_MESH_DIR
#define MBP_MESH_DIR ""
#endif

namespace SMP = CGAL::Surface_mesh_parameterization;
typedef CGAL::Simple_cartesian<double>             K;
typedef CGAL::Surface_mesh<K::Point_3>             Mesh;
typedef std::chrono::steady_clock                  Clock;
typedef SMP::Cholmod_supernodal_cholesky_traits    Cholmod;

namespace {

double seconds(Clock::time_point a) { return std::chrono::duration<double>(Clock::now() - a).count(); }

double load_average()
{
  std::ifstream in("/proc/loadavg");
  double l = 0.;
  in >> l;
  return l;
}

struct Timing
{
  double first = 1e300, again = 1e300, solve = 1e300;
  std::size_t nonzeros = 0;
};

Timing time_cholmod(const Eigen::SparseMatrix<double>& A, Cholmod::Ordering ordering)
{
  Timing t;
  const Eigen::MatrixXd B = Eigen::MatrixXd::Random(A.rows(), 2);
  for(int run = 0; run < 3; ++run)
  {
    Cholmod traits(ordering);
    Cholmod::Matrix M(static_cast<int>(A.rows()), static_cast<int>(A.cols()));
    M.eigen_object() = A;
    double D = 1.;
    Clock::time_point start = Clock::now();
    if(!traits.factor(M, D))
      return Timing();
    t.first = (std::min)(t.first, seconds(start));
    start = Clock::now();
    traits.factor(M, D);  // same pattern: the analysis is reused
    t.again = (std::min)(t.again, seconds(start));
    Eigen::MatrixXd X;
    start = Clock::now();
    traits.solve(B, X);
    t.solve = (std::min)(t.solve, seconds(start));
    t.nonzeros = traits.factor_nonzeros();
  }
  return t;
}

Timing time_ldlt(const Eigen::SparseMatrix<double>& A)
{
  Timing t;
  const Eigen::MatrixXd B = Eigen::MatrixXd::Random(A.rows(), 2);
  for(int run = 0; run < 3; ++run)
  {
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double> > ldlt;
    Clock::time_point start = Clock::now();
    ldlt.compute(A);
    t.first = (std::min)(t.first, seconds(start));
    start = Clock::now();
    ldlt.factorize(A);
    t.again = (std::min)(t.again, seconds(start));
    start = Clock::now();
    const Eigen::MatrixXd X = ldlt.solve(B);
    t.solve = (std::min)(t.solve, seconds(start));
    t.nonzeros = static_cast<std::size_t>(ldlt.matrixL().nestedExpression().nonZeros()) + std::size_t(A.rows());
  }
  return t;
}

} // namespace

int main(int argc, char** argv)
{
  std::vector<std::string> specs;
  for(int a = 1; a < argc; ++a)
    specs.push_back(argv[a]);
  if(specs.empty())
  {
    const std::string dir = MBP_MESH_DIR;
    specs = {dir + "/bimba_i.obj:0", dir + "/bimba_i.obj:1", dir + "/bimba_i.obj:2", dir + "/mask.off:3"};
  }
  std::printf("| mesh | V | L_II rows | solver | first factorization (s) | again, same pattern (s) | "
              "nnz(L) (M) | 2-column solve (s) | load |\n|---|---|---|---|---|---|---|---|---|\n");
  for(const std::string& spec : specs)
  {
    const std::size_t colon = spec.rfind(':');
    const std::string file = spec.substr(0, colon);
    const int levels = (colon == std::string::npos) ? 0 : std::atoi(spec.c_str() + colon + 1);
    Mesh mesh;
    if(!CGAL::IO::read_polygon_mesh(file, mesh))
    {
      std::fprintf(stderr, "cannot read %s\n", file.c_str());
      return EXIT_FAILURE;
    }
    for(int l = 0; l < levels; ++l)
    {
      Mesh refined;
      mbp_benchmark::midpoint_subdivision(mesh, refined);
      mesh = std::move(refined);
    }
    // L_II as the package assembles it (benchmark_support.h)
    Eigen::SparseMatrix<double> A;
    if(!mbp_benchmark::interior_cotangent_laplacian(mesh, CGAL::Polygon_mesh_processing::longest_border(mesh).first, A))
    {
      std::fprintf(stderr, "%s: not a disk\n", file.c_str());
      return EXIT_FAILURE;
    }
    const std::string name = file.substr(file.find_last_of('/') + 1) + (levels ? " x" + std::to_string(levels) : "");
    auto row = [&](const char* solver, const Timing& t) {
      std::printf("| %s | %zu | %ld | %s | %.3f | %.3f | %.2f | %.4f | %.1f |\n", name.c_str(),
                  std::size_t(num_vertices(mesh)), long(A.rows()), solver, t.first, t.again,
                  double(t.nonzeros) * 1e-6, t.solve, load_average());
      std::fflush(stdout);
    };
    row("Eigen LDLT (AMD)", time_ldlt(A));
    row("CHOLMOD AMD", time_cholmod(A, Cholmod::AMD));
    row("CHOLMOD METIS nested dissection", time_cholmod(A, Cholmod::NESTED_DISSECTION));
    row("CHOLMOD NESDIS (SuiteSparse)", time_cholmod(A, Cholmod::SUITESPARSE_NESTED_DISSECTION));
  }
  return EXIT_SUCCESS;
}
