// libFuzzer harness: any bytes as a batch CSV (the first line its header, the others rows). A header
// is refused or read; each row is refused or becomes JSON text, which for valid UTF-8 is valid JSON
// within the reader's limits; where the row's tree is built from its cells (case_tree, over the last
// row's tree as batch builds it), it is the tree that text reads as, and the case reader gives the same
// answer from both; never a crash, a hang or unbounded memory.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "impact3d/cli/batch_csv.hpp"
#include "impact3d/case_format/case_spec.hpp"
#include "impact3d/case_format/escape.hpp"
#include "impact3d/case_format/json_tree.hpp"
#include "json_tree_equal.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace impact3d;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const std::size_t nl = text.find('\n');
  std::optional<cli::csv::CaseColumns> columns;
  try {
    columns.emplace(text.substr(0, nl));
  } catch (const case_format::CaseError&) {
    return 0;
  }
  std::string_view rest = nl == std::string_view::npos ? std::string_view() : text.substr(nl + 1);
  cli::csv::RowTree row;  // kept from row to row, as case_spec keeps it
  while (!rest.empty()) {
    const std::size_t end = std::min(rest.find('\n'), rest.size());
    const std::string_view line = rest.substr(0, end);
    rest.remove_prefix(std::min(end + 1, rest.size()));
    std::string json;
    try {
      json = columns->case_json(line);
    } catch (const case_format::CaseError&) {
      continue;
    }
    std::vector<cli::csv::Cell> cells;
    columns->cells_of(line, cells);  // case_json took the row: the same cells
    const bool built = columns->case_tree(cells, row);
    const case_format::JsonValue& direct = row.tree();
    case_format::JsonValue tree;
    try {
      tree = case_format::parse_json_tree(json);
    } catch (const case_format::CaseError& e) {
      if (built) std::abort();  // the cells' tree where the text is refused
      if (case_format::valid_utf8(std::string(line)) && std::string_view(e.what()).rfind("invalid JSON", 0) == 0) std::abort();
      continue;
    }
    if (built && !case_format::json_tree_equal(direct, tree)) std::abort();
    std::string from_text, from_row;
    try {
      (void)case_format::read_case_tree(tree);
    } catch (const case_format::CaseError& e) {
      from_text = e.line();
    }
    try {
      (void)columns->case_spec(line);
    } catch (const case_format::CaseError& e) {
      from_row = e.line();
    }
    if (from_text != from_row) std::abort();
  }
  return 0;
}
