// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// Output files of the measured_parameterization program, all or nothing:
//
// - the targets are checked before the computation: none may be an input or another target
//   (the same file after resolving links: st_dev/st_ino, or the canonical path of a file that
//   does not exist yet); an existing target must be a regular file (a directory, FIFO, device,
//   socket or symbolic link is refused by name: a link is never replaced by a regular file);
//   its directory must exist;
// - each output is written (buffered, numbers by std::to_chars) to a temporary file with a
//   short name in the target's directory (".mbp-PID-K.tmp": a legal long target name never
//   makes the temporary name too long), and the targets are published (renamed) only when ALL
//   are written;
// - publishing keeps a hard link to every pre-existing target until all renames succeeded: a
//   failure puts the previous files back, so a failed run never deletes what was there;
// - SIGINT, SIGTERM and SIGHUP remove the temporary files (a signal handler unlinks a fixed
//   list of paths with the async-signal-safe unlink(), then re-raises the signal).
// No CGAL here.

#ifndef MBP_CLI_FILE_OUTPUT_H
#define MBP_CLI_FILE_OUTPUT_H

#include <charconv>
#include <cerrno>
#include <csignal>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

namespace mbp_cli {

namespace output_detail {

// The temporary files of this process, for the signal handler: a fixed array of paths (no
// allocation in the handler), `count` of them in use.
const int max_temporaries = 16;
const std::size_t max_path = 4096;
inline char temporaries[max_temporaries][max_path];
inline volatile std::sig_atomic_t count = 0;

extern "C" inline void remove_temporaries_and_reraise(int signal_number)
{
  for(int i = 0; i < count; ++i)
    if(temporaries[i][0] != '\0')
      ::unlink(temporaries[i]);
  ::signal(signal_number, SIG_DFL);
  ::raise(signal_number);
}

/// blocks the handled signals while a temporary file is created and registered
class Signals_blocked
{
public:
  Signals_blocked()
  {
    sigset_t set;
    sigemptyset(&set);
    for(int s : {SIGINT, SIGTERM, SIGHUP})
      sigaddset(&set, s);
    ::sigprocmask(SIG_BLOCK, &set, &m_old);
  }
  ~Signals_blocked() { ::sigprocmask(SIG_SETMASK, &m_old, nullptr); }

private:
  sigset_t m_old;
};

inline void install_handlers()
{
  static bool installed = false;
  if(installed)
    return;
  installed = true;
  struct sigaction action;
  std::memset(&action, 0, sizeof(action));
  action.sa_handler = remove_temporaries_and_reraise;
  sigemptyset(&action.sa_mask);
  for(int s : {SIGINT, SIGTERM, SIGHUP})
  {
    struct sigaction old;
    // a signal ignored by the parent (nohup) stays ignored
    if(::sigaction(s, nullptr, &old) == 0 && old.sa_handler != SIG_IGN)
      ::sigaction(s, &action, nullptr);
  }
}

/// registers `path` in a free slot (signals blocked by the caller); false when full or long
inline bool register_path(const std::string& path)
{
  if(path.size() + 1 > max_path)
    return false;
  for(int i = 0; i < count; ++i)
    if(temporaries[i][0] == '\0')
    {
      std::memcpy(temporaries[i], path.c_str(), path.size() + 1);
      return true;
    }
  if(count >= max_temporaries)
    return false;
  std::memcpy(temporaries[count], path.c_str(), path.size() + 1);
  count = count + 1;
  return true;
}

inline void unregister_path(const std::string& path)
{
  Signals_blocked blocked;
  for(int i = 0; i < count; ++i)
    if(path == temporaries[i])
      temporaries[i][0] = '\0';
}

/// what a file system object is, for a message
inline const char* kind(const struct stat& st)
{
  if(S_ISDIR(st.st_mode)) return "a directory";
  if(S_ISFIFO(st.st_mode)) return "a FIFO (named pipe)";
  if(S_ISCHR(st.st_mode)) return "a character device";
  if(S_ISBLK(st.st_mode)) return "a block device";
  if(S_ISSOCK(st.st_mode)) return "a socket";
  if(S_ISLNK(st.st_mode)) return "a symbolic link";
  return "not a regular file";
}

} // namespace output_detail

/// A file written through a buffer: text and numbers (std::to_chars), flushed in blocks.
class Buffered_writer
{
public:
  static constexpr std::size_t capacity = std::size_t(1) << 20;

