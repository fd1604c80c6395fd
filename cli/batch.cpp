// Copyright (c) 2026  The measured boundary parameterization authors.
// All rights reserved.
//
// This file is part of the measured boundary parameterization package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s)     : The measured boundary parameterization authors

// The batch mode (batch.h): the input list, the report, the worker processes. No CGAL here.

#include "batch.h"
#include "text_output.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace mbp_cli {

namespace {

namespace fs = std::filesystem;
typedef std::chrono::steady_clock Clock;

const int exit_failure = 1;
const int exit_usage = 2;

// ------------------------------------------------------------------------------ the inputs

// The paths of a list (one a line; empty lines and lines starting with # skipped), relative
// ones taken from `base`.
std::vector<std::string> read_list(std::istream& in, const fs::path& base)
{
  std::vector<std::string> inputs;
  std::string line;
  while(std::getline(in, line))
  {
    if(!line.empty() && line.back() == '\r')
      line.pop_back();
    if(line.empty() || line[0] == '#')
      continue;
    const fs::path p(line);
    inputs.push_back(p.is_absolute() || base.empty() ? line : (base / p).string());
  }
  return inputs;
}

// The inputs of --batch, sorted, without duplicates; `error` set when there are none.
std::vector<std::string> list_inputs(const Batch_options& b, std::string& error)
{
  std::vector<std::string> inputs;
  std::error_code ec;
  if(b.source == "-")
    inputs = read_list(std::cin, fs::path());
  else if(fs::is_directory(b.source, ec))
  {
    for(const fs::path& p : mesh_files_in(b.source, ec))
      inputs.push_back(p.string());
    if(ec)
      error = "--batch=" + b.source + ": cannot list the folder: " + ec.message();
  }
  else if(fs::exists(b.source, ec))
  {
    std::ifstream list(b.source);
    if(!list)
      error = "--batch=" + b.source + ": cannot read the list file";
    inputs = read_list(list, fs::path(b.source).parent_path());
  }
  else
    error = "--batch=" + b.source + ": no such folder or list file";
  std::sort(inputs.begin(), inputs.end());
  inputs.erase(std::unique(inputs.begin(), inputs.end()), inputs.end());
  if(error.empty() && inputs.empty())
    error = "--batch=" + b.source + ": no input (a folder's .off, .obj, .ply and .stl files, or a list's lines)";
  return inputs;
}

// The output of each input, DIR/<stem>_uv.obj, or DIR/<file name>_uv.obj for the inputs
// that share a stem; decided on the whole list, so that every shard names them alike.
std::vector<std::string> output_names(const std::vector<std::string>& inputs, const fs::path& dir, std::string& error)
{
  std::map<std::string, int> stems;
  for(const std::string& input : inputs)
    ++stems[fs::path(input).stem().string()];
  std::vector<std::string> outputs;
  std::map<std::string, std::string> taken;
  for(const std::string& input : inputs)
  {
    const fs::path p(input);
    const std::string stem = p.stem().string();
    const std::string name = (stems[stem] > 1 ? p.filename().string() : stem) + "_uv.obj";
    if(!taken.emplace(name, input).second && error.empty())
      error = "two inputs have the same file name: '" + taken[name] + "' and '" + input +
              "' (their outputs would both be " + name + ")";
    outputs.push_back((dir / name).string());
  }
  return outputs;
}

// ------------------------------------------------------------------------------ the report

struct Report_line
{
  std::string input, status;
  std::vector<std::string> outputs;
  std::string text;  // the whole line
};

// The JSON string at text[pos] (a quote), decoded; `pos` moves past it. False when it is not
// one. (\u escapes: the report's strings only hold \u00XX and \ufffd.)
bool read_string(const std::string& text, std::size_t& pos, std::string& s)
{
  if(pos >= text.size() || text[pos] != '"')
    return false;
  s.clear();
  for(++pos; pos < text.size(); ++pos)
  {
    char c = text[pos];
    if(c == '"')
    {
      ++pos;
      return true;
    }
    if(c == '\\' && ++pos < text.size())
    {
      c = text[pos];
      if(c == 'u' && pos + 4 < text.size())
      {
        const unsigned long u = std::strtoul(text.substr(pos + 1, 4).c_str(), nullptr, 16);
        s += u < 0x80 ? std::string(1, char(u)) : std::string("\xEF\xBF\xBD");
        pos += 4;
        continue;
      }
      c = c == 'n' ? '\n' : c == 't' ? '\t' : c == 'r' ? '\r' : c == 'b' ? '\b' : c == 'f' ? '\f' : c;
    }
    s += c;
  }
  return false;
}

bool skip(const std::string& text, std::size_t& pos, const std::string& expected)
{
  if(text.compare(pos, expected.size(), expected) != 0)
    return false;
  pos += expected.size();
  return true;
}

// A line of a report as this program writes it: {"input":..,"status":..,"outputs":[..],...
bool parse_report_line(const std::string& text, Report_line& r)
{
  std::size_t pos = 0;
  r.text = text;
  r.outputs.clear();
  if(!skip(text, pos, "{\"input\":") || !read_string(text, pos, r.input) ||
     !skip(text, pos, ",\"status\":") || !read_string(text, pos, r.status) || !skip(text, pos, ",\"outputs\":["))
    return false;
  std::string output;
  while(pos < text.size() && text[pos] != ']')
  {
    if(!read_string(text, pos, output))
      return false;
    r.outputs.push_back(output);
    skip(text, pos, ",");
  }
  return pos < text.size();
}

// The last line of each input in the report file (none when it does not exist).
std::map<std::string, Report_line> read_report(const fs::path& path)
{
  std::map<std::string, Report_line> lines;
  std::ifstream in(path);
  std::string text;
  Report_line r;
  while(std::getline(in, text))
    if(parse_report_line(text, r))
      lines[r.input] = r;
  return lines;
}

// Whether the mesh was done by an earlier run: its last line says OK and names `output`
// (the output this run would write), its outputs exist.
bool done_before(const std::map<std::string, Report_line>& report, const std::string& input, const std::string& output)
{
  const auto it = report.find(input);
  if(it == report.end() || it->second.status != "OK" ||
     std::find(it->second.outputs.begin(), it->second.outputs.end(), output) == it->second.outputs.end())
    return false;
  std::error_code ec;
  for(const std::string& output : it->second.outputs)
    if(!fs::is_regular_file(output, ec))
      return false;
  return true;
}

// A JSON document on one line: whitespace outside strings removed.
std::string one_line(const std::string& json)
{
  std::string line;
  bool in_string = false, escaped = false;
  for(char c : json)
  {
    if(in_string)
    {
      in_string = escaped || c != '"';
      escaped = !escaped && c == '\\';
    }
    else if(c == '"')
      in_string = true;
    else if(c == ' ' || c == '\n' || c == '\t' || c == '\r')
      continue;
    line += c;
  }
  return line;
}

// ------------------------------------------------------------------------------ the workers

struct Job
{
  std::string input, output;
  std::string out_path, err_path;  // the worker's stdout and stderr
  Clock::time_point start;
};

struct Outcome
{
  bool ok = false;
  std::string message, figures = "null";
};

std::string read_file(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The message of a worker: its "error: " lines, or else everything it wrote on stderr, on
// one line.
std::string worker_message(const std::string& err)
{
  std::istringstream lines(err);
  std::string line, errors, all;
  while(std::getline(lines, line))
  {
    if(line.empty())
      continue;
    all += (all.empty() ? "" : "; ") + line;
    if(line.compare(0, 7, "error: ") == 0)
      errors += (errors.empty() ? "" : "; ") + line.substr(7);
  }
  return errors.empty() ? all : errors;
}

// What a worker that ended with `status` (waitpid()) did.
Outcome outcome_of(const Job& job, int status)
{
  Outcome o;
  const std::string out = read_file(job.out_path), err = read_file(job.err_path);
  o.message = worker_message(err);
  if(WIFSIGNALED(status))
  {
    const int s = WTERMSIG(status);
    o.message = "the worker was killed by signal " + std::to_string(s) + " (" + strsignal(s) + ")" +
                (o.message.empty() ? std::string() : ": " + o.message);
    return o;
  }
  o.ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  if(!WIFEXITED(status))
    o.message = "the worker ended abnormally";
  else if(!o.ok && o.message.empty())
    o.message = "the worker exited with status " + std::to_string(WEXITSTATUS(status));
  const std::string figures = one_line(out);
  if(!figures.empty() && figures.front() == '{' && figures.back() == '}')
    o.figures = figures;
  return o;
}

// The report line of a mesh.
std::string report_line(const Job& job, const Outcome& o, double seconds)
{
  std::string line = "{\"input\":" + Json_writer::quoted(job.input) + ",\"status\":\"" +
                     (o.ok ? "OK" : "FAILED") + "\",\"outputs\":[";
  if(o.ok)
    line += Json_writer::quoted(job.output);
  return line + "],\"message\":" + Json_writer::quoted(o.message) + ",\"seconds\":" +
         Json_writer::number(seconds) + ",\"figures\":" + o.figures + "}";
}

// The worker's command line: this program, the options of a mode (those of the batch left
// out), --json, then "--" INPUT OUTPUT.
std::vector<std::string> worker_arguments(const std::string& program, int argc, char** argv, const Job& job)
{
  std::vector<std::string> args{program};
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    bool batch_option = a == "--" || a == "--force";
    for(const char* name : {"--batch", "--output-dir", "--jobs", "--shard"})
      batch_option = batch_option || a == name || a.compare(0, std::strlen(name) + 1, std::string(name) + "=") == 0;
    if(!batch_option)
      args.push_back(a);
  }
  for(const char* a : {"--json", "--"})
    args.push_back(a);
  args.push_back(job.input);
  args.push_back(job.output);
  return args;
}

// Starts the worker of `job`: stdin from /dev/null, stdout and stderr into its files.
// Returns its process id, or -1 (errno set).
pid_t spawn_worker(const std::vector<std::string>& args, const Job& job)
{
  std::vector<char*> argv;
  for(const std::string& a : args)
    argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, job.out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  posix_spawn_file_actions_addopen(&actions, 2, job.err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  pid_t pid = -1;
  const int e = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if(e != 0)
  {
    errno = e;
    return -1;
  }
  return pid;
}

// ------------------------------------------------------------------------------ the batch

class Batch
{
public:
  Batch(const Options& options, int argc, char** argv)
    : m_b(options.batch), m_argc(argc), m_argv(argv)
  { }

  int run();

private:
  std::string prepare();
  void start(std::size_t k);
  void finish(pid_t pid, int status);
  void append(const std::string& line);
  bool rewrite_report();
  void progress(bool last);

  const Batch_options& m_b;
  int m_argc;
  char** m_argv;
  std::string m_program;                // the worker's executable
  fs::path m_dir, m_report, m_scratch;  // --output-dir, the report, the workers' stdout and stderr
  std::vector<std::string> m_inputs, m_outputs;  // of this shard, in order
  std::map<std::string, Report_line> m_before;   // the report of the earlier runs
  std::map<pid_t, Job> m_running;
  std::size_t m_done = 0, m_skipped = 0, m_failed = 0;
  bool m_report_ok = true;
  bool m_tty = false;
};

// The inputs of this shard, their outputs, the folders and the earlier report. Returns the
// error.
std::string Batch::prepare()
{
  std::string error;
  const std::vector<std::string> all = list_inputs(m_b, error);
  m_dir = m_b.output_dir;
  std::error_code ec;
  if(error.empty() && m_b.source != "-" && fs::is_directory(m_b.source, ec) && fs::exists(m_dir, ec) &&
     fs::equivalent(m_dir, m_b.source, ec))
    error = "--output-dir=" + m_b.output_dir + " is the input folder: choose another folder for the outputs";
  const std::vector<std::string> outputs = error.empty() ? output_names(all, m_dir, error) : all;
  if(!error.empty())
    return error;
  for(std::size_t k = 0; k < all.size(); ++k)
    if(k % m_b.shards == m_b.shard - 1)
    {
      m_inputs.push_back(all[k]);
      m_outputs.push_back(outputs[k]);
    }
  fs::create_directories(m_dir, ec);
  if(!fs::is_directory(m_dir, ec))
    return "--output-dir=" + m_b.output_dir + ": cannot create the folder" + (ec ? ": " + ec.message() : std::string());
  m_report = m_dir / (m_b.shards == 1 ? std::string("report.jsonl")
                                       : "report-shard-" + std::to_string(m_b.shard) + "-of-" +
                                             std::to_string(m_b.shards) + ".jsonl");
  m_before = read_report(m_report);
  m_scratch = fs::temp_directory_path(ec) / ("mbp-batch-" + std::to_string(::getpid()));
  fs::create_directories(m_scratch, ec);
  if(ec)
    return "cannot create the folder of the workers' outputs " + m_scratch.string() + ": " + ec.message();
  // the worker is this program: /proc/self/exe where there is one (Linux), or argv[0]
  m_program = fs::exists("/proc/self/exe", ec) ? fs::read_symlink("/proc/self/exe", ec).string() : m_argv[0];
  if(m_program.empty())
    m_program = m_argv[0];
  return std::string();
}

void Batch::start(std::size_t k)
{
  Job job;
  job.input = m_inputs[k];
  job.output = m_outputs[k];
  job.out_path = (m_scratch / (std::to_string(k) + ".json")).string();
  job.err_path = (m_scratch / (std::to_string(k) + ".err")).string();
  job.start = Clock::now();
  const pid_t pid = spawn_worker(worker_arguments(m_program, m_argc, m_argv, job), job);
  if(pid < 0)
  {
    Outcome o;
    o.message = "could not start the worker " + m_program + ": " + std::strerror(errno);
    ++m_failed;
    append(report_line(job, o, 0.));
    return;
  }
  // A test aid (test_cli, batch_reports_every_mesh_and_resumes): the worker of the input whose
  // file name is MBP_CLI_TEST_KILL_INPUT is killed with SIGKILL as soon as it is started, from
  // outside, as the kernel's out-of-memory killer or an operator would; the library is not
  // involved, and the worker's own code is the same as in any batch.
  const char* kill_name = std::getenv("MBP_CLI_TEST_KILL_INPUT");
  if(kill_name != nullptr && fs::path(job.input).filename() == kill_name)
    ::kill(pid, SIGKILL);
  m_running.emplace(pid, job);
}

void Batch::finish(pid_t pid, int status)
{
  const auto it = m_running.find(pid);
  if(it == m_running.end())
    return;
  const Job job = it->second;
  m_running.erase(it);
  const Outcome o = outcome_of(job, status);
  const double seconds = std::chrono::duration<double>(Clock::now() - job.start).count();
  std::error_code ec;
  fs::remove(job.out_path, ec);
  fs::remove(job.err_path, ec);
  if(o.ok)
    ++m_done;
  else
  {
    ++m_failed;
    if(m_tty)
      std::cerr << "\r\033[K";
    // (a worker's message names its input when it is about the input)
    std::cerr << "error: " << (o.message.compare(0, job.input.size(), job.input) == 0 ? "" : job.input + ": ")
              << o.message << "\n";
  }
  append(report_line(job, o, seconds));
}

// Appends a line to the report at once (an interrupted batch keeps it).
void Batch::append(const std::string& line)
{
  std::ofstream out(m_report, std::ios::app | std::ios::binary);
  out << line << '\n';
  out.flush();
  m_report_ok = m_report_ok && out.good();
}

// The report rewritten: the last line of every mesh of this run in the order of the inputs,
// then the other meshes of earlier runs, by input; written to a temporary file, then renamed.
bool Batch::rewrite_report()
{
  std::map<std::string, Report_line> lines = read_report(m_report);
  const fs::path temporary = m_report.string() + ".tmp-" + std::to_string(::getpid());
  std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
  for(const std::string& input : m_inputs)
  {
    const auto it = lines.find(input);
    if(it != lines.end())
    {
      out << it->second.text << '\n';
      lines.erase(it);
    }
  }
  for(const auto& other : lines)
    out << other.second.text << '\n';
  out.close();
  std::error_code ec;
  if(out.good())
    fs::rename(temporary, m_report, ec);
  if(!out.good() || ec)
    fs::remove(temporary, ec);
  return out.good() && !ec;
}

// The progress bar on stderr, when it is a terminal; `last`: the end of its line.
void Batch::progress(bool last)
{
  if(!m_tty)
    return;
  if(last)
  {
    std::cerr << "\n";
    return;
  }
  const std::size_t total = m_inputs.size(), ended = m_done + m_skipped + m_failed;
  const std::size_t width = 30, filled = total == 0 ? width : width * ended / total;
  std::cerr << "\r[" << std::string(filled, '#') << std::string(width - filled, '.') << "] " << ended << "/"
            << total << " meshes, " << m_skipped << " skipped, " << m_failed << " failed, " << m_running.size()
            << " running\033[K" << std::flush;
}

int Batch::run()
{
  const std::string error = prepare();
  if(!error.empty())
  {
    std::cerr << "error: " << error << "\n(run with --help for the usage)\n";
    return exit_usage;
  }
  m_tty = ::isatty(2) != 0;
  std::vector<std::size_t> todo;
  for(std::size_t k = 0; k < m_inputs.size(); ++k)
    if(!m_b.force && done_before(m_before, m_inputs[k], m_outputs[k]))
      ++m_skipped;
    else
      todo.push_back(k);
  std::size_t next = 0;
  progress(false);
  while(next < todo.size() || !m_running.empty())
  {
    while(m_running.size() < m_b.jobs && next < todo.size())
      start(todo[next++]);
    int status = 0;
    const pid_t pid = m_running.empty() ? 0 : ::waitpid(-1, &status, 0);
    if(pid > 0)
      finish(pid, status);
    else if(pid < 0 && errno != EINTR)
      break;
    progress(false);
  }
  progress(true);
  const bool rewritten = rewrite_report();
  std::error_code ec;
  fs::remove_all(m_scratch, ec);
  std::cout << "batch: " << m_inputs.size() << " meshes"
            << (m_b.shards > 1 ? " (shard " + std::to_string(m_b.shard) + "/" + std::to_string(m_b.shards) + ")" : "")
            << ": " << m_done << " done, " << m_skipped << " skipped, " << m_failed << " failed; report "
            << m_report.string() << "\n";
  if(!m_report_ok || !rewritten)
    std::cerr << "error: cannot write the report " << m_report.string() << "\n";
  return m_failed == 0 && m_report_ok && rewritten ? EXIT_SUCCESS : exit_failure;
}

} // namespace

int run_batch(const Options& options, int argc, char** argv)
{
  Batch batch(options, argc, argv);
  return batch.run();
}

} // namespace mbp_cli
