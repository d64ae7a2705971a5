// `impact3d montecarlo` (../shared/spec/many-cases.md) as a user runs it: on the bundled Figure 8 case
// and its uncertainty file, the JSON has the contract's keys and summarizes at least every number the
// contract names, checked against the keys of `solve`'s own document for the case; the same seed gives
// the same bytes at --jobs 1 and 2; --samples-out writes a row per sample; bad uncertainty files and
// options get one line naming the field, exit 1 (2 for usage), and nothing on standard output.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "cli_process.hpp"

namespace check_montecarlo_cli {

using namespace impact3d::test;
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

const std::string kCase = IMPACT3D_EXAMPLES_DIR "/fig8_side_impact.json";
const std::string kUncertainty = IMPACT3D_EXAMPLES_DIR "/uncertainty/fig8_side_impact.json";

fs::path scratch() {
  static const fs::path dir = fresh_directory("impact3d-mc");
  return dir;
}

// Every number's path inside one result of a solve document, under the groups the contract names.
void numbers(const json& v, const std::string& path, std::set<std::string>& out) {
  if (v.is_number()) out.insert(path);
  else if (v.is_object())
    for (auto it = v.begin(); it != v.end(); ++it) numbers(it.value(), path.empty() ? it.key() : path + "." + it.key(), out);
  else if (v.is_array())
    for (std::size_t i = 0; i < v.size(); ++i) numbers(v[i], fmt::format("{}[{}]", path, i), out);
}

}  // namespace

TEST_CASE("the Figure 8 Monte Carlo: the contract's JSON, the same bytes at any --jobs") {
  const Run one = run_program(IMPACT3D_CLI, {"montecarlo", kCase, "--uncertainty", kUncertainty, "--samples", "3000",
                                             "--format", "json", "--jobs", "1"});
  REQUIRE(one.status == 0);
  CHECK(one.err.empty());  // no progress display when standard error is not a terminal
  const Run two = run_program(IMPACT3D_CLI, {"montecarlo", kCase, "--uncertainty", kUncertainty, "--samples", "3000",
                                             "--format", "json", "--jobs", "2"});
  REQUIRE(two.status == 0);
  CHECK(two.out == one.out);
  const json doc = json::parse(one.out);
  CHECK(doc["samples"] == 3000);
  CHECK(doc["seed"] == 42);
  const Run solved = run_program(IMPACT3D_CLI, {"solve", kCase, "--format", "json"});
  REQUIRE(solved.status == 0);
  const json reference = json::parse(solved.out);
  REQUIRE(doc["results"].size() == reference["results"].size());
  std::size_t checked = 0;
  for (std::size_t k = 0; k < doc["results"].size(); ++k) {
    const json& r = doc["results"][k];
    INFO("result " << k);
    CHECK(r["strategy"] == reference["results"][k]["strategy"]);
    std::uint64_t rejected = 0;
    for (const auto& [reason, count] : r["rejected"].items()) rejected += count.get<std::uint64_t>();
    CHECK(r["solved"].get<std::uint64_t>() + rejected == 3000);
    double regimes = 0;
    for (const auto& [name, p] : r["regime_probability"].items()) regimes += p.get<double>();
    CHECK(std::fabs(regimes - 1) <= 1e-15);  // every solved sample has a regime
    CHECK(r["warning_probability"].contains("tensile normal impulse"));
    // Every number the contract names is summarized, with every percentile.
    std::set<std::string> wanted;
    const json& result = reference["results"][k];
    for (const char* group : {"impulse", "sliding", "energy"}) numbers(result[group], group, wanted);
    // The energy split's shares echo the case's input, not a computed number.
    std::erase_if(wanted, [](const std::string& p) { return p.starts_with("energy.split."); });
    numbers(result["relative_velocity"]["after"], "relative_velocity.after", wanted);
    for (int v = 0; v < 2; ++v)
      for (const char* key : {"velocity", "angular_velocity", "delta_v", "delta_v_magnitude", "pdof_deg", "delta_v_vehicle",
                              "speed_after", "heading_after_deg", "yaw_rate_after", "deformation_energy", "ees"})
        numbers(result["vehicles"][v][key], fmt::format("vehicles[{}].{}", v, key), wanted);
    REQUIRE(wanted.size() >= 30);
    for (const auto& path : wanted) {
      INFO(path);
      REQUIRE(r["outputs"].contains(path));
      const json& o = r["outputs"][path];
      for (const char* p : {"1", "2.5", "5", "25", "50", "75", "95", "97.5", "99"}) {
        CHECK(o["percentiles"].contains(p));
        CHECK(o["percentile_se"].contains(p));
      }
      CHECK(o.contains("mean"));
      CHECK(o.contains("sd"));
      ++checked;
    }
  }
  CHECK(checked >= 120);
  CHECK(doc["results"][0]["outputs"]["vehicles[1].pdof_deg"]["angle"] == "[0, 360)");
}

