// The result CSV's header, its rejected rows, and its rows taken from a result document's text.
#include "impact3d/case_format/result_csv.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "impact3d/case_format/escape.hpp"
#include "impact3d/case_format/json_path.hpp"
#include "impact3d/case_format/json_tree.hpp"
#include "impact3d/case_format/strategy_kinds.hpp"

namespace impact3d::case_format {
namespace {

// Each column's name, as result_csv_cells gives them.
struct Names {
  std::vector<std::string> names;
  template <typename... Ignored>
  void number(const char* name, const Ignored&...) { names.emplace_back(name); }
  template <typename... Ignored>
  void count(const char* name, const Ignored&...) { names.emplace_back(name); }
  template <typename... Ignored>
  void text(const char* name, const Ignored&...) { names.emplace_back(name); }
  template <typename... Ignored>
  void bound(const char* name, const Ignored&...) { names.emplace_back(name); }
  template <typename... Ignored>
  void vec(const char* name, const Ignored&...) {
    for (int i = 0; i < 3; ++i) names.push_back(fmt::format("{}[{}]", name, i));
  }
};

// The document's columns' names, as result_csv_document_cells gives them.
const std::vector<std::string>& document_column_names() {
  static const std::vector<std::string> names = [] {
    Names n;
    result_csv_document_cells(n, CaseSpec{}, "", Engine::generated);
    return std::move(n.names);
  }();
  return names;
}

}  // namespace

const std::vector<std::string>& result_csv_column_names() {
  static const std::vector<std::string> names = [] {
    Names n;
    const Solution<double> any{};
    result_csv_cells(n, any, Present<double>(Units::SI, 17));
    return std::move(n.names);
  }();
  return names;
}

std::string result_csv_header() {
  std::string out = "line,result,error";
  for (const auto& c : document_column_names()) out += ',' + c;
  out += ",strategy,regime";
  for (const auto& c : result_csv_column_names()) out += ',' + c;
  out += ",warnings\n";
  return out;
}

std::string result_csv_error(long line, const std::string& problem) {
  std::string out = fmt::format("{},,", line);
  put_csv_text(out, printable(problem));
  out.append(document_column_names().size() + 2 + result_csv_column_names().size() + 1, ',');  // ... strategy, regime, ..., warnings
  out += '\n';
  return out;
}

std::string strategy_cell_text(const StrategySpec& s) {
  // The keys and values write_strategy_echo writes (result_json.hpp), in its order.
  const KindRow row = strategy_kind(s.kind);
  std::string text(row.name), params;
  for (const auto& p : row.parameters) {
    params += params.empty() ? "" : ",";
    params += p.key;
    params += '=';
    if (p.type == ParameterType::choice) params += s.choice(p.key);
    else if (const auto& n = s.number(p.key)) params += n->text;
    else params += "critical";
  }
  return params.empty() ? text : text + ":" + params;
}

JsonPick result_csv_pick() {
  // Column c of the pick: the document's columns, result_csv_cells' columns, then each result's
  // regime and warnings (its strategy is the case's).
  std::vector<JsonPath> paths;
  for (const auto& c : document_column_names()) paths.push_back(parse_json_path(c, c));
  for (const auto& n : result_csv_column_names()) paths.push_back(under_each_result(parse_json_path(n, n)));
  for (const char* key : {"regime", "warnings"}) paths.push_back(under_each_result({PathStep::of_key(key)}));
  return JsonPick(paths, true);
}

std::string result_csv_from_document(std::string_view document, const JsonPick& pick, const CaseSpec& c, long line) {
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

}  // namespace impact3d::case_format
