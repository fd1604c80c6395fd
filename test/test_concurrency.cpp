// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// Concurrency (issue 15's edge, from test_edges.cpp): a call with CGAL::Sequential_tag starts
// no thread; one with CGAL::Parallel_tag does (the control that the check reaches the threaded
// paths), with the same result.
//
// The threads are counted from outside the library (issue 21: no test hooks in library
// code): this executable defines pthread_create, which counts each call and forwards it to
// the C library's (dlsym(RTLD_NEXT)). std::thread and std::async start their threads through
// it, from libstdc++; a thread whose start routine lies in libstdc++ is a C++ standard thread,
// the only kind the package starts (internal::start_thread is std::async). Threads that
// CHOLMOD's OpenMP or a threaded BLAS start on their own are counted apart.

#include <boost/test/unit_test.hpp>

#include "test_support.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Surface_mesh_parameterization/Conformal_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Default_sparse_cholesky_traits.h>
#include <CGAL/Surface_mesh_parameterization/main_border.h>
#include <CGAL/Surface_mesh_parameterization/Measured_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Parameterization_report.h>
#include <CGAL/Surface_mesh_parameterization/internal/borders/border_step.h>
#include <CGAL/Surface_mesh_parameterization/internal/core/disk.h>
#ifdef MBP_WITH_CHOLMOD
#include <CGAL/Surface_mesh_parameterization/Cholmod_supernodal_cholesky_traits.h>
#endif

#include <Eigen/Core>

#include <dlfcn.h>
#include <pthread.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <future>
#include <string>
#include <thread>
#include <vector>

BOOST_AUTO_TEST_SUITE(concurrency)

// ---------------------------------------------------------------- the thread counter

namespace {

std::atomic<long> all_threads{0};  // every pthread_create of the process
std::atomic<long> cpp_threads{0};  // those of std::thread / std::async

typedef int (*Pthread_create)(pthread_t*, const pthread_attr_t*, void* (*)(void*), void*);

} // namespace

// A sanitizer runtime linked statically (Clang's -fsanitize=address or thread) defines
// pthread_create as a weak alias of its interceptor, which this definition replaces: the
// interceptor is then called by its own name, so that the sanitizer still sees every thread.
extern "C" int __interceptor_pthread_create(pthread_t*, const pthread_attr_t*, void* (*)(void*), void*)
  __attribute__((weak));

namespace {

// the pthread_create this one forwards to: the sanitizer's interceptor, or the next
// definition after this executable (the C library's, or a shared sanitizer runtime's)
Pthread_create real_pthread_create()
{
  static const Pthread_create real =
    (__interceptor_pthread_create != nullptr)
      ? &__interceptor_pthread_create
      : reinterpret_cast<Pthread_create>(dlsym(RTLD_NEXT, "pthread_create"));
  return real;
}

// whether `start` lies in libstdc++ (std::thread's start routine)
bool is_cpp_thread_routine(void* (*start)(void*))
{
  Dl_info info;
  return dladdr(reinterpret_cast<void*>(start), &info) != 0 && info.dli_fname != nullptr &&
         std::strstr(info.dli_fname, "libstdc++") != nullptr;
}

} // namespace

extern "C" int pthread_create(pthread_t* thread, const pthread_attr_t* attr, void* (*start)(void*), void* arg) noexcept
{
  const Pthread_create real = real_pthread_create();
  if(real == nullptr)
    return EAGAIN;
  ++all_threads;
  if(is_cpp_thread_routine(start))
    ++cpp_threads;
  return real(thread, attr, start, arg);
}

namespace {

// The threads started while `f` runs: every thread, and the C++ standard threads.
struct Started
{
  long all = 0, cpp = 0;
};

template <class F>
Started threads_started_by(F&& f)
{
  const long all = all_threads, cpp = cpp_threads;
  f();
  return Started{all_threads - all, cpp_threads - cpp};
}

} // namespace

// ---------------------------------------------------------------- the tests

