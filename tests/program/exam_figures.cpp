// Every number a figure states equals what `solve` reports for the same case: each solution plane's
// angle, CIR and GIR (to the six digits the figure prints), its warnings word for word, the solution
// point drawn, and the mu sweep's range of 1.5 GIR. The known answer is `solve --format json` of each
// bundled example, with the offset-frontal Wach case (a negative ratio, plane angle -179.96 deg) among
// them: a figure that computes its own geometry, or drops a sign or a warning, fails here.
#include <catch2/catch.hpp>
#include <algorithm>
#include <array>
#include <fstream>
#include <filesystem>
#include <limits>
#include <map>
#include <set>
#include <regex>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli_process.hpp"

namespace exam_figures {

namespace fs = std::filesystem;
using namespace impact3d::test;

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
const fs::path kWork = fresh_directory("impact3d-figures");

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

// The rows of a "label,value" file after its header.
std::vector<std::pair<std::string, double>> rows(const std::string& csv) {
  std::vector<std::pair<std::string, double>> out;
  for (const auto& [label, v] : labelled_rows(csv)) out.push_back({label, v.at(0)});
  return out;
}

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
      // The mu sweep of this strategy (or of the first strategy alike but for mu) marks its mu, and for
      // the first also GIR and CIR; it spans 1.5 GIR of eq 14 and every mark.
      for (std::size_t j = 0; j <= k; ++j) {
        const fs::path marks_file = dir / fmt::format("sweep_mu_{}.marks.csv", j + 1);
        if (!fs::exists(marks_file)) continue;
        const auto marks = rows(slurp(marks_file));
        const std::string key = kind == "brach" ? "mu_t" : "mu";
        const auto& mu = r.at("strategy").at(key);
        if (!mu.is_number()) continue;  // "critical": marked with the ratio found, by the first only
        const auto mine = std::find_if(marks.begin(), marks.end(), [&](const auto& m) { return m.first.rfind(key + "=", 0) == 0 &&
                                                                                                 std::fabs(m.second - mu.get<double>()) == 0; });
        if (mine == marks.end()) continue;  // a sweep of other strategies
        ++sweeps;
        if (j == k) {
          for (const char* limit : {"gir", "cir"}) {
            if (!limits.contains(limit) || limits.at(limit).is_null()) continue;
            const double v = limits.at(limit).get<double>();
            std::string name(limit);
            std::transform(name.begin(), name.end(), name.begin(), ::toupper);
            const auto m = std::find_if(marks.begin(), marks.end(), [&](const auto& x) { return x.first == name + "=" + six(v); });
            REQUIRE(m != marks.end());
            CHECK(std::fabs(m->second - v) <= 4 * kEps * std::fabs(v));  // 17 digits both ways
          }
        }
        const std::string sweep = slurp(dir / fmt::format("sweep_mu_{}.gp", j + 1));
        const double top = number_after(line_starting(sweep, "set xrange [0:"), "set xrange [0:");
        if (kind == "pc-crash") CHECK(top >= 1.5 * limits.at("gir").get<double>() * (1 - 4 * kEps));
        for (const auto& m : marks) CHECK(top > m.second);
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

namespace {

// Every `title '...'` of a script but the multiplot's, unescaped.
std::vector<std::string> key_titles(const std::string& script) {
  std::vector<std::string> out;
  std::istringstream in(script);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("set multiplot", 0) == 0) continue;
    for (std::size_t at = line.find(" title '"); at != std::string::npos; at = line.find(" title '", at + 1))
      out.push_back(quoted_strings(line.substr(at + 7)).at(0));
  }
  return out;
}

std::string xml_escaped(const std::string& text) {
  std::string out;
  for (char ch : text) out += ch == '&' ? "&amp;" : ch == '<' ? "&lt;" : ch == '>' ? "&gt;" : std::string(1, ch);
  return out;
}

// pt, ps and colour of each `with points` item of a script, by its key title.
struct Look {
  int glyph;
  double size;
  std::string colour;
};
std::map<std::string, Look> looks(const std::string& script) {
  std::map<std::string, Look> out;
  static const std::regex item(R"(with points pt (\d+) ps ([0-9.]+) lw 2 lc rgb '(#[0-9a-f]{6})' title '([^']*)')");
  for (std::sregex_iterator it(script.begin(), script.end(), item), end; it != end; ++it)
    out[(*it)[4]] = {std::stoi((*it)[1]), std::stod((*it)[2]), (*it)[3]};
  return out;
}

}  // namespace

