// The CLI on named malformed and hostile inputs: exactly one line on stderr naming the JSON path and the
// problem, exit status 1, nothing on stdout, within bounded time and memory, at every precision (each
// converts the text itself). And the error policy of every subcommand (solve, plot, verify, compare).
//
// Where the expected answers come from:
//  - the exit statuses and line shapes are the policy of docs/limits-and-exit-status.md ("Exit status"): 1 and one line
//    `impact3d: error: FILE: $.path: problem` with nothing on stdout for bad input, 2 and one line
//    `impact3d: usage: ...` for a command-line usage error;
//  - each corpus file's line is in bad_input/expected.tsv, one per file and reviewed by hand (its header
//    says so): the field's JSON path, as the contract (case-format.md) asks, and what is wrong with it;
//  - the strategy with no solution is derived by hand below.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "bad_input.hpp"
#include "cli_process.hpp"

namespace exam_bad_input {

namespace fs = std::filesystem;
using namespace impact3d::test;

TEST_CASE("every malformed case is rejected with one line naming the field", "[bad-input]") {
  const auto expected = expected_lines();
  int files = 0;
  for (const auto& entry : fs::directory_iterator(IMPACT3D_BAD_INPUT_DIR)) {
    if (entry.path().extension() != ".json") continue;
    ++files;
    const std::string name = entry.path().filename().string();
    INFO(name);
    REQUIRE(expected.count(name) == 1);
    const std::vector<std::vector<std::string>> runs = {{"--format", "text"}, {"--format", "json"}, {"--precision", "long-double"},
                                                        {"--precision", "float128"}, {"--precision", "50"}, {"--precision", "100"}, {"--precision", "exact"}};
    for (const auto& extra : runs) {
      std::vector<std::string> args{"solve", entry.path().string()};
      args.insert(args.end(), extra.begin(), extra.end());
      // 10 s of CPU and 256 MiB of address space: a rejection takes milliseconds and a few megabytes.
      const Run r = run_argv(args, "", 10, 256);
      INFO(extra[0] << " " << extra[1]);
      CHECK(r.status == 1);
      CHECK(r.out.empty());
      CHECK(r.err == fmt::format("impact3d: error: {}: {}\n", entry.path().string(), expected.at(name)));
    }
  }
  CHECK(files == static_cast<int>(expected.size()));
  CHECK(files >= 54);  // the corpus held 54 files when this was written: an empty or missing one fails
}

TEST_CASE("a missing case file is one clear line", "[bad-input]") {
  const Run r = run_cli("solve /nonexistent/case.json");
  CHECK(r.status == 1);
  CHECK(r.out.empty());
  CHECK(r.err == "impact3d: error: /nonexistent/case.json: cannot read the file (No such file or directory)\n");
}

TEST_CASE("an endless or oversized file is refused after the size limit", "[bad-input]") {
  const Run zero = run_argv({"solve", "/dev/zero"}, "", 10, 1024);
  CHECK(zero.status == 1);
  CHECK(zero.out.empty());
  CHECK(zero.err == "impact3d: error: /dev/zero: larger than 1048576 bytes, the limit for this input\n");
  const Run dir = run_argv({"solve", "/"});
  CHECK(dir.status == 1);
  CHECK(dir.err == "impact3d: error: /: cannot read the file (a directory)\n");
}

TEST_CASE("command-line usage errors: exit 2 and one line", "[bad-input]") {
  const std::string fig8 = std::string(IMPACT3D_EXAMPLES_DIR) + "/fig8_side_impact.json";
  // Run in a scratch directory, so that a plot that wrongly ran would leave its figures where we look.
  const fs::path dir = fresh_directory("impact3d-usage");
  // For each subcommand: an unknown option, a missing argument (positional or an option's value), and an
  // invalid value where the subcommand has options that take one.
  for (const auto& args : std::vector<std::vector<std::string>>{{"solve", fig8, "--digits", "0"},
                                                                {"solve", fig8, "--format", "xml\n\x1b[2J"},
                                                                {"solve"},
                                                                {"solve", fig8, "--bogus"},
                                                                {"solve", fig8, "--format"},
                                                                {"frobnicate"},
                                                                {},
                                                                {"plot"},
                                                                {"plot", fig8},
                                                                {"plot", fig8, "-o"},
                                                                {"plot", fig8, "-o", "figs", "--bogus"},
                                                                {"compare", fig8},
                                                                {"compare"},
                                                                {"compare", fig8, fig8, "--bogus"},
                                                                {"compare", fig8, fig8, "--rtol"},
                                                                {"compare", fig8, fig8, "--atol", "inf"},
                                                                {"compare", fig8, fig8, "--rtol", "-1"},
                                                                {"verify", "--bogus"},
                                                                {"verify", "--random"},
                                                                {"verify", "--random", "1000000000"}}) {
    std::string line;
    for (const auto& a : args) line += a + " ";
    INFO(line);
    const Run r = run_argv(args, dir.string());
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(r.err.rfind("impact3d: usage: ", 0) == 0);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK((!r.err.empty() && r.err.back() == '\n'));
    CHECK(r.err.find('\x1b') == std::string::npos);
  }
  CHECK(!fs::exists(dir / "figs"));
  fs::remove_all(dir);
}

TEST_CASE("bad input to every subcommand: exit 1, one error line, nothing on stdout", "[bad-input]") {
  // A malformed case (its line from bad_input/expected.tsv) and a file that does not exist, given to each
  // subcommand that reads it; compare reads result files, so it gets a case file where a result belongs.
  const std::string bad = std::string(IMPACT3D_BAD_INPUT_DIR) + "/mass_negative.json";
  const std::string fig8 = std::string(IMPACT3D_EXAMPLES_DIR) + "/fig8_side_impact.json";
  const std::string missing = "/nonexistent/case.json";
  const std::string bad_line = "impact3d: error: " + bad + ": $.vehicles[1].mass: must be > 0 (got -2200)\n";
  const std::string missing_line = "impact3d: error: " + missing + ": cannot read the file (No such file or directory)\n";
  const fs::path dir = fresh_directory("impact3d-bad");
  struct Expect {
    std::vector<std::string> args;
    std::string err;  // the exact line, or empty when only its shape is pinned
  };
  const std::vector<Expect> runs = {{{"solve", bad}, bad_line},
                                    {{"solve", missing}, missing_line},
                                    {{"plot", bad, "-o", "figs"}, bad_line},
                                    {{"plot", missing, "-o", "figs"}, missing_line},
                                    {{"verify", bad}, bad_line},
                                    {{"verify", missing}, missing_line},
                                    {{"compare", fig8, fig8}, ""},
                                    {{"compare", missing, fig8}, ""}};
  for (const auto& [args, err] : runs) {
    std::string line;
    for (const auto& a : args) line += a + " ";
    const Run r = run_argv(args, dir.string());
    INFO(line << "\n" << r.err);
    CHECK(r.status == 1);
    CHECK(r.out.empty());
    CHECK(r.err.rfind("impact3d: error: ", 0) == 0);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK((!r.err.empty() && r.err.back() == '\n'));
    if (!err.empty()) CHECK(r.err == err);
  }
  CHECK(!fs::exists(dir / "figs"));  // plot wrote nothing for a case it rejected
  fs::remove_all(dir);
}

TEST_CASE("a command-line strategy that is not UTF-8 or holds control characters: one escaped line", "[bad-input]") {
  const std::string fig8 = std::string(IMPACT3D_EXAMPLES_DIR) + "/fig8_side_impact.json";
  const Run bad_utf8 = run_argv({"solve", fig8, "--strategy", "pc-crash:mu=\xff\xfe"});
  CHECK(bad_utf8.status == 1);
  CHECK(bad_utf8.out.empty());
  CHECK(bad_utf8.err == "impact3d: error: " + fig8 + ": --strategy[0]: not valid UTF-8\n");
  const Run control = run_argv({"solve", fig8, "--strategy", "wach\n\x1b[31m:mu=0.4"});
  CHECK(control.status == 1);
  CHECK(control.err == "impact3d: error: " + fig8 +
                           ": --strategy[0].name: unknown strategy \"wach\\n\\x1B[31m\" (expected pc-crash, wach, brach or stronge)\n");
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

TEST_CASE("verify with nothing to verify fails instead of passing", "[bad-input]") {
  const fs::path empty = fresh_directory("impact3d-empty");
  // Nothing named: a usage error that says what to give.
  const Run bare = run_argv({"verify"});
  CHECK(bare.status == 2);
  CHECK(bare.out.empty());
  CHECK(bare.err ==
        "impact3d: usage: verify: nothing to verify: give case files or directories (e.g. examples "
        "verification/cases), or --random N (impact3d verify --help)\n");
  // A directory with no cases in it: bad input.
  const Run r = run_argv({"verify", empty.string()});
  CHECK(r.status == 1);
  CHECK(r.out.empty());
  CHECK(r.err == "impact3d: error: verify: no cases to verify: name case files or directories holding them, or --random N\n");
  fs::remove_all(empty);
}

// K = [[2, -1, 0], [-1, 2, 0], [0, 0, 3]] exactly (hand derivation: unit masses and inertias, lever arms
// (1, 1, 0), m' = 1/2), so Brach with mu_t = 2, mu_z = 0 makes the restitution row a1 + b1 mu_t = 0: that
// strategy alone has no impulse, at every precision and in both engines.
TEST_CASE("a strategy with no solution is named by its path", "[bad-input]") {
  const fs::path dir = fresh_directory("impact3d-singular");
  std::ofstream(dir / "case.json") << R"({"vehicles": [
    {"mass": 1, "inertia": {"Ixx": 1, "Iyy": 1, "Izz": 1}, "velocity": [1, 0, 0], "impulse_center": [1, 1, 0]},
    {"mass": 1, "inertia": {"Ixx": 1, "Iyy": 1, "Izz": 1}, "orientation_deg": {"yaw": 180}, "velocity": [-1, 0, 0],
     "impulse_center": [1, 1, 0]}],
    "contact": {"normal_yaw_deg": 180}, "restitution": 0.5,
    "strategy": [{"name": "pc-crash", "mu": 0.4}, {"name": "brach", "mu_t": 2, "mu_z": 0}]})";
  int runs = 0;
  for (const char* precision : {"double", "long-double", "float128", "50", "100", "exact"})
    for (const char* engine : {"generated", "direct"}) {
      const Run r = run_argv({"solve", "case.json", "--precision", precision, "--engine", engine}, dir.string());
      INFO(precision << " " << engine << ": " << r.err);
      CHECK(r.status == 1);
      CHECK(r.out.empty());
      CHECK(r.err.rfind("impact3d: error: case.json: $.strategy[1]: no solution: ", 0) == 0);
      ++runs;
    }
  CHECK(runs == 12);
  // plot and verify name it the same way, with the file.
  for (const auto& args : std::vector<std::vector<std::string>>{{"plot", "case.json", "-o", "figs"}, {"verify", "case.json"}}) {
    const Run r = run_argv(args, dir.string());
    INFO(args[0] << ": " << r.err);
    CHECK(r.status == 1);
    CHECK(r.out.empty());
    CHECK(r.err.rfind("impact3d: error: case.json: $.strategy[1]: no solution: ", 0) == 0);
  }
  fs::remove_all(dir);
}

}  // namespace exam_bad_input
