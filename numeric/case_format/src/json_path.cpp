#include "impact3d/case_format/json_path.hpp"

#include <algorithm>
#include <cctype>

#include <fmt/format.h>

#include "impact3d/case_format/case_spec.hpp"
#include "impact3d/case_format/limits.hpp"

namespace impact3d::case_format {

JsonPath parse_json_path(std::string_view text, const std::string& where) {
  std::string_view p = text;
  if (p.substr(0, 2) == "$.") p.remove_prefix(2);
  else if (p.substr(0, 2) == "$[") p.remove_prefix(1);
  JsonPath steps;
  std::size_t i = 0;
  auto fail = [&](const std::string& problem) { throw CaseError(where, problem); };
  while (i < p.size()) {
    if (p[i] == '[') {
      std::size_t j = i + 1, value = 0;
      for (; j < p.size() && std::isdigit(static_cast<unsigned char>(p[j])); ++j)
        value = std::min(value * 10 + static_cast<std::size_t>(p[j] - '0'), kPathMaxIndex + 1);  // saturated: no overflow
      if (j == i + 1 || j >= p.size() || p[j] != ']') fail("expected an index [n] in the path");
      if (value > kPathMaxIndex) fail(fmt::format("an index beyond {}", kPathMaxIndex));
      steps.push_back(PathStep::of_index(value));
      i = j + 1;
    } else {
      if (!steps.empty()) {
        if (p[i] != '.') fail("expected '.' or '[' in the path");
        ++i;
      }
      const std::size_t start = i;
      while (i < p.size() && (std::isalnum(static_cast<unsigned char>(p[i])) || p[i] == '_')) ++i;
      if (i == start || std::isdigit(static_cast<unsigned char>(p[start]))) fail("expected a key (letters, digits, _) in the path");
      if (i - start > limits::kKeyChars) fail(fmt::format("a key longer than {} characters", limits::kKeyChars));
      steps.push_back(PathStep::of_key(p.substr(start, i - start)));
    }
    if (steps.size() > kPathMaxSteps) fail(fmt::format("a path deeper than {} steps", kPathMaxSteps));
  }
  if (steps.empty()) fail("an empty path");
  return steps;
}

JsonPath under_each_result(const JsonPath& path) {
  JsonPath out = {PathStep::of_key("results"), PathStep::any_index()};
  out.insert(out.end(), path.begin(), path.end());
  return out;
}

std::string path_text(const JsonPath& path) {
  std::string s = "$";
  for (const PathStep& step : path) {
    if (step.kind == PathStep::Kind::key) s += "." + step.key;
    else if (step.kind == PathStep::Kind::index) s += fmt::format("[{}]", step.index);
    else s += "[]";
  }
  return s;
}

}  // namespace impact3d::case_format
