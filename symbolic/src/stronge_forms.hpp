// Stronge's impact through the normal impulse p (issue 59), derived from eq 9 (m' dV = -K dP, contact
// axes) with K's symbols a1..c3 as in closed_forms.hpp: the sliding right-hand side, the tangential
// impulse ratio that keeps the contact stuck, and the equation of the invariant directions.
#pragma once

#include "model.hpp"

namespace impact3d::symbolic {

struct StrongeForms {
  // dV/dp while the contact slides, dP/dp = (1, mu u / |u|), u = (Vt, Vz): in mp, mu, Vn, Vt, Vz.
  matrix sliding_rate;
  // Sliding along the unit direction d = (dc, ds): m' d|u|/dp (growth) and m' |u| dtheta/dp (turning).
  ex growth, turning;
  // (r_t, r_z) with dP/dp = (1, r_t, r_z) keeping dV_t = dV_z = 0.
  matrix stick_ratio;
  // (1 + t^2)^2 times `turning` at d = R(theta_0) (cos phi, sin phi), t = tan(phi / 2), as the
  // coefficients of t^0..t^4, in mu and the unit vector (c0, s0) of theta_0.
  std::vector<ex> invariant_quartic;
};

StrongeForms derive_stronge_forms();

}  // namespace impact3d::symbolic
