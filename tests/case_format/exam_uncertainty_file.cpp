// The uncertainty file reader (case_format/read_uncertainty.hpp) on named answers: the example of
// many-cases.md ("montecarlo") read into the distributions it spells, and bad files each refused with
// the one-line message written here, naming the JSON path of the field.
#include <string>

#include <catch2/catch.hpp>

#include "impact3d/case_format/case_spec.hpp"
#include "impact3d/case_format/read_uncertainty.hpp"

namespace exam_uncertainty_file {

namespace {

using namespace impact3d::case_format;
using Kind = impact3d::uncertainty::Distribution::Kind;

std::string refusal(const std::string& text) {
  try {
    (void)read_uncertainty(text);
  } catch (const CaseError& e) {
    return e.line();
  }
  return "accepted";
}

std::string one(const std::string& input) { return R"({"inputs": [)" + input + "]}"; }

}  // namespace

TEST_CASE("the contract's example reads into the distributions it spells") {
  const UncertaintySpec s = read_uncertainty(R"({
    "samples": 100000, "seed": 42,
    "inputs": [
      { "path": "$.vehicles[1].velocity[1]", "distribution": "normal", "mean": 11.176, "sd": 0.3 },
      { "path": "$.restitution", "distribution": "uniform", "min": 0.05, "max": 0.2 },
      { "path": "$.contact.normal_yaw_deg", "distribution": "triangular", "min": 85, "mode": 90, "max": 95 },
      { "path": "$.vehicles[0].mass", "distribution": "truncated-normal", "mean": 1500, "sd": 60, "min": 1350, "max": 1650 },
      { "path": "$.strategy[1].mu", "distribution": "lognormal", "median": 0.4, "sigma": 0.2 },
      { "path": "$.vehicles[0].impulse_center[1]", "distribution": "discrete", "values": [-0.9, -0.8], "weights": [0.5, 0.5] }
    ],
    "correlations": [ { "paths": ["$.vehicles[0].mass", "$.vehicles[1].velocity[1]"], "rho": 0.5 } ] })");
  CHECK(s.samples == 100000);
  CHECK(s.seed == 42);
  REQUIRE(s.inputs.size() == 6);
  CHECK(s.inputs[0].distribution.kind == Kind::normal);
  CHECK(s.inputs[0].distribution.mean == 11.176);
  REQUIRE(s.inputs[0].path.size() == 4);  // vehicles, [1], velocity, [1]
  CHECK(s.inputs[0].path[3].index == 1);
  CHECK(s.inputs[2].distribution.mode == 90);
  CHECK(s.inputs[3].distribution.kind == Kind::truncated_normal);
  CHECK(s.inputs[4].distribution.median == 0.4);
  CHECK(s.inputs[5].distribution.cumulative == std::vector<double>{0.5, 1.0});
  REQUIRE(s.correlations.size() == 1);
  CHECK(s.correlations[0].a == 3);
  CHECK(s.correlations[0].b == 0);
  CHECK(s.correlations[0].rho == 0.5);
  // Defaults where the file is silent.
  const UncertaintySpec d = read_uncertainty(one(R"({"path": "$.restitution", "distribution": "uniform", "min": 0, "max": 1})"));
  CHECK(d.samples == 10000);
  CHECK(d.seed == 0);
}