// At 100 digits every thread leaves MPFR's caches (pi, the arctangent's tables) behind unless it frees
// them before it ends (scalar/thread_caches.hpp); the sanitizer run of this case sees any it loses.
TEST_CASE("at 100 digits the same bytes on one thread and on two, the samples shared between them") {
  std::string out[2];
  for (int jobs = 1; jobs <= 2; ++jobs) {
    const Run r = run_program(IMPACT3D_CLI, {"montecarlo", kCase, "--uncertainty", kUncertainty, "--samples", "300",
                                             "--precision", "100", "--format", "json", "--jobs", std::to_string(jobs)},
                              "", "", 120);
    REQUIRE(r.status == 0);
    out[jobs - 1] = r.out;
  }
  CHECK(out[1] == out[0]);
  CHECK(json::parse(out[0])["precision"] == "100");
  CHECK(json::parse(out[0])["samples"] == 300);  // five chunks of 64: both threads take some
}

TEST_CASE("every sample is written by --samples-out, and the text report fits 80 columns") {
  const fs::path csv = scratch() / "samples.csv";
  const Run r = run_program(IMPACT3D_CLI, {"montecarlo", kCase, "--uncertainty", kUncertainty, "--samples", "500",
                                           "--samples-out", csv.string()});
  REQUIRE(r.status == 0);
  CHECK(r.out.rfind("Monte Carlo: 500 samples, seed 42", 0) == 0);
  std::size_t lines = 0, widest = 0;
  for (std::size_t at = 0, end; at < r.out.size(); at = end + 1) {
    end = r.out.find('\n', at);
    widest = std::max(widest, end - at);
    ++lines;
  }
  CHECK(lines > 50);
  CHECK(widest <= 80);
  std::ifstream in(csv);
  std::string line;
  std::size_t rows = 0;
  std::getline(in, line);
  CHECK(line.rfind("sample,$.vehicles[0].velocity[0],$.vehicles[1].velocity[1],", 0) == 0);
  CHECK(line.find(",results[0].regime,results[0].rejected,") != std::string::npos);
  const auto columns = std::count(line.begin(), line.end(), ',');
  while (std::getline(in, line)) {
    CHECK(std::count(line.begin(), line.end(), ',') == columns);
    CHECK(line.rfind(std::to_string(rows) + ",", 0) == 0);
    ++rows;
  }
  CHECK(rows == 500);
}

