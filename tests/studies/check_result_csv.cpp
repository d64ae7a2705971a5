// The result CSV written straight from the analysis (case_format/result_csv.hpp's result_csv_rows, which
// `render` takes for --format csv at a floating precision) against the same rows taken from the result
// document as it is written (result_csv_from_document.hpp): byte for byte, on every bundled case and on
// seeded variants of them (speeds, impulse centres, restitution, strategies, unit systems read and
// written, and names that CSV must quote), at every precision, exact's in the case's units; and on a
// solution holding a NaN, infinities and negative zeros. The header against the one the program wrote
// before the direct route existed.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "impact3d/case_format/case_spec.hpp"
#include "impact3d/case_format/read_case.hpp"
#include "impact3d/studies/precision.hpp"
#include "impact3d/case_format/result_csv.hpp"
#include "impact3d/case_format/result_json.hpp"
#include "impact3d/case_format/to_scene.hpp"
#include "impact3d/mechanics/strategy.hpp"

#include "result_csv_from_document.hpp"
#include "case_files.hpp"

namespace check_result_csv {

namespace {

using namespace impact3d::case_format;
using namespace impact3d::studies;
using impact3d::Units;
using nlohmann::json;

std::vector<json> bundled_cases() {
  std::vector<std::filesystem::path> paths;
  for (const auto& e : std::filesystem::directory_iterator(IMPACT3D_EXAMPLES_DIR))
    if (e.path().extension() == ".json") paths.push_back(e.path());
  std::sort(paths.begin(), paths.end());  // the directory's order is the file system's
  std::vector<json> out;
  for (const auto& p : paths) out.push_back(json::parse(impact3d::test::read_text(p.string())));
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

// The cells of the first record of `text` (RFC 4180), read here independently of the writer.
std::vector<std::string> cells_of(const std::string& text) {
  std::vector<std::string> cells(1);
  bool quoted = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted && c == '"' && i + 1 < text.size() && text[i + 1] == '"') cells.back() += '"', ++i;
    else if (c == '"') quoted = !quoted;
    else if (!quoted && c == ',') cells.emplace_back();
    else if (!quoted && c == '\n') break;
    else cells.back() += c;
  }
  return cells;
}

std::string from_document(const CaseSpec& spec, const std::string& precision, RenderOptions o) {
  JsonPick pick = impact3d::test::result_csv_pick();
  o.format = Format::jsonl;
  o.pick = &pick;
  const std::string document = render(spec, precision, o);
  return impact3d::test::result_csv_from_document(document, pick, spec, o.line);
}

}  // namespace

TEST_CASE("the result CSV written from the analysis is the CSV taken from the written document") {
  std::mt19937_64 g(2611);
  std::vector<json> cases = bundled_cases();
  const std::size_t bundled = cases.size();
  REQUIRE(bundled > 0);
  for (int k = 0; k < 40; ++k) cases.push_back(variant(cases[static_cast<std::size_t>(k) % bundled], g, k));
  // The units the numbers are written in (solve --units): the case's, or each system in turn.
  const std::optional<Units> written[] = {std::nullopt, Units::metric_kmh, Units::US, Units::SI};
  std::size_t compared = 0, rows = 0, quoted_names = 0, with_warnings = 0, empty_cells = 0, kmh = 0;
  std::size_t precisions = 0;
  for (const std::string& precision : precision_names()) {
    ++precisions;
    const bool exact = precision == "exact";  // fractions of the case's own units only
    for (std::size_t i = 0; i < cases.size(); ++i) {
      const CaseSpec spec = read_case(cases[i].dump());
      RenderOptions csv;
      csv.format = Format::csv;
      csv.line = static_cast<long>(i) + 7;
      csv.units = exact ? std::nullopt : written[i % 4];
      std::string direct;
      try {
        direct = render(spec, precision, csv);
      } catch (const impact3d::SolveError&) {
        continue;  // bodies that do not approach: no rows by either route
      }
      INFO(precision << " case " << i << ": " << cases[i].dump());
      REQUIRE(direct == from_document(spec, precision, csv));
      ++compared;
      kmh += csv.units == Units::metric_kmh;
      for (std::size_t at = direct.find('\n'); at != std::string::npos; at = direct.find('\n', at + 1)) ++rows;
      quoted_names += direct.find(",\"") != std::string::npos;
      RenderOptions whole;
      whole.format = Format::jsonl;
      const json parsed = json::parse(render(spec, precision, whole));
      for (const auto& result : parsed.at("results")) {
        with_warnings += !result.at("warnings").empty();
        empty_cells += !result.at("impulse_ratio").contains("mu_t") || result.at("sliding").at("swerve_angle_deg").is_null();
      }
    }
  }
  // Every precision, each over the bundled cases and 40 variants, most of them approaching.
  CHECK(precisions == precision_names().size());
  CHECK(compared >= precisions * (bundled + 30));
  CHECK(rows >= 3 * compared);
  CHECK(kmh >= (precisions - 1) * 8);
  CHECK(quoted_names >= precisions * 4 * 5 / 8);  // the names of 5 of the 8 kinds are quoted
  CHECK(with_warnings > 0);
  CHECK(empty_cells > 0);
}

