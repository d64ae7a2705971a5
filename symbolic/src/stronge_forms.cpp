#include "stronge_forms.hpp"

#include <stdexcept>

namespace impact3d::symbolic {

using namespace GiNaC;

StrongeForms derive_stronge_forms() {
  StrongeForms f;
  const matrix K(3, 3, lst{sym("a1"), sym("b1"), sym("c1"), sym("a2"), sym("b2"), sym("c2"), sym("a3"), sym("b3"), sym("c3")});
  const ex mp = sym("mp"), mu = sym("mu"), Vt = sym("Vt"), Vz = sym("Vz");

  // Coulomb's law while sliding: the tangential impulse opposes u, its rate mu times the normal's.
  const ex speed = sqrt(pow(Vt, 2) + pow(Vz, 2));
  const matrix dP = column(1, mu * Vt / speed, mu * Vz / speed);
  f.sliding_rate = ex_to<matrix>((K.mul(dP)).mul_scalar(-1 / mp));

  // Along a unit direction d, u = |u| d: the rate of u projected on d and across it (|u| cancels).
  const ex dc = sym("dc"), ds = sym("ds");
  const matrix du = K.mul(column(1, mu * dc, mu * ds)).mul_scalar(-1);  // m' du/dp, rows t and z
  f.growth = expand(dc * du(1, 0) + ds * du(2, 0));
  f.turning = expand(dc * du(2, 0) - ds * du(1, 0));

  // Sticking: the rate (1, r_t, r_z) that leaves V_t and V_z unchanged.
  const ex rt = sym("rt"), rz = sym("rz");
  const matrix stuck = K.mul(column(1, rt, rz));
  const ex sol = lsolve(lst{stuck(1, 0) == 0, stuck(2, 0) == 0}, lst{rt, rz});
  if (sol.nops() != 2) throw std::runtime_error("stronge forms: the stick ratio is not unique");
  f.stick_ratio = matrix(2, 1, lst{normal(sol.op(0).rhs()), normal(sol.op(1).rhs())});

  // The invariant directions: turning = 0 at theta_0 + phi, by the half-angle substitution.
  const ex c0 = sym("c0"), s0 = sym("s0"), t = sym("t");
  const ex cp = (1 - pow(t, 2)) / (1 + pow(t, 2)), sp = 2 * t / (1 + pow(t, 2));
  const ex at_phi = f.turning.subs(lst{dc == c0 * cp - s0 * sp, ds == s0 * cp + c0 * sp}, subs_options::no_pattern);
  const ex quartic = expand(normal(at_phi * pow(1 + pow(t, 2), 2)));
  if (quartic.degree(t) > 4 || quartic.ldegree(t) < 0) throw std::runtime_error("stronge forms: the turning is not a quartic in t");
  for (int i = 0; i <= 4; ++i) f.invariant_quartic.push_back(collect(quartic.coeff(t, i), lst{mu}));
  return f;
}

}  // namespace impact3d::symbolic
