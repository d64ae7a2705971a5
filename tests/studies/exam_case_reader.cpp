// The case-file reader on inputs written here: literals kept exactly, defaults, shorthands and
// command-line strategies. Each known value is either the literal text of the input (which the reader
// keeps as written, for every precision to convert itself), a default or a shorthand of the case-format
// contract (SI units, zero orientation and angular velocity, contact pitch and roll zero, the diagonal
// inertia shorthand with zero products), or the JSON-path syntax docs/limits-and-exit-status.md documents for error lines.
#include <catch2/catch.hpp>

#include "impact3d/case_format/json_literals.hpp"
#include "impact3d/case_format/read_case.hpp"
#include "impact3d/case_format/strategy_kinds.hpp"
#include "impact3d/case_format/to_scene.hpp"
#include "impact3d/studies/precision.hpp"
#include "support.hpp"

namespace exam_case_reader {

using namespace impact3d;
using namespace impact3d::test;

namespace {

std::string minimal(const std::string& contact = R"("contact": {"normal_yaw_deg": 90})",
                    const std::string& strategy = R"({"name": "pc-crash", "mu": 0.4})") {
  return R"({"vehicles": [
      {"mass": 1500, "inertia": {"Ixx": 500, "Iyy": 2000, "Izz": 2200}, "velocity": [10.10000000000000000001, 0, 0],
       "impulse_center": [0.5, -0.9, 0]},
      {"mass": 2000, "inertia": [[700, 0, -50], [0, 3000, 0], [-50, 0, 3300]], "orientation_deg": {"yaw": 90},
       "velocity": [0, 12, 0], "impulse_center": [2.4, 0, 0]}],
    )" + contact + R"(, "restitution": 0.1, "strategy": )" + strategy + "}";
}

}  // namespace

TEST_CASE("number literals are kept as written", "[reader]") {
  const case_format::CaseSpec c = case_format::read_case(minimal());
  CHECK(c.vehicles[0].velocity[0].text == "10.10000000000000000001");
  CHECK(c.restitution.text == "0.1");
  CHECK(c.vehicles[0].mass.text == "1500");
  CHECK(c.vehicles[1].inertia[0][2].text == "-50");
  CHECK(c.vehicles[0].inertia[0][1].text == "0");  // shorthand: zero products of inertia
}

TEST_CASE("defaults: SI, zero orientation and angular velocity, contact pitch and roll", "[reader]") {
  const case_format::CaseSpec c = case_format::read_case(minimal());
  CHECK(c.units == Units::SI);
  CHECK(c.vehicles[0].yaw.value == 0.0);
  CHECK(c.vehicles[0].angular_velocity[2].value == 0.0);
  CHECK(c.contact.normal_pitch.value == 0.0);
  CHECK(!c.strategy_is_array);
}

TEST_CASE("a contact frame given by vectors equals the one given by angles", "[reader]") {
  // By hand from the contract's definitions: normal_yaw 90, pitch 0, roll 0 gives n = Rz(90) e_x = +y and
  // t = Rz(90) e_y = -x, with no rounding (sin_cos_deg is exact at quarter turns); the vectors give
  // n = (0, 2, 0) / 2 = +y and t = (-1, 0.3, 0) with its n part removed, normalised: -x. The vector path
  // rounds in a normalisation and a Gram-Schmidt step: a few eps.
  const auto by_angles = case_format::to_scene<double>(case_format::read_case(minimal()));
  const auto by_vectors =
      case_format::to_scene<double>(case_format::read_case(minimal(R"("contact": {"normal": [0, 2, 0], "tangent": [-1, 0.3, 0]})")));
  CHECK((by_angles.R_WC - by_vectors.R_WC).cwiseAbs().maxCoeff() <= 4 * eps);
}

TEST_CASE("strategy arrays and brach critical ratios", "[reader]") {
  const case_format::CaseSpec c = case_format::read_case(minimal(R"("contact": {"normal_yaw_deg": 90})",
                                               R"([{"name": "wach", "mu": 0.4, "limit": "gir"},
                                                   {"name": "brach", "mu_t": "critical", "mu_z": -0.05}])"));
  REQUIRE(c.strategies.size() == 2);
  CHECK(case_format::strategy_kind(c.strategies[0].kind).name == "wach");
  CHECK(c.strategies[0].choice("limit") == "gir");
  CHECK(!c.strategies[1].number("mu_t"));
  CHECK(c.strategies[1].number("mu_z")->text == "-0.05");
}

