// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// Text output of the measured_parameterization program: number formatting and a small JSON
// writer (the output files themselves: file_output.h). No CGAL here.

#ifndef MBP_CLI_TEXT_OUTPUT_H
#define MBP_CLI_TEXT_OUTPUT_H

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

namespace mbp_cli {

// The extension of `path` without its dot, lowercase ("a/b.OFF" -> "off").
inline std::string lowercase_extension(const std::string& path)
{
  std::string ext = std::filesystem::path(path).extension().string();
  if(!ext.empty())
    ext.erase(0, 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

// Whether `path` has the extension of a mesh format the program reads: .off, .obj, .ply or
// .stl, in any case. (The one list of the formats: the reader, the batch's folder listing
// and the benchmarks' call this.)
inline bool is_mesh_file_name(const std::string& path)
{
  const std::string ext = lowercase_extension(path);
  return ext == "off" || ext == "obj" || ext == "ply" || ext == "stl";
}

// The mesh files of the folder `folder` (is_mesh_file_name; subfolders skipped), sorted; `ec`
// gets the error when the folder cannot be listed.
inline std::vector<std::filesystem::path> mesh_files_in(const std::filesystem::path& folder, std::error_code& ec)
{
  std::vector<std::filesystem::path> files;
  for(const std::filesystem::directory_entry& e : std::filesystem::directory_iterator(folder, ec))
    if(!e.is_directory(ec) && is_mesh_file_name(e.path().string()))
      files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

/// the shortest decimal text that reads back as exactly `x` (full double precision).
inline std::string exact(double x)
{
  char buffer[32];
  const std::to_chars_result r = std::to_chars(buffer, buffer + sizeof(buffer), x);
  return std::string(buffer, r.ptr);
}

/// `x` with `digits` significant digits, for people ("inf" and "nan" as printf writes them).
inline std::string rounded(double x, int digits = 4)
{
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.*g", digits, x);
  return buffer;
}

/// A JSON document written in order: objects, arrays and scalar members, indented by two
/// spaces. Strings are escaped (invalid UTF-8 becomes U+FFFD); a non-finite number is
/// written as null.
class Json_writer
{
public:
  Json_writer& begin_object(const std::string& key = std::string()) { return open(key, '{', false); }
  Json_writer& end_object() { return close('}'); }
  /// an array, written on one line unless `one_line` is false (an array of objects)
  Json_writer& begin_array(const std::string& key = std::string(), bool one_line = true)
  {
    return open(key, '[', one_line);
  }
  Json_writer& end_array() { return close(']'); }

  Json_writer& member(const std::string& key, const std::string& value) { return raw(key, quoted(value)); }
  Json_writer& member(const std::string& key, const char* value) { return raw(key, quoted(value)); }
  Json_writer& member(const std::string& key, double value) { return raw(key, number(value)); }
  Json_writer& member(const std::string& key, std::size_t value) { return raw(key, std::to_string(value)); }
  Json_writer& member(const std::string& key, int value) { return raw(key, std::to_string(value)); }
  Json_writer& member(const std::string& key, bool value) { return raw(key, value ? "true" : "false"); }
  Json_writer& null_member(const std::string& key) { return raw(key, "null"); }
  /// an element of the current array
  Json_writer& element(double value) { return raw(std::string(), number(value)); }

  const std::string& text() const { return m_text; }

  static std::string number(double x) { return std::isfinite(x) ? exact(x) : std::string("null"); }

  static std::string quoted(const std::string& s)
  {
    std::string q = "\"";
    for(std::size_t i = 0; i < s.size();)
    {
      const unsigned char c = static_cast<unsigned char>(s[i]);
      if(c == '"' || c == '\\')
      {
        q += '\\';
        q += char(c);
        ++i;
      }
      else if(c < 0x20)
      {
        const char* named = (c == '\n') ? "\\n" : (c == '\t') ? "\\t" : (c == '\r') ? "\\r"
                          : (c == '\b') ? "\\b" : (c == '\f') ? "\\f" : nullptr;
        if(named != nullptr)
          q += named;
        else
        {
          char u[8];
          std::snprintf(u, sizeof(u), "\\u%04x", unsigned(c));
          q += u;
        }
        ++i;
      }
      else if(c < 0x80)
      {
        q += char(c);
        ++i;
      }
      else
      {
        const std::size_t n = utf8_sequence_length(s, i);
        if(n == 0)
        {
          q += "\\ufffd";
          ++i;
        }
        else
        {
          q.append(s, i, n);
          i += n;
        }
      }
    }
    return q + "\"";
  }

private:
  // length of the valid UTF-8 sequence starting at s[i] (a byte >= 0x80), or 0
  static std::size_t utf8_sequence_length(const std::string& s, std::size_t i)
  {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    std::size_t n = 0;
    unsigned long min = 0;
    if(c >= 0xc2 && c <= 0xdf) { n = 2; min = 0x80; }
    else if(c >= 0xe0 && c <= 0xef) { n = 3; min = 0x800; }
    else if(c >= 0xf0 && c <= 0xf4) { n = 4; min = 0x10000; }
    else return 0;
    if(i + n > s.size())
      return 0;
    unsigned long code = c & (0xff >> (n + 1));
    for(std::size_t k = 1; k < n; ++k)
    {
      const unsigned char d = static_cast<unsigned char>(s[i + k]);
      if((d & 0xc0) != 0x80)
        return 0;
      code = (code << 6) | (d & 0x3f);
    }
    if(code < min || code > 0x10ffff || (code >= 0xd800 && code <= 0xdfff))
      return 0;
    return n;
  }

  Json_writer& raw(const std::string& key, const std::string& value)
  {
    separate();
    if(!key.empty())
      m_text += quoted(key) + ": ";
    m_text += value;
    return *this;
  }

  Json_writer& open(const std::string& key, char bracket, bool one_line)
  {
    raw(key, std::string(1, bracket));
    m_open.push_back({true, one_line});
    return *this;
  }

  Json_writer& close(char bracket)
  {
    const Container c = m_open.back();
    m_open.pop_back();
    if(!c.empty && !c.one_line)
      m_text += "\n" + std::string(2 * m_open.size(), ' ');
    m_text += bracket;
    if(m_open.empty())
      m_text += "\n";
    return *this;
  }

  void separate()
  {
    if(m_open.empty())
      return;
    Container& c = m_open.back();
    if(!c.empty)
      m_text += c.one_line ? ", " : ",";
    if(!c.one_line)
      m_text += "\n" + std::string(2 * m_open.size(), ' ');
    c.empty = false;
  }

  struct Container
  {
    bool empty;     // nothing written in it yet
    bool one_line;
  };
  std::string m_text;
  std::vector<Container> m_open;
};

} // namespace mbp_cli

#endif // MBP_CLI_TEXT_OUTPUT_H