namespace SMP = CGAL::Surface_mesh_parameterization;
typedef CGAL::Simple_cartesian<double>                          K;
typedef CGAL::Surface_mesh<K::Point_3>                          Mesh;
typedef boost::graph_traits<Mesh>::vertex_descriptor            vertex_descriptor;
typedef boost::graph_traits<Mesh>::halfedge_descriptor          halfedge_descriptor;
typedef Mesh::Property_map<vertex_descriptor, K::Point_2>       UV_map;
typedef SMP::Default_sparse_cholesky_traits                     Traits;
typedef SMP::internal::Disk<Mesh, Traits>                       Disk;

namespace {

// largest |a - b| over the vertices
double uv_difference(const Mesh& m, UV_map a, UV_map b)
{
  double worst = 0.;
  for(vertex_descriptor v : vertices(m))
    worst = (std::max)(worst, std::hypot(a[v].x() - b[v].x(), a[v].y() - b[v].y()));
  return worst;
}

// More than 10000 interior vertices: with Parallel_tag, the multi-column solves split their
// columns over two threads.
Mesh large_curved_disk()
{
  mbp_test::Soup soup = mbp_test::hex_disk(60);
  for(auto& p : soup.points)
    p[2] = 0.3 * p[0] * p[0] - 0.2 * p[1] * p[1] + 0.1 * p[0] * p[1];
  return mbp_test::make_mesh<Mesh>(soup);
}

} // namespace

BOOST_AUTO_TEST_CASE(the_thread_counter_sees_the_threads_of_std_async)
{
  // the counter itself: what internal::start_thread does (std::async, launch::async)
  const Started s = threads_started_by([] {
    std::future<int> f = std::async(std::launch::async, [] { return 1; });
    BOOST_TEST(f.get() == 1);
  });
  BOOST_TEST(s.all == 1);
  BOOST_TEST(s.cpp == 1);
  const Started none = threads_started_by([] {});
  BOOST_TEST(none.all == 0);
}

