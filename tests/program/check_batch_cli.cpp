// `impact3d batch` (../shared/spec/many-cases.md) against `impact3d solve`, case by case: a JSON Lines
// file of the bundled examples and verification cases mixed with malformed rows and blank lines. Row i
// of the output is solve's result document for case line i with "line" added, or the error record with
// the one-line problem solve prints; the counts add up; the order holds at any --jobs; a run stopped
// midway leaves only whole rows.
#include <catch2/catch.hpp>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <thread>

#include <sys/stat.h>

#include "cli_process.hpp"

namespace check_batch_cli {

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

// Each case on one line, a malformed row after every third, a blank line after every fifth, and before
// each copy of them a case that does not approach.
Input make_input(const fs::path& dir, int copies) {
  Input in;
  in.path = dir / "cases.jsonl";
  const std::vector<std::string> malformed = {"{\"units\": \"SI\"", "[1, 2, 3]", "{\"vehicles\": 5}", "not json at all",
                                              "{\"restitution\": 0.1, \"restitution\": 0.2}"};
  // A case that parses but is rejected when solved: Figure 8 with every velocity reversed separates.
  json separating = json::parse(slurp(fs::path(IMPACT3D_EXAMPLES_DIR) / "fig8_side_impact.json"));
  for (json& v : separating.at("vehicles"))
    for (const char* key : {"velocity", "angular_velocity"})
      if (v.contains(key))
        for (json& x : v.at(key)) x = -x.get<double>();
  std::ofstream out(in.path, std::ios::binary);
  int k = 0;
  for (int c = 0; c < copies; ++c) {
    out << separating.dump() << "\n";
    in.cases.push_back(separating.dump()), in.files.push_back({}), ++in.bad;
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

struct Compared {
  int documents = 0, errors = 0;
};

// Row by row against solve with the same options: the document with "line" added, the same digits, or
// the error record with the problem solve prints for the same text.
Compared compare_with_solve(const Input& in, const std::vector<std::string>& rows, const fs::path& dir,
                            const std::vector<std::string>& options) {
  Compared n;
  std::size_t row = 0;
  const auto solve = [&](const fs::path& f) {
    std::vector<std::string> args = {"solve", f.string(), "--format", "json"};
    args.insert(args.end(), options.begin(), options.end());
    return run_argv(args);
  };
  for (std::size_t line = 0; line < in.cases.size(); ++line) {
    if (in.cases[line].empty()) continue;  // blank: no row
    const json got = json::parse(rows.at(row++));
    REQUIRE(got.at("line") == line + 1);
    if (in.files[line].empty()) {
      // solve on the same text: "impact3d: error: FILE: $.path: problem"
      const fs::path bad = dir / "bad.json";
      std::ofstream(bad, std::ios::binary) << in.cases[line];
      const Run s = solve(bad);
      CHECK(s.status == 1);
      CHECK(s.err == fmt::format("impact3d: error: {}: {}\n", bad.string(), got.at("error").get<std::string>()));
      CHECK(got.size() == 2);
      ++n.errors;
      continue;
    }
    const Run s = solve(in.files[line]);
    REQUIRE(s.status == 0);
    json expected = json::parse(s.out);
    json g = got;
    g.erase("line");
    CHECK(g == expected);
    // The same digits, not only the same values: the texts without "line" and whitespace.
    const std::string prefix = fmt::format("{{\"line\": {}, ", line + 1);
    REQUIRE(rows[row - 1].rfind(prefix, 0) == 0);
    CHECK(tokens("{" + rows[row - 1].substr(prefix.size())) == tokens(s.out));
    ++n.documents;
  }
  CHECK(row == rows.size());
  return n;
}

}  // namespace

TEST_CASE("batch answers each case line with solve's document or solve's error, in order, at any --jobs", "[batch]") {
  const fs::path dir = fresh_directory("impact3d-batch");
  const Input in = make_input(dir, 1);
  const Run one = run_argv({"batch", in.path.string(), "--jobs", "1"});
  INFO(one.err);
  CHECK(one.status == 1);  // malformed rows were rejected, after every row was written
  const auto rows = lines_of(one.out);
  REQUIRE(rows.size() == static_cast<std::size_t>(in.good + in.bad));
  CHECK(one.err.find(fmt::format("{} rows read, {} solved, {} rejected", in.good + in.bad, in.good, in.bad)) !=
        std::string::npos);

  const Compared n = compare_with_solve(in, rows, dir, {});
  CHECK(n.documents == in.good);
  CHECK(n.errors == in.bad);
  CHECK(n.documents >= 20);
  CHECK(n.errors >= 8);  // the malformed rows and the one that does not approach

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

// The rows are read, solved and written in blocks of 2048 (cli/src/batch.cpp): the order must hold across
// them, whichever thread solved which block.
TEST_CASE("batch keeps the input's order across blocks at any --jobs", "[batch]") {
  const fs::path dir = fresh_directory("impact3d-batch-blocks");
  const Input in = make_input(dir, 110);
  REQUIRE(in.good + in.bad > 2 * 2048 + 1);  // three blocks at least
  std::vector<std::string> names;  // of each line's case, by line
  for (const fs::path& f : in.files)
    names.push_back(f.empty() ? "" : json::parse(slurp(f)).at("name").get<std::string>());
  const Run one = run_argv({"batch", in.path.string(), "--jobs", "1"}, "", 120);
  CHECK(one.status == 1);
  CHECK(one.err.find(fmt::format("{} rows read, {} solved, {} rejected", in.good + in.bad, in.good, in.bad)) !=
        std::string::npos);
  const auto rows = lines_of(one.out);
  REQUIRE(rows.size() == static_cast<std::size_t>(in.good + in.bad));
  std::size_t row = 0;
  int checked = 0;
  for (std::size_t line = 0; line < in.cases.size(); ++line) {
    if (in.cases[line].empty()) continue;
    const json got = json::parse(rows[row++]);
    REQUIRE(got.at("line") == line + 1);
    if (names[line].empty())
      CHECK(got.contains("error"));
    else
      CHECK(got.at("name") == names[line]);
    ++checked;
  }
  CHECK(checked == in.good + in.bad);
  for (const char* jobs : {"2", "3"}) {
    const Run r = run_argv({"batch", in.path.string(), "--jobs", jobs}, "", 120);
    CHECK(r.status == 1);
    CHECK(r.out == one.out);
  }
  fs::remove_all(dir);
}

// --precision applies to every row: each floating precision the double tests above do not cover, row
// by row against solve at that precision (exact is compared in the CSV test below).
TEST_CASE("batch at long double, float128, 50 and 100 digits answers each row as solve does", "[batch]") {
  const fs::path dir = fresh_directory("impact3d-batch-precision");
  Input in;
  in.path = dir / "cases.jsonl";
  {
    fs::create_directories(dir / "all");
    const Input all = make_input(dir / "all", 1);  // its first 12 lines: the separating case, cases, malformed rows
    std::ofstream out(in.path, std::ios::binary);
    for (std::size_t line = 0; line < 12; ++line) {
      out << all.cases[line] << "\n";
      in.cases.push_back(all.cases[line]), in.files.push_back(all.files[line]);
      if (all.cases[line].empty()) continue;
      ++(all.files[line].empty() ? in.bad : in.good);
    }
  }
  REQUIRE(in.good >= 8);
  REQUIRE(in.bad >= 3);
  int compared = 0;
  for (const char* precision : {"long-double", "float128", "50", "100"}) {
    INFO(precision);
    const Run r = run_argv({"batch", in.path.string(), "--precision", precision, "--jobs", "2"}, "", 120);
    CHECK(r.status == 1);
    const Compared n = compare_with_solve(in, lines_of(r.out), dir, {"--precision", precision});
    CHECK(n.documents == in.good);
    CHECK(n.errors == in.bad);
    ++compared;
  }
  CHECK(compared == 4);
  fs::remove_all(dir);
}

TEST_CASE("batch refuses bad options as solve does, and a line longer than a case file may be", "[batch]") {
  const fs::path dir = fresh_directory("impact3d-batch-opt");
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

namespace {

// A file named by -o is written as a hidden temporary beside it (.NAME.*.tmp), renamed over the name when
// the run ends: its bytes so far, while the run goes on.
std::string temporary_of(const fs::path& target) {
  const std::string prefix = "." + target.filename().string() + ".";
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(target.parent_path(), ec)) {
    const std::string name = e.path().filename().string();
    if (name.rfind(prefix, 0) == 0 && name.size() > 4 && name.compare(name.size() - 4, 4, ".tmp") == 0) return slurp(e.path());
  }
  return {};
}

}  // namespace

TEST_CASE("batch stopped midway by SIGTERM leaves only whole rows, numbered from the first", "[batch]") {
  const fs::path dir = fresh_directory("impact3d-batch-kill");
  const Input in = make_input(dir, 2);
  const fs::path out_file = dir / "out.jsonl", fifo = dir / "cases.fifo";
  // The input comes through a FIFO holding the first half of the lines and kept open: the program
  // answers those rows, writes them (a block ends when the input would wait) and waits for more, when
  // the signal comes. Where the run stands is then known, not raced: it has read exactly these rows.
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  // Held open for writing here, so that the program's open does not wait and its reads never see the end;
  // non-blocking, so that a program that stopped reading cannot keep the writer waiting.
  const int feed = ::open(fifo.c_str(), O_RDWR | O_CLOEXEC | O_NONBLOCK);
  REQUIRE(feed >= 0);
  const std::size_t fed_lines = in.cases.size() / 2;
  std::string fed;
  std::size_t expected = 0;
  for (std::size_t i = 0; i < fed_lines; ++i) fed += in.cases[i] + "\n", expected += !in.cases[i].empty();
  REQUIRE(expected >= 20);
  // From another thread: more than a pipe holds, written as the program reads.
  std::atomic<bool> ended{false};
  std::thread writer([&] {
    for (std::size_t at = 0; at < fed.size() && !ended;) {
      const ssize_t n = ::write(feed, fed.data() + at, fed.size() - at);
      if (n > 0) at += static_cast<std::size_t>(n);
      else if (n < 0 && (errno == EAGAIN || errno == EINTR)) ::usleep(1000);
      else break;
    }
  });
  auto rows_out = [&] {
    const std::string t = temporary_of(out_file);
    return static_cast<std::size_t>(std::count(t.begin(), t.end(), '\n'));
  };
  const Run r = run_program(IMPACT3D_CLI, {"batch", "-", "-o", out_file.string(), "--jobs", "2"}, fifo.string(), "", 120,
                            2048, [&] { return rows_out() >= expected; });
  ended = true;
  writer.join();
  ::close(feed);
  INFO(r.err);
  CHECK(r.status == 128 + SIGTERM);
  CHECK(r.err.find("interrupted") != std::string::npos);
  // The stopped run puts the file in place, holding the rows written: all those fed, none more.
  const std::string text = slurp(out_file);
  CHECK((!text.empty() && text.back() == '\n'));
  const auto rows = lines_of(text);
  CHECK(rows.size() == expected);
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

TEST_CASE("batch writes a file past 64 MiB, its end straight to the disk, byte for byte as its standard output", "[batch]") {
  // Beside the build, not in the temporary directory, which may be a tmpfs that takes no direct writes.
  const fs::path dir = fs::current_path() / fmt::format("impact3d-batch-large-{}", ::getpid());
  fs::create_directories(dir);
  // Figure 8 with its four strategies (12 KB a row), a malformed row every 1000th: some 84 MB, past the
  // 64 MiB a file takes through the page cache (cli/library/include/impact3d/cli/row_output.hpp). Standard output, here a file
  // the program did not open, is written as it is given.
  constexpr int kRows = 7000;
  const std::string fig8 = json::parse(slurp(fs::path(IMPACT3D_EXAMPLES_DIR) / "fig8_side_impact.json")).dump();
  const fs::path cases = dir / "cases.jsonl";
  {
    std::ofstream out(cases, std::ios::binary);
    for (int i = 1; i <= kRows; ++i) out << (i % 1000 == 0 ? "{\"vehicles\": 5}" : fig8) << "\n";
  }
  const fs::path file = dir / "out.jsonl";
  const Run to_file = run_argv({"batch", cases.string(), "-o", file.string()}, "", 120);
  const Run to_stdout = run_argv({"batch", cases.string()}, "", 120);
  CHECK(to_file.status == 1);  // the malformed rows
  CHECK(to_stdout.status == 1);
  CHECK(to_file.out.empty());
  CHECK(to_file.err == to_stdout.err);
  const std::string written = slurp(file);
  CHECK(written.size() > (std::size_t{80} << 20));
  CHECK(written == to_stdout.out);
  const auto rows = lines_of(written);
  REQUIRE(rows.size() == static_cast<std::size_t>(kRows));
  CHECK(json::parse(rows.back()).at("error").is_string());
  CHECK(json::parse(rows[kRows - 2]).at("line") == kRows - 1);
  fs::remove_all(dir);
}

TEST_CASE("batch whose output cannot be written says why and exits 3", "[batch]") {
  const fs::path dir = fresh_directory("impact3d-batch-full");
  const fs::path cases = dir / "cases.jsonl";
  std::ofstream(cases, std::ios::binary) << json::parse(slurp(fs::path(IMPACT3D_EXAMPLES_DIR) / "fig8_side_impact.json")).dump() << "\n";
  // /dev/full refuses every write with ENOSPC, as a full disk does.
  const Run rows = run_argv({"batch", cases.string(), "-o", "/dev/full"});
  CHECK(rows.status == 3);
  CHECK(rows.out.empty());
  CHECK(rows.err == "impact3d: batch: 1 rows read, 1 solved, 0 rejected (the output could not be written: " +
                        std::string(std::strerror(ENOSPC)) + ")\n");
  // The CSV header is the first write: no row is read.
  const Run csv = run_argv({"batch", cases.string(), "--format", "csv", "-o", "/dev/full"});
  CHECK(csv.status == 3);
  CHECK(csv.err == "impact3d: batch: 0 rows read, 0 solved, 0 rejected (the output could not be written: " +
                       std::string(std::strerror(ENOSPC)) + ")\n");
  fs::remove_all(dir);
}

namespace {

// RFC 4180 cells of one line, written here independently of the program's reader.
std::vector<std::string> csv_cells(const std::string& line) {
  std::vector<std::string> cells(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') cells.back() += '"', ++i;
      else if (c == '"') quoted = false;
      else cells.back() += c;
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      cells.emplace_back();
    } else {
      cells.back() += c;
    }
  }
  return cells;
}

// "vehicles[1].delta_v[2]" -> /vehicles/1/delta_v/2
json::json_pointer pointer_of(const std::string& path) {
  std::string p = "/";
  for (char c : path) p += c == '.' || c == '[' ? '/' : c == ']' ? '\0' : c;
  p.erase(std::remove(p.begin(), p.end(), '\0'), p.end());
  return json::json_pointer(p);
}

}  // namespace

TEST_CASE("batch reads a CSV whose header names case paths, and writes solve's numbers as CSV", "[batch]") {
  const fs::path dir = fresh_directory("impact3d-batch-csv");
  const std::string variants = std::string(IMPACT3D_EXAMPLES_DIR) + "/fig8_variants_with_a_bad_row.csv";
  // The bundled example without the bad row: every row solved, exit 0 (a newcomer's first batch).
  const Run good = run_argv({"batch", std::string(IMPACT3D_EXAMPLES_DIR) + "/fig8_variants.csv", "--format", "csv"});
  CHECK(good.status == 0);
  CHECK(good.err.find("2 rows read, 2 solved, 0 rejected") != std::string::npos);

  // Row 2 of the bundled CSVs is this case, written by hand from its columns.
  const fs::path hand = dir / "row2.json";
  std::ofstream(hand) << R"x({"name": "Figure 8, 25 mph each", "vehicles": [
    {"name": "Malibu", "mass": 1560, "inertia": [[560, 0, -40], [0, 2500, 0], [-40, 0, 2700]], "velocity": [11.176, 0, 0],
     "impulse_center": [0.35, -0.9, 0.05]},
    {"name": "Suburban", "mass": 2600, "inertia": {"Ixx": 1100, "Iyy": 5600, "Izz": 5900}, "orientation_deg": {"yaw": 90},
     "velocity": [0, 11.176, 0], "impulse_center": [2.6, 0.2, -0.15]}],
  "contact": {"normal_yaw_deg": 90}, "restitution": 0.1,
  "strategy": [{"name": "pc-crash", "mu": 0.5}, {"name": "brach", "mu_t": "critical", "mu_z": "critical"}]})x";
  const Run solved = run_argv({"solve", hand.string(), "--format", "json"});
  REQUIRE(solved.status == 0);

