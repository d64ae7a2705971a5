// impact3d report in a real browser: headless Chromium (Debian's `chromium`) loads the Figure 8 page from
// disk with no console message, renders a screenshot, and its DOM holds the summary with each vehicle's
// Delta-V as `solve --format json` gives it (to the 10 digits shown), every figure inlined and nothing
// fetched from a network. Without Chromium the test says so and is skipped (exit 77).
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <regex>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli_process.hpp"

namespace exam_report_html {

namespace fs = std::filesystem;
using namespace impact3d::test;

namespace {

std::string chromium() {
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "/usr/bin:/bin";
  for (std::size_t at = 0; at <= dirs.size();) {
    const std::size_t end = std::min(dirs.find(':', at), dirs.size());
    for (const char* name : {"chromium", "chromium-browser"}) {
      const fs::path p = fs::path(dirs.substr(at, end - at)) / name;
      if (!p.empty() && ::access(p.c_str(), X_OK) == 0) return p.string();
    }
    at = end + 1;
  }
  return "";
}

// The text of each cell of the summary row whose heading is `label`.
std::vector<std::string> row_cells(const std::string& dom, const std::string& label) {
  const std::regex row("<tr><th class=\"quantity\">" + std::regex_replace(label, std::regex(R"([\[\]\(\)\.\+])"), R"(\$&)") +
                       R"(</th>(.*?)</tr>)");
  std::smatch m;
  if (!std::regex_search(dom, m, row)) return {};
  std::vector<std::string> cells;
  const std::string tds = m[1];
  const std::regex td(R"(<td[^>]*>([^<]*)</td>)");
  for (std::sregex_iterator it(tds.begin(), tds.end(), td), end; it != end; ++it) cells.push_back((*it)[1]);
  return cells;
}

}  // namespace

TEST_CASE("the Figure 8 report opens in Chromium without console messages and shows solve's Delta-V", "[report][html]") {
  const std::string browser = chromium();
  if (browser.empty()) {
    std::puts("SKIPPED: Chromium is not installed (Debian: apt-get install chromium); the HTML report was not opened");
    std::exit(77);
  }
  const fs::path dir = fresh_directory("impact3d-report-html");
  fs::create_directories(dir / "profile");
  const std::string fig8 = std::string(IMPACT3D_EXAMPLES_DIR) + "/fig8_side_impact.json";
  const Run made = run_argv({"report", fig8, "-o", (dir / "fig8.html").string()});
  INFO(made.err);
  REQUIRE(made.status == 0);
  const std::string page = slurp(dir / "fig8.html");
  // Self-contained: no address to fetch, no script to run.
  CHECK(page.find("http://") == std::string::npos);
  CHECK(page.find("https://") == std::string::npos);
  CHECK(page.find("<script") == std::string::npos);

  const std::vector<std::string> common{"--headless", "--no-sandbox", "--disable-gpu", "--no-first-run", "--enable-logging=stderr",
                                        "--v=0", "--user-data-dir=" + (dir / "profile").string()};
  const std::string url = "file://" + (dir / "fig8.html").string();
  auto args = common;
  args.push_back("--dump-dom");
  args.push_back(url);
  const Run dom = run_program(browser, args, "", dir.string(), 120, 0);
  INFO(dom.err);
  REQUIRE(dom.status == 0);
  // Chromium logs each console message as "CONSOLE"; the page must raise none.
  CHECK(dom.err.find("CONSOLE") == std::string::npos);
  CHECK(dom.out.find("<table class=\"summary\" id=\"summary\">") != std::string::npos);

  const auto solved = nlohmann::json::parse(run_argv({"solve", fig8, "--format", "json"}).out);
  const auto dv = row_cells(dom.out, "Delta-V [m/s]");
  const auto& results = solved["results"];
  REQUIRE(dv.size() == 2 * results.size());
  int compared = 0;
  for (std::size_t k = 0; k < results.size(); ++k)
    for (int i = 0; i < 2; ++i) {
      const double shown = std::stod(dv[2 * k + i]), want = results[k]["vehicles"][i]["delta_v_magnitude"].get<double>();
      // 10 significant digits: within half a unit of the 10th.
      CHECK(std::fabs(shown - want) <= 5.0000001e-10 * std::fabs(want));
      ++compared;
    }
  CHECK(compared == 8);  // four strategies, two vehicles
  // Every figure is an image in the page: 4 collision diagrams, contact plane, impulse space, 4 solution
  // planes, 3 mu and 4 eps sweeps.
  std::size_t images = 0;
  for (std::size_t at = dom.out.find("<img"); at != std::string::npos; at = dom.out.find("<img", at + 1)) ++images;
  CHECK(images == 17);

  args = common;
  args.push_back("--screenshot=" + (dir / "page.png").string());
  args.push_back("--window-size=1300,3000");
  args.push_back(url);
  const Run shot = run_program(browser, args, "", dir.string(), 120, 0);
  INFO(shot.err);
  REQUIRE(shot.status == 0);
  CHECK(shot.err.find("CONSOLE") == std::string::npos);
  const std::string png = slurp(dir / "page.png");
  CHECK(png.rfind("\x89PNG\r\n\x1a\n", 0) == 0);
  CHECK(png.size() > 50000);  // a page of tables and figures, not a blank one
  fs::remove_all(dir);
}

}  // namespace exam_report_html
