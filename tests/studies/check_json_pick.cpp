// JsonPick (json_pick.hpp) against a JSON parser: on every bundled case at every precision, seeded random
// sets of paths (keys, indices, and "any index" under results) are picked while the result document is
// written. Each span must read, by nlohmann::json, as the value the parser finds at its path; the
// document must not change because something was picked; and writing only the picked values must give
// the same spans, text for text, with the same strings.
#include <filesystem>
#include <random>
#include <set>
#include <string>
#include <vector>

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "impact3d/case_format/case_spec.hpp"
#include "impact3d/case_format/json_pick.hpp"
#include "impact3d/studies/precision.hpp"

#include "support.hpp"

namespace check_json_pick {

namespace {

using namespace impact3d::case_format;
using namespace impact3d::studies;
using nlohmann::json;

// Every value's path in the document, containers included.
void paths_of(const json& v, JsonPath& at, std::vector<JsonPath>& out) {
  if (!at.empty()) out.push_back(at);
  if (v.is_object()) {
    for (auto it = v.begin(); it != v.end(); ++it) {
      at.push_back(PathStep::of_key(it.key()));
      paths_of(it.value(), at, out);
      at.pop_back();
    }
  } else if (v.is_array()) {
    for (std::size_t i = 0; i < v.size(); ++i) {
      at.push_back(PathStep::of_index(i));
      paths_of(v[i], at, out);
      at.pop_back();
    }
  }
}

std::string text_of(const JsonPath& p) {
  std::string s = "$";
  for (const auto& step : p)
    s += step.kind == PathStep::Kind::key ? "." + step.key : step.kind == PathStep::Kind::any ? "[]" : "[" + std::to_string(step.index) + "]";
  return s;
}

const json* find(const json& root, const JsonPath& p, std::size_t group) {
  const json* v = &root;
  for (const auto& step : p) {
    if (step.kind == PathStep::Kind::key) {
      if (!v->is_object() || !v->contains(step.key)) return nullptr;
      v = &(*v)[step.key];
    } else {
      const std::size_t i = step.kind == PathStep::Kind::any ? group : step.index;
      if (!v->is_array() || i >= v->size()) return nullptr;
      v = &(*v)[i];
    }
  }
  return v;
}

}  // namespace

TEST_CASE("picked spans read as the parser's values at their paths, and writing only them changes no span") {
  std::size_t documents = 0, spans_checked = 0, strings_checked = 0;
  for (const auto& e : std::filesystem::directory_iterator(IMPACT3D_EXAMPLES_DIR)) {
    if (e.path().extension() != ".json") continue;
    const CaseSpec spec = read_case(impact3d::test::read_text(e.path().string()));
    for (const std::string& precision : precision_names())
    for (const Format format : {Format::jsonl, Format::json}) {  // one line, and indented
      const std::string plain = render(spec, precision, {format, 0});
      const json doc = json::parse(plain);
      std::vector<JsonPath> all;
      JsonPath at;
      paths_of(doc, at, all);
      // Half the sets name results by index, half by "any result"; a set does not mix the two, since
      // where both are named the index takes its result and "any" does not see it.
      std::mt19937_64 rng(documents + 1);
      int set = 0;
      for (const double share : {0.02, 0.1, 0.5, 0.02, 0.1, 0.5}) {
        const bool any = set++ >= 3;
        std::vector<JsonPath> chosen;
        std::set<std::string> seen;
        for (JsonPath p : all) {
          const bool of_result = p.size() >= 2 && p[0].key == "results";
          if (any && of_result) p[1] = PathStep::any_index();
          if (std::bernoulli_distribution(share)(rng) && seen.insert(text_of(p)).second) chosen.push_back(p);
        }
        JsonPick whole(chosen), alone(chosen, true);
        const std::string full = render(spec, precision, {format, 0, impact3d::Engine::generated, &whole});
        const std::string sparse = render(spec, precision, {format, 0, impact3d::Engine::generated, &alone});
        INFO(e.path().filename().string() << " at " << precision << " as " << format_name(format) << ", share " << share << (any ? ", any result" : ""));
        REQUIRE(full == plain);
        REQUIRE(whole.spans().size() == alone.spans().size());
        for (std::size_t i = 0; i < whole.spans().size(); ++i) {
          const auto& a = whole.spans()[i];
          const auto& b = alone.spans()[i];
          const std::string_view ta = std::string_view(full).substr(a.begin, a.end - a.begin);
          const std::string_view tb = std::string_view(sparse).substr(b.begin, b.end - b.begin);
          INFO(text_of(chosen[a.column]) << " group " << a.group << ": " << ta);
          REQUIRE(a.column == b.column);
          REQUIRE(a.group == b.group);
          REQUIRE(ta == tb);
          const json* expected = find(doc, chosen[a.column], a.group);
          REQUIRE(expected);
          REQUIRE(json::parse(ta) == *expected);
          REQUIRE((a.string != JsonPick::kNoString) == (b.string != JsonPick::kNoString));
          if (a.string != JsonPick::kNoString) {
            REQUIRE(expected->is_string());
            REQUIRE(whole.string(a) == expected->get<std::string>());
            REQUIRE(alone.string(b) == whole.string(a));
            ++strings_checked;
          }
          ++spans_checked;
        }
        // Writing only the picked values leaves out every other value: outside the spans there are only
        // the picked values' keys and separators, so no digit, bracket or brace.
        std::vector<bool> covered(sparse.size(), false);
        for (const auto& b : alone.spans())
          for (std::size_t k = b.begin; k < b.end; ++k) covered[k] = true;
        std::size_t stray = 0;
        for (std::size_t k = 0; k < sparse.size(); ++k)
          stray += !covered[k] && std::string_view("0123456789[]{}").find(sparse[k]) != std::string_view::npos;
        REQUIRE(stray == 0);
        // Every chosen path present in the document was picked, once per result for an "any" path.
        std::size_t expected_spans = 0;
        for (const JsonPath& p : chosen) {
          const bool each = p.size() > 1 && p[1].kind == PathStep::Kind::any;
          const std::size_t groups = each ? doc["results"].size() : 1;
          for (std::size_t g = 0; g < groups; ++g) expected_spans += find(doc, p, g) != nullptr;
        }
        REQUIRE(whole.spans().size() == expected_spans);
      }
      ++documents;
    }
  }
  CHECK(documents >= 2 * 4 * precision_names().size());
  CHECK(spans_checked > 10000);
  CHECK(strings_checked > 100);
}

}  // namespace check_json_pick
