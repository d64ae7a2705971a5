#include "closed_forms.hpp"

#include <stdexcept>

namespace impact3d::symbolic {

using namespace GiNaC;

namespace {

ex S(const char* n) { return sym(n); }

// Solves three linear equations for (Pn, Pt, Pz) or other unknowns; the solution must be unique.
matrix solve3(const lst& equations, const lst& unknowns) {
  const ex sol = lsolve(equations, unknowns);
  if (sol.nops() != 3) throw std::runtime_error("closed forms: constraints without a unique solution");
  matrix out(3, 1);
  for (int i = 0; i < 3; ++i) out(i, 0) = normal(sol.op(i).rhs());
  return out;
}

ex row(const matrix& M, int r, const matrix& x) {
  return M(r, 0) * x(0, 0) + M(r, 1) * x(1, 0) + M(r, 2) * x(2, 0);
}

}  // namespace

ClosedForms derive_closed_forms() {
  ClosedForms c;
  c.K = matrix(3, 3, lst{S("a1"), S("b1"), S("c1"), S("a2"), S("b2"), S("c2"), S("a3"), S("b3"), S("c3")});
  c.V = column(S("Vn"), S("Vt"), S("Vz"));
  const ex mp = S("mp"), e = S("eps"), mu = S("mu"), cp = S("cp"), sp = S("sp");
  const ex Pn = S("Pn"), Pt = S("Pt"), Pz = S("Pz");
  const matrix P = column(Pn, Pt, Pz);
  const lst unknowns{Pn, Pt, Pz};

  // Full Impact: every component of the post-impact relative velocity is -eps times the initial.
  // Solved for a symbolic right-hand side R first, so the result keeps Cramer's form (eqs 10-12).
  c.full_impact_rhs = solve3(lst{row(c.K, 0, P) == S("Rn"), row(c.K, 1, P) == S("Rt"), row(c.K, 2, P) == S("Rz")}, unknowns);
  for (int i = 0; i < 3; ++i) c.full_impact_rhs(i, 0) = collect(numer(c.full_impact_rhs(i, 0)), lst{S("Rn"), S("Rt"), S("Rz")}) /
                                                       denom(c.full_impact_rhs(i, 0));
  const exmap rhs{{S("Rn"), mp * (1 + e) * S("Vn")}, {S("Rt"), mp * (1 + e) * S("Vt")}, {S("Rz"), mp * (1 + e) * S("Vz")}};
  c.full_impact = ex_to<matrix>(c.full_impact_rhs.subs(rhs));

  // eq 17: with Q's rows n, u, w, the plane-frame coefficients are Q K Q^T and velocities Q V.
  const matrix Q(3, 3, lst{1, 0, 0, 0, cp, sp, 0, -sp, cp});
  c.plane_K = Q.mul(c.K).mul(Q.transpose());
  c.plane_V = Q.mul(c.V);

  // In the plane frame, with the plane-frame coefficients as symbols: restitution, the ratio or the
  // no-sliding condition along u, and no impulse along w.
  const matrix Kp(3, 3, lst{S("pa1"), S("pb1"), S("pc1"), S("pa2"), S("pb2"), S("pc2"), S("pa3"), S("pb3"), S("pc3")});
  const ex Pcp = S("Pcp"), Pb = S("Pb");
  const matrix Pp = column(Pn, Pcp, Pb);
  const lst plane_unknowns{Pn, Pcp, Pb};
  const matrix ratio = solve3(lst{row(Kp, 0, Pp) == mp * (1 + e) * S("Vn"), Pcp == mu * Pn, Pb == 0}, plane_unknowns);
  c.plane_Pn = ratio(0, 0);
  const matrix crit = solve3(lst{row(Kp, 0, Pp) == mp * (1 + e) * S("Vn"), row(Kp, 1, Pp) == mp * S("Vcp"), Pb == 0},
                             plane_unknowns);
  c.plane_critical = normal(crit(1, 0) / crit(0, 0));

  // The same constraints in contact axes with the full K.
  const matrix u = column(0, cp, sp), w = column(0, -sp, cp);
  const ex uP = cp * Pt + sp * Pz, wP = -sp * Pt + cp * Pz;
  c.plane_P_contact = solve3(lst{row(c.K, 0, P) == mp * (1 + e) * S("Vn"), uP == mu * Pn, wP == 0}, unknowns);
  const ex uKP = cp * row(c.K, 1, P) + sp * row(c.K, 2, P);
  const matrix pc = solve3(lst{row(c.K, 0, P) == mp * (1 + e) * S("Vn"), uKP == mp * (cp * S("Vt") + sp * S("Vz")), wP == 0},
                           unknowns);
  c.plane_critical_contact = normal((cp * pc(1, 0) + sp * pc(2, 0)) / pc(0, 0));

  // Brach: ratios along t and z, or the no-sliding conditions in their place.
  const ex rest = row(c.K, 0, P) - mp * (1 + e) * S("Vn");
  const ex t_stop = row(c.K, 1, P) - mp * S("Vt"), z_stop = row(c.K, 2, P) - mp * S("Vz");
  c.brach_P = solve3(lst{rest == 0, Pt == S("mut") * Pn, Pz == S("muz") * Pn}, unknowns);
  const matrix bt = solve3(lst{rest == 0, t_stop == 0, Pz == S("muz") * Pn}, unknowns);
  c.brach_mu_t_critical = normal(bt(1, 0) / bt(0, 0));
  const matrix bz = solve3(lst{rest == 0, Pt == S("mut") * Pn, z_stop == 0}, unknowns);
  c.brach_mu_z_critical = normal(bz(2, 0) / bz(0, 0));
  const matrix bb = solve3(lst{rest == 0, t_stop == 0, z_stop == 0}, unknowns);
  c.brach_both_t = normal(bb(1, 0) / bb(0, 0));
  c.brach_both_z = normal(bb(2, 0) / bb(0, 0));

  // Energy: dT = -P . (V_ri + V_rf) / 2 with V_rf = V_ri - K P / m' (verified from the bodies' kinetic
  // energies by the audit).
  c.energy_change = -(P.transpose().mul(c.V))(0, 0) + (P.transpose().mul(c.K).mul(P))(0, 0) / (2 * mp);
  return c;
}

exmap plane_symbols_in_contact_terms(const ClosedForms& c) {
  exmap m;
  const char* names[3][3] = {{"pa1", "pb1", "pc1"}, {"pa2", "pb2", "pc2"}, {"pa3", "pb3", "pc3"}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m[sym(names[i][j])] = c.plane_K(i, j);
  m[sym("Vcp")] = c.plane_V(1, 0);
  m[sym("Vb")] = c.plane_V(2, 0);
  return m;
}

}  // namespace impact3d::symbolic
