#include "model.hpp"

#include <map>
#include <stdexcept>

namespace impact3d::symbolic {

using namespace GiNaC;

const symbol& sym(const std::string& name) {
  static std::map<std::string, symbol> table;
  auto it = table.find(name);
  if (it == table.end()) it = table.emplace(name, symbol(name)).first;
  return it->second;
}

matrix column(const ex& a, const ex& b, const ex& c) { return matrix(3, 1, lst{a, b, c}); }

matrix cross(const matrix& a, const matrix& b) {
  return column(a(1, 0) * b(2, 0) - a(2, 0) * b(1, 0), a(2, 0) * b(0, 0) - a(0, 0) * b(2, 0),
                a(0, 0) * b(1, 0) - a(1, 0) * b(0, 0));
}

matrix skew(const matrix& r) {
  return matrix(3, 3, lst{0, -r(2, 0), r(1, 0), r(2, 0), 0, -r(0, 0), -r(1, 0), r(0, 0), 0});
}

Body make_body(int i) {
  const std::string n = std::to_string(i);
  const char* ax = "xyz";
  Body b;
  b.index = i;
  b.m = sym("m" + n);
  b.J = matrix(3, 3);
  b.Jinv = matrix(3, 3);
  b.T = matrix(3, 3);
  for (int p = 0; p < 3; ++p)
    for (int q = 0; q < 3; ++q) {
      const int lo = std::min(p, q), hi = std::max(p, q);
      b.J(p, q) = sym(std::string("J") + n + "_" + ax[lo] + ax[hi]);
      b.Jinv(p, q) = sym(std::string("ji") + n + "_" + ax[lo] + ax[hi]);
      b.T(p, q) = sym("T" + n + "_" + std::to_string(p + 1) + std::to_string(q + 1));
    }
  b.r = column(sym("x" + n), sym("y" + n), sym("z" + n));
  return b;
}

Derivation derive() {
  Derivation d;
  d.body = {make_body(1), make_body(2)};
  d.P = column(sym("Pn"), sym("Pt"), sym("Pz"));
  d.P1 = column(sym("P1x"), sym("P1y"), sym("P1z"));
  d.P2 = column(sym("P2x"), sym("P2y"), sym("P2z"));
  d.m_prime = sym("mp");
  const matrix* Pb[2] = {&d.P1, &d.P2};

  // eq 2: dV = P_i / m_i, J dw = r x P_i;  eq 4: dV_IC = dV + dw x r.
  for (int i = 0; i < 2; ++i) {
    const Body& b = d.body[i];
    const matrix dw = b.Jinv.mul(cross(b.r, *Pb[i]));
    d.dV_ic[i] = Pb[i]->mul_scalar(1 / b.m).add(cross(dw, b.r));
  }
  // eq 6: the relative velocity change at the impulse centre, contact axes.
  d.dV_rel_body = d.body[1].T.mul(d.dV_ic[1]).sub(d.body[0].T.mul(d.dV_ic[0]));

  // eq 7: T1 P1 = -T2 P2 = P. The translational terms T_i P_i / m_i are +-P / m_i by that definition;
  // in the rotational terms P_i = +-T_i^T P.
  const matrix Pbody[2] = {d.body[0].T.transpose().mul(d.P), d.body[1].T.transpose().mul(d.P).mul_scalar(-1)};
  matrix rot(3, 1);
  for (int i = 0; i < 2; ++i) {
    const Body& b = d.body[i];
    const matrix dw = b.Jinv.mul(cross(b.r, Pbody[i]));
    const matrix term = b.T.mul(cross(dw, b.r));
    rot = i == 0 ? term.mul_scalar(-1) : rot.add(term);
  }
  const ex m1 = d.body[0].m, m2 = d.body[1].m;
  const matrix trans = d.P.mul_scalar(-(1 / m1 + 1 / m2));
  d.dV_rel = trans.add(rot);

  // eq 9: m' (V_rf - V_ri) = -K P, i.e. K = -m' d(dV_rel)/dP. m' = m1 m2 / (m1 + m2) makes the
  // translational part exactly the identity; the rest stays with the symbol mp.
  const ex mp_value = m1 * m2 / (m1 + m2);
  d.K = matrix(3, 3);
  const symbol* Pk[3] = {&sym("Pn"), &sym("Pt"), &sym("Pz")};
  for (int j = 0; j < 3; ++j)
    for (int k = 0; k < 3; ++k) {
      const ex t = normal(-mp_value * trans(j, 0).diff(*Pk[k]));
      if (!(t - (j == k ? 1 : 0)).is_zero()) throw std::runtime_error("derive: m' does not reduce the mass terms to I");
      d.K(j, k) = t - d.m_prime * rot(j, 0).diff(*Pk[k]);
    }

  matrix Kf = ex_to<matrix>(unit_matrix(3));
  for (const Body& b : d.body) {
    const matrix S = skew(b.r);
    Kf = Kf.add(b.T.mul(S.transpose()).mul(b.Jinv).mul(S).mul(b.T.transpose()).mul_scalar(d.m_prime));
  }
  d.K_factored = Kf;
  return d;
}

exmap weierstrass(const std::vector<std::pair<std::string, std::string>>& cos_sin_names) {
  exmap m;
  for (const auto& [c, s] : cos_sin_names) {
    const symbol& u = sym("u_" + c);
    m[sym(c)] = (1 - u * u) / (1 + u * u);
    m[sym(s)] = 2 * u / (1 + u * u);
  }
  return m;
}

bool identical(const ex& a, const ex& b, const exmap& substitutions) {
  return normal((a - b).subs(substitutions)).is_zero();
}

}  // namespace impact3d::symbolic
