// A path into a JSON document as case-format.md spells it ("$.vehicles[0].impulse_center[1]",
// "strategy[1].mu"): a chain of keys and indices. The batch CSV header names its columns so, the result
// CSV its cells, and an uncertainty file its inputs.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "impact3d/case_format/limits.hpp"

namespace impact3d::case_format {

struct PathStep {
  // `any` stands for every index (JsonPick's groups); text never spells it.
  enum class Kind { key, index, any } kind = Kind::key;
  std::string key;
  std::size_t index = 0;

  static PathStep of_key(std::string_view k) { return {Kind::key, std::string(k), 0}; }
  static PathStep of_index(std::size_t i) { return {Kind::index, {}, i}; }
  static PathStep any_index() { return {Kind::any, {}, 0}; }
};
using JsonPath = std::vector<PathStep>;

// Limits of a path read from input: an index (a case has at most 64 strategies) and the steps.
inline constexpr std::size_t kPathMaxIndex = limits::kStrategies - 1;
inline constexpr std::size_t kPathMaxSteps = 8;

// Reads a path, with or without the leading "$" ("$.a", "$[0]", "a[0].b"); keys are letters, digits
// and _, not starting with a digit. Throws CaseError(where, problem).
JsonPath parse_json_path(std::string_view text, const std::string& where);

// The path under every result of a result document ("$.results[].<path>"): the result's fields that
// JsonPick takes from each result in turn.
JsonPath under_each_result(const JsonPath& path);

// The path as messages spell it: "$.vehicles[0].mass" ("[]" for any index).
std::string path_text(const JsonPath& path);

}  // namespace impact3d::case_format
