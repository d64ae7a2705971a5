// The two JSON readers against each other (json_tree.hpp): on the bundled cases, the bad-input cases
// and seeded random mutations of them (bytes flipped, inserted, deleted, cut), whatever the fast reader
// accepts the checking reader accepts with the same tree, and the fast reader takes every well-formed
// case, into a new tree or into one that held the document before. The same property is fuzzed by
// tests/fuzz/fuzz_json_tree.cpp.
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "json_tree_equal.hpp"
#include "impact3d/case_format/case_spec.hpp"
#include "impact3d/case_format/json_tree.hpp"
#include "impact3d/case_format/read_case.hpp"

namespace check_json_tree {

namespace {

using namespace impact3d::case_format;

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

// 0: both refuse; 1: only the checker accepts; 2: both accept, same tree; -1: disagreement. The fast
// reader also reads into a tree that holds the document before (accepted or refused), as read_case
// reuses one, and must give the same verdict and tree as into a new one.
int compare_readers(const std::string& text) {
  JsonValue fast;
  const bool fast_ok = parse_json_tree_fast(text, fast);
  static JsonValue reused;
  if (parse_json_tree_fast(text, reused) != fast_ok || (fast_ok && !json_tree_equal(reused, fast))) return -1;
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
  // impact3d's own documents read back as written: a printed negative zero stays "-0" (batch CSV).
  JsonValue w;
  REQUIRE(parse_json_tree_fast("[-0, 1]", w, true));
  CHECK(w.items[0].text == "-0");
  CHECK(std::signbit(w.items[0].number));
  CHECK(compare_readers("[-0, -0.0, 1E+2, 18446744073709551615]") == 2);
  // Beyond 64 bits an integer is still a number: both read it as the double nearest its text, text kept
  // (simdjson's strict parse refused it, which the fast reader no longer runs).
  CHECK(compare_readers("[123456789012345678901234567890, -98765432109876543210987654321e-3]") == 2);
}

TEST_CASE("long literals below one: the value of the text, as the checker reads it (simdjson issue 2093)") {
  // simdjson 3.0's own value of such literals is wrong; the fast reader takes the text's.
  const std::string text = "[-0.2345664455510000555100005375809, 0.90000000000000000000, 0.30000000000000000000]";
  JsonValue v;
  REQUIRE(parse_json_tree_fast(text, v));
  CHECK(v.items[0].number == std::strtod("-0.2345664455510000555100005375809", nullptr));
  CHECK(v.items[1].number == 0.9);
  CHECK(compare_readers(text) == 2);
  // And so the case reader's definiteness test: the first tensor is indefinite (0.5^2 < 0.9^2), the
  // second definite (0.3^2 > 0.2^2), whichever reader read them.
  std::ifstream in(std::string(IMPACT3D_EXAMPLES_DIR) + "/fig8_side_impact.json");
  std::ostringstream s;
  s << in.rdbuf();
  const std::string fig8 = s.str(), tensor = "[[560, 0, -40], [0, 2500, 0], [-40, 0, 2700]]";
  const auto at = fig8.find(tensor);
  REQUIRE(at != std::string::npos);
  auto with = [&](const std::string& t) { return std::string(fig8).replace(at, tensor.size(), t); };
  const std::string indefinite = with("[[0.5, 0.90000000000000000000, 0], [0.90000000000000000000, 0.5, 0], [0, 0, 1]]");
  const std::string definite = with("[[0.30000000000000000000, 0.2, 0], [0.2, 0.30000000000000000000, 0], [0, 0, 1]]");
  for (const std::string& bom : {std::string(), std::string("\xEF\xBB\xBF")}) {  // with a BOM the checker reads them
    CHECK_THROWS_WITH(read_case(bom + indefinite), "not positive definite");
    CHECK_NOTHROW(read_case(bom + definite));
  }
}

TEST_CASE("the fast reader leaves to the checker what needs a message") {
  for (const char* text : {"{\"a\": 1, \"a\": 2}", "{\"x\": \"\\udc00\"}", "{\"x\": \"\\ud800\"}", "[1e400]", "{} x", "[1,]",
                           "[1e-1001]", "", "nul", "[01]"}) {
    JsonValue v;
    INFO(text);
    CHECK(!parse_json_tree_fast(text, v));
  }
  // What the reader's own walk must refuse, there being no strict parse before it (json_tree.cpp): broken
  // structure, broken literals, text after the root, and bytes that are not UTF-8 inside strings and keys.
  for (const char* text : {"[1 2]", "{\"a\" 1}", "{\"a\": 1,}", "[1]]", "{\"a\": 1}}", "{\"a\": [}", "[1] x", "[1] 2",
                           "{} {}", "[tru]", "[nulls]", "[1.]", "[-]", "[.5]", "[\"a\\x\"]", "[\"a]", "[\"\xff\"]",
                           "{\"\xc3\": 0}", "[\"\xed\xa0\x80\"]", "[\"\xf4\x90\x80\x80\"]", "[\"\xc0\xaf\"]", "[1]\xff"}) {
    JsonValue v;
    INFO(text);
    CHECK(!parse_json_tree_fast(text, v));
    CHECK(compare_readers(text) == 0);  // the checker refuses it as well
  }
  // And what it must still take: whitespace after the root, every literal, valid multi-byte UTF-8.
  for (const char* text : {"[1, 2] \n", "{\"a\": [true, false, null, -0.5e-3]}", "[\"\xc3\xa9\xe2\x82\xac\xf0\x9f\x9a\x97\"]",
                           "{\"\xc3\xa9\": {}}\r\n\t"}) {
    INFO(text);
    CHECK(compare_readers(text) == 2);
  }
  JsonValue v;
  CHECK(!parse_json_tree_fast(std::string(33, '[') + std::string(33, ']'), v));
  CHECK(!parse_json_tree_fast("{\"" + std::string(129, 'k') + "\": 1}", v));
  std::string many = "{";
  for (int k = 0; k < 65; ++k) many += (k ? ", \"k" : "\"k") + std::to_string(k) + "\": 0";
  CHECK(!parse_json_tree_fast(many + "}", v));  // more keys than the duplicate scan takes
  CHECK(compare_readers(many + "}") == 1);
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

// same_key compares keys of up to 16 bytes by overlapping word loads (json_tree.hpp): here against
// std::string_view's equality, on pairs of every length up to 24 from a two-letter alphabet, so that
// equal pairs, and pairs differing in one byte anywhere, are both common.
TEST_CASE("same_key is string equality, at every key length") {
  std::mt19937_64 g(5);
  int compared = 0, equal = 0;
  for (int n = 0; n < 200000; ++n) {
    std::string a(g() % 25, 'a');
    for (auto& c : a) c = g() % 8 == 0 ? 'b' : 'a';
    std::string b = a;
    if (g() % 2 && !b.empty()) b[g() % b.size()] ^= 3;
    if (g() % 8 == 0) b.push_back('a');
    CHECK(impact3d::case_format::same_key(a, b) == (std::string_view(a) == std::string_view(b)));
    ++compared;
    equal += a == b;
  }
  CHECK(compared == 200000);
  CHECK(equal > 50000);
  CHECK(equal < 150000);
}

}  // namespace check_json_tree
