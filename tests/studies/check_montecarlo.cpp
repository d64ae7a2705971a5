// The Monte Carlo runner (studies/montecarlo.hpp) on the Figure 8 case, against what is known without it:
// - an output linear in a normal input has the analytic mean and standard deviation (within their
//   sampling errors), and exactly the linear map of the sampled inputs' mean;
// - percentiles of a uniform input pushed through a known increasing map are that map's percentiles;
// - a correlation between inputs reaches the samples;
// - every sample's outputs are the numbers `solve` writes for that variant of the case, and every
//   sample `solve` refuses is counted as rejected with solve's message, none dropped;
// - the same seed gives the same output whatever the number of threads;
// - uncertainty files that can break the case are refused before any sample, naming the field.
// Statistical tolerances are 4 standard errors of the estimate at the sample size (a fixed seed makes
// each check deterministic; 4 sigma would fail by chance about once in 16 000 seeds).
#include <algorithm>
#include <cmath>
#include <fstream>
#include <cstdint>
#include <limits>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "impact3d/case_format/case_variants.hpp"
#include "impact3d/studies/montecarlo.hpp"
#include "impact3d/studies/precision.hpp"
#include "impact3d/case_format/strategy_option.hpp"

namespace check_montecarlo {

namespace {

using namespace impact3d;
using namespace impact3d::case_format;
using namespace impact3d::studies;
using nlohmann::json;

constexpr double kEps = std::numeric_limits<double>::epsilon();

std::string fig8() {
  std::ifstream in(IMPACT3D_EXAMPLES_DIR "/fig8_side_impact.json", std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// pc-crash at mu = 5: far above the Figure 8 case's GIR (0.48) for every sample below, so the Full
// Impact is taken throughout and the impulse is linear in the relative velocity and in (1 + eps).
MonteCarloOptions full_impact(unsigned jobs = 2) {
  MonteCarloOptions o;
  o.strategies = {read_strategy_option("pc-crash:mu=5", 0)};
  o.jobs = jobs;
  o.keep_samples = true;
  return o;
}

// The result document of the case with `value` at `path`, solved as `solve --format json` does.
json solved_at(const std::string& path, double value, const std::vector<StrategySpec>& strategies) {
  CaseVariants v(fig8(), {parse_json_path(path, "test")}, {"test"});
  CaseSpec spec = v.with(&value);
  spec.strategies = strategies;
  RenderOptions ro;
  ro.format = Format::json;
  return json::parse(render(spec, "double", ro));
}

// A result document with its numbers read at long double: every digit a double or long double
// document writes (max_digits10) reads back to the number written.
using json_ld = nlohmann::basic_json<std::map, std::vector, std::string, bool, std::int64_t, std::uint64_t, long double>;

template <typename Json = json>
auto at(const Json& result, const std::string& path) {
  return result.at(typename Json::json_pointer(
                       "/" + std::regex_replace(std::regex_replace(path, std::regex(R"(\[(\d+)\])"), ".$1"), std::regex(R"(\.)"), "/")))
      .template get<typename Json::number_float_t>();
}

const OutputSummary& output(const StrategySummary& s, const std::string& path) {
  for (const auto& o : s.outputs)
    if (o.output->text == path) return o;
  FAIL("no output " << path);
  throw;
}

}  // namespace

TEST_CASE("an output linear in a normal input: the analytic mean and sd, and the samples' own map") {
  const double mean = 11.176, sd = 0.5;
  const std::uint64_t n = 20000;
  const UncertaintySpec u = read_uncertainty(R"({"samples": 20000, "seed": 7, "inputs": [
      {"path": "$.vehicles[1].velocity[1]", "distribution": "normal", "mean": 11.176, "sd": 0.5}]})");
  const MonteCarloOptions o = full_impact();
  const MonteCarloRun run = montecarlo(fig8(), u, o);
  REQUIRE(run.results.size() == 1);
  const StrategySummary& r = run.results[0];
  REQUIRE(r.solved == n);
  CHECK(r.regimes[0] == n);  // full
  double mean_in = 0;
  for (double x : run.inputs_of) mean_in += x;
  mean_in /= static_cast<double>(n);
  // y = a + b x by two solves of the document, one unit apart.
  const json y0 = solved_at("$.vehicles[1].velocity[1]", mean, o.strategies)["results"][0];
  const json y1 = solved_at("$.vehicles[1].velocity[1]", mean + 1, o.strategies)["results"][0];
  int checked = 0;
  for (const std::string path : {"vehicles[0].delta_v[1]", "vehicles[1].delta_v[0]", "impulse.contact[0]", "impulse.world[2]",
                                 "vehicles[1].angular_velocity[2]", "relative_velocity.after[0]"}) {
    INFO(path);
    const double a = at(y0, path), b = at(y1, path) - a;
    REQUIRE(std::fabs(b) > 1e-6 * std::max(1.0, std::fabs(a)));  // the output does depend on the input
    const auto& s = output(r, path).summary;
    CHECK(std::fabs(s.mean - a) <= 4 * std::fabs(b) * sd / std::sqrt(double(n)));
    CHECK(std::fabs(s.sd - std::fabs(b) * sd) <= 4 * std::fabs(b) * sd / std::sqrt(2.0 * double(n - 1)));
    // The mean of a linear map is the map of the mean: only rounding separates them. Each sample is a
    // well-conditioned double solve (rounding bound ~1e-15), b is a difference of two of them: 2^12 eps
    // of the output's scale covers both.
    const double scale = std::fabs(a) + std::fabs(b) * mean;
    CHECK(std::fabs(s.mean - (a + b * (mean_in - mean))) <= 4096 * kEps * scale);
    // The first order is exact for a linear map: its mean is the document's value at the input's mean
    // and its sd |b| sd, b here a difference over a unit step of a linear map (2^12 eps as above).
    const std::size_t c = static_cast<std::size_t>(output(r, path).output - monte_carlo_outputs().data());
    CHECK(std::fabs(r.linear.mean[c] - a) <= 4096 * kEps * scale);
    CHECK(std::fabs(r.linear.sd[c] - std::fabs(b) * sd) <= 4096 * kEps * scale * sd);
    ++checked;
  }
  CHECK(checked == 6);
  CHECK(r.linear.note.empty());
  CHECK(r.linear.regime == "full");
  CHECK_FALSE(r.linear.regime_switch);
  CHECK(r.linear.differs.empty());
}

TEST_CASE("the first order flags the regime switch and the non-linearity that the samples show") {
  // The Figure 8 case's pc-crash (its $.strategy[1]) with mu uniform on [0.2, 0.6]: its GIR is 0.48,
  // so the samples above it take the Full Impact, where nothing depends on mu, while the mean (0.4)
  // takes the sliding one, where the impulse grows with mu.
  const UncertaintySpec u = read_uncertainty(R"({"samples": 4000, "seed": 3, "inputs": [
      {"path": "$.strategy[1].mu", "distribution": "uniform", "min": 0.2, "max": 0.6}]})");
  const MonteCarloRun run = montecarlo(fig8(), u, {});
  const StrategySummary& r = run.results[1];
  CHECK(r.linear.regime == "sliding");
  INFO("full " << r.regimes[0] << ", sliding " << r.regimes[1]);
  REQUIRE(r.regimes[0] > 0);
  REQUIRE(r.regimes[1] > 0);
  CHECK(r.linear.regime_switch);
  CHECK_FALSE(r.linear.differs.empty());
}

