// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// The readers of mesh_reader.h: one small strict reader per format. No CGAL here.

#include "mesh_reader.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <string_view>
#include <system_error>
#include <utility>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace mbp_cli {

namespace {

/// What kind of file system object `st` is, for a message ("a FIFO", "a directory", ...).
const char* file_kind(const struct stat& st)
{
  if(S_ISDIR(st.st_mode))
    return "a directory";
  if(S_ISFIFO(st.st_mode))
    return "a FIFO (named pipe)";
  if(S_ISCHR(st.st_mode))
    return "a character device";
  if(S_ISBLK(st.st_mode))
    return "a block device";
  if(S_ISSOCK(st.st_mode))
    return "a socket";
  if(S_ISLNK(st.st_mode))
    return "a symbolic link";
  return S_ISREG(st.st_mode) ? "a regular file" : "not a regular file";
}

/// A regular file opened for reading, read in blocks.
class Input_file
{
public:
  static constexpr std::size_t block_size = std::size_t(1) << 20;

  Input_file() = default;
  Input_file(const Input_file&) = delete;
  Input_file& operator=(const Input_file&) = delete;
  ~Input_file()
  {
    if(m_fd >= 0)
      ::close(m_fd);
  }

  /// opens `path`, a regular file (after following symbolic links). Returns the message of
  /// the failure, or an empty string.
  std::string open(const std::string& path)
  {
    struct stat st;
    if(::stat(path.c_str(), &st) != 0)
      return errno == ENOENT ? std::string("no such file") : std::string("cannot open: ") + std::strerror(errno);
    if(S_ISDIR(st.st_mode))
      return "it is a directory, not a mesh file";
    if(!S_ISREG(st.st_mode))
      return std::string("it is ") + file_kind(st) + ", not a regular file (only regular files are read)";
    // O_NONBLOCK: if a FIFO replaced the file since stat(), open() does not wait for a writer
    m_fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if(m_fd < 0)
      return std::string("cannot open: ") + std::strerror(errno);
    struct stat opened;
    if(::fstat(m_fd, &opened) != 0 || !S_ISREG(opened.st_mode))
      return "it is not a regular file (only regular files are read)";
    m_size = static_cast<std::uint64_t>(opened.st_size);
    return std::string();
  }

  std::uint64_t size() const { return m_size; }

  /// back to the first byte
  bool rewind() { return ::lseek(m_fd, 0, SEEK_SET) == 0; }

