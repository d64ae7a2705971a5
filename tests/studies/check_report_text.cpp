// The text report against the JSON result of the same case: every number of the summary is the JSON's
// number rounded to the digits printed, each row is one the test knows (an unknown row fails: nothing
// printed goes unchecked), and no line is wider than 80 columns, for every bundled case in its own
// units and another, and for a case whose names are far too long for a line.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

#include "impact3d/case_format/present.hpp"
#include "impact3d/case_format/read_case.hpp"
#include "impact3d/studies/precision.hpp"
#include "case_files.hpp"

namespace check_report_text {

using namespace impact3d;
using namespace impact3d::test;
using nlohmann::json;

namespace {

constexpr int kDigits = 10;  // the CLI's default for double

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

// Cells are right-aligned and set apart by at least two spaces; a cell holds at most single spaces.
std::vector<std::string> cells_of(const std::string& s) {
  std::vector<std::string> out;
  std::size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && s[i] == ' ') ++i;
    if (i == s.size()) break;
    std::size_t j = s.find("  ", i);
    if (j == std::string::npos) j = s.size();
    out.push_back(s.substr(i, j - i));
    i = j;
  }
  return out;
}

// A row label without its unit, "[...]", which the units decide.
std::string unitless(std::string label) {
  return std::regex_replace(label, std::regex(R"( \[[^\]]*\])"), "");
}

struct Checker {
  const json& r;     // one result of the JSON document
  double yaw_factor; // the JSON's angular velocity unit to the report's deg/s
  int numbers = 0;   // numbers compared

  // A number printed to kDigits significant digits from the value the JSON holds to 17.
  void number(const std::string& cell, const json& want, double factor = 1) {
    INFO("cell '" << cell << "', JSON " << want.dump());
    if (cell == "-") {
      CHECK(want.is_null());
      return;
    }
    REQUIRE(want.is_number());
    const double j = want.get<double>() * factor;
    static const std::regex zero(R"(0 \(\|x\| < ([0-9.e+-]+)\))");
    std::smatch m;
    if (std::regex_match(cell, m, zero)) {
      // Within the velocity rounding bound, itself printed to one digit: at most 1.5 times it.
      CHECK(std::fabs(j) <= 1.5 * std::stod(m[1]));
    } else {
      std::size_t used = 0;
      const double t = std::stod(cell, &used);
      CHECK(used == cell.size());
      // Rounding to 10 digits moves a value by at most half a unit of its 10th digit, 5e-10 of it; the
      // JSON's 17 digits and a unit conversion add a few epsilon.
      CHECK(std::fabs(t - j) <= 5.0000001e-10 * std::fabs(j) + 1e-300);
    }
    ++numbers;
  }
  // A ratio printed to two significant digits beside the JSON's three.
  void ratio(const std::string& cell, const json& want) {
    INFO("cell '" << cell << "', JSON " << want.dump());
    const double t = std::stod(cell), j = want.get<double>();
    CHECK(std::fabs(t - j) <= 0.06 * std::fabs(j));  // 2 digits: within 5% of the value, and 1% for the third
    ++numbers;
  }
  void pair(const std::vector<std::string>& c, const char* key, double factor = 1) {
    REQUIRE(c.size() == 2);
    for (int i = 0; i < 2; ++i) number(c[i], r["vehicles"][i][key], factor);
  }

