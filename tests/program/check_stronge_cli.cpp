// `solve` with Stronge's strategy as a user runs it, against the contract (../shared/spec/case-format.md,
// extensions of version 2) and against the document's own other numbers: the events in order of p, from
// the slip to the end, the end's p and relative velocity those of the impulse and of the post-impact
// state; friction within Coulomb's cone; the regime `full` exactly when no final sliding direction is
// written; the restitution law energetic when a case omits it; exact and certified arithmetic refuse it
// with one line; the text report shows the events, the swerve and the normal work; `plot` draws the
// hodograph, V_n and the normal work against p and the impulse path from the numbers `solve` writes.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <nlohmann/json.hpp>

#include "cli_process.hpp"

namespace check_stronge_cli {

using namespace impact3d::test;
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr double kEps = 0x1p-52;
const std::string kCase = IMPACT3D_EXAMPLES_DIR "/fig8_side_impact.json";

fs::path scratch() {
  static const fs::path dir = fresh_directory("impact3d-stronge");
  return dir;
}

double norm(const json& v) { return std::hypot(v[0].get<double>(), v[1].get<double>(), v[2].get<double>()); }

std::string fmt_name(const char* stem, std::size_t k, const char* suffix) { return stem + std::to_string(k + 1) + suffix; }

}  // namespace

TEST_CASE("stronge's result: the contract's keys, its events, Coulomb's cone, the regime rule") {
  const Run run = run_program(IMPACT3D_CLI, {"solve", kCase, "--format", "json", "--strategy", "stronge:mu=0.4",
                                             "--strategy", "stronge:mu=0.9,restitution=newton", "--strategy",
                                             "stronge:mu=0.4,restitution=poisson"});
  REQUIRE(run.status == 0);
  CHECK(run.err.empty());
  const json doc = json::parse(run.out);
  REQUIRE(doc["results"].size() == 3);
  const char* const laws[] = {"energetic", "newton", "poisson"};
  int checked = 0;
  for (std::size_t k = 0; k < 3; ++k) {
    const json& r = doc["results"][k];
    INFO("result " << k);
    CHECK(r["strategy"]["name"] == "stronge");
    CHECK(r["strategy"]["restitution"] == laws[k]);
    const json& events = r["events"];
    REQUIRE(events.size() >= 3);
    CHECK(events.front()["kind"] == "slip");  // Figure 8 slides at first
    CHECK(events.back()["kind"] == "end");
    int compression_ends = 0;
    for (std::size_t i = 0; i < events.size(); ++i) {
      for (const char* key : {"kind", "p", "relative_velocity", "normal_work"}) CHECK(events[i].contains(key));
      if (i > 0) CHECK(events[i]["p"].get<double>() >= events[i - 1]["p"].get<double>());
      compression_ends += events[i]["kind"] == "compression end";
    }
    CHECK(compression_ends == 1);
    // The end's p is the impulse's normal component, both x m' |V_ri| of the same number; its velocity
    // is the integration's, the document's "after" the post-impact states': a few roundings of the case's
    // speeds apart.
    const json& P = r["impulse"]["contact"];
    CHECK(events.back()["p"].get<double>() == P[0].get<double>());
    const json& after = r["relative_velocity"]["after"];
    const double speed = norm(r["relative_velocity"]["before"]);
    for (int j = 0; j < 3; ++j)
      CHECK(std::fabs(events.back()["relative_velocity"][j].get<double>() - after[j].get<double>()) <= 64 * kEps * speed);
    const double mu = r["strategy"]["mu"].get<double>();
    CHECK(std::hypot(P[1].get<double>(), P[2].get<double>()) <= mu * P[0].get<double>() * (1 + 8 * kEps));
    CHECK(r["swerve_deg"].get<double>() >= 0);
    CHECK((r["regime"] == "full") == r["final_direction_deg"].is_null());
    CHECK(r["normal_work"]["compression"].get<double>() > 0);
    CHECK(r["normal_work"]["restitution"].get<double>() >= 0);
    // At mu = 0.9 the slide comes to rest within reach of its invariant direction from the start: all of
    // it in closed form (stop_series.hpp), no Taylor step; at 0.4 it slides throughout.
    CHECK((r["integration"]["steps"].get<int>() > 0) == (k != 1));
    CHECK(r["integration"]["error_bound"].get<double>() < 1e-6);
    ++checked;
  }
  CHECK(checked == 3);
  // mu = 0.9 holds Figure 8's contact: it sticks, and the impulse lies inside the cone.
  CHECK(doc["results"][1]["regime"] == "full");
}

