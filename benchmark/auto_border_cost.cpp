// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// Where the time of the automatic border (AUTOMATIC_BORDER) goes, on one mesh: the plain
// geodesic method and the automatic border as whole calls, and the pieces of the search, each
// alone on the patch's one factorization of L_II (median of 5 runs):
//
//   auto_border_cost MESH...
//
//   geodesic call    SMP::parameterize() with Measured_conformal_parameterizer_3<Mesh,
//                    Poisson_center_locator, Geodesic_border_distance<Mesh, Fast_marching_geodesics>>,
//                    NO_REPAIR
//   auto call        the default policies with set_border_choice(AUTOMATIC_BORDER); "search" is
//                    its report's search_seconds (last run)
//   solve 1 / 3      the interior back-substitution for 1 border (2 columns) and for a batch of
//                    3 borders (6 columns), right-hand side from the border included
//   assemble         the UV vector of the patch from the solution
//   one-to-one test  internal::is_one_to_one (exact orientation of every face; border curves)
//   angle objective  internal::Angle_distortion_objective::operator() (the paper's angle
//                    distortion), and its setup (once per call)
//   per border       solve 3 / 3 + assemble + test + objective; x13 = the 13 borders of a search
//
// The search also computes the second border's distances (fast marching, in a second thread)
// and places the blended borders; the rest of the auto call is the center, the policy's border
// (Poisson: the spring factorization) and the patch. See README.md, section Automatic border.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include <CGAL/Surface_mesh_parameterization/Geodesic_border_distance.h>
#include <CGAL/Surface_mesh_parameterization/Measured_conformal_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/internal/border_search.h>
#include <CGAL/Surface_mesh_parameterization/internal/repair.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

namespace SMP = CGAL::Surface_mesh_parameterization;
typedef CGAL::Simple_cartesian<double>                  K;
typedef CGAL::Surface_mesh<K::Point_3>                  Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor    vertex_descriptor;
typedef std::chrono::steady_clock                       Clock;
typedef SMP::Measured_conformal_parameterizer_3<Mesh, SMP::Poisson_center_locator<Mesh>,
                                                SMP::Geodesic_border_distance<Mesh> > Geodesic;
typedef SMP::Measured_conformal_parameterizer_3<Mesh>   Automatic;
typedef Geodesic::Patch                                 Patch;

namespace {

template <class F>
double median_seconds(F f, int runs = 5)
{
  std::vector<double> t;
  for(int i = 0; i < runs; ++i)
  {
    const Clock::time_point start = Clock::now();
    f();
    t.push_back(std::chrono::duration<double>(Clock::now() - start).count());
  }
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 2)
  {
    std::fprintf(stderr, "usage: %s MESH...\n", argv[0]);
    return 2;
  }
  std::printf("| mesh | V | geodesic call | auto call | auto / geodesic | search | solve 1 border | solve 3 borders |"
              " assemble | one-to-one test | angle objective | objective setup | per border | x13 | x13 / geodesic call |\n"
              "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for(int a = 1; a < argc; ++a)
  {
    Mesh mesh;
    if(!CGAL::IO::read_polygon_mesh(argv[a], mesh) || faces(mesh).empty())
    {
      std::fprintf(stderr, "cannot read %s\n", argv[a]);
      return 1;
    }
    const auto bhd = CGAL::Polygon_mesh_processing::longest_border(mesh).first;
    auto uvmap = mesh.add_property_map<vertex_descriptor, K::Point_2>("v:bench_uv").first;

    const double geodesic = median_seconds([&] {
      Geodesic p;
      p.set_repair(Geodesic::NO_REPAIR);
      SMP::parameterize(mesh, p, bhd, uvmap);
    });
    double search = 0.;
    const double automatic = median_seconds([&] {
      Automatic p;
      p.set_border_choice(Automatic::AUTOMATIC_BORDER);
      SMP::parameterize(mesh, p, bhd, uvmap);
      search = p.last_report().search_seconds;
    });

    Patch patch;
    if(patch.build_disk(mesh, bhd, get(CGAL::vertex_point, mesh)) != SMP::OK ||
       patch.factorize_interior_laplacian() != SMP::OK)
    {
      std::fprintf(stderr, "%s: not a disk, or L_II not factorized\n", argv[a]);
      return 1;
    }
    const std::vector<double> angles = SMP::internal::arc_length_angles(patch);
    const Eigen::Index m = static_cast<Eigen::Index>(patch.border().size());
    std::vector<Eigen::Vector2d> border_uv(static_cast<std::size_t>(m));
    for(Eigen::Index k = 0; k < m; ++k)
      border_uv[static_cast<std::size_t>(k)] =
        Eigen::Vector2d(std::cos(-angles[static_cast<std::size_t>(k)]), std::sin(-angles[static_cast<std::size_t>(k)]));
    Eigen::MatrixXd x;
    auto solve = [&](int borders) {
      Eigen::MatrixXd values(m, 2 * borders), rhs;
      for(int c = 0; c < borders; ++c)
        for(Eigen::Index k = 0; k < m; ++k)
        {
          values(k, 2 * c) = border_uv[static_cast<std::size_t>(k)].x();
          values(k, 2 * c + 1) = border_uv[static_cast<std::size_t>(k)].y();
        }
      patch.interior_rhs_from_border(values, rhs);
      patch.solve_interior(rhs, x);
    };
    const double solve1 = median_seconds([&] { solve(1); });
    const double solve3 = median_seconds([&] { solve(3); });
    solve(1);
    const std::vector<double> u(x.col(0).data(), x.col(0).data() + x.rows()), v(x.col(1).data(), x.col(1).data() + x.rows());
    std::vector<Eigen::Vector2d> uv;
    const double assemble = median_seconds([&] { SMP::internal::assemble_uv(patch, border_uv, u, v, uv); });
    bool valid = false;
    const double test = median_seconds([&] { valid = SMP::internal::is_one_to_one(patch, uv); });
    const SMP::internal::Angle_distortion_objective objective(patch);
    double value = 0.;
    const double evaluate = median_seconds([&] { value = objective(uv); });
    const double setup = median_seconds([&] { SMP::internal::Angle_distortion_objective o(patch); (void)o; });
    const double per_border = solve3 / 3. + assemble + test + evaluate;
    std::printf("| %s | %zu | %.4f | %.4f | %.2f | %.4f | %.4f | %.4f | %.5f | %.5f | %.4f | %.4f | %.4f | %.4f | %.2f |\n",
                argv[a], std::size_t(num_vertices(mesh)), geodesic, automatic, automatic / geodesic, search, solve1, solve3,
                assemble, test, evaluate, setup, per_border, 13. * per_border, 13. * per_border / geodesic);
    std::fflush(stdout);
    if(!valid || !(value >= 0.))
      std::fprintf(stderr, "%s: unexpected circle layout (valid %d, objective %g)\n", argv[a], int(valid), value);
  }
  return 0;
}
