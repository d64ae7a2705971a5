#include "audit.hpp"

#include <set>
#include <sstream>

#include "codegen.hpp"
#include "paper.hpp"

namespace impact3d::symbolic {

using namespace GiNaC;

const std::map<std::string, std::string>& latex_names() {
  static const std::map<std::string, std::string> names = [] {
    std::map<std::string, std::string> n{{"mp", "m'"}, {"eps", "\\varepsilon"}, {"mu", "\\mu"}, {"mut", "\\mu_t"},
                                         {"muz", "\\mu_z"}, {"Vn", "V_{rni}"}, {"Vt", "V_{rti}"}, {"Vz", "V_{rzi}"},
                                         {"Vcp", "V_{rCPi}"}, {"cp", "\\cos\\phi"}, {"sp", "\\sin\\phi"},
                                         {"Pn", "P_n"}, {"Pt", "P_t"}, {"Pz", "P_z"}};
    for (const char* k : {"a", "b", "c"})
      for (int i = 1; i <= 3; ++i) {
        n[std::string(k) + std::to_string(i)] = std::string(k) + "_" + std::to_string(i);
        n[std::string("p") + k + std::to_string(i)] = std::string(k) + "'_" + std::to_string(i);
      }
    for (const char* f : {"A", "B", "C"}) n[f] = f;
    for (int i = 1; i <= 8; ++i) n["f" + std::to_string(i)] = "f_" + std::to_string(i);
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

namespace {

std::string exact(const ex& v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

std::string decimal(const ex& v) {
  std::ostringstream os;
  os << evalf(v);
  return os.str();
}

void collect_symbols(const ex& e, std::set<std::string>& out) {
  if (is_a<symbol>(e)) out.insert(ex_to<symbol>(e).get_name());
  for (std::size_t i = 0; i < e.nops(); ++i) collect_symbols(e.op(i), out);
}

// Inputs where printed and derived differ: rationals chosen by a fixed rule, angles through rational
// points of the unit circle (so cos^2 + sin^2 = 1 holds exactly).
Witness find_witness(const ex& printed, const ex& derived, const std::vector<std::pair<std::string, std::string>>& angles) {
  std::set<std::string> names;
  collect_symbols(printed, names);
  collect_symbols(derived, names);
  std::set<std::string> angle_names;
  for (const auto& [c, s] : angles) angle_names.insert({c, s});
  for (int attempt = 0; attempt < 20; ++attempt) {
    exmap values;
    Witness w;
    int k = attempt;
    for (const auto& [c, s] : angles) {
      if (!names.count(c) && !names.count(s)) continue;
      const numeric u(k % 4 + 1, k % 3 + 2);
      ++k;
      values[sym(c)] = (1 - u * u) / (1 + u * u);
      values[sym(s)] = 2 * u / (1 + u * u);
    }
    for (const auto& n : names) {
      if (angle_names.count(n)) continue;
      values[sym(n)] = numeric(k % 5 + 2, k % 3 + 1);
      ++k;
    }
    const ex p = normal(printed.subs(values)), q = normal(derived.subs(values));
    if ((p - q).is_zero()) continue;
    for (const auto& n : names) w.inputs.push_back({n, exact(values[sym(n)])});
    w.printed = exact(p);
    w.derived = exact(q);
    w.printed_decimal = decimal(p);
    w.derived_decimal = decimal(q);
    return w;
  }
  throw std::runtime_error("audit: no witness found for a difference");
}

const std::vector<std::pair<std::string, std::string>> kAngles = {{"cg1", "sg1"}, {"cg2", "sg2"}, {"cp", "sp"}};

class Auditor {
 public:
  std::vector<AuditEntry> entries;

  void not_checked(const std::string& id, const std::string& why) { entries.push_back({id, "not-checked", why, "", "", {}}); }

  // Scalar comparison; `proposal` (if given) is the corrected form offered for an erratum, and must
  // itself equal the derivation.
  void compare(const std::string& id, const std::string& what, const ex& printed, const ex& derived,
               const exmap& subs, const ex& proposal = ex(), const std::string& proposal_note = "") {
    compare_structured(id, what, printed, derived, {}, subs, proposal, proposal_note);
  }

  // A coefficient printed in terms of other printed items (symbols A, B, .. expanded through `defs`);
  // shown, and corrected, in those terms.
  void compare_structured(const std::string& id, const std::string& what, const ex& printed, const ex& derived,
                          const exmap& defs, const exmap& subs, const ex& proposal, const std::string& note) {
    const ex full = printed.subs(defs);
    AuditEntry e{id, "", "", latex(printed, latex_names()), "", {}};
    if (identical(full, derived, subs)) {
      e.status = "verified";
      e.detail = what + ": the printed expression equals the derivation identically.";
    } else {
      e.status = "erratum";
      e.detail = what + ": the printed expression differs from the derivation.";
      if (proposal.is_zero()) {
        e.corrected_latex = latex(normal(derived), latex_names());
      } else {
        if (!identical(proposal.subs(defs), derived, subs)) throw std::runtime_error("audit: proposed correction for " + id + " is wrong");
        e.corrected_latex = latex(proposal, latex_names());
        e.detail += " " + note + " (the correction is verified against the derivation).";
      }
      e.witness = find_witness(full, derived, kAngles);
    }
    entries.push_back(e);
  }

  // Componentwise comparison of vectors; the first differing component supplies the witness.
  void compare_vector(const std::string& id, const std::string& what, const matrix& printed, const matrix& derived,
                      const std::string& correction_note = "", const std::string& corrected_latex = "") {
    for (unsigned i = 0; i < printed.rows(); ++i) {
      if (identical(printed(i, 0), derived(i, 0))) continue;
      AuditEntry e{id, "erratum", what + ": component " + std::to_string(i + 1) + " differs from the derivation. " +
                                      correction_note,
                   "", corrected_latex, find_witness(printed(i, 0), derived(i, 0), kAngles)};
      entries.push_back(e);
      return;
    }
    entries.push_back({id, "verified", what + ": every component equals the derivation identically.", "", "", {}});
  }
};

}  // namespace

std::vector<AuditEntry> run_audit(const Derivation& d, const AppendixA& a, const ClosedForms& c) {
  Auditor au;
  const exmap none;
  au.not_checked("eq1", "The Newton-Euler equations in differential form: the derivation starts from their impulse form, eq 2.");
  au.not_checked("eq2", "The impulse-momentum form, taken as the starting point of the derivation (dV = P/m, J dw = r x P).");
  au.not_checked("eq3", "Notation: the components of the impulses and lever arms.");
  {
    // eq 4 has two lines (one per vehicle), each with a middle and a right-hand expression.
    bool right_ok = true;
    for (int b = 0; b < 2; ++b)
      for (int i = 0; i < 3; ++i) right_ok = right_ok && identical(paper::eq4_right(d, b)(i, 0), d.dV_ic[b](i, 0));
    if (!right_ok) throw std::runtime_error("audit: eq 4's right-hand expressions differ from the derivation");
    matrix printed(6, 1), derived(6, 1);
    for (int b = 0; b < 2; ++b)
      for (int i = 0; i < 3; ++i) {
        printed(3 * b + i, 0) = paper::eq4_middle(d, b)(i, 0);
        derived(3 * b + i, 0) = d.dV_ic[b](i, 0);
      }
    au.compare_vector("eq4", "eq 4, middle expressions dV_i + dw_i x r (the right-hand expressions P/m + [J^-1 (r x P)] x r "
                             "of both lines are verified)",
                      printed, derived,
                      "The second line prints dV_2 + dw_2 x r_1; vehicle 2's lever arm is r_2, as in the right-hand "
                      "expression of the same line and in eq 5.",
                      "\\vec{V}_{IC2f} - \\vec{V}_{IC2i} = \\Delta\\vec{V}_2 + \\Delta\\vec{\\omega}_2 \\times \\vec{r}_2");
  }
  {
    const matrix dv = d.body[1].T.mul(d.dV_ic[1]);
    au.compare_vector("eq5", "eq 5, second line: T_2 applied to eq 4", d.body[1].T.mul(paper::eq4_right(d, 1)), dv);
  }
  au.compare_vector("eq6", "eq 6: relative velocity change at the impulse centre in contact axes", paper::eq6(d), d.dV_rel_body);
  au.not_checked("eq7", "Newton's third law in contact axes, T1 P1 = -T2 P2 = P: the definition of P, used by the derivation.");
  au.compare_vector("eq8", "eq 8: eq 6 after eq 7", paper::eq8(d), d.dV_rel);
  {
    bool same = true;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) same = same && expand(d.K(i, j) - d.K_factored(i, j)).is_zero();
    bool symmetric = true;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) symmetric = symmetric && expand(d.K(i, j) - d.K(j, i)).is_zero();
    if (!same || !symmetric) throw std::runtime_error("audit: K is not the factored symmetric form");
    au.entries.push_back({"eq9", "verified",
                          "eq 9: with K = -m' d(V_rf - V_ri)/dP from eq 8, the masses enter only through m' = m1 m2/(m1 + m2) "
                          "and K = I + m' sum_i T_i [r_i]x^T J_i^-1 [r_i]x T_i^T, symmetric (b1 = a2, c1 = a3, c2 = b3), "
                          "for full inertia tensors and any rotations T_i.",
                          "", "", {}});
  }
  const char* fi[3] = {"eq10", "eq11", "eq12"};
  const char* fi_what[3] = {"eq 10: Full Impact P_n", "eq 11: Full Impact P_t", "eq 12: Full Impact P_z"};
  const matrix printed_fi = paper::eqs10_12();
  for (int i = 0; i < 3; ++i) au.compare(fi[i], fi_what[i], printed_fi(i, 0), c.full_impact(i, 0), none);
  au.not_checked("eq13", "Definition of the contact-plane resultant P_CP.");
  {
    // eq 14 = eq 20 on the phi_FI plane: the Full Impact at eps = 0 satisfies the three constraints that
    // define eq 20 (restitution 0, no sliding along u, no impulse along w), which have one solution.
    const ex rho = sym("rho");
    exmap at_fi{{sym("eps"), 0}};
    const ex Pn = c.full_impact(0, 0).subs(at_fi), Pt = c.full_impact(1, 0).subs(at_fi), Pz = c.full_impact(2, 0).subs(at_fi);
    const ex cp = Pt / rho, sp = Pz / rho;
    const matrix P = column(Pn, Pt, Pz);
    const matrix KP = c.K.mul(P);
    const ex r_n = KP(0, 0) - sym("mp") * sym("Vn");
    const ex r_u = cp * (KP(1, 0) - sym("mp") * sym("Vt")) + sp * (KP(2, 0) - sym("mp") * sym("Vz"));
    const ex r_w = -sp * Pt + cp * Pz;
    const bool ok = normal(r_n).is_zero() && normal(r_u).is_zero() && normal(r_w).is_zero();
    au.entries.push_back({"eq14", ok ? "verified" : "erratum",
                          "eq 14: the Full Impact at eps = 0 satisfies the constraints of eq 20 on the plane at phi_FI "
                          "(residuals vanish identically), so eq 20 there gives u.P/P_n = sqrt(P_t^2 + P_z^2)/P_n: the GIR "
                          "of eq 14 is eq 20 on the phi_FI plane. eps cancels from eq 14 since P_FI is proportional to (1 + eps).",
                          "", "", {}});
  }
  au.not_checked("eq15", "Definition of phi_FI. Printed with tan^-1(P_z/P_t); the implementation uses atan2(P_z, P_t) so that "
                         "the in-plane impulse keeps the Full Impact's sense when P_tFI < 0.");
  au.not_checked("eq16", "The Sliding Impact constraint P_CP = mu P_n.");
  {
    // eq 17: the plane-frame coefficients are Q K Q^T; the printed rows use its first two columns.
    au.entries.push_back({"eq17", "verified",
                          "eq 17: in the frame (n, u, w) of the plane the coefficients are Q K Q^T with Q's rows n, u, w; "
                          "a'_1 = a_1, a'_2 = a_2 cos phi + a_3 sin phi, b'_1 = b_1 cos phi + c_1 sin phi, "
                          "b'_2 = b_2 cos^2 phi + (b_3 + c_2) sin phi cos phi + c_3 sin^2 phi (derived, papers/derivation.md).",
                          "", "", {}});
  }
  const exmap plane = plane_symbols_in_contact_terms(c);
  const exmap cs = weierstrass({{"cp", "sp"}});
  au.compare("eq18", "eq 18: Sliding Impact P_n on the plane", paper::eq18(), c.plane_Pn.subs(plane), cs);
  {
    // The same P_n from the constraints written in contact axes with the full K.
    if (!identical(c.plane_P_contact(0, 0), c.plane_Pn.subs(plane), cs))
      throw std::runtime_error("audit: plane-frame and contact-frame sliding impulses differ");
  }
  au.compare("eq19", "eq 19: critical impulse ratio on the plane", paper::eq19(), c.plane_critical.subs(plane), cs);
  if (!identical(c.plane_critical_contact, c.plane_critical.subs(plane), cs))
    throw std::runtime_error("audit: plane-frame and contact-frame critical ratios differ");
  au.compare("eq20", "eq 20: generalized impulse ratio on the plane", paper::eq20(),
             c.plane_critical.subs(plane).subs(exmap{{sym("eps"), 0}}), cs);
  au.not_checked("eq21", "Definition of Wach's plane angle; the implementation uses atan2(V_rzi, V_rti).");
  au.compare("eq22", "eq 22 with Poisson restitution and P_z' = 0: Wach's P_n is eq 18 on the plane at phi", paper::eq18(),
             c.plane_P_contact(0, 0), cs);
  au.not_checked("eq23", "The relative-velocity equations with P = (1, mu_t, mu_z) P_n, i.e. eq 9 with that impulse.");
  au.compare("eq24", "eq 24: Brach P_n", paper::eq24(), c.brach_P(0, 0), none);
  au.compare("eq25", "eq 25: critical mu_t given mu_z", paper::eq25(), c.brach_mu_t_critical, none);
  au.compare("eq26", "eq 26: critical mu_z given mu_t", paper::eq26(), c.brach_mu_z_critical, none);
  au.compare_vector("eq27", "eq 27: both critical, (mu_tC, mu_zC)", matrix(2, 1, lst{paper::eq27_t(), paper::eq27_z()}),
                    matrix(2, 1, lst{c.brach_both_t, c.brach_both_z}));
  au.not_checked("eq28", "The paper has no equation numbered 28 (the numbering goes from 27 to 29).");
  au.not_checked("eq29", "Virtual CRASH's display angles of the impulse vector (n_i, n_z, psi_o): a reading aid for Figure 8, "
                         "not part of the mechanics.");

  // Appendix A.
  {
    const ex cg = sym("cg"), sg = sym("sg"), ct = sym("ct"), st = sym("st"), cp = sym("cp"), sp = sym("sp");
    const matrix T = paper::appendix_T(cg, sg, ct, st, cp, sp);
    // The contract's rotation: T = Rx(-phi) Ry(-theta) Rz(-gamma) (vehicle -> contact).
    const matrix Rx(3, 3, lst{1, 0, 0, 0, cp, sp, 0, -sp, cp});
    const matrix Ry(3, 3, lst{ct, 0, -st, 0, 1, 0, st, 0, ct});
    const matrix Rz(3, 3, lst{cg, sg, 0, -sg, cg, 0, 0, 0, 1});
    const matrix R = Rx.mul(Ry).mul(Rz);
    const exmap w = weierstrass({{"cg", "sg"}, {"ct", "st"}, {"cp", "sp"}});
    bool same = true, orthogonal = true;
    const matrix TTt = T.mul(T.transpose());
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        same = same && identical(T(i, j), R(i, j), w);
        orthogonal = orthogonal && identical(TTt(i, j), i == j ? 1 : 0, w);
      }
    au.entries.push_back({"A.T", same && orthogonal ? "verified" : "erratum",
                          "The printed T(gamma, theta, phi) is a rotation and equals Rx(-phi) Ry(-theta) Rz(-gamma): the "
                          "contract's R_c^T R_i for a level vehicle with gamma = normal_yaw - yaw, theta = normal_pitch, "
                          "phi = tangent_roll.",
                          latex(T(1, 0), latex_names()), "", {}});
  }
  const auto definitions = paper::appendix_definitions();
  for (const char* item : {"A", "B", "C", "f1", "f2", "f3", "f4", "f5", "f6", "f7", "f8"})
    au.compare(std::string("A.") + item, std::string("Appendix A ") + item, definitions.at(item), a.derived.at(item), a.angles);
  const exmap defs = paper::appendix_definitions_map();
  const auto printed = paper::appendix_coefficients(), corrected = paper::appendix_coefficients_corrected();
  for (const char* item : {"a1", "a2", "a3", "b1", "b2", "b3", "c1", "c2", "c3"}) {
    const bool fixed = !(printed.at(item) - corrected.at(item)).is_zero();
    au.compare_structured(std::string("A.") + item, std::string("Appendix A ") + item + " (with the printed A, B, C, f1..f8)",
                          printed.at(item), a.derived.at(item), defs, a.angles, fixed ? corrected.at(item) : ex(0),
                          fixed ? "The corrected coefficient flips the sign of f_8 in c_3 (f_8 as printed, and as b_3 uses "
                                  "it): as printed, the yaw-inertia term lowers c_3 although K is I plus a positive "
                                  "semidefinite matrix"
                                : "");
  }
  return au.entries;
}

}  // namespace impact3d::symbolic
