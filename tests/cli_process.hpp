// Running the impact3d program from the tests: its exit status, stdout and stderr, captured apart.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <fmt/format.h>

namespace impact3d::test {

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

struct Run {
  int status;
  std::string out, err;
};

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

}  // namespace impact3d::test