  const Run jsonl = run_argv({"batch", variants, "--jobs", "2"});
  INFO(jsonl.err);
  CHECK(jsonl.status == 1);
  CHECK(jsonl.err.find("3 rows read, 2 solved, 1 rejected") != std::string::npos);
  const auto rows = lines_of(jsonl.out);
  REQUIRE(rows.size() == 3);
  const std::string prefix = "{\"line\": 2, ";
  REQUIRE(rows[0].rfind(prefix, 0) == 0);
  CHECK(tokens("{" + rows[0].substr(prefix.size())) == tokens(solved.out));
  CHECK(json::parse(rows[1]).at("results").size() == 1);  // its second strategy's cells are empty
  CHECK(rows[2] == R"x({"line": 4, "error": "$.vehicles[0].mass: must be > 0 (got -1560)"})x");

  // CSV out: one row per result, every column the document's value at its path.
  const Run table = run_argv({"batch", variants, "--format", "csv"});
  CHECK(table.status == 1);
  const auto lines = lines_of(table.out);
  REQUIRE(lines.size() == 1 + 2 + 1 + 1);
  const auto header = csv_cells(lines[0]);
  REQUIRE(header.size() > 60);
  int compared = 0;
  for (std::size_t r = 1; r < lines.size(); ++r) {
    const auto cells = csv_cells(lines[r]);
    REQUIRE(cells.size() == header.size());
    const long line = std::stol(cells[0]);
    const json doc = json::parse(rows.at(static_cast<std::size_t>(line - 2)));
    if (!cells[2].empty()) {
      CHECK(cells[2] == doc.at("error").get<std::string>());
      CHECK(cells[1].empty());
      continue;
    }
    const json& result = doc.at("results").at(std::stoul(cells[1]));
    for (std::size_t c = 3; c < header.size(); ++c) {
      const std::string& name = header[c];
      if (name == "strategy" || name == "warnings") continue;
      const bool of_document = name == "name" || name == "units" || name == "precision" || name == "engine";
      const json& from = of_document ? doc : result;
      const auto ptr = pointer_of(name);
      INFO(name);
      if (!from.contains(ptr) || from.at(ptr).is_null()) {
        CHECK(cells[c].empty());
      } else if (from.at(ptr).is_string()) {
        CHECK(cells[c] == from.at(ptr).get<std::string>());
      } else {
        CHECK(std::stod(cells[c]) == from.at(ptr).get<double>());  // 17 digits read back to the same double
      }
      ++compared;
    }
    CHECK(cells[header.size() - 1].empty() == result.at("warnings").empty());
  }
  CHECK(compared > 3 * 60);
  // The byte order mark a spreadsheet writes before the header changes nothing.
  const fs::path bom = dir / "bom.csv";
  std::ofstream(bom, std::ios::binary) << "\xEF\xBB\xBF" << slurp(variants);
  CHECK(run_argv({"batch", bom.string(), "--format", "csv"}).out == table.out);
  fs::remove_all(dir);
}

