// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_FIXED_CENTER_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_FIXED_CENTER_H

/// \file Fixed_center.h

#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>

#include <boost/graph/graph_traits.hpp>

#include <cstddef>

namespace CGAL {
namespace Surface_mesh_parameterization {

/// \ingroup PkgSurfaceMeshParameterizationMeasured
///
/// A center locator that returns a vertex chosen by the user (for example to reproduce a
/// figure, or to study the effect of the center as in the paper's Fig. 4).
///
/// \cgalModels `MeasuredCenterLocator`
///
/// \tparam TriangleMesh a model of `FaceGraph`.
template <class TriangleMesh>
class Fixed_center
{
public:
  /// Vertex type of the mesh.
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;

  /// creates a locator with no vertex: `locate_center()` then fails with
  /// `ERROR_WRONG_PARAMETER`.
  Fixed_center() : m_vertex(boost::graph_traits<TriangleMesh>::null_vertex()) { }

  /// creates a locator that always returns `v`.
  explicit Fixed_center(vertex_descriptor v) : m_vertex(v) { }

  /// the vertex this locator returns.
  vertex_descriptor vertex() const { return m_vertex; }

  /// stores in `center` the disk index of the user's vertex.
  /// \tparam Disk a model of `MeasuredDisk`.
  /// \return `OK`, or `ERROR_WRONG_PARAMETER` when the vertex is null, is not a vertex of
  ///         the disk, or lies on its border loop (the center must be interior).
  template <class Disk>
  Error_code locate_center(Disk& disk, std::size_t& center) const
  {
    if(!disk.contains(m_vertex))  // null, not in this component, or not a vertex of the mesh
      return ERROR_WRONG_PARAMETER;
    const int id = disk.index(m_vertex);
    if(id < 0 || disk.is_on_border(static_cast<std::size_t>(id)))
      return ERROR_WRONG_PARAMETER;
    center = static_cast<std::size_t>(id);
    return OK;
  }

private:
  vertex_descriptor m_vertex;
};

} // namespace Surface_mesh_parameterization
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_FIXED_CENTER_H