TEST_CASE("every key entry is in the SVG, and the PNG is drawn from the same script", "[plot][figures]") {
  const fs::path svg_dir = kWork / "keys_svg", png_dir = kWork / "keys_png";
  fs::remove_all(svg_dir);
  fs::remove_all(png_dir);
  const std::string fig8 = std::string(IMPACT3D_EXAMPLES_DIR) + "/fig8_side_impact.json";
  REQUIRE(run_argv({"plot", fig8, "-o", svg_dir.string()}).status == 0);
  REQUIRE(run_argv({"plot", fig8, "-o", png_dir.string(), "--png"}).status == 0);
  int scripts = 0, entries = 0;
  for (const auto& e : fs::directory_iterator(svg_dir)) {
    if (e.path().extension() != ".gp") continue;
    ++scripts;
    const std::string name = e.path().stem().string();
    INFO(name);
    const std::string script = slurp(e.path()), svg = slurp(svg_dir / (name + ".svg"));
    for (const auto& title : key_titles(script)) {
      INFO(title);
      CHECK(svg.find(">" + xml_escaped(title) + "<") != std::string::npos);
      ++entries;
    }
    // The PNG's script is the SVG's but for the terminal line and the point sizes (each terminal's own).
    std::string png_script = slurp(png_dir / (name + ".gp"));
    CHECK(png_script.rfind("set terminal pngcairo", 0) == 0);
    const std::regex size(" ps [0-9.]+ ");
    CHECK(std::regex_replace(png_script.substr(png_script.find('\n')), size, " ps N ") ==
          std::regex_replace(script.substr(script.find('\n')), size, " ps N "));
    CHECK(slurp(png_dir / (name + ".png")).rfind("\x89PNG", 0) == 0);
  }
  // Figure 8: a contact plane, an impulse space, four solution planes, three mu and four eps sweeps,
  // four collision diagrams.
  CHECK(scripts == 17);
  CHECK(entries >= 80);
  // The shaded planes of the impulse space each have a key entry (gnuplot draws none for polygons).
  const std::string space = slurp(svg_dir / "impulse_space.gp");
  std::size_t polygons = 0;
  for (std::size_t at = space.find("with polygons"); at != std::string::npos; at = space.find("with polygons", at + 1)) ++polygons;
  CHECK(polygons == 6);
  for (const char* plane : {"maximum-compression plane", "t no-sliding plane", "z no-sliding plane", "PC-Crash plane (phi_FI, eq 15)",
                            "Wach plane (phi, eq 21)"})
    CHECK(space.find(fmt::format("fs solid 0.4 title '{}'", plane)) != std::string::npos);
  // The paper's four volumes are labelled.
  for (const char* v : {"'A' at", "'B' at", "'C' at", "'D' at"}) CHECK(space.find(v) != std::string::npos);
}

