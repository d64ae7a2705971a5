// The suggestion an unknown key's refusal carries (case_format/nearest_key.hpp), on answers worked by
// hand: the edit distances are counted letter by letter in the comments; issue 60's example
// (normal_yaw for normal_yaw_deg) and the bundled bad input's misspelling (restitutoin) among them.
#include <array>
#include <string>
#include <string_view>

#include <catch2/catch.hpp>

#include "impact3d/case_format/nearest_key.hpp"
#include "impact3d/case_format/read_case.hpp"

namespace exam_nearest_key {

using namespace impact3d::case_format;

namespace {

constexpr std::array<std::string_view, 5> kContact{"normal", "normal_yaw_deg", "normal_pitch_deg", "tangent_roll_deg", "tangent"};
constexpr std::array<std::string_view, 6> kRoot{"name", "units", "vehicles", "contact", "restitution", "strategy"};
constexpr std::array<std::string_view, 3> kBrach{"name", "mu_t", "mu_z"};

std::string refusal(const std::string& text) {
  try {
    (void)read_case(text);
  } catch (const CaseError& e) {
    return e.path + ": " + e.what();
  }
  return "accepted";
}

}  // namespace

TEST_CASE("an unknown key is matched to the known key it most likely meant") {
  // restitutoin -> restitution: one swap of neighbours (o, i), one edit; within 3 of 11 letters.
  CHECK(nearest_key("restitutoin", kRoot) == "restitution");
  // vehicle -> vehicles: one insertion.
  CHECK(nearest_key("vehicle", kRoot) == "vehicles");
  // Contact -> contact: case alone.
  CHECK(nearest_key("Contact", kRoot) == "contact");
  // normal_yaw: 4 insertions from normal_yaw_deg, past 3, but its unit suffix left out.
  CHECK(nearest_key("normal_yaw", kContact) == "normal_yaw_deg");
  // tangent_roll_deg_x: begins with a known key at an underscore (the suffix added).
  CHECK(nearest_key("tangent_roll_deg_x", kContact) == "tangent_roll_deg");
  // mu: 2 insertions from both mu_t and mu_z, which it begins alike: ambiguous, none.
  CHECK(!nearest_key("mu", kBrach));
  // nmae -> name: a swap, one edit, within 1 of a 4-letter key.
  CHECK(nearest_key("nmae", kBrach) == "name");
  // colour: 5 or more edits from every key.
  CHECK(!nearest_key("colour", kRoot));
  // Longer than any key could be: no search.
  CHECK(!nearest_key(std::string(65, 'a'), kRoot));
  CHECK(did_you_mean("vehicle", kRoot) == "; did you mean vehicles?");
  CHECK(did_you_mean("colour", kRoot).empty());
}

TEST_CASE("a case's unknown key is refused with the suggestion, its path named") {
  CHECK(refusal(R"({"restitutoin": 0.1})") == "$.restitutoin: unknown key; did you mean restitution? (keys starting with '_' are ignored)");
  CHECK(refusal(R"({"colour": 1})") == "$.colour: unknown key (keys starting with '_' are ignored)");
}

}  // namespace exam_nearest_key
