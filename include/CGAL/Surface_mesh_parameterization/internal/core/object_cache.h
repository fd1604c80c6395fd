// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CORE_OBJECT_CACHE_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CORE_OBJECT_CACHE_H

// One object of each type, built on first request from an argument and shared afterwards:
// the measured border's policies share their center-independent work through it (a geodesic
// solver's precomputation serves the center locator and the border distance). Thread-safe:
// the distance policy's preparation may run in a second thread while the center is located.

#include <map>
#include <memory>
#include <mutex>
#include <typeindex>
#include <typeinfo>

namespace CGAL {
namespace Surface_mesh_parameterization {
namespace internal {

class Object_cache
{
public:
  Object_cache() = default;
  Object_cache(const Object_cache&) = delete;
  Object_cache& operator=(const Object_cache&) = delete;

  // the object of type T, constructed as T(argument) on the first request; a request made
  // while it is being constructed waits for it
  template <class T, class Argument>
  T& get(const Argument& argument)
  {
    std::unique_lock<std::mutex> lock(m_mutex);
    std::shared_ptr<void>& slot = m_objects[std::type_index(typeid(T))];
    if(!slot)
      slot = std::make_shared<T>(argument);
    return *static_cast<T*>(slot.get());
  }

private:
  std::mutex m_mutex;
  std::map<std::type_index, std::shared_ptr<void> > m_objects;
};

} // namespace internal
} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_INTERNAL_CORE_OBJECT_CACHE_H