TEST_CASE("batch refuses a CSV header that does not spell a case's paths", "[batch]") {
  const fs::path dir = fresh_directory("impact3d-batch-csvh");
  const std::vector<std::pair<std::string, std::string>> headers = {
      {"name,vehicles[0].mass[", "header column 2 (\"vehicles[0].mass[\"): expected an index [n] in the path"},
      {"name,vehicles[1].mass", "header: no column for $.vehicles[0]"},
      {"name,name", "header column 2 (\"name\"): the same field as another column, or a field another column is inside"},
      {"vehicles.x,vehicles[0]", "header column 2 (\"vehicles[0]\"): an index where another column has a key"},
      {"strategy[64].name", "header column 1 (\"strategy[64].name\"): an index beyond 63"},
      {"strategy[99999999999999999999999].name", "header column 1 (\"strategy[99999999999999999999999].name\"): an index beyond 63"},
      {"$name", "header column 1 (\"$name\"): expected a key (letters, digits, _) in the path"}};
  int checked = 0;
  for (const auto& [header, problem] : headers) {
    const fs::path f = dir / "cases.csv";
    std::ofstream(f, std::ios::binary) << header << "\n1,2\n";
    const Run r = run_argv({"batch", f.string()});
    CHECK(r.status == 1);
    CHECK(r.out.empty());
    CHECK(r.err == fmt::format("impact3d: error: {}: line 1: {}\n", f.string(), problem));
    ++checked;
  }
  CHECK(checked == 7);
  fs::remove_all(dir);
}

