// The CLI on malformed cases: exactly one line on stderr naming the JSON path and the problem, exit
// status 1, nothing on stdout. Expected lines are in bad_input/expected.tsv, one per corpus file.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <map>

#include <fmt/format.h>

#include "cli_process.hpp"

namespace fs = std::filesystem;
using namespace impact3d::test;

namespace {

std::map<std::string, std::string> expected_lines() {
  std::map<std::string, std::string> m;
  std::ifstream in(fs::path(BAD_INPUT_DIR) / "expected.tsv");
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    const auto tab = line.find('\t');
    m[line.substr(0, tab)] = line.substr(tab + 1);
  }
  return m;
}

}  // namespace

TEST_CASE("every malformed case is rejected with one line naming the field", "[bad-input]") {
  const auto expected = expected_lines();
  int files = 0;
  for (const auto& entry : fs::directory_iterator(BAD_INPUT_DIR)) {
    if (entry.path().extension() != ".json") continue;
    ++files;
    const std::string name = entry.path().filename().string();
    INFO(name);
    REQUIRE(expected.count(name) == 1);
    for (const char* format : {"text", "json"}) {
      const Run r = run_cli(fmt::format("solve '{}' --format {}", entry.path().string(), format));
      CHECK(r.status == 1);
      CHECK(r.out.empty());
      CHECK(r.err == fmt::format("impact3d: error: {}: {}\n", entry.path().string(), expected.at(name)));
    }
  }
  CHECK(files == static_cast<int>(expected.size()));
}

TEST_CASE("a missing case file is one clear line", "[bad-input]") {
  const Run r = run_cli("solve /nonexistent/case.json");
  CHECK(r.status == 1);
  CHECK(r.out.empty());
  CHECK(r.err == "impact3d: error: /nonexistent/case.json: /nonexistent/case.json: cannot read the file\n");
}

TEST_CASE("a bad command-line strategy names the option", "[bad-input]") {
  const Run r = run_cli(fmt::format("solve '{}/fig8_side_impact.json' --strategy pc-crash:mu=0.4 --strategy wach:mu=x",
                                    IMPACT3D_EXAMPLES_DIR));
  CHECK(r.status == 1);
  CHECK(r.out.empty());
  CHECK(r.err.find(": --strategy[1].mu: expected a number, got a string\n") != std::string::npos);
}

TEST_CASE("a valid case exits 0 with output and nothing on stderr", "[bad-input]") {
  const Run r = run_cli(fmt::format("solve '{}/fig8_side_impact.json' --format json", IMPACT3D_EXAMPLES_DIR));
  CHECK(r.status == 0);
  CHECK(r.err.empty());
  CHECK(r.out.find("\"results\"") != std::string::npos);
}