TEST_CASE("percentiles of a uniform input through an increasing map are the map's percentiles") {
  const std::uint64_t n = 20000;
  const UncertaintySpec u = read_uncertainty(R"({"samples": 20000, "seed": 11, "inputs": [
      {"path": "$.restitution", "distribution": "uniform", "min": 0.05, "max": 0.2}]})");
  const MonteCarloOptions o = full_impact();
  const MonteCarloRun run = montecarlo(fig8(), u, o);
  const StrategySummary& r = run.results[0];
  REQUIRE(r.solved == n);
  // P_n of the Full Impact is linear in eps: a + b eps with b > 0.
  const double a = at(solved_at("$.restitution", 0, o.strategies)["results"][0], "impulse.contact[0]");
  const double b = at(solved_at("$.restitution", 1, o.strategies)["results"][0], "impulse.contact[0]") - a;
  REQUIRE(b > 0);
  const auto& s = output(r, "impulse.contact[0]").summary;
  int checked = 0;
  for (std::size_t k = 0; k < uncertainty::kPercentiles.size(); ++k) {
    const double p = uncertainty::kPercentiles[k] / 100;
    INFO("percentile " << uncertainty::kPercentileKeys[k]);
    const double expected = a + b * (0.05 + 0.15 * p);
    const double se = b * 0.15 * std::sqrt(p * (1 - p) / double(n));  // the uniform's quantile slope, exact
    CHECK(std::fabs(s.percentile[k] - expected) <= 4 * se);
    // The reported error estimates that one from the samples' spacing alone.
    CHECK(s.percentile_se[k] >= 0.5 * se);
    CHECK(s.percentile_se[k] <= 2 * se);
    ++checked;
  }
  CHECK(checked == 9);
}