  Buffered_writer() { m_buffer.reserve(capacity); }

  Buffered_writer& operator<<(std::string_view s)
  {
    if(m_buffer.size() + s.size() > capacity)
      flush();
    if(s.size() >= capacity)
      write_out(s.data(), s.size());
    else
      m_buffer.append(s.data(), s.size());
    return *this;
  }
  Buffered_writer& operator<<(char c) { return *this << std::string_view(&c, 1); }
  /// the shortest decimal text that reads back as exactly `x`
  Buffered_writer& operator<<(double x) { return number(x); }
  Buffered_writer& operator<<(std::size_t n) { return number(n); }

  /// writes the buffer out; false after any failed write (the error is kept)
  bool flush()
  {
    write_out(m_buffer.data(), m_buffer.size());
    m_buffer.clear();
    return m_errno == 0;
  }

  int error() const { return m_errno; }

private:
  friend class Output_files;

  template <class T>
  Buffered_writer& number(T x)
  {
    if(m_buffer.size() + 32 > capacity)
      flush();
    char digits[32];
    const std::to_chars_result r = std::to_chars(digits, digits + sizeof(digits), x);
    m_buffer.append(digits, r.ptr);
    return *this;
  }

  void write_out(const char* data, std::size_t n)
  {
    while(n > 0 && m_errno == 0)
    {
      const ssize_t w = ::write(m_fd, data, n);
      if(w < 0 && errno == EINTR)
        continue;
      if(w <= 0)
      {
        m_errno = (w < 0) ? errno : EIO;
        return;
      }
      data += w;
      n -= static_cast<std::size_t>(w);
    }
  }

  int m_fd = -1;
  int m_errno = 0;
  std::string m_buffer;
};

/// The output files of one run, all or nothing (see the top of this file). Usage: `add_input()`
/// for every file the run reads, `add_target()` for every output (before the computation),
/// then `begin(k)`, write into the returned writer, `end(k)` for every target, and
/// `publish()`. The destructor removes whatever was not published.
class Output_files
{
public:
  Output_files() = default;
  Output_files(const Output_files&) = delete;
  Output_files& operator=(const Output_files&) = delete;
  ~Output_files() { discard(); }

  /// a file the run reads (`what` names it in messages, e.g. "the input"); no output may be it
  void add_input(const std::string& path, const std::string& what)
  {
    Named n;
    n.path = path;
    n.what = what;
    struct stat st;
    if(::stat(path.c_str(), &st) == 0)
    {
      n.exists = true;
      n.device = st.st_dev;
      n.inode = st.st_ino;
    }
    m_inputs.push_back(n);
  }

  /// checks the output `path` (`what` names it, e.g. "OUTPUT" or "--svg"). Returns an error
  /// message, or an empty string; `usage` is set when the problem is the command line (the
  /// target names an input or another target) rather than the file system.
  std::string add_target(const std::string& path, const std::string& what, bool& usage)
  {
    namespace fs = std::filesystem;
    usage = false;
    const std::string cannot = "cannot write " + what + " '" + path + "': ";
    const fs::path target(path);
    struct stat st;
    const bool exists = ::lstat(path.c_str(), &st) == 0;
    const int lstat_errno = exists ? 0 : errno;
    if(exists && S_ISDIR(st.st_mode))
      return cannot + "it is a directory, not a regular file";
    if(target.filename().empty() || target.filename() == "." || target.filename() == "..")
      return cannot + "not a file name";
    Target t;
    t.path = path;
    t.what = what;
    std::string error;
    if(exists)
      error = check_existing_target(st, cannot, usage, t);
    else if(lstat_errno != ENOENT)
      return cannot + std::strerror(lstat_errno);
    else
      error = check_directory(target, cannot);
    if(error.empty())
      error = check_names(t, usage);
    if(error.empty())
      m_targets.push_back(t);
    return error;
  }