BOOST_AUTO_TEST_CASE(a_sequential_call_starts_no_thread)
{
  Mesh m = large_curved_disk();
  const halfedge_descriptor bhd = SMP::main_border(m).first;

  // the steps that Conformal_parameterizer_3 composes, on a disk of the call's concurrency:
  // a Sequential_tag measured border step starts no thread and leaves the disk's later
  // multi-column solve (the automatic border's batch of candidate layouts) single-threaded;
  // with Parallel_tag the border step's preparation and that solve use a second thread (the
  // control that this solve reaches the threaded path)
  {
    const auto threads_of_the_border_and_a_batch = [&](bool parallel) {
      Disk disk(Traits(), parallel);
      BOOST_REQUIRE_EQUAL(disk.build_disk(m, bhd, get(CGAL::vertex_point, m)), SMP::OK);
      BOOST_REQUIRE(disk.interior_vertices().size() >= 10000u);
      SMP::Parameterization_report report;
      SMP::internal::Border_step<Disk> step(disk, report, parallel, true);
      const Started border = threads_started_by([&] {
        BOOST_REQUIRE_EQUAL(SMP::Measured_border<>().build(step), SMP::OK);
      });
      std::vector<Eigen::Vector2d> border_uv;
      BOOST_REQUIRE(step.members.border(SMP::MEASURED, 0., border_uv));
      Eigen::MatrixXd values = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(border_uv.size()), 4), rhs, x;
      for(std::size_t k = 0; k < border_uv.size(); ++k)
        values.row(static_cast<Eigen::Index>(k)) << border_uv[k].x(), border_uv[k].y(), 1., -border_uv[k].x();
      BOOST_REQUIRE(disk.systems().interior() != nullptr);
      disk.systems().interior()->rhs_from_fixed(values, rhs);
      const Started batch = threads_started_by([&] { BOOST_REQUIRE_EQUAL(disk.solve_interior(rhs, x), SMP::OK); });
      // the solve is right whatever the threads: constant border values give a constant
      BOOST_TEST((x.col(2).array() - 1.).abs().maxCoeff() < 1e-9);
      BOOST_TEST((x.col(3) + x.col(0)).cwiseAbs().maxCoeff() <= 1e-12 * x.col(0).cwiseAbs().maxCoeff());
      return std::make_pair(border, batch);
    };
    const auto sequential = threads_of_the_border_and_a_batch(false);
    BOOST_TEST(sequential.first.all == 0);
    BOOST_TEST(sequential.second.all == 0);
    const auto parallel = threads_of_the_border_and_a_batch(true);
    BOOST_TEST(parallel.first.cpp >= 1);
    BOOST_TEST(parallel.second.cpp >= 1);
  }

  // the complete parameterizer, measured and automatic border: Sequential_tag (the default)
  // against Parallel_tag
  const auto compare = [&](auto sequential, auto parallel, const std::string& border) {
    BOOST_TEST_CONTEXT("border " << border)
    {
      UV_map sequential_uv = mbp_test::new_uv_map(m, "v:sequential"), parallel_uv = mbp_test::new_uv_map(m, "v:parallel");
      SMP::Parameterization_report sequential_report, parallel_report;
      const Started s = threads_started_by([&] {
        BOOST_REQUIRE_EQUAL(SMP::parameterize(m, sequential, bhd, sequential_uv, &sequential_report), SMP::OK);
      });
      BOOST_TEST(s.all == 0);
      const Started p = threads_started_by([&] {
        BOOST_REQUIRE_EQUAL(SMP::parameterize(m, parallel, bhd, parallel_uv, &parallel_report), SMP::OK);
      });
      BOOST_TEST_MESSAGE("border " << border << ", Parallel_tag: " << p.cpp << " threads");
      BOOST_TEST(p.cpp >= 1);
      BOOST_TEST(uv_difference(m, sequential_uv, parallel_uv) == 0.);
      BOOST_TEST(sequential_report.has_center == parallel_report.has_center);
      BOOST_TEST(sequential_report.center == parallel_report.center);
      m.remove_property_map(sequential_uv);
      m.remove_property_map(parallel_uv);
    }
  };
  compare(SMP::Conformal_parameterizer_3<Mesh, SMP::Measured_border<> >(),
          SMP::Conformal_parameterizer_3<Mesh, SMP::Measured_border<>, CGAL::Default, CGAL::Parallel_tag>(), "measured");
  compare(SMP::Conformal_parameterizer_3<Mesh, SMP::Automatic_border<> >(),
          SMP::Conformal_parameterizer_3<Mesh, SMP::Automatic_border<>, CGAL::Default, CGAL::Parallel_tag>(), "automatic");

  // the drop-in measured border parameterizer (for CGAL's DCP): sequential too; Parallel_tag
  // prepares the border distance in a second thread
  const auto drop_in = [&](auto border) {
    UV_map border_uv = mbp_test::new_uv_map(m, "v:border");
    auto done = m.add_property_map<vertex_descriptor, bool>("v:done", false).first;
    auto index = m.add_property_map<vertex_descriptor, int>("v:index", 0).first;
    const Started s = threads_started_by([&] {
      BOOST_REQUIRE_EQUAL(border.parameterize(m, bhd, border_uv, index, done), SMP::OK);
    });
    m.remove_property_map(border_uv);
    m.remove_property_map(done);
    m.remove_property_map(index);
    return s;
  };
  BOOST_TEST(drop_in(SMP::Measured_border_parameterizer_3<Mesh>()).all == 0);
  BOOST_TEST(drop_in(SMP::Measured_border_parameterizer_3<Mesh, CGAL::Default, CGAL::Default, CGAL::Default,
                                                          CGAL::Parallel_tag>()).cpp >= 1);