TEST_CASE("a correlation of normal scores reaches the samples") {
  const std::uint64_t n = 20000;
  const UncertaintySpec u = read_uncertainty(R"({"samples": 20000, "seed": 3, "inputs": [
      {"path": "$.vehicles[0].velocity[0]", "distribution": "normal", "mean": 11.176, "sd": 0.3},
      {"path": "$.vehicles[1].velocity[1]", "distribution": "normal", "mean": 11.176, "sd": 0.3}],
      "correlations": [{"paths": ["$.vehicles[0].velocity[0]", "$.vehicles[1].velocity[1]"], "rho": 0.6}]})");
  const MonteCarloRun run = montecarlo(fig8(), u, full_impact());
  double mx = 0, my = 0;
  for (std::uint64_t i = 0; i < n; ++i) mx += run.inputs_of[2 * i], my += run.inputs_of[2 * i + 1];
  mx /= double(n), my /= double(n);
  double sxx = 0, syy = 0, sxy = 0;
  for (std::uint64_t i = 0; i < n; ++i) {
    const double dx = run.inputs_of[2 * i] - mx, dy = run.inputs_of[2 * i + 1] - my;
    sxx += dx * dx, syy += dy * dy, sxy += dx * dy;
  }
  const double r = sxy / std::sqrt(sxx * syy);
  CHECK(std::fabs(r - 0.6) <= 4 * (1 - 0.36) / std::sqrt(double(n)));  // the standard error of r
}