  /// creates the temporary file of target `k` and returns its writer (null on failure: see
  /// `error()`)
  Buffered_writer* begin(std::size_t k)
  {
    namespace fs = std::filesystem;
    output_detail::install_handlers();
    Target& t = m_targets[k];
    const fs::path directory = fs::path(t.path).parent_path();
    for(int attempt = 0; attempt < 100; ++attempt)
    {
      const std::string name = ".mbp-" + std::to_string(::getpid()) + "-" + std::to_string(k) +
                               (attempt > 0 ? "-" + std::to_string(attempt) : std::string()) + ".tmp";
      const std::string temporary = directory.empty() ? name : (directory / name).string();
      output_detail::Signals_blocked blocked;
      const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
      if(fd < 0 && errno == EEXIST)
        continue;
      if(fd < 0)
      {
        m_error = "cannot write " + t.what + " '" + t.path + "': " + std::strerror(errno);
        return nullptr;
      }
      if(!output_detail::register_path(temporary))
      {
        ::close(fd);
        ::unlink(temporary.c_str());
        m_error = "cannot write " + t.what + " '" + t.path + "': its directory's path is too long";
        return nullptr;
      }
      t.temporary = temporary;
      t.writer.m_fd = fd;
      return &t.writer;
    }
    m_error = "cannot write " + t.what + " '" + t.path + "': no free temporary file name";
    return nullptr;
  }

  /// flushes and closes the temporary file of target `k`; false on failure (see `error()`)
  bool end(std::size_t k)
  {
    Target& t = m_targets[k];
    const bool flushed = t.writer.flush();
    const int fd = t.writer.m_fd;
    t.writer.m_fd = -1;
    if(!flushed || ::close(fd) != 0)
    {
      m_error = "cannot write " + t.what + " '" + t.path + "': " +
                std::strerror(t.writer.error() != 0 ? t.writer.error() : errno);
      return false;
    }
    t.written = true;
    return true;
  }

  /// renames every temporary file to its target, all or none: on a failure, the targets
  /// already renamed get their previous contents back (or are removed when there was none)
  bool publish()
  {
    if(!back_up_targets() || !rename_targets())
      return false;
    for(Target& t : m_targets)
      if(!t.backup.empty())
      {
        ::unlink(t.backup.c_str());
        forget(t.backup);
      }
    m_targets.clear();
    return true;
  }

  /// the message of the last failure
  const std::string& error() const { return m_error; }

private:
  struct Named
  {
    std::string path, what;
    bool exists = false;
    dev_t device = 0;
    ino_t inode = 0;
  };
  struct Target : Named
  {
    std::filesystem::path canonical;
    std::string temporary, backup;
    Buffered_writer writer;
    bool written = false, published = false, backup_by_rename = false;
  };

  // the checks of an existing target `t` (its lstat() `st`): a regular file that is no input
  std::string check_existing_target(const struct stat& st, const std::string& cannot, bool& usage, Target& t) const
  {
    if(S_ISLNK(st.st_mode))
    {
      struct stat pointed;
      if(::stat(t.path.c_str(), &pointed) == 0)
      {
        const std::string same = same_as_input(pointed, usage, t, t.path);
        if(!same.empty())
          return same;
      }
      return cannot + "it is a symbolic link; the program does not replace a link by a file (give the path of"
                      " the file it points to, or remove the link)";
    }
    if(!S_ISREG(st.st_mode))
      return cannot + "it is " + output_detail::kind(st) + ", not a regular file";
    const std::string same = same_as_input(st, usage, t, t.path);
    if(!same.empty())
      return same;
    t.exists = true;
    t.device = st.st_dev;
    t.inode = st.st_ino;
    return std::string();
  }

  // the check of a target that does not exist: its directory must exist (the temporary file
  // is created there)
  static std::string check_directory(const std::filesystem::path& target, const std::string& cannot)
  {
    namespace fs = std::filesystem;
    const fs::path directory = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    struct stat d;
    if(::stat(directory.c_str(), &d) != 0)
      return cannot + "its directory '" + directory.string() + "': " + std::strerror(errno);
    if(!S_ISDIR(d.st_mode))
      return cannot + "'" + directory.string() + "' is not a directory";
    return std::string();
  }

