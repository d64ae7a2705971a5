// Every generated kernel, instantiated with exact rationals, against GiNaC's evaluation of the derived
// expression at the same random rational inputs: equal exactly, so the printer, the common-subexpression
// hoisting and the constants are all checked with no tolerance.
#include <catch2/catch.hpp>

#include <random>

#include <boost/multiprecision/cpp_int.hpp>
#include <boost/multiprecision/eigen.hpp>

#include "closed_forms.hpp"
#include "impact3d/generated/brach.hpp"
#include "impact3d/generated/coefficient_matrix.hpp"
#include "impact3d/generated/energy.hpp"
#include "impact3d/generated/full_impact.hpp"
#include "impact3d/generated/solution_plane.hpp"
#include "impact3d/generated/stronge.hpp"
#include "model.hpp"
#include "stronge_forms.hpp"

using namespace impact3d::symbolic;
using namespace GiNaC;
using Q = boost::multiprecision::cpp_rational;
using M3 = Eigen::Matrix<Q, 3, 3>;
using V3 = Eigen::Matrix<Q, 3, 1>;

namespace {

struct Draw {
  std::mt19937_64 g{77};
  // A rational p/q with |p| <= 40, 1 <= q <= 9, never zero.
  numeric operator()() {
    std::uniform_int_distribution<int> p(-40, 40), q(1, 9);
    int a = 0;
    while (a == 0) a = p(g);
    return numeric(a, q(g));
  }
};

Q to_q(const numeric& n) {
  std::ostringstream a, b;
  a << n.numer();
  b << n.denom();
  return Q(boost::multiprecision::cpp_int(a.str())) / Q(boost::multiprecision::cpp_int(b.str()));
}

Q value(const ex& e, const exmap& v) {
  const ex r = normal(e.subs(v));
  REQUIRE(is_a<numeric>(r));
  return to_q(ex_to<numeric>(r));
}

// K, V, e and the other closed-form inputs as random rationals (the identities are algebraic; no
// physical constraint is needed for exact agreement).
struct Inputs {
  exmap v;
  M3 K;
  V3 V;
  Q mp, e, mu, mut, muz, c, s;
};

Inputs draw(Draw& d) {
  Inputs in;
  const char* names[3][3] = {{"a1", "b1", "c1"}, {"a2", "b2", "c2"}, {"a3", "b3", "c3"}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const numeric x = d();
      in.v[sym(names[i][j])] = x;
      in.K(i, j) = to_q(x);
    }
  const char* vn[3] = {"Vn", "Vt", "Vz"};
  for (int i = 0; i < 3; ++i) {
    const numeric x = d();
    in.v[sym(vn[i])] = x;
    in.V(i) = to_q(x);
  }
  auto one = [&](const char* name, Q& q) {
    const numeric x = d();
    in.v[sym(name)] = x;
    q = to_q(x);
  };
  one("mp", in.mp);
  one("eps", in.e);
  one("mu", in.mu);
  one("mut", in.mut);
  one("muz", in.muz);
  one("cp", in.c);
  one("sp", in.s);
  return in;
}

}  // namespace

TEST_CASE("closed-form kernels equal the derived expressions exactly", "[check]") {
  const ClosedForms c = derive_closed_forms();
  const exmap plane = plane_symbols_in_contact_terms(c);
  Draw d;
  for (int n = 0; n < 40; ++n) {
    const Inputs in = draw(d);
    const V3 fi = impact3d::generated::full_impact(in.K, in.mp, in.e, in.V);
    for (int i = 0; i < 3; ++i) CHECK(fi(i) == value(c.full_impact(i, 0), in.v));
    const V3 pl = impact3d::generated::plane_impulse(in.K, in.mp, in.e, in.V, in.c, in.s, in.mu);
    CHECK(pl(0) == value(c.plane_Pn.subs(plane), in.v));
    CHECK(pl(1) == value(sym("cp") * sym("mu") * c.plane_Pn.subs(plane), in.v));
    CHECK(impact3d::generated::plane_critical_ratio(in.K, in.e, in.V, in.c, in.s) == value(c.plane_critical.subs(plane), in.v));
    CHECK(impact3d::generated::plane_generalized_ratio(in.K, in.V, in.c, in.s) ==
          value(c.plane_critical.subs(plane).subs(exmap{{sym("eps"), 0}}), in.v));
    const V3 bp = impact3d::generated::brach_impulse(in.K, in.mp, in.e, in.V, in.mut, in.muz);
    for (int i = 0; i < 3; ++i) CHECK(bp(i) == value(c.brach_P(i, 0), in.v));
    CHECK(impact3d::generated::brach_critical_t(in.K, in.e, in.V, in.muz) == value(c.brach_mu_t_critical, in.v));
    CHECK(impact3d::generated::brach_critical_z(in.K, in.e, in.V, in.mut) == value(c.brach_mu_z_critical, in.v));
    const auto both = impact3d::generated::brach_critical_both(in.K, in.e, in.V);
    CHECK(both(0) == value(c.brach_both_t, in.v));
    CHECK(both(1) == value(c.brach_both_z, in.v));
    exmap with_p = in.v;
    V3 P;
    const char* pn[3] = {"Pn", "Pt", "Pz"};
    for (int i = 0; i < 3; ++i) {
      const numeric x = d();
      with_p[sym(pn[i])] = x;
      P(i) = to_q(x);
    }
    CHECK(impact3d::generated::energy_change(in.K, in.mp, in.V, P) == value(c.energy_change, with_p));
  }
}