TEST_CASE("bad uncertainty files are refused in one line naming the field") {
  const std::string normal = R"("distribution": "normal", "mean": 0, "sd": 1)";
  CHECK(refusal("[1]") == "$: must be an object");
  CHECK(refusal(R"({"inputs": [], "extra": 1})") == "$: unknown key \"extra\" (keys starting with '_' are ignored)");
  CHECK(refusal(R"({"inputs": [], "_note": "ignored, as in a case file", "extra": 1})") ==
        "$: unknown key \"extra\" (keys starting with '_' are ignored)");
  CHECK(refusal(R"({"samples": 0, "inputs": []})") == "$.samples: must be from 1 to 10000000 (got 0)");
  CHECK(refusal(R"({"samples": 1e5, "inputs": []})") == "$.samples: must be a whole number written in digits (got 1e5)");
  CHECK(refusal(R"({"seed": 18446744073709551616, "inputs": []})") == "$.seed: must be at most 18446744073709551615");
  CHECK(refusal(R"({"inputs": []})") == "$.inputs: must hold 1 to 256 inputs");
  CHECK(refusal(one(R"({"path": "$.vehicles[0].mas[", )" + normal + "}")) ==
        "$.inputs[0].path: expected an index [n] in the path");
  CHECK(refusal(one(R"({"path": "$.a", "distribution": "gaussian"})")) ==
        "$.inputs[0].distribution: unknown distribution \"gaussian\" (normal, truncated-normal, uniform, triangular, lognormal, discrete)");
  CHECK(refusal(one(R"({"path": "$.a", "distribution": "normal", "mean": 0, "sd": 0})")) == "$.inputs[0].sd: must be > 0 (got 0)");
  CHECK(refusal(one(R"({"path": "$.a", "distribution": "normal", "mean": 0})")) == "$.inputs[0]: missing \"sd\"");
  CHECK(refusal(one(R"({"path": "$.a", "distribution": "normal", "mean": 0, "sd": 1, "max": 2})")) == "$.inputs[0]: unknown key \"max\" (keys starting with '_' are ignored)");
  CHECK(refusal(one(R"({"path": "$.a", "distribution": "uniform", "min": 2, "max": 1})")) == "$.inputs[0].max: must be above \"min\"");
  CHECK(refusal(one(R"({"path": "$.a", "distribution": "triangular", "min": 0, "mode": 2, "max": 1})")) ==
        "$.inputs[0].max: must be at least \"mode\"");
  CHECK(refusal(one(R"({"path": "$.a", "distribution": "lognormal", "median": -1, "sigma": 1})")) == "$.inputs[0].median: must be > 0 (got -1)");
  CHECK(refusal(one(R"({"path": "$.a", "distribution": "discrete", "values": [1, 2], "weights": [1]})")) ==
        "$.inputs[0].weights: must be an array of 2 numbers, one per value");
  CHECK(refusal(one(R"({"path": "$.a", "distribution": "discrete", "values": [1, 2], "weights": [0, 0]})")) ==
        "$.inputs[0].weights: must not all be 0");
  CHECK(refusal(one(R"({"path": "$.a", "distribution": "discrete", "values": [1, "x"]})")) ==
        "$.inputs[0].values[1]: must be a finite number of magnitude at most 1e12");
  CHECK(refusal(one(R"({"path": "$.a", "distribution": "normal", "mean": 1e13, "sd": 1})")) ==
        "$.inputs[0].mean: must be a finite number of magnitude at most 1e12 (got 1e13)");
  CHECK(refusal(R"({"inputs": [{"path": "$.a", )" + normal + R"(}, {"path": "$.a", )" + normal + "}]}") ==
        "$.inputs[1].path: \"$.a\" is given twice");
  // User text in a message is escaped.
  CHECK(refusal(one(R"({"path": "$.a", "distribution": "x\u0007\"y"})")) ==
        "$.inputs[0].distribution: unknown distribution \"x\\x07\\\"y\" (normal, truncated-normal, uniform, triangular, lognormal, discrete)");
  const std::string two = R"({"path": "$.a", )" + normal + R"(}, {"path": "$.b", )" + normal + "}";
  CHECK(refusal(R"({"inputs": [)" + two + R"(], "correlations": [{"paths": ["$.a", "$.c"], "rho": 0.5}]})") ==
        "$.correlations[0].paths[1]: \"$.c\" is not one of the inputs");
  CHECK(refusal(R"({"inputs": [)" + two + R"(], "correlations": [{"paths": ["$.a", "$.b"], "rho": 1}]})") ==
        "$.correlations[0].rho: must be strictly between -1 and 1 (got 1)");
  CHECK(refusal(R"({"inputs": [)" + two + R"(], "correlations": [{"paths": ["$.a", "$.a"], "rho": 0.1}]})") ==
        "$.correlations[0].paths: must name two different inputs");
  CHECK(refusal(R"({"inputs": [)" + two + R"(], "correlations": [{"paths": ["$.a", "$.b"], "rho": 0.1}, {"paths": ["$.b", "$.a"], "rho": 0.2}]})") ==
        "$.correlations[1].paths: this pair is correlated twice");
  // One input has no pair, and a correlation naming another path is refused by that path.
  CHECK(refusal(R"({"inputs": [{"path": "$.a", )" + normal + R"(}], "correlations": [{"paths": ["$.a", "$.b"], "rho": 0.5}]})") ==
        "$.correlations[0].paths[1]: \"$.b\" is not one of the inputs");
  // A truncated normal whose window no double resolves: one line, its path.
  CHECK_THAT(refusal(one(R"({"path": "$.a", "distribution": "truncated-normal", "mean": 0, "sd": 1, "min": 1e6, "max": 1e7})")),
             Catch::StartsWith("$.inputs[0]: its window is too narrow, or too far from the mean, to be sampled to double precision"));
  const std::string three = two + R"(, {"path": "$.c", )" + normal + "}";
  CHECK(refusal(R"({"inputs": [)" + three +
                R"(], "correlations": [{"paths": ["$.a", "$.b"], "rho": 0.9}, {"paths": ["$.b", "$.c"], "rho": 0.9}, {"paths": ["$.a", "$.c"], "rho": -0.9}]})") ==
        "$.correlations: not positive definite: the correlations of \"$.c\" with \"$.b\", \"$.a\" cannot all hold with the others");
  CHECK(refusal(R"({"inputs": [)" + three +
                R"(], "correlations": [{"paths": ["$.a", "$.b"], "rho": 0.1}, {"paths": ["$.b", "$.a"], "rho": 0.2}]})") ==
        "$.correlations[1].paths: this pair is correlated twice");
}

}  // namespace exam_uncertainty_file