// Stronge's columns (the bundled stronge example, beside pc-crash): at every floating precision, the
// cells of the written document; filled for stronge, empty for pc-crash; a sticking end's direction
// null, an empty cell.
TEST_CASE("stronge's columns are its document's, empty for the algebraic strategies") {
  const CaseSpec spec = read_case(impact3d::test::read_text(impact3d::test::example("stronge/fig8_through_the_impact.json")));
  const auto& names = result_csv_column_names();
  const auto column = [&](const char* name) { return 9 + static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin()); };
  int compared = 0, filled = 0, empty = 0;
  for (const std::string& precision : precision_names()) {
    if (precision == "exact" || precision.rfind("certified", 0) == 0) continue;  // stronge refuses them
    RenderOptions csv;
    csv.format = Format::csv;
    csv.line = 3;
    const std::string direct = render(spec, precision, csv);
    INFO(precision);
    REQUIRE(direct == from_document(spec, precision, csv));
    std::size_t at = 0;
    for (std::size_t k = 0; k < spec.strategies.size(); ++k) {
      const std::vector<std::string> row = cells_of(direct.substr(at));
      at = direct.find('\n', at) + 1;
      const bool stronge = row.at(7).rfind("stronge", 0) == 0;  // the strategy cell
      for (const char* name : {"swerve_deg", "normal_work.compression", "normal_work.restitution", "integration.steps",
                               "integration.error_bound", "integration.diverging_directions"}) {
        CHECK(row.at(column(name)).empty() == !stronge);
        filled += stronge, empty += !stronge;
      }
      // The final direction: null (an empty cell) exactly where the contact sticks at the end.
      if (stronge) CHECK(row.at(column("final_direction_deg")).empty() == (row.at(8) == "full"));
    }
    ++compared;
  }
  CHECK(compared == static_cast<int>(impact3d::kScalarCount));  // every floating precision the build has
  CHECK(filled > 0);
  CHECK(empty > 0);
}

TEST_CASE("a NaN, an infinity and a negative zero are the document's null and -0 in the CSV") {
  const CaseSpec spec = impact3d::test::load_spec(impact3d::test::example("offset_frontal.json"));
  impact3d::Analysis<double> a = impact3d::analyze(to_scene<double>(spec), to_strategies<double>(spec));
  REQUIRE(!a.solutions.empty());
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  auto& s = a.solutions[0];
  s.impulse.P_C.x() = nan;
  s.P_W.y() = -inf;
  s.V_ri.z() = -0.0;
  s.sliding_after = inf;
  s.impulse.mu = nan;
  s.change[1].pdof_deg = -0.0;
  s.energy_loss = -nan;
  s.rounding_bound = inf;
  JsonPick pick = impact3d::test::result_csv_pick();
  const std::string document = result_json(spec, a, "double", 0, false, {}, true, &pick);
  const std::string direct = result_csv_rows(spec, a, "double", 3);
  CHECK(direct == impact3d::test::result_csv_from_document(document, pick, spec, 3));
  // The cells by name, from the header: null is an empty cell, -0 is written "-0".
  const std::vector<std::string> header = cells_of(result_csv_header()), row = cells_of(direct);
  REQUIRE(row.size() == header.size());
  auto cell = [&](const std::string& name) {
    const auto at = std::find(header.begin(), header.end(), name);
    REQUIRE(at != header.end());
    return row[static_cast<std::size_t>(at - header.begin())];
  };
  for (const char* empty : {"impulse.contact[0]", "impulse.world[1]", "sliding.after", "impulse_ratio.mu", "energy.loss", "rounding_bound"})
    CHECK(cell(empty).empty());
  CHECK(cell("relative_velocity.before[2]") == "-0");
  CHECK(cell("vehicles[1].pdof_deg") == "-0");
  CHECK(!cell("impulse.contact[1]").empty());
}

TEST_CASE("the result CSV's header is the one documented") {
  // The header `batch --format csv` wrote before the rows were written from the analysis (docs/batch.md,
  // "Results as CSV").
  std::string expected = "line,result,error,name,units,precision,engine,strategy,regime,impulse_ratio.mu,impulse_ratio.mu_t,"
                         "impulse_ratio.mu_z,limits.gir,limits.cir,limits.mu_t_critical,limits.mu_z_critical,plane_angle_deg";
  for (const char* v : {"impulse.contact", "impulse.world", "relative_velocity.before", "relative_velocity.after"})
    for (int i = 0; i < 3; ++i) expected += "," + std::string(v) + "[" + std::to_string(i) + "]";
  expected += ",sliding.before,sliding.after,sliding.swerve_angle_deg,sliding.swerve_speed,impulse_space.restitution_effective,"
              "impulse_space.t_sliding,impulse_space.z_sliding,impulse_space.volume";
  for (const char* v : {"vehicles[0].", "vehicles[1]."}) {
    for (const char* w : {"velocity", "angular_velocity", "delta_v"})
      for (int i = 0; i < 3; ++i) expected += "," + std::string(v) + w + "[" + std::to_string(i) + "]";
    for (const char* w : {"delta_v_magnitude", "pdof_deg", "pdof_clock"}) expected += "," + std::string(v) + w;
  }
  expected += ",energy.before,energy.after,energy.loss";
  // Stronge's course (docs/case-format.md), empty for the algebraic strategies.
  expected += ",swerve_deg,final_direction_deg,normal_work.compression,normal_work.restitution,integration.steps,"
              "integration.error_bound,integration.diverging_directions";
  expected += ",rounding_bound,warnings\n";
  CHECK(result_csv_header() == expected);
  // A rejected row has as many cells.
  const std::string error = result_csv_error(9, "$.x: a \"problem\", quoted");
  CHECK(std::count(error.begin(), error.end(), ',') == std::count(expected.begin(), expected.end(), ',') + 1);
  CHECK(error.rfind("9,,\"$.x: a \"\"problem\"\", quoted\",", 0) == 0);
}

}  // namespace check_result_csv
