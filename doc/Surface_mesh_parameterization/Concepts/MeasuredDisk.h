// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

/*!
\ingroup PkgSurfaceMeshParameterizationConcepts
\cgalConcept

The disk that the measured border's policies (`MeasuredCenterLocator`, `MeasuredBorderDistance`)
work on during one call of a parameterizer: one connected component of the mesh, checked
(triangles, a disk with holes, finite coordinates, no degenerate face) and indexed, with the
Dirichlet systems that the steps of the call share. The parameterizers build it; a policy
receives it as a template argument and uses only what this concept names.

Local indices: the vertices of the disk are `0 .. number_of_vertices() - 1`, so that
generic code never relies on the mesh's own descriptors being integers. Holes are filled
virtually: each gets one virtual vertex (after the real ones, `is_virtual(i)`, no mesh vertex)
and a fan of virtual faces (after the real faces), so that every solve works on a topological
disk. Positions are stored divided by a power of two (`length_unit()`), exactly, so that no
result depends on the mesh's scale: lengths measured on the disk are in this unit.

The geometry is built once and only read: a policy may read it from a second thread (the
distance policy's `prepare()` runs concurrently with the center locator under
`CGAL::Parallel_tag`). The solves are not thread-safe, except `shared_object()`.

\cgalHasModel the type the package's parameterizers pass to the policies, one per call (an
implementation class of the package, `internal::Disk<TriangleMesh, SolverTraits>`, not part of
the API: a policy names it only through its template parameter `Disk`)

\sa `MeasuredCenterLocator`
\sa `MeasuredBorderDistance`
*/
class MeasuredDisk
{
public:
  /// \name Types
  /// @{

  /// the mesh's vertex type
  typedef unspecified_type vertex_descriptor;

  /// @}

  /// \name The checked disk (read only)
  /// @{

  /// number of vertices, virtual ones included
  std::size_t number_of_vertices() const;
  /// number of real vertices (the mesh's): local indices `0 .. number_of_real_vertices() - 1`
  std::size_t number_of_real_vertices() const;
  /// whether local vertex `i` fills a hole
  bool is_virtual(std::size_t i) const;
  /// the position of local vertex `i`, in the unit `length_unit()`
  const Eigen::Vector3d& point(std::size_t i) const;
  /// all positions
  const std::vector<Eigen::Vector3d>& points() const;
  /// the unit of the positions (a power of two)
  double length_unit() const;
  /// the faces as local index triples, oriented as in the mesh (real faces first)
  const std::vector<std::array<int, 3> >& faces_indices() const;
  /// per face, bit `k` set when the edge opposite corner `k` has no other face
  const std::vector<unsigned char>& single_edge_masks() const;
  /// the border loop, in the order of `halfedges_around_face(bhd)` from `source(bhd)`
  const std::vector<int>& border() const;
  /// whether local vertex `i` lies on the border loop
  bool is_on_border(std::size_t i) const;
  /// the interior vertices (every vertex off the border loop, hole fillings included), increasing
  const std::vector<int>& interior_vertices() const;
  /// the row of local vertex `i` among `interior_vertices()`, -1 on the border loop
  int interior_index(std::size_t i) const;
  /// the holes, each as its loop of local indices
  const std::vector<std::vector<int> >& hole_loops() const;
  /// whether local vertex `i` lies on a hole
  bool is_on_hole(std::size_t i) const;
  /// \f$ d_i = \sum_j w_{ij} \f$ for the cotangent weights
  const std::vector<double>& cotangent_row_sums() const;
  /// \f$ g_i \f$, the mean length of the edges at each vertex (the paper's Eq. 1)
  const std::vector<double>& mean_spoke_lengths() const;
  /// the mesh vertex of local index `i`
  vertex_descriptor vertex(std::size_t i) const;
  /// the local index of the mesh vertex `v`, -1 when `v` is not in the disk
  int index(vertex_descriptor v) const;
  /// whether `v` is a vertex of the disk (any descriptor value accepted)
  bool contains(vertex_descriptor v) const;

  /// @}

  /// \name The shared systems
  /// @{

  /// solves \f$ L_{II} x = b \f$, \f$ L_{II} \f$ the cotangent Laplacian with the border loop
  /// eliminated, factorized once per call for every step (one entry per interior vertex, in
  /// `interior_vertices()` order). A policy that needs this matrix must use it through the
  /// disk, so that it is factorized once.
  Error_code solve_interior(const std::vector<double>& b, std::vector<double>& x);
  /// the same for every column of `B`
  Error_code solve_interior(const Eigen::MatrixXd& B, Eigen::MatrixXd& X);
  /// factorizes the spring Laplacian (weights \f$ |x_i - x_j|^{-r} \f$) grounded at one
  /// vertex, unless it already is for this exponent; it does not depend on the center. The
  /// parameterizer frees it once the distances are measured.
  Error_code factorize_spring_laplacian(double exponent);
  /// the paper's Poisson distance map from `source` with the spring system: one value per
  /// local vertex, 0 at `source`, one back-substitution
  Error_code solve_spring_poisson(std::size_t source, double exponent, std::vector<double>& values);
  /// the object of type `T` shared by the policies of the call, constructed as `T(disk)` on
  /// the first request (thread-safe), for center-independent work that the center locator
  /// and the border distance share (a geodesic solver's precomputation)
  template <class T> T& shared_object();

  /// @}
};
