// impact3d plot on named inputs (the bundled examples, and cases written here): every figure of every
// example renders, the files are valid and non-empty, and the solution points drawn (read back from the
// data the figures are drawn from) are the computed impulses.
//
// Where the expected answers come from: the figure list of docs/figures.md ("Impulse-space diagrams": the
// contact plane, the impulse space, and per strategy a solution plane and two sweeps), the SVG and PNG
// file signatures (`<?xml`, `\x89PNG\r\n\x1a\n`), and `impact3d solve --format json` of the same case for
// the impulses; the hostile names are reproductions of reported attacks.
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli_process.hpp"

namespace exam_plot {

namespace fs = std::filesystem;
using namespace impact3d::test;

namespace {

const fs::path kWork = fresh_directory("impact3d-plot");

// Rows of NAME.points.csv after the header: label and numbers.
std::vector<std::pair<std::string, std::vector<double>>> points(const fs::path& p) { return labelled_rows(slurp(p)); }

// A drawn point against solve's number: both are doubles printed with 17 significant digits, which read
// back exactly; the plot's own hypot or unit factor may round once more than solve's: 4 eps of the value
// (the examples differ by at most 0.8 eps).
bool near(double a, double b) { return std::fabs(a - b) <= 4 * std::numeric_limits<double>::epsilon() * std::fabs(b); }

}  // namespace

TEST_CASE("every figure of every example renders as SVG and draws the computed impulses", "[plot]") {
  int examples = 0;
  for (const auto& entry : fs::directory_iterator(IMPACT3D_EXAMPLES_DIR)) {
    if (entry.path().extension() != ".json") continue;  // examples/figures/ and any other non-case file
    ++examples;
    const std::string name = entry.path().stem().string();
    INFO(name);
    const fs::path out = kWork / name;
    REQUIRE(run_cli(fmt::format("plot '{}' -o '{}'", entry.path().string(), out.string())).status == 0);
    const Run solved = run_cli(fmt::format("solve '{}' --format json", entry.path().string()));
    REQUIRE(solved.status == 0);
    const auto result = nlohmann::json::parse(solved.out);
    const std::size_t n = result["results"].size();
    std::vector<std::string> figures{"contact_plane", "impulse_space"};
    for (std::size_t k = 1; k <= n; ++k)
      for (const char* f : {"solution_plane_", "sweep_eps_"}) figures.push_back(f + std::to_string(k));
    // One mu sweep for strategies alike but for the ratio swept (mu; Brach's mu_t), named after the first.
    std::set<std::string> swept;
    for (std::size_t k = 0; k < n; ++k) {
      auto alike = result["results"][k]["strategy"];
      alike.erase(alike["name"] == "brach" ? "mu_t" : "mu");
      const bool first = swept.insert(alike.dump()).second;
      const fs::path mu = out / fmt::format("sweep_mu_{}.svg", k + 1);
      INFO(mu.string());
      CHECK(fs::exists(mu) == first);
      if (first) figures.push_back(fmt::format("sweep_mu_{}", k + 1));
    }
    for (const auto& f : figures) {
      INFO(f);
      const std::string svg = slurp(out / (f + ".svg"));
      CHECK(svg.size() > 1000);
      CHECK(svg.rfind("<?xml", 0) == 0);
      CHECK(svg.find("<svg") != std::string::npos);
      CHECK(svg.find("</svg>") != std::string::npos);
    }
    // The contact-plane view: rows 3.. are the strategies' (P_t, P_z), in the result's units.
    const auto cp = points(out / "contact_plane.points.csv");
    REQUIRE(cp.size() == n + 2);
    for (std::size_t k = 0; k < n; ++k) {
      const auto& P = result["results"][k]["impulse"]["contact"];
      CHECK(near(cp[k + 2].second[0], P[1].get<double>()));
      CHECK(near(cp[k + 2].second[1], P[2].get<double>()));
    }
    // The impulse-space view: (P_t, P_z, P_n); the maximum-energy-loss point, the Full Impact and the
    // Critical Impulse Line's point (where it exists), then the strategies'.
    const auto is = points(out / "impulse_space.points.csv");
    REQUIRE(is.size() >= n + 2);
    REQUIRE(is.size() <= n + 3);
    CHECK(is[0].first == "maximum energy loss (eps = 0)");
    const auto& mx = result["impulse_space"]["max_energy_loss_impulse"];
    for (int c = 0; c < 3; ++c) CHECK(near(is[0].second[(c + 2) % 3], mx[c].get<double>()));
    const std::size_t first = is.size() - n;
    for (std::size_t k = 0; k < n; ++k) {
      const auto& P = result["results"][k]["impulse"]["contact"];
      CHECK(near(is[first + k].second[0], P[1].get<double>()));
      CHECK(near(is[first + k].second[1], P[2].get<double>()));
      CHECK(near(is[first + k].second[2], P[0].get<double>()));
    }
    // Each solution plane: (in-plane impulse, P_n) = (+-|(P_t, P_z)|, P_n) on the strategy's plane, negative
    // where the impulse points against the plane's direction (a negative ratio; exam_figures checks the sign).
    for (std::size_t k = 0; k < n; ++k) {
      const auto sp = points(out / fmt::format("solution_plane_{}.points.csv", k + 1));
      const auto& P = result["results"][k]["impulse"]["contact"];
      REQUIRE(sp.size() == 1);
      CHECK(near(std::fabs(sp[0].second[0]), std::hypot(P[1].get<double>(), P[2].get<double>())));
      CHECK(near(sp[0].second[1], P[0].get<double>()));
    }
  }
  CHECK(examples >= 4);  // the four bundled examples (fig8, offset frontal, override, US); more may come
}

TEST_CASE("PNG files on request (option --png)", "[plot]") {
  const fs::path out = kWork / "png";
  REQUIRE(run_cli(fmt::format("plot '{}/fig8_side_impact.json' -o '{}' --png", IMPACT3D_EXAMPLES_DIR, out.string())).status == 0);
  const std::string png = slurp(out / "contact_plane.png");
  REQUIRE(png.size() > 1000);
  CHECK(png.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0);
}

TEST_CASE("without gnuplot: one clear line and a non-zero exit", "[plot]") {
  const Run r = run_cli(fmt::format("plot '{}/fig8_side_impact.json' -o '{}'", IMPACT3D_EXAMPLES_DIR, (kWork / "nogp").string()),
                        "env PATH=/nonexistent");
  CHECK(r.status == 1);
  CHECK(r.out.empty());
  CHECK(r.err.find("gnuplot not found") != std::string::npos);
}

// Reproductions of reported attacks: text from the case or the command line never reaches gnuplot or a shell as code.
TEST_CASE("a case name is drawn as text, never run by gnuplot", "[plot][hostile]") {
  auto doc = nlohmann::json::parse(slurp(fs::path(IMPACT3D_EXAMPLES_DIR) / "fig8_side_impact.json"));
  const fs::path dir = kWork / "names";
  fs::create_directories(dir);
  const std::vector<std::string> names = {"x `touch pwned1` y", "Fig 8\n!touch pwned2\n#", "a' . system('touch pwned3') . 'b",
                                          "t\nset print 'pwned4'\nprint 1", "m @x `touch pwned5`"};
  for (const auto& name : names) {
    doc["name"] = name;
    std::ofstream(dir / "case.json") << doc.dump();
    const Run r = run_argv({"plot", "case.json", "-o", "figs"}, dir.string());
    INFO(name << "\n" << r.err);
    CHECK(r.status == 0);
    CHECK(r.err.empty());
  }
  for (const char* f : {"pwned1", "pwned2", "pwned3", "pwned4", "pwned5"}) {
    CHECK(!fs::exists(dir / f));
    CHECK(!fs::exists(dir / "figs" / f));
  }
  // The last name is in the title as written, backquotes and all (gnuplot escapes it for SVG).
  CHECK(slurp(dir / "figs" / "contact_plane.svg").find("m @x `touch pwned5`") != std::string::npos);
}

TEST_CASE("the output directory is an argument, never shell text", "[plot][hostile]") {
  const fs::path dir = kWork / "outdir";
  fs::create_directories(dir);
  const std::string odd = "x'; touch pwned; echo '";
  const Run r = run_argv({"plot", (fs::path(IMPACT3D_EXAMPLES_DIR) / "fig8_side_impact.json").string(), "-o", odd}, dir.string());
  CHECK(r.status == 0);
  CHECK(fs::exists(dir / odd / "contact_plane.svg"));
  CHECK(!fs::exists(dir / "pwned"));
  // "-" is a directory named "-", not the previous working directory.
  const Run dash = run_argv({"plot", (fs::path(IMPACT3D_EXAMPLES_DIR) / "fig8_side_impact.json").string(), "-o", "-"}, dir.string());
  CHECK(dash.status == 0);
  CHECK(fs::exists(dir / "-" / "contact_plane.svg"));
}

TEST_CASE("a link planted in the output directory is replaced, not followed", "[plot][hostile]") {
  const fs::path dir = kWork / "planted";
  fs::create_directories(dir / "figs");
  std::ofstream(dir / "target") << "keep";
  for (const char* f : {"contact_plane.dat", "contact_plane.svg", "contact_plane.gp"}) fs::create_symlink(dir / "target", dir / "figs" / f);
  const Run r = run_argv({"plot", (fs::path(IMPACT3D_EXAMPLES_DIR) / "fig8_side_impact.json").string(), "-o", "figs"}, dir.string());
  CHECK(r.status == 0);
  CHECK(slurp(dir / "target") == "keep");
  CHECK(!fs::is_symlink(dir / "figs" / "contact_plane.dat"));
  CHECK(!fs::is_symlink(dir / "figs" / "contact_plane.svg"));
}

TEST_CASE("a head-on case (no contact-plane impulse) plots every figure without a gnuplot message", "[plot][hostile]") {
  const fs::path dir = kWork / "head_on";
  fs::create_directories(dir);
  std::ofstream(dir / "case.json") << R"({"name": "head-on", "vehicles": [
    {"mass": 1500, "inertia": {"Ixx": 500, "Iyy": 2000, "Izz": 2200}, "velocity": [10, 0, 0], "impulse_center": [2, 0, 0]},
    {"mass": 1500, "inertia": {"Ixx": 500, "Iyy": 2000, "Izz": 2200}, "orientation_deg": {"yaw": 180},
     "velocity": [-10, 0, 0], "impulse_center": [2, 0, 0]}],
    "contact": {"normal_yaw_deg": 180}, "restitution": 0.1,
    "strategy": [{"name": "pc-crash", "mu": 0.4}, {"name": "wach", "mu": 0.4}, {"name": "brach", "mu_t": "critical", "mu_z": 0}]})";
  const Run r = run_argv({"plot", "case.json", "-o", "figs"}, dir.string());
  INFO(r.err);
  CHECK(r.status == 0);
  CHECK(r.err.empty());
  int figures = 0;
  for (const auto& e : fs::directory_iterator(dir / "figs"))
    if (e.path().extension() == ".svg") {
      ++figures;
      CHECK(fs::file_size(e.path()) > 1000);
    }
  // Contact plane, impulse space; per strategy (three of different kinds) a solution plane, two sweeps
  // and a collision diagram.
  CHECK(figures == 14);
}