TEST_CASE("a strategy looks the same in every figure; coincident points are drawn around each other and named", "[plot][figures]") {
  const fs::path dir = kWork / "looks";
  fs::remove_all(dir);
  const std::string fig8 = std::string(IMPACT3D_EXAMPLES_DIR) + "/fig8_side_impact.json";
  REQUIRE(run_argv({"plot", fig8, "-o", dir.string()}).status == 0);
  const auto contact = looks(slurp(dir / "contact_plane.gp")), space = looks(slurp(dir / "impulse_space.gp"));
  // Figure 8's pc-crash mu=1.0 is the Full Impact, and Brach with both ratios critical is the Critical
  // Impulse Line's point (the paper's Figure 8 discussion): each drawn larger around the other.
  const std::vector<std::string> strategies{"pc-crash mu=1.0", "pc-crash mu=0.4", "wach mu=0.4 limit=cir",
                                            "brach mu_t=critical mu_z=critical"};
  REQUIRE(contact.count("pc-crash mu=1.0 (= Full Impact)"));
  REQUIRE(contact.count("brach mu_t=critical mu_z=critical (= no sliding (CIL))"));
  CHECK(contact.at("pc-crash mu=1.0 (= Full Impact)").size > contact.at("Full Impact").size);
  CHECK(contact.at("brach mu_t=critical mu_z=critical (= no sliding (CIL))").size > contact.at("no sliding (CIL)").size);
  const auto find = [](const std::map<std::string, Look>& m, const std::string& label) {
    for (const auto& [title, look] : m)
      if (title == label || title.rfind(label + " (= ", 0) == 0) return look;
    FAIL("no point " << label);
    return Look{};
  };
  std::set<std::pair<int, std::string>> seen;
  for (std::size_t k = 0; k < strategies.size(); ++k) {
    INFO(strategies[k]);
    const Look a = find(contact, strategies[k]), b = find(space, strategies[k]);
    const Look c = find(looks(slurp(dir / fmt::format("solution_plane_{}.gp", k + 1))), strategies[k]);
    CHECK(a.glyph == b.glyph);
    CHECK(a.glyph == c.glyph);
    CHECK(a.colour == b.colour);
    CHECK(a.colour == c.colour);
    seen.insert({a.glyph, a.colour});
    // No strategy takes a reference point's glyph.
    for (const char* ref : {"Full Impact", "no sliding (CIL)"}) CHECK(a.glyph != contact.at(ref).glyph);
    CHECK(a.glyph != space.at("maximum energy loss (eps = 0)").glyph);
  }
  CHECK(seen.size() == strategies.size());
}

TEST_CASE("sweeps draw a value within its rounding bound as zero", "[plot][figures]") {
  const fs::path dir = kWork / "zero";
  fs::remove_all(dir);
  REQUIRE(run_argv({"plot", std::string(IMPACT3D_EXAMPLES_DIR) + "/fig8_side_impact.json", "-o", dir.string()}).status == 0);
  // Figure 8's Brach with mu_z critical leaves no sliding across the initial sliding (along t): the
  // computed value is rounding, up to 1e-15 m/s, which the sweep drew as data before.
  std::istringstream in(slurp(dir / "sweep_mu_4.csv"));
  std::string line;
  std::getline(in, line);
  REQUIRE(line == "mu_t,sliding_along_after,sliding_across_after,swerve_deg,energy_loss");
  int rows = 0;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::vector<std::string> cells;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) cells.push_back(cell);
    REQUIRE(cells.size() == 5);
    CHECK(cells[2] == "0");
    ++rows;
  }
  CHECK(rows == 61);
}

namespace {

// NAME.arrows.csv: label -> (from, value, drawn per unit).
struct ArrowRow {
  std::array<double, 3> from, value;
  double scale;
};
std::map<std::string, ArrowRow> arrows(const std::string& csv) {
  std::map<std::string, ArrowRow> out;
  for (const auto& [label, v] : labelled_rows(csv)) {
    REQUIRE(v.size() == 7);
    out[label] = {{v[0], v[1], v[2]}, {v[3], v[4], v[5]}, v[6]};
  }
  return out;
}

bool near_vec(const std::array<double, 3>& a, const nlohmann::json& b, double eps_count) {
  double scale = 0;
  for (int c = 0; c < 3; ++c) scale = std::max(scale, std::fabs(b[c].get<double>()));
  for (int c = 0; c < 3; ++c)
    if (std::fabs(a[c] - b[c].get<double>()) > eps_count * kEps * scale) return false;
  return true;
}

}  // namespace

