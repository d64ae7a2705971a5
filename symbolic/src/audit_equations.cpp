// The audit's entries for the paper's numbered equations and Appendix A.
#include "audit_parts.hpp"

#include "audit_checks.hpp"
#include "codegen.hpp"
#include "paper.hpp"

namespace impact3d::symbolic {

using namespace GiNaC;

namespace {

const std::vector<std::string> kBodyAxes = {"x (vehicle axes)", "y (vehicle axes)", "z (vehicle axes)"};

void append(std::vector<Check>& to, std::vector<Check> more) {
  for (auto& c : more) to.push_back(std::move(c));
}

// a_i -> K(i, n), b_i -> K(i, t), c_i -> K(i, z).
exmap coefficient_symbols(const matrix& K) {
  exmap m;
  for (int i = 0; i < 3; ++i) {
    const std::string n = std::to_string(i + 1);
    m[sym("a" + n)] = K(i, 0);
    m[sym("b" + n)] = K(i, 1);
    m[sym("c" + n)] = K(i, 2);
  }
  return m;
}

ex dot3(const matrix& a, const matrix& b) { return a(0, 0) * b(0, 0) + a(1, 0) * b(1, 0) + a(2, 0) * b(2, 0); }

}  // namespace

void audit_equations(std::vector<AuditEntry>& out, const Derivation& d, const ClosedForms& c) {
  const exmap& angles = all_angles();
  const ex mp = sym("mp"), mu = sym("mu"), Pn = sym("Pn"), cp = sym("cp"), sp = sym("sp");
  const ex mp_value = d.body[0].m * d.body[1].m / (d.body[0].m + d.body[1].m);

  out.push_back(definition("eq1", "The Newton-Euler equations in differential form: the derivation starts from their "
                                  "impulse form, eq 2."));
  out.push_back(definition("eq2", "The impulse-momentum form, the derivation's starting point: dV_i = P_i / m_i, "
                                  "J_i dw_i = r_i x P_i, with full symmetric inertia tensors J_i."));
  out.push_back(definition("eq3", "Notation: the components of the impulses and lever arms in vehicle axes."));
  {
    std::vector<Check> checks;
    for (int b = 0; b < 2; ++b) {
      const std::string line = "line " + std::to_string(b + 1) + " (vehicle " + std::to_string(b + 1) + ")";
      append(checks, Auditor::compare_each(line + ", middle expression dV_i + dw_i x r", kBodyAxes,
                                           paper::eq4_middle(d, b, 0), d.dV_ic[b]));
      append(checks, Auditor::compare_each(line + ", right-hand expression P_i/m_i + [J_i^-1 (r_i x P_i)] x r_i",
                                           kBodyAxes, paper::eq4_right(d, b), d.dV_ic[b]));
    }
    AuditEntry e = formula("eq4",
                           "eq 4, both lines, middle and right-hand expressions, each component, against dV_IC = dV + "
                           "dw x r_i from eq 2. The second line prints dV_2 + dw_2 x r_1; vehicle 2's lever arm is r_2, "
                           "as in the right-hand expression of the same line and in eq 5.",
                           std::move(checks));
    e.printed_latex = "\\vec{V}_{IC2f} - \\vec{V}_{IC2i} = \\Delta\\vec{V}_2 + \\Delta\\vec{\\omega}_2 \\times \\vec{r}_1";
    e.corrected_latex = "\\vec{V}_{IC2f} - \\vec{V}_{IC2i} = \\Delta\\vec{V}_2 + \\Delta\\vec{\\omega}_2 \\times \\vec{r}_2";
    e.corrections = Auditor::compare_each("line 2, middle expression dV_2 + dw_2 x r_2", kBodyAxes,
                                          paper::eq4_middle(d, 1, 1), d.dV_ic[1]);
    out.push_back(std::move(e));
  }
  {
    std::vector<Check> checks;
    for (int b = 0; b < 2; ++b)
      append(checks, Auditor::compare_each("line " + std::to_string(b + 1) + ": T_" + std::to_string(b + 1) +
                                               " applied to eq 4's right-hand side, contact axes",
                                           kContactAxes, paper::eq5(d, b), d.body[b].T.mul(d.dV_ic[b])));
    out.push_back(formula("eq5", "eq 5, both lines, each contact-axis component, against T_i dV_IC,i.", std::move(checks)));
  }
  out.push_back(formula("eq6", "eq 6: the relative velocity change at the impulse centre, T_2 dV_IC2 - T_1 dV_IC1.",
                        Auditor::compare_each("eq 6", kContactAxes, paper::eq6(d), d.dV_rel_body)));
  out.push_back(definition("eq7", "Newton's third law in contact axes, T_1 P_1 = -T_2 P_2 = P: the definition of P "
                                  "(with T_i^-1 = T_i^T for a rotation)."));
  out.push_back(formula("eq8", "eq 8: eq 6 after eq 7 (P_1 = T_1^T P, P_2 = -T_2^T P).",
                        Auditor::compare_each("eq 8", kContactAxes, paper::eq8(d), d.dV_rel)));
  {
    // Each row: the printed -(a_i Pn + b_i Pt + c_i Pz) / m' with the coefficients of the mass-free form
    // K = I + m' sum T [r]x^T J^-1 [r]x T^T and m' = m1 m2 / (m1 + m2), against eq 8.
    const matrix printed = ex_to<matrix>(paper::eq9().subs(coefficient_symbols(d.K_factored)).subs(exmap{{mp, mp_value}}))
                               .mul_scalar(1 / mp_value);
    out.push_back(formula("eq9",
                          "eq 9, each row, with m' = m1 m2 / (m1 + m2) and K = I + m' sum_i T_i [r_i]x^T J_i^-1 [r_i]x "
                          "T_i^T (row i of K is a_i, b_i, c_i), against eq 8: the masses enter only through m', for full "
                          "inertia tensors and any rotations T_i.",
                          Auditor::compare_each("eq 9", {"row n", "row t", "row z"}, printed, d.dV_rel)));
  }
  {
    const matrix printed_fi = paper::eqs10_12();
    const char* name[3] = {"eq10", "eq11", "eq12"};
    const char* what[3] = {"eq 10: Full Impact P_n", "eq 11: Full Impact P_t", "eq 12: Full Impact P_z"};
    for (int i = 0; i < 3; ++i)
      out.push_back(formula(name[i], std::string(what[i]) + ", against K P = m'(1 + eps) V_ri solved for P.",
                            {Auditor::compare(what[i], printed_fi(i, 0), c.full_impact(i, 0))}, tex(printed_fi(i, 0))));
  }
  out.push_back(definition("eq13", "Definition of the contact-plane resultant P_CP."));
  {
    // eq 14's ratio sqrt(P_tFI^2 + P_zFI^2) / P_nFI against the GIR of eq 20 on the plane at phi_FI, i.e. with
    // (cos phi, sin phi) = (P_tFI, P_zFI) / rho, rho = sqrt(P_tFI^2 + P_zFI^2). Both sides are rho times a
    // rational function of the coefficients, so rho cancels from their quotient: the comparison is exact.
    const ex rho = sym("rho");
    const exmap at_fi{{sym("eps"), 0}};
    const ex Pn0 = c.full_impact(0, 0).subs(at_fi), Pt0 = c.full_impact(1, 0).subs(at_fi), Pz0 = c.full_impact(2, 0).subs(at_fi);
    const ex gir = c.plane_critical.subs(plane_symbols_in_contact_terms(c)).subs(exmap{{sym("eps"), 0}});
    const ex gir_on_fi_plane = gir.subs(exmap{{cp, Pt0 / rho}, {sp, Pz0 / rho}});
    const ex printed14 = rho / Pn0;
    out.push_back(formula(
        "eq14",
        "eq 14's ratio sqrt(P_tFI^2 + P_zFI^2) / P_nFI against eq 20, the GIR, on the plane at phi_FI (eq 15); eps "
        "cancels from eq 14 since P_FI is proportional to (1 + eps), so it is compared at eps = 0.",
        {Auditor::compare("eq 14's ratio against eq 20 at phi_FI, both divided by rho = sqrt(P_tFI^2 + P_zFI^2)",
                          printed14 / rho, normal(gir_on_fi_plane / rho))}));
  }
  out.push_back(definition("eq15", "Definition of phi_FI. Printed with tan^-1(P_z/P_t); the implementation uses "
                                   "atan2(P_z, P_t) so that the in-plane impulse keeps the Full Impact's sense when "
                                   "P_tFI < 0."));
  out.push_back(definition("eq16", "The Sliding Impact's constraint P_CP = mu P_n, which with restitution and no impulse "
                                   "across the plane defines it; its consequence, eq 18, is compared there."));
  {
    // The plane's frame (n, u, w): an impulse in the plane is (Pn, cos phi Pcp, sin phi Pcp) in contact
    // axes, and m' times the velocity change along n, u, w is -Q K P.
    const matrix Q(3, 3, lst{1, 0, 0, 0, cp, sp, 0, -sp, cp});
    const matrix P_plane = column(Pn, cp * sym("Pcp"), sp * sym("Pcp"));
    const matrix derived = Q.mul(c.K).mul(P_plane).mul_scalar(-1);
    const matrix derived_right = ex_to<matrix>(derived.subs(exmap{{sym("Pcp"), mu * Pn}}));
    const std::vector<std::string> rows = {"row 1 (n)", "row 2 (CP: along u)", "row 3 (b: across the plane, the swerve)"};
    const exmap primed = coefficient_symbols(c.plane_K);
    Reading plane{"a_i, b_i are the coefficients in the plane's frame (n, u, w) (\"determined for phi_FI\")",
                  "a_i \\to (Q K Q^T)_{i1}, \\; b_i \\to (Q K Q^T)_{i2}, \\quad Q = \\begin{bmatrix} 1 & 0 & 0 \\\\ 0 & "
                  "\\cos\\phi & \\sin\\phi \\\\ 0 & -\\sin\\phi & \\cos\\phi \\end{bmatrix}",
                  true, {}};
    append(plane.checks, Auditor::compare_each("middle form", rows, ex_to<matrix>(paper::eq17_middle().subs(primed)),
                                               derived, angles));
    append(plane.checks, Auditor::compare_each("right form (P_CP = mu P_n)", rows,
                                               ex_to<matrix>(paper::eq17_right().subs(primed)), derived_right, angles));
    Reading unprimed{"a_i, b_i are eq 9's coefficients in contact axes (the same unprimed letters)",
                     "a_i \\to K_{i1}, \\; b_i \\to K_{i2}", false, {}};
    append(unprimed.checks, Auditor::compare_each("middle form", rows, paper::eq17_middle(), derived, angles));
    out.push_back(ambiguous(
        "eq17",
        "eq 17 reuses the unprimed a, b of eq 9 for the coefficients on the solution plane. Read as eq 9's "
        "coefficients it differs from the derivation unless phi = 0; read as the plane frame's coefficients "
        "(Q K Q^T, Q's rows n, u, w) all three rows agree, including the third (the velocity across the plane: "
        "swerve). The implementation uses the plane frame's coefficients.",
        "m'(V_{rbf} - V_{rbi}) = -(a_3 P_n + b_3 P_{CP}) = -(a_3 + \\mu_{user} b_3) P_n",
        {std::move(plane), std::move(unprimed)}));
  }
  const exmap plane = plane_symbols_in_contact_terms(c);
  out.push_back(formula("eq18", "eq 18: the Sliding Impact's P_n on a plane at any phi (PC-Crash's phi_FI, Wach's phi), "
                                "with the plane-frame coefficients, against the constraints solved in the plane frame and in "
                                "contact axes.",
                        {Auditor::compare("P_n", paper::eq18(), c.plane_Pn.subs(plane), angles),
                         Auditor::compare("P_n, solved in contact axes with the full K", paper::eq18(),
                                          c.plane_P_contact(0, 0), angles)},
                        tex(paper::eq18())));
  out.push_back(formula("eq19", "eq 19: critical impulse ratio on the plane, r = V_rCPi / V_rni.",
                        {Auditor::compare("mu_CIR", paper::eq19(), c.plane_critical.subs(plane), angles),
                         Auditor::compare("mu_CIR, solved in contact axes with the full K", paper::eq19(),
                                          c.plane_critical_contact, angles)},
                        tex(paper::eq19())));
  out.push_back(formula("eq20", "eq 20: generalized impulse ratio, eq 19 at eps = 0.",
                        {Auditor::compare("mu_GIR", paper::eq20(), c.plane_critical.subs(plane).subs(exmap{{sym("eps"), 0}}),
                                          angles)},
                        tex(paper::eq20())));
  out.push_back(definition("eq21", "Definition of Wach's plane angle; the implementation uses atan2(V_rzi, V_rti) so "
                                   "that the plane follows the sliding's sense."));
  out.push_back(definition("eq22", "Wach's constraint P_t' = mu P_n along t' = (0, cos phi, sin phi) at eq 21's phi; with "
                                   "P_z' = 0 and Poisson restitution it defines Wach's impulse, whose P_n is eq 18 on that "
                                   "plane (compared there for every phi, with the constraints solved in contact axes)."));
  {
    const exmap brach{{sym("Pt"), sym("mut") * Pn}, {sym("Pz"), sym("muz") * Pn}};
    const matrix printed = ex_to<matrix>(paper::eq23().subs(coefficient_symbols(d.K_factored)).subs(exmap{{mp, mp_value}}))
                               .mul_scalar(1 / mp_value);
    out.push_back(formula("eq23",
                          "eq 23, each row: eq 9 with P = (1, mu_t, mu_z) P_n, against eq 8 with that impulse "
                          "(coefficients and m' as in eq 9).",
                          Auditor::compare_each("eq 23", {"row n", "row t", "row z"}, printed, ex_to<matrix>(d.dV_rel.subs(brach)))));
  }
  out.push_back(formula("eq24", "eq 24: Brach's impulse P = (1, mu_t, mu_z) P_n.",
                        {Auditor::compare("P_n", paper::eq24(), c.brach_P(0, 0)),
                         Auditor::compare("P_t = mu_t P_n", sym("mut") * c.brach_P(0, 0), c.brach_P(1, 0)),
                         Auditor::compare("P_z = mu_z P_n", sym("muz") * c.brach_P(0, 0), c.brach_P(2, 0))},
                        tex(paper::eq24())));
  {
    const ex r_velocity = sym("Vt") / sym("Vn");
    const ex r_plane = (sym("Vt") * cp + sym("Vz") * sp) / sym("Vn");
    const std::string velocity = "r = V_rti / V_rni, the t-axis counterpart of eq 26's r_z = V_rzi / V_rni";
    const std::string on_plane = "r = V_rCPi / V_rni as eq 19 defines it, V_rCPi = V_rti cos phi_FI + V_rzi sin phi_FI";
    const std::string velocity_latex = "r = V_{rti} / V_{rni}";
    const std::string on_plane_latex = "r = (V_{rti} \\cos\\phi_{FI} + V_{rzi} \\sin\\phi_{FI}) / V_{rni}";
    out.push_back(ambiguous(
        "eq25",
        "eq 25 uses an r the paper defines only on the phi_FI plane (eq 19); eq 26 defines r_z for the z axis. With "
        "r = V_rti / V_rni it is the derived critical ratio; with eq 19's r it is not. The implementation uses "
        "V_rti / V_rni.",
        "\\mu_{tC} = \\eta_t \\mu_z + \\mu_{tC0}, \\quad \\eta_t = \\frac{r c_1 - (1+\\varepsilon) c_2}"
        "{(1+\\varepsilon) b_2 - r b_1}, \\quad \\mu_{tC0} = \\frac{r a_1 - (1+\\varepsilon) a_2}"
        "{(1+\\varepsilon) b_2 - r b_1}",
        {{velocity, velocity_latex, true, {Auditor::compare("mu_tC", paper::eq25(r_velocity), c.brach_mu_t_critical)}},
         {on_plane, on_plane_latex, false,
          {Auditor::compare("mu_tC", paper::eq25(r_plane), c.brach_mu_t_critical, angles)}}}));
    out.push_back(formula("eq26", "eq 26: critical mu_z given mu_t, r_z = V_rzi / V_rni.",
                          {Auditor::compare("mu_zC", paper::eq26(), c.brach_mu_z_critical)}, tex(paper::eq26())));
    out.push_back(ambiguous(
        "eq27",
        "eq 27 combines eqs 25 and 26 and inherits eq 25's r: with r = V_rti / V_rni both ratios are the derived ones; "
        "with eq 19's r they are not. The implementation uses V_rti / V_rni.",
        "\\mu_{tC} = \\frac{\\eta_t \\mu_{zC0} + \\mu_{tC0}}{1 - \\eta_t \\eta_z}, \\quad "
        "\\mu_{zC} = \\frac{\\eta_z \\mu_{tC0} + \\mu_{zC0}}{1 - \\eta_t \\eta_z}",
        {{velocity,
          velocity_latex,
          true,
          {Auditor::compare("mu_tC", paper::eq27_t(r_velocity), c.brach_both_t),
           Auditor::compare("mu_zC", paper::eq27_z(r_velocity), c.brach_both_z)}},
         {on_plane,
          on_plane_latex,
          false,
          {Auditor::compare("mu_tC", paper::eq27_t(r_plane), c.brach_both_t, angles),
           Auditor::compare("mu_zC", paper::eq27_z(r_plane), c.brach_both_z, angles)}}}));
  }
  {
    // An impulse of azimuth n_i and elevation n_z in world axes, z up; the contact normal horizontal at yaw
    // psi_o, t = z x n (horizontal, psi_o + 90 degrees), z up.
    const ex cni = sym("cni"), sni = sym("sni"), cnz = sym("cnz"), snz = sym("snz"), cpo = sym("cpo"), spo = sym("spo");
    const matrix P_world = column(cnz * cni, cnz * sni, snz);
    const ex P_t = dot3(column(-spo, cpo, 0), P_world), P_z = dot3(column(0, 0, 1), P_world);
    out.push_back(formula(
        "eq29",
        "eq 29 under its assumptions, stated here since the paper does not: n_i is the impulse vector's azimuth in "
        "the world's horizontal plane and psi_o the contact normal's, both from world x toward world y; n_z is the "
        "impulse's elevation above the horizontal; the contact plane is vertical with t = z x n horizontal and z up "
        "(this project's axes). Then P_t = |P| cos n_z sin(n_i - psi_o) and P_z = |P| sin n_z.",
        {Auditor::compare("P_z / P_t", paper::eq29(), P_z / P_t, angles)}, tex(paper::eq29())));
  }
}

}  // namespace impact3d::symbolic