TEST_CASE("bad uncertainty files and options: one line naming the field, nothing on stdout") {
  const fs::path dir = scratch();
  struct Bad {
    std::string file, message;
  };
  const std::vector<Bad> bad = {
      {R"({"inputs": [{"path": "$.vehicles[3].mass", "distribution": "uniform", "min": 1, "max": 2}]})",
       "$.inputs[0].path: \"$.vehicles[3].mass\" is no field of the case"},
      {R"({"inputs": [{"path": "$.restitution", "distribution": "normal", "mean": 0.1, "sd": -1}]})", "$.inputs[0].sd"},
      {R"({"inputs": [{"path": "$.restitution", "distribution": "uniform", "min": 0.2, "max": 0.1}]})", "$.inputs[0]"},
      {R"({"inputs": [{"path": "$.vehicles[0].mass", "distribution": "normal", "mean": 1500, "sd": 60}]})",
       "$.inputs[0].distribution: a normal is not bounded below"},
      {R"({"inputs": [{"path": "$.restitution", "distribution": "uniform", "min": 0.1, "max": 0.2},
                      {"path": "$.vehicles[0].mass", "distribution": "uniform", "min": 1500, "max": 1600},
                      {"path": "$.vehicles[1].mass", "distribution": "uniform", "min": 2500, "max": 2600}],
          "correlations": [{"paths": ["$.restitution", "$.vehicles[0].mass"], "rho": 0.9},
                           {"paths": ["$.restitution", "$.vehicles[1].mass"], "rho": 0.9},
                           {"paths": ["$.vehicles[0].mass", "$.vehicles[1].mass"], "rho": -0.9}]})",
       "$.correlations"},
      {"{\"inputs\": [", "$"},
  };
  int checked = 0;
  for (std::size_t i = 0; i < bad.size(); ++i) {
    const fs::path u = dir / fmt::format("bad{}.json", i);
    std::ofstream(u) << bad[i].file;
    const Run r = run_program(IMPACT3D_CLI, {"montecarlo", kCase, "--uncertainty", u.string()});
    INFO(bad[i].file);
    CHECK(r.status == 1);
    CHECK(r.out.empty());
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK_THAT(r.err, Catch::StartsWith("impact3d: error: " + u.string() + ": " + bad[i].message));
    ++checked;
  }
  CHECK(checked == 6);
  // A bad case names the case file; options out of range are usage errors.
  const fs::path bad_case = dir / "case.json";
  std::ofstream(bad_case) << "{}";
  const Run c = run_program(IMPACT3D_CLI, {"montecarlo", bad_case.string(), "--uncertainty", kUncertainty});
  CHECK(c.status == 1);
  CHECK(c.out.empty());
  CHECK_THAT(c.err, Catch::StartsWith("impact3d: error: " + bad_case.string() + ": $"));
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"--samples", "0"}, {"--samples", "10000001"}, {"--precision", "exact"}, {"--jobs", "0"},
        {"--seed", "-1"}, {"--seed", "18446744073709551616"}, {"--seed", "1e3"}, {"--seed", ""}}) {
    std::vector<std::string> all = {"montecarlo", kCase, "--uncertainty", kUncertainty};
    all.insert(all.end(), args.begin(), args.end());
    const Run u = run_program(IMPACT3D_CLI, all);
    INFO(args[0] << " " << args[1]);
    CHECK(u.status == 2);
    CHECK(u.out.empty());
  }
  const Run unwritable = run_program(IMPACT3D_CLI, {"montecarlo", kCase, "--uncertainty", kUncertainty, "--samples", "10",
                                                    "--samples-out", (dir / "no" / "such" / "dir.csv").string()});
  CHECK(unwritable.status == 1);
  CHECK(unwritable.out.empty());
  CHECK(unwritable.err == "impact3d: error: --samples-out: " + (dir / "no" / "such" / "dir.csv").string() +
                              ": cannot write the file: its directory cannot be opened (No such file or directory)\n");
  fs::remove_all(dir);
}