TEST_CASE("batch answers a case piped in before the next arrives", "[batch]") {
  const fs::path dir = fresh_directory("impact3d-batch-pipe");
  const fs::path fifo = dir / "cases", out = dir / "out.jsonl";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  const std::string one_case = json::parse(slurp(fs::path(IMPACT3D_EXAMPLES_DIR) / "fig8_side_impact.json")).dump() + "\n";
  // The producer writes one case, waits (up to 20 s) for its answer, and only then ends the input.
  bool answered_first = false;
  std::thread producer([&] {
    const int fd = ::open(fifo.c_str(), O_WRONLY);
    if (fd < 0) return;
    if (::write(fd, one_case.data(), one_case.size()) == static_cast<ssize_t>(one_case.size()))
      for (int ms = 0; ms < 20000 && !answered_first; ms += 10) {
        answered_first = temporary_of(out).find('\n') != std::string::npos;
        ::usleep(10000);
      }
    ::close(fd);
  });
  const Run r = run_program(IMPACT3D_CLI, {"batch", "-o", out.string(), "--jobs", "2"}, fifo.string());
  producer.join();
  CHECK(r.status == 0);
  CHECK(answered_first);
  CHECK(lines_of(slurp(out)).size() == 1);
  CHECK(temporary_of(out).empty());  // renamed over the name at the end
  fs::remove_all(dir);
}

