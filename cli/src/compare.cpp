#include "compare.hpp"

#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "impact3d/case/case_spec.hpp"

namespace impact3d::cli {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

json parse(const fs::path& p) {
  try {
    return json::parse(io::read_text_file(p.string()));
  } catch (const json::parse_error& e) {
    throw std::runtime_error(p.string() + ": invalid JSON");
  }
}

// The fields the contract requires of a result, as paths below results[i]; and the top-level ones.
const std::vector<std::string> kContractTop = {"coefficients.m_prime", "coefficients.K"};
const std::vector<std::string> kContractResult = {
    "regime",     "impulse_ratio", "limits", "impulse.contact", "impulse.world", "relative_velocity.before",
    "relative_velocity.after", "vehicles.0.velocity", "vehicles.0.angular_velocity", "vehicles.0.delta_v",
    "vehicles.1.velocity", "vehicles.1.angular_velocity", "vehicles.1.delta_v", "energy.before", "energy.after",
    "energy.loss"};

const json* at_path(const json& root, const std::string& dotted) {
  const json* node = &root;
  std::stringstream ss(dotted);
  for (std::string part; std::getline(ss, part, '.');) {
    if (node->is_array()) {
      const auto index = static_cast<std::size_t>(std::stoul(part));
      if (index >= node->size()) return nullptr;
      node = &(*node)[index];
    } else if (node->is_object()) {
      auto it = node->find(part);
      if (it == node->end()) return nullptr;
      node = &*it;
    } else {
      return nullptr;
    }
  }
  return node;
}

struct Field {
  std::string path;
  bool pass;
  double rel = 0;
  std::string detail;
};

struct CaseReport {
  std::string name;
  std::vector<Field> fields;
};

class Comparer {
 public:
  explicit Comparer(const CompareOptions& o) : o_(o) {}

  // Every leaf of `ref` below `path`; `other` missing a leaf fails when `required`.
  void leaves(const std::string& path, const json& ref, const json* other, bool required, CaseReport& r) {
    if (ref.is_object() || ref.is_array()) {
      if (ref.is_object())
        for (const auto& [k, v] : ref.items()) leaves(path + "." + k, v, other ? at_path(*other, k) : nullptr, required, r);
      else
        for (std::size_t i = 0; i < ref.size(); ++i)
          leaves(path + "." + std::to_string(i), ref[i], other ? at_path(*other, std::to_string(i)) : nullptr, required, r);
      return;
    }
    const std::string p = path.substr(1);
    if (!other) {
      if (required) r.fields.push_back({p, false, 0, "missing"});
      return;
    }
    if (ref.is_number()) {
      if (!other->is_number()) {
        r.fields.push_back({p, false, 0, "not a number"});
        return;
      }
      const double a = ref.get<double>(), b = other->get<double>();
      double d = std::fabs(b - a);
      // Angles in degrees wrap: 180 and -180 (or 0 and 360) are the same direction.
      if (p.size() > 4 && p.compare(p.size() - 4, 4, "_deg") == 0) d = std::fabs(std::remainder(b - a, 360.0));
      // A relative error is reported only where the value stands above the absolute tolerance.
      const double rel = std::fabs(a) > o_.atol ? d / std::fabs(a) : 0;
      r.fields.push_back({p, d <= o_.atol + o_.rtol * std::fabs(a), rel,
                          fmt::format("reference {:.17g}, other {:.17g}", a, b)});
    } else if (ref.is_string()) {
      const bool same = other->is_string() && other->get<std::string>() == ref.get<std::string>();
      r.fields.push_back({p, same, 0, same ? "" : "reference \"" + ref.get<std::string>() + "\", other " + other->dump()});
    }
  }

  // `require_contract`: a JSON result must carry every field the contract requires; a CSV names its
  // own columns, and exactly those are compared.
  CaseReport compare_json(const std::string& name, const json& ref, const json& other, bool require_contract) {
    CaseReport r{name, {}};
    for (const auto& path : kContractTop)
      if (const json* v = at_path(ref, path)) leaves("." + path, *v, at_path(other, path), require_contract, r);
    const json& rr = ref.at("results");
    const json* orr = at_path(other, "results");
    for (std::size_t i = 0; i < rr.size(); ++i) {
      const json* o = orr ? at_path(*orr, std::to_string(i)) : nullptr;
      const std::string base = ".results." + std::to_string(i);
      for (const auto& path : kContractResult)
        if (const json* v = at_path(rr[i], path))
          leaves(base + "." + path, *v, o ? at_path(*o, path) : nullptr, require_contract, r);
      if (!o) continue;
      // Beyond the contract: compared where the other tool has them (required with --all).
      for (const auto& [k, v] : rr[i].items()) {
        bool contract = false;
        for (const auto& c : kContractResult) contract = contract || c == k || c.rfind(k + ".", 0) == 0;
        if (!contract && k != "strategy" && k != "warnings")
          leaves(base + "." + k, v, at_path(*o, k), require_contract && o_.all_fields, r);
      }
    }
    return r;
  }