TEST_CASE("a case naming stronge without a law integrates by the energetic law") {
  json c = json::parse(slurp(kCase));
  c["strategy"] = json::array({json{{"name", "stronge"}, {"mu", 0.4}}});
  const fs::path file = scratch() / "stronge_default.json";
  std::ofstream(file) << c.dump(2);
  const Run omitted = run_program(IMPACT3D_CLI, {"solve", file.string(), "--format", "json"});
  const Run named = run_program(IMPACT3D_CLI, {"solve", kCase, "--format", "json", "--strategy",
                                               "stronge:mu=0.4,restitution=energetic"});
  REQUIRE(omitted.status == 0);
  REQUIRE(named.status == 0);
  const json a = json::parse(omitted.out)["results"][0], b = json::parse(named.out)["results"][0];
  CHECK(a["strategy"]["restitution"] == "energetic");
  CHECK(a["impulse"] == b["impulse"]);
  CHECK(a["events"] == b["events"]);
}

TEST_CASE("exact and certified arithmetic refuse stronge with one line; bad laws are named") {
  for (const char* precision : {"exact", "certified"}) {
    const Run run = run_program(IMPACT3D_CLI, {"solve", kCase, "--precision", precision, "--strategy", "stronge:mu=0.4"});
    INFO(precision << ": " << run.err);
    CHECK(run.status == 1);
    CHECK(run.out.empty());
    CHECK(run.err.find("stronge has no exact or certified form") != std::string::npos);
    CHECK(std::count(run.err.begin(), run.err.end(), '\n') == 1);
  }
  const Run bad = run_program(IMPACT3D_CLI, {"solve", kCase, "--strategy", "stronge:mu=0.4,restitution=kane"});
  CHECK(bad.status == 1);
  CHECK(bad.out.empty());
  CHECK(bad.err.find(R"(expected "energetic", "poisson" or "newton")") != std::string::npos);
}

TEST_CASE("the text report shows stronge's events, swerve and normal work") {
  const Run run = run_program(IMPACT3D_CLI, {"solve", kCase, "--strategy", "stronge:mu=0.9"});
  REQUIRE(run.status == 0);
  for (const char* line : {"events: p [N s], V_n, sliding [m/s]", "slip", "stick", "compression end",
                           "swerve during the impact [deg]", "sliding direction at the end [deg]        - (sticks)",
                           "normal work: compression, restitution [J]", "integration: steps, error bound"})
    CHECK(run.out.find(line) != std::string::npos);
}

