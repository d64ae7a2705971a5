// The result CSV written straight from the analysis (io/result_csv.hpp's result_csv_rows, which
// `render` takes for --format csv at a floating precision) against the same rows taken from the result
// document as it is written (result_csv_from_document, the route of exact results): byte for byte, on
// every bundled case and on seeded variants of them (speeds, impulse centres, restitution, strategies,
// unit systems, and names that CSV must quote), at every floating precision.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "impact3d/io/case_spec.hpp"
#include "impact3d/io/read_case.hpp"
#include "impact3d/io/render.hpp"
#include "impact3d/io/result_csv.hpp"
#include "impact3d/numeric/strategy.hpp"

namespace {

using namespace impact3d::io;
using nlohmann::json;

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<json> bundled_cases() {
  std::vector<json> out;
  for (const auto& e : std::filesystem::directory_iterator(IMPACT3D_EXAMPLES_DIR))
    if (e.path().extension() == ".json") out.push_back(json::parse(slurp(e.path())));
  return out;
}

// A variant of `c`: each draw its own statement, so that the cases do not depend on the compiler's
// order of a call's arguments.
json variant(json c, std::mt19937_64& g, int k) {
  std::uniform_real_distribution<double> scale(0.3, 1.7), unit(0.0, 1.0);
  static const char* names[] = {"plain", "with, comma", "quote\"in", " spaced ", "line\nbreak", "tab\tx", "\xC3\xA9 \xC3\xBC", ""};
  c["name"] = std::string(names[k % 8]) + std::to_string(k);
  if (unit(g) < 0.3) c["units"] = c.value("units", "SI") == "SI" ? "US" : "SI";
  for (auto& v : c["vehicles"]) {
    for (auto& x : v["velocity"]) x = x.get<double>() * scale(g);
    if (v.contains("impulse_center"))
      for (auto& x : v["impulse_center"]) x = x.get<double>() * scale(g);
  }
  const double e = unit(g);
  c["restitution"] = std::round(e * 1000) / 1000;
  const double mu = std::round(unit(g) * 100) / 100;
  json extra = {{"name", "wach"}, {"mu", mu}, {"limit", k % 2 ? "gir" : "cir"}};
  if (k % 3 == 0) extra = {{"name", "brach"}, {"mu_t", "critical"}, {"mu_z", mu}};
  c["strategy"].push_back(extra);
  return c;
}

}  // namespace

TEST_CASE("the result CSV written from the analysis is the CSV taken from the written document") {
  std::mt19937_64 g(2611);
  std::vector<json> cases = bundled_cases();
  const std::size_t bundled = cases.size();
  for (int k = 0; k < 40; ++k) cases.push_back(variant(cases[static_cast<std::size_t>(k) % bundled], g, k));
  std::size_t compared = 0, rows = 0, quoted_names = 0, with_warnings = 0, empty_cells = 0;
  for (const std::string& precision : precision_names()) {
    if (precision == "exact") continue;  // written from its document by both routes
    for (std::size_t i = 0; i < cases.size(); ++i) {
      const CaseSpec spec = read_case(cases[i].dump());
      RenderOptions csv;
      csv.format = "csv";
      csv.line = static_cast<long>(i) + 7;
      std::string direct;
      try {
        direct = render(spec, precision, csv);
      } catch (const impact3d::SolveError&) {
        continue;  // bodies that do not approach: no rows by either route
      }
      JsonPick pick = result_csv_pick();
      RenderOptions jsonl;
      jsonl.format = "jsonl";
      jsonl.pick = &pick;
      const std::string document = render(spec, precision, jsonl);
      INFO(precision << " case " << i << ": " << cases[i].dump());
      REQUIRE(direct == result_csv_from_document(document, pick, csv.line));
      ++compared;
      for (std::size_t at = direct.find('\n'); at != std::string::npos; at = direct.find('\n', at + 1)) ++rows;
      quoted_names += direct.find(",\"with, comma") != std::string::npos;
      RenderOptions whole;
      whole.format = "jsonl";
      const json parsed = json::parse(render(spec, precision, whole));
      for (const auto& result : parsed.at("results")) {
        with_warnings += !result.at("warnings").empty();
        empty_cells += !result.at("impulse_ratio").contains("mu_t") || result.at("sliding").at("swerve_angle_deg").is_null();
      }
    }
  }
  // Every floating precision: 5 of them, each over the bundled cases and 40 variants, most approaching.
  CHECK(compared >= 5 * (bundled + 30));
  CHECK(rows >= 3 * compared);
  CHECK(quoted_names >= 5 * 4);
  CHECK(with_warnings > 0);
  CHECK(empty_cells > 0);
}
