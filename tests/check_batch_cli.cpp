// `impact3d batch` (../shared/spec/many-cases.md) against `impact3d solve`, case by case: a JSON Lines
// file of the bundled examples and verification cases mixed with malformed rows and blank lines. Row i
// of the output is solve's result document for case line i with "line" added, or the error record with
// the one-line problem solve prints; the counts add up; the order holds at any --jobs; a run stopped
// midway leaves only whole rows.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>

#include "cli_process.hpp"

using namespace impact3d::test;
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

struct Input {
  fs::path path;
  std::vector<std::string> cases;   // by line, empty for a blank line
  std::vector<fs::path> files;      // the case file of each non-blank line, empty for a malformed row
  int good = 0, bad = 0;
};

std::vector<fs::path> case_files() {
  std::vector<fs::path> files;
  for (const char* dir : {IMPACT3D_EXAMPLES_DIR, IMPACT3D_CASES_DIR})
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().extension() == ".json") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

// Each case on one line, a malformed row after every third, a blank line after every fifth.
Input make_input(const fs::path& dir, int copies) {
  Input in;
  in.path = dir / "cases.jsonl";
  const std::vector<std::string> malformed = {"{\"units\": \"SI\"", "[1, 2, 3]", "{\"vehicles\": 5}", "not json at all",
                                              "{\"restitution\": 0.1, \"restitution\": 0.2}"};
  std::ofstream out(in.path, std::ios::binary);
  int k = 0;
  for (int c = 0; c < copies; ++c)
    for (const fs::path& f : case_files()) {
      const std::string line = json::parse(slurp(f)).dump();
      out << line << "\n";
      in.cases.push_back(line), in.files.push_back(f), ++in.good;
      if (++k % 3 == 0) {
        out << malformed[k % malformed.size()] << "\n";
        in.cases.push_back(malformed[k % malformed.size()]), in.files.push_back({}), ++in.bad;
      }
      if (k % 5 == 0) {
        out << "  \t\r\n";
        in.cases.push_back(""), in.files.push_back({});
      }
    }
  return in;
}

// JSON text without the whitespace between tokens: two documents that print the same numbers, strings
// and keys in the same order compare equal.
std::string tokens(const std::string& doc) {
  std::string out;
  bool in_string = false, escaped = false;
  for (char c : doc) {
    if (in_string) {
      if (escaped) escaped = false;
      else if (c == '\\') escaped = true;
      else if (c == '"') in_string = false;
    } else if (c == ' ' || c == '\n' || c == '\t' || c == '\r') {
      continue;
    } else if (c == '"') {
      in_string = true;
    }
    out += c;
  }
  return out;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  for (std::size_t nl; (nl = text.find('\n', start)) != std::string::npos; start = nl + 1)
    lines.push_back(text.substr(start, nl - start));
  if (start < text.size()) lines.push_back(text.substr(start) + "<no newline>");
  return lines;
}

}  // namespace

TEST_CASE("batch answers each case line with solve's document or solve's error, in order, at any --jobs", "[batch]") {
  const fs::path dir = fs::temp_directory_path() / fmt::format("impact3d-batch-{}", ::getpid());
  fs::create_directories(dir);
  const Input in = make_input(dir, 1);
  // A lone malformed file for solve's error text.
  const Run one = run_argv({"batch", in.path.string(), "--jobs", "1"});
  INFO(one.err);
  CHECK(one.status == 1);  // malformed rows were rejected, after every row was written
  const auto rows = lines_of(one.out);
  REQUIRE(rows.size() == static_cast<std::size_t>(in.good + in.bad));
  CHECK(one.err.find(fmt::format("{} rows read, {} solved, {} rejected", in.good + in.bad, in.good, in.bad)) !=
        std::string::npos);

  std::size_t row = 0;
  int compared = 0, errors = 0;
  for (std::size_t line = 0; line < in.cases.size(); ++line) {
    if (in.cases[line].empty()) continue;  // blank: no row
    const json got = json::parse(rows.at(row++));
    REQUIRE(got.at("line") == line + 1);
    if (in.files[line].empty()) {
      // solve on the same text: "impact3d: error: FILE: $.path: problem"
      const fs::path bad = dir / "bad.json";
      std::ofstream(bad, std::ios::binary) << in.cases[line];
      const Run s = run_argv({"solve", bad.string(), "--format", "json"});
      CHECK(s.status == 1);
      CHECK(s.err == fmt::format("impact3d: error: {}: {}\n", bad.string(), got.at("error").get<std::string>()));
      CHECK(got.size() == 2);
      ++errors;
      continue;
    }
    const Run s = run_argv({"solve", in.files[line].string(), "--format", "json"});
    REQUIRE(s.status == 0);
    json expected = json::parse(s.out);
    json g = got;
    g.erase("line");
    CHECK(g == expected);
    // The same digits, not only the same values: the texts without "line" and whitespace.
    const std::string prefix = fmt::format("{{\"line\": {}, ", line + 1);
    REQUIRE(rows[row - 1].rfind(prefix, 0) == 0);
    CHECK(tokens("{" + rows[row - 1].substr(prefix.size())) == tokens(s.out));
    ++compared;
  }
  CHECK(compared == in.good);
  CHECK(errors == in.bad);
  CHECK(compared >= 20);
  CHECK(errors >= 7);

  // Order and content at other --jobs, and from standard input.
  for (const char* jobs : {"2", "3", "7"}) {
    const Run r = run_argv({"batch", in.path.string(), "--jobs", jobs});
    CHECK(r.status == 1);
    CHECK(r.out == one.out);
  }
  const Run piped = run_program(IMPACT3D_CLI, {"batch", "--jobs", "2"}, in.path.string());
  CHECK(piped.out == one.out);
  const fs::path out_file = dir / "out.jsonl";
  const Run to_file = run_argv({"batch", in.path.string(), "-o", out_file.string()});
  CHECK(to_file.out.empty());
  CHECK(slurp(out_file) == one.out);
  fs::remove_all(dir);
}

