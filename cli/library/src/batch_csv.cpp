// Case rows are read by the case reader as the JSON text of a case would be, so that a CSV case is
// checked exactly as a case file is and its errors name the same paths: from the reader's tree built
// straight from the cells where the JSON reader's fast route would give that tree (the last row's tree
// with its leaves written over, when the row fills the same cells), from the text otherwise. Result
// rows are written by case_format/result_csv.hpp.
#include "impact3d/cli/batch_csv.hpp"

#include <atomic>
#include <cctype>
#include <charconv>

#include <fmt/format.h>

#include "impact3d/case_format/case_spec.hpp"
#include "impact3d/case_format/decimal.hpp"
#include "impact3d/case_format/escape.hpp"
#include "impact3d/case_format/json_path.hpp"
#include "impact3d/case_format/json_writer.hpp"
#include "impact3d/case_format/limits.hpp"

namespace impact3d::cli::csv {
namespace {

using Node = CaseColumns::Node;
using case_format::JsonValue;

// `exponent`, when given, is told whether the number has an exponent part.
bool json_number(std::string_view s, bool* exponent = nullptr) {
  std::size_t i = 0;
  auto digits = [&] {
    const std::size_t start = i;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
    return i > start;
  };
  if (i < s.size() && s[i] == '-') ++i;
  if (i < s.size() && s[i] == '0') ++i;
  else if (!digits()) return false;
  if (i < s.size() && s[i] == '.' && (++i, !digits())) return false;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    if (exponent) *exponent = true;
    ++i;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    if (!digits()) return false;
  }
  return i == s.size();
}

// Fields the paths of one header may spell, containers and gaps included: a few per column, so that a
// header of sparse indices cannot build a large tree.
constexpr std::size_t kMaxNodes = 4 * case_format::limits::kCsvColumns;

void insert(Node& root, const case_format::JsonPath& steps, std::size_t column, const std::string& where, std::size_t& nodes) {
  Node* node = &root;
  node->kind = Node::Kind::object;
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const case_format::PathStep& s = steps[k];
    Node* child = nullptr;
    if (s.kind == case_format::PathStep::Kind::index) {
      if (node->kind != Node::Kind::array) throw case_format::CaseError(where, "an index where another column has a key");
      if (node->elements.size() <= s.index) {
        nodes += s.index + 1 - node->elements.size();
        if (nodes > kMaxNodes) throw case_format::CaseError(where, fmt::format("the header spells more than {} fields", kMaxNodes));
        node->elements.resize(s.index + 1, Node{Node::Kind::leaf, SIZE_MAX, {}, {}, {}});
      }
      child = &node->elements[s.index];
    } else {
      if (node->kind != Node::Kind::object) throw case_format::CaseError(where, "a key where another column has an index");
      for (std::size_t m = 0; m < node->keys.size(); ++m)
        if (node->keys[m] == s.key) child = &node->members[m];
      if (!child) {
        if (++nodes > kMaxNodes) throw case_format::CaseError(where, fmt::format("the header spells more than {} fields", kMaxNodes));
        node->keys.push_back(s.key);
        child = &node->members.emplace_back(Node{Node::Kind::leaf, SIZE_MAX, {}, {}, {}});
      }
    }
    const bool last = k + 1 == steps.size();
    const bool fresh = child->kind == Node::Kind::leaf && child->column == SIZE_MAX && child->members.empty() && child->elements.empty();
    if (last) {
      if (!fresh) throw case_format::CaseError(where, "the same field as another column, or a field another column is inside");
      child->column = column;
    } else {
      const Node::Kind want = steps[k + 1].kind == case_format::PathStep::Kind::index ? Node::Kind::array : Node::Kind::object;
      if (fresh) child->kind = want;
      else if (child->kind == Node::Kind::leaf) throw case_format::CaseError(where, "inside a field another column fills");
    }
    node = child;
  }
}