  void row(const std::string& label, const std::vector<std::string>& c) {
    INFO("row '" << label << "'");
    const auto& v = r["vehicles"];
    const std::string key = unitless(label);
    if (key == "regime") {
      CHECK(c == std::vector<std::string>{r["regime"].get<std::string>()});
    } else if (key == "impulse ratio used") {
      number(c.at(0), r["impulse_ratio"]["mu"]);
    } else if (key == "impulse ratios used, t and z") {
      number(c.at(0), r["impulse_ratio"]["mu_t"]);
      number(c.at(1), r["impulse_ratio"]["mu_z"]);
    } else if (key == "GIR (eqs 14, 20)") {
      number(c.at(0), r["limits"]["gir"]);
    } else if (key == "CIR (eq 19)") {
      number(c.at(0), r["limits"]["cir"]);
    } else if (key == "impulse on vehicle 1 (n, t, z)") {
      REQUIRE(c.size() == 3);
      for (int k = 0; k < 3; ++k) number(c[k], r["impulse"]["contact"][k]);
    } else if (key == "Delta-V") {
      pair(c, "delta_v_magnitude");
    } else if (key == "  longitudinal (+ forward)" || key == "  lateral (+ left)" || key == "  vertical (+ up)") {
      const int k = key[2] == 'l' ? (key[3] == 'o' ? 0 : 1) : 2;
      REQUIRE(c.size() == 2);
      for (int i = 0; i < 2; ++i) number(c[i], v[i]["delta_v_vehicle"][k]);
    } else if (key == "PDOF (clock)") {
      REQUIRE(c.size() == 2);
      for (int i = 0; i < 2; ++i) {
        if (c[i] == "-") {
          CHECK(v[i]["pdof_deg"].is_null());
          continue;
        }
        const auto open = c[i].find(" (");
        REQUIRE(open != std::string::npos);
        number(c[i].substr(0, open), v[i]["pdof_deg"]);
        CHECK(c[i].substr(open) == " (" + std::to_string(v[i]["pdof_clock"].get<int>()) + ")");
      }
    } else if (key == "speed after") {
      pair(c, "speed_after");
    } else if (key == "heading after") {
      pair(c, "heading_after_deg");
    } else if (key == "yaw rate after") {
      pair(c, "yaw_rate_after", yaw_factor);
    } else if (key == "deformation energy") {
      pair(c, "deformation_energy");
    } else if (key == "EES") {
      pair(c, "ees");
    } else if (key == "sliding before") {
      number(c.at(0), r["sliding"]["before"]);
    } else if (key == "sliding after: along, across") {
      REQUIRE(c.size() == 2);
      number(c[0], r["sliding"]["along"]);
      number(c[1], r["sliding"]["swerve_speed"]);
    } else if (key == "swerve off the sliding line") {
      number(c.at(0), r["sliding"]["swerve_angle_deg"]);
    } else if (key == "sliding reversed") {
      const json& rev = r["sliding"]["reversed"];
      CHECK(c.at(0) == (rev.is_null() ? "-" : rev.get<bool>() ? "yes" : "no"));
    } else if (key == "energy before, after, lost") {
      REQUIRE(c.size() == 3);
      number(c[0], r["energy"]["before"]);
      number(c[1], r["energy"]["after"]);
      number(c[2], r["energy"]["loss"]);
    } else if (key == "momentum residual / bound: linear, angular 1, 2") {
      REQUIRE(c.size() == 3);
      ratio(c[0], r["momentum"]["linear"]["residual_over_bound"]);
      for (int i = 0; i < 2; ++i) ratio(c[1 + i], r["momentum"]["angular_about_impulse_centre"][i]["residual_over_bound"]);
    } else if (key == "impulse rounding bound, relative") {
      ratio(c.at(0), r["rounding_bound"]);
    } else if (key == "warnings") {
      CHECK(c == std::vector<std::string>{"none"});
      CHECK(r["warnings"].empty());
    } else {
      FAIL("a summary row the test does not know");
    }
  }
};

struct Summary {
  int blocks = 0, numbers = 0;
};

