# Copyright (c) 2026  The measured boundary parameterization authors.
# All rights reserved.
#
# This file is part of the measured boundary parameterization package for CGAL.
#
# SPDX-License-Identifier: GPL-3.0-or-later
#
# Author(s)     : The measured boundary parameterization authors

# mbp_detect_openblas_threads(TARGET PREFIX): whether the BLAS that CHOLMOD links is OpenBLAS,
# decided at configure time (never by a symbol lookup when the program runs). When it is,
# TARGET (CHOLMOD's INTERFACE target) gets the compile definition
# CGAL_SMP_USE_OPENBLAS_THREADS and links OpenBLAS itself, so that
# Cholmod_supernodal_cholesky_traits can call openblas_set_num_threads(); otherwise the BLAS is
# left alone. Used by the top CMakeLists.txt and by the installed package configuration
# (MeasuredParameterizationConfig.cmake), so that the decision is made again on the machine
# that uses the package. PREFIX names the cache variables:
#   ${PREFIX}_BLAS_LIBRARY       the BLAS found as `blas` (what CHOLMOD links: Debian's libblas.so
#                                is the BLAS alternative, OpenBLAS or the reference BLAS)
#   ${PREFIX}_OPENBLAS_LIBRARY   OpenBLAS's library (libopenblas), which exports
#                                openblas_set_num_threads()
# and the variable ${PREFIX}_OPENBLAS_THREADS (TRUE or FALSE) says what was decided.
# -DMBP_OPENBLAS_THREADS=OFF (or ${PREFIX}_OPENBLAS_THREADS=OFF) turns the detection off.
include(CheckCXXSourceCompiles)

# a program that links openblas_set_num_threads() (the check is a link, in C++: the projects
# that use this file may not enable C)
set(_mbp_openblas_probe [=[
extern "C" void openblas_set_num_threads(int);
int main() { openblas_set_num_threads(1); return 0; }
]=])

function(mbp_detect_openblas_threads target prefix)
  set(${prefix}_OPENBLAS_THREADS FALSE PARENT_SCOPE)
  if(DEFINED MBP_OPENBLAS_THREADS AND NOT MBP_OPENBLAS_THREADS)
    return()
  endif()
  find_library(${prefix}_BLAS_LIBRARY NAMES blas openblas
               DOC "the BLAS that CHOLMOD links (checked for OpenBLAS)")
  find_library(${prefix}_OPENBLAS_LIBRARY NAMES openblas
               DOC "OpenBLAS (openblas_set_num_threads) when it is the BLAS of CHOLMOD")
  set(blas "${${prefix}_BLAS_LIBRARY}")
  set(openblas "${${prefix}_OPENBLAS_LIBRARY}")
  if(NOT blas OR NOT openblas)
    return()
  endif()
  # The BLAS is OpenBLAS when the file it resolves to is OpenBLAS's (Debian: the alternative
  # libblas.so -> .../openblas-pthread/libblas.so.3; elsewhere libblas.so -> libopenblas.so),
  # or when it exports OpenBLAS's own function.
  get_filename_component(blas_real "${blas}" REALPATH)
  set(is_openblas FALSE)
  if(blas_real MATCHES "[Oo]pen[Bb][Ll][Aa][Ss]")
    set(is_openblas TRUE)
  else()
    set(CMAKE_REQUIRED_LIBRARIES "${blas}")
    set(CMAKE_REQUIRED_QUIET ON)
    check_cxx_source_compiles("${_mbp_openblas_probe}" MBP_BLAS_EXPORTS_OPENBLAS_SET_NUM_THREADS)
    set(is_openblas ${MBP_BLAS_EXPORTS_OPENBLAS_SET_NUM_THREADS})
  endif()
  if(NOT is_openblas)
    return()
  endif()
  # the function is linked from OpenBLAS's own library (it is the same library as the BLAS's)
  set(CMAKE_REQUIRED_LIBRARIES "${openblas}")
  set(CMAKE_REQUIRED_QUIET ON)
  check_cxx_source_compiles("${_mbp_openblas_probe}" MBP_OPENBLAS_LINKS_SET_NUM_THREADS)
  if(NOT MBP_OPENBLAS_LINKS_SET_NUM_THREADS)
    return()
  endif()
  if(TARGET ${target})
    set_property(TARGET ${target} APPEND PROPERTY INTERFACE_COMPILE_DEFINITIONS CGAL_SMP_USE_OPENBLAS_THREADS)
    set_property(TARGET ${target} APPEND PROPERTY INTERFACE_LINK_LIBRARIES "${openblas}")
  endif()
  set(${prefix}_OPENBLAS_THREADS TRUE PARENT_SCOPE)
endfunction()
