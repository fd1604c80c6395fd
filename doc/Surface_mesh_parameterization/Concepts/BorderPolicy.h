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

A border policy chooses the border polygon of `CGAL::Surface_mesh_parameterization::Conformal_parameterizer_3`
and of the drop-in border parameterizer `CGAL::Surface_mesh_parameterization::Border_parameterizer_3`,
as a compile-time template argument: the type tells what runs.

The package's models are the members of one family of borders (`Border_family`): each member
is a path of borders from the member itself to a convex border, along which the repair
blends, and the automatic policy searches over them. A policy holds its options (for the
measured border, its center locator and border distance) and is copied by the
parameterizers; it holds no state of the calls.

How a policy works during a call (`build()`, which adds its members to the family, and, for a
searching policy, `choose()`) is a protocol between the policies and the parameterizers of
this package on objects of the implementation: the concept is not meant to be modeled outside
the package. Users choose among the models and configure them.

\cgalHasModel `CGAL::Surface_mesh_parameterization::Circular_border`
\cgalHasModel `CGAL::Surface_mesh_parameterization::Conformal_border`
\cgalHasModel `CGAL::Surface_mesh_parameterization::Conformal_length_border`
\cgalHasModel `CGAL::Surface_mesh_parameterization::Measured_border<CenterLocator, BorderDistance>`
\cgalHasModel `CGAL::Surface_mesh_parameterization::Automatic_border<CenterLocator, BorderDistance>` (not for `Border_parameterizer_3`)
*/
class BorderPolicy
{
public:
  /// Copy constructor (parameterizers store their policy by value).
  BorderPolicy(const BorderPolicy&);
};
