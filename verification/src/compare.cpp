#include "impact3d/verification/compare.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <numbers>
#include <optional>
#include <set>
#include <string_view>
#include <system_error>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "impact3d/case_format/case_spec.hpp"
#include "impact3d/case_format/escape.hpp"
#include "impact3d/case_format/json_literals.hpp"
#include "impact3d/case_format/limits.hpp"

#include "compare_diagnosis.hpp"

namespace impact3d::verification {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;
using case_format::CaseError;

// A CSV cell holds a number or a short string; anything longer is not a result.
constexpr std::size_t kCellChars = 256;

// The fields the contract requires: of the document, and of each result (paths below results[i]).
const std::vector<std::string> kContractTop = {"coefficients.m_prime", "coefficients.K"};
const std::vector<std::string> kContractResult = {
    "regime",     "impulse_ratio", "limits", "impulse.contact", "impulse.world", "relative_velocity.before",
    "relative_velocity.after", "vehicles.0.velocity", "vehicles.0.angular_velocity", "vehicles.0.delta_v",
    "vehicles.1.velocity", "vehicles.1.angular_velocity", "vehicles.1.delta_v", "energy.before", "energy.after",
    "energy.loss"};

// One scalar of the reference that compare checks. A null (an undefined angle) is kept so that a CSV
// may name its column, but it is never compared or counted.
struct Leaf {
  std::vector<std::string> parts;  // keys, and array indices as decimal text
  std::string dotted;              // parts joined with '.', as a CSV column names it
  json value;
  bool contract;
};

struct RefCase {
  std::string name, file;
  std::vector<Leaf> top;                   // below the document's root
  std::vector<std::vector<Leaf>> results;  // below results[i]
  std::size_t fields = 0;                  // leaves that are compared (not null)
  double largest = 0;                      // the largest magnitude among the numbers compared
  std::vector<std::unordered_map<std::string, double>> numbers;  // by result: its numbers by dotted path
};

struct Field {
  Field(std::string path_, bool pass_, double rel_ = 0, std::string detail_ = "", bool compared_ = false)
      : path(std::move(path_)), pass(pass_), rel(rel_), detail(std::move(detail_)), compared(compared_) {}
  std::string path;
  bool pass;
  double rel = 0;
  std::string detail;
  bool compared = false;  // the other side gave a value (not a missing field or a whole-case failure)
  std::string leaf;       // the reference leaf compared: below its result, or from the top
  int result = -1;        // that result's index; -1 from the top
  std::optional<double> reference, other;  // both numbers, where both were numbers
  double rtol = 0, atol = 0;               // the tolerance the number was held to
  double excess = 0;                       // |other - reference| / (atol + rtol |reference|); above 1 fails
  double abs_error = 0;
};

struct CaseReport {
  std::string name;
  std::vector<Field> fields;
  bool whole = false;           // the case failed as a whole (its one field says why)
  std::optional<double> rtol;   // with --rtol-from-bound: the case's own
};

// The field of a result that --rtol-from-bound takes a case's tolerance from.
constexpr const char* kBoundKey = "rounding_bound";

std::string join(const std::vector<std::string>& parts) {
  std::string s;
  for (std::size_t i = 0; i < parts.size(); ++i) s.append(i ? "." : "").append(parts[i]);
  return s;
}

std::vector<std::string> split_dots(const std::string& s) {
  std::vector<std::string> out;
  for (std::size_t start = 0;;) {
    const auto dot = s.find('.', start);
    out.push_back(s.substr(start, dot - start));
    if (dot == std::string::npos) return out;
    start = dot + 1;
  }
}

// Iterative: the nesting of a file is input, never a bound on the stack. Below the top every leaf is
// the contract's; below a result, those at or below a kContractResult path.
void collect(const json& root, std::vector<std::string> prefix, bool top, std::vector<Leaf>& out) {
  struct Item {
    const json* node;
    std::vector<std::string> parts;
  };
  std::vector<Item> stack;
  stack.push_back({&root, std::move(prefix)});
  while (!stack.empty()) {
    Item item = std::move(stack.back());
    stack.pop_back();
    const json& node = *item.node;
    if (node.is_object() || node.is_array()) {
      std::vector<Item> children;
      std::size_t i = 0;
      for (auto it = node.begin(); it != node.end(); ++it, ++i) {
        // A momentum residual over its rounding bound measures the precision that computed it, as the
        // rounding bound does: it is no result to compare.
        if (node.is_object() && it.key() == "residual_over_bound") continue;
        auto parts = item.parts;
        parts.push_back(node.is_object() ? it.key() : std::to_string(i));
        children.push_back({&*it, std::move(parts)});
      }
      for (auto it = children.rbegin(); it != children.rend(); ++it) stack.push_back(std::move(*it));
      continue;
    }
    Leaf leaf{item.parts, join(item.parts), node, top};
    for (const auto& c : kContractResult)
      leaf.contract = leaf.contract || leaf.dotted == c || leaf.dotted.rfind(c + ".", 0) == 0;
    out.push_back(std::move(leaf));
  }
}

// The node at `parts` below `root`, or null; array indices are read from the reference's own text.
const json* find(const json& root, const std::vector<std::string>& parts) {
  const json* node = &root;
  for (const auto& part : parts) {
    if (node->is_object()) {
      const auto it = node->find(part);
      if (it == node->end()) return nullptr;
      node = &*it;
    } else if (node->is_array()) {
      std::size_t i = 0;
      const char* end = part.data() + part.size();
      const auto [p, ec] = std::from_chars(part.data(), end, i);
      if (ec != std::errc() || p != end || i >= node->size()) return nullptr;
      node = &(*node)[i];
    } else {
      return nullptr;
    }
  }
  return node;
}

json read_json(const std::string& file) {
  return case_format::parse_json_bounded(case_format::read_text_file(file, case_format::limits::kResultFileBytes), file + ": $", case_format::limits::kResultDepth);
}

RefCase load_reference(const std::string& name, const std::string& file) {
  const json doc = read_json(file);
  const auto results = doc.is_object() ? doc.find("results") : doc.end();
  if (!doc.is_object() || results == doc.end())
    throw CaseError(file + ": $.results", "missing (a reference result is an object with a \"results\" array)");
  if (!results->is_array()) throw CaseError(file + ": $.results", "not an array");
  RefCase rc{name, file, {}, {}, 0, 0, {}};
  for (const auto& path : kContractTop) {
    auto parts = split_dots(path);
    if (const json* v = find(doc, parts)) collect(*v, std::move(parts), true, rc.top);
  }
  for (std::size_t i = 0; i < results->size(); ++i) {
    const json& r = (*results)[i];
    if (!r.is_object()) throw CaseError(file + ": " + case_format::element_path("$.results", i), "not an object");
    auto& leaves = rc.results.emplace_back();
    // The strategy echoes the input, the warnings are prose, the rounding bound belongs to the
    // precision that computed the result, and the decisions to the ball arithmetic that proved it: none
    // is a result to compare.
    for (const auto& [k, v] : r.items())
      if (k != "strategy" && k != "warnings" && k != "rounding_bound" && k != "decisions") collect(v, {k}, false, leaves);
    auto& numbers = rc.numbers.emplace_back();
    for (const auto& l : leaves)
      if (l.value.is_number()) numbers.emplace(l.dotted, l.value.get<double>());
  }
  const auto count = [&](const std::vector<Leaf>& v) {
    for (const auto& l : v) {
      rc.fields += l.value.is_null() ? 0 : 1;
      if (l.value.is_number()) rc.largest = std::max(rc.largest, std::fabs(l.value.get<double>()));
    }
  };
  count(rc.top);
  for (const auto& r : rc.results) count(r);
  return rc;
}

// Other people's text in a detail: quoted, and cut short.
std::string excerpt(std::string_view s) {
  return s.size() > 60 ? case_format::quoted(s.substr(0, 60)) + "..." : case_format::quoted(s);
}

std::string describe(const json& v) {
  if (v.is_string()) return excerpt(v.get_ref<const std::string&>());
  if (v.is_object()) return "an object";
  if (v.is_array()) return "an array";
  if (v.is_number()) return fmt::format("{:.17g}", v.get<double>());
  return v.dump();
}

bool ends_with(const std::string& s, std::string_view tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

struct Tolerance {
  double rtol, atol;
};

class Comparer {
 public:
  explicit Comparer(const CompareOptions& o) : o_(o), tol_{o.rtol, o.atol} {}

  bool required(const Leaf& l) const { return !o_.subset && (l.contract || o_.all_fields); }

  bool subset() const { return o_.subset; }

  // The reference has null (an angle undefined here, as a swerve angle with no sliding after) and the other
  // side a value: a value where there is none is a failure, not something to skip.
  Field undefined_here(const std::string& path, const Leaf& l, int result, const std::string& other) const {
    Field f{path, false, 0, "reference null (undefined here), other " + other, true};
    f.leaf = l.dotted;
    f.result = result;
    return f;
  }

  Field missing(const std::string& path, const char* what = "missing") const { return {path, false, 0, what}; }

  // `result`: the index of the reference result the leaf belongs to, -1 for a leaf from the top.
  Field from_json(const std::string& path, const Leaf& l, int result, const json& other) const {
    Field f = [&] {
      if (l.value.is_number()) {
        if (!other.is_number()) return mismatch(path, l, describe(other), ": not a number");
        const double b = other.get<double>();
        if (!std::isfinite(b)) return mismatch(path, l, describe(other), ": not a finite number");
        return number(path, l, b);
      }
      return Field{path, other == l.value, 0, other == l.value ? "" : mismatch(path, l, describe(other), "").detail, true};
    }();
    f.leaf = l.dotted;
    f.result = result;
    return f;
  }

  Field from_cell(const std::string& path, const Leaf& l, int result, std::string_view cell) const {
    Field f = [&] {
      if (l.value.is_number()) {
        const std::string text(cell);  // at most kCellChars
        char* end = nullptr;
        const double b = std::strtod(text.c_str(), &end);
        // The whole cell, NUL bytes included: "1\0junk" is not the number 1.
        if (end != text.c_str() + text.size() || text.empty()) return mismatch(path, l, excerpt(cell), ": not a number");
        if (!std::isfinite(b)) return mismatch(path, l, excerpt(cell), ": not a finite number");
        return number(path, l, b);
      }
      const std::string want = l.value.is_string() ? l.value.get<std::string>() : l.value.dump();
      return Field{path, cell == want, 0, cell == want ? "" : mismatch(path, l, excerpt(cell), "").detail, true};
    }();
    f.leaf = l.dotted;
    f.result = result;
    return f;
  }

  // A result file: every reference leaf looked up in it; shape errors in `other` are failing fields.
  // With --rtol-from-bound, at the tolerance the file's own rounding bound gives the case.
  CaseReport compare_json(const RefCase& rc, const json& other, const std::string& file) const {
    return compare_json_at(rc, other, file);
  }

 private:
  Field number(const std::string& path, const Leaf& l, double b) const {
    const double a = l.value.get<double>();
    double d = std::fabs(b - a);
    // Angles in degrees wrap: 180 and -180 (or 0 and 360) are the same direction.
    if (!l.parts.empty() && ends_with(l.parts.back(), "_deg")) d = std::fabs(std::remainder(b - a, 360.0));
    // A relative error is reported only where the value stands above the absolute tolerance.
    const double rel = std::fabs(a) > tol_.atol ? d / std::fabs(a) : 0;
    const double allowed = tol_.atol + tol_.rtol * std::fabs(a);
    Field f{path, d <= allowed, rel, fmt::format("reference {:.17g}, other {:.17g}", a, b), true};
    f.reference = a;
    f.other = b;
    f.rtol = tol_.rtol;
    f.atol = tol_.atol;
    f.excess = allowed > 0 ? d / allowed : (d > 0 ? INFINITY : 0);
    f.abs_error = d;
    return f;
  }

  Field mismatch(const std::string& path, const Leaf& l, const std::string& other, const char* why) const {
    return {path, false, 0, fmt::format("reference {}, other {}{}", describe(l.value), other, why), true};
  }

  CaseReport compare_json_at(const RefCase& rc, const json& other, const std::string& file) const {
    if (!other.is_object()) throw CaseError(file + ": $", "not an object (a result file is the contract's result JSON)");
    if (!o_.rtol_from_bound) return compare_fields(rc, other);
    std::string why;
    const auto bound = case_bound(rc, other, why);
    if (!bound) return CaseReport{rc.name, {{kBoundKey, false, 0, why}}, true, std::nullopt};
    Comparer at = *this;
    at.tol_ = {*bound, *bound * rc.largest};
    CaseReport r = at.compare_fields(rc, other);
    r.rtol = *bound;
    return r;
  }

  // --rtol-from-bound: the largest rounding_bound of the other side's results of this case (impact3d
  // writes one per result: the relative bound of its precision, rounding.hpp); every result compared
  // must give a finite one. Empty, with the reason, when one does not.
  std::optional<double> case_bound(const RefCase& rc, const json& other, std::string& why) const {
    const auto results = other.find("results");
    if (results == other.end() || !results->is_array()) {
      why = "no results to take the rounding bound from (--rtol-from-bound)";
      return std::nullopt;
    }
    std::optional<double> bound;
    for (std::size_t i = 0; i < rc.results.size() && i < results->size(); ++i) {
      const json& o = (*results)[i];
      if (!o.is_object()) continue;  // a failing field of its own
      const auto b = o.find(kBoundKey);
      const bool ok = b != o.end() && b->is_number() && std::isfinite(b->get<double>()) && b->get<double>() >= 0;
      if (!ok) {
        why = fmt::format("results.{}.{} is {}: --rtol-from-bound takes the case's tolerance from it", i, kBoundKey,
                          b == o.end() ? std::string("missing") : describe(*b) + ", not a finite number >= 0");
        return std::nullopt;
      }
      bound = std::max(bound.value_or(0.0), b->get<double>());
    }
    if (!bound) why = "no result gives a rounding bound (--rtol-from-bound)";
    return bound;
  }

  // --rtol-from-bound: an angle is the direction of a vector whose components are held to atol, so a
  // small vector has a poorly determined angle (a sliding that nearly stops swerves anywhere). The angle
  // is held to the arc atol / L of that vector's length L in the reference, in degrees, and never to
  // less than atol: L is the smaller of the sliding speeds before and after for the swerve angle, the
  // contact-plane impulse for the plane angle, |Delta-V| for the PDOF (its body x-y part is not in
  // the file) and the horizontal velocity after for the heading after. Other fields, and an angle whose L the file does not give, are held to atol.
  double angle_atol(const std::unordered_map<std::string, double>& numbers, const Leaf& l) const {
    const auto get = [&](const std::string& path) {
      const auto it = numbers.find(path);
      return it == numbers.end() ? std::optional<double>() : std::optional<double>(std::fabs(it->second));
    };
    std::optional<double> length;
    if (l.dotted == "sliding.swerve_angle_deg") {
      const auto before = get("sliding.before"), after = get("sliding.after");
      if (before && after) length = std::min(*before, *after);
    } else if (l.dotted == "plane_angle_deg") {
      const auto t = get("impulse.contact.1"), z = get("impulse.contact.2");
      if (t && z) length = std::hypot(*t, *z);
    } else if (l.parts.size() == 3 && l.parts[0] == "vehicles" && l.parts[2] == "pdof_deg") {
      length = get("vehicles." + l.parts[1] + ".delta_v_magnitude");
    } else if (l.parts.size() == 3 && l.parts[0] == "vehicles" && l.parts[2] == "heading_after_deg") {
      const auto x = get("vehicles." + l.parts[1] + ".velocity.0"), y = get("vehicles." + l.parts[1] + ".velocity.1");
      if (x && y) length = std::hypot(*x, *y);
    }
    if (!length || !(*length > 0)) return tol_.atol;
    return std::max(tol_.atol, tol_.atol / *length * (180 / std::numbers::pi));
  }

  CaseReport compare_fields(const RefCase& rc, const json& other) const {
    CaseReport r{rc.name, {}, false, std::nullopt};
    for (const auto& l : rc.top) {
      if (l.value.is_null()) {
        if (const json* v = find(other, l.parts); v && !v->is_null()) r.fields.push_back(undefined_here(l.dotted, l, -1, describe(*v)));
        continue;
      }
      if (const json* v = find(other, l.parts)) r.fields.push_back(from_json(l.dotted, l, -1, *v));
      else if (required(l)) r.fields.push_back(missing(l.dotted));
    }
    const auto results = other.find("results");
    if (results == other.end()) {
      if (!o_.subset)
        for (std::size_t i = 0; i < rc.results.size(); ++i) r.fields.push_back(missing(fmt::format("results.{}", i)));
      return r;
    }
    if (!results->is_array()) {
      r.fields.push_back({"results", false, 0, "not an array (other: " + describe(*results) + ")"});
      return r;
    }
    for (std::size_t i = 0; i < rc.results.size(); ++i) {
      const std::string base = fmt::format("results.{}", i);
      if (i >= results->size()) {
        if (!o_.subset) r.fields.push_back(missing(base));
        continue;
      }
      const json& o = (*results)[i];
      if (!o.is_object()) {
        r.fields.push_back({base, false, 0, "not an object (other: " + describe(o) + ")"});
        continue;
      }
      for (const auto& l : rc.results[i]) {
        if (l.value.is_null()) {
          if (const json* v = find(o, l.parts); v && !v->is_null())
            r.fields.push_back(undefined_here(base + "." + l.dotted, l, static_cast<int>(i), describe(*v)));
          continue;
        }
        if (const json* v = find(o, l.parts)) {
          Comparer at = *this;
          if (o_.rtol_from_bound) at.tol_.atol = angle_atol(rc.numbers[i], l);
          r.fields.push_back(at.from_json(base + "." + l.dotted, l, static_cast<int>(i), *v));
        } else if (required(l)) {
          r.fields.push_back(missing(base + "." + l.dotted));
        }
      }
    }
    if (results->size() > rc.results.size())
      r.fields.push_back({"results", false, 0,
                          fmt::format("{} results, the reference has {}", results->size(), rc.results.size())});
    return r;
  }

  const CompareOptions& o_;
  Tolerance tol_;
};

// What a CSV gives for one reference case.
struct CsvCase {
  bool any = false;
  std::vector<std::optional<Field>> top;          // by top leaf: the failing or else the first value given
  std::map<std::size_t, std::vector<Field>> results;
};

// A CSV compares the fields it has columns for, no others.
struct CsvFile {
  std::vector<CsvCase> cases;
  std::unordered_set<std::string> columns;
};

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

// Callers count the commas first: a line of a million commas is refused before it is split.
std::vector<std::string_view> split_cells(std::string_view line) {
  std::vector<std::string_view> cells;
  for (std::size_t start = 0;;) {
    const auto comma = line.find(',', start);
    cells.push_back(trim(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start)));
    if (comma == std::string_view::npos) return cells;
    start = comma + 1;
  }
}

// `result`: a decimal index below `n`, nothing else (no sign, no space, no exponent).
std::optional<std::size_t> result_index(std::string_view s, std::size_t n) {
  if (s.empty() || s.size() > 9 || !std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return std::nullopt;
  std::size_t i = 0;
  std::from_chars(s.data(), s.data() + s.size(), i);
  return i < n ? std::optional(i) : std::nullopt;
}

// Each row stays a flat map from the header's dotted paths to its cells; the reference's leaves are
// looked up in it. No document is built from a column's path, so no path can size an allocation.
CsvFile read_csv(const std::string& file, const std::vector<RefCase>& refs, const Comparer& cmp) {
  const std::string text = case_format::read_text_file(file, case_format::limits::kResultFileBytes);
  std::string_view rest = text;
  if (rest.substr(0, 3) == "\xEF\xBB\xBF") rest.remove_prefix(3);  // a spreadsheet's byte-order mark
  int row = 0;
  const auto next_line = [&]() -> std::optional<std::string_view> {
    if (rest.empty()) return std::nullopt;
    const auto nl = rest.find('\n');
    const std::string_view line = rest.substr(0, nl);
    rest.remove_prefix(nl == std::string_view::npos ? rest.size() : nl + 1);
    ++row;
    return line;
  };
  const auto header_line = next_line();
  if (!header_line) throw CaseError(file, "empty CSV");
  if (static_cast<std::size_t>(std::count(header_line->begin(), header_line->end(), ',')) >= case_format::limits::kCsvColumns)
    throw CaseError(file, fmt::format("more than {} columns", case_format::limits::kCsvColumns));
  std::vector<std::string> header;
  for (const auto cell : split_cells(*header_line)) {
    if (cell.size() > kCellChars)
      throw CaseError(file, fmt::format("row 1, column {}: a name longer than {} characters", header.size() + 1, kCellChars));
    header.emplace_back(cell);
  }
  if (header.size() < 3 || header[0] != "case" || header[1] != "result")
    throw CaseError(file, "the CSV header must start with case,result and name at least one field");

  // Every column must name a field compare checks somewhere in the reference: a misspelt one never passes.
  std::unordered_set<std::string> known;
  for (const auto& rc : refs) {
    for (const auto& l : rc.top) known.insert(l.dotted);
    for (const auto& r : rc.results)
      for (const auto& l : r) known.insert(l.dotted);
  }
  std::unordered_map<std::string, std::size_t> column;
  for (std::size_t c = 0; c < header.size(); ++c) {
    if (!column.emplace(header[c], c).second) throw CaseError(file, fmt::format("column {} appears twice", case_format::quoted(header[c])));
    if (c >= 2 && !known.count(header[c]))
      throw CaseError(file, fmt::format("column {} is not a field of the reference that compare checks", case_format::quoted(header[c])));
  }

  std::unordered_map<std::string, std::size_t> case_of;
  for (std::size_t k = 0; k < refs.size(); ++k) case_of.emplace(refs[k].name, k);
  CsvFile csv;
  csv.columns.insert(header.begin() + 2, header.end());
  std::vector<CsvCase>& out = csv.cases;
  out.resize(refs.size());
  for (std::size_t k = 0; k < refs.size(); ++k) out[k].top.resize(refs[k].top.size());
  std::map<std::pair<std::size_t, std::size_t>, int> first_row;
  std::vector<char> used(header.size());
  while (const auto line = next_line()) {
    if (trim(*line).empty()) continue;
    const auto commas = static_cast<std::size_t>(std::count(line->begin(), line->end(), ','));
    if (commas + 1 != header.size())
      throw CaseError(file, fmt::format("row {} has {} cells, the header {}", row, commas + 1, header.size()));
    const auto cells = split_cells(*line);
    const auto where = [&](std::size_t c) {
      return fmt::format("row {}, column {}", row, c < 2 ? header[c] : case_format::quoted(header[c]));
    };
    for (std::size_t c = 0; c < cells.size(); ++c)
      if (cells[c].size() > kCellChars)
        throw CaseError(file, fmt::format("{}: a cell longer than {} characters", where(c), kCellChars));
    const auto k = case_of.find(std::string(cells[0]));
    if (k == case_of.end())
      throw CaseError(file, fmt::format("{}: {} is not a case of the reference", where(0), case_format::quoted(cells[0])));
    const RefCase& rc = refs[k->second];
    const auto i = result_index(cells[1], rc.results.size());
    if (!i) {
      if (rc.results.empty())
        throw CaseError(file, fmt::format("{}: the reference case {} has no results", where(1), case_format::quoted(rc.name)));
      throw CaseError(file, fmt::format("{}: expected a result index from 0 to {}, got {}", where(1), rc.results.size() - 1,
                                        case_format::quoted(cells[1])));
    }
    if (const auto [it, fresh] = first_row.emplace(std::pair(k->second, *i), row); !fresh)
      throw CaseError(file, fmt::format("row {}: case {} result {} is also in row {}", row, case_format::quoted(rc.name), *i, it->second));

    CsvCase& cc = out[k->second];
    cc.any = true;
    std::fill(used.begin(), used.end(), 0);
    used[0] = used[1] = 1;
    // The cell of a leaf, marking its column as one this row may fill; empty means not given. A leaf
    // with no column is not compared.
    const auto cell_of = [&](const Leaf& l) -> std::optional<std::string_view> {
      const auto c = column.find(l.dotted);
      if (c == column.end()) return std::nullopt;
      used[c->second] = 1;
      if (cells[c->second].empty()) return std::nullopt;
      return cells[c->second];
    };
    for (std::size_t t = 0; t < rc.top.size(); ++t) {
      const Leaf& l = rc.top[t];
      const auto cell = cell_of(l);
      if (!cell || (l.value.is_null() && *cell == "null")) continue;
      Field f = l.value.is_null() ? cmp.undefined_here(l.dotted, l, -1, excerpt(*cell)) : cmp.from_cell(l.dotted, l, -1, *cell);
      if (!f.pass) f.detail += fmt::format(" (row {})", row);
      if (!cc.top[t] || (cc.top[t]->pass && !f.pass)) cc.top[t] = std::move(f);
    }
    auto& fields = cc.results[*i];
    const std::string base = fmt::format("results.{}.", *i);
    for (const Leaf& l : rc.results[*i]) {
      const auto cell = cell_of(l);
      if (l.value.is_null()) {  // undefined in the reference: an empty cell or "null" agrees
        if (cell && *cell != "null") fields.push_back(cmp.undefined_here(base + l.dotted, l, static_cast<int>(*i), excerpt(*cell)));
        continue;
      }
      if (cell) fields.push_back(cmp.from_cell(base + l.dotted, l, static_cast<int>(*i), *cell));
      else if (!cmp.subset() && column.count(l.dotted))
        fields.push_back(cmp.missing(base + l.dotted, "missing (an empty cell in a column of the CSV)"));
    }
    for (std::size_t c = 2; c < cells.size(); ++c)
      if (!used[c] && !cells[c].empty())
        throw CaseError(file, fmt::format("{}: result {} of {} has no such field in the reference (leave the cell empty)",
                                          where(c), *i, case_format::quoted(rc.name)));
  }
  return csv;
}

// A failure of the whole case, listed like a field: "case missing", "nothing compared".
Field whole_case(const std::string& what, const std::string& detail) { return {what, false, 0, detail}; }

// The error of a field as the table shows it: a number's relative error (its absolute one near zero), or
// what kind of failure it is.
std::string error_text(const Field& f) {
  if (f.reference && f.other) {
    if (f.rel > 0) return fmt::format("{:.3e}", f.rel);
    return fmt::format("abs {:.2e}", f.abs_error);
  }
  return f.compared ? "mismatch" : "missing";
}

// Which of two failures is worse: one that is not a number comparison (a wrong regime, a missing field)
// before any number, then the number furthest outside its tolerance.
bool worse(const Field& a, const Field& b) {
  const bool an = a.reference.has_value(), bn = b.reference.has_value();
  if (an != bn) return !an;
  return a.excess > b.excess;
}

int report(const std::vector<RefCase>& refs, std::vector<std::optional<CaseReport>>& reports, const CompareOptions& o,
           const std::string& other, const std::optional<std::unordered_set<std::string>>& csv_columns) {
  std::size_t reference_fields = 0, compared = 0, cases = 0, failed_cases = 0, results_total = 0, results_given = 0,
              cases_given = 0;
  double worst = 0;
  std::string worst_where = "-";
  std::optional<Field> worst_failure;
  std::string worst_failure_case;
  std::map<std::string, std::size_t> compared_by_leaf;
  std::vector<detail::NumericFailure> numeric_failures;
  // Every line passes through printable(): case names, paths and values come from other people's files.
  const auto line = [](const std::string& s) { return case_format::printable(s) + "\n"; };
  // With --rtol-from-bound each case's rtol is a column of its own.
  const auto row = [&](const std::string& name, const std::string& fields, const std::string& failed, const std::string& rtol,
                       const std::string& err, const std::string& field) {
    if (!o.rtol_from_bound) return line(fmt::format("{:<40} {:>7} {:>7}  {:>12}  {}", name, fields, failed, err, field));
    return line(fmt::format("{:<40} {:>7} {:>7}  {:>9}  {:>12}  {}", name, fields, failed, rtol, err, field));
  };
  std::string table = row("case", "fields", "failed", "rtol", "worst error", "worst field");
  std::string failures;
  std::optional<double> rtol_lo, rtol_hi;
  for (std::size_t k = 0; k < refs.size(); ++k) {
    reference_fields += refs[k].fields;
    results_total += refs[k].results.size();
    if (!reports[k]) continue;
    CaseReport& r = *reports[k];
    ++cases;
    const auto n = static_cast<std::size_t>(std::count_if(r.fields.begin(), r.fields.end(), [](const Field& f) { return f.compared; }));
    compared += n;
    const bool whole = r.whole || (!r.fields.empty() && !r.fields.front().compared && r.fields.front().path == "case missing");
    if (n == 0 && !whole) r.fields.insert(r.fields.begin(), whole_case("nothing compared", "no field of the reference in the other results"));
    int failed = 0;
    const Field* named = nullptr;    // the worst failure
    const Field* largest = nullptr;  // the largest relative error compared
    std::set<int> given;
    for (const auto& f : r.fields) {
      if (f.compared) {
        ++compared_by_leaf[f.leaf];
        if (f.result >= 0) given.insert(f.result);
      }
      if (!f.pass) {
        ++failed;
        failures += line(fmt::format("  FAIL {}: {}: {}", r.name, f.path, f.detail));
        if (!named || worse(f, *named)) named = &f;
        if (f.reference && f.other && f.pass == false)
          numeric_failures.push_back({f.leaf, *f.reference, *f.other, f.rtol, f.atol,
                                      f.result >= 0 ? &refs[k].numbers[static_cast<std::size_t>(f.result)] : nullptr});
      }
      if (f.compared && (!largest || f.rel > largest->rel)) largest = &f;
      if (f.compared && f.rel > worst) {
        worst = f.rel;
        worst_where = r.name + ": " + f.path;
      }
    }
    results_given += given.size();
    cases_given += r.fields.empty() || r.fields.front().path != "case missing" ? 1 : 0;
    if (failed) ++failed_cases;
    std::string err = fmt::format("{:.3e}", largest ? largest->rel : 0.0), field = largest && largest->rel > 0 ? largest->path : "-";
    if (named) {
      err = error_text(*named);
      field = named->reference ? named->path : named->path + ": " + named->detail;
      if (!worst_failure || worse(*named, *worst_failure)) {
        worst_failure = *named;
        worst_failure_case = r.name;
      }
    }
    if (r.rtol) {
      rtol_lo = std::min(rtol_lo.value_or(*r.rtol), *r.rtol);
      rtol_hi = std::max(rtol_hi.value_or(*r.rtol), *r.rtol);
    }
    table += row(r.name, std::to_string(n), std::to_string(failed), r.rtol ? fmt::format("{:.2e}", *r.rtol) : "-", err, field);
  }
  std::string out = table;
  if (!failures.empty()) out.append("\n").append(failures);
  const auto diagnoses = detail::diagnose(numeric_failures);
  if (!diagnoses.empty()) out.append("\n");
  for (const auto& d : diagnoses) out.append(line(d));
  if (compared == 0) out.append("\n").append(line(fmt::format("nothing was compared: {} gives no field of the reference", other)));

  // What was compared: a CSV's columns with their counts; for result files the number of fields.
  std::string fields = fmt::format("fields compared: {} values", compared);
  if (csv_columns) {
    std::vector<std::string> names(csv_columns->begin(), csv_columns->end());
    std::sort(names.begin(), names.end());
    constexpr std::size_t kListed = 24;
    fields += fmt::format(" in the CSV's {} column{} (only these; the reference has {} values):", names.size(),
                          names.size() == 1 ? "" : "s", reference_fields);
    for (std::size_t i = 0; i < names.size() && i < kListed; ++i) {
      const auto it = compared_by_leaf.find(names[i]);
      fields += fmt::format(" {} x{}", names[i], it == compared_by_leaf.end() ? 0 : it->second);
    }
    if (names.size() > kListed) fields += fmt::format(" and {} more", names.size() - kListed);
  } else {
    fields += fmt::format(" of {} distinct fields (the reference has {} values)", compared_by_leaf.size(), reference_fields);
  }
  out.append("\n").append(line(fields));
  out.append(line(fmt::format("coverage: {} of {} reference cases, {} of {} results given{}", cases_given, refs.size(), results_given,
                              results_total, o.subset ? " (--subset: the others are not compared)" : "")));

  const std::string tolerance =
      !o.rtol_from_bound ? fmt::format("rtol {:g}, atol {:g}", o.rtol, o.atol)
      : rtol_lo          ? fmt::format("rtol from each case's rounding_bound, {:.2e} to {:.2e}; atol rtol x its largest magnitude",
                                       *rtol_lo, *rtol_hi)
                         : std::string("rtol from each case's rounding_bound");
  std::string summary = fmt::format("{} of {} cases pass ({}); ", cases - failed_cases, cases, tolerance);
  if (worst_failure)
    summary += fmt::format("worst failure {} at {}: {}{}", error_text(*worst_failure), worst_failure_case, worst_failure->path,
                           worst_failure->reference ? "" : " (" + worst_failure->detail + ")");
  else
    summary += fmt::format("worst relative error {:.3e} at {}", worst, worst_where);
  if (o.subset) summary += fmt::format("; subset: {} of {} reference fields compared", compared, reference_fields);
  out.append(line(summary));
  std::fwrite(out.data(), 1, out.size(), stdout);
  return failed_cases || compared == 0 ? 1 : 0;
}

}  // namespace

int compare(const std::string& reference, const std::string& other, const CompareOptions& o) {
  std::error_code ec;
  std::vector<RefCase> refs;
  const bool reference_dir = fs::is_directory(reference, ec);
  if (reference_dir) {
    std::vector<std::pair<std::string, std::string>> files;
    fs::directory_iterator it(reference, ec);
    for (; !ec && it != fs::directory_iterator(); it.increment(ec))
      if (it->path().extension() == ".json") files.push_back({it->path().stem().string(), it->path().string()});
    if (ec) throw CaseError(reference, "cannot list the directory (" + ec.message() + ")");
    if (files.empty()) throw CaseError(reference, "no reference results (*.json) in this directory");
    std::sort(files.begin(), files.end());
    for (const auto& [name, file] : files) refs.push_back(load_reference(name, file));
  } else {
    refs.push_back(load_reference(fs::path(reference).stem().string(), reference));
  }

  const Comparer cmp(o);
  std::optional<std::unordered_set<std::string>> csv_columns;  // a CSV: the fields it compares
  // By reference case; empty where --subset leaves out a case the other side does not have.
  std::vector<std::optional<CaseReport>> reports(refs.size());
  const auto absent = [&](std::size_t k, const std::string& detail) {
    if (!o.subset) reports[k] = CaseReport{refs[k].name, {whole_case("case missing", detail)}, true, std::nullopt};
  };
  if (fs::path(other).extension() == ".csv") {
    if (o.rtol_from_bound)
      throw CaseError(other, "--rtol-from-bound takes each case's tolerance from its result JSON's rounding_bound; a CSV has none");
    if (o.all_fields)
      throw CaseError(other, "--all requires every field of a result file; a CSV is compared on its columns, so name them");
    const CsvFile file = read_csv(other, refs, cmp);
    csv_columns = file.columns;
    const auto& csv = file.cases;
    for (std::size_t k = 0; k < refs.size(); ++k) {
      const RefCase& rc = refs[k];
      if (!csv[k].any) {
        absent(k, "no row in " + other);
        continue;
      }
      CaseReport r{rc.name, {}, false, std::nullopt};
      for (std::size_t t = 0; t < rc.top.size(); ++t) {
        if (csv[k].top[t]) r.fields.push_back(*csv[k].top[t]);
        else if (!rc.top[t].value.is_null() && !o.subset && file.columns.count(rc.top[t].dotted))
          r.fields.push_back(cmp.missing(rc.top[t].dotted, "missing (no row gives this column)"));
      }
      for (std::size_t i = 0; i < rc.results.size(); ++i) {
        const auto it = csv[k].results.find(i);
        if (it != csv[k].results.end()) r.fields.insert(r.fields.end(), it->second.begin(), it->second.end());
        else if (!o.subset) r.fields.push_back({fmt::format("results.{}", i), false, 0, "missing (no row)"});
      }
      reports[k] = std::move(r);
    }
  } else if (fs::is_directory(other, ec)) {
    for (std::size_t k = 0; k < refs.size(); ++k) {
      const std::string file = (fs::path(other) / (refs[k].name + ".json")).string();
      if (!fs::exists(file, ec)) absent(k, "no file " + file);
      else reports[k] = cmp.compare_json(refs[k], read_json(file), file);
    }
  } else if (!reference_dir) {
    reports[0] = cmp.compare_json(refs[0], read_json(other), other);
  } else {
    // One result file against a directory: the case is the one the file is named after.
    const std::string name = fs::path(other).stem().string();
    const auto it = std::find_if(refs.begin(), refs.end(), [&](const RefCase& rc) { return rc.name == name; });
    if (it == refs.end())
      throw CaseError(other, fmt::format("no case of the reference is named {} (a result file is named like its case)",
                                         case_format::quoted(name)));
    const json doc = read_json(other);
    for (std::size_t k = 0; k < refs.size(); ++k) {
      if (&refs[k] == &*it) reports[k] = cmp.compare_json(refs[k], doc, other);
      else absent(k, "not in " + other);
    }
  }

  return report(refs, reports, o, other, csv_columns);
}

}  // namespace impact3d::verification
