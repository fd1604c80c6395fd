// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// Input of the measured_parameterization program: reading a mesh file with a message that
// names the problem when it fails, the generated fallback mesh, and the checks that give a
// precise message before the library sees the mesh.

#ifndef MBP_CLI_MESH_INPUT_H
#define MBP_CLI_MESH_INPUT_H

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/Measured_error_code.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <new>
#include <stdexcept>
#include <sstream>
#include <string>
#include <vector>

namespace mbp_cli {

namespace SMP = CGAL::Surface_mesh_parameterization;

/// A failure of the program: a code of the library (`SMP::OK` for failures that have none,
/// such as an unreadable file) and the details.
struct Failure
{
  SMP::Error_code code = SMP::OK;
  std::string detail;

  bool failed() const { return !detail.empty() || code != SMP::OK; }
  /// the message: the library's text for the code, then the details.
  std::string message() const
  {
    if(code == SMP::OK)
      return detail;
    std::string m = SMP::get_measured_error_message(code);
    if(!detail.empty())
      m += ": " + detail;
    return m;
  }
};

inline std::string lowercase_extension(const std::string& path)
{
  std::string ext = std::filesystem::path(path).extension().string();
  if(!ext.empty())
    ext.erase(0, 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

namespace internal {

// CGAL's text readers stop at a coordinate such as "nan" or "inf" and only say that reading
// failed. To name that problem, the file is scanned for a token that is entirely a number
// (as strtod reads it) but not a finite one. Comment lines are skipped. Returns the message,
// or an empty string when there is no such token.
inline std::string find_non_finite_number(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::string line;
  for(std::size_t line_number = 1; std::getline(in, line); ++line_number)
  {
    std::istringstream tokens(line);
    std::string token;
    bool first = true;
    while(tokens >> token)
    {
      if(first && (token[0] == '#' || token == "comment"))
        break;
      first = false;
      char* end = nullptr;
      errno = 0;
      const double value = std::strtod(token.c_str(), &end);
      if(end == token.c_str() + token.size() && !std::isfinite(value))
        return "line " + std::to_string(line_number) + " has the coordinate '" + token +
               "', which is not a finite number (NaN and infinite coordinates are not accepted)";
    }
  }
  return std::string();
}

// Where the comment of an OFF line starts: a '#' that begins a word ("COFF#16" is one word,
// as CGAL's scanner reads it), or npos.
inline std::size_t comment_start(const std::string& line)
{
  for(std::size_t i = 0; i < line.size(); ++i)
    if(line[i] == '#' && (i == 0 || std::isspace(static_cast<unsigned char>(line[i - 1]))))
      return i;
  return std::string::npos;
}

// The size in bytes of a PLY scalar type, 0 when unknown.
inline std::size_t ply_type_size(const std::string& type)
{
  if(type == "char" || type == "uchar" || type == "int8" || type == "uint8")
    return 1;
  if(type == "short" || type == "ushort" || type == "int16" || type == "uint16")
    return 2;
  if(type == "int" || type == "uint" || type == "float" || type == "int32" || type == "uint32" || type == "float32")
    return 4;
  if(type == "double" || type == "float64")
    return 8;
  return 0;
}

// CGAL's readers size their containers from the counts a file announces before checking that
// the file holds that much data: an OFF header or a PLY list count of a few billion makes a
// file of a few bytes allocate gigabytes (and CGAL 5.5's OFF header code converts an
// oversized count to int, which is undefined). Every vertex, face or list entry takes at least
// one byte, so a count larger than the file is corrupt. Returns the message, or an empty
// string when the counts are plausible (the readers check the rest).
inline std::string find_impossible_count(const std::string& path, const std::string& ext)
{
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const double size = double(bytes.size());
  auto too_large = [&](const std::string& what, double count) {
    return what + " " + std::to_string((long long)count) + ", more than a file of " +
           std::to_string(bytes.size()) + " bytes can hold (corrupt or truncated)";
  };
  auto to_number = [](const std::string& token, double& value) {
    char* end = nullptr;
    value = std::strtod(token.c_str(), &end);
    return !token.empty() && end == token.c_str() + token.size();
  };

  if(ext == "off")
  {
    // [ST][C][N][4][n]OFF [BINARY], then (n: the dimension), then V F E; '#' starts a comment
    std::istringstream text(bytes);
    std::vector<std::string> tokens;
    std::string line;
    while(tokens.size() < 6 && std::getline(text, line))
    {
      std::istringstream words(line.substr(0, comment_start(line)));
      std::string w;
      while(words >> w)
        tokens.push_back(w);
    }
    // CGAL 5.5's OFF reader is lenient (a keyword that only contains OFF, "COFF-"; no keyword;
    // a count with trailing characters) and then reads past its buffers on some such files:
    // this program accepts the header only in its documented form, checked here.
    if(tokens.empty())
      return std::string();  // empty: the reader says so
    const std::string& keyword_token = tokens[0];
    const std::size_t off_at = keyword_token.find("OFF");
    bool keyword_ok = (off_at != std::string::npos && off_at + 3 == keyword_token.size());
    const std::string off_prefix = keyword_ok ? keyword_token.substr(0, off_at) : std::string();
    {
      std::size_t i = 0;  // [ST][C][N][4][n]
      if(off_prefix.compare(i, 2, "ST") == 0)
        i += 2;
      for(const char c : {'C', 'N', '4', 'n'})
        if(i < off_prefix.size() && off_prefix[i] == c)
          ++i;
      keyword_ok = keyword_ok && i == off_prefix.size();
    }
    if(!keyword_ok)
      return "the file does not start with an OFF keyword ([ST][C][N][4][n]OFF), but with '" +
             keyword_token.substr(0, 16) + "' (corrupt)";
    if(tokens.size() > 1 && tokens[1] == "BINARY")
      return "binary OFF files are not supported by this program (convert it to ASCII OFF, PLY or OBJ)";
    std::size_t first = (off_prefix.find('n') != std::string::npos) ? 2 : 1;
    const char* names[2] = {"the header announces vertices:", "the header announces faces:"};
    for(std::size_t k = 0; k < 2; ++k)
    {
      double count = 0.;
      if(first + k >= tokens.size() || !to_number(tokens[first + k], count) || count != std::floor(count))
        return "the OFF header has no vertex and face counts (corrupt or truncated)";
      if(count < 0. || count > size)
        return too_large(names[k], count);
    }
    // The face lines (after the vertex lines): a face announcing more vertices than the file
    // has bytes makes CGAL 5.5 resize its index list to that count first.
    double announced_vertices = 0.;
    if(tokens.size() > first + 1 && to_number(tokens[first], announced_vertices))
    {
      std::istringstream lines(bytes);
      double line_index = -2.;  // the keyword line and the counts line come first
      for(std::string l; std::getline(lines, l);)
      {
        std::istringstream words(l.substr(0, comment_start(l)));
        std::string w;
        if(!(words >> w))
          continue;
        if(line_index < 0. && w.find("OFF") != std::string::npos && line_index < -1.5)
        {
          line_index += 1.;
          if(words >> w)  // the counts on the keyword line
            line_index += 1.;
          continue;
        }
        line_index += 1.;
        double n = 0.;
        if(line_index > announced_vertices && to_number(w, n) && (n < 0. || n > size))
          return "face " + std::to_string((long long)(line_index - announced_vertices - 1.)) + " announces " +
                 w + " vertices, more than a file of " + std::to_string(bytes.size()) +
                 " bytes can hold (corrupt)";
      }
    }
    // The same by tokens, as CGAL 5.5's scanner reads: the counts V F E may span lines; a
    // vertex is its coordinates (the rest of its line skipped: colors); a face is its size,
    // that many indices, and the rest of its line. A face size larger than the file is
    // corrupt wherever it stands on its line.
    {
      struct Token { std::string text; std::size_t line; };
      std::vector<Token> all;
      std::istringstream lines(bytes);
      std::size_t line_number = 0;
      for(std::string l; std::getline(lines, l); ++line_number)
      {
        std::istringstream words(l.substr(0, comment_start(l)));
        for(std::string w; words >> w;)
          all.push_back({w, line_number});
      }
      const std::string& key = off_prefix;
      std::size_t at = 1;
      double dimension = 3.;
      if(key.find('n') != std::string::npos)
      {
        if(at >= all.size() || !to_number(all[at].text, dimension) || dimension < 0. || dimension > size)
          return std::string();  // the readers reject it
        ++at;
      }
      double v_count = 0., f_count = 0.;
      if(at + 2 < all.size() && to_number(all[at].text, v_count) && to_number(all[at + 1].text, f_count) &&
         v_count >= 0. && f_count >= 0. && v_count <= size && f_count <= size)
      {
        at += 3;  // V F E
        if(at < all.size() && all[at].line == all[at - 1].line)  // CGAL would read them as vertex data
          return "the OFF counts line has more than the three counts V F E (corrupt)";
        // every vertex and every face has its own line: fewer lines is a truncated or corrupt
        // file (CGAL 5.5's scanner then reads past its buffers on some of them)
        {
          double data_lines = 0.;
          for(std::size_t i = at; i < all.size(); ++i)
            if(i == at || all[i].line != all[i - 1].line)
              data_lines += 1.;
          if(data_lines < v_count + f_count)
            return "the file announces " + std::to_string((long long)v_count) + " vertices and " +
                   std::to_string((long long)f_count) + " faces but has " + std::to_string((long long)data_lines) +
                   " lines of data after its counts (truncated or corrupt)";
        }
        const std::size_t per_vertex = std::size_t(dimension) + ((key.find('4') != std::string::npos) ? 1 : 0) +
                                       ((key.find('N') != std::string::npos) ? std::size_t(dimension) : 0) +
                                       ((key.find("ST") != std::string::npos) ? 2 : 0);
        auto next_line = [&all](std::size_t i) {  // the first token after the line of token i - 1
          const std::size_t line = all[i - 1].line;
          while(i < all.size() && all[i].line == line)
            ++i;
          return i;
        };
        for(std::size_t k = 0; k < std::size_t(v_count) && at < all.size(); ++k)
        {
          at += per_vertex;
          if(at > all.size())
            break;
          at = next_line(at);
        }
        for(std::size_t k = 0; k < std::size_t(f_count) && at < all.size(); ++k)
        {
          // the scanner reads the number at the start of the token ("66666666666z0" is 66666666666)
          char* end = nullptr;
          const double n = std::strtod(all[at].text.c_str(), &end);
          if(end == all[at].text.c_str())
            break;
          if(n < 0. || n > size)
            return "face " + std::to_string(k) + " announces " +
                   all[at].text.substr(0, std::size_t(end - all[at].text.c_str())) + " vertices, more than a file of " +
                   std::to_string(bytes.size()) + " bytes can hold (corrupt)";
          at += 1 + std::size_t(n);
          if(at > all.size())
            break;
          at = next_line(at);
        }
      }
    }
    // Vertex colors (C before OFF): CGAL 5.5's scanner reads the color entries of a vertex
    // line without checking that the line has them (a heap overflow on a malformed line).
    // Every vertex line must be numbers: the coordinates (and normals, texture), then 0, 1,
    // 3 or 4 color entries.
    const std::string& keyword = off_prefix;
    double vertex_count = 0.;
    if(keyword.find('C') != std::string::npos && keyword.find('n') == std::string::npos &&
       first < tokens.size() && to_number(tokens[first], vertex_count))
    {
      const std::size_t fixed = ((keyword.find('4') != std::string::npos) ? 4 : 3) +
                                ((keyword.find('N') != std::string::npos) ? 3 : 0) +
                                ((keyword.find("ST") != std::string::npos) ? 2 : 0);
      std::istringstream lines(bytes);
      std::size_t seen = 0, skip_counts = 1;  // the line of the counts
      for(std::string l; seen < std::size_t(vertex_count) && std::getline(lines, l);)
      {
        std::istringstream words(l.substr(0, comment_start(l)));
        std::vector<std::string> w;
        for(std::string t; words >> t;)
          w.push_back(t);
        if(w.empty() || w[0].find("OFF") != std::string::npos)
          continue;
        if(skip_counts > 0)
        {
          --skip_counts;
          continue;
        }
        const std::size_t colors = w.size() >= fixed ? w.size() - fixed : std::size_t(-1);
        bool numbers = true;
        for(const std::string& t : w)
        {
          double value = 0.;
          numbers = numbers && to_number(t, value);
        }
        if(!numbers || !(colors == 0 || colors == 1 || colors == 3 || colors == 4))
          return "vertex line " + std::to_string(seen) + " is malformed (expected " + std::to_string(fixed) +
                 " numbers and 0, 1, 3 or 4 color entries)";
        ++seen;
      }
    }
    return std::string();
  }

  if(ext == "ply")
  {
    // the header: format, elements (name, count) and their properties (scalar or list)
    struct Property { bool list = false; std::string count_type, type; std::string name; };
    struct Element { std::string name; double count = 0.; std::vector<Property> properties; };
    std::vector<Element> elements;
    std::string format;
    std::size_t pos = 0;
    bool header_ended = false;
    while(pos < bytes.size())
    {
      std::size_t end = bytes.find('\n', pos);
      if(end == std::string::npos)
        end = bytes.size();
      std::istringstream words(bytes.substr(pos, end - pos));
      pos = end + 1;
      std::string keyword;
      words >> keyword;
      if(keyword == "format")
        words >> format;
      else if(keyword == "element")
      {
        Element e;
        std::string count;
        words >> e.name >> count;
        if(!to_number(count, e.count))  // CGAL would read the number at its start ("1y": 1)
          return "the PLY header has an element count that is not a number: '" + count + "' (corrupt)";
        if(e.count < 0. || e.count > size)
          return too_large("the header announces " + e.name + " elements:", e.count);
        elements.push_back(e);
      }
      else if(keyword == "property" && elements.empty())  // CGAL 5.5 reads past its element list
        return "the PLY header has a property before any element (corrupt)";
      else if(keyword == "property")
      {
        Property p;
        std::string type;
        words >> type;
        if(type == "list")
        {
          p.list = true;
          words >> p.count_type >> p.type;
        }
        else
          p.type = type;
        words >> p.name;
        if(ply_type_size(p.type) == 0 || (p.list && ply_type_size(p.count_type) == 0))
          return "the PLY header has a property of unknown type '" + (p.list ? p.count_type + " " : std::string()) +
                 p.type + "' (corrupt)";
        elements.back().properties.push_back(p);
      }
      else if(keyword == "end_header")
      {
        header_ended = true;
        break;
      }
      else if(!keyword.empty() && keyword != "ply" && keyword != "comment" && keyword != "obj_info")
        return "the PLY header has an unknown line starting with '" + keyword + "' (corrupt)";
    }
    if(!header_ended)
      return "the PLY header has no end_header line (corrupt or truncated)";
    // CGAL 5.5 reads a header without a format line as ASCII (and sizes lists from it)
    if(format != "ascii" && format != "binary_little_endian" && format != "binary_big_endian")
      return "the PLY header has no valid format line (expected 'format ascii 1.0', 'format "
             "binary_little_endian 1.0' or 'format binary_big_endian 1.0')";

    // the body: every list count must fit in what is left of the file
    auto list_too_long = [&](const Element& e, const Property& p, double count) {
      return "element '" + e.name + "', property '" + p.name + "': a list of " +
             std::to_string((long long)count) + " entries, more than the rest of the file holds (corrupt)";
    };
    if(format == "ascii")
    {
      std::istringstream body(bytes.substr(std::min(pos, bytes.size())));
      std::vector<std::string> tokens;
      for(std::string t; body >> t;)
        tokens.push_back(t);
      std::size_t t = 0;
      for(const Element& e : elements)
        for(double i = 0.; i < e.count && !e.properties.empty(); i += 1.)
          for(const Property& p : e.properties)
          {
            if(t >= tokens.size())
              return std::string();  // truncated: the reader says so
            if(!p.list)
            {
              ++t;
              continue;
            }
            // CGAL reads the number at the start of the token ("4000000000x" is 4000000000)
            const std::string& token = tokens[t++];
            char* end = nullptr;
            const double count = std::strtod(token.c_str(), &end);
            if(end == token.c_str())
              return "element '" + e.name + "', property '" + p.name + "': a list count that is not a number (corrupt)";
            if(count < 0. || count > double(tokens.size() - t))
              return list_too_long(e, p, count);
            t += std::size_t(count);
          }
      return std::string();
    }
    if(format == "binary_little_endian" || format == "binary_big_endian")
    {
      const bool little = (format == "binary_little_endian");
      auto read_unsigned = [&](std::size_t at, std::size_t n) {
        double v = 0.;
        for(std::size_t k = 0; k < n; ++k)
          v = v * 256. + double(static_cast<unsigned char>(bytes[at + (little ? n - 1 - k : k)]));
        return v;
      };
      for(const Element& e : elements)
        for(double i = 0.; i < e.count && !e.properties.empty(); i += 1.)
          for(const Property& p : e.properties)
          {
            if(pos >= bytes.size())
              return std::string();  // truncated: the reader says so
            const std::size_t item = ply_type_size(p.type);
            if(item == 0)
              return std::string();  // unknown type: the reader says so
            if(!p.list)
            {
              pos += item;
              continue;
            }
            const std::size_t n = ply_type_size(p.count_type);
            if(n == 0 || p.count_type == "float" || p.count_type == "float32" || p.count_type == "double" ||
               p.count_type == "float64" || pos + n > bytes.size())
              return std::string();
            double count = read_unsigned(pos, n);
            const bool is_signed = p.count_type[0] != 'u';
            if(is_signed && count >= std::ldexp(1., int(8 * n) - 1))
              count -= std::ldexp(1., int(8 * n));  // two's complement
            pos += n;
            if(count < 0. || count * double(item) > double(bytes.size() - pos))
              return list_too_long(e, p, count);
            pos += std::size_t(count) * item;
          }
      return std::string();
    }
  }
  return std::string();
}

} // namespace internal

/// reads the polygon mesh of the file `path` (.off, .obj, .ply or .stl). Vertices keep the
/// order of the file (CGAL's readers add them in file order; the STL reader merges equal
/// points in order of first appearance). On failure, the message names the problem (the
/// caller prefixes the file name).
template <class Mesh>
Failure read_mesh(const std::string& path, Mesh& mesh)
{
  namespace fs = std::filesystem;
  Failure f;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if(!fs::exists(status))
  {
    f.detail = "no such file";
    return f;
  }
  if(fs::is_directory(status))
  {
    f.detail = "it is a directory, not a mesh file";
    return f;
  }
  {
    std::ifstream probe(path, std::ios::binary);
    if(!probe)
    {
      f.detail = std::string("cannot open: ") + std::strerror(errno);
      return f;
    }
    if(probe.peek() == std::ifstream::traits_type::eof())
    {
      f.detail = "the file is empty";
      return f;
    }
  }
  const std::string ext = lowercase_extension(path);
  if(ext != "off" && ext != "obj" && ext != "ply" && ext != "stl")
  {
    f.detail = "unsupported file extension '" + fs::path(path).extension().string() +
               "' (expected .off, .obj, .ply or .stl)";
    return f;
  }

  const std::string impossible = internal::find_impossible_count(path, ext);
  if(!impossible.empty())
  {
    f.detail = "cannot read it: " + impossible;
    return f;
  }

  // CGAL's read_polygon_mesh() is its polygon soup reader followed by a mesh builder that
  // indexes the points with the face indices unchecked (CGAL 5.5): an index out of range is a
  // heap overflow. So the soup is read, its indices checked, and the mesh built here as that
  // builder does (every point a vertex, in file order; faces added in file order).
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::property_traits<
    typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type Point_3;
  std::vector<Point_3> points;
  std::vector<std::vector<std::size_t> > polygons;
  bool read = false;
  try
  {
    read = CGAL::IO::read_polygon_soup(path, points, polygons);
  }
  catch(const std::bad_alloc&)  // a count the checks above let through, still too large
  {
    read = false;
  }
  catch(const std::length_error&)
  {
    read = false;
  }
  catch(const std::exception&)  // e.g. a CGAL precondition of the reader (a PLY coordinate
  {                             // stored as an integer), when CGAL's checks are compiled in
    read = false;
  }
  if(!read)
  {
    // Why did it fail? A non-finite coordinate, or a file that cannot be parsed at all.
    const std::string non_finite = internal::find_non_finite_number(path);
    if(!non_finite.empty())
    {
      f.code = SMP::ERROR_NON_FINITE_COORDINATES;
      f.detail = non_finite;
      return f;
    }
    f.detail = "cannot read it: not a valid ." + ext + " mesh file (malformed or truncated)";
    return f;
  }
  for(std::size_t i = 0; i < polygons.size(); ++i)
    for(std::size_t k : polygons[i])
      if(k >= points.size())
      {
        // OBJ numbers vertices from 1 (negative: from the end); the others from 0
        const std::string index = (k > points.size() + 1000000000ul) ? std::string("far out of range")
                                  : (ext == "obj") ? std::to_string(k + 1) + " (1-based)"
                                                   : std::to_string(k) + " (0-based)";
        f.detail = "cannot read it: face " + std::to_string(i) + " uses vertex index " + index +
                   ", but the file has " + std::to_string(points.size()) + " vertices";
        return f;
      }

  std::vector<vertex_descriptor> vertex(points.size());
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    vertex[i] = add_vertex(mesh);
    put(get(CGAL::vertex_point, mesh), vertex[i], points[i]);
  }
  bool built = true;
  std::vector<vertex_descriptor> face;
  for(const std::vector<std::size_t>& polygon : polygons)
  {
    face.clear();
    for(std::size_t k : polygon)
      face.push_back(vertex[k]);
    if(CGAL::Euler::add_face(face, mesh) == boost::graph_traits<Mesh>::null_face())
    {
      built = false;
      break;
    }
  }
  if(built)  // Euler::add_face keeps the mesh valid (isolated vertices included)
    return f;
  mesh.clear();
  f.detail = "not a polygon mesh: its " + std::to_string(polygons.size()) +
             " faces do not form a consistently oriented 2-manifold (an edge shared by more than"
             " two faces, a non-manifold vertex, inconsistent orientation, or a face that uses"
             " a vertex twice or has fewer than three vertices)";
  return f;
}

/// The fallback default mesh: a curved, elliptic disk (a hexagonal lattice pushed onto
/// concentric circles, lifted onto an asymmetric bump), 1261 vertices and 2400 faces.
/// `Mesh` is a `CGAL::Surface_mesh`, as in the rest of this file.
template <class Mesh>
void make_curved_disk(Mesh& mesh)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::property_traits<
    typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type Point_3;
  const int rings = 20;
  const std::size_t side = std::size_t(2 * rings + 1);
  auto ring_of = [](int q, int r) { return (std::abs(q) + std::abs(r) + std::abs(q + r)) / 2; };
  auto inside = [&](int q, int r) {
    return q >= -rings && q <= rings && r >= -rings && r <= rings && ring_of(q, r) <= rings;
  };
  std::vector<vertex_descriptor> id(side * side);
  auto slot = [&](int q, int r) -> vertex_descriptor& { return id[std::size_t(q + rings) * side + std::size_t(r + rings)]; };

  for(int q = -rings; q <= rings; ++q)
    for(int r = -rings; r <= rings; ++r)
      if(inside(q, r))
      {
        // lattice point, moved radially so that lattice ring k lies on the circle k / rings
        const double x = q + 0.5 * r, y = 0.5 * std::sqrt(3.) * r;
        const int k = ring_of(q, r);
        const double scale = (k == 0) ? 0. : (double(k) / rings) / std::sqrt(x * x + y * y);
        const double px = 1.4 * scale * x, py = 0.9 * scale * y;
        const double pz = 0.45 * px * px - 0.25 * py * py + 0.2 * px * py + 0.15 * std::sin(3. * px);
        slot(q, r) = mesh.add_vertex(Point_3(px, py, pz));
      }
  for(int q = -rings; q < rings; ++q)
    for(int r = -rings; r < rings; ++r)
    {
      if(inside(q, r) && inside(q + 1, r) && inside(q, r + 1))
        CGAL::Euler::add_face(std::array<vertex_descriptor, 3>{slot(q, r), slot(q + 1, r), slot(q, r + 1)}, mesh);
      if(inside(q + 1, r) && inside(q + 1, r + 1) && inside(q, r + 1))
        CGAL::Euler::add_face(std::array<vertex_descriptor, 3>{slot(q + 1, r), slot(q + 1, r + 1), slot(q, r + 1)}, mesh);
    }
}

/// checks what the program needs before the library runs, with precise messages: faces, all
/// triangles, one connected component.
template <class Mesh>
Failure check_mesh(const Mesh& mesh)
{
  typedef typename boost::graph_traits<Mesh>::face_descriptor face_descriptor;
  Failure f;
  if(faces(mesh).empty())
  {
    f.code = SMP::ERROR_EMPTY_MESH;
    f.detail = "it has no faces (" + std::to_string(num_vertices(mesh)) + " vertices)";
    return f;
  }

  std::size_t non_triangles = 0, first_index = 0, first_degree = 0, index = 0;
  for(face_descriptor fd : faces(mesh))
  {
    const std::size_t degree = CGAL::halfedges_around_face(halfedge(fd, mesh), mesh).size();
    if(degree != 3 && non_triangles++ == 0)
    {
      first_index = index;
      first_degree = degree;
    }
    ++index;
  }
  if(non_triangles > 0)
  {
    f.code = SMP::ERROR_NON_TRIANGULAR_MESH;
    f.detail = std::to_string(non_triangles) + " of its " + std::to_string(num_faces(mesh)) +
               " faces are not triangles (the first is face " + std::to_string(first_index) + ", with " +
               std::to_string(first_degree) + " vertices); triangulate it first";
    return f;
  }

  auto component = get(CGAL::dynamic_face_property_t<std::size_t>(), mesh);
  const std::size_t components = CGAL::Polygon_mesh_processing::connected_components(mesh, component);
  if(components > 1)
  {
    f.code = SMP::ERROR_NO_TOPOLOGICAL_DISC;
    f.detail = "it has " + std::to_string(components) +
               " connected components (the program needs one: extract it first)";
    return f;
  }

  return f;
}

/// sets `bhd` to a halfedge of the longest border of `tm` (a mesh, or a `Seam_mesh`, whose
/// seams are on its border) and `border_length` to the 3D length of that border. Fails for a
/// closed mesh, which needs seams.
template <class TriangleMesh>
Failure find_longest_border(const TriangleMesh& tm,
                            typename boost::graph_traits<TriangleMesh>::halfedge_descriptor& bhd,
                            double& border_length)
{
  Failure f;
  const auto border = CGAL::Polygon_mesh_processing::longest_border(tm);
  if(border.first == boost::graph_traits<TriangleMesh>::null_halfedge())
  {
    f.detail = "the mesh is closed (it has no border): give seams that cut it open into a disk with"
               " --seams=FILE.selection.txt";
    return f;
  }
  bhd = border.first;
  border_length = CGAL::to_double(border.second);
  return f;
}

/// The first face whose doubled area `2A` is at most `threshold` times its longest squared
/// edge (the library's test of `ERROR_DEGENERATE_FACE`), to name it in the message; empty
/// when there is none.
template <class Mesh>
std::string find_degenerate_face(const Mesh& mesh, double threshold)
{
  std::size_t index = 0;
  for(auto fd : faces(mesh))
  {
    std::vector<std::size_t> ids;
    std::vector<std::array<double, 3> > p;
    for(auto v : CGAL::vertices_around_face(halfedge(fd, mesh), mesh))
    {
      const auto& q = mesh.point(v);
      ids.push_back(std::size_t(v));
      p.push_back({CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z())});
    }
    if(p.size() == 3)
    {
      auto sub = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
        return std::array<double, 3>{a[0] - b[0], a[1] - b[1], a[2] - b[2]};
      };
      auto sq = [](const std::array<double, 3>& a) { return a[0] * a[0] + a[1] * a[1] + a[2] * a[2]; };
      const std::array<double, 3> a = sub(p[1], p[0]), b = sub(p[2], p[0]), c = sub(p[2], p[1]);
      const std::array<double, 3> n = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
      const double longest2 = (std::max)({sq(a), sq(b), sq(c)});
      const double double_area = std::sqrt(sq(n));
      if(!(double_area > threshold * longest2) || !std::isfinite(double_area))
        return "face " + std::to_string(index) + " (vertices " + std::to_string(ids[0]) + " " +
               std::to_string(ids[1]) + " " + std::to_string(ids[2]) + ")";
    }
    ++index;
  }
  return std::string();
}

/// The first vertex with a non-finite coordinate, to name it in the message; empty when there
/// is none (CGAL's binary readers let NaN through; its text readers stop at it).
template <class Mesh>
std::string find_non_finite_vertex(const Mesh& mesh)
{
  for(auto v : vertices(mesh))
  {
    const auto& p = mesh.point(v);
    if(!std::isfinite(CGAL::to_double(p.x())) || !std::isfinite(CGAL::to_double(p.y())) ||
       !std::isfinite(CGAL::to_double(p.z())))
      return "vertex " + std::to_string(std::size_t(v));
  }
  return std::string();
}

} // namespace mbp_cli

#endif // MBP_CLI_MESH_INPUT_H