TEST_CASE("a run that cannot solve a sample is refused up front, one that solved none fails, one that solved few warns") {
  const fs::path dir = scratch();
  const auto run_with = [&](const std::string& name, const std::string& file, std::vector<std::string> more = {}) {
    const fs::path u = dir / name;
    std::ofstream(u) << file;
    std::vector<std::string> args = {"montecarlo", kCase, "--uncertainty", u.string()};
    args.insert(args.end(), more.begin(), more.end());
    return std::make_pair(u.string(), run_program(IMPACT3D_CLI, args));
  };
  // An off-diagonal inertia entry varied alone is never symmetric: refused before any sample.
  const auto [u1, alone] = run_with("inertia.json", R"({"samples": 50, "inputs": [{"path": "$.vehicles[0].inertia[0][1]", "distribution": "uniform", "min": 10, "max": 20}]})");
  CHECK(alone.status == 1);
  CHECK(alone.out.empty());
  CHECK(alone.err == "impact3d: error: " + u1 +
                         ": $.inputs[0].distribution: the uniform reaches 10 at its lower end, where the case refuses it, and no "
                         "other input varies $.vehicles[0].inertia: $.vehicles[0].inertia: not symmetric: [0][1] = 10 but [1][0] = 0\n");
  // With its transpose varied too, the samples may meet the rule: the run is the samples' to judge.
  const auto [u2, both] = run_with("inertia_pair.json", R"({"samples": 20, "inputs": [
      {"path": "$.vehicles[0].inertia[0][1]", "distribution": "uniform", "min": 10, "max": 20},
      {"path": "$.vehicles[0].inertia[1][0]", "distribution": "uniform", "min": 10, "max": 20}]})");
  CHECK(both.status == 1);
  CHECK_THAT(both.err, Catch::StartsWith("impact3d: error: " + u2 + ": $: pc-crash mu=1.0 solved none of the 20 samples: 20 of them are refused (invalid $.vehicles[0].inertia)"));
  // The second vehicle driving away: no sample approaches, and the run fails naming that.
  const auto [u3, away] = run_with("away.json", R"({"samples": 50, "inputs": [{"path": "$.vehicles[1].velocity[1]", "distribution": "uniform", "min": -30, "max": -20}]})");
  CHECK(away.status == 1);
  CHECK(away.out.empty());
  CHECK(std::count(away.err.begin(), away.err.end(), '\n') == 1);
  CHECK_THAT(away.err, Catch::StartsWith("impact3d: error: " + u3 + ": $: pc-crash mu=1.0 solved none of the 50 samples: 50 of them do not approach, the first (sample 0): $.vehicles: not approaching"));
  // Fewer than half approach: the run succeeds, and says per strategy that its summary is of those.
  const auto [u4, few] = run_with("few.json", R"({"samples": 200, "inputs": [{"path": "$.vehicles[1].velocity[1]", "distribution": "uniform", "min": -10, "max": 4}]})");
  CHECK(few.status == 0);
  const auto solved = nlohmann::json::parse(run_program(IMPACT3D_CLI, {"montecarlo", kCase, "--uncertainty", u4, "--format", "json"}).out)["results"][0]["solved"].get<int>();
  CHECK(solved < 100);
  CHECK(std::count(few.err.begin(), few.err.end(), '\n') == 4);  // the case's four strategies
  CHECK_THAT(few.err, Catch::StartsWith(fmt::format("impact3d: warning: montecarlo: pc-crash mu=1.0 solved {} of 200 samples (the commonest rejection: not approaching, {})", solved, 200 - solved)));
  fs::remove_all(dir);
}

TEST_CASE("a seed and a sample count are read in decimal: 010 is ten, not octal eight") {
  const Run r = run_program(IMPACT3D_CLI, {"montecarlo", kCase, "--uncertainty", kUncertainty, "--samples", "010", "--seed", "010",
                                           "--format", "json"});
  REQUIRE(r.status == 0);
  const auto doc = nlohmann::json::parse(r.out);
  CHECK(doc["samples"] == 10);
  CHECK(doc["seed"] == 10);
}