// Reads the summary of `text` and checks it against `doc`, row by row.
Summary check_summary(const std::string& text, const json& doc) {
  const auto lines = lines_of(text);
  std::size_t i = 0;
  while (i < lines.size() && lines[i].rfind("Summary (", 0) != 0) ++i;
  REQUIRE(i < lines.size());
  while (i < lines.size() && !lines[i].empty()) ++i;  // the heading, wrapped
  Summary out;
  const std::vector<std::string> kVehicles{"vehicle 1", "vehicle 2"};
  const double yaw_factor = doc["units"] == "SI" ? 180 / M_PI : 1;
  std::vector<std::string> warnings;
  std::optional<Checker> block;
  const auto close = [&] {
    if (!block) return;
    CHECK(warnings == block->r["warnings"].get<std::vector<std::string>>());
    out.numbers += block->numbers;
    warnings.clear();
  };
  while (++i < lines.size() && lines[i].rfind("Detail: ", 0) != 0) {
    const std::string& l = lines[i];
    INFO("line '" << l << "'");
    if (l.empty()) continue;
    if (l[0] != ' ') {  // a strategy's block
      close();
      REQUIRE(out.blocks < static_cast<int>(doc["results"].size()));
      block.emplace(Checker{doc["results"][out.blocks++], yaw_factor});
      continue;
    }
    REQUIRE(block);
    if (l.rfind("  WARNING: ", 0) == 0) {
      std::string w = l.substr(11);
      // Continued under its first word, eleven columns in.
      while (i + 1 < lines.size() && lines[i + 1].rfind(std::string(11, ' '), 0) == 0 && lines[i + 1][11] != ' ')
        w += " " + lines[++i].substr(11);
      warnings.push_back(w);
      continue;
    }
    if (cells_of(l) == kVehicles) continue;
    // A label at column 2 (or 4 for a component), then its cells on the line or on the lines below.
    const std::size_t indent = l.find_first_not_of(' ');
    REQUIRE((indent == 2 || indent == 4));
    const std::size_t end = l.find("  ", indent);
    std::string label = l.substr(2, end == std::string::npos ? std::string::npos : end - 2);
    std::vector<std::string> cells = end == std::string::npos ? std::vector<std::string>{} : cells_of(l.substr(end));
    const auto cells_below = [&] {
      if (i + 1 == lines.size()) return false;
      const std::size_t at = lines[i + 1].find_first_not_of(' ');
      return at != std::string::npos && at > 4 && cells_of(lines[i + 1]) != kVehicles;
    };
    if (cells.empty())
      while (cells_below())
        for (auto& c : cells_of(lines[++i])) cells.push_back(c);
    block->row(label, cells);
  }
  close();
  CHECK(out.blocks == static_cast<int>(doc["results"].size()));
  return out;
}

std::string render_as(const case_format::CaseSpec& spec, const char* format, std::optional<Units> u) {
  case_format::RenderOptions o;
  o.format = case_format::parse_format(format).value();
  o.digits = kDigits;
  o.units = u;
  return studies::render(spec, "double", o);
}

void check_width(const std::string& text) {
  for (const auto& l : lines_of(text)) {
    INFO(l);
    CHECK(l.size() <= 80);
  }
}

std::vector<std::filesystem::path> bundled_cases() {
  std::vector<std::filesystem::path> out;
  for (const char* dir : {IMPACT3D_EXAMPLES_DIR, IMPACT3D_CASES_DIR})
    for (const auto& e : std::filesystem::directory_iterator(dir))
      if (e.path().extension() == ".json") out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

TEST_CASE("every number of the summary is the JSON's, in every bundled case and two unit systems", "[report]") {
  int cases = 0, blocks = 0, numbers = 0;
  for (const auto& path : bundled_cases()) {
    const case_format::CaseSpec spec = load_spec(path);
    const Units other = spec.units == Units::SI ? Units::US : Units::metric_kmh;
    for (const std::optional<Units> u : {std::optional<Units>{}, std::optional<Units>{other}}) {
      INFO(path.filename().string() << (u ? " in " + std::string(units_name(*u)) : std::string()));
      const std::string text = render_as(spec, "text", u);
      check_width(text);
      const auto s = check_summary(text, json::parse(render_as(spec, "json", u)));
      blocks += s.blocks;
      numbers += s.numbers;
    }
    ++cases;
  }
  CHECK(cases == 32);  // 4 examples, 28 verification cases
  CHECK(blocks >= 2 * cases);
  CHECK(numbers >= 30 * blocks);  // a block prints 30 to 40 numbers, fewer where one is undefined
}

TEST_CASE("names too long for a line are wrapped or cut, never past 80 columns", "[report]") {
  case_format::CaseSpec spec = load_spec(example("fig8_side_impact.json"));
  spec.name = std::string(70, 'N') + " " + std::string(120, 'M');
  spec.description = std::string(300, 'd') + " and some words after it";
  spec.vehicles[0].name = std::string(150, 'a');
  spec.vehicles[1].name = "two " + std::string(100, 'b');
  const std::string text = render_as(spec, "text", std::nullopt);
  check_width(text);
  // Every character of a name reaches the report, cut into lines.
  std::string joined;
  for (const auto& l : lines_of(text)) joined += l;
  CHECK(joined.find(std::string(150, 'a')) != std::string::npos);
  CHECK(joined.find(std::string(300, 'd')) != std::string::npos);
  CHECK(check_summary(text, json::parse(render_as(spec, "json", std::nullopt))).blocks ==
        static_cast<int>(spec.strategies.size()));
}

}  // namespace check_report_text
