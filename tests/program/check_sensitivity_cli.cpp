// `impact3d sensitivity` (../shared/spec/many-cases.md) as a user runs it: the contract's keys for every
// example; the regime margin is GIR - mu (cap - mu for Wach) of `solve`'s own document; every output
// the document writes has a derivative by every input; bad cases get solve's own one line (the bad-input
// corpus, whose lines are reviewed by hand in bad_input/expected.tsv), exit 1, nothing on stdout; bad
// options exit 1 or 2 with one line; --plot draws a tornado per vehicle.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "bad_input.hpp"
#include "cli_process.hpp"

namespace check_sensitivity_cli {

using namespace impact3d::test;
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr double kEps = 0x1p-52;

}  // namespace

TEST_CASE("every example: the contract's keys, and the regime margin from solve's own limits") {
  int results = 0;
  for (const auto& entry : fs::directory_iterator(IMPACT3D_EXAMPLES_DIR)) {
    if (entry.path().extension() != ".json") continue;
    const std::string file = entry.path().string();
    INFO(file);
    const Run sens = run_program(IMPACT3D_CLI, {"sensitivity", file, "--format", "json"});
    REQUIRE(sens.status == 0);
    CHECK(sens.err.empty());
    const Run solve = run_program(IMPACT3D_CLI, {"solve", file, "--format", "json"});
    REQUIRE(solve.status == 0);
    const json s = json::parse(sens.out), doc = json::parse(solve.out);
    REQUIRE(s["results"].size() == doc["results"].size());
    for (std::size_t k = 0; k < doc["results"].size(); ++k) {
      const json& r = s["results"][k];
      const json& d = doc["results"][k];
      CHECK(r["strategy"] == d["strategy"]);
      CHECK(r["regime"] == d["regime"]);
      const std::string name = d["strategy"]["name"];
      if (name == "pc-crash" || name == "wach") {
        const std::string limit = name == "wach" ? d["strategy"].value("limit", std::string("cir")) : "gir";
        const double margin = d["limits"][limit].get<double>() - d["strategy"]["mu"].get<double>();
        CHECK(r["regime_margin_of"] == limit + " - mu");
        // The same arithmetic on the value, but Eigen vectorizes double products and not dual ones, so
        // sums may be taken in another order: 2^6 eps of the limit.
        CHECK(std::fabs(r["regime_margin"].get<double>() - margin) <= 64 * kEps * std::fabs(d["limits"][limit].get<double>()));
      } else {
        CHECK(r["regime_margin"].is_null());
      }
      REQUIRE(r["derivatives"].is_object());
      for (const auto& [output, by] : r["derivatives"].items()) {
        CHECK(by.size() == s["inputs"].size());
        CHECK(r["values"].contains(output));
      }
      CHECK(r["derivatives"].contains("vehicles[0].delta_v_magnitude"));
      CHECK(r["derivatives"].contains("energy.loss"));
      ++results;
    }
  }
  CHECK(results >= 10);
}

TEST_CASE("bad cases get solve's one line, exit 1, nothing on stdout") {
  int checked = 0;
  for (const auto& [file, line] : expected_lines()) {
    const std::string path = (fs::path(IMPACT3D_BAD_INPUT_DIR) / file).string();
    const Run solve = run_program(IMPACT3D_CLI, {"solve", path});
    const Run sens = run_program(IMPACT3D_CLI, {"sensitivity", path});
    INFO(file);
    CHECK(sens.status == 1);
    CHECK(sens.out.empty());
    CHECK(sens.err == solve.err);
    ++checked;
  }
  CHECK(checked >= 40);
}

TEST_CASE("bad options: one line, nothing on stdout") {
  const std::string fig8 = IMPACT3D_EXAMPLES_DIR "/fig8_side_impact.json";
  const Run strategy = run_program(IMPACT3D_CLI, {"sensitivity", fig8, "--strategy", "pc-crash:mu=-1"});
  CHECK(strategy.status == 1);
  CHECK(strategy.out.empty());
  // As solve names it: the case file, then the option's path.
  CHECK(strategy.err == run_program(IMPACT3D_CLI, {"solve", fig8, "--strategy", "pc-crash:mu=-1"}).err);
  CHECK(strategy.err.find(": --strategy[0].mu: ") != std::string::npos);
  const Run format = run_program(IMPACT3D_CLI, {"sensitivity", fig8, "--format", "xml"});
  CHECK(format.status == 2);
  CHECK(format.out.empty());
  const Run missing = run_program(IMPACT3D_CLI, {"sensitivity", "/nonexistent/case.json"});
  CHECK(missing.status == 1);
  CHECK(missing.out.empty());
}

TEST_CASE("the plot option draws a tornado of each vehicle's delta-V per strategy") {
  const fs::path dir = fresh_directory("impact3d-sens");
  const Run r = run_program(IMPACT3D_CLI, {"sensitivity", IMPACT3D_EXAMPLES_DIR "/fig8_side_impact.json", "--plot", dir.string()});
  REQUIRE(r.status == 0);
  for (int k = 0; k < 4; ++k)
    for (int v = 0; v < 2; ++v) CHECK(fs::exists(dir / fmt::format("sens{}_tornado_dv{}.svg", k, v)));
  fs::remove_all(dir);
}

}  // namespace check_sensitivity_cli