// Stronge's forms at rational directions (the sliding rate's square root is checked at 50 digits, in
// tests/mechanics/check_stronge_forms.cpp: a rational kernel has no sqrt).
TEST_CASE("stronge kernels equal the derived expressions exactly", "[check]") {
  const StrongeForms f = derive_stronge_forms();
  Draw d;
  int checked = 0;
  for (int n = 0; n < 40; ++n) {
    Inputs in = draw(d);
    // (c, s) and (c0, s0) unit and rational: from Pythagorean triples.
    const int triples[][3] = {{3, 4, 5}, {-5, 12, 13}, {8, -15, 17}, {-7, -24, 25}};
    const auto& a = triples[n % 4];
    const auto& b = triples[(n / 4) % 4];
    exmap v = in.v;
    v[sym("dc")] = numeric(a[0], a[2]), v[sym("ds")] = numeric(a[1], a[2]);
    v[sym("c0")] = numeric(b[0], b[2]), v[sym("s0")] = numeric(b[1], b[2]);
    const Q c(Q(a[0]) / a[2]), s(Q(a[1]) / a[2]), c0(Q(b[0]) / b[2]), s0(Q(b[1]) / b[2]);
    const auto rates = impact3d::generated::stronge_direction_rates(in.K, in.mu, c, s);
    CHECK(rates(0) == value(f.growth, v));
    CHECK(rates(1) == value(f.turning, v));
    const auto r = impact3d::generated::stronge_stick_ratio(in.K);
    CHECK(r(0) == value(f.stick_ratio(0, 0), v));
    CHECK(r(1) == value(f.stick_ratio(1, 0), v));
    const auto q = impact3d::generated::stronge_invariant_quartic(in.K, in.mu, c0, s0);
    for (int i = 0; i < 5; ++i) CHECK(q(i) == value(f.invariant_quartic[static_cast<std::size_t>(i)], v));
    ++checked;
  }
  CHECK(checked == 40);
}

TEST_CASE("the general K kernel equals the derivation exactly", "[check]") {
  const Derivation der = derive();
  Draw d;
  for (int n = 0; n < 20; ++n) {
    exmap v;
    M3 J[2], T[2];
    V3 r[2];
    const numeric mp = d();
    v[sym("mp")] = mp;
    for (int b = 0; b < 2; ++b) {
      const Body& body = der.body[b];
      // A symmetric tensor with a dominant diagonal (so it is invertible), and rational T and r.
      for (int p = 0; p < 3; ++p)
        for (int q = p; q < 3; ++q) {
          const numeric x = p == q ? numeric(200) + abs(d()) : d();
          v[body.J(p, q)] = x;
          J[b](p, q) = J[b](q, p) = to_q(x);
        }
      for (int p = 0; p < 3; ++p) {
        const numeric x = d();
        v[body.r(p, 0)] = x;
        r[b](p) = to_q(x);
        for (int q = 0; q < 3; ++q) {
          const numeric t = d();
          v[body.T(p, q)] = t;
          T[b](p, q) = to_q(t);
        }
      }
      const matrix Jinv = ex_to<matrix>(body.J.inverse());
      for (int p = 0; p < 3; ++p)
        for (int q = 0; q < 3; ++q) v[body.Jinv(p, q)] = normal(Jinv(p, q).subs(v));
    }
    const M3 K = impact3d::generated::coefficient_matrix(to_q(mp), J[0], J[1], r[0], r[1], T[0], T[1]);
    for (int p = 0; p < 3; ++p)
      for (int q = 0; q < 3; ++q) CHECK(K(p, q) == value(der.K(p, q), v));
  }
}
