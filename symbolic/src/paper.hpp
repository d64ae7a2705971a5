// The paper's printed formulas, typed in as printed (symbols named as in the derivation). Nothing here
// is used to compute: these are only compared with what the derivation gives.
#pragma once

#include <map>
#include <string>

#include "model.hpp"

namespace impact3d::symbolic::paper {

// eq 4's middle expression dV + dw x r of `body`'s line, with the lever arm of `lever_body`: as printed,
// both lines use r_1.
matrix eq4_middle(const Derivation& d, int body, int lever_body);
// eq 4, right-hand expression: P/m + [J^-1 (r x P)] x r.
matrix eq4_right(const Derivation& d, int body);
// eq 5, right-hand side as printed: T_i (P_i / m_i) + T_i ([J_i^-1 (r_i x P_i)] x r_i).
matrix eq5(const Derivation& d, int body);
matrix eq6(const Derivation& d);
matrix eq8(const Derivation& d);

// eq 9 as printed, m'(V_rf - V_ri) = -(a_i P_n + b_i P_t + c_i P_z), in the symbols a1..c3, Pn, Pt, Pz.
matrix eq9();
// eq 17 as printed, m'(V_f - V_i) along n, CP, b: -(a_i P_n + b_i P_CP) (middle) and -(a_i + mu b_i) P_n
// (right), in the symbols a1..b3 (which the audit reads two ways), Pn, Pcp, mu.
matrix eq17_middle();
matrix eq17_right();
// eq 23 as printed: -(a_i + b_i mu_t + c_i mu_z) P_n.
matrix eq23();

// eqs 10-12 in the symbols a1..c3, Vn, Vt, Vz, mp, eps.
matrix eqs10_12();

// Plane coefficients of eq 17 for a plane at (cp, sp) = (cos phi, sin phi), from the coefficients of
// eq 9 (the paper leaves them implicit: "a, b and c determined for phi").
struct PlaneCoefficients {
  ex a1, a2, b1, b2, r;  // and r = V_rCPi / V_rni of eq 19
};
PlaneCoefficients plane_coefficients();

ex eq18();  // P_n
ex eq19();  // CIR
ex eq20();  // GIR
ex eq24();  // P_n
// eq 25 leaves r undefined for the t axis: the audit passes each reading of it.
ex eq25(const ex& r);  // mu_tC given mu_z
ex eq26();             // mu_zC given mu_t (r_z = V_rzi / V_rni, defined there)
ex eq27_t(const ex& r);
ex eq27_z(const ex& r);
// eq 29 in the symbols cnz, snz (n_z), cni, sni (n_i), cpo, spo (psi_o): tan n_z / sin(n_i - psi_o).
ex eq29();

// Appendix A. T(gamma, theta, phi) as printed, in symbols cg, sg, ct, st, cp, sp.
matrix appendix_T(const ex& cg, const ex& sg, const ex& ct, const ex& st, const ex& cp, const ex& sp);
// A, B, C, f1..f8 as printed, in the symbols mp, Ix1, ..., x1, ..., cg1, sg1, cp, sp.
std::map<std::string, ex> appendix_definitions();
// a1..c3 as printed, in the symbols A, B, C, f1..f8 (and mp, cp, sp).
std::map<std::string, ex> appendix_coefficients();
// Symbol A -> its printed definition, ... : turns a coefficient into the basic symbols.
GiNaC::exmap appendix_definitions_map();
// The coefficients with the corrections the audit verifies (c3), in the symbols A, B, C, f1..f8.
std::map<std::string, ex> appendix_coefficients_corrected();

}  // namespace impact3d::symbolic::paper
