// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CORE_CONCURRENCY_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CORE_CONCURRENCY_H

// The one place where the package starts threads: only under CGAL::Parallel_tag (CGAL's
// convention; CGAL::Sequential_tag, the default, starts none).

#include <CGAL/tags.h>

#include <future>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

// Whether a concurrency tag asks for threads.
template <class ConcurrencyTag>
struct Is_parallel : std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag> {};

// Runs `f` in a new thread; the result is the future of its value.
template <class F>
auto start_thread(F&& f)
{
  return std::async(std::launch::async, std::forward<F>(f));
}

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CORE_CONCURRENCY_H