// The CSV cells are written from the analysis at double and taken as the document is written at exact
// (case_format/result_csv.hpp), never read back from it: a name with every character JSON escapes, each strategy
// of the offset frontal case (one with a warning, one with a limit choice). Every cell against the JSON
// Lines document of the same row.
TEST_CASE("batch's CSV cells are the JSON document's values, escapes, strategies and warnings included", "[batch]") {
  const fs::path dir = fresh_directory("impact3d-batch-pick");
  json c = json::parse(slurp(std::string(IMPACT3D_EXAMPLES_DIR) + "/offset_frontal.json"));
  c["name"] = "q\"b\\s\nn\x01t\tc, \xC3\xA9";
  const fs::path in = dir / "cases.jsonl";
  std::ofstream(in, std::ios::binary) << c.dump() << "\n";
  int compared = 0, warnings = 0;
  std::size_t columns = 0;
  for (const char* precision : {"double", "exact"}) {
    const Run jsonl = run_argv({"batch", in.string(), "--precision", precision});
    const Run table = run_argv({"batch", in.string(), "--precision", precision, "--format", "csv"});
    REQUIRE(jsonl.status == 0);
    REQUIRE(table.status == 0);
    const nlohmann::ordered_json doc = nlohmann::ordered_json::parse(lines_of(jsonl.out).at(0));  // the strategy's key order
    const std::string row_tokens = tokens(lines_of(jsonl.out).at(0));
    // Records, not lines: the name's newline sits inside a quoted cell (RFC 4180).
    std::vector<std::string> lines(1);
    bool quoted = false;
    for (const char ch : table.out) {
      if (ch == '"') quoted = !quoted;
      if (ch == '\n' && !quoted) lines.emplace_back();
      else lines.back() += ch;
    }
    CHECK(lines.back().empty());
    lines.pop_back();
    const auto header = csv_cells(lines.at(0));
    REQUIRE(lines.size() == 1 + doc.at("results").size());
    for (std::size_t r = 1; r < lines.size(); ++r) {
      const auto cells = csv_cells(lines[r]);
      REQUIRE(cells.size() == header.size());
      const auto& result = doc.at("results").at(std::stoul(cells.at(1)));
      columns = header.size() - 3;
      for (std::size_t col = 3; col < header.size(); ++col) {
        const std::string& name = header[col];
        INFO(precision << " " << name);
        if (name == "strategy") {
          std::string text = result.at("strategy").at("name").get<std::string>(), params;
          for (const auto& [k, v] : result.at("strategy").items())
            if (k != "name") params += (params.empty() ? "" : ",") + k + "=" + (v.is_string() ? v.get<std::string>() : v.dump());
          CHECK(cells[col] == (params.empty() ? text : text + ":" + params));
        } else if (name == "warnings") {
          std::string joined;
          for (const auto& w : result.at("warnings")) joined += (joined.empty() ? "" : " | ") + w.get<std::string>();
          CHECK(cells[col] == joined);
          warnings += !joined.empty();
        } else {
          const bool of_document = name == "name" || name == "units" || name == "precision" || name == "engine";
          const auto& from = of_document ? doc : result;
          const auto ptr = nlohmann::ordered_json::json_pointer(pointer_of(name).to_string());
          if (!from.contains(ptr) || from.at(ptr).is_null()) CHECK(cells[col].empty());
          else if (from.at(ptr).is_string()) CHECK(cells[col] == from.at(ptr).get<std::string>());
          else {
            // The value, its sign (a -0 stays -0), and the text: a whole number token of the document.
            const double x = std::stod(cells[col]), y = from.at(ptr).get<double>();
            CHECK(x == y);
            CHECK(std::signbit(x) == std::signbit(y));
            bool whole_token = false;
            for (std::size_t at = row_tokens.find(cells[col]); at != std::string::npos && !whole_token;
                 at = row_tokens.find(cells[col], at + 1)) {
              const std::size_t end = at + cells[col].size();
              whole_token = at > 0 && std::string_view(":[,").find(row_tokens[at - 1]) != std::string_view::npos &&
                            end < row_tokens.size() && std::string_view(",]}").find(row_tokens[end]) != std::string_view::npos;
            }
            CHECK(whole_token);
          }
        }
        ++compared;
      }
    }
  }
  CHECK(warnings >= 2);  // wach's, at both precisions
  CHECK(columns > 60);
  CHECK(compared == static_cast<int>(2 * 5 * columns));  // two precisions, five strategies
  fs::remove_all(dir);
}

}  // namespace check_batch_cli
