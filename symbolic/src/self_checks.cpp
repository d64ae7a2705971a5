#include "self_checks.hpp"

#include <stdexcept>

namespace impact3d::symbolic {

using namespace GiNaC;

namespace {

ex dot(const matrix& a, const matrix& b) { return (a.transpose().mul(b))(0, 0); }

void require(bool ok, const std::string& what) {
  if (!ok) throw std::runtime_error("self-check failed: " + what);
}

}  // namespace

std::vector<std::string> self_checks(const Derivation& d, const ClosedForms& c) {
  std::vector<std::string> facts;

  // One body: the kinetic energy change of an impulse P at r, from the definitions (J^-1 the true
  // inverse of the symmetric tensor), equals P.(V_IC + dV_IC / 2).
  {
    const Body& b = d.body[0];
    const matrix v = column(sym("vx"), sym("vy"), sym("vz")), w = column(sym("wx"), sym("wy"), sym("wz"));
    const matrix P = column(sym("Qx"), sym("Qy"), sym("Qz"));
    const matrix Jinv = ex_to<matrix>(b.J.inverse());
    const matrix dv = P.mul_scalar(1 / b.m), dw = Jinv.mul(cross(b.r, P));
    auto energy = [&](const matrix& vv, const matrix& ww) { return (b.m * dot(vv, vv) + dot(ww, b.J.mul(ww))) / 2; };
    const ex dT = energy(v.add(dv), w.add(dw)) - energy(v, w);
    const matrix V_ic = v.add(cross(w, b.r)), dV_ic = dv.add(cross(dw, b.r));
    require(normal(dT - dot(P, V_ic.add(dV_ic.mul_scalar(ex(1) / 2)))).is_zero(), "single-body energy change");
    facts.push_back("For one body, the kinetic-energy change of an impulse P applied at r is P . (V_IC + dV_IC / 2), "
                    "with the full inertia tensor.");
  }
  // Both bodies, with P1 = T1^T P and P2 = -T2^T P: dT = -P . V_ri + P^T K P / (2 m').
  {
    const ex m1 = d.body[0].m, m2 = d.body[1].m;
    const ex PKP = dot(d.P, d.K.mul(d.P));
    const ex lhs = -dot(d.P, d.dV_rel) / 2;  // the dV_IC / 2 terms of both bodies, by eq 6 and eq 7
    require(normal(expand(lhs - PKP / (2 * sym("mp"))).subs(GiNaC::exmap{{sym("mp"), m1 * m2 / (m1 + m2)}})).is_zero(),
            "two-body energy change");
    facts.push_back("For the pair, dT = -P . (V_ri + V_rf) / 2 = -P . V_ri + P^T K P / (2 m'): a convex quadratic in P, "
                    "since K is symmetric positive definite.");
  }
  // Its stationary point is the Full Impact at eps = 0: the maximum-energy-loss impulse (Figure 2).
  {
    const matrix P0 = ex_to<matrix>(c.full_impact.subs(GiNaC::exmap{{sym("eps"), 0}}));
    const matrix grad = c.K.mul(P0).mul_scalar(1 / sym("mp")).sub(c.V);
    for (int i = 0; i < 3; ++i) require(normal(grad(i, 0)).is_zero(), "maximum energy loss at the Full Impact");
    facts.push_back("The gradient of dT vanishes at the Full Impact with eps = 0: it is the maximum-energy-loss "
                    "impulse, where the three fundamental planes meet.");
  }
  // The Critical Impulse Line: K d ~ e_n, so moving along it changes only the normal relative velocity.
  {
    const matrix d_cil = cross(column(c.K(1, 0), c.K(1, 1), c.K(1, 2)), column(c.K(2, 0), c.K(2, 1), c.K(2, 2)));
    const matrix Kd = c.K.mul(d_cil);
    require(normal(Kd(1, 0)).is_zero() && normal(Kd(2, 0)).is_zero(), "Critical Impulse Line direction");
    facts.push_back("The t and z no-sliding planes meet in the Critical Impulse Line, direction K_t x K_z (rows of K); "
                    "K times it has no t or z component.");
  }
  return facts;
}

}  // namespace impact3d::symbolic
