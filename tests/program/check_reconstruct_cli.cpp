// `impact3d reconstruct` (../shared/spec/many-cases.md) as a user runs it, on the bundled evidence for
// Figure 8: the contract's keys; chi2, dof and the p-value from the residuals it prints (chi2 by Boost's
// chi-squared distribution, not the incomplete gamma function the program calls); the fitted values are
// what `solve` prints for the case with the estimated speeds written in. Bad evidence files and options:
// one line naming the file and the field, exit 1 (2 for usage), nothing on stdout.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <boost/math/distributions/chi_squared.hpp>
#include <nlohmann/json.hpp>

#include "cli_process.hpp"

namespace check_reconstruct_cli {

using namespace impact3d::test;
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr double kEps = 0x1p-52;
const std::string kCase = std::string(IMPACT3D_EXAMPLES_DIR) + "/fig8_side_impact.json";
const std::string kEvidence = std::string(IMPACT3D_EXAMPLES_DIR) + "/evidence/fig8_side_impact.json";

fs::path scratch() {
  static const fs::path dir = fresh_directory("impact3d-rec");
  return dir;
}

// The value at a monte_carlo_outputs() path ("vehicles[0].velocity[1]") of one result document.
double at_path(const json& result, const std::string& path) {
  const json* node = &result;
  std::size_t i = 0;
  while (i < path.size()) {
    if (path[i] == '.') ++i;
    if (path[i] == '[') {
      const std::size_t close = path.find(']', i);
      node = &(*node)[std::stoul(path.substr(i + 1, close - i - 1))];
      i = close + 1;
    } else {
      const std::size_t end = path.find_first_of(".[", i);
      node = &(*node)[path.substr(i, end - i)];
      i = end == std::string::npos ? path.size() : end;
    }
  }
  return node->get<double>();
}

}  // namespace

TEST_CASE("Figure 8's evidence: the contract's keys, chi2 from the residuals, and fitted values that solve reproduces") {
  const Run r = run_program(IMPACT3D_CLI, {"reconstruct", kCase, "--evidence", kEvidence, "--strategy", "pc-crash:mu=0.4", "--format", "json"});
  REQUIRE(r.status == 0);
  CHECK(r.err.empty());
  const json d = json::parse(r.out);
  for (const char* key : {"estimates", "correlation", "residuals", "chi2", "dof", "p_value", "regime", "identifiable", "undetermined",
                          "alternatives"})
    CHECK(d.contains(key));
  REQUIRE(d["estimates"].size() == 2);
  CHECK(d["estimates"][0]["unknown"] == json{{"speed", 0}});
  CHECK(d["regime"] == "sliding");
  CHECK(d["identifiable"] == true);
  // chi2 is the sum of the squared standardized residuals, each (fitted - value) / sd.
  double chi2 = 0;
  int components = 0;
  for (const auto& e : d["residuals"]) {
    const double z = e["standardized"].get<double>();
    CHECK(std::fabs(z - (e["fitted"].get<double>() - e["value"].get<double>()) / e["sd"].get<double>()) <= 8 * kEps * std::fabs(z) + 1e-15);
    chi2 += z * z;
    ++components;
  }
  CHECK(components == 10);
  CHECK(d["dof"] == components - 2);
  CHECK(std::fabs(chi2 - d["chi2"].get<double>()) <= 16 * kEps * chi2);
  const boost::math::chi_squared dist(components - 2);
  const double p = boost::math::cdf(boost::math::complement(dist, chi2));
  CHECK(std::fabs(p - d["p_value"].get<double>()) <= 1e-12);  // two routes to Q(dof/2, chi2/2)

  // The case with the estimated speeds along its own directions, solved by `solve`: the fitted values.
  json c = json::parse(slurp(kCase));
  for (int i = 0; i < 2; ++i) {
    auto& v = c["vehicles"][static_cast<std::size_t>(i)]["velocity"];
    const double norm = std::hypot(v[0].get<double>(), v[1].get<double>(), v[2].get<double>());
    const double s = d["estimates"][static_cast<std::size_t>(i)]["value"].get<double>();
    for (int k = 0; k < 3; ++k) v[static_cast<std::size_t>(k)] = v[static_cast<std::size_t>(k)].get<double>() / norm * s;
  }
  const fs::path fitted_case = scratch() / "fitted.json";
  std::ofstream(fitted_case) << c.dump();
  const Run s = run_program(IMPACT3D_CLI, {"solve", fitted_case.string(), "--strategy", "pc-crash:mu=0.4", "--format", "json"});
  REQUIRE(s.status == 0);
  const json result = json::parse(s.out)["results"][0];
  int compared = 0;
  for (const auto& e : d["residuals"]) {
    const double expect = at_path(result, e["output"].get<std::string>());
    // The speeds pass through 17 digits and a division by the direction's norm: a few ulps of 11 m/s,
    // amplified by at most the case's rounding bound into the outputs of order 10 (2^6 eps of 10).
    CHECK(std::fabs(e["fitted"].get<double>() - expect) <= 0x1p6 * kEps * 10);
    ++compared;
  }
  CHECK(compared == 10);
  fs::remove_all(scratch());
}

