// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

#ifndef CGAL_SURFACE_MESH_PARAMETERIZATION_MEASURED_CONFORMAL_PARAMETERIZER_3_H
#define CGAL_SURFACE_MESH_PARAMETERIZATION_MEASURED_CONFORMAL_PARAMETERIZER_3_H

/// \file Measured_conformal_parameterizer_3.h
/// `Measured_conformal_parameterizer_3`, the paper's method: defined in
/// Conformal_parameterizer_3.h.

#include <CGAL/Surface_mesh_parameterization/Conformal_parameterizer_3.h>

#endif // CGAL_SURFACE_MESH_PARAMETERIZATION_MEASURED_CONFORMAL_PARAMETERIZER_3_H