// The figures' numbers against `solve --format json` of the same case: both print doubles to 17 digits,
// which read back exactly, from one computation; 4 eps of the value for a unit factor applied once more.
// The path's last point is the end state by one formula's operations in another order: 8 eps of |V_ri|.
TEST_CASE("plot draws stronge's hodograph, normal history and impulse path from solve's numbers", "[plot]") {
  const std::string example = IMPACT3D_EXAMPLES_DIR "/stronge/fig8_through_the_impact.json";
  const fs::path out = scratch() / "plot";
  const Run plot = run_program(IMPACT3D_CLI, {"plot", example, "-o", out.string()});
  REQUIRE(plot.status == 0);
  CHECK(plot.err.empty());
  const Run solved = run_program(IMPACT3D_CLI, {"solve", example, "--format", "json"});
  REQUIRE(solved.status == 0);
  const json results = json::parse(solved.out)["results"];
  const auto near = [](double a, double b, double scale) { return std::fabs(a - b) <= 4 * kEps * scale; };
  int drawn = 0;
  for (std::size_t k = 0; k < results.size(); ++k) {
    const json& r = results[k];
    const bool integrated = r["strategy"]["name"] == "stronge";
    INFO("result " << k + 1);
    for (const char* f : {"stronge_hodograph_", "stronge_normal_", "stronge_impulse_path_"}) {
      const fs::path svg = out / (f + std::to_string(k + 1) + ".svg");
      CHECK(fs::exists(svg) == integrated);
      if (integrated) CHECK(slurp(svg).find("</svg>") != std::string::npos);
    }
    if (!integrated) continue;
    const json& events = r["events"];
    const auto rows = labelled_rows(slurp(out / fmt_name("stronge_normal_", k, ".events.csv")));
    REQUIRE(rows.size() == events.size());
    const double work = r["normal_work"]["compression"].get<double>();
    for (std::size_t i = 0; i < rows.size(); ++i) {
      CHECK(rows[i].first == events[i]["kind"].get<std::string>());
      CHECK(near(rows[i].second[0], events[i]["p"].get<double>(), events.back()["p"].get<double>()));
      CHECK(near(rows[i].second[1], events[i]["relative_velocity"][0].get<double>(), norm(events[0]["relative_velocity"])));
      CHECK(near(rows[i].second[2], events[i]["normal_work"].get<double>(), work));
    }
    // The impulse path's points: the Full Impact, then every strategy's impulse (P_n, P_t, P_z), then the
    // events on the path.
    const auto pts = labelled_rows(slurp(out / fmt_name("stronge_impulse_path_", k, ".points.csv")));
    REQUIRE(pts.size() == 1 + results.size() + events.size());
    CHECK(pts[0].first == "Full Impact");
    for (std::size_t m = 0; m < results.size(); ++m) {
      const json& P = results[m]["impulse"]["contact"];
      for (int j = 0; j < 3; ++j) CHECK(near(pts[1 + m].second[j], P[j].get<double>(), norm(P)));
    }
    CHECK(near(pts.back().second[0], r["impulse"]["contact"][0].get<double>(), norm(r["impulse"]["contact"])));
    // The hodograph runs from the sliding velocity before to the one at the end.
    const std::string dat = slurp(out / fmt_name("stronge_hodograph_", k, ".dat"));
    const auto first = labelled_rows("V_t,V_z\nx," + dat.substr(0, dat.find('\n')));
    std::string last_line = dat.substr(0, dat.find("\n\n"));
    last_line = last_line.substr(last_line.rfind('\n') + 1);
    const auto last = labelled_rows("V_t,V_z\nx," + last_line);
    const double speed = norm(events[0]["relative_velocity"]);
    const json& before = events.front()["relative_velocity"];
    const json& end = events.back()["relative_velocity"];
    CHECK(near(first[0].second[0], before[1].get<double>(), speed));
    CHECK(near(first[0].second[1], before[2].get<double>(), speed));
    CHECK(std::fabs(last[0].second[0] - end[1].get<double>()) <= 8 * kEps * speed);
    CHECK(std::fabs(last[0].second[1] - end[2].get<double>()) <= 8 * kEps * speed);
    ++drawn;
  }
  CHECK(drawn == 3);  // the example's three stronge strategies
}

// batch's scalar path for stronge: every row's results are solve's for the same case and strategies,
// to the last digit (one computation, one writer), on two threads.
TEST_CASE("batch integrates stronge as solve does, row by row", "[batch]") {
  json c = json::parse(slurp(kCase));
  std::string lines;
  for (const double speed : {11.176, 13.4112, 8.9408}) {
    c["vehicles"][0]["velocity"][0] = speed;
    lines += c.dump() + "\n";
  }
  const fs::path rows = scratch() / "stronge_rows.jsonl";
  std::ofstream(rows) << lines;
  const std::vector<std::string> strategies{"--strategy", "stronge:mu=0.4", "--strategy", "stronge:mu=0.9,restitution=newton"};
  std::vector<std::string> args{"batch", rows.string(), "--jobs", "2"};
  args.insert(args.end(), strategies.begin(), strategies.end());
  const Run batch = run_program(IMPACT3D_CLI, args);
  REQUIRE(batch.status == 0);
  std::istringstream out(batch.out);
  std::string line;
  int checked = 0;
  for (const double speed : {11.176, 13.4112, 8.9408}) {
    REQUIRE(std::getline(out, line));
    c["vehicles"][0]["velocity"][0] = speed;
    const fs::path one = scratch() / "stronge_row.json";
    std::ofstream(one) << c.dump();
    std::vector<std::string> solve_args{"solve", one.string(), "--format", "json"};
    solve_args.insert(solve_args.end(), strategies.begin(), strategies.end());
    const Run solved = run_program(IMPACT3D_CLI, solve_args);
    REQUIRE(solved.status == 0);
    const json a = json::parse(line)["results"], b = json::parse(solved.out)["results"];
    REQUIRE(a.size() == 2);
    for (std::size_t k = 0; k < 2; ++k) {
      CHECK(a[k]["impulse"] == b[k]["impulse"]);
      CHECK(a[k]["events"] == b[k]["events"]);
      CHECK(a[k]["swerve_deg"] == b[k]["swerve_deg"]);
      CHECK(a[k]["integration"] == b[k]["integration"]);
      ++checked;
    }
  }
  CHECK(checked == 6);
}

}  // namespace check_stronge_cli
