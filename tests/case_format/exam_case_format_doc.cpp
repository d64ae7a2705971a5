// docs/case-format.md against what the program writes: every key of every reference result is
// documented, and every reference case says in one line what it exercises.
//
// Where the expected answers come from: the committed reference results (verification/reference, written
// by impact3d-reference) and case files (verification/cases, examples); the document is the project's own.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

namespace exam_case_format_doc {

namespace fs = std::filesystem;

namespace {

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void keys(const nlohmann::json& v, std::set<std::string>& out) {
  if (v.is_object())
    for (const auto& [k, x] : v.items()) {
      out.insert(k);
      keys(x, out);
    }
  else if (v.is_array())
    for (const auto& x : v) keys(x, out);
}

std::vector<fs::path> json_files(const fs::path& dir) {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".json") out.push_back(e.path());
  return out;
}

}  // namespace

TEST_CASE("every key of every reference result is documented in docs/case-format.md", "[docs]") {
  const std::string doc = read(IMPACT3D_SOURCE_DIR "/docs/case-format.md");
  REQUIRE(!doc.empty());
  std::set<std::string> all;
  const auto files = json_files(IMPACT3D_SOURCE_DIR "/verification/reference");
  for (const auto& f : files) keys(nlohmann::json::parse(read(f)), all);
  CHECK(files.size() == 32);
  CHECK(all.size() > 50);
  for (const auto& k : all) {
    INFO(k);
    CHECK(doc.find("`" + k + "`") != std::string::npos);
  }
}

TEST_CASE("every key of every case file is documented in docs/case-format.md", "[docs]") {
  const std::string doc = read(IMPACT3D_SOURCE_DIR "/docs/case-format.md");
  std::set<std::string> all;
  for (const char* dir : {IMPACT3D_SOURCE_DIR "/verification/cases", IMPACT3D_SOURCE_DIR "/examples"})
    for (const auto& f : json_files(dir)) keys(nlohmann::json::parse(read(f)), all);
  CHECK(all.size() > 25);
  for (const auto& k : all) {
    if (k.rfind('_', 0) == 0) continue;  // ignored by the reader: comments and provenance
    INFO(k);
    // As a key in backticks, or quoted inside a backticked object such as `{ "Ixx", "Iyy", "Izz" }`.
    CHECK((doc.find("`" + k + "`") != std::string::npos || doc.find("\"" + k + "\"") != std::string::npos));
  }
}

TEST_CASE("the document states the frames' signs and the CSV's columns", "[docs]") {
  const std::string doc = read(IMPACT3D_SOURCE_DIR "/docs/case-format.md");
  for (const char* part : {"n points into vehicle 1", "P is the impulse on vehicle 1",
                           "The relative velocity is vehicle 2's minus vehicle 1's", "x forward, y left, z up",
                           "mph = 0.44704 m/s", "`case`", "`result`", "Coverage is part of the verdict",
                           "`pc-crash`", "`wach`", "`brach`"}) {
    INFO(part);
    CHECK(doc.find(part) != std::string::npos);
  }
}

TEST_CASE("every reference case carries a one-line description, echoed in its reference result", "[docs]") {
  int cases = 0;
  for (const char* dir : {IMPACT3D_SOURCE_DIR "/verification/cases", IMPACT3D_SOURCE_DIR "/examples"})
    for (const auto& f : json_files(dir)) {
      INFO(f.string());
      const auto c = nlohmann::json::parse(read(f));
      REQUIRE(c.contains("description"));
      const std::string d = c["description"];
      CHECK(!d.empty());
      CHECK(d.size() <= 200);
      CHECK(d.find('\n') == std::string::npos);
      const auto r = nlohmann::json::parse(read(fs::path(IMPACT3D_SOURCE_DIR "/verification/reference") / f.filename()));
      CHECK(r["description"] == d);
      ++cases;
    }
  CHECK(cases == 32);
}

}  // namespace exam_case_format_doc
