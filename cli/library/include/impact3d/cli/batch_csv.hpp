// `impact3d batch --input-format csv` (docs/batch.md, "Cases as CSV"): a case per CSV row whose header names each
// column by the JSON path of the case field it fills. The result CSV is case_format/result_csv.hpp's.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "impact3d/case_format/case_spec.hpp"
#include "impact3d/case_format/json_tree.hpp"

namespace impact3d::cli::csv {

struct Cell {
  std::string text;
  bool quoted = false;
};

// A row's tree for the case reader, kept from row to row (one per thread): a row that fills the same
// cells as the last row read has the same tree but for its leaves, and only the leaves are written
// over. The leaves are held by address, so it is neither copied nor moved.
class RowTree {
 public:
  using Leaves = std::vector<std::pair<std::size_t, case_format::JsonValue*>>;  // each leaf and its cell's column
  RowTree() = default;
  RowTree(const RowTree&) = delete;
  RowTree& operator=(const RowTree&) = delete;
  const case_format::JsonValue& tree() const { return tree_; }
  bool reused() const { return reused_; }  // the last case_tree wrote the leaves alone

 private:
  friend class CaseColumns;
  case_format::JsonValue tree_;
  bool reused_ = false;
  std::uint64_t built_for_ = 0;  // the header (CaseColumns::id_) whose tree this is; 0: none
  std::vector<char> filled_;     // which cells the tree was built from held text
  Leaves leaves_;
};

// The cells of one line (RFC 4180, a row on one line; a trailing carriage return is dropped). Returns
// an empty string, or the problem.
std::string split(std::string_view line, std::vector<Cell>& cells);

// The header of a case CSV: each column a path of case-format.md ("vehicles[0].mass", "$.restitution",
// "strategy[0].mu"), together a tree of objects and dense arrays.
class CaseColumns {
 public:
  // Throws case_format::CaseError naming the column ("header column 3 (vehicles[0].mas[): ...").
  explicit CaseColumns(std::string_view header);
  // The row's case as JSON text: unquoted cells that read as JSON numbers are numbers, as written;
  // every other cell a string; an empty cell leaves its key out (null inside an array that has other
  // cells), and an object or array with no cell at all is left out. Throws case_format::CaseError at "$".
  std::string case_json(std::string_view line) const;
  // The row's case read as case_json's text would be read, by the shorter route where it can be taken:
  // the reader's tree built straight from the cells (case_tree). Throws case_format::CaseError.
  case_format::CaseSpec case_spec(std::string_view line) const;
  // The tree case_format::parse_json_tree(case_json(line)) gives, built from the row's cells without the text
  // into out.tree(). False (out.tree() then unspecified) for a row that parser would not take on its
  // fast route: a limit near, a string or key that is not valid UTF-8, a literal beyond a double's
  // range. Those rows are read from the text, so that the checking parser alone words every problem.
  bool case_tree(const std::vector<Cell>& cells, RowTree& out) const;
  // The row's cells, as many as the header has columns. Throws case_format::CaseError at "$".
  void cells_of(std::string_view line, std::vector<Cell>& cells) const;

  struct Node {
    enum class Kind { leaf, object, array } kind = Kind::leaf;
    std::size_t column = 0;
    std::vector<std::string> keys;  // objects: members[i] is keys[i]'s
    std::vector<Node> members;
    std::vector<Node> elements;
  };

 private:
  Node root_;
  std::uint64_t id_ = 0;  // one per header read: a RowTree knows whose tree it holds
  std::size_t columns_ = 0;
  std::size_t keys_bound_ = 0;  // the JSON text's bytes from keys and punctuation, at most
};

}  // namespace impact3d::cli::csv
