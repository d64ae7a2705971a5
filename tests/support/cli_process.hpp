// Running the impact3d program from the tests: its exit status, stdout and stderr, captured apart.
#pragma once

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <functional>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

namespace impact3d::test {

// A directory of this process's own under the system's temporary one, made empty: a process of an
// earlier run with the same pid may have left files there, and the tests assert what the program wrote.
inline std::filesystem::path fresh_directory(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / fmt::format("{}-{}", name, ::getpid());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The rows after the header of a CSV the program writes beside a figure: a label, then numbers.
inline std::vector<std::pair<std::string, std::vector<double>>> labelled_rows(const std::string& csv) {
  std::vector<std::pair<std::string, std::vector<double>>> rows;
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    std::stringstream ss(line);
    std::string cell, label;
    std::getline(ss, label, ',');
    std::vector<double> v;
    while (std::getline(ss, cell, ',')) v.push_back(std::stod(cell));
    rows.push_back({label, v});
  }
  return rows;
}

struct Run {
  int status;
  std::string out, err;
};

// `program ARGS` with the arguments passed as they are (no shell: they may hold quotes and newlines),
// standard input from `stdin_path` (/dev/null when empty), in `dir` when given, with at most
// `cpu_seconds` of CPU time and, outside sanitizer builds (whose shadow memory needs the address space)
// and when `memory_mib` > 0, that much address space: a hostile input must be rejected within both.
// With `terminate_when` the program is sent SIGTERM, if still running, once it returns true (polled
// every millisecond).
inline Run run_program(const std::string& program, const std::vector<std::string>& args, const std::string& stdin_path = "",
                       const std::string& dir = "", int cpu_seconds = 20, long memory_mib = 2048,
                       const std::function<bool()>& terminate_when = {}) {
  namespace fs = std::filesystem;
  static int calls = 0;
  const fs::path work = fs::temp_directory_path() / fmt::format("impact3d-argv-{}-{}", ::getpid(), calls++);
  fs::create_directories(work);
  const std::string out = (work / "out").string(), err = (work / "err").string();
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int in = ::open(stdin_path.empty() ? "/dev/null" : stdin_path.c_str(), O_RDONLY),
              o = ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644),
              e = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (in < 0) ::_exit(126);
    ::dup2(in, 0), ::dup2(o, 1), ::dup2(e, 2);
    if (!dir.empty() && ::chdir(dir.c_str()) != 0) ::_exit(126);
    const rlimit cpu{static_cast<rlim_t>(cpu_seconds), static_cast<rlim_t>(cpu_seconds)};
    ::setrlimit(RLIMIT_CPU, &cpu);
#ifndef IMPACT3D_SANITIZED
    if (memory_mib > 0) {
      const rlimit as{static_cast<rlim_t>(memory_mib) << 20, static_cast<rlim_t>(memory_mib) << 20};
      ::setrlimit(RLIMIT_AS, &as);
    }
#endif
    std::vector<char*> argv{const_cast<char*>(program.c_str())};
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(program.c_str(), argv.data());
    ::_exit(127);
  }
  int raw = 0;
  bool done = false;
  while (terminate_when && !done && !terminate_when()) {
    done = ::waitpid(pid, &raw, WNOHANG) == pid;
    if (!done) ::usleep(1000);
  }
  if (!done && terminate_when) ::kill(pid, SIGTERM);
  if (!done) ::waitpid(pid, &raw, 0);
  Run r{WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(out), slurp(err)};
  fs::remove_all(work);
  return r;
}

#ifdef IMPACT3D_CLI
// `impact3d ARGS`, after `prefix` (e.g. "env PATH=/nonexistent"), with no standard input.
inline Run run_cli(const std::string& args, const std::string& prefix = "") {
  namespace fs = std::filesystem;
  static int calls = 0;
  const fs::path dir = fs::temp_directory_path() / fmt::format("impact3d-cli-{}-{}", ::getpid(), calls++);
  fs::create_directories(dir);
  const std::string cmd = fmt::format("{} '{}' {} >'{}' 2>'{}' </dev/null", prefix, IMPACT3D_CLI, args, (dir / "out").string(),
                                      (dir / "err").string());
  const int raw = std::system(cmd.c_str());
  Run r{WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(dir / "out"), slurp(dir / "err")};
  fs::remove_all(dir);
  return r;
}

// `impact3d ARGS` through run_program, with no standard input.
inline Run run_argv(const std::vector<std::string>& args, const std::string& dir = "", int cpu_seconds = 20,
                    long memory_mib = 2048) {
  return run_program(IMPACT3D_CLI, args, "", dir, cpu_seconds, memory_mib);
}
#endif

}  // namespace impact3d::test