void check_dense(const Node& node, const std::string& path) {
  for (std::size_t i = 0; i < node.elements.size(); ++i) {
    const Node& e = node.elements[i];
    const std::string p = path + "[" + std::to_string(i) + "]";
    if (e.kind == Node::Kind::leaf && e.column == SIZE_MAX) throw case_format::CaseError("header", fmt::format("no column for {}", p));
    check_dense(e, p);
  }
  for (std::size_t m = 0; m < node.keys.size(); ++m) check_dense(node.members[m], path + "." + node.keys[m]);
}

bool any(const Node& n, const std::vector<Cell>& cells) {
  if (n.kind == Node::Kind::leaf) return !cells[n.column].text.empty();
  for (const auto& m : n.members)
    if (any(m, cells)) return true;
  for (const auto& e : n.elements)
    if (any(e, cells)) return true;
  return false;
}

void emit(const Node& n, const std::vector<Cell>& cells, std::string& out) {
  switch (n.kind) {
    case Node::Kind::leaf: {
      const Cell& c = cells[n.column];
      if (c.text.empty()) out += "null";
      else if (!c.quoted && json_number(c.text)) out += c.text;
      else case_format::JsonWriter::append_quoted(out, c.text);
      return;
    }
    case Node::Kind::object: {
      out += '{';
      bool first = true;
      for (std::size_t m = 0; m < n.keys.size(); ++m) {
        if (!any(n.members[m], cells)) continue;
        if (!first) out += ", ";
        first = false;
        case_format::JsonWriter::append_quoted(out, n.keys[m]);
        out += ": ";
        emit(n.members[m], cells, out);
      }
      out += '}';
      return;
    }
    case Node::Kind::array: {
      // Trailing elements with no cell are left out, so that rows may hold fewer strategies than the
      // header has columns for.
      std::size_t size = n.elements.size();
      while (size > 0 && !any(n.elements[size - 1], cells)) --size;
      out += '[';
      for (std::size_t i = 0; i < size; ++i) {
        if (i) out += ", ";
        emit(n.elements[i], cells, out);
      }
      out += ']';
      return;
    }
  }
}

// What the fast route of case_format::parse_json_tree does with case_json's text (case_format/src/json_tree.cpp, Walk), done
// on the cells: the same values counted in the same order against the same limits, a number's literal
// and value as that reader takes them. Whatever it would hand to the checking parser, this refuses.
class TreeBuilder {
 public:
  using Leaves = RowTree::Leaves;
  // `leaves`, when given, is told where each leaf stands in `out` (RowTree).
  TreeBuilder(const std::vector<Cell>& cells, Leaves* leaves) : cells_(cells), leaves_(leaves) {}

  // The leaves of a tree built for a row that filled the same cells, written from this row's cells:
  // the rest of the tree, and every limit value() counts, depend on which cells are filled alone.
  static bool refresh(const std::vector<Cell>& cells, const Leaves& leaves) {
    for (const auto& [column, v] : leaves) {
      clear_scalar(*v);
      if (!leaf(cells[column], *v)) return false;
    }
    return true;
  }

  // `out` may hold the last row's tree: its strings and vectors are written over, not made again.
  bool value(const Node& n, JsonValue& out, std::size_t depth) {
    ++values_;
    if (values_ >= case_format::limits::kValues || depth + 1 >= static_cast<std::size_t>(case_format::limits::kDepth)) return false;
    clear_scalar(out);
    std::size_t count = 0;
    bool ok = true;
    switch (n.kind) {
      case Node::Kind::leaf:
        ok = leaf(cells_[n.column], out);
        if (leaves_) leaves_->emplace_back(n.column, &out);
        break;
      case Node::Kind::object: {
        out.type = JsonValue::Type::object;
        // Room for every member first: a leaf's address, once told, stays while the tree is built. The
        // items may outnumber the keys (an array of the last row stood here): each grows on its own.
        out.keys.reserve(n.keys.size());
        out.items.reserve(n.keys.size());
        for (std::size_t m = 0; ok && m < n.keys.size(); ++m) {
          if (!any(n.members[m], cells_)) continue;
          const std::string& key = n.keys[m];
          if (count >= kScannedKeys || key.size() > case_format::limits::kKeyChars || !text_ok(key)) {
            ok = false;
            break;
          }
          if (count == out.keys.size()) out.keys.emplace_back();
          if (count == out.items.size()) out.items.emplace_back();
          if (!case_format::same_key(out.keys[count], key)) out.keys[count] = key;  // mostly the last row's key
          ok = value(n.members[m], out.items[count++], depth + 1);
        }
        out.keys.resize(count);
        break;
      }
      case Node::Kind::array: {
        std::size_t size = n.elements.size();
        while (size > 0 && !any(n.elements[size - 1], cells_)) --size;
        out.type = JsonValue::Type::array;
        out.keys.clear();
        out.items.reserve(size);
        for (; ok && count < size; ++count) {
          if (count == out.items.size()) out.items.emplace_back();
          ok = value(n.elements[count], out.items[count], depth + 1);
        }
        break;
      }
    }
    if (n.kind == Node::Kind::leaf) out.keys.clear();
    out.items.resize(count);
    return ok;
  }