namespace {

std::string example(const std::string& name) {
  std::ifstream in(std::string(IMPACT3D_EXAMPLES_DIR "/") + name, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Runs `u` on the case at `precision` and compares every sample with `solve`'s document for that
// variant: the regime, every output (bit for bit: the document's number, read at long double, rounded
// once to double; at double, its 17 digits read back), null where the
// document has null, and a refusal, with its reason, where `solve` refuses. Returns the samples refused;
// `*twice` counts the outputs that differ from the document's text read as a double (which rounds twice).
std::uint64_t compare_with_solve(const std::string& case_text, const UncertaintySpec& u, const std::string& precision,
                                 bool direct, std::uint64_t* twice = nullptr) {
  MonteCarloOptions o;
  o.keep_samples = true;
  o.jobs = 2;
  o.precision = parse_precision(precision);
  const MonteCarloRun run = montecarlo(case_text, u, o);
  CHECK(run.direct == direct);  // the route under test
  std::vector<JsonPath> paths;
  for (const auto& in : u.inputs) paths.push_back(in.path);
  CaseVariants variants(case_text, paths, std::vector<std::string>(paths.size(), "test"));
  const std::size_t outputs = monte_carlo_outputs().size(), results = run.results.size(), inputs = paths.size();
  std::uint64_t checked = 0, refused = 0, compared = 0;
  for (std::uint64_t i = 0; i < run.samples; ++i) {
    const CaseSpec spec = variants.with(&run.inputs_of[i * inputs]);
    RenderOptions ro;
    ro.format = Format::json;
    std::string problem;
    json_ld doc;
    json doc_double;
    try {
      const std::string text = render(spec, precision, ro);
      doc = json_ld::parse(text);
      doc_double = json::parse(text);
    } catch (const CaseError& e) {
      problem = e.line();
    }
    for (std::size_t k = 0; k < results; ++k) {
      INFO(precision << ", sample " << i << ", result " << k);
      if (!problem.empty()) {
        REQUIRE(run.reason_of[k][i] != 0);
        CHECK(run.reasons[run.reason_of[k][i] - 1u] == "not approaching");
        CHECK(run.regime_of[k][i] == -1);
        continue;
      }
      REQUIRE(run.reason_of[k][i] == 0);
      const json_ld& result = doc["results"][k];
      CHECK(kRegimeNames[static_cast<std::size_t>(run.regime_of[k][i])] == result["regime"].get<std::string>());
      for (const auto& out : run.results[k].outputs) {
        INFO(out.output->text);
        const auto c = static_cast<std::size_t>(out.output - monte_carlo_outputs().data());
        const double mine = run.outputs_of[(k * outputs + c) * run.samples + i];
        double theirs;
        try {
          theirs = static_cast<double>(at(result, out.output->text));
        } catch (const json_ld::exception&) {
          CHECK(std::isnan(mine));  // null, or not written for this sample
          continue;
        }
        CHECK(mine == theirs);
        if (twice && mine != at(doc_double["results"][k], out.output->text)) ++*twice;
        ++compared;
      }
    }
    if (!problem.empty()) ++refused;
    ++checked;
  }
  CHECK(checked == run.samples);
  CHECK(compared > 20 * checked);
  for (const auto& r : run.results) {
    std::uint64_t rejected = 0;
    for (const auto& rej : r.rejected) rejected += rej.count;
    CHECK(r.solved + rejected == run.samples);
    if (refused) {
      REQUIRE(r.rejected.size() == 1);
      CHECK(r.rejected[0].reason == "not approaching");
      CHECK(r.rejected[0].count == refused);
      CHECK(r.rejected[0].message.rfind("$.vehicles: not approaching", 0) == 0);
    }
  }
  return refused;
}

}  // namespace

TEST_CASE("every sample is solve's answer for its variant, and every refusal is counted with solve's message") {
  // Vehicle 2's speed towards the struck side straddles zero: about a third of the samples do not
  // approach. The case's own four strategies, at double and at long double, both held to the
  // document.
  const UncertaintySpec u = read_uncertainty(R"({"samples": 400, "seed": 5, "inputs": [
      {"path": "$.vehicles[1].velocity[1]", "distribution": "normal", "mean": 1.5, "sd": 3},
      {"path": "$.restitution", "distribution": "uniform", "min": 0.05, "max": 0.2},
      {"path": "$.vehicles[0].impulse_center[0]", "distribution": "uniform", "min": 0.15, "max": 0.55}]})");
  for (const char* precision : {"double", "long-double"}) {
    std::uint64_t twice = 0;
    const std::uint64_t refused = compare_with_solve(fig8(), u, precision, true, &twice);
    CHECK(refused >= 50);  // both kinds of sample are exercised
    CHECK(refused <= 350);
    // At long double some numbers lie next to a midpoint between doubles (about 1 in 2048 has its last
    // 11 bits 10...0): there the comparison tells rounding once from reading the text.
    if (precision == std::string("double")) CHECK(twice == 0);
    else CHECK(twice > 0);
  }
  // US units (lb, ft, mph, deg/s): every output divided by its unit factor as the document writes it;
  // an angular velocity and the yaw uncertain.
  const UncertaintySpec us = read_uncertainty(R"({"samples": 200, "seed": 9, "inputs": [
      {"path": "$.vehicles[0].velocity[0]", "distribution": "normal", "mean": 20, "sd": 2},
      {"path": "$.vehicles[1].angular_velocity[2]", "distribution": "uniform", "min": -8, "max": 0},
      {"path": "$.vehicles[1].orientation_deg.yaw", "distribution": "triangular", "min": 115, "mode": 120, "max": 125},
      {"path": "$.strategy[1].mu", "distribution": "uniform", "min": 0.2, "max": 0.6}]})");
  CHECK(compare_with_solve(example("us_pickup_into_sedan.json"), us, "double", true) == 0);
  // An inertia entry is checked with its tensor by the reader: every sample goes through it.
  const UncertaintySpec tensor = read_uncertainty(R"({"samples": 200, "seed": 9, "inputs": [
      {"path": "$.vehicles[0].velocity[0]", "distribution": "normal", "mean": 20, "sd": 2},
      {"path": "$.vehicles[1].inertia.Izz", "distribution": "uniform", "min": 3000, "max": 4000}]})");
  CHECK(compare_with_solve(example("us_pickup_into_sedan.json"), tensor, "double", false) == 0);
}