TEST_CASE("the text report: both speeds with their sd, the test's verdict, and the regime not admitted") {
  const Run r = run_program(IMPACT3D_CLI, {"reconstruct", kCase, "--evidence", kEvidence, "--strategy", "pc-crash:mu=0.4"});
  REQUIRE(r.status == 0);
  CHECK_THAT(r.out, Catch::Contains("regime sliding; chi2 = "));
  CHECK_THAT(r.out, Catch::Contains("(test at 0.01: passed)"));
  CHECK_THAT(r.out, Catch::Contains("speed[0]"));
  CHECK_THAT(r.out, Catch::Contains("not admissible: the full regime's fit"));
}

TEST_CASE("plot: the plan view arrows are the fitted velocities at one scale, and the chi2 surface is least at the fit") {
  const fs::path dir = scratch() / "figures";
  const Run r = run_program(IMPACT3D_CLI, {"reconstruct", kCase, "--evidence", kEvidence, "--strategy", "pc-crash:mu=0.4", "--format",
                                           "json", "--plot", dir.string()});
  REQUIRE(r.status == 0);
  CHECK(fs::exists(dir / "rec_plan.svg"));
  CHECK(fs::exists(dir / "rec_chi2.svg"));
  const json d = json::parse(r.out);
  std::map<std::string, double> fitted;
  for (const auto& e : d["residuals"]) fitted[e["output"].get<std::string>()] = e["fitted"].get<double>();
  // Rows: x y dx dy kind (1 before, 2 after), vehicle by vehicle; every after-arrow is T times the
  // fitted post-impact velocity, with one T for both vehicles.
  std::ifstream arrows(dir / "rec_plan_arrows.dat");
  std::vector<double> scales;
  for (int vehicle = 0; vehicle < 2; ++vehicle)
    for (int row = 0; row < 2; ++row) {
      double x, y, dx, dy, kind;
      REQUIRE(arrows >> x >> y >> dx >> dy >> kind);
      if (kind != 2) continue;
      scales.push_back(dx / fitted.at(fmt::format("vehicles[{}].velocity[0]", vehicle)));
      scales.push_back(dy / fitted.at(fmt::format("vehicles[{}].velocity[1]", vehicle)));
    }
  REQUIRE(scales.size() == 4);
  for (double t : scales) CHECK(std::fabs(t - scales[0]) <= 8 * kEps * scales[0]);  // one product and one quotient each
  // The fit minimizes chi2: no grid point lies below it (beyond rounding), and the centre is the fit.
  std::ifstream grid(dir / "rec_chi2.dat");
  const double best = d["chi2"].get<double>();
  double least = INFINITY;
  int points = 0;
  for (double a, b, z; grid >> a >> b >> z; ++points) least = std::min(least, z);
  CHECK(points == 41 * 41);
  CHECK(least >= best * (1 - 1e-9));
  CHECK(least <= best * (1 + 1e-9));  // the centre point is the fit itself
  fs::remove_all(dir);
}

