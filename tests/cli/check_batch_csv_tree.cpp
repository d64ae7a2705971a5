// The CSV case rows' two routes to the case reader (cli/library/include/impact3d/cli/batch_csv.hpp): the tree built straight
// from the cells (case_tree) against the text case_json writes read by case_format::parse_json_tree. Wherever
// the cells' tree is built it is the text's tree, value for value and bit for bit, and the case reader
// says the same of both; the rows it leaves to the text are those whose text the JSON reader's fast
// route would leave to the checking parser. The same is fuzzed by tests/fuzz/fuzz_batch_csv.cpp.
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "impact3d/cli/batch_csv.hpp"
#include "json_tree_equal.hpp"
#include "impact3d/case_format/case_spec.hpp"
#include "impact3d/case_format/json_tree.hpp"

namespace check_batch_csv_tree {

namespace {

using namespace impact3d;
using case_format::JsonValue;
using cli::csv::Cell;
using cli::csv::CaseColumns;
using cli::csv::RowTree;

// A case header with strings, numbers, nested arrays and an array of strategies rows may leave short.
const char* const kHeader =
    "name,units,restitution,vehicles[0].mass,vehicles[0].velocity[0],vehicles[0].velocity[1],vehicles[0].velocity[2],"
    "vehicles[0].inertia[0][0],vehicles[0].inertia[0][1],vehicles[1].mass,contact.normal_yaw_deg,"
    "strategy[0].name,strategy[0].mu,strategy[1].name,strategy[1].mu";

std::string csv_cell(const std::string& text, bool quoted) {
  if (!quoted) return text;
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + '"';
}

struct Routes {
  bool built = false;   // the cells' tree was built
  bool reused = false;  // built by writing over the leaves of the last row's tree
  bool same = false;    // built: equal to the text's tree and read alike; not built: the text read
};

Routes routes(const CaseColumns& columns, const std::string& line) {
  std::vector<Cell> cells;
  columns.cells_of(line, cells);
  static RowTree row;  // kept from row to row, as case_spec keeps it: the last row's tree is written over
  const JsonValue& direct = row.tree();
  Routes r;
  r.built = columns.case_tree(cells, row);
  r.reused = row.reused();
  JsonValue tree;
  try {
    tree = case_format::parse_json_tree(columns.case_json(line));
  } catch (const case_format::CaseError&) {
    r.same = !r.built;  // a text the JSON reader refuses must not have had a tree built from its cells
    return r;
  }
  if (r.built && !case_format::json_tree_equal(direct, tree)) return r;
  std::string from_text, from_row;
  try {
    (void)case_format::read_case_tree(tree);
  } catch (const case_format::CaseError& e) {
    from_text = e.line();
  }
  try {
    (void)columns.case_spec(line);
  } catch (const case_format::CaseError& e) {
    from_row = e.line();
  }
  r.same = from_text == from_row;
  return r;
}

}  // namespace

// Known rows, each built or left to the text for a reason the JSON reader's fast route has
// (case_format/src/json_tree.cpp): a "-0" integer read as 0, literals beyond the limits or a double's range, text that
// is not UTF-8.
TEST_CASE("exam: rows built from their cells, and rows left to the text") {
  const CaseColumns columns("a,b[0],b[1],c.d");
  struct Known {
    std::string line;
    bool built;
  };
  const std::vector<Known> rows = {
      {"1,2,3,x", true},
      {"-0,-0.0,0e0,\"7\"", true},
      {",,,", true},
      {"1,,,", true},
      {",,5,", true},
      {"h\xC3\xA9,1,2,3", true},
      {"\xFF,1,2,3", false},                           // not UTF-8
      {"1e400,1,2,3", false},                          // beyond a double: the checker names it
      {"1e-400,1,2,3", false},                         // below a double's least subnormal
      {"1e1001,1,2,3", false},                         // an exponent beyond the limit
      {std::string(257, '1') + ",1,2,3", false},       // a literal longer than the limit
      {"4e-320,007,+1,.5", true},                      // a subnormal; the rest are not JSON numbers: strings
  };
  for (const auto& k : rows) {
    INFO(k.line.substr(0, 40));
    const Routes r = routes(columns, k.line);
    CHECK(r.built == k.built);
    CHECK(r.same);
  }
  std::vector<Cell> cells;
  columns.cells_of("-0,1,2,3", cells);
  RowTree row;
  REQUIRE(columns.case_tree(cells, row));
  CHECK(!row.reused());
  const JsonValue& tree = row.tree();
  CHECK(tree.items[0].text == "0");  // as nlohmann reports the integer -0
  CHECK(tree.items[0].number == 0.0);
  CHECK(!std::signbit(tree.items[0].number));
  // The same cells filled: the leaves alone are written, then a string where a number stood.
  columns.cells_of("5,1e3,2,\"3\"", cells);
  REQUIRE(columns.case_tree(cells, row));
  CHECK(row.reused());
  CHECK(tree.items[0].number == 5.0);
  CHECK(tree.items[1].items[0].number == 1000.0);
  columns.cells_of("x,1,2,3", cells);
  REQUIRE(columns.case_tree(cells, row));
  CHECK(row.reused());
  CHECK(tree.items[0].type == JsonValue::Type::string);
  CHECK(tree.items[0].text == "x");
  CHECK(tree.items[0].number == 0.0);
  // Another header read with the same cells filled builds its own tree.
  const CaseColumns other("a,b[0],b[1],c.e");
  REQUIRE(other.case_tree(cells, row));
  CHECK(!row.reused());
  CHECK(tree.items[2].keys == std::vector<std::string>{"e"});
}

// An object whose members land where the last row's array left more items than the object has keys
// (the array has no keys): its leaves' places must not move while the tree is built. A review found the
// items grown with the keys past the room reserved, the next row of the same cells written through the
// old places. Each row is compared with the text's tree.
TEST_CASE("exam: an object built where the last row had an array keeps its leaves in place") {
  struct Rows {
    const char* header;
    std::vector<const char*> lines;
    int reused;  // rows that fill the cells the row before filled
  };
  const std::vector<Rows> known = {
      // Arrays of one to three elements before an object of two, three and four members: the room
      // reserved for the object is exact, and its last member's item went past it.
      {"a[0],b.p,b.q", {"1,,", ",2,3", ",4,5", ",6,7"}, 2},
      {"a[0],a[1],b.p,b.q,b.r", {"1,2,,,", ",,3,4,5", ",,6,7,8", ",,9,10,11"}, 2},
      {"a[0],a[1],a[2],b.p,b.q,b.r,b.s", {"1,2,3,,,,", ",,,4,5,6,7", ",,,8,9,10,11", ",,,1,2,3,4"}, 2},
      // An array trimmed on the row before leaves room for one more item, which the object's first
      // member took before the second's went past it (from the second review).
      {"a[0],a[1],a[2],a[3],b.p,b.q", {"1,2,3,4,,", "1,2,3,,,", ",,,,5,6", ",,,,7,8"}, 1}};
  for (const auto& k : known) {
    const CaseColumns columns(k.header);
    RowTree row;
    int reused = 0;
    for (const char* line : k.lines) {
      INFO(k.header << ": " << line);
      std::vector<Cell> cells;
      columns.cells_of(line, cells);
      REQUIRE(columns.case_tree(cells, row));
      reused += row.reused();
      CHECK(case_format::json_tree_equal(row.tree(), case_format::parse_json_tree(columns.case_json(line))));
    }
    CHECK(reused == k.reused);
  }
}

// Seeded random rows from fragments that reach every branch: numbers of every form, strings that look
// like numbers, quoted cells, empty cells inside arrays and whole strategies left out, bytes that are
// not UTF-8, control characters, literals beyond the limits.
TEST_CASE("check: the cells' tree is the text's tree on random rows") {
  const CaseColumns columns(kHeader);
  const std::vector<std::string> ordinary = {
      "", "", "0", "-0", "-0.0", "12", "1.5e3", "-2.25E-2", "4e-320", "0." + std::string(30, '1'), "abc", "SI", "US",
      "pc-crash", "h\xC3\xA9", "a\x01z", "007", "+1", ".5", "1.", "NaN", "-", "a\"b", "x,y", " 7 ", "\t8"};
  const std::vector<std::string> refused = {"1e-400", "1e400", "1e1001", "1e-1001", std::string(300, '9'), "\xFF",
                                            "\xED\xA0\x80"};
  std::mt19937_64 rng(20261124);
  const std::size_t width = 15;
  long built = 0, reused = 0, left = 0, rows = 0;
  for (int n = 0; n < 20000; ++n) {
    std::string line;
    for (std::size_t c = 0; c < width; ++c) {
      // One cell in 40 from the refused: about one row in three then holds one.
      const std::string& f = rng() % 40 == 0 ? refused[rng() % refused.size()] : ordinary[rng() % ordinary.size()];
      const bool must_quote = f.find_first_of(",\"") != std::string::npos;
      const bool quoted = must_quote || (rng() % 8 == 0);
      line += (c ? "," : "") + csv_cell(f, quoted);
    }
    const Routes r = routes(columns, line);
    INFO(line);
    REQUIRE(r.same);
    ++(r.built ? built : left);
    reused += r.reused;
    ++rows;
  }
  CHECK(rows == 20000);
  // Both routes taken many times: (39/40)^15 = 0.68 of the rows hold no refused cell (more are built,
  // since most refused fragments read as strings when quoted). A row fills the cells the last filled
  // with probability about ((24/26)^2 + (2/26)^2)^15 = 0.1 (the fragments hold two empty ones), and both
  // rows are built in about 0.7^2 of those: some 1 000 rows written over the last row's tree.
  CHECK(built > 10000);
  CHECK(left > 4000);
  CHECK(reused > 400);
}

// split against a reading of RFC 4180 one character at a time (written here for the test): the same
// cells, quoted or not, or a problem where it finds one, on random rows of quotes, doubled quotes,
// commas, spaces and carriage returns.
TEST_CASE("check: split reads rows as RFC 4180 does, one character at a time") {
  auto reference = [](std::string_view line, std::vector<Cell>& cells) -> bool {
    cells.clear();
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    std::size_t i = 0;
    for (;;) {
      Cell cell;
      if (i < line.size() && line[i] == '"') {
        cell.quoted = true;
        for (++i;; ++i) {
          if (i >= line.size()) return false;
          if (line[i] == '"') {
            if (i + 1 < line.size() && line[i + 1] == '"') ++i;
            else break;
          }
          cell.text += line[i];
        }
        ++i;
        if (i < line.size() && line[i] != ',') return false;
      } else {
        std::size_t end = i;
        while (end < line.size() && line[end] != ',') ++end;
        std::string t(line.substr(i, end - i));
        while (!t.empty() && (t.front() == ' ' || t.front() == '\t')) t.erase(0, 1);
        while (!t.empty() && (t.back() == ' ' || t.back() == '\t')) t.pop_back();
        cell.text = t;
        i = end;
      }
      cells.push_back(cell);
      if (i >= line.size()) return true;
      ++i;
    }
  };
  std::mt19937_64 g(4180);
  const std::string alphabet = "\"\",, \tab\r";
  int compared = 0, refused = 0;
  std::vector<Cell> mine, theirs;
  for (int n = 0; n < 20000; ++n) {
    std::string line;
    const std::size_t length = g() % 24;
    for (std::size_t k = 0; k < length; ++k) line += alphabet[g() % alphabet.size()];
    const bool ok = reference(line, theirs);
    const std::string problem = cli::csv::split(line, mine);
    ++compared;
    INFO(line);
    REQUIRE(problem.empty() == ok);
    if (!ok) {
      ++refused;
      continue;
    }
    REQUIRE(mine.size() == theirs.size());
    for (std::size_t c = 0; c < mine.size(); ++c) {
      CHECK(mine[c].text == theirs[c].text);
      CHECK(mine[c].quoted == theirs[c].quoted);
    }
  }
  CHECK(compared == 20000);
  CHECK(refused > 1000);            // unclosed quotes and text after them, exercised
  CHECK(compared - refused > 5000);  // rows read, quoted cells among them
}

}  // namespace check_batch_csv_tree
