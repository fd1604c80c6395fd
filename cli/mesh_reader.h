// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// Input of the measured_parameterization program: strict streaming readers of OFF, OBJ, PLY
// (ASCII, binary little- and big-endian) and STL (ASCII and binary) into a polygon soup.
//
// - Regular files only: a FIFO, a device, a socket or a directory is refused by name (checked
//   with stat() before opening; opened with O_NONBLOCK, so that a FIFO swapped in between
//   never blocks, then checked again with fstat()).
// - Streaming: the file is read in blocks of `Input_file::block_size` bytes; no whole-file
//   read. A line longer than `max_line_length` is an error.
// - Bounded memory: the counts an OFF or PLY header announces, and every PLY list, must fit
//   in the bytes of the file (each entry takes at least one or two bytes), so the soup never
//   exceeds a small multiple of the file size; OBJ and STL grow with what they read, and the
//   file size (a regular file) bounds that too.
// - Strict: every number is parsed whole (std::from_chars), every index checked, every
//   message names the line (text) or the element (binary) and the problem.
// No CGAL here: the soup is plain arrays (mesh_input.h builds the mesh).

#ifndef MBP_CLI_MESH_READER_H
#define MBP_CLI_MESH_READER_H

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace mbp_cli {

/// A polygon soup: points in file order, and the faces as one array of 0-based point indices
/// (`face_end[i]` is one past the last corner of face `i`).
struct Polygon_soup
{
  std::vector<std::array<double, 3> > points;
  std::vector<std::uint32_t> corners;
  std::vector<std::uint32_t> face_end;

  std::size_t number_of_faces() const { return face_end.size(); }
  std::size_t face_begin(std::size_t i) const { return i == 0 ? 0 : face_end[i - 1]; }
  std::size_t face_size(std::size_t i) const { return face_end[i] - face_begin(i); }
};

/// Why reading failed: a message, and whether the problem is a non-finite coordinate (the
/// program then reports the library's code for it).
struct Read_error
{
  std::string message;
  bool non_finite = false;

  bool failed() const { return !message.empty(); }
};

/// checks that `path` names a regular file (after following links) that can be opened
/// without blocking: an empty string, or the message (a FIFO, a device, a directory...)
std::string check_regular_input(const std::string& path);

/// reads the polygon soup of the regular file `path` in the format of `extension` ("off",
/// "obj", "ply" or "stl", lowercase). On failure the message names the problem (the caller
/// names the file).
Read_error read_polygon_soup(const std::string& path, const std::string& extension, Polygon_soup& soup);

} // namespace mbp_cli

#endif // MBP_CLI_MESH_READER_H