  /// reads up to `n` bytes; 0 at the end of the file, -1 on an error (errno set)
  long read(char* buffer, std::size_t n)
  {
    for(;;)
    {
      const ssize_t r = ::read(m_fd, buffer, n);
      if(r < 0 && errno == EINTR)
        continue;
      return static_cast<long>(r);
    }
  }

private:
  int m_fd = -1;
  std::uint64_t m_size = 0;
};

const std::size_t max_line_length = std::size_t(64) << 20;  // a face of millions of vertices still fits

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

/// The next whitespace-separated word of `rest` (empty at the end), removed from `rest`.
std::string_view next_word(std::string_view& rest)
{
  std::size_t i = 0;
  while(i < rest.size() && is_blank(rest[i]))
    ++i;
  std::size_t j = i;
  while(j < rest.size() && !is_blank(rest[j]))
    ++j;
  const std::string_view word = rest.substr(i, j - i);
  rest.remove_prefix(j);
  return word;
}

/// `s` for a message: at most 40 characters, control characters replaced.
std::string shown(std::string_view s)
{
  std::string t(s.substr(0, 40));
  for(char& c : t)
    if(static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
      c = '?';
  return s.size() > 40 ? t + "..." : t;
}

/// Buffered reading of a file: lines (text formats) or bytes (binary formats). Keeps the line
/// number and the number of bytes consumed.
class Stream
{
public:
  // a block, or less for a small file (the buffer grows when a line fills it)
  explicit Stream(Input_file& file)
    : m_file(file),
      m_buffer(static_cast<std::size_t>(std::min<std::uint64_t>(Input_file::block_size, file.size() + 64)))
  { }

  const std::string& error() const { return m_error; }
  std::size_t line_number() const { return m_line; }
  std::uint64_t consumed() const { return m_consumed; }
  std::uint64_t remaining() const { return m_file.size() > m_consumed ? m_file.size() - m_consumed : 0; }

  /// the next line, without its end of line; false at the end of the file or on an error
  bool next_line(std::string_view& line)
  {
    for(std::size_t searched = m_begin;;)
    {
      const char* base = m_buffer.data();
      const void* nl = std::memchr(base + searched, '\n', m_end - searched);
      if(nl != nullptr)
      {
        const std::size_t at = static_cast<std::size_t>(static_cast<const char*>(nl) - base);
        line = std::string_view(base + m_begin, at - m_begin);
        m_consumed += at + 1 - m_begin;
        m_begin = at + 1;
        ++m_line;
        return true;
      }
      searched = m_end;
      if(m_eof)
      {
        if(m_begin == m_end)
          return false;
        line = std::string_view(base + m_begin, m_end - m_begin);  // the last line, no '\n'
        m_consumed += m_end - m_begin;
        m_begin = m_end;
        ++m_line;
        return true;
      }
      const std::size_t kept = m_end - m_begin;
      if(kept >= max_line_length)
      {
        m_error = "line " + std::to_string(m_line + 1) + " is longer than " +
                  std::to_string(max_line_length >> 20) + " MiB (not a mesh file, or corrupt)";
        return false;
      }
      if(!fill())
        return false;
      searched = m_begin + kept;
    }
  }

  /// copies the next `n` bytes to `out`; false (and an error) at a premature end of the file
  bool read_bytes(char* out, std::size_t n)
  {
    while(m_end - m_begin < n)
    {
      const std::size_t have = m_end - m_begin;
      std::memcpy(out, m_buffer.data() + m_begin, have);
      out += have;
      n -= have;
      m_consumed += have;
      m_begin = m_end;
      if(m_eof || !fill() || m_end == m_begin)
      {
        if(m_error.empty())
          m_error = "unexpected end of the file";
        return false;
      }
    }
    std::memcpy(out, m_buffer.data() + m_begin, n);
    m_begin += n;
    m_consumed += n;
    return true;
  }

private:
  // moves the unread bytes to the front, grows the buffer when a line fills it, reads a block
  bool fill()
  {
    const std::size_t kept = m_end - m_begin;
    if(m_begin > 0)
    {
      std::memmove(m_buffer.data(), m_buffer.data() + m_begin, kept);
      m_begin = 0;
      m_end = kept;
    }
    if(m_end == m_buffer.size())  // a line as long as the buffer
      m_buffer.resize(m_buffer.size() * 2);
    const long r = m_file.read(m_buffer.data() + m_end, m_buffer.size() - m_end);
    if(r < 0)
    {
      m_error = std::string("cannot read: ") + std::strerror(errno);
      return false;
    }
    if(r == 0)
      m_eof = true;
    m_end += static_cast<std::size_t>(r);
    return true;
  }

  Input_file& m_file;
  std::vector<char> m_buffer;
  std::size_t m_begin = 0, m_end = 0;
  bool m_eof = false;
  std::size_t m_line = 0;
  std::uint64_t m_consumed = 0;
  std::string m_error;
};

/// parses the whole of `word` as a double (a leading '+' is allowed). Returns an empty string,
/// or why it is not a finite number; `non_finite` tells a NaN, an infinity or an overflow.
std::string parse_double(std::string_view word, double& value, bool& non_finite)
{
  non_finite = false;
  std::string_view w = word;
  if(w.size() > 1 && w[0] == '+' && w[1] != '-')
    w.remove_prefix(1);
  const std::from_chars_result r = std::from_chars(w.data(), w.data() + w.size(), value);
  if(r.ec == std::errc::result_out_of_range && r.ptr == w.data() + w.size())
  {
    // a magnitude beyond double: huge overflows to infinity, tiny underflows to zero (kept)
    const std::size_t e = w.find_first_of("eE");
    if(e != std::string_view::npos && e + 1 < w.size() && w[e + 1] == '-')
    {
      value = 0.;
      return std::string();
    }
    non_finite = true;
    return "the coordinate '" + shown(word) + "' is too large for a double (it overflows to infinity)";
  }
  if(r.ec != std::errc() || r.ptr != w.data() + w.size() || w.empty())
    return "'" + shown(word) + "' is not a number";
  if(!std::isfinite(value))
  {
    non_finite = true;
    return "the coordinate '" + shown(word) + "' is not a finite number (NaN and infinite coordinates are not accepted)";
  }
  return std::string();
}

/// parses the whole of `word` as a non-negative integer below 2^63. Returns an empty string or
/// why it is not one.
std::string parse_count(std::string_view word, std::uint64_t& value, const char* what)
{
  const std::from_chars_result r = std::from_chars(word.data(), word.data() + word.size(), value);
  if(r.ec == std::errc::result_out_of_range)
    return std::string(what) + " '" + shown(word) + "' is too large";
  if(word.empty() || r.ec != std::errc() || r.ptr != word.data() + word.size())
    return std::string(what) + " '" + shown(word) + "' is not a non-negative integer";
  return std::string();
}

/// the soup's limits: 32-bit indices (as CGAL::Surface_mesh)
const std::uint64_t max_points = std::numeric_limits<std::uint32_t>::max() - 1;

std::string at_line(std::size_t line) { return "line " + std::to_string(line) + ": "; }

/// checks the faces' indices against the number of points; `base` is 1 for OBJ (in messages)
std::string check_indices(const Polygon_soup& soup, int base)
{
  const std::size_t n = soup.points.size();
  for(std::size_t f = 0, k = 0; f < soup.face_end.size(); ++f)
    for(; k < soup.face_end[f]; ++k)
      if(soup.corners[k] >= n)
        return "face " + std::to_string(f) + " uses vertex index " + std::to_string(std::uint64_t(soup.corners[k]) + std::uint64_t(base)) +
               (base == 1 ? " (1-based)" : " (0-based)") + ", but the file has " + std::to_string(n) + " vertices";
  return std::string();
}

/// adds a face's end, with the 32-bit limit on the number of corners
bool end_face(Polygon_soup& soup)
{
  if(soup.corners.size() >= max_points)
    return false;
  soup.face_end.push_back(static_cast<std::uint32_t>(soup.corners.size()));
  return true;
}

// ------------------------------------------------------------------------------------ OFF

std::string strip_off_comment(std::string_view& line)
{
  const std::size_t hash = line.find('#');
  if(hash != std::string_view::npos)
    line = line.substr(0, hash);
  return std::string();
}

// The words of `rest` (which is emptied).
std::vector<std::string_view> words_of(std::string_view& rest)
{
  std::vector<std::string_view> words;
  for(std::string_view w = next_word(rest); !w.empty(); w = next_word(rest))
    words.push_back(w);
  return words;
}

// An OFF file: the keyword [ST][C][N][4][n]OFF, the counts, the vertices, the faces.
class Off_reader
{
public:
  Off_reader(Input_file& file, Polygon_soup& soup) : in(file), soup(soup) { }

  Read_error read()
  {
    if(read_keyword() && read_counts() && read_vertices() && read_faces())
      read_end();
    return e;
  }

private:
  bool fail(const std::string& m)
  {
    e.message = in.error().empty() ? m : in.error();
    return false;
  }

  // the next line with content (comments removed) in `line` and `rest`
  bool next_content_line()
  {
    while(in.next_line(line))
    {
      strip_off_comment(line);
      rest = line;
      std::string_view probe = rest;
      if(!next_word(probe).empty())
        return true;
    }
    return false;
  }

  // the keyword: [ST][C][N][4][n]OFF, alone or followed by the counts
  bool read_keyword()
  {
    if(!next_content_line())
      return fail("the file has no OFF keyword (it is empty or only comments)");
    const std::string_view keyword = next_word(rest);
    std::size_t i = 0;
    texture = keyword.substr(0, 2) == "ST";
    if(texture)
      i = 2;
    bool homogeneous = false;
    if(i < keyword.size() && keyword[i] == 'C') { ++i; }  // colors: not used
    if(i < keyword.size() && keyword[i] == 'N') { normal = true; ++i; }
    if(i < keyword.size() && keyword[i] == '4') { homogeneous = true; ++i; }
    if(i < keyword.size() && keyword[i] == 'n') { dimension = true; ++i; }
    if(keyword.substr(i) != "OFF")
      return fail(at_line(in.line_number()) + "the file does not start with an OFF keyword ([ST][C][N][4][n]OFF), but with '" +
                  shown(keyword) + "'");
    if(homogeneous)
      return fail(at_line(in.line_number()) + "4OFF (homogeneous coordinates) is not supported: convert it to OFF");
    std::string_view after = rest;
    if(next_word(after) == "BINARY")
      return fail("binary OFF files are not supported by this program (convert it to ASCII OFF, PLY or OBJ)");
    return true;
  }

  // nOFF: the dimension before the counts, which must be 3
  bool read_dimension(std::vector<std::string_view>& words, std::size_t counts_line)
  {
    std::uint64_t d = 0;
    const std::string m = parse_count(words.front(), d, "the dimension");
    if(!m.empty())
      return fail(at_line(counts_line) + m);
    if(d != 3)
      return fail(at_line(counts_line) + "nOFF of dimension " + std::to_string(d) + " is not supported (only 3)");
    words.erase(words.begin());
    if(words.empty())
    {
      if(!next_content_line())
        return fail("the OFF header has no vertex and face counts (truncated)");
      words = words_of(rest);
    }
    return true;
  }

  // the dimension (nOFF) and the counts V F E, on one line
  bool read_counts()
  {
    std::string_view after = rest;
    if(next_word(after).empty() && !next_content_line())
      return fail("the OFF header has no vertex and face counts (truncated)");
    const std::size_t counts_line = in.line_number();
    std::vector<std::string_view> words = words_of(rest);
    if(dimension && !words.empty() && !read_dimension(words, counts_line))
      return false;
    if(words.size() != 3)
    {
      std::string found;
      for(const std::string_view& w : words)
        found += (found.empty() ? "" : " ") + shown(w);
      return fail(at_line(in.line_number()) + "the OFF counts line '" + found + "' has " + std::to_string(words.size()) +
                  (words.size() == 1 ? " number" : " numbers") +
                  "; it needs exactly three: vertices, faces and edges (the edge count may be 0)");
    }
    std::uint64_t counts[3];
    const char* names[3] = {"the vertex count", "the face count", "the edge count"};
    for(int k = 0; k < 3; ++k)
    {
      const std::string m = parse_count(words[std::size_t(k)], counts[k], names[k]);
      if(!m.empty())
        return fail(at_line(in.line_number()) + m);
    }
    nv = counts[0];
    nf = counts[1];
    return check_counts();
  }

  // the counts against the size of the file; then the soup's memory is reserved
  bool check_counts()
  {
    // every vertex line holds at least 6 bytes ("0 0 0\n"), every face line 2 ("0\n")
    if(nv > in.remaining() / 6 || nf > in.remaining() / 2 || 6 * nv + 2 * nf > in.remaining())
      return fail(at_line(in.line_number()) + "the header announces " + std::to_string(nv) + " vertices and " +
                  std::to_string(nf) + " faces, more than the " + std::to_string(in.remaining()) +
                  " bytes after it can hold (corrupt or truncated)");
    if(nv > max_points)
      return fail("the file has more than 2^32 - 2 vertices");
    soup.points.reserve(nv);
    soup.face_end.reserve(nf);
    soup.corners.reserve(3 * nf);
    return true;
  }

  bool read_vertices()
  {
    const std::size_t per_vertex = 3 + (normal ? 3 : 0) + (texture ? 2 : 0);
    for(std::uint64_t v = 0; v < nv; ++v)
    {
      if(!next_content_line())
        return fail("the file ends after " + std::to_string(v) + " of its " + std::to_string(nv) + " vertices (truncated)");
      std::array<double, 3> p;
      std::size_t count = 0;
      for(std::string_view w = next_word(rest); !w.empty(); w = next_word(rest), ++count)
      {
        double x = 0.;
        bool non_finite = false;
        const std::string m = parse_double(w, x, non_finite);
        if(!m.empty() && (count < 3 || !non_finite))  // NaN in a color or a normal is not ours to judge
        {
          e.non_finite = non_finite;
          return fail(at_line(in.line_number()) + "vertex " + std::to_string(v) + ": " + m);
        }
        if(count < 3)
          p[count] = x;
      }
      const std::size_t colors = count >= per_vertex ? count - per_vertex : std::size_t(-1);
      if(!(colors == 0 || colors == 1 || colors == 3 || colors == 4))
        return fail(at_line(in.line_number()) + "vertex " + std::to_string(v) + " has " + std::to_string(count) +
                    " numbers; expected " + std::to_string(per_vertex) + " (then 0, 1, 3 or 4 color entries)");
      soup.points.push_back(p);
    }
    return true;
  }

  // the vertex indices of face `f`, announcing `n`
  bool read_face_indices(std::uint64_t f, std::uint64_t n)
  {
    for(std::uint64_t k = 0; k < n; ++k)
    {
      const std::string_view w = next_word(rest);
      if(w.empty())
        return fail(at_line(in.line_number()) + "face " + std::to_string(f) + " announces " + std::to_string(n) +
                    " vertices but lists " + std::to_string(k));
      std::uint64_t index = 0;
      const std::string m = parse_count(w, index, "the vertex index");
      if(!m.empty())
        return fail(at_line(in.line_number()) + "face " + std::to_string(f) + ": " + m);
      if(index >= nv)
        return fail(at_line(in.line_number()) + "face " + std::to_string(f) + " uses vertex index " +
                    std::to_string(index) + " (0-based), but the file has " + std::to_string(nv) + " vertices");
      soup.corners.push_back(static_cast<std::uint32_t>(index));
    }
    return true;
  }

  // after the indices of face `f` (`n` of them): 0, 1, 3 or 4 color entries
  bool read_face_colors(std::uint64_t f, std::uint64_t n)
  {
    std::size_t colors = 0;
    for(std::string_view w = next_word(rest); !w.empty(); w = next_word(rest), ++colors)
    {
      double x = 0.;
      bool non_finite = false;
      if(!parse_double(w, x, non_finite).empty() && !non_finite)
        return fail(at_line(in.line_number()) + "face " + std::to_string(f) + ": '" + shown(w) +
                    "' after its vertex indices is not a number (more indices than announced, or a malformed color)");
    }
    if(colors == 2 || colors > 4)
      return fail(at_line(in.line_number()) + "face " + std::to_string(f) + " has " + std::to_string(colors) +
                  " numbers after its " + std::to_string(n) + " vertex indices (expected 0, 1, 3 or 4 color entries)");
    return true;
  }

  bool read_faces()
  {
    for(std::uint64_t f = 0; f < nf; ++f)
    {
      if(!next_content_line())
        return fail("the file ends after " + std::to_string(f) + " of its " + std::to_string(nf) + " faces (truncated)");
      std::uint64_t n = 0;
      const std::string m = parse_count(next_word(rest), n, "the vertex count");
      if(!m.empty())
        return fail(at_line(in.line_number()) + "face " + std::to_string(f) + ": " + m);
      if(n > line.size())
        return fail(at_line(in.line_number()) + "face " + std::to_string(f) + " announces " + std::to_string(n) +
                    " vertices, more than its line holds (corrupt)");
      if(!read_face_indices(f, n) || !read_face_colors(f, n))
        return false;
      if(!end_face(soup))
        return fail("the file has more than 2^32 - 2 face corners");
    }
    return true;
  }

  bool read_end()
  {
    if(next_content_line())
      return fail(at_line(in.line_number()) + "unexpected data after the last face ('" + shown(line) + "')");
    if(!in.error().empty())
      return fail(in.error());
    return true;
  }

  Stream in;
  Polygon_soup& soup;
  Read_error e;
  std::string_view line, rest;  // the current line, and what is left of it
  bool texture = false, normal = false, dimension = false;
  std::uint64_t nv = 0, nf = 0;
};

// ------------------------------------------------------------------------------------ OBJ

// The statements of OBJ that the program skips: texture coordinates, normals, groups,
// materials, polylines, points.
bool is_skipped_obj_statement(std::string_view tag)
{
  return tag == "vt" || tag == "vn" || tag == "vp" || tag == "o" || tag == "g" || tag == "s" || tag == "usemtl" ||
         tag == "mtllib" || tag == "l" || tag == "p" || tag == "mg" || tag == "usemap" || tag == "maplib" ||
         tag == "lod" || tag == "shadow_obj" || tag == "trace_obj" || tag == "bevel" || tag == "c_interp" ||
         tag == "d_interp";
}

// The statements of OBJ's free-form geometry, which the program refuses.
bool is_free_form_statement(std::string_view tag)
{
  return tag == "cstype" || tag == "deg" || tag == "bmat" || tag == "step" || tag == "curv" || tag == "curv2" ||
         tag == "surf" || tag == "parm" || tag == "trim" || tag == "hole" || tag == "scrv" || tag == "sp" ||
         tag == "end" || tag == "con" || tag == "ctech" || tag == "stech";
}

// An OBJ file: its 'v' and 'f' statements.
class Obj_reader
{
public:
  Obj_reader(Input_file& file, Polygon_soup& soup) : in(file), soup(soup) { }

  Read_error read()
  {
    std::string_view line;
    while(in.next_line(line))
      if(!statement(line))
        return e;
    if(!in.error().empty())
    {
      e.message = in.error();
      return e;
    }
    e.message = check_indices(soup, 1);
    return e;
  }

private:
  bool fail(const std::string& m)
  {
    e.message = at_line(in.line_number()) + m;
    return false;
  }

  bool statement(std::string_view line)
  {
    std::string_view rest = line;
    const std::string_view tag = next_word(rest);
    if(tag.empty() || tag[0] == '#')
      return true;
    if(tag == "v")
      return vertex(rest);
    if(tag == "f")
      return face(rest);
    if(is_skipped_obj_statement(tag))
      return true;
    if(is_free_form_statement(tag))
      return fail("free-form geometry ('" + std::string(tag) + "') is not supported: triangulate it first");
    return fail("'" + shown(tag) + "' is not an OBJ statement (not an OBJ file, or corrupt)");
  }

  bool vertex(std::string_view rest)
  {
    if(soup.points.size() >= max_points)
      return fail("more than 2^32 - 2 vertices");
    std::array<double, 3> p;
    std::size_t count = 0;
    for(std::string_view w = next_word(rest); !w.empty() && w[0] != '#'; w = next_word(rest), ++count)
    {
      double x = 0.;
      bool non_finite = false;
      const std::string m = parse_double(w, x, non_finite);
      if(!m.empty() && (count < 3 || !non_finite))
      {
        e.non_finite = non_finite;
        return fail("vertex " + std::to_string(soup.points.size()) + ": " + m);
      }
      if(count < 3)
        p[count] = x;
    }
    // x y z, then an optional weight w, or a color r g b [a]
    if(count < 3 || count > 7 || count == 5)
      return fail("a 'v' line needs 3 coordinates (then an optional weight or color), but has " +
                  std::to_string(count) + " numbers");
    soup.points.push_back(p);
    return true;
  }

  // the vertex index (0-based) of the face corner `w`: v, v/vt, v//vn or v/vt/vn, the index
  // before the first '/', from 1, or negative counting back from the last of the `defined`
  // vertices
  bool corner(std::string_view w, std::size_t defined, std::uint64_t& index)
  {
    const std::string_view index_text = w.substr(0, w.find('/'));
    const bool negative = !index_text.empty() && index_text[0] == '-';
    const std::string_view digits = negative ? index_text.substr(1) : index_text;
    std::uint64_t k = 0;
    const std::from_chars_result r = std::from_chars(digits.data(), digits.data() + digits.size(), k);
    if(digits.empty() || r.ptr != digits.data() + digits.size() || (r.ec != std::errc() && r.ec != std::errc::result_out_of_range))
      return fail("face " + std::to_string(soup.face_end.size()) + ": '" + shown(w) + "' is not a vertex index");
    if(r.ec == std::errc::result_out_of_range || k > max_points)
      return fail("face " + std::to_string(soup.face_end.size()) + ": vertex index " + shown(index_text) +
                  " is out of range (the largest index this program reads is " + std::to_string(max_points) + ")");
    if(k == 0)
      return fail("face " + std::to_string(soup.face_end.size()) +
                  ": vertex index 0 is invalid in OBJ (indices start at 1; negative indices count back from the last vertex)");
    index = k - 1;
    if(negative)
    {
      if(k > defined)
        return fail("face " + std::to_string(soup.face_end.size()) + ": relative vertex index " + shown(index_text) +
                    " refers to before the first vertex (" + std::to_string(defined) + " vertices precede it)");
      index = defined - k;
    }
    return true;
  }

  bool face(std::string_view rest)
  {
    const std::size_t defined = soup.points.size();
    for(std::string_view w = next_word(rest); !w.empty() && w[0] != '#'; w = next_word(rest))
    {
      std::uint64_t index = 0;
      if(!corner(w, defined, index))
        return false;
      soup.corners.push_back(static_cast<std::uint32_t>(index));
    }
    if(!end_face(soup))
      return fail("more than 2^32 - 2 face corners");
    return true;
  }

  Stream in;
  Polygon_soup& soup;
  Read_error e;
};

// ------------------------------------------------------------------------------------ PLY

enum class Ply_type { none, int8, uint8, int16, uint16, int32, uint32, float32, float64 };

Ply_type ply_type(std::string_view t)
{
  if(t == "char" || t == "int8") return Ply_type::int8;
  if(t == "uchar" || t == "uint8") return Ply_type::uint8;
  if(t == "short" || t == "int16") return Ply_type::int16;
  if(t == "ushort" || t == "uint16") return Ply_type::uint16;
  if(t == "int" || t == "int32") return Ply_type::int32;
  if(t == "uint" || t == "uint32") return Ply_type::uint32;
  if(t == "float" || t == "float32") return Ply_type::float32;
  if(t == "double" || t == "float64") return Ply_type::float64;
  return Ply_type::none;
}

std::size_t ply_size(Ply_type t)
{
  switch(t)
  {
    case Ply_type::int8: case Ply_type::uint8: return 1;
    case Ply_type::int16: case Ply_type::uint16: return 2;
    case Ply_type::int32: case Ply_type::uint32: case Ply_type::float32: return 4;
    case Ply_type::float64: return 8;
    default: return 0;
  }
}

bool ply_integral(Ply_type t) { return t != Ply_type::float32 && t != Ply_type::float64 && t != Ply_type::none; }

struct Ply_property
{
  std::string name;
  Ply_type type = Ply_type::none;
  Ply_type count_type = Ply_type::none;  // none: a scalar
  int role = -1;                          // vertex: 0, 1, 2 for x, y, z; face: 3 for the index list
};

struct Ply_element
{
  std::string name;
  std::uint64_t count = 0;
  std::vector<Ply_property> properties;
};

/// decodes a binary PLY value of type `t` from `bytes` (in file order)
double ply_decode(Ply_type t, const unsigned char* bytes, bool swap)
{
  unsigned char b[8];
  const std::size_t n = ply_size(t);
  for(std::size_t k = 0; k < n; ++k)
    b[k] = bytes[swap ? n - 1 - k : k];
  switch(t)
  {
    case Ply_type::int8: { std::int8_t v; std::memcpy(&v, b, 1); return v; }
    case Ply_type::uint8: return b[0];
    case Ply_type::int16: { std::int16_t v; std::memcpy(&v, b, 2); return v; }
    case Ply_type::uint16: { std::uint16_t v; std::memcpy(&v, b, 2); return v; }
    case Ply_type::int32: { std::int32_t v; std::memcpy(&v, b, 4); return v; }
    case Ply_type::uint32: { std::uint32_t v; std::memcpy(&v, b, 4); return v; }
    case Ply_type::float32: { float v; std::memcpy(&v, b, 4); return v; }
    case Ply_type::float64: { double v; std::memcpy(&v, b, 8); return v; }
    default: return 0.;
  }
}

bool host_is_little_endian()
{
  const std::uint16_t one = 1;
  unsigned char first;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

// A PLY file (ASCII, binary little- or big-endian): the header, then the elements; the
// points are the x, y, z of the element 'vertex', the faces the index list of 'face'.
class Ply_reader
{
public:
  Ply_reader(Input_file& file, Polygon_soup& soup) : in(file), soup(soup) { }

  Read_error read()
  {
    if(!in.next_line(line) || line.substr(0, 3) != "ply" || !next_word(line = line.substr(3)).empty())
    {
      fail("the file does not start with the line 'ply'");
      return e;
    }
    if(!read_header() || !find_roles() || !check_sizes())
      return e;
    for(const Ply_element& el : elements)
      for(std::uint64_t i = 0; i < el.count; ++i)
        if(!read_instance(el, i))
          return e;
    if(ascii)
      while(in.next_line(line))
        if(!next_word(line).empty())
        {
          fail(at_line(in.line_number()) + "unexpected data after the last element");
          return e;
        }
    if(!in.error().empty())
      fail(in.error());
    return e;
  }

private:
  bool fail(const std::string& m)
  {
    e.message = in.error().empty() ? m : in.error();
    return false;
  }

  // ---- the header

  bool read_header()
  {
    bool ended = false;
    while(!ended && in.next_line(line))
    {
      std::string_view rest = line;
      const std::string_view tag = next_word(rest);
      if(tag == "comment" || tag == "obj_info" || tag.empty())
        continue;
      std::vector<std::string_view> w;
      for(std::string_view x = next_word(rest); !x.empty(); x = next_word(rest))
        w.push_back(x);
      if(tag == "end_header" && w.empty())
        ended = true;
      else if(!header_line(tag, w, at_line(in.line_number())))
        return false;
    }
    if(!ended)
      return fail("the PLY header has no 'end_header' line (truncated or corrupt)");
    if(format.empty())
      return fail("the PLY header has no format line");
    ascii = (format == "ascii");
    swap = !ascii && ((format == "binary_little_endian") != host_is_little_endian());
    return true;
  }

  // a line of the header (not a comment, not end_header): its tag and words
  bool header_line(std::string_view tag, const std::vector<std::string_view>& w, const std::string& here)
  {
    if(tag == "format")
    {
      if(!format.empty() || w.size() != 2 || w[1] != "1.0" ||
         (w[0] != "ascii" && w[0] != "binary_little_endian" && w[0] != "binary_big_endian"))
        return fail(here + "bad format line (expected 'format ascii 1.0', 'format binary_little_endian 1.0' or "
                           "'format binary_big_endian 1.0')");
      format = std::string(w[0]);
      return true;
    }
    if(tag == "element")
    {
      Ply_element el;
      std::string m;
      if(w.size() != 2)
        return fail(here + "an element line needs a name and a count");
      if(!(m = parse_count(w[1], el.count, "the element count")).empty())
        return fail(here + m);
      el.name = std::string(w[0]);
      elements.push_back(el);
      return true;
    }
    if(tag == "property")
      return property_line(w, here);
    return fail(here + "unknown PLY header line '" + shown(tag) + "'");
  }

  bool property_line(const std::vector<std::string_view>& w, const std::string& here)
  {
    if(elements.empty())
      return fail(here + "a property before any element (corrupt header)");
    Ply_property p;
    if(w.size() == 4 && w[0] == "list")
    {
      p.count_type = ply_type(w[1]);
      p.type = ply_type(w[2]);
      p.name = std::string(w[3]);
      if(!ply_integral(p.count_type))
        return fail(here + "the list count type '" + shown(w[1]) + "' is not an integer type");
    }
    else if(w.size() == 2)
    {
      p.type = ply_type(w[0]);
      p.name = std::string(w[1]);
    }
    else
      return fail(here + "malformed property line");
    if(p.type == Ply_type::none)
      return fail(here + "unknown property type '" + shown(w.size() == 4 ? w[2] : w[0]) + "'");
    elements.back().properties.push_back(p);
    return true;
  }

  // ---- the roles: x, y, z of 'vertex'; the index list of 'face'

  bool vertex_roles(Ply_element& el)
  {
    vertex = &el;
    for(Ply_property& p : el.properties)
      if(p.count_type == Ply_type::none && (p.name == "x" || p.name == "y" || p.name == "z"))
        p.role = p.name[0] - 'x';
    for(int r = 0; r < 3; ++r)
      if(std::none_of(el.properties.begin(), el.properties.end(), [r](const Ply_property& p) { return p.role == r; }))
        return fail(std::string("the vertex element has no scalar property '") + char('x' + r) + "'");
    return true;
  }

  bool face_roles(Ply_element& el)
  {
    face = &el;
    for(Ply_property& p : el.properties)
      if(p.count_type != Ply_type::none && (p.name == "vertex_indices" || p.name == "vertex_index"))
      {
        if(!ply_integral(p.type))
          return fail("the face index list has the non-integer type of '" + p.name + "'");
        p.role = 3;
        break;
      }
    if(std::none_of(el.properties.begin(), el.properties.end(), [](const Ply_property& p) { return p.role == 3; }))
      return fail("the face element has no list property 'vertex_indices' or 'vertex_index'");
    return true;
  }

  bool find_roles()
  {
    for(Ply_element& el : elements)
    {
      if(el.name == "vertex" && vertex == nullptr)
      {
        if(!vertex_roles(el))
          return false;
      }
      else if(el.name == "face" && face == nullptr)
      {
        if(!face_roles(el))
          return false;
      }
    }
    if(vertex == nullptr)
      return fail("the PLY file has no vertex element");
    for(const Ply_element& el : elements)
      if(el.properties.empty() && el.count > 0)
        return fail("the element '" + el.name + "' has no properties (corrupt header)");
    return true;
  }

  // every element instance takes at least one byte per property (binary) or two (ASCII);
  // then the soup's memory is reserved
  bool check_sizes()
  {
    long double bytes = 0.;
    for(const Ply_element& el : elements)
    {
      long double per = 0.;
      for(const Ply_property& p : el.properties)
        per += ascii ? 2. : double(ply_size(p.count_type == Ply_type::none ? p.type : p.count_type));
      bytes += per * el.count;
    }
    if(bytes > (long double)in.remaining())
      return fail("the header announces more elements than the " + std::to_string(in.remaining()) +
                  " bytes after it can hold (corrupt or truncated)");
    if(vertex->count > max_points)
      return fail("the file has more than 2^32 - 2 vertices");
    soup.points.reserve(vertex->count);
    if(face != nullptr)
    {
      soup.face_end.reserve(face->count);
      soup.corners.reserve(3 * face->count);
    }
    return true;
  }

  // ---- the body

  // the next value of the body: a number parsed from the current ASCII line, or decoded bytes
  bool next_value(Ply_type t, double& value, std::string& m)
  {
    if(!ascii)
    {
      unsigned char b[8];
      if(!in.read_bytes(reinterpret_cast<char*>(b), ply_size(t)))
      {
        m = "the file ends before the element does (truncated)";
        return false;
      }
      value = ply_decode(t, b, swap);
      return true;
    }
    const std::string_view w = next_word(rest);
    if(w.empty())
    {
      m = "the line ends before the element does";
      return false;
    }
    if(ply_integral(t))
    {
      // integers are written as integers
      long long v = 0;
      const std::from_chars_result r = std::from_chars(w.data(), w.data() + w.size(), v);
      if(r.ec != std::errc() || r.ptr != w.data() + w.size())
      {
        m = "'" + shown(w) + "' is not an integer";
        return false;
      }
      value = double(v);
      return true;
    }
    bool non_finite = false;
    m = parse_double(w, value, non_finite);
    e.non_finite = non_finite;
    return m.empty();
  }

  // the prefix of a message on element instance `what`
  std::string where(const std::string& what) const
  {
    return (ascii ? at_line(in.line_number()) : std::string()) + what + ": ";
  }

  // instance `i` of element `el`
  bool read_instance(const Ply_element& el, std::uint64_t i)
  {
    const std::string what = "element '" + el.name + "' " + std::to_string(i);
    if(ascii)
    {
      do
      {
        if(!in.next_line(line))
          return fail("the file ends before " + what + " (truncated)");
        rest = line;
      } while(next_word(line).empty());  // blank lines
    }
    std::array<double, 3> p = {0., 0., 0.};
    for(const Ply_property& prop : el.properties)
      if(!(prop.count_type == Ply_type::none ? read_scalar(prop, what, i, p) : read_list(prop, what, &el == face, i)))
        return false;
    if(ascii)
    {
      const std::string_view extra = next_word(rest);
      if(!extra.empty())
        return fail(where(what) + "unexpected '" + shown(extra) + "' after the element's properties");
    }
    if(&el == vertex)
      soup.points.push_back(p);
    else if(&el == face && !end_face(soup))
      return fail("the file has more than 2^32 - 2 face corners");
    return true;
  }

  // a scalar property of instance `i`: into `p` when it is a coordinate of a vertex
  bool read_scalar(const Ply_property& prop, const std::string& what, std::uint64_t i, std::array<double, 3>& p)
  {
    double value = 0.;
    std::string m;
    if(!next_value(prop.type, value, m))
      return fail(where(what) + "property '" + prop.name + "': " + m);
    if(prop.role >= 0 && prop.role < 3)
    {
      if(!std::isfinite(value))
      {
        e.non_finite = true;
        return fail("vertex " + std::to_string(i) + " has a non-finite coordinate (" + prop.name + " = " +
                    (std::isnan(value) ? "nan" : "inf") + ")");
      }
      p[std::size_t(prop.role)] = value;
    }
    return true;
  }

  // a list property of instance `i`: the corners of a face when it is the index list
  bool read_list(const Ply_property& prop, const std::string& what, bool is_face, std::uint64_t i)
  {
    double value = 0.;
    std::string m;
    if(!next_value(prop.count_type, value, m))
      return fail(where(what) + "property '" + prop.name + "': " + m);
    const std::size_t item = ascii ? 2 : ply_size(prop.type);
    if(value < 0. || value * double(item) > double(in.remaining()) + double(ascii ? line.size() + 1 : 0))
      return fail(where(what) + "property '" + prop.name + "': a list of " + std::to_string((long long)value) +
                  " entries, more than the rest of the file holds (corrupt)");
    const std::uint64_t n = static_cast<std::uint64_t>(value);
    for(std::uint64_t k = 0; k < n; ++k)
    {
      if(!next_value(prop.type, value, m))
        return fail(where(what) + "property '" + prop.name + "': " + m);
      if(is_face && prop.role == 3)
      {
        if(value < 0. || value >= double(vertex->count))
          return fail("face " + std::to_string(i) + " uses vertex index " + std::to_string((long long)value) +
                      " (0-based), but the file has " + std::to_string(vertex->count) + " vertices");
        soup.corners.push_back(static_cast<std::uint32_t>(value));
      }
    }
    return true;
  }

  Stream in;
  Polygon_soup& soup;
  Read_error e;
  std::string_view line, rest;  // the current line of an ASCII body, and what is left of it
  std::string format;
  std::vector<Ply_element> elements;
  Ply_element* vertex = nullptr;
  Ply_element* face = nullptr;
  bool ascii = false, swap = false;
};

/// Vertices of an STL file, merged by exact equality of their coordinates (0 and -0 equal),
/// numbered in order of first appearance (as CGAL's STL reader does). Open addressing.
class Stl_vertices
{
public:
  explicit Stl_vertices(Polygon_soup& soup, std::size_t expected) : m_soup(soup)
  {
    std::size_t capacity = 1024;
    while(capacity < 2 * expected)
      capacity *= 2;
    m_slots.assign(capacity, empty);
  }

  /// the index of `p`, added when new; false when there are too many vertices
  bool index(const std::array<double, 3>& p, std::uint32_t& i)
  {
    if(2 * (m_soup.points.size() + 1) > m_slots.size())
      grow();
    std::size_t s = hash(p) & (m_slots.size() - 1);
    for(;; s = (s + 1) & (m_slots.size() - 1))
    {
      const std::uint32_t k = m_slots[s];
      if(k == empty)
        break;
      if(m_soup.points[k] == p)
      {
        i = k;
        return true;
      }
    }
    if(m_soup.points.size() >= max_points)
      return false;
    i = static_cast<std::uint32_t>(m_soup.points.size());
    m_slots[s] = i;
    m_soup.points.push_back(p);
    return true;
  }

private:
  static constexpr std::uint32_t empty = std::numeric_limits<std::uint32_t>::max();

  static std::size_t hash(const std::array<double, 3>& p)
  {
    std::uint64_t h = 0x9e3779b97f4a7c15ull;
    for(double x : p)
    {
      if(x == 0.)
        x = 0.;  // -0 as 0
      std::uint64_t b;
      std::memcpy(&b, &x, 8);
      h = (h ^ b) * 0xff51afd7ed558ccdull;
      h ^= h >> 32;
    }
    return static_cast<std::size_t>(h);
  }

  void grow()
  {
    std::size_t capacity = 2 * m_slots.size();  // a power of two (the probing masks with it)
    while(capacity < 4 * m_soup.points.size())
      capacity *= 2;
    std::vector<std::uint32_t>().swap(m_slots);
    m_slots.assign(capacity, empty);
    for(std::uint32_t k = 0; k < m_soup.points.size(); ++k)
    {
      std::size_t s = hash(m_soup.points[k]) & (m_slots.size() - 1);
      while(m_slots[s] != empty)
        s = (s + 1) & (m_slots.size() - 1);
      m_slots[s] = k;
    }
  }

  Polygon_soup& m_soup;
  std::vector<std::uint32_t> m_slots;
};

std::string stl_vertex_check(const std::array<double, 3>& p, std::uint64_t triangle, Read_error& e)
{
  for(double x : p)
    if(!std::isfinite(x))
    {
      e.non_finite = true;
      return "triangle " + std::to_string(triangle) + " has a non-finite vertex coordinate (" +
             (std::isnan(x) ? "nan" : "inf") + ")";
    }
  return std::string();
}

Read_error read_binary_stl(Input_file& file, Polygon_soup& soup, std::uint64_t triangles)
{
  Stream in(file);
  Read_error e;
  char header[84];
  in.read_bytes(header, 84);
  Stl_vertices vertices(soup, std::size_t(triangles / 2 + 3));
  soup.face_end.reserve(triangles);
  soup.corners.reserve(3 * triangles);
  const bool swap = !host_is_little_endian();
  char record[50];
  for(std::uint64_t t = 0; t < triangles; ++t)
  {
    if(!in.read_bytes(record, 50))
    {
      e.message = in.error();
      return e;
    }
    for(int c = 0; c < 3; ++c)
    {
      std::array<double, 3> p;
      for(int k = 0; k < 3; ++k)
        p[std::size_t(k)] = ply_decode(Ply_type::float32, reinterpret_cast<const unsigned char*>(record) + 12 + 12 * c + 4 * k, swap);
      if(!(e.message = stl_vertex_check(p, t, e)).empty())
        return e;
      std::uint32_t i = 0;
      if(!vertices.index(p, i))
      {
        e.message = "the file has more than 2^32 - 2 vertices";
        return e;
      }
      soup.corners.push_back(i);
    }
    end_face(soup);
  }
  return e;
}

// An ASCII STL file: solid, then facets of three vertices, then endsolid (several solids may
// follow one another).
class Ascii_stl_reader
{
public:
  Ascii_stl_reader(Input_file& file, Polygon_soup& soup)
    : in(file), soup(soup),
      vertices(soup, std::size_t(std::min<std::uint64_t>(file.size() / 200, std::uint64_t(1) << 24)))
  { }

  Read_error read()
  {
    std::string_view line;
    while(in.next_line(line))
      if(!statement(line))
        return e;
    if(!in.error().empty())
      fail(in.error());
    else if(state != done)
      e.message = "the file ends inside facet " + std::to_string(triangle) + " (truncated: no 'endsolid')";
    return e;
  }

private:
  // the expected keyword sequence, by state
  enum State { solid, facet_or_end, outer, vertex, endloop, endfacet, done };

  bool fail(const std::string& m)
  {
    e.message = in.error().empty() ? at_line(in.line_number()) + m : in.error();
    return false;
  }

  bool statement(std::string_view line)
  {
    std::string_view rest = line;
    const std::string_view tag = next_word(rest);
    if(tag.empty())
      return true;
    if(state == done)
    {
      if(tag == "solid")  // several solids in one file
      {
        state = facet_or_end;
        return true;
      }
      return fail("unexpected '" + shown(tag) + "' after 'endsolid'");
    }
    if(state == solid)
    {
      if(tag != "solid")
        return fail("an ASCII STL file starts with 'solid'");
      state = facet_or_end;
    }
    else if(state == facet_or_end && tag == "endsolid")
      state = done;
    else if(state == facet_or_end && tag == "facet")
      state = outer;
    else if(state == outer && tag == "outer" && next_word(rest) == "loop")
      state = vertex;
    else if(state == vertex && tag == "vertex")
      return vertex_line(rest);
    else if(state == endloop && tag == "endloop")
      state = endfacet;
    else if(state == endfacet && tag == "endfacet")
      return end_facet();
    else
    {
      const char* expected[] = {"solid", "facet or endsolid", "outer loop", "vertex", "endloop", "endfacet", ""};
      return fail("'" + shown(tag) + "' where '" + expected[state] + "' was expected (facet " + std::to_string(triangle) +
                  ")");
    }
    return true;
  }

  bool vertex_line(std::string_view rest)
  {
    std::array<double, 3> p;
    for(int k = 0; k < 3; ++k)
    {
      bool non_finite = false;
      const std::string m = parse_double(next_word(rest), p[std::size_t(k)], non_finite);
      if(!m.empty())
      {
        e.non_finite = non_finite;
        return fail("triangle " + std::to_string(triangle) + ": " + m);
      }
    }
    if(!next_word(rest).empty())
      return fail("a 'vertex' line has more than three coordinates");
    std::uint32_t i = 0;
    if(!vertices.index(p, i))
      return fail("more than 2^32 - 2 vertices");
    soup.corners.push_back(i);
    if(++corners == 3)
      state = endloop;
    return true;
  }

  bool end_facet()
  {
    if(!end_face(soup))
      return fail("more than 2^32 - 2 face corners");
    state = facet_or_end;
    corners = 0;
    ++triangle;
    return true;
  }

  Stream in;
  Polygon_soup& soup;
  Stl_vertices vertices;
  Read_error e;
  State state = solid;
  int corners = 0;
  std::uint64_t triangle = 0;
};

// An STL file: binary when the size matches the triangle count of bytes 80 to 83; ASCII when
// it starts with "solid" (a binary header may start with "solid" too, so the size decides).
Read_error read_stl(Input_file& file, Polygon_soup& soup)
{
  Read_error e;
  unsigned char start[84] = {};
  long got = 0;
  for(long r = 1; got < 84 && r > 0; got += r)
    if((r = file.read(reinterpret_cast<char*>(start) + got, std::size_t(84 - got))) < 0)
    {
      e.message = std::string("cannot read: ") + std::strerror(errno);
      return e;
    }
  if(!file.rewind())
  {
    e.message = std::string("cannot read: ") + std::strerror(errno);
    return e;
  }
  if(got == 84)
  {
    const std::uint64_t triangles = std::uint64_t(start[80]) | std::uint64_t(start[81]) << 8 |
                                    std::uint64_t(start[82]) << 16 | std::uint64_t(start[83]) << 24;
    if(file.size() == 84 + 50 * triangles)
      return read_binary_stl(file, soup, triangles);
    if(std::memcmp(start, "solid", 5) != 0)
    {
      e.message = "a binary STL file of " + std::to_string(triangles) + " triangles has " +
                  std::to_string(84 + 50 * triangles) + " bytes, but this one has " + std::to_string(file.size()) +
                  " (truncated or corrupt; an ASCII STL file starts with 'solid')";
      return e;
    }
  }
  else if(got < 5 || std::memcmp(start, "solid", 5) != 0)
  {
    e.message = "the file is too short for a binary STL file (" + std::to_string(file.size()) +
                " bytes) and does not start with 'solid' (ASCII STL)";
    return e;
  }
  return Ascii_stl_reader(file, soup).read();
}

} // namespace

std::string check_regular_input(const std::string& path)
{
  Input_file file;
  return file.open(path);
}

Read_error read_polygon_soup(const std::string& path, const std::string& extension, Polygon_soup& soup)
{
  Read_error e;
  Input_file file;
  e.message = file.open(path);
  if(e.failed())
    return e;
  if(file.size() == 0)
  {
    e.message = "the file is empty";
    return e;
  }
  if(extension == "off")
    return Off_reader(file, soup).read();
  if(extension == "obj")
    return Obj_reader(file, soup).read();
  if(extension == "ply")
    return Ply_reader(file, soup).read();
  if(extension == "stl")
    return read_stl(file, soup);
  e.message = "unsupported file extension '." + extension + "' (expected .off, .obj, .ply or .stl)";
  return e;
}

} // namespace mbp_cli