 private:
  const CompareOptions& o_;
};

// CSV: a header naming the columns, then one row per case result. Columns: `case` (the reference file
// name without .json), `result` (index into results), then JSON paths with dots: below results[result],
// or from the top when they start with "coefficients.".
std::map<std::string, json> read_csv(const fs::path& p) {
  std::map<std::string, json> docs;
  std::istringstream in(io::read_text_file(p.string()));
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error(p.string() + ": empty CSV");
  auto split = [](const std::string& s) {
    std::vector<std::string> out;
    std::stringstream ss(s);
    for (std::string cell; std::getline(ss, cell, ',');) {
      while (!cell.empty() && (cell.back() == '\r' || cell.back() == ' ')) cell.pop_back();
      out.push_back(cell);
    }
    return out;
  };
  const auto header = split(line);
  if (header.size() < 3 || header[0] != "case" || header[1] != "result")
    throw std::runtime_error(p.string() + ": the CSV header must start with case,result");
  for (int row = 2; std::getline(in, line); ++row) {
    if (line.empty()) continue;
    const auto cells = split(line);
    if (cells.size() != header.size()) throw std::runtime_error(fmt::format("{}: row {} has {} cells, the header {}", p.string(), row, cells.size(), header.size()));
    json& doc = docs[cells[0]];
    const std::string result = cells[1];
    for (std::size_t c = 2; c < header.size(); ++c) {
      const std::string path = header[c].rfind("coefficients.", 0) == 0 ? header[c] : "results." + result + "." + header[c];
      json value;
      try {
        std::size_t used = 0;
        const double d = std::stod(cells[c], &used);
        value = used == cells[c].size() ? json(d) : json(cells[c]);
      } catch (const std::exception&) {
        value = cells[c];
      }
      doc[json::json_pointer("/" + [&] {
        std::string s = path;
        for (auto& ch : s) if (ch == '.') ch = '/';
        return s;
      }())] = value;
    }
  }
  return docs;
}

}  // namespace

int compare(const std::string& reference, const std::string& other, const CompareOptions& o) {
  std::vector<std::pair<std::string, fs::path>> refs;
  if (fs::is_directory(reference)) {
    for (const auto& e : fs::directory_iterator(reference))
      if (e.path().extension() == ".json") refs.push_back({e.path().stem().string(), e.path()});
  } else {
    refs.push_back({fs::path(reference).stem().string(), reference});
  }
  std::sort(refs.begin(), refs.end());
  std::map<std::string, json> csv;
  const bool is_csv = fs::path(other).extension() == ".csv";
  if (is_csv) csv = read_csv(other);

  Comparer cmp(o);
  std::vector<CaseReport> reports;
  for (const auto& [name, path] : refs) {
    json other_doc;
    if (is_csv) {
      auto it = csv.find(name);
      if (it == csv.end()) continue;  // a CSV may cover only some cases; those are listed as not compared
      other_doc = it->second;
    } else if (fs::is_directory(other)) {
      const fs::path op = fs::path(other) / (name + ".json");
      if (!fs::exists(op)) {
        reports.push_back({name, {{"(file)", false, 0, op.string() + " missing"}}});
        continue;
      }
      other_doc = parse(op);
    } else {
      other_doc = parse(other);
    }
    reports.push_back(cmp.compare_json(name, parse(path), other_doc, !is_csv));
  }
  if (reports.empty()) throw std::runtime_error("no case of the reference was found in " + other);

  int failed_cases = 0;
  double worst = 0;
  std::string worst_where;
  std::string table = fmt::format("{:<40} {:>7} {:>7}  {:>12}  {}\n", "case", "fields", "failed", "worst rel", "worst field");
  std::string failures;
  for (const auto& r : reports) {
    int failed = 0;
    double w = 0;
    std::string wf = "-";
    for (const auto& f : r.fields) {
      if (!f.pass) {
        ++failed;
        failures += fmt::format("  FAIL {}: {}: {}\n", r.name, f.path, f.detail);
      }
      if (f.rel > w) {
        w = f.rel;
        wf = f.path;
      }
    }
    if (failed) ++failed_cases;
    if (w > worst) {
      worst = w;
      worst_where = r.name + ": " + wf;
    }
    table += fmt::format("{:<40} {:>7} {:>7}  {:>12.3e}  {}\n", r.name, r.fields.size(), failed, w, wf);
  }
  std::fputs(table.c_str(), stdout);
  if (!failures.empty()) std::fputs(("\n" + failures).c_str(), stdout);
  std::fputs(fmt::format("\n{} of {} cases pass (rtol {:g}, atol {:g}); worst relative error {:.3e} at {}\n",
                         reports.size() - failed_cases, reports.size(), o.rtol, o.atol, worst,
                         worst_where.empty() ? "-" : worst_where)
                 .c_str(),
             stdout);
  return failed_cases ? 1 : 0;
}

}  // namespace impact3d::cli