TEST_CASE("the same seed gives the same bytes at any number of threads") {
  std::ifstream in(IMPACT3D_EXAMPLES_DIR "/uncertainty/fig8_side_impact.json", std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  UncertaintySpec u = read_uncertainty(text.str());
  u.samples = 3000;
  std::string first_json, first_csv;
  int runs = 0;
  for (unsigned jobs : {1u, 2u, 3u}) {
    MonteCarloOptions o;
    o.jobs = jobs;
    o.keep_samples = true;
    const MonteCarloRun run = montecarlo(fig8(), u, o);
    std::string csv;
    samples_csv(run, [&](std::string_view s) { csv += s; });
    const std::string doc = montecarlo_json(run);
    if (jobs == 1) first_json = doc, first_csv = csv;
    CHECK(doc == first_json);
    CHECK(csv == first_csv);
    ++runs;
  }
  CHECK(runs == 3);
  CHECK(std::count(first_csv.begin(), first_csv.end(), '\n') == 3001);
}

TEST_CASE("an uncertainty file that can break the case is refused before any sample, naming the field") {
  auto refusal = [](const std::string& inputs) -> std::string {
    try {
      montecarlo(fig8(), read_uncertainty(R"({"samples": 10, "inputs": [)" + inputs + "]}"), MonteCarloOptions{});
    } catch (const CaseError& e) {
      return e.line();
    }
    return "accepted";
  };
  CHECK_THAT(refusal(R"({"path": "$.vehicles[0].mass", "distribution": "normal", "mean": 1500, "sd": 60})"),
             Catch::StartsWith("$.inputs[0].distribution: a normal is not bounded below, but the case bounds $.vehicles[0].mass"));
  CHECK_THAT(refusal(R"({"path": "$.restitution", "distribution": "lognormal", "median": 0.1, "sigma": 0.2})"),
             Catch::StartsWith("$.inputs[0].distribution: a lognormal is not bounded above, but the case bounds $.restitution"));
  CHECK(refusal(R"({"path": "$.restitution", "distribution": "uniform", "min": 0.5, "max": 1.5})") ==
        "$.inputs[0].distribution: the uniform reaches 1.5 at its upper end, but the case refuses it: $.restitution: must be "
        "in [0, 1] (got 1.5)");
  CHECK_THAT(refusal(R"({"path": "$.strategy[0].mu", "distribution": "discrete", "values": [0.4, -0.1], "weights": [1, 1]})"),
             Catch::StartsWith("$.inputs[0].distribution: the discrete reaches -0.1 at its lower end, but the case refuses it: "
                               "$.strategy[0].mu: must be >= 0"));
  CHECK(refusal(R"({"path": "$.vehicles[2].mass", "distribution": "uniform", "min": 1, "max": 2})") ==
        "$.inputs[0].path: \"$.vehicles[2].mass\" is no field of the case");
  CHECK(refusal(R"({"path": "$.vehicles[0].name", "distribution": "uniform", "min": 1, "max": 2})") ==
        "$.inputs[0].path: \"$.vehicles[0].name\" is not a number of the case");
  // Bounded where the case is: accepted, and a velocity may be normal.
  CHECK(refusal(R"({"path": "$.vehicles[0].mass", "distribution": "truncated-normal", "mean": 1500, "sd": 60, "min": 1350, "max": 1650},
                   {"path": "$.vehicles[0].velocity[0]", "distribution": "normal", "mean": 11, "sd": 1},
                   {"path": "$.strategy[1].mu", "distribution": "lognormal", "median": 0.4, "sigma": 0.2})") == "accepted");
  // --strategy replaces the strategies an input would vary.
  try {
    MonteCarloOptions o;
    o.strategies = {read_strategy_option("pc-crash:mu=0.4", 0)};
    montecarlo(fig8(), read_uncertainty(R"({"inputs": [{"path": "$.strategy[1].mu", "distribution": "uniform", "min": 0.3, "max": 0.5}]})"), o);
    FAIL("accepted");
  } catch (const CaseError& e) {
    CHECK(e.line() == "--strategy: replaces the case's strategies, which $.inputs[0] varies ($.strategy[1].mu)");
  }
  // A run that would keep more values than the limit.
  try {
    UncertaintySpec u = read_uncertainty(R"({"samples": 10000000, "inputs": [{"path": "$.restitution", "distribution": "uniform", "min": 0, "max": 1}]})");
    montecarlo(fig8(), u, MonteCarloOptions{});
    FAIL("accepted");
  } catch (const CaseError& e) {
    CHECK_THAT(e.line(), Catch::StartsWith("$.samples: 10000000 samples of 4 results would take 23499 MiB"));
  }
}

}  // namespace check_montecarlo