TEST_CASE("bad evidence files and options: one line naming the file and the field, nothing on stdout") {
  const fs::path dir = scratch();
  struct Bad {
    std::string file, message;
  };
  const std::string speeds = R"("unknowns": [{"speed": 0}, {"speed": 1}])";
  const std::string velocity = R"("evidence": [{"output": "vehicles[0].velocity", "value": [8, 7, 0], "sd": 0.3}])";
  const std::vector<Bad> bad = {
      {"[]", "$: must be an object"},
      {"{\"unknowns\": [", "$"},
      {"{" + velocity + "}", "$: missing \"unknowns\""},
      {"{" + speeds + "}", "$: missing \"evidence\""},
      {R"({"unknowns": [], )" + velocity + "}", "$.unknowns: must name at least one unknown"},
      {R"({"unknowns": [{"speed": 2}], )" + velocity + "}", "$.unknowns[0].speed: must be from 0 to 1 (got 2)"},
      {R"({"unknowns": [{"speed": 0, "path": "$.restitution"}], )" + velocity + "}",
       "$.unknowns[0]: must name exactly one of \"speed\" (a vehicle), \"heading\" (a vehicle) or \"path\" (an input of the case)"},
      {R"({"unknowns": [{"speed": 0}, {"speed": 0}], )" + velocity + "}", "$.unknowns[1]: \"speed[0]\" is an unknown twice"},
      {R"({"unknowns": [{"speed": 0, "start": "fast"}], )" + velocity + "}", "$.unknowns[0].start: must be a finite number"},
      {R"({"unknowns": [{"speed": 0, "colour": 1}], )" + velocity + "}", "$.unknowns[0]: unknown key \"colour\""},
      {R"({"unknowns": [{"path": "$.vehicles[3].mass"}], )" + velocity + "}", "$.unknowns[0].path: \"$.vehicles[3].mass\""},
      {R"({"unknowns": [{"path": "$.vehicles[0].velocity[1]"}, {"speed": 0}], )" + velocity + "}",
       "$.unknowns[0].path: moves vehicle 0's velocity, which its speed or heading unknown already moves"},
      {R"({"unknowns": [{"path": "$.strategy[0].mu"}], )" + velocity + "}",
       "$.unknowns[0].path: names an input of the case's strategy, which --strategy replaces"},
      {"{" + speeds + R"(, "evidence": [{"output": "vehicles[0].colour", "value": 1, "sd": 1}]})",
       "$.evidence[0].output: \"vehicles[0].colour\" is not an output of a result"},
      {"{" + speeds + R"(, "evidence": [{"output": "vehicles[0].velocity", "value": 8, "sd": 1}]})",
       "$.evidence[0].value: must be an array of 3 numbers, one per component"},
      {"{" + speeds + R"(, "evidence": [{"output": "vehicles[0].velocity", "value": [8, 7, 0], "sd": [1, 0, 1]}]})",
       "$.evidence[0].sd[1]: must be at least 1e-12 (got 0)"},
      {"{" + speeds + R"(, "evidence": [{"output": "vehicles[0].speed_after", "value": 1e400, "sd": 1}]})",
       "$.evidence[0].value: not a finite number (1e400)"},
      {"{" + speeds + R"(, "evidence": [{"output": "vehicles[0].speed_after", "value": 1e13, "sd": 1}]})",
       "$.evidence[0].value: must be a finite number of magnitude at most 1e12 (got 1e13)"},
      {"{" + speeds + R"(, "evidence": [{"output": "limits.gir", "value": 0.5, "sd": 0.1}]})",
       "$.evidence[0].output: the result has no \"limits.gir\" here"},
      {"{" + speeds + R"(, "evidence": [{"speed": 0, "output": "energy.loss", "value": 1, "sd": 1}]})",
       "$.evidence[0]: must name exactly one of \"output\""},
      {R"({"unknowns": [{"speed": 1, "start": -20}], )" + velocity + "}",
       "$.unknowns: the case has no solution at the unknowns' starting values (speed[1] = -20): $.vehicles: not approaching"},
  };
  int checked = 0;
  for (std::size_t i = 0; i < bad.size(); ++i) {
    const fs::path e = dir / fmt::format("bad{}.json", i);
    std::ofstream(e) << bad[i].file;
    // brach has no GIR: the one item above that needs it.
    const std::string strategy = bad[i].message.find("limits.gir") != std::string::npos ? "brach:mu_t=critical,mu_z=critical" : "pc-crash:mu=0.4";
    const Run r = run_program(IMPACT3D_CLI, {"reconstruct", kCase, "--evidence", e.string(), "--strategy", strategy});
    INFO(bad[i].file);
    CHECK(r.status == 1);
    CHECK(r.out.empty());
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK_THAT(r.err, Catch::StartsWith("impact3d: error: " + e.string() + ": " + bad[i].message));
    ++checked;
  }
  CHECK(checked == 21);
  // The case's problems name the case: four strategies and no --strategy.
  const Run many = run_program(IMPACT3D_CLI, {"reconstruct", kCase, "--evidence", kEvidence});
  CHECK(many.status == 1);
  CHECK(many.out.empty());
  CHECK(many.err == "impact3d: error: " + kCase + ": $.strategy: holds 4 strategies: a reconstruction fits one (give it with --strategy)\n");
  const Run option = run_program(IMPACT3D_CLI, {"reconstruct", kCase, "--evidence", kEvidence, "--strategy", "pc-crash:mu=x"});
  CHECK(option.status == 1);
  CHECK(option.out.empty());
  CHECK_THAT(option.err, Catch::StartsWith("impact3d: error: --strategy"));
  const Run usage = run_program(IMPACT3D_CLI, {"reconstruct", kCase});
  CHECK(usage.status == 2);
  CHECK(usage.out.empty());
  fs::remove_all(dir);
}

}  // namespace check_reconstruct_cli
