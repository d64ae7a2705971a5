// The proof of the reference suite's digits (verification/reference/, issue 14) on Figure 8's case:
// the committed reference is what the proof writes, and a reference one unit off in its 40th digit, or
// with a category the certified result does not have, is refused by path. The known answer is the
// certified result of the same case (ball arithmetic, an independent route from the 100-digit solve).
#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>

#include "impact3d/case_format/number_literals.hpp"
#include "impact3d/case_format/read_case.hpp"
#include "impact3d/studies/precision.hpp"
#include "impact3d/case_format/result_json.hpp"
#include "impact3d/case_format/to_scene.hpp"
#include "impact3d/scalar/multiprecision.hpp"
#include "impact3d/verification/reference_proof.hpp"

namespace exam_reference_proof {

using namespace impact3d;

namespace {

const std::string kCase = std::string(IMPACT3D_EXAMPLES_DIR) + "/fig8_side_impact.json";

struct Fixture {
  explicit Fixture(const std::string& path = kCase) : spec(case_format::read_case(case_format::read_text_file(path))) {}
  case_format::CaseSpec spec;
  Analysis<mp::float100> analysis =
      analyze(case_format::to_scene<mp::float100>(spec), case_format::to_strategies<mp::float100>(spec), Engine::generated);
  std::string certified = [&] {
    case_format::RenderOptions o;
    o.format = case_format::Format::json;
    return studies::render(spec, "certified", o);
  }();

  // The reference as the generator writes it, with `edit` applied to its text.
  verification::ReferenceProof prove(const std::function<void(std::string&)>& edit = {}) const {
    return verification::prove_reference(
        [&](const auto& extra, const auto& per_result) {
          std::string text = case_format::result_json(spec, analysis, "100", 40, true, extra, false, nullptr, per_result);
          if (edit) edit(text);
          return text;
        },
        certified, 40);
  }
};

// The literal at `path` of `text` with its last digit moved by one.
void nudge(std::string& text, const std::string& path) {
  for (const auto& n : case_format::number_literals(text))
    if (n.path == path) {
      // The last digit of the significand, before any exponent.
      const std::size_t e = text.find_first_of("eE", n.begin);
      std::size_t last = (e < n.end ? e : n.end) - 1;
      while (text[last] < '0' || text[last] > '9') --last;
      text[last] = text[last] == '9' ? '8' : static_cast<char>(text[last] + 1);
      return;
    }
  FAIL("no number at " << path);
}

}  // namespace

TEST_CASE("the committed Figure 8 reference is every digit proven, as the proof writes it", "[certified]") {
  const Fixture f;
  const auto proof = f.prove();
  INFO(proof.failure);
  REQUIRE(proof.failure.empty());
  std::ifstream in(std::string(IMPACT3D_REFERENCE_DIR) + "/fig8_side_impact.json", std::ios::binary);
  std::stringstream committed;
  committed << in.rdbuf();
  CHECK(proof.document == committed.str());
  // Rounding noise of the 100-digit solve (a conserved momentum's components that are exactly 0) is
  // written 0, and the rest of the numbers are those of the 100-digit solve.
  const std::string raw = case_format::result_json(f.spec, f.analysis, "100", 40, true);
  std::size_t zeroed = 0, numbers = 0;
  const auto before = case_format::number_literals(raw), after = case_format::number_literals(proof.document);
  for (std::size_t i = 0; i < before.size(); ++i) {
    const std::string a = raw.substr(before[i].begin, before[i].end - before[i].begin);
    const std::string b = proof.document.substr(after[i].begin, after[i].end - after[i].begin);
    INFO(before[i].path);
    REQUIRE(after[i].path == before[i].path);
    ++numbers;
    if (a != b) {
      ++zeroed;
      CHECK(b == "0");
      CHECK(before[i].path.find("momentum") != std::string::npos);
    }
  }
  CHECK(numbers > 400);
  CHECK(zeroed > 0);
}

TEST_CASE("a reference digit one unit off, or a category the certified result lacks, is refused by path", "[certified]") {
  const Fixture f;
  for (const std::string path : {"coefficients.K[0][0]", "results[0].impulse.contact[0]", "results[3].vehicles[1].delta_v[1]"}) {
    const auto proof = f.prove([&](std::string& text) { nudge(text, path); });
    INFO(path);
    CHECK(proof.document.empty());
    CHECK(proof.failure.rfind(path + ":", 0) == 0);
  }
  const auto proof = f.prove([](std::string& text) {
    const std::size_t at = text.find("\"volume\": \"");
    REQUIRE(at != std::string::npos);
    text.replace(at, 11, "\"volume\": \"X");
  });
  CHECK(proof.document.empty());
  CHECK(proof.failure.find("impulse_space.volume") != std::string::npos);
}

namespace {

// The n-th (0-based) `"key": old` of `text` replaced by `"key": value`.
void set_nth(std::string& text, const std::string& key, const std::string& old, int n, const std::string& value) {
  const std::string pattern = "\"" + key + "\": " + old;
  std::size_t at = text.find(pattern);
  for (int i = 0; i < n && at != std::string::npos; ++i) at = text.find(pattern, at + 1);
  REQUIRE(at != std::string::npos);
  text.replace(at, pattern.size(), "\"" + key + "\": " + value);
}

}  // namespace

// The near-zero sliding case's result 0 (a Full Impact) leaves the PDOF's quadrant undecided at every
// bits: each vehicle's Delta-V lies along its x axis to within the balls, so its angle is 0 or 360.
// The alternative is that decision's other branch, both vehicles at 360; one of them alone mixes the
// branches.
TEST_CASE("a result is proven on one branch throughout: an alternative's, or none when branches mix", "[certified]") {
  const Fixture f(IMPACT3D_CASES_DIR "/hard_sliding_near_zero.json");
  const auto other = f.prove([](std::string& text) {
    set_nth(text, "pdof_deg", "0,", 0, "360,");
    set_nth(text, "pdof_deg", "0,", 0, "360,");
  });
  INFO(other.failure);
  REQUIRE(other.failure.empty());
  CHECK(other.document.find("for 1 of the results the other branch of one decision") != std::string::npos);
  const auto mixed = f.prove([](std::string& text) { set_nth(text, "pdof_deg", "0,", 0, "360,"); });
  CHECK(mixed.document.empty());
  CHECK(mixed.failure.rfind("results[0].", 0) == 0);
}

}  // namespace exam_reference_proof