#ifdef MBP_WITH_CHOLMOD
  {
    // CHOLMOD's OpenMP and a threaded BLAS under it may start threads of their own (the
    // traits set the BLAS's thread count, not the package's threads): the package's own
    // threads are counted
    typedef SMP::Conformal_parameterizer_3<Mesh, SMP::Automatic_border<>, SMP::Cholmod_supernodal_cholesky_traits>
      Cholmod;
    UV_map uv = mbp_test::new_uv_map(m, "v:cholmod");
    const Started s = threads_started_by([&] { BOOST_REQUIRE_EQUAL(SMP::parameterize(m, Cholmod(), bhd, uv), SMP::OK); });
    BOOST_TEST_MESSAGE("CHOLMOD, Sequential_tag: " << s.all - s.cpp << " threads not started by the package");
    BOOST_TEST(s.cpp == 0);
    m.remove_property_map(uv);
  }
#else
  BOOST_TEST_MESSAGE("CHOLMOD not available in this build: its sequential call not tested");
#endif
}

// The BLAS threads (issue 24): Cholmod_supernodal_cholesky_traits sets OpenBLAS's thread count
// before a factorization (blas_threads, default 1), or leaves it alone (0). Run when CMake
// found that the BLAS under CHOLMOD is OpenBLAS (CGAL_SMP_USE_OPENBLAS_THREADS); skipped, with
// the reason, otherwise.
boost::test_tools::assertion_result blas_threads_are_set(boost::unit_test::test_unit_id)
{
  boost::test_tools::assertion_result r(false);
#if defined(MBP_WITH_CHOLMOD) && defined(CGAL_SMP_USE_OPENBLAS_THREADS)
  r = true;
#elif defined(MBP_WITH_CHOLMOD)
  r.message() << "the BLAS under CHOLMOD is not OpenBLAS in this build: the traits leave it alone";
#else
  r.message() << "CHOLMOD not available in this build";
#endif
  return r;
}

BOOST_AUTO_TEST_CASE(cholmod_traits_set_the_blas_threads, *boost::unit_test::precondition(blas_threads_are_set))
{
#if defined(MBP_WITH_CHOLMOD) && defined(CGAL_SMP_USE_OPENBLAS_THREADS)
  typedef SMP::Cholmod_supernodal_cholesky_traits Cholmod;
  BOOST_TEST(Cholmod::sets_blas_threads());
  // a symmetric positive definite matrix (both triangles stored)
  const int n = 2000;
  Cholmod::Matrix A(n, n);
  for(int i = 0; i < n; ++i)
  {
    A.set_coef(i, i, 4., true);
    if(i > 0)
    {
      A.set_coef(i, i - 1, -1., true);
      A.set_coef(i - 1, i, -1., true);
    }
  }
  const int before = openblas_get_num_threads();
  const auto factor_with = [&](const Cholmod& traits) {
    Cholmod copy(traits);  // the parameterizers copy the traits they are given: so does this
    BOOST_TEST(copy.blas_threads() == traits.blas_threads());
    double D = 0.;
    BOOST_REQUIRE(copy.factor(A, D));
    return openblas_get_num_threads();
  };
  openblas_set_num_threads(2);
  const int two = openblas_get_num_threads();  // 2, or fewer on a machine of one core
  BOOST_TEST(Cholmod().blas_threads() == 1);
  BOOST_TEST(factor_with(Cholmod()) == 1);     // the default: one thread
  BOOST_TEST(factor_with(Cholmod(Cholmod::AMD, 0)) == 1);  // left alone
  openblas_set_num_threads(2);
  BOOST_TEST(factor_with(Cholmod(Cholmod::AMD, 0)) == two);  // left alone
  BOOST_TEST(factor_with(SMP::Cholmod_nested_dissection_cholesky_traits(1)) == 1);
  BOOST_TEST(factor_with(Cholmod(Cholmod::AMD, 2)) == two);
  BOOST_TEST(Cholmod(Cholmod::AMD, -3).blas_threads() == 0);
  openblas_set_num_threads(before);
#endif
}

BOOST_AUTO_TEST_SUITE_END()