TEST_CASE("batch refuses bad options as solve does, and a line longer than a case file may be", "[batch]") {
  const fs::path dir = fs::temp_directory_path() / fmt::format("impact3d-batch-opt-{}", ::getpid());
  fs::create_directories(dir);
  const fs::path f = dir / "long.jsonl";
  {
    std::ofstream out(f, std::ios::binary);
    out << json::parse(slurp(case_files().at(0))).dump() << "\n" << std::string((1 << 20) + 10, ' ') << "x\n";
  }
  const Run r = run_argv({"batch", f.string()});
  const auto rows = lines_of(r.out);
  REQUIRE(rows.size() == 2);
  CHECK(json::parse(rows[1]) ==
        json::parse(R"({"line": 2, "error": "$: larger than 1048576 bytes, the limit for this input"})"));
  CHECK(r.status == 1);
  for (const auto& args : std::vector<std::vector<std::string>>{{"batch", f.string(), "--jobs", "0"},
                                                                {"batch", f.string(), "--precision", "7"},
                                                                {"batch", f.string(), "--format", "xml"}}) {
    const Run bad = run_argv(args);
    CHECK(bad.status == 2);
    CHECK(bad.out.empty());
  }
  const Run strategy = run_argv({"batch", f.string(), "--strategy", "pc-crash:mu=-1"});
  CHECK(strategy.status == 1);
  CHECK(strategy.out.empty());
  CHECK(strategy.err.rfind("impact3d: error: --strategy", 0) == 0);
  const Run missing = run_argv({"batch", (dir / "none.jsonl").string()});
  CHECK(missing.status == 1);
  CHECK(missing.out.empty());
  fs::remove_all(dir);
}

TEST_CASE("batch stopped midway by SIGTERM leaves only whole rows, numbered from the first", "[batch]") {
  const fs::path dir = fs::temp_directory_path() / fmt::format("impact3d-batch-kill-{}", ::getpid());
  fs::create_directories(dir);
  const Input in = make_input(dir, 300);
  const fs::path out_file = dir / "out.jsonl";
  // Stopped once the first block is written: the handler is installed and some rows are out.
  const Run r = run_program(IMPACT3D_CLI, {"batch", in.path.string(), "-o", out_file.string(), "--jobs", "2"}, "", "", 120,
                            2048, [&] {
                              std::error_code ec;
                              const auto size = fs::file_size(out_file, ec);
                              return !ec && size > 0;
                            });
  INFO(r.err);
  CHECK(r.status == 128 + SIGTERM);
  CHECK(r.err.find("interrupted") != std::string::npos);
  const auto rows = lines_of(slurp(out_file));
  CHECK(rows.size() > 0);
  CHECK(rows.size() < static_cast<std::size_t>(in.good + in.bad));
  std::size_t line = 0;
  for (const std::string& row : rows) {
    const json j = json::parse(row);  // throws on a partial row
    const std::size_t at = j.at("line").get<std::size_t>();
    while (line < in.cases.size() && in.cases[line].empty()) ++line;
    CHECK(at == ++line);
  }
  std::smatch m;
  REQUIRE(std::regex_search(r.err, m, std::regex("(\\d+) rows read, (\\d+) solved, (\\d+) rejected")));
  CHECK(std::stoul(m[1]) == rows.size());
  CHECK(std::stoul(m[2]) + std::stoul(m[3]) == rows.size());
  fs::remove_all(dir);
}
