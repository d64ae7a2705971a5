// The closed forms of every strategy, derived by solving its constraint equations symbolically. The
// coefficients of eq 9 are the symbols a1..c3 (rows n, t, z), the initial relative velocity Vn, Vt, Vz.
#pragma once

#include "model.hpp"

namespace impact3d::symbolic {

struct ClosedForms {
  matrix K;              // [[a1, b1, c1], [a2, b2, c2], [a3, b3, c3]]
  matrix V;              // (Vn, Vt, Vz)
  matrix full_impact;    // eqs 10-12: K P = m' (1 + eps) V
  matrix full_impact_rhs;  // the same as K P = R, in the symbols Rn, Rt, Rz (Cramer's rule)
  // A solution plane at (cp, sp): u = (0, cp, sp) in it, w = (0, -sp, cp) normal to it.
  matrix plane_K;        // eq 17: the coefficients in the plane frame (n, u, w), Q K Q^T
  matrix plane_V;        // (Vn, V_cp, V_b)
  ex plane_Pn;           // eq 18, in the plane-frame symbols pa1, pb1 (K' entries) and mu
  ex plane_critical;     // eq 19, in pa1, pa2, pb1, pb2 and Vcp
  // The same three constraints solved in contact axes with the full K (a check on the plane route).
  matrix plane_P_contact;           // ratio mu along u
  ex plane_critical_contact;        // sliding along u stops
  matrix brach_P;                   // eq 24
  ex brach_mu_t_critical;           // eq 25 (mu_z given)
  ex brach_mu_z_critical;           // eq 26 (mu_t given)
  ex brach_both_t, brach_both_z;    // eq 27
  ex energy_change;                 // of any impulse P, from K: -P.V + P^T K P / (2 m')
};

ClosedForms derive_closed_forms();

// The plane-frame symbols pa1.. and Vcp, Vb as expressions in a1..c3, cp, sp, Vt, Vz.
GiNaC::exmap plane_symbols_in_contact_terms(const ClosedForms& c);

}  // namespace impact3d::symbolic
