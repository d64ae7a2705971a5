// The result CSV's rows taken from the text of a result document (result_json.hpp) as it is written,
// cell by cell at each column's path: the independent route check_result_csv holds result_csv_rows to.
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "impact3d/case_format/csv_text.hpp"
#include "impact3d/case_format/json_path.hpp"
#include "impact3d/case_format/json_pick.hpp"
#include "impact3d/case_format/json_text.hpp"
#include "impact3d/case_format/json_tree.hpp"
#include "impact3d/case_format/result_csv.hpp"

namespace impact3d::test {
using namespace impact3d::case_format;

// The document's own columns, as the header names them: between "line,result,error" and "strategy".
inline const std::vector<std::string>& document_column_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> all(1);
    for (const char c : result_csv_header()) {
      if (c == ',') all.emplace_back();
      else if (c != '\n') all.back() += c;
    }
    const auto strategy = std::find(all.begin(), all.end(), "strategy");
    return std::vector<std::string>(all.begin() + 3, strategy);
  }();
  return names;
}

inline JsonPick result_csv_pick() {
  // Column c of the pick: the document's columns, result_csv_cells' columns, then each result's
  // regime and warnings (its strategy is the case's).
  std::vector<JsonPath> paths;
  for (const auto& c : document_column_names()) paths.push_back(parse_json_path(c, c));
  for (const auto& n : result_csv_column_names()) paths.push_back(under_each_result(parse_json_path(n, n)));
  for (const char* key : {"regime", "warnings"}) paths.push_back(under_each_result({PathStep::of_key(key)}));
  return JsonPick(paths, true);
}

inline std::string result_csv_from_document(std::string_view document, const JsonPick& pick, const CaseSpec& c, long line) {
  const std::size_t documents = document_column_names().size(), columns = documents + result_csv_column_names().size();
  const std::size_t regime = columns, warnings = columns + 1, width = columns + 2;
  auto of_document = [&](std::size_t column) { return column < documents; };
  // The span of each (result, column): the document's columns sit in every result's row.
  std::size_t results = 0;
  for (const auto& s : pick.spans())
    if (!of_document(s.column)) results = std::max(results, s.group + 1);
  constexpr std::size_t kMissing = ~std::size_t{0};
  thread_local std::vector<std::size_t> at;  // kept from row to row: no allocation once warm
  at.assign(results * width, kMissing);
  const auto& spans = pick.spans();
  for (std::size_t i = 0; i < spans.size(); ++i) {
    const auto& s = spans[i];
    if (!of_document(s.column)) at[s.group * width + s.column] = i;
    else
      for (std::size_t k = 0; k < results; ++k) at[k * width + s.column] = i;
  }
  JsonText out;
  out.reserve(1024 * std::max<std::size_t>(results, 1));
  auto text_of = [&](std::size_t k, std::size_t column) -> std::optional<std::string_view> {
    const std::size_t i = at[k * width + column];
    if (i == kMissing) return std::nullopt;
    return document.substr(spans[i].begin, spans[i].end - spans[i].begin);
  };
  // A cell as the document has it: a string as the writer was given it, a number or literal as written
  // (null: an empty cell).
  auto cell = [&](std::size_t k, std::size_t column) {
    const auto text = text_of(k, column);
    if (!text) return;
    const std::size_t i = at[k * width + column];
    if (spans[i].string != JsonPick::kNoString) put_csv_text(out, pick.string(spans[i]));
    else if (*text != "null") out += *text;
  };
  // The warnings are an array: short, read as JSON.
  JsonValue scratch;
  auto container = [&](std::string_view text) -> const JsonValue& {
    if (!parse_json_tree_fast(text, scratch, true)) throw std::runtime_error("the result document's value does not read back");
    return scratch;
  };
  for (std::size_t k = 0; k < results; ++k) {
    out += fmt::format("{},{},", line, k);
    for (std::size_t c = 0; c < documents; ++c) out += ',', cell(k, c);
    out += ',';
    if (k < c.strategies.size()) put_csv_text(out, strategy_cell_text(c.strategies[k]));
    out += ',';
    cell(k, regime);
    for (std::size_t c = documents; c < columns; ++c) out += ',', cell(k, c);
    out += ',';
    if (const auto text = text_of(k, warnings); text && *text != "[]") {
      std::string joined;
      if (const JsonValue& w = container(*text); w.is(JsonValue::Type::array))
        for (const auto& item : w.items) joined += (joined.empty() ? "" : " | ") + item.text;
      put_csv_text(out, joined);
    }
    out += '\n';
  }
  return std::move(out).take();
}

}  // namespace impact3d::test