TEST_CASE("report: the case author's text is escaped into the page, never markup", "[report][hostile]") {
  const fs::path dir = kWork / "report_hostile";
  fs::create_directories(dir);
  auto c = nlohmann::json::parse(slurp(fs::path(IMPACT3D_EXAMPLES_DIR) / "fig8_side_impact.json"));
  c["name"] = "</title><script>alert(1)</script>";
  c["description"] = "<img src=x onerror=alert(2)> & \"quoted\"";
  c["vehicles"][0]["name"] = "a'b<i>";
  std::ofstream(dir / "case.json") << c.dump();
  const Run r = run_argv({"report", "case.json", "-o", "page.html", "--no-figures"}, dir.string());
  INFO(r.err);
  REQUIRE(r.status == 0);
  CHECK(r.out == "page.html\n");
  const std::string page = slurp(dir / "page.html");
  CHECK(page.find("<script") == std::string::npos);
  CHECK(page.find("<img") == std::string::npos);  // no figures asked for, and the description's is text
  CHECK(page.find("&lt;/title&gt;&lt;script&gt;alert(1)&lt;/script&gt;") != std::string::npos);
  CHECK(page.find("&lt;img src=x onerror=alert(2)&gt; &amp; &quot;quoted&quot;") != std::string::npos);
  CHECK(page.find("a&#39;b&lt;i&gt;") != std::string::npos);
  CHECK(page.find("Figures left out (--no-figures).") != std::string::npos);
  // Exact arithmetic has no page; the refusal names the option, and nothing is written.
  const Run exact = run_argv({"report", "case.json", "-o", "exact.html", "--precision", "exact"}, dir.string());
  CHECK(exact.status == 1);
  CHECK(exact.out.empty());
  CHECK(exact.err.find("--precision") != std::string::npos);
  CHECK_FALSE(fs::exists(dir / "exact.html"));
}

}  // namespace exam_plot
