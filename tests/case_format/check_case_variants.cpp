// Variants of one case (case_format/case_variants.hpp) against the case file edited as text: a variant with
// values at given paths reads as the same case as the file with those numbers written in, for seeded
// random values; copies vary independently; a path that names nothing, or no number, is refused at its
// given place; a variant that breaks the case's rules is refused with the case's message.
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "impact3d/case_format/case_variants.hpp"
#include "impact3d/case_format/format_double.hpp"
#include "impact3d/uncertainty/philox.hpp"

namespace check_case_variants {

namespace {

using namespace impact3d::case_format;

std::string fig8() {
  std::ifstream in(IMPACT3D_EXAMPLES_DIR "/fig8_side_impact.json", std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string g17(double x) {
  char buf[32];
  return std::string(buf, format_g17(buf, x));
}

// nlohmann writes a number back as its shortest text, the variant as its 17 digits: the same double.
bool same(const Number& a, const Number& b) { return a.value == b.value && a.text == g17(a.value); }

}  // namespace

TEST_CASE("a variant reads as the case file with its numbers written in") {
  const std::string text = fig8();
  const std::vector<std::string> spelled = {"$.vehicles[1].velocity[1]", "$.restitution", "$.contact.normal_yaw_deg",
                                            "$.vehicles[0].mass", "$.strategy[1].mu", "$.vehicles[0].impulse_center[1]"};
  std::vector<JsonPath> paths;
  for (const auto& p : spelled) paths.push_back(parse_json_path(p, p));
  CaseVariants v(text, paths, spelled);
  CaseVariants copy(v);
  int checked = 0;
  for (std::uint64_t i = 0; i < 200; ++i) {
    const double u = impact3d::uncertainty::uniform_open(1, i, 0);
    const double values[6] = {11.176 + u - 0.5, 0.05 + 0.15 * u, 85 + 10 * u, 1350 + 300 * u, 0.2 + u, -0.9 + 0.1 * u};
    const CaseSpec got = (i % 2 ? copy : v).with(values);
    // The file edited by nlohmann, each number written as the variant writes it.
    nlohmann::ordered_json j = nlohmann::ordered_json::parse(text);
    for (std::size_t k = 0; k < spelled.size(); ++k)
      j[nlohmann::ordered_json::json_pointer(
          [&] {
            std::string ptr;
            for (const PathStep& s : paths[k]) ptr += "/" + (s.kind == PathStep::Kind::key ? s.key : std::to_string(s.index));
            return ptr;
          }())] = nlohmann::ordered_json::parse(g17(values[k]));
    const CaseSpec want = read_case(j.dump());
    REQUIRE(same(got.vehicles[1].velocity[1], want.vehicles[1].velocity[1]));
    REQUIRE(got.vehicles[1].velocity[1].value == values[0]);
    REQUIRE(same(got.restitution, want.restitution));
    REQUIRE(same(got.vehicles[0].mass, want.vehicles[0].mass));
    REQUIRE(same(got.vehicles[0].impulse_center[1], want.vehicles[0].impulse_center[1]));
    REQUIRE(got.strategies.size() == want.strategies.size());
    ++checked;
  }
  CHECK(checked == 200);
  // The base case is untouched by the variants.
  CHECK(v.base().restitution.text == "0.1");
}

TEST_CASE("paths that name no number of the case, and variants that break its rules, are refused") {
  const std::string text = fig8();
  auto refusal = [&](const std::string& path) {
    try {
      CaseVariants v(text, {parse_json_path(path, path)}, {"$.inputs[0].path"});
    } catch (const CaseError& e) {
      return e.line();
    }
    return std::string("accepted");
  };
  CHECK(refusal("$.vehicles[2].mass") == "$.inputs[0].path: \"$.vehicles[2].mass\" is no field of the case");
  CHECK(refusal("$.vehicles[0].name") == "$.inputs[0].path: \"$.vehicles[0].name\" is not a number of the case");
  CHECK(refusal("$.vehicles[0].velocity") == "$.inputs[0].path: \"$.vehicles[0].velocity\" is not a number of the case");
  CHECK(refusal("$.vehicles[0].mass") == "accepted");
  CaseVariants v(text, {parse_json_path("$.vehicles[0].mass", "m")}, {"m"});
  const double negative = -5;
  CHECK_THROWS_AS(v.with(&negative), CaseError);
  try {
    v.with(&negative);
  } catch (const CaseError& e) {
    CHECK(e.path == "$.vehicles[0].mass");
  }
  const double inf = std::numeric_limits<double>::infinity();
  CHECK_THROWS_AS(v.with(&inf), CaseError);
}

}  // namespace check_case_variants
