// `solve` with Stronge's strategy as a user runs it, against the contract (../shared/spec/case-format.md,
// extensions of version 2) and against the document's own other numbers: the events in order of p, from
// the slip to the end, the end's p and relative velocity those of the impulse and of the post-impact
// state; friction within Coulomb's cone; the regime `full` exactly when no final sliding direction is
// written; the restitution law energetic when a case omits it; exact and certified arithmetic refuse it
// with one line; the text report shows the events, the swerve and the normal work.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
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
    CHECK(r["integration"]["steps"].get<int>() > 0);
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

}  // namespace check_stronge_cli