  // the target `t` may not name an input that does not exist yet, nor another target
  std::string check_names(Target& t, bool& usage) const
  {
    t.canonical = canonical(t.path);
    for(const Named& in : m_inputs)
      if(!in.exists && !t.exists && t.canonical == canonical(in.path))
      {
        usage = true;
        return t.what + " '" + t.path + "' names " + in.what + " '" + in.path + "'";
      }
    for(const Target& other : m_targets)
      if((t.exists && other.exists && t.device == other.device && t.inode == other.inode) ||
         t.canonical == other.canonical)
      {
        usage = true;
        return t.what + " '" + t.path + "' and " + other.what + " '" + other.path + "' name the same file";
      }
    return std::string();
  }

  // the first step of publish(): hard links to the pre-existing targets, kept until every
  // rename succeeded
  bool back_up_targets()
  {
    for(std::size_t k = 0; k < m_targets.size(); ++k)
    {
      Target& t = m_targets[k];
      if(!t.written)
      {
        m_error = "internal: " + t.what + " was not written";
        return false;
      }
      struct stat st;
      if(::lstat(t.path.c_str(), &st) != 0)
        continue;
      if(!S_ISREG(st.st_mode))  // changed since the check
      {
        m_error = "cannot write " + t.what + " '" + t.path + "': it is " + output_detail::kind(st) +
                  ", not a regular file";
        return false;
      }
      // a hard link where the file system has them, else the old file is renamed aside
      // just before its replacement
      const std::string backup = t.temporary.substr(0, t.temporary.size() - 4) + ".old";
      output_detail::Signals_blocked blocked;
      if(!output_detail::register_path(backup))
      {
        m_error = "cannot write " + t.what + " '" + t.path + "': too many files";
        return false;
      }
      t.backup = backup;
      t.backup_by_rename = (::link(t.path.c_str(), backup.c_str()) != 0);
    }
    return true;
  }

  // the second step of publish(): every temporary file renamed to its target, or, on a
  // failure, the targets renamed before put back
  bool rename_targets()
  {
    for(std::size_t k = 0; k < m_targets.size(); ++k)
    {
      Target& t = m_targets[k];
      const bool aside = !t.backup_by_rename || std::rename(t.path.c_str(), t.backup.c_str()) == 0;
      if(!aside || std::rename(t.temporary.c_str(), t.path.c_str()) != 0)
      {
        m_error = "cannot write " + t.what + " '" + t.path + "': " + std::strerror(errno);
        if(aside && t.backup_by_rename)
          std::rename(t.backup.c_str(), t.path.c_str());
        for(std::size_t j = 0; j < k; ++j)  // undo
        {
          Target& done = m_targets[j];
          if(!done.backup.empty())
          {
            if(std::rename(done.backup.c_str(), done.path.c_str()) == 0)
              forget(done.backup);
          }
          else
            ::unlink(done.path.c_str());
        }
        return false;
      }
      forget(t.temporary);
      t.published = true;
    }
    return true;
  }

  // the absolute path with the links of its existing part resolved, '.' and '..' removed
  static std::filesystem::path canonical(const std::string& path)
  {
    namespace fs = std::filesystem;
    std::error_code ec;
    const fs::path absolute = fs::absolute(path, ec);
    const fs::path resolved = fs::weakly_canonical(absolute, ec);
    return ec ? absolute.lexically_normal() : resolved;
  }

  // the message when `st` (the target's file) is an input, else empty
  std::string same_as_input(const struct stat& st, bool& usage, const Target& t, const std::string& path) const
  {
    for(const Named& in : m_inputs)
      if(in.exists && in.device == st.st_dev && in.inode == st.st_ino)
      {
        usage = true;
        return t.what + " '" + path + "' is " + in.what + " '" + in.path +
               "' (the same file): it would be overwritten; choose another name";
      }
    return std::string();
  }

  static void forget(std::string& path)
  {
    output_detail::unregister_path(path);
    path.clear();
  }

  void discard()
  {
    for(Target& t : m_targets)
    {
      if(t.writer.m_fd >= 0)
        ::close(t.writer.m_fd);
      if(!t.temporary.empty())
      {
        ::unlink(t.temporary.c_str());
        forget(t.temporary);
      }
      if(!t.backup.empty())
      {
        ::unlink(t.backup.c_str());
        forget(t.backup);
      }
    }
    m_targets.clear();
  }

  std::vector<Named> m_inputs;
  std::vector<Target> m_targets;
  std::string m_error;
};

} // namespace mbp_cli

#endif // MBP_CLI_FILE_OUTPUT_H
