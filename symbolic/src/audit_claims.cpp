// The audit's entries for statements of the text: Figure 8's prose and the conclusions, each decided by
// a computation on the derived closed forms (coefficients a1..c3 of eq 9, initial velocity Vn, Vt, Vz).
#include "audit_checks.hpp"
#include "audit_parts.hpp"

#include <sstream>

namespace impact3d::symbolic {

using namespace GiNaC;

void audit_claims(std::vector<AuditEntry>& out, const ClosedForms& general) {
  // K is symmetric (eq 9's derivation): b1 = a2, c1 = a3, c2 = b3. A claim is decided on symmetric K; a
  // rational function not identically zero there is nonzero on all but a thin set of configurations, so
  // its witness, a point where it is nonzero, decides "generally".
  const exmap symmetric{{sym("b1"), sym("a2")}, {sym("c1"), sym("a3")}, {sym("c2"), sym("b3")}};
  ClosedForms c = general;
  for (matrix* m : {&c.K, &c.full_impact, &c.plane_K, &c.plane_P_contact, &c.brach_P}) *m = ex_to<matrix>(m->subs(symmetric));
  for (ex* e : {&c.plane_critical_contact, &c.brach_both_t, &c.brach_both_z, &c.energy_change}) *e = e->subs(symmetric);
  const exmap& angles = all_angles();
  const ex mp = sym("mp"), eps = sym("eps"), cp = sym("cp"), sp = sym("sp"), Vt = sym("Vt"), Vz = sym("Vz");
  const exmap horizontal{{Vz, 0}};  // Figure 8: no vertical component of the initial velocities
  const exmap no_restitution{{eps, 0}};
  // The relative velocity after an impulse P: eq 9, V_rf = V_ri - K P / m'.
  auto after = [&](const matrix& P) { return c.V.sub(c.K.mul(P).mul_scalar(1 / mp)); };
  const matrix& P_fi = c.full_impact;
  const matrix V_fi = after(P_fi);
  const matrix minus_eps_V = c.V.mul_scalar(-eps);
  // The plane at (cos phi, sin phi) is phi_FI when the Full Impact lies in it: -sin phi P_tFI + cos phi P_zFI = 0,
  // linear in the initial velocity. Solving it for one velocity component makes phi_FI the free angle, so
  // that a claim about the phi_FI plane is decided on that plane and no other.
  auto on_fi_plane = [&](const exmap& given, const ex& unknown) {
    const matrix P = ex_to<matrix>(P_fi.subs(given));
    const ex sol = lsolve(lst{-sp * P(1, 0) + cp * P(2, 0) == 0}, lst{unknown});
    exmap m = given;
    m[unknown] = normal(sol.op(0).rhs());
    return m;
  };
  const exmap fig8_plane = on_fi_plane(horizontal, Vt);  // Figure 8: V_rzi = 0, phi_FI free
  const exmap fi_plane = on_fi_plane({}, Vz);             // any initial velocity, phi_FI free
  auto at = [](const matrix& m, const exmap& s) { return ex_to<matrix>(m.subs(s)); };
  const matrix& P_slide = c.plane_P_contact;  // restitution, P_CP = mu P_n along u, none along w

  {
    const numeric before_mph(25), after_mph(numeric(-22, 10));
    std::ostringstream eps_needed;
    eps_needed << ex_to<numeric>(-after_mph / before_mph).to_double();
    out.push_back(claim(
        "fig8.full_t_sliding",
        "The post-impact sliding velocity along the tangential axis was -2.2 mph (reversed sliding) for the Full Impact "
        "configuration [initial sliding 25 mph along +t].",
        "Eqs 10-12 leave V_rf = -eps V_ri for any vehicles, so the t sliding after a Full Impact is -eps x 25 mph: "
        "reversed for every eps > 0, as the text says. Its -2.2 mph means eps = " + eps_needed.str() +
            ", a value the paper does not state: the number itself is not decided.",
        Auditor::compare_each("V_rf at the Full Impact against -eps V_ri", kContactAxes, V_fi, minus_eps_V)));
  }
  out.push_back(claim(
      "fig8.full_swerve",
      "Both example configurations resulted in small swerve components of less than 0.5 mph; downward relative to the "
      "Malibu for the Full Impact configuration.",
      "With no vertical initial velocity (V_rzi = 0), eqs 10-12 give V_rzf = -eps V_rzi = 0 for any vehicles and any eps: "
      "a Full Impact cannot swerve here. The swerve the paper reports for its Full Impact is not a consequence of eqs "
      "10-12 (the Sliding Impact's swerve is: fig8.sliding_swerve).",
      {Auditor::differs("z sliding after the Full Impact with V_rzi = 0", V_fi(2, 0).subs(horizontal), 0, {}, "V_rzf",
                        "zero")}));
  out.push_back(claim(
      "fig8.vertical_impulse",
      "The initial relative velocity vector in these configurations is purely in the x-y (horizontal) plane yet both "
      "solutions result in a vertical component for the resulting impulse.",
      "P_zFI of eq 12 with V_rzi = 0 is m'(1 + eps)(V_rni (a_2 b_3 - a_3 b_2) + V_rti (a_3 b_1 - a_1 b_3)) / D, not "
      "identically zero: the witness is a configuration with a vertical Full Impact impulse. The Sliding Impact shares "
      "its P_z / P_t (fig8.same_ratio).",
      {Auditor::differs("P_zFI with V_rzi = 0", P_fi(2, 0).subs(horizontal), 0, {}, "P_zFI", "zero")}));
  {
    const matrix P = at(P_slide, fig8_plane), F = at(P_fi, fig8_plane);
    out.push_back(claim(
        "fig8.same_ratio",
        "Using the stated impulse vector orientation values (n_i and n_z) highlighted in Figure 8 it can be shown, using "
        "equation 29, that both solutions result in the same contact plane impulse ratio (P_z/P_t). This then indicates "
        "both solutions reside on the Full Impact impulse-space solution plane.",
        "On the phi_FI plane of Figure 8's setting (V_rzi = 0, V_rti such that the Full Impact lies in the plane), the "
        "Sliding Impact's P_z / P_t equals the Full Impact's P_zFI / P_tFI. eq 29, which turns the display angles into "
        "P_z / P_t, is verified under its assumptions as eq29; the angles themselves are in the figure's image.",
        {Auditor::compare("P_z P_tFI against P_t P_zFI", P(2, 0) * F(1, 0), P(1, 0) * F(2, 0), angles)}));
  }
  out.push_back(claim(
      "fig8.not_wach",
      "The example Sliding Impact configuration is essentially setup as described by Wach (and the Virtual Crash "
      "User's Guide) but nonetheless results in vertical impulse and swerve velocity components.",
      "With V_rzi = 0 and V_rti > 0, Wach's plane (eq 21) is phi = 0, and its constraint P_z' = 0 leaves P_z = 0: a "
      "vertical impulse means the solution is not on Wach's plane (while the Full Impact's is, fig8.vertical_impulse).",
      {Auditor::compare("P_z of Wach's impulse at phi = 0", P_slide(2, 0).subs(exmap{{cp, 1}, {sp, 0}}), 0)}));
  {
    const matrix P = at(P_slide, fig8_plane);
    const matrix V_after = ex_to<matrix>(after(P).subs(fig8_plane));
    const ex across = -sp * V_after(1, 0) + cp * V_after(2, 0);
    out.push_back(claim(
        "fig8.sliding_swerve",
        "Both example configurations resulted in small swerve components of less than 0.5 mph; [...] upward for the "
        "Sliding Impact configuration.",
        "The Sliding Impact on the phi_FI plane of Figure 8's setting (V_rzi = 0, and V_rti the value that puts the Full "
        "Impact in that plane) leaves a sliding across the plane, w . V_rf, that is not identically zero: a swerve. Its size and sign depend on the vehicles, which the paper "
        "does not give, so they are not decided (examples/fig8_side_impact.json shows one with stand-in vehicles).",
        {Auditor::differs("w . V_rf of the Sliding Impact on the phi_FI plane, V_rzi = 0", across, 0, angles, "w . V_rf",
                          "zero")}));
  }
  {
    const matrix P0 = ex_to<matrix>(P_fi.subs(no_restitution));
    const matrix V0 = after(P0);
    std::vector<Check> checks = Auditor::compare_each("V_rf at the Full Impact with eps = 0", kContactAxes, V0,
                                                      matrix(3, 1, lst{0, 0, 0}));
    const exmap at_P0{{sym("Pn"), P0(0, 0)}, {sym("Pt"), P0(1, 0)}, {sym("Pz"), P0(2, 0)}};
    const symbol* comps[3] = {&sym("Pn"), &sym("Pt"), &sym("Pz")};
    for (int i = 0; i < 3; ++i)
      checks.push_back(Auditor::compare("d(energy change)/dP_" + kContactAxes[i] + " at that impulse",
                                        c.energy_change.diff(*comps[i]).subs(at_P0), 0));
    out.push_back(claim(
        "conclusion.full_impact_cil",
        "A PC-Crash Full-Impact solution, with the coefficient of restitution value equal to zero, lies at a point in "
        "impulse space that is on the Critical Impulse Line and coincides with the point of maximum energy loss.",
        "At eps = 0 the Full Impact leaves no relative velocity at all (on both no-sliding planes, so on the CIL, and on "
        "the maximum compression plane), and the gradient of the energy change dT = -P.V_ri + P^T K P / (2 m') vanishes "
        "there: with K positive definite it is the maximum of the loss.",
        std::move(checks)));
  }
  {
    const exmap zero_eps{{eps, 0}};
    const matrix P = at(P_slide, fi_plane), F = at(P_fi, fi_plane);
    out.push_back(claim(
        "conclusion.full_impact_plane",
        "A PC-Crash Full-Impact solution with a non-zero coefficient of restitution will reside on a plane defined by "
        "the contact plane components of the zero restitution solution (equation 15) and result in a post-impulse "
        "sliding velocity that will be in the opposite direction to that of the initial sliding velocity. The PC-Crash "
        "Sliding Impact solutions are also constrained to lie in this plane.",
        "P_FI is (1 + eps) times its value at eps = 0, V_rf = -eps V_ri in the contact plane, and on the phi_FI plane "
        "(the initial velocity such that the Full Impact lies in it) the Sliding Impact has the Full Impact's P_z / P_t.",
        {Auditor::compare("P_tFI(eps) P_zFI(0) against P_zFI(eps) P_tFI(0)", P_fi(1, 0) * P_fi(2, 0).subs(zero_eps),
                          P_fi(2, 0) * P_fi(1, 0).subs(zero_eps)),
         Auditor::compare("V_rtf against -eps V_rti", V_fi(1, 0), -eps * Vt),
         Auditor::compare("V_rzf against -eps V_rzi", V_fi(2, 0), -eps * Vz),
         Auditor::compare("Sliding Impact on the phi_FI plane: P_z P_tFI against P_t P_zFI", P(2, 0) * F(1, 0),
                          P(1, 0) * F(2, 0), angles)}));
  }
  {
    // Wach's plane at phi along the initial sliding: V_rti = V cos phi, V_rzi = V sin phi (V = sym Vcp). The
    // critical ratio and P_n come from the same symmetric K as the velocity after.
    const exmap along{{Vt, sym("Vcp") * cp}, {Vz, sym("Vcp") * sp}};
    const ex mu_cir = c.plane_critical.subs(plane_symbols_in_contact_terms(c)).subs(symmetric).subs(along);
    const ex Pn = (mp * (1 + eps) * sym("Vn")) /
                  (c.K(0, 0) + mu_cir * (c.K(0, 1) * cp + c.K(0, 2) * sp));  // eq 18 with mu = mu_CIR
    const matrix P = column(Pn, mu_cir * cp * Pn, mu_cir * sp * Pn);
    const matrix V_after = ex_to<matrix>(after(P).subs(along));
    const ex in_plane = cp * V_after(1, 0) + sp * V_after(2, 0), across = -sp * V_after(1, 0) + cp * V_after(2, 0);
    out.push_back(claim(
        "conclusion.wach",
        "Solutions using this approach will generally lie in an impulse-space plane in which a Full Impact solution "
        "cannot be found and one in which out-of-plane post-impact velocities will generally always exist, even for "
        "Wach's limiting critical impulse ratio.",
        "Wach's plane holds the Full Impact only if V_rzi P_tFI = V_rti P_zFI, which is not an identity; at Wach's "
        "critical ratio the sliding along the plane stops (u . V_rf = 0, the CIR's definition, checked) and the sliding "
        "across it, w . V_rf, is not identically zero.",
        {Auditor::differs("V_rzi P_tFI against V_rti P_zFI", Vz * P_fi(1, 0), Vt * P_fi(2, 0), {}, "V_rzi P_tFI",
                          "V_rti P_zFI"),
         Auditor::compare("u . V_rf at Wach's CIR", in_plane, 0, angles),
         Auditor::differs("w . V_rf at Wach's CIR", across, 0, angles, "w . V_rf", "zero")}));
  }
  {
    const matrix P = column(1, c.brach_both_t, c.brach_both_z).mul_scalar(c.brach_P(0, 0).subs(
        exmap{{sym("mut"), c.brach_both_t}, {sym("muz"), c.brach_both_z}}));
    const matrix V_after = after(P);
    out.push_back(claim(
        "conclusion.brach_cil",
        "Ultimately, this model provides the user the ability to specify impulse solutions along the Critical Impulse "
        "Line if one so chooses.",
        "With both ratios critical (eq 27) and P_n from eq 24, the sliding after is zero along t and z, whatever eps: "
        "the impulse is on the Critical Impulse Line.",
        {Auditor::compare("V_rtf with eq 27's ratios", V_after(1, 0), 0),
         Auditor::compare("V_rzf with eq 27's ratios", V_after(2, 0), 0)}));
  }
}

}  // namespace impact3d::symbolic
