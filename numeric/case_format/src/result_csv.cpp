// The result CSV's header and its rejected rows.
#include "impact3d/case_format/result_csv.hpp"

#include <fmt/format.h>

#include "impact3d/case_format/escape.hpp"
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

}  // namespace impact3d::case_format
