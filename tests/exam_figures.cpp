// Every number a figure states equals what `solve` reports for the same case: each solution plane's
// angle, CIR and GIR (to the six digits the figure prints), its warnings word for word, the solution
// point drawn, and the mu sweep's range of 1.5 GIR. The known answer is `solve --format json` of each
// bundled example, with the offset-frontal Wach case (a negative ratio, plane angle -179.96 deg) among
// them: a figure that computes its own geometry, or drops a sign or a warning, fails here.
#include <catch2/catch.hpp>
#include <filesystem>
#include <limits>
#include <regex>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli_process.hpp"

namespace fs = std::filesystem;
using namespace impact3d::test;

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
const fs::path kWork = fs::temp_directory_path() / fmt::format("impact3d-figures-{}", ::getpid());

// The gnuplot single-quoted strings of a script line, unescaped ('' is one quote).
std::vector<std::string> quoted_strings(const std::string& line) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < line.size(); ++i) {
    if (line[i] != '\'') continue;
    std::string s;
    for (++i; i < line.size(); ++i) {
      if (line[i] == '\'' && i + 1 < line.size() && line[i + 1] == '\'') {
        s += '\'';
        ++i;
      } else if (line[i] == '\'') {
        break;
      } else {
        s += line[i];
      }
    }
    out.push_back(s);
  }
  return out;
}

std::string line_starting(const std::string& script, const std::string& start) {
  std::istringstream in(script);
  for (std::string line; std::getline(in, line);)
    if (line.rfind(start, 0) == 0) return line;
  return "";
}

double number_after(const std::string& text, const std::string& key) {
  const auto at = text.find(key);
  REQUIRE(at != std::string::npos);
  return std::stod(text.substr(at + key.size()));
}

// The figure prints {:.6g}; the report's value printed so must read the same.
std::string six(double x) { return fmt::format("{:.6g}", x); }

}  // namespace

TEST_CASE("every solution-plane figure states the report's angle, CIR, GIR and warnings", "[plot][figures]") {
  int figures = 0, with_limits = 0, warnings_checked = 0, sweeps = 0;
  bool wach_negative_seen = false;
  for (const auto& entry : fs::directory_iterator(IMPACT3D_EXAMPLES_DIR)) {
    if (entry.path().extension() != ".json") continue;
    const std::string name = entry.path().stem().string();
    INFO(name);
    const Run solved = run_argv({"solve", entry.path().string(), "--format", "json"});
    REQUIRE(solved.status == 0);
    const auto report = nlohmann::json::parse(solved.out);
    const fs::path dir = kWork / name;
    fs::remove_all(dir);
    const Run plotted = run_argv({"plot", entry.path().string(), "-o", dir.string()});
    REQUIRE(plotted.status == 0);
    const auto& results = report.at("results");
    for (std::size_t k = 0; k < results.size(); ++k) {
      const auto& r = results[k];
      INFO("result " << k);
      const std::string script = slurp(dir / fmt::format("solution_plane_{}.gp", k + 1));
      const auto title = quoted_strings(line_starting(script, "set title "));
      REQUIRE(title.size() >= 2);
      ++figures;
      const std::string kind = r.at("strategy").at("name");
      // Brach has no plane of its own in the report; the figure draws the plane of its impulse.
      if (r.contains("plane_angle_deg") && !r.at("plane_angle_deg").is_null()) {
        CHECK(six(number_after(title[1], "(angle ")) == six(r.at("plane_angle_deg").get<double>()));
      }
      const auto& limits = r.at("limits");
      if (limits.contains("cir") && limits.contains("gir")) {
        ++with_limits;
        CHECK(script.find(fmt::format("title 'CIR = {}'", six(limits.at("cir").get<double>()))) != std::string::npos);
        CHECK(script.find(fmt::format("title 'GIR = {}'", six(limits.at("gir").get<double>()))) != std::string::npos);
        if (kind == "wach" && limits.at("cir").get<double>() < 0) wach_negative_seen = true;
      }
      // Every warning of the result, in order, and nothing else, after the figure's own two lines.
      std::vector<std::string> stated(title.begin() + 2, title.end());
      std::vector<std::string> reported;
      for (const auto& w : r.at("warnings")) reported.push_back("warning: " + w.get<std::string>());
      CHECK(stated == reported);
      warnings_checked += static_cast<int>(reported.size());
      // The solution point drawn is the reported impulse: P_n exactly, P_u = |P_cp| up to its sign.
      const std::string points = slurp(dir / fmt::format("solution_plane_{}.points.csv", k + 1));
      const auto row = points.substr(points.find('\n') + 1);
      const double P_u = std::stod(row.substr(row.rfind(',', row.rfind(',') - 1) + 1));
      const double P_n = std::stod(row.substr(row.rfind(',') + 1));
      const auto& P = r.at("impulse").at("contact");
      const double P_cp = std::hypot(P[1].get<double>(), P[2].get<double>());
      // 17-digit text both ways; the in-plane component is a dot product of a few roundings: 8 eps.
      CHECK(std::fabs(P_n - P[0].get<double>()) <= 4 * kEps * std::fabs(P[0].get<double>()));
      CHECK(std::fabs(std::fabs(P_u) - P_cp) <= 8 * kEps * (P_cp + std::fabs(P[0].get<double>())));
      // pc-crash sweeps mu over 0 to 1.5 GIR of eq 14: the GIR the report gives.
      if (kind == "pc-crash") {
        const std::string sweep = slurp(dir / fmt::format("sweep_mu_{}.gp", k + 1));
        const double top = number_after(line_starting(sweep, "set xrange [0:"), "set xrange [0:");
        const double gir = limits.at("gir").get<double>();
        // 1.5 GIR printed to 17 digits: the product's one rounding and the text's.
        CHECK(std::fabs(top - 1.5 * gir) <= 4 * kEps * std::fabs(1.5 * gir));
        ++sweeps;
      }
    }
    fs::remove_all(dir);
  }
  // Four examples with five, three, two and three strategies at the time of writing: at least ten figures.
  CHECK(figures >= 10);
  CHECK(with_limits >= 6);
  CHECK(warnings_checked >= 1);
  CHECK(sweeps >= 3);
  CHECK(wach_negative_seen);  // the offset-frontal Wach case
}