TEST_CASE("the collision diagram draws solve's velocities and impulse from CGs placed by the impulse centres", "[plot][figures][collision]") {
  int diagrams = 0;
  for (const char* file : {"fig8_side_impact.json", "us_pickup_into_sedan.json"}) {
    const std::string path = std::string(IMPACT3D_EXAMPLES_DIR) + "/" + file;
    INFO(file);
    const fs::path dir = kWork / (std::string("collision_") + file);
    fs::remove_all(dir);
    REQUIRE(run_argv({"plot", path, "-o", dir.string()}).status == 0);
    const auto solved = nlohmann::json::parse(run_argv({"solve", path, "--format", "json"}).out);
    const auto in_case = nlohmann::json::parse(slurp(path));
    for (std::size_t k = 0; k < solved["results"].size(); ++k) {
      const auto& r = solved["results"][k];
      const auto rows = arrows(slurp(dir / fmt::format("collision_{}.arrows.csv", k + 1)));
      for (int i = 0; i < 2; ++i) {
        const auto& before = rows.at(fmt::format("vehicle {} velocity before", i + 1));
        const auto& after = rows.at(fmt::format("vehicle {} velocity after", i + 1));
        // Before: the case's own numbers (a unit factor there and back: 4 eps); after: solve's.
        CHECK(near_vec(before.value, in_case["vehicles"][i]["velocity"], 4));
        CHECK(near_vec(after.value, r["vehicles"][i]["velocity"], 4));
        // The CG lies where the impulse centre, turned into the world, puts it: as far as the case says.
        const auto& ic = in_case["vehicles"][i]["impulse_center"];
        const double want = std::hypot(ic[0].get<double>(), ic[1].get<double>(), ic[2].get<double>());
        CHECK(std::fabs(std::hypot(before.from[0], before.from[1], before.from[2]) - want) <= 8 * kEps * want);
        CHECK(before.scale == after.scale);  // one time scale for every velocity
      }
      CHECK(near_vec(rows.at("impulse on vehicle 1").value, r["impulse"]["world"], 4));
      for (const char* axis : {"n", "t", "z"}) {
        const auto& a = rows.at(std::string("contact axis ") + axis).value;
        CHECK(std::fabs(std::hypot(a[0], a[1], a[2]) - 1) <= 4 * kEps);
      }
      // Level vehicles and a level contact: the plan alone.
      CHECK(slurp(dir / fmt::format("collision_{}.gp", k + 1)).find("set multiplot") == std::string::npos);
      ++diagrams;
    }
  }
  CHECK(diagrams >= 6);
  // Pitched and rolled vehicles: an elevation beside the plan.
  const fs::path tilted = kWork / "collision_tilted";
  fs::remove_all(tilted);
  REQUIRE(run_argv({"plot", std::string(IMPACT3D_CASES_DIR) + "/pitched_rolled_vehicles.json", "-o", tilted.string()}).status == 0);
  CHECK(slurp(tilted / "collision_1.gp").find("set multiplot layout 1,2") != std::string::npos);
  CHECK(slurp(tilted / "collision_1.gp").find("'elevation (along the normal''s horizontal, z up)'") != std::string::npos);
}

TEST_CASE("given dimensions draw the box: a level vehicle's outline is its length and width about the CG", "[plot][figures][collision]") {
  auto c = nlohmann::json::parse(slurp(std::string(IMPACT3D_EXAMPLES_DIR) + "/fig8_side_impact.json"));
  c["vehicles"][0]["dimensions"] = {{"length", 4.8}, {"width", 1.8}, {"cg_to_front", 1.9}};
  const fs::path dir = kWork / "dimensions";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path file = dir / "case.json";
  std::ofstream(file) << c.dump();
  REQUIRE(run_argv({"plot", file.string(), "-o", (dir / "out").string()}).status == 0);
  const std::string script = slurp(dir / "out" / "collision_1.gp");
  CHECK(script.find("stand-in") != std::string::npos);  // vehicle 2 still has none
  // Block 0 of the data: vehicle 1's outline in plan. Figure 8's Malibu is level at yaw 0: x from the
  // CG - 2.9 to the CG + 1.9, y the CG +- 0.9.
  std::istringstream in(slurp(dir / "out" / "collision_1.dat"));
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  for (std::string line; std::getline(in, line) && !line.empty();) {
    const double x = std::stod(line), y = std::stod(line.substr(line.find(',') + 1));
    x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
  }
  const auto rows = arrows(slurp(dir / "out" / "collision_1.arrows.csv"));
  const auto& cg = rows.at("vehicle 1 velocity before").from;
  CHECK(std::fabs(x1 - cg[0] - 1.9) <= 1e-14);
  CHECK(std::fabs(cg[0] - x0 - 2.9) <= 1e-14);
  CHECK(std::fabs(y1 - cg[1] - 0.9) <= 1e-14);
  CHECK(std::fabs(cg[1] - y0 - 0.9) <= 1e-14);
}

}  // namespace exam_figures
