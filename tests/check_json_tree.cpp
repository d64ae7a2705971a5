// The two JSON readers against each other (json_tree.hpp): on the bundled cases, the bad-input cases
// and seeded random mutations of them (bytes flipped, inserted, deleted, cut), whatever the fast reader
// accepts the checking reader accepts with the same tree, and the fast reader takes every well-formed
// case. The same property is fuzzed by tests/fuzz/fuzz_json_tree.cpp.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "fuzz/json_tree_equal.hpp"
#include "impact3d/io/case_spec.hpp"
#include "impact3d/io/json_tree.hpp"

namespace {

using namespace impact3d::io;

std::vector<std::string> documents(const std::string& dir) {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    if (e.path().extension() != ".json") continue;
    std::ifstream in(e.path(), std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    out.push_back(s.str());
  }
  return out;
}

// 0: both refuse; 1: only the checker accepts; 2: both accept, same tree; -1: disagreement.
int compare_readers(const std::string& text) {
  JsonValue fast;
  const bool fast_ok = parse_json_tree_fast(text, fast);
  try {
    const JsonValue checked = parse_json_tree_checked(text);
    if (!fast_ok) return 1;
    return json_tree_equal(fast, checked) ? 2 : -1;
  } catch (const CaseError&) {
    return fast_ok ? -1 : 0;
  }
}

}  // namespace

TEST_CASE("the fast reader takes every bundled case and reads it as the checker does") {
  const auto cases = documents(IMPACT3D_EXAMPLES_DIR);
  REQUIRE(cases.size() >= 4);
  for (const auto& text : cases) CHECK(compare_readers(text) == 2);
}

TEST_CASE("numbers as the checker reports them: integers as printed, -0 as 0, values to the bit") {
  JsonValue v;
  REQUIRE(parse_json_tree_fast("[-0, -0.0, 1E+2, 18446744073709551615]", v));
  REQUIRE(v.size() == 4);
  CHECK(v.items[0].text == "0");
  CHECK(!std::signbit(v.items[0].number));
  CHECK(v.items[1].text == "-0.0");
  CHECK(std::signbit(v.items[1].number));
  CHECK(v.items[2].text == "1E+2");
  CHECK(v.items[3].text == "18446744073709551615");
  CHECK(compare_readers("[-0, -0.0, 1E+2, 18446744073709551615]") == 2);
  // Beyond 64 bits simdjson refuses the integer; the checker reads it, as a double with its text.
  CHECK(compare_readers("[123456789012345678901234567890]") == 1);
}

TEST_CASE("the fast reader leaves to the checker what needs a message") {
  for (const char* text : {"{\"a\": 1, \"a\": 2}", "{\"x\": \"\\udc00\"}", "{\"x\": \"\\ud800\"}", "[1e400]", "{} x", "[1,]",
                           "[1e-1001]", "", "nul", "[01]"}) {
    JsonValue v;
    INFO(text);
    CHECK(!parse_json_tree_fast(text, v));
  }
  JsonValue v;
  CHECK(!parse_json_tree_fast(std::string(33, '[') + std::string(33, ']'), v));
  CHECK(!parse_json_tree_fast("{\"" + std::string(129, 'k') + "\": 1}", v));
}

TEST_CASE("random mutations: whatever the fast reader accepts, the checker reads the same") {
  std::vector<std::string> seeds = documents(IMPACT3D_EXAMPLES_DIR);
  for (auto& d : documents(IMPACT3D_BAD_INPUT_DIR)) seeds.push_back(std::move(d));
  REQUIRE(seeds.size() >= 20);
  std::mt19937_64 rng(20261122);
  const std::string alphabet = "{}[],:\"\\-+.eE0123456789 \ntfnula_\x01\xc3\xa9\xff";
  int counts[3] = {0, 0, 0}, disagreements = 0, runs = 0;
  for (int n = 0; n < 6000; ++n) {
    std::string text = seeds[rng() % seeds.size()];
    const int edits = 1 + static_cast<int>(rng() % 3);
    for (int k = 0; k < edits && !text.empty(); ++k) {
      const std::size_t at = rng() % text.size();
      const char c = alphabet[rng() % alphabet.size()];
      switch (rng() % 4) {
        case 0: text[at] = c; break;
        case 1: text.insert(text.begin() + static_cast<long>(at), c); break;
        case 2: text.erase(at, 1 + rng() % 4); break;
        default: text.resize(at); break;
      }
    }
    const int r = compare_readers(text);
    ++runs;
    if (r < 0) {
      ++disagreements;
      UNSCOPED_INFO("disagreement on: " << text);
    } else {
      ++counts[r];
    }
  }
  CHECK(disagreements == 0);
  CHECK(runs == 6000);
  // Mutations keep enough documents valid, and break enough, for both sides to be exercised.
  CHECK(counts[2] > 300);
  CHECK(counts[0] > 1000);
}
