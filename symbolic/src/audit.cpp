#include "audit.hpp"

#include <set>
#include <sstream>
#include <string_view>
#include <stdexcept>

#include "audit_checks.hpp"
#include "codegen.hpp"
#include "audit_parts.hpp"

namespace impact3d::symbolic {

using namespace GiNaC;

const std::vector<std::string> kContactAxes = {"n", "t", "z"};

const std::map<std::string, std::string>& latex_names() {
  static const std::map<std::string, std::string> names = [] {
    std::map<std::string, std::string> n{{"mp", "m'"}, {"eps", "\\varepsilon"}, {"mu", "\\mu"}, {"mut", "\\mu_t"},
                                         {"muz", "\\mu_z"}, {"Vn", "V_{rni}"}, {"Vt", "V_{rti}"}, {"Vz", "V_{rzi}"},
                                         {"Vcp", "V_{rCPi}"}, {"cp", "\\cos\\phi"}, {"sp", "\\sin\\phi"},
                                         {"Pn", "P_n"}, {"Pt", "P_t"}, {"Pz", "P_z"}, {"Pcp", "P_{CP}"}};
    for (const char* k : {"a", "b", "c"})
      for (int i = 1; i <= 3; ++i) {
        n[std::string(k) + std::to_string(i)] = std::string(k) + "_" + std::to_string(i);
        n[std::string("p") + k + std::to_string(i)] = std::string(k) + "'_" + std::to_string(i);
      }
    for (const char* f : {"A", "B", "C"}) n[f] = f;
    for (int i = 1; i <= 8; ++i) {
      const std::string d = std::to_string(i);  // not "f_" + a temporary: GCC 12's false -Wrestrict (PR 105329)
      n["f" + d] = "f_" + d;
    }
    for (int i = 1; i <= 2; ++i) {
      const std::string s = std::to_string(i);
      n["m" + s] = "m_" + s;
      for (const char* q : {"x", "y", "z"}) n[q + s] = std::string(q) + "_" + s;
      for (const char* q : {"Ix", "Iy", "Iz"}) n[q + s] = std::string("I_{") + q[1] + s + "}";
      n["cg" + s] = "\\cos\\gamma_" + s;
      n["sg" + s] = "\\sin\\gamma_" + s;
    }
    return n;
  }();
  return names;
}

std::string symbol_meaning(const std::string& s) {
  static const std::map<std::string, std::string> fixed{
      {"mp", "m' = m1 m2 / (m1 + m2)"},
      {"eps", "restitution coefficient"},
      {"mu", "impulse ratio along the solution plane"},
      {"mut", "impulse ratio along t (Brach)"},
      {"muz", "impulse ratio along z (Brach)"},
      {"Vn", "initial relative velocity at the impulse centre, n component (V_rni)"},
      {"Vt", "initial relative velocity at the impulse centre, t component (V_rti)"},
      {"Vz", "initial relative velocity at the impulse centre, z component (V_rzi)"},
      {"Vcp", "initial sliding speed along the plane's in-plane axis u (V_rCPi)"},
      {"Pn", "impulse on vehicle 1, n component"},
      {"Pt", "impulse on vehicle 1, t component"},
      {"Pz", "impulse on vehicle 1, z component"},
      {"Pcp", "impulse along the plane's in-plane axis u (P_CP)"},
      {"cp", "cos phi: the solution plane's angle (eqs 17-22), or Appendix A's contact roll"},
      {"sp", "sin phi"},
      {"cg", "cos gamma (Appendix A heading)"},
      {"sg", "sin gamma"},
      {"ct", "cos theta (Appendix A attitude)"},
      {"st", "sin theta"},
      {"A", "Appendix A's A (printed definition)"},
      {"B", "Appendix A's B (printed definition)"},
      {"C", "Appendix A's C (printed definition)"},
      {"cni", "cos n_i: azimuth of the impulse vector, world horizontal plane (Virtual CRASH's display)"},
      {"sni", "sin n_i"},
      {"cnz", "cos n_z: elevation of the impulse vector above the horizontal"},
      {"snz", "sin n_z"},
      {"cpo", "cos psi_o: yaw of the contact normal in the world frame"},
      {"spo", "sin psi_o"}};
  if (auto it = fixed.find(s); it != fixed.end()) return it->second;
  // Built with append: GCC 12 warns falsely (-Wrestrict) on chains of operator+ with single characters.
  auto cat = [](std::initializer_list<std::string_view> parts) {
    std::string out;
    for (auto p : parts) out.append(p);
    return out;
  };
  auto ch = [&](std::size_t i) { return std::string_view(s).substr(i, 1); };
  static const char* axis_name[3] = {"n", "t", "z"};
  static const char* plane_axis[3] = {"n", "u", "w"};
  const std::string vehicle = s.empty() ? "" : cat({"vehicle ", ch(s.size() - 1)});
  // a1..c3: K's entries; the letter is the column (a: n, b: t, c: z), the digit the row.
  if (s.size() == 2 && (s[0] == 'a' || s[0] == 'b' || s[0] == 'c') && s[1] >= '1' && s[1] <= '3')
    return cat({"entry of K (eq 9): row ", axis_name[s[1] - '1'], ", column ", axis_name[s[0] - 'a']});
  if (s.size() == 3 && s[0] == 'p' && (s[1] == 'a' || s[1] == 'b' || s[1] == 'c') && s[2] >= '1' && s[2] <= '3')
    return cat({"entry of K in the plane frame (n, u, w): row ", plane_axis[s[2] - '1'], ", column ", plane_axis[s[1] - 'a']});
  if (s.size() == 2 && s[0] == 'f' && s[1] >= '1' && s[1] <= '8') return cat({"Appendix A's ", s, " (printed definition)"});
  if (s.size() == 2 && s[0] == 'm' && (s[1] == '1' || s[1] == '2')) return cat({"mass of ", vehicle});
  if (s.size() == 2 && (s[0] == 'x' || s[0] == 'y' || s[0] == 'z') && (s[1] == '1' || s[1] == '2'))
    return cat({"impulse centre relative to the CG of ", vehicle, ", ", ch(0), " (vehicle axes)"});
  if (s.size() == 3 && s[0] == 'I' && (s[2] == '1' || s[2] == '2'))
    return cat({"principal moment of inertia of ", vehicle, " about its ", ch(1), " axis"});
  if (s.size() == 3 && (s[0] == 'c' || s[0] == 's') && s[1] == 'g')
    return cat({s[0] == 'c' ? "cos" : "sin", " gamma_", ch(2), ": heading of ", vehicle, " relative to the contact axes"});
  if (s.size() == 3 && s[0] == 'P' && (s[1] == '1' || s[1] == '2'))
    return cat({"impulse on vehicle ", ch(1), ", its own ", ch(2), " axis"});
  if (s.size() == 6 && s.rfind("ji", 0) == 0 && s[3] == '_')
    return cat({"entry (", ch(4), ", ", ch(5), ") of the inverse inertia tensor of vehicle ", ch(2),
                " (symmetric; an identity must hold for every value)"});
  if (s.size() == 5 && s[0] == 'J' && s[2] == '_')
    return cat({"entry (", ch(3), ", ", ch(4), ") of the inertia tensor of vehicle ", ch(1)});
  if (s.size() == 5 && s[0] == 'T' && s[2] == '_')
    return cat({"entry (row ", ch(3), ", column ", ch(4), ") of T_", ch(1), ", vehicle ", ch(1), " axes to contact axes"});
  throw std::logic_error("audit: no meaning written for the symbol " + s);
}

const std::vector<std::pair<std::string, std::string>>& angle_pairs() {
  static const std::vector<std::pair<std::string, std::string>> pairs = {
      {"cg1", "sg1"}, {"cg2", "sg2"}, {"cp", "sp"}, {"cg", "sg"}, {"ct", "st"}, {"cni", "sni"}, {"cnz", "snz"}, {"cpo", "spo"}};
  return pairs;
}

const GiNaC::exmap& all_angles() {
  static const GiNaC::exmap m = weierstrass(angle_pairs());
  return m;
}

namespace {

std::string exact(const ex& v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

// Decimals of two different exact numbers, with as many digits as it takes for them to differ.
std::pair<std::string, std::string> decimals(const ex& p, const ex& q) {
  const long saved = Digits;
  std::pair<std::string, std::string> out;
  for (long digits : {12L, 20L, 40L, 80L, 160L}) {
    Digits = digits;
    std::ostringstream a, b;
    a << evalf(p);
    b << evalf(q);
    out = {a.str(), b.str()};
    if (out.first != out.second) break;
  }
  Digits = saved;
  return out;
}

void collect_symbols(const ex& e, std::set<std::string>& out) {
  if (is_a<symbol>(e)) out.insert(ex_to<symbol>(e).get_name());
  for (std::size_t i = 0; i < e.nops(); ++i) collect_symbols(e.op(i), out);
}

// Inputs where left and right differ: rationals chosen by a fixed rule, angles through rational
// points of the unit circle (so cos^2 + sin^2 = 1 holds exactly).
Witness find_witness(const ex& left, const ex& right, const char* left_name, const char* right_name) {
  std::set<std::string> names;
  collect_symbols(left, names);
  collect_symbols(right, names);
  std::set<std::string> angle_names;
  for (const auto& [c, s] : angle_pairs()) angle_names.insert({c, s});
  for (int attempt = 0; attempt < 20; ++attempt) {
    exmap values;
    int k = attempt;
    for (const auto& [c, s] : angle_pairs()) {
      if (!names.count(c) && !names.count(s)) continue;
      const numeric u(k % 4 + 1, k % 3 + 2);
      ++k;
      values[sym(c)] = (1 - u * u) / (1 + u * u);
      values[sym(s)] = 2 * u / (1 + u * u);
    }
    // Ratios and restitution between 0 and 1, so that a witness reads like a collision; any value decides.
    static const std::set<std::string> fractions = {"eps", "mu", "mut", "muz"};
    for (const auto& n : names) {
      if (angle_names.count(n)) continue;
      values[sym(n)] = fractions.count(n) ? numeric(1, k % 4 + 2) : numeric(k % 5 + 2, k % 3 + 1);
      ++k;
    }
    const ex p = normal(left.subs(values)), q = normal(right.subs(values));
    if ((p - q).is_zero()) continue;
    Witness w;
    for (const auto& n : names) w.inputs.push_back({n, exact(values[sym(n)])});
    w.left_name = left_name;
    w.right_name = right_name;
    w.left = exact(p);
    w.right = exact(q);
    std::tie(w.left_decimal, w.right_decimal) = decimals(p, q);
    return w;
  }
  throw std::runtime_error("audit: no witness found for a difference");
}

}  // namespace

Check Auditor::compare(const std::string& what, const ex& printed, const ex& derived, const exmap& subs,
                       const char* left_name, const char* right_name) {
  if (identical(printed, derived, subs)) return Check(what, true, true, std::nullopt);
  return Check(what, true, false, find_witness(printed, derived, left_name, right_name));
}

Check Auditor::differs(const std::string& what, const ex& left, const ex& right, const exmap& subs, const char* left_name,
                       const char* right_name) {
  if (identical(left, right, subs)) return Check(what, false, true, std::nullopt);
  return Check(what, false, false, find_witness(left, right, left_name, right_name));
}

std::vector<Check> Auditor::compare_each(const std::string& what, const std::vector<std::string>& names,
                                         const matrix& printed, const matrix& derived, const exmap& subs) {
  std::vector<Check> out;
  for (unsigned i = 0; i < printed.rows(); ++i)
    out.push_back(compare(what + ", " + names.at(i), printed(i, 0), derived(i, 0), subs));
  return out;
}

std::string status_of(const AuditEntry& e) {
  auto fail = [&](const std::string& why) -> std::string { throw std::logic_error("audit entry " + e.id + ": " + why); };
  auto all_equal = [](const std::vector<Check>& cs) {
    for (const auto& c : cs)
      if (!c.equal()) return false;
    return true;
  };
  switch (e.kind) {
    case EntryKind::definition:
      if (!e.checks.empty() || !e.readings.empty() || !e.corrections.empty()) fail("a definition carries comparisons");
      return "definition";
    case EntryKind::formula:
      if (e.checks.empty()) fail("no comparison was made");
      if (!e.readings.empty()) fail("a formula has readings");
      for (const auto& c : e.checks)
        if (!c.expect_equal()) fail("a formula's comparison must expect equality");
      if (all_equal(e.checks)) {
        if (!e.corrections.empty()) fail("a correction offered for an expression that agrees");
        return "verified";
      }
      if (e.corrections.empty() || !all_equal(e.corrections) || e.corrected_latex.empty())
        fail("an erratum without a corrected expression that agrees with the derivation");
      return "erratum";
    case EntryKind::ambiguous: {
      if (e.readings.size() < 2) fail("an ambiguity needs at least two readings");
      int used = 0;
      for (const auto& r : e.readings) {
        if (r.checks.empty()) fail("a reading was not compared");
        if (r.used_by_implementation) {
          ++used;
          if (!all_equal(r.checks)) fail("the implementation's reading does not agree with the derivation");
        }
      }
      if (used != 1) fail("exactly one reading must be the implementation's");
      bool another_differs = false;
      for (const auto& r : e.readings) another_differs = another_differs || (!r.used_by_implementation && !all_equal(r.checks));
      if (!another_differs) fail("no other reading differs from the derivation: nothing is ambiguous");
      return "ambiguous";
    }
    case EntryKind::claim:
      if (e.checks.empty()) fail("a claim was not decided by any computation");
      if (e.claim.empty()) fail("a claim without the paper's words");
      for (const auto& c : e.checks)
        if (!c.holds()) return "claim-contradicted";
      return "claim-checked";
  }
  return fail("unknown kind");
}

}  // namespace impact3d::symbolic

namespace impact3d::symbolic {

AuditEntry definition(const std::string& id, const std::string& detail) {
  AuditEntry e;
  e.id = id;
  e.kind = EntryKind::definition;
  e.detail = detail;
  return e;
}

AuditEntry formula(const std::string& id, const std::string& detail, std::vector<Check> checks,
                   const std::string& printed_latex) {
  AuditEntry e = definition(id, detail);
  e.kind = EntryKind::formula;
  e.checks = std::move(checks);
  e.printed_latex = printed_latex;
  return e;
}

AuditEntry ambiguous(const std::string& id, const std::string& detail, const std::string& printed_latex,
                     std::vector<Reading> readings) {
  AuditEntry e = definition(id, detail);
  e.kind = EntryKind::ambiguous;
  e.printed_latex = printed_latex;
  e.readings = std::move(readings);
  return e;
}

AuditEntry claim(const std::string& id, const std::string& words, const std::string& detail, std::vector<Check> checks) {
  AuditEntry e = definition(id, detail);
  e.kind = EntryKind::claim;
  e.claim = words;
  e.checks = std::move(checks);
  return e;
}

std::string tex(const ex& e) { return latex(e, latex_names()); }

std::vector<AuditEntry> run_audit(const Derivation& d, const AppendixA& a, const ClosedForms& c) {
  std::vector<AuditEntry> entries;
  audit_equations(entries, d, c);
  audit_appendix_a(entries, a);
  audit_claims(entries, c);
  for (const auto& e : entries) status_of(e);  // every entry earns its status, or the generator stops
  return entries;
}

}  // namespace impact3d::symbolic
