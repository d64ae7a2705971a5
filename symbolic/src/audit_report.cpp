#include "audit_report.hpp"

#include <map>
#include <set>

#include <nlohmann/json.hpp>

namespace impact3d::symbolic {

namespace {

using json = nlohmann::ordered_json;

json witness_json(const Witness& w) {
  json inputs = json::array();
  for (const auto& [k, v] : w.inputs) inputs.push_back({{"symbol", k}, {"meaning", symbol_meaning(k)}, {"value", v}});
  json out;
  out["inputs"] = inputs;
  out[w.left_name] = {{"exact", w.left}, {"decimal", w.left_decimal}};
  out[w.right_name] = {{"exact", w.right}, {"decimal", w.right_decimal}};
  return out;
}

json checks_json(const std::vector<Check>& checks) {
  json out = json::array();
  for (const auto& c : checks) {
    json j;
    j["compared"] = c.what();
    j["expected"] = c.expect_equal() ? "equal" : "different";
    j["result"] = c.equal() ? "equal" : "different";
    if (c.witness()) j["witness"] = witness_json(*c.witness());
    out.push_back(j);
  }
  return out;
}

std::size_t count_checks(const AuditEntry& e) {
  std::size_t n = e.checks.size() + e.corrections.size();
  for (const auto& r : e.readings) n += r.checks.size();
  return n;
}

std::string witness_markdown(const Check& c) {
  const Witness& w = *c.witness();
  std::string s = "Witness for *" + c.what() + "*:\n\n| symbol | stands for | value |\n|---|---|---|\n";
  for (const auto& [k, v] : w.inputs) s += "| `" + k + "` | " + symbol_meaning(k) + " | `" + v + "` |\n";
  s += "\n| | exact | decimal |\n|---|---|---|\n";
  s += "| " + w.left_name + " | `" + w.left + "` | " + w.left_decimal + " |\n";
  s += "| " + w.right_name + " | `" + w.right + "` | " + w.right_decimal + " |\n\n";
  return s;
}

std::string checks_markdown(const std::vector<Check>& checks) {
  std::string s;
  for (const auto& c : checks) {
    const std::string result = c.equal() ? "identical" : "differ";
    if (c.expect_equal())
      s += "- " + c.what() + ": " + (c.equal() ? result : "**" + result + "**") + "\n";
    else
      s += "- " + c.what() + ": claimed to differ; computed: " + result + ", so the claim " +
           (c.holds() ? "holds" : "**does not hold**") + "\n";
  }
  s += "\n";
  // The first witness shows the difference; generated/audit.json has one for every differing comparison.
  for (const auto& c : checks)
    if (c.witness()) return s + witness_markdown(c);
  return s;
}

}  // namespace

std::string audit_json(const std::vector<AuditEntry>& entries, const std::string& provenance) {
  json j;
  j["generator"] = "impact3d-derive";
  j["provenance"] = provenance;
  j["paper"] = "M. C. Marine, Three-Dimensional Rigid-Body Impact Mechanics for Automobile Collisions";
  j["statuses"] = {
      {"verified", "the printed expression was compared with the derivation and agrees identically"},
      {"erratum", "the printed expression differs from the derivation; corrected form (itself compared) and witness"},
      {"ambiguous", "the printed text admits more than one reading; each reading compared, the implementation's named"},
      {"definition", "nothing to compare: a definition, notation or the starting point"},
      {"claim-checked", "a statement of the text, decided by the listed computations, holds"},
      {"claim-contradicted", "a statement of the text, decided by the listed computations, does not hold"}};
  json items = json::array();
  for (const auto& e : entries) {
    json it;
    it["id"] = e.id;
    it["status"] = status_of(e);
    it["summary"] = e.detail;
    if (!e.claim.empty()) it["claim"] = e.claim;
    if (!e.printed_latex.empty()) it["printed"] = e.printed_latex;
    if (!e.corrected_latex.empty()) it["corrected"] = e.corrected_latex;
    if (!e.checks.empty()) it["comparisons"] = checks_json(e.checks);
    if (!e.corrections.empty()) it["correction_comparisons"] = checks_json(e.corrections);
    if (!e.readings.empty()) {
      json rs = json::array();
      for (const auto& r : e.readings)
        rs.push_back({{"reading", r.description}, {"used_by_implementation", r.used_by_implementation},
                      {"comparisons", checks_json(r.checks)}});
      it["readings"] = rs;
    }
    items.push_back(it);
  }
  j["items"] = items;
  return j.dump(2) + "\n";
}

std::string audit_markdown(const std::vector<AuditEntry>& entries, const std::string& banner) {
  std::map<std::string, std::vector<std::string>> by_status;
  std::size_t comparisons = 0;
  for (const auto& e : entries) {
    by_status[status_of(e)].push_back(e.id);
    comparisons += count_checks(e);
  }
  auto n = [&](const char* s) { return std::to_string(by_status[s].size()); };
  auto ids = [&](const char* s) {
    std::string out;
    for (const auto& id : by_status[s]) out += (out.empty() ? "`" : ", `") + id + "`";
    return out.empty() ? std::string("none") : out;
  };
  std::string s = "# Audit of the paper against the derivation\n\n" + banner;
  s += "## Summary\n\n";
  s += "**" + n("verified") + " verified, " + n("erratum") + " errata, " + n("ambiguous") + " ambiguous, " +
       n("definition") + " definitions, " + n("claim-checked") + " claims checked, " + n("claim-contradicted") +
       " claims contradicted**, from " + std::to_string(comparisons) + " comparisons.\n\n";
  s += "**What was checked.** Every numbered equation, line by line and component by component; Appendix A's T, "
       "A, B, C, f_1..f_8 and a_1..c_3; and the statements of the text about Figure 8 and in the conclusions.\n\n";
  s += "**Method.** `symbolic/` derives every quantity from the impulse-momentum equations (eq 2) with full inertia "
       "tensors and general rotations, and compares with it each printed expression, typed in as printed, and each "
       "claim of the text, written as an equation. Two sides agree when their difference reduces to zero by exact "
       "rational algebra (GiNaC's `normal()`, with sines and cosines through the rational parametrization of the "
       "circle); a difference is shown by a witness, exact inputs at which the two sides differ, and a claim that "
       "something happens in general holds when such a witness exists for a symmetric K. A status is computed from "
       "the comparisons alone (`status_of`), so an entry that compared nothing can only be a definition.\n\n";
  s += "**Errata** (the corrected form is itself compared with the derivation):\n\n";
  for (const auto& e : entries)
    if (status_of(e) == "erratum")
      s += "- `" + e.id + "`: printed $" + e.printed_latex + "$, corrected $" + e.corrected_latex + "$\n";
  s += "\n**Ambiguities** (each reading compared; the implementation's is marked):\n\n";
  for (const auto& e : entries) {
    if (status_of(e) != "ambiguous") continue;
    s += "- `" + e.id + "`: $" + e.printed_latex + "$\n";
    for (const auto& r : e.readings) {
      bool agree = true;
      for (const auto& c : r.checks) agree = agree && c.equal();
      s += "  - " + r.description + ", $" + r.latex + "$: " + (agree ? "agrees" : "differs") +
           (r.used_by_implementation ? " (**the implementation's reading**)" : "") + "\n";
    }
  }
  s += "\n**Claims of the text contradicted**: ";
  for (const auto& e : entries)
    if (status_of(e) == "claim-contradicted") s += "`" + e.id + "` (" + e.detail + ") ";
  s += "\n\n**Claims checked**: " + ids("claim-checked") + ". **Definitions**: " + ids("definition") +
       ". The paper has no equation 28.\n\n";
  s += "**Not decided** (no computation can: they depend on Virtual CRASH's vehicle data, which the paper does not "
       "give): Figure 8's +3.5 mph continued t sliding at mu = 0.4, the size and direction of the Sliding Impact's swerve (below 0.5 mph, upward), and the "
       "n_i, n_z values in the figure's image. The claims above decide what follows from the equations alone.\n\n";
  s += "## Entries\n\n| id | status | comparisons | what |\n|---|---|---|---|\n";
  for (const auto& e : entries)
    s += "| `" + e.id + "` | " + status_of(e) + " | " + std::to_string(count_checks(e)) + " | " + e.detail + " |\n";
  s += "\n## Comparisons, entry by entry\n\n";
  for (const auto& e : entries) {
    if (e.kind == EntryKind::definition) continue;
    s += "### `" + e.id + "`: " + status_of(e) + "\n\n";
    if (!e.claim.empty()) s += "> " + e.claim + "\n\n";
    if (!e.printed_latex.empty()) s += "Printed: $" + e.printed_latex + "$\n\n";
    s += checks_markdown(e.checks);
    if (!e.corrections.empty()) s += "Corrected: $$" + e.corrected_latex + "$$\n\n" + checks_markdown(e.corrections);
    for (const auto& r : e.readings)
      s += "Reading: " + r.description + (r.used_by_implementation ? " (the implementation's)" : "") + "\n\n" +
           checks_markdown(r.checks);
  }
  return s;
}

}  // namespace impact3d::symbolic