 private:
  static constexpr std::size_t kScannedKeys = 64;  // the fast reader scans for duplicates up to this many keys

  static void clear_scalar(JsonValue& v) {
    v.flag = false;
    v.number = 0;
    v.text.clear();
  }

  static bool text_ok(std::string_view s) {
    for (const char c : s)
      if (static_cast<unsigned char>(c) >= 0x80) return case_format::valid_utf8(s);
    return true;
  }

  static bool leaf(const Cell& c, JsonValue& out) {
    if (c.text.empty()) {
      out.type = JsonValue::Type::null;
      return true;
    }
    bool exponent = false;
    if (c.quoted || !json_number(c.text, &exponent)) {
      if (!text_ok(c.text)) return false;
      out.type = JsonValue::Type::string;
      out.text.append(c.text);  // empty: value() and refresh() clear it, and append is the shorter call
      return true;
    }
    std::string_view raw = c.text;
    if (raw.size() > case_format::limits::kLiteralChars) return false;
    const long e = exponent ? case_format::written_exponent(raw) : 0;
    if (e > case_format::limits::kExponent || e < -case_format::limits::kExponent) return false;
    double x;
    const auto r = std::from_chars(raw.data(), raw.data() + raw.size(), x);
    if (r.ec != std::errc() || r.ptr != raw.data() + raw.size()) return false;
    if (raw == "-0") raw = "0", x = 0;  // an integer as nlohmann reports it (json_tree.cpp)
    out.type = JsonValue::Type::number;
    out.text.append(raw);
    out.number = x;
    return true;
  }

  const std::vector<Cell>& cells_;
  Leaves* leaves_;
  std::size_t values_ = 0;
};

// Bytes case_json may write for `n`, its keys and punctuation, without its cells' texts.
std::size_t keys_bound(const Node& n) {
  std::size_t bytes = 16;
  for (std::size_t m = 0; m < n.keys.size(); ++m) bytes += 6 * n.keys[m].size() + 16 + keys_bound(n.members[m]);
  for (const auto& e : n.elements) bytes += 16 + keys_bound(e);
  return bytes;
}

}  // namespace