TEST_CASE("command-line strategies use the same rules", "[reader]") {
  const auto s = case_format::read_strategy_option("wach:mu=0.35,limit=gir", 0);
  CHECK(case_format::strategy_kind(s.kind).name == "wach");
  CHECK(s.number("mu")->text == "0.35");
  CHECK(s.choice("limit") == "gir");
  const auto b = case_format::read_strategy_option("brach:mu_t=critical,mu_z=0.1", 1);
  CHECK(!b.number("mu_t"));
  CHECK(b.number("mu_z")->text == "0.1");
  const auto j = case_format::read_strategy_option(R"({"name": "pc-crash", "mu": 0.5})", 2);
  CHECK(j.number("mu")->text == "0.5");
  try {
    case_format::read_strategy_option("pc-crash:mu=-1", 3);
    FAIL("accepted a negative mu");
  } catch (const case_format::CaseError& e) {
    // The contract: mu >= 0 for pc-crash; the path names the fourth --strategy option (index 3).
    CHECK(e.line() == "--strategy[3].mu: must be >= 0 (got -1)");
  }
}

TEST_CASE("paths print keys that are not identifiers quoted and escaped", "[reader]") {
  // docs/limits-and-exit-status.md's rule for error lines: keys that are not identifiers are quoted as in $["a/b"] (JSONPath's
  // bracket notation), control characters printed as \n or \xNN (ESC = 0x1B), so every error stays one line.
  CHECK(case_format::member_path(case_format::element_path("$.vehicles", 0), "mass") == "$.vehicles[0].mass");
  CHECK(case_format::member_path("$", "vehicles/0/mass") == "$[\"vehicles/0/mass\"]");
  CHECK(case_format::member_path("$", "0") == "$[\"0\"]");
  CHECK(case_format::member_path("$", "a\nb\x1b[31m") == "$[\"a\\nb\\x1B[31m\"]");
}

TEST_CASE("a description is read, echoed in the result, and printed escaped like the name", "[reader]") {
  // The case author's text: a newline and an escape sequence must not reach a terminal as such.
  std::string text = minimal();
  text.insert(1, R"("name": "a\u001b[31mred", "description": "line one\nline two", )");
  const case_format::CaseSpec c = case_format::read_case(text);
  CHECK(c.description == "line one\nline two");
  const std::string report = studies::render(c, "double", {case_format::Format::text});
  CHECK(report.find("impact3d: a\\x1B[31mred (units SI") != std::string::npos);
  CHECK(report.find("line one\\nline two\n") != std::string::npos);
  CHECK(report.find('\x1b') == std::string::npos);
  const std::string json = studies::render(c, "double", {case_format::Format::json});
  CHECK(json.find(R"("description": "line one\nline two")") != std::string::npos);
  // A description that is not a string is an error at its path.
  std::string bad = minimal();
  bad.insert(1, R"("description": 3, )");
  try {
    case_format::read_case(bad);
    FAIL("accepted a numeric description");
  } catch (const case_format::CaseError& e) {
    CHECK(e.line() == "$.description: expected a string, got a number");
  }
}

namespace {

// minimal() with the first `from` replaced by `to`.
std::string with(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

std::string reader_error(const std::string& text) {
  try {
    case_format::read_case(text);
  } catch (const case_format::CaseError& e) {
    return e.line();
  }
  return "accepted";
}

}  // namespace

// The reader takes a literal whose digits are all zeros as zero from its double, without parsing its
// decimal (the decimal stays the judge of every other literal the double cannot place): the known
// answers are the contract's ranges (case-format.md): zero is admitted wherever a number may be zero,
// refused where it must be positive, and a literal with a digit that is not zero is not zero, however
// far below the range its double falls.
TEST_CASE("zero in any spelling is zero, and a literal with a digit that is not zero is not", "[reader]") {
  const std::vector<std::string> zeros = {"0", "-0.0", "0.000", "0e5", "0E-400", "-0.0e+999", "0.000e-1000", "-0e0"};
  int checked = 0;
  for (const auto& z : zeros) {
    INFO(z);
    const case_format::CaseSpec c = case_format::read_case(with(minimal(), "[0, 12, 0]", "[" + z + ", 12, 0]"));
    CHECK(c.vehicles[1].velocity[0].value == 0);
    CHECK(reader_error(with(minimal(), "\"mass\": 1500", "\"mass\": " + z)).find("$.vehicles[0].mass: must be > 0") == 0);
    CHECK(reader_error(with(minimal(), "\"mu\": 0.4", "\"mu\": " + z)) == "accepted");
    ++checked;
  }
  CHECK(checked == static_cast<int>(zeros.size()));
  for (const std::string tiny : {"1e-400", "-0.0001e-399", "0.00000000000000000000000000001e-330"}) {
    INFO(tiny);
    CHECK(reader_error(with(minimal(), "[0, 12, 0]", "[" + tiny + ", 12, 0]")).find("is not zero but below 1e-100") !=
          std::string::npos);
  }
}

}  // namespace exam_case_reader
