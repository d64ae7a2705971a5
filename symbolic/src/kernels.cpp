#include "kernels.hpp"

#include "paper.hpp"
#include "stronge_forms.hpp"

namespace impact3d::symbolic {

using namespace GiNaC;

namespace {

const char* kAxis = "xyz";

// C++ for the symbols of eq 9's coefficients and the closed forms' inputs.
std::map<std::string, std::string> coefficient_symbols() {
  std::map<std::string, std::string> m{{"mp", "m_prime"}, {"eps", "e"},     {"Vn", "V(0)"},  {"Vt", "V(1)"},
                                       {"Vz", "V(2)"},    {"cp", "c"},       {"sp", "s"},     {"mu", "mu"},
                                       {"mut", "mu_t"},   {"muz", "mu_z"},   {"Pn", "P(0)"},  {"Pt", "P(1)"},
                                       {"Pz", "P(2)"}};
  const char* k[3] = {"a", "b", "c"};
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 3; ++col)
      m[k[col] + std::to_string(row + 1)] = "K(" + std::to_string(row) + ", " + std::to_string(col) + ")";
  return m;
}

const KernelArg kK{"const Eigen::Matrix<Scalar, 3, 3>& K", "coefficient matrix of eq 9, rows (a_k, b_k, c_k)"};
const KernelArg kMp{"const Scalar& m_prime", "m' = m1 m2 / (m1 + m2)"};
const KernelArg kE{"const Scalar& e", "restitution eps"};
const KernelArg kV{"const Eigen::Matrix<Scalar, 3, 1>& V", "initial relative velocity at the impulse centre (n, t, z)"};
const KernelArg kC{"const Scalar& c", "cos phi of the solution plane (phi from t towards z)"};
const KernelArg kS{"const Scalar& s", "sin phi of the solution plane"};

ex plane_local(const ClosedForms& c, const char* name) {
  return plane_symbols_in_contact_terms(c).at(sym(name));
}

Kernel general_coefficient_matrix(const Derivation& d) {
  Kernel k;
  k.name = "coefficient_matrix";
  k.equations = {"eq9"};
  k.doc = "K of eq 9 from full inertia tensors and general rotations: I + m' sum_i T_i [r_i]x^T J_i^-1 [r_i]x T_i^T "
          "(derived as -m' d(V_rf - V_ri)/dP from eqs 2, 4, 6, 7).";
  k.returns = "Eigen::Matrix<Scalar, 3, 3>";
  k.returns_doc = "K (symmetric)";
  k.args = {kMp,
            {"const Eigen::Matrix<Scalar, 3, 3>& J1", "inertia tensor of vehicle 1 about its CG, body axes (symmetric; upper triangle read)"},
            {"const Eigen::Matrix<Scalar, 3, 3>& J2", "inertia tensor of vehicle 2"},
            {"const Eigen::Matrix<Scalar, 3, 1>& r1", "impulse centre of vehicle 1 relative to its CG, body axes"},
            {"const Eigen::Matrix<Scalar, 3, 1>& r2", "impulse centre of vehicle 2"},
            {"const Eigen::Matrix<Scalar, 3, 3>& T1", "vehicle 1 -> contact axes rotation (the paper's T_1)"},
            {"const Eigen::Matrix<Scalar, 3, 3>& T2", "vehicle 2 -> contact axes rotation"}};
  k.symbol_code["mp"] = "m_prime";
  for (const Body& b : d.body) {
    const std::string n = std::to_string(b.index);
    const char* rc[3] = {"x", "y", "z"};
    for (int p = 0; p < 3; ++p) {
      k.symbol_code[rc[p] + n] = "r" + n + "(" + std::to_string(p) + ")";
      for (int q = 0; q < 3; ++q) {
        k.symbol_code["T" + n + "_" + std::to_string(p + 1) + std::to_string(q + 1)] =
            "T" + n + "(" + std::to_string(p) + ", " + std::to_string(q) + ")";
        if (q >= p) k.symbol_code[std::string("J") + n + "_" + kAxis[p] + kAxis[q]] =
            "J" + n + "(" + std::to_string(p) + ", " + std::to_string(q) + ")";
      }
    }
    // The inverse tensor, J^-1 = adj(J) / det(J), as locals the coefficient expressions use.
    const matrix Jinv = ex_to<matrix>(b.J.inverse());
    for (int p = 0; p < 3; ++p)
      for (int q = p; q < 3; ++q) {
        const std::string name = std::string("ji") + n + "_" + kAxis[p] + kAxis[q];
        k.symbol_code[name] = name;
        k.locals.push_back({name, normal(Jinv(p, q))});
      }
  }
  for (int p = 0; p < 3; ++p)
    for (int q = 0; q < 3; ++q) {
      const int lo = std::min(p, q), hi = std::max(p, q);  // K is symmetric (audit eq9)
      k.outputs.push_back({"out(" + std::to_string(p) + ", " + std::to_string(q) + ")", d.K_factored(lo, hi)});
    }
  return k;
}

Kernel appendix_a_coefficient_matrix() {
  Kernel k;
  k.name = "coefficient_matrix_appendix_a";
  k.equations = {"eq9", "A.A", "A.B", "A.C"};
  for (int i = 1; i <= 8; ++i) k.equations.push_back("A.f" + std::to_string(i));
  for (const char* c : {"a", "b", "c"})
    for (int i = 1; i <= 3; ++i) k.equations.push_back("A." + std::string(c) + std::to_string(i));
  k.doc = "K of eq 9 under the paper's Appendix A assumptions (diagonal inertia tensors, level vehicles, horizontal "
          "normal), from the printed A, B, C, f1..f8 and a1..c3 with c3 corrected (audit A.c3).";
  k.returns = "Eigen::Matrix<Scalar, 3, 3>";
  k.returns_doc = "K";
  k.args = {kMp,
            {"const Eigen::Matrix<Scalar, 3, 1>& I1", "principal moments (Ixx, Iyy, Izz) of vehicle 1"},
            {"const Eigen::Matrix<Scalar, 3, 1>& I2", "principal moments of vehicle 2"},
            {"const Eigen::Matrix<Scalar, 3, 1>& r1", "impulse centre of vehicle 1 relative to its CG, body axes"},
            {"const Eigen::Matrix<Scalar, 3, 1>& r2", "impulse centre of vehicle 2"},
            {"const Scalar& gamma1", "heading of the normal relative to vehicle 1 (normal_yaw - yaw_1), radians"},
            {"const Scalar& gamma2", "heading of the normal relative to vehicle 2, radians"},
            {"const Scalar& phi", "roll of the t axis about n (tangent_roll), radians"}};
  k.symbol_code = {{"mp", "m_prime"}, {"cp", "cp"}, {"sp", "sp"}};
  for (int i = 1; i <= 2; ++i) {
    const std::string n = std::to_string(i);
    for (int p = 0; p < 3; ++p) {
      k.symbol_code[std::string(1, kAxis[p]) + n] = "r" + n + "(" + std::to_string(p) + ")";
      k.symbol_code[std::string("I") + kAxis[p] + n] = "I" + n + "(" + std::to_string(p) + ")";
    }
    k.symbol_code["cg" + n] = "cg" + n;
    k.symbol_code["sg" + n] = "sg" + n;
    k.locals.push_back({"cg" + n, cos(sym("gamma" + n))});
    k.locals.push_back({"sg" + n, sin(sym("gamma" + n))});
    k.symbol_code["gamma" + n] = "gamma" + n;
  }
  k.symbol_code["phi"] = "phi";
  k.locals.push_back({"cp", cos(sym("phi"))});
  k.locals.push_back({"sp", sin(sym("phi"))});
  for (const auto& [name, e] : paper::appendix_definitions()) {
    k.symbol_code[name] = name;
    k.locals.push_back({name, e});
  }
  const auto coef = paper::appendix_coefficients_corrected();
  const char* names[3][3] = {{"a1", "b1", "c1"}, {"a2", "b2", "c2"}, {"a3", "b3", "c3"}};
  for (int p = 0; p < 3; ++p)
    for (int q = 0; q < 3; ++q)
      k.outputs.push_back({"out(" + std::to_string(p) + ", " + std::to_string(q) + ")", coef.at(names[p][q])});
  return k;
}

Kernel full_impact(const ClosedForms& c) {
  Kernel k;
  k.name = "full_impact";
  k.equations = {"eq10", "eq11", "eq12"};
  k.doc = "Full Impact impulse, eqs 10-12: K P = m' (1 + e) V (at e = 0, the maximum-energy-loss impulse).";
  k.returns = "Eigen::Matrix<Scalar, 3, 1>";
  k.returns_doc = "P = (P_n, P_t, P_z) on vehicle 1, contact axes";
  k.args = {kK, kMp, kE, kV};
  k.symbol_code = coefficient_symbols();
  const char* R[3] = {"Rn", "Rt", "Rz"};
  const char* V[3] = {"Vn", "Vt", "Vz"};
  for (int i = 0; i < 3; ++i) {
    k.symbol_code[R[i]] = R[i];
    k.locals.push_back({R[i], sym("mp") * (1 + sym("eps")) * sym(V[i])});
  }
  for (int i = 0; i < 3; ++i) k.outputs.push_back({"out(" + std::to_string(i) + ")", c.full_impact_rhs(i, 0)});
  return k;
}

Kernel plane_impulse(const ClosedForms& c) {
  Kernel k;
  k.name = "plane_impulse";
  k.equations = {"eq17", "eq18", "eq22"};
  k.doc = "Impulse on a solution plane through n at (c, s) with P_CP = mu P_n and none across it: eqs 17-18 "
          "(PC-Crash Sliding Impact at phi_FI, Wach's eq 22 at phi).";
  k.returns = "Eigen::Matrix<Scalar, 3, 1>";
  k.returns_doc = "P = (P_n, P_t, P_z) on vehicle 1, contact axes";
  k.args = {kK, kMp, kE, kV, kC, kS, {"const Scalar& mu", "impulse ratio P_CP / P_n"}};
  k.symbol_code = coefficient_symbols();
  for (const char* n : {"pa1", "pb1"}) {
    k.symbol_code[n] = n;
    k.locals.push_back({n, plane_local(c, n)});
  }
  k.symbol_code["pn"] = "pn";
  k.locals.push_back({"pn", c.plane_Pn});
  // Back to contact axes: P = Q^T (P_n, mu P_n, 0).
  const ex pn = sym("pn");
  k.outputs = {{"out(0)", pn}, {"out(1)", sym("cp") * sym("mu") * pn}, {"out(2)", sym("sp") * sym("mu") * pn}};
  return k;
}

Kernel plane_ratio(const ClosedForms& c, bool generalized) {
  Kernel k;
  k.name = generalized ? "plane_generalized_ratio" : "plane_critical_ratio";
  k.equations = generalized ? std::vector<std::string>{"eq14", "eq17", "eq20"} : std::vector<std::string>{"eq17", "eq19"};
  k.doc = generalized ? "Generalized impulse ratio of a solution plane, eq 20 (eq 19 at eps = 0)."
                      : "Critical impulse ratio of a solution plane, eq 19: sliding along the plane stops at separation.";
  k.returns = "Scalar";
  k.returns_doc = generalized ? "mu_GIR" : "mu_CIR";
  k.args = generalized ? std::vector<KernelArg>{kK, kV, kC, kS} : std::vector<KernelArg>{kK, kE, kV, kC, kS};
  k.symbol_code = coefficient_symbols();
  for (const char* n : {"pa1", "pa2", "pb1", "pb2", "Vcp"}) {
    k.symbol_code[n] = n;
    k.locals.push_back({n, plane_local(c, n)});
  }
  ex mu = c.plane_critical;
  if (generalized) mu = normal(mu.subs(sym("eps") == 0));
  k.outputs = {{"out", mu}};
  return k;
}

Kernel brach_impulse(const ClosedForms& c) {
  Kernel k;
  k.name = "brach_impulse";
  k.equations = {"eq24"};
  k.doc = "Impulse with independent ratios P_t = mu_t P_n, P_z = mu_z P_n: eq 24.";
  k.returns = "Eigen::Matrix<Scalar, 3, 1>";
  k.returns_doc = "P = (P_n, P_t, P_z) on vehicle 1, contact axes";
  k.args = {kK, kMp, kE, kV, {"const Scalar& mu_t", "impulse ratio along t"}, {"const Scalar& mu_z", "impulse ratio along z"}};
  k.symbol_code = coefficient_symbols();
  for (int i = 0; i < 3; ++i) k.outputs.push_back({"out(" + std::to_string(i) + ")", c.brach_P(i, 0)});
  return k;
}

Kernel brach_critical(const ClosedForms& c, char which) {
  Kernel k;
  k.symbol_code = coefficient_symbols();
  if (which == 't') {
    k.name = "brach_critical_t";
    k.equations = {"eq25"};
    k.doc = "Critical mu_t given mu_z, eq 25: sliding along t stops at separation.";
    k.returns = "Scalar";
    k.returns_doc = "mu_tC";
    k.args = {kK, kE, kV, {"const Scalar& mu_z", "impulse ratio along z"}};
    k.outputs = {{"out", c.brach_mu_t_critical}};
  } else if (which == 'z') {
    k.name = "brach_critical_z";
    k.equations = {"eq26"};
    k.doc = "Critical mu_z given mu_t, eq 26: sliding along z stops at separation.";
    k.returns = "Scalar";
    k.returns_doc = "mu_zC";
    k.args = {kK, kE, kV, {"const Scalar& mu_t", "impulse ratio along t"}};
    k.outputs = {{"out", c.brach_mu_z_critical}};
  } else {
    k.name = "brach_critical_both";
    k.equations = {"eq27"};
    k.doc = "Both ratios critical, eq 27: no sliding at separation (on the Critical Impulse Line).";
    k.returns = "Eigen::Matrix<Scalar, 2, 1>";
    k.returns_doc = "(mu_tC, mu_zC)";
    k.args = {kK, kE, kV};
    k.outputs = {{"out(0)", c.brach_both_t}, {"out(1)", c.brach_both_z}};
  }
  return k;
}

Kernel energy_change(const ClosedForms& c) {
  Kernel k;
  k.name = "energy_change";
  k.doc = "Change of the pair's kinetic energy for any impulse P: -P . V + P^T K P / (2 m') (loss is its negative).";
  k.returns = "Scalar";
  k.returns_doc = "T_after - T_before";
  k.args = {kK, kMp, kV, {"const Eigen::Matrix<Scalar, 3, 1>& P", "impulse on vehicle 1, contact axes"}};
  k.symbol_code = coefficient_symbols();
  k.outputs = {{"out", c.energy_change}};
  return k;
}

const KernelArg kMu{"const Scalar& mu", "Coulomb friction coefficient"};

// A Stronge kernel (all evaluate eq 9 with Coulomb's law): its outputs out(0), out(1), ... in order.
Kernel stronge_kernel(const char* name, const char* doc, int rows, const char* returns_doc, std::vector<KernelArg> args,
                      const std::vector<ex>& outputs, const std::map<std::string, std::string>& symbols = {}) {
  Kernel k;
  k.name = name;
  k.equations = {"eq9"};
  k.doc = doc;
  k.returns = "Eigen::Matrix<Scalar, " + std::to_string(rows) + ", 1>";
  k.returns_doc = returns_doc;
  k.args = std::move(args);
  k.symbol_code = coefficient_symbols();
  for (const auto& [symbol, code] : symbols) k.symbol_code[symbol] = code;
  for (std::size_t i = 0; i < outputs.size(); ++i) k.outputs.push_back({"out(" + std::to_string(i) + ")", outputs[i]});
  return k;
}

std::vector<Kernel> stronge_kernels(const StrongeForms& f) {
  const KernelArg c{"const Scalar& c", "cos theta of the sliding direction"}, s{"const Scalar& s", "sin theta"};
  const KernelArg c0{"const Scalar& c0", "cos theta_0 (c0^2 + s0^2 = 1)"}, s0{"const Scalar& s0", "sin theta_0"};
  const KernelArg V{"const Eigen::Matrix<Scalar, 3, 1>& V",
                    "relative velocity at the impulse centre now (n, t, z), sliding: (V_t, V_z) != 0"};
  return {
      stronge_kernel("stronge_sliding_rate",
                     "Stronge's sliding right-hand side: dV/dp = -K (1, mu u / |u|) / m' with u = (V_t, V_z), the "
                     "normal impulse p the independent variable (eq 9 with Coulomb's law).",
                     3, "dV/dp (n, t, z)", {kK, kMp, kMu, V},
                     {f.sliding_rate(0, 0), f.sliding_rate(1, 0), f.sliding_rate(2, 0)}),
      stronge_kernel("stronge_direction_rates",
                     "Sliding along the unit direction d = (c, s) of the contact plane: how fast the sliding speed "
                     "grows and its direction turns, from m' du/dp = -(rows t, z of K) (1, mu c, mu s).",
                     2, "(m' d|u|/dp, m' |u| dtheta/dp), theta from t towards z", {kK, kMu, c, s},
                     {f.growth, f.turning}, {{"dc", "c"}, {"ds", "s"}}),
      stronge_kernel("stronge_stick_ratio",
                     "The tangential impulse ratio that keeps a stopped contact stuck: dP/dp = (1, r_t, r_z) with "
                     "dV_t = dV_z = 0 (Coulomb's cone holds it when |r| <= mu).",
                     2, "(r_t, r_z)", {kK}, {f.stick_ratio(0, 0), f.stick_ratio(1, 0)}),
      stronge_kernel("stronge_invariant_quartic",
                     "The invariant directions of the sliding map (turning = 0) at theta = theta_0 + phi: (1 + t^2)^2 "
                     "times the turning rate, t = tan(phi / 2), a quartic in t.",
                     5, "the coefficients of t^0 .. t^4", {kK, kMu, c0, s0}, f.invariant_quartic,
                     {{"c0", "c0"}, {"s0", "s0"}}),
  };
}

}  // namespace

std::vector<GeneratedFile> kernel_files(const Derivation& d, const ClosedForms& c) {
  const StrongeForms f = derive_stronge_forms();
  return {
      {"coefficient_matrix.hpp", "K of eq 9 from the full Newton-Euler tensors", {general_coefficient_matrix(d)}},
      {"coefficient_matrix_appendix_a.hpp", "K of eq 9 under the Appendix A assumptions, c3 corrected",
       {appendix_a_coefficient_matrix()}},
      {"full_impact.hpp", "Full Impact, eqs 10-12", {full_impact(c)}},
      {"solution_plane.hpp", "Solution-plane closed forms, eqs 17-20",
       {plane_impulse(c), plane_ratio(c, false), plane_ratio(c, true)}},
      {"brach.hpp", "Independent impulse ratios, eqs 24-27",
       {brach_impulse(c), brach_critical(c, 't'), brach_critical(c, 'z'), brach_critical(c, 'b')}},
      {"energy.hpp", "Kinetic-energy change of an impulse", {energy_change(c)}},
      {"stronge.hpp", "Stronge's impact through the normal impulse: sliding, sticking, invariant directions",
       stronge_kernels(f)},
  };
}

}  // namespace impact3d::symbolic