std::string split(std::string_view line, std::vector<Cell>& cells) {
  // The cells' strings are kept from the last row and written over: no allocation a cell once warm.
  std::size_t count = 0;
  struct Trim {
    std::vector<Cell>& cells;
    std::size_t& count;
    ~Trim() { cells.resize(count); }
  } trim{cells, count};
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  // As a JSON Lines row with one is refused; the byte would otherwise become a \u0000 escape.
  if (const auto nul = line.find('\0'); nul != std::string_view::npos) return fmt::format("a NUL byte at offset {}", nul);
  std::size_t i = 0;
  for (;;) {
    if (count == case_format::limits::kCsvColumns) return fmt::format("more than {} cells", case_format::limits::kCsvColumns);
    if (count == cells.size()) cells.emplace_back();
    Cell& cell = cells[count++];
    cell.text.clear();
    cell.quoted = false;
    if (i < line.size() && line[i] == '"') {
      cell.quoted = true;
      // Runs up to the next quote are copied whole; a doubled quote is one quote of the text.
      for (++i;;) {
        const std::size_t quote = line.find('"', i);
        if (quote == std::string_view::npos) return fmt::format("cell {}: a quote not closed on its line", count);
        cell.text.append(line.data() + i, quote - i);
        i = quote + 1;
        if (i < line.size() && line[i] == '"') {
          cell.text += '"';
          ++i;
        } else {
          break;
        }
      }
      if (i < line.size() && line[i] != ',') return fmt::format("cell {}: text after the closing quote", count);
    } else {
      std::size_t end = i;  // cells are short: a loop, not a call to memchr each
      while (end < line.size() && line[end] != ',') ++end;
      std::size_t from = i, to = end;  // trimmed of spaces and tabs
      while (from < to && (line[from] == ' ' || line[from] == '\t')) ++from;
      while (to > from && (line[to - 1] == ' ' || line[to - 1] == '\t')) --to;
      cell.text.append(line.data() + from, to - from);  // cleared above
      i = end;
    }
    if (i >= line.size()) return {};
    ++i;  // the comma
  }
}

CaseColumns::CaseColumns(std::string_view header) {
  static std::atomic<std::uint64_t> headers{0};
  id_ = ++headers;
  if (header.substr(0, 3) == "\xEF\xBB\xBF") header.remove_prefix(3);  // the byte order mark spreadsheets write
  std::vector<Cell> cells;
  if (const std::string problem = split(header, cells); !problem.empty()) throw case_format::CaseError("header", problem);
  root_.kind = Node::Kind::object;
  std::size_t nodes = 0;
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const std::string where = fmt::format("header column {} ({})", c + 1, case_format::quoted(cells[c].text.substr(0, 80)));
    insert(root_, case_format::parse_json_path(cells[c].text, where), c, where, nodes);
  }
  check_dense(root_, "$");
  columns_ = cells.size();
  keys_bound_ = keys_bound(root_);
}

void CaseColumns::cells_of(std::string_view line, std::vector<Cell>& cells) const {
  if (const std::string problem = split(line, cells); !problem.empty()) throw case_format::CaseError("$", "not a CSV row: " + problem);
  if (cells.size() != columns_)
    throw case_format::CaseError("$", fmt::format("{} cells, but the header has {} columns", cells.size(), columns_));
}

std::string CaseColumns::case_json(std::string_view line) const {
  std::vector<Cell> cells;
  cells_of(line, cells);
  std::string out;
  out.reserve(line.size() * 2 + 64);
  emit(root_, cells, out);
  return out;
}

bool CaseColumns::case_tree(const std::vector<Cell>& cells, RowTree& out) const {
  out.reused_ = false;
  // The fast reader refuses a text above the case file's size; every cell escaped at most sixfold.
  std::size_t bytes = keys_bound_;
  for (const auto& c : cells) bytes += 6 * c.text.size() + 2;
  if (bytes > case_format::limits::kCaseFileBytes) return false;
  bool same = out.built_for_ == id_ && out.filled_.size() == cells.size();
  out.built_for_ = 0;  // until the tree is whole again: a throw (bad_alloc) leaves nothing to reuse
  out.filled_.resize(cells.size());
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const char filled = cells[c].text.empty() ? 0 : 1;
    same = same && out.filled_[c] == filled;
    out.filled_[c] = filled;
  }
  bool whole;
  if (same) {
    whole = out.reused_ = TreeBuilder::refresh(cells, out.leaves_);
  } else {
    out.leaves_.clear();
    whole = TreeBuilder(cells, &out.leaves_).value(root_, out.tree_, 0);
  }
  if (whole) out.built_for_ = id_;
  return whole;
}

case_format::CaseSpec CaseColumns::case_spec(std::string_view line) const {
  thread_local std::vector<Cell> cells;
  thread_local RowTree row;
  cells_of(line, cells);
  if (case_tree(cells, row)) return case_format::read_case_tree(row.tree());
  std::string text;
  text.reserve(line.size() * 2 + 64);
  emit(root_, cells, text);
  return case_format::read_case(text);
}

}  // namespace impact3d::cli::csv