TEST_CASE("a run is sized before it starts: one past the memory limit is refused, saying how to fit") {
  // 1.1e6 samples of four strategies: within the samples' limit, but 2464 bytes a sample (71 outputs
  // of 8 bytes a strategy, 48 on each of the 4 summaries' threads) is 2585 MiB, past the 2048 a run may
  // take. Run within 512 MiB of address space: refused before anything is allocated.
  const fs::path dir = scratch();
  const fs::path u = dir / "u.json";
  std::ofstream(u) << R"({"inputs": [{"path": "$.vehicles[1].velocity[1]", "distribution": "uniform", "min": 10, "max": 12}]})";
  const Run r = run_program(IMPACT3D_CLI, {"montecarlo", kCase, "--uncertainty", u.string(), "--samples", "1100000", "--strategy",
                                           "pc-crash:mu=0.4", "--strategy", "wach:mu=0.4", "--strategy", "brach:mu_t=critical,mu_z=0", "--strategy", "pc-crash:mu=1"},
                            "", "", 20, 512);
  CHECK(r.status == 1);
  CHECK(r.out.empty());
  CHECK(r.err == "impact3d: error: --samples: 1100000 samples of 4 results would take 2585 MiB (2464 bytes a sample), more than "
                 "the 2048 MiB a run may take: every output of every sample is kept for the percentiles; take at most 871543 "
                 "samples, or fewer strategies\n");
  fs::remove_all(dir);
}

TEST_CASE("the figures draw the run's own numbers: histogram counts and percentile marks") {
  const fs::path dir = scratch() / "figures";
  const fs::path u = scratch() / "two_inputs.json";
  std::ofstream(u) << R"({"seed": 3, "inputs": [
      {"path": "$.vehicles[1].velocity[1]", "distribution": "normal", "mean": 11.176, "sd": 0.9},
      {"path": "$.restitution", "distribution": "uniform", "min": 0.05, "max": 0.2}]})";
  const Run r = run_program(IMPACT3D_CLI, {"montecarlo", kCase, "--uncertainty", u.string(), "--samples", "1000", "--format", "json",
                                           "--strategy", "pc-crash:mu=0.4", "--plot", dir.string()});
  REQUIRE(r.status == 0);
  const json doc = json::parse(r.out);
  const json& result = doc["results"][0];
  int checked = 0;
  for (const auto& [slug, path] : std::vector<std::pair<std::string, std::string>>{
           {"vehicles_0_delta_v_magnitude", "vehicles[0].delta_v_magnitude"},
           {"vehicles_1_delta_v_magnitude", "vehicles[1].delta_v_magnitude"},
           {"energy_loss", "energy.loss"}}) {
    INFO(path);
    const std::string name = "mc0_hist_" + slug;
    REQUIRE(fs::exists(dir / (name + ".svg")));
    // The bars hold every solved sample once.
    std::ifstream dat(dir / (name + ".dat"));
    std::string line;
    std::uint64_t total = 0;
    while (std::getline(dat, line)) total += std::stoull(line.substr(line.find(',') + 1));
    CHECK(total == result["outputs"][path]["count"].get<std::uint64_t>());
    // The marks stand at the summary's 2.5, 50 and 97.5 percentiles (17 digits: the same doubles).
    const std::string script = slurp(dir / (name + ".gp"));
    std::vector<double> marks;
    for (std::size_t at = 0; (at = script.find("set arrow from ", at)) != std::string::npos; at += 15)
      marks.push_back(std::stod(script.substr(at + 15)));
    REQUIRE(marks.size() == 3);
    CHECK(marks[0] == result["outputs"][path]["percentiles"]["2.5"].get<double>());
    CHECK(marks[1] == result["outputs"][path]["percentiles"]["50"].get<double>());
    CHECK(marks[2] == result["outputs"][path]["percentiles"]["97.5"].get<double>());
    ++checked;
  }
  CHECK(checked == 3);
  CHECK(fs::exists(dir / "mc0_scatter.svg"));
  for (int j = 0; j < 2; ++j) CHECK(fs::exists(dir / fmt::format("mc0_dv_vs_input{}.svg", j)));
  const Run bad = run_program(IMPACT3D_CLI, {"montecarlo", kCase, "--uncertainty", kUncertainty, "--plot", dir.string(), "--scatter",
                                             "energy.loss", "vehicles[2].pdof_deg"});
  CHECK(bad.status == 1);
  CHECK(bad.out.empty());
  CHECK_THAT(bad.err, Catch::StartsWith("impact3d: error: --scatter: \"vehicles[2].pdof_deg\" is not an output"));
  fs::remove_all(dir);
}

}  // namespace check_montecarlo_cli
