// The sensitivities' automatic differentiation (scalar/autodiff.hpp, Eigen's AutoDiffScalar through
// make_problem and the engines) against GiNaC's symbolic derivatives of the derived closed forms: K of
// eq 9 (masses through m' = m1 m2 / (m1 + m2), J^-1 as the symbolic inverse of the full tensor) and
// the Full Impact of eqs 10-12, by a mass, an impulse-centre coordinate, a diagonal and an
// off-diagonal (symmetric pair) entry of the inertia tensor, and the restitution. Inputs are random
// rationals with power-of-two denominators (exact in double), rotations rational by Cayley's
// transform; the symbolic derivative is evaluated exactly and rounded once. The AD derivative is a
// double computation of a few hundred operations on a well-conditioned K (condition below 10^3): it is
// held to 2^8 eps of the largest derivative of the same quantity.
#include <catch2/catch.hpp>

#include <random>

#include "closed_forms.hpp"
#include "impact3d/scalar/autodiff.hpp"
#include "impact3d/mechanics/analysis.hpp"
#include "model.hpp"

using namespace impact3d::symbolic;
using namespace GiNaC;
using impact3d::Dual;

namespace {

constexpr int kInputs = 5;  // m1, x1, J1_xx, J1_xy, eps
constexpr double kEps = 0x1p-52;

struct Draw {
  std::mt19937_64 g{2026};
  // p / 2^k with |p| <= 64, k <= 3, never zero: exact in double.
  numeric operator()() {
    std::uniform_int_distribution<int> p(-64, 64), k(0, 3);
    int a = 0;
    while (a == 0) a = p(g);
    return numeric(a, 1 << k(g));
  }
};

double to_double(const ex& e) { return ex_to<numeric>(evalf(e)).to_double(); }

Dual seeded(double value, int index) {
  static_assert(kInputs <= impact3d::kDualWidth);
  Dual x(value, Dual::DerType::Zero());
  if (index >= 0) x.derivatives()[index] = 1;
  return x;
}

// A rational rotation: (I - S)^-1 (I + S) for a skew S with entries a, b, c.
matrix cayley(const numeric& a, const numeric& b, const numeric& c) {
  const matrix S(3, 3, lst{0, -c, b, c, 0, -a, -b, a, 0});
  const matrix I = ex_to<matrix>(unit_matrix(3));
  return ex_to<matrix>(I.sub(S).inverse().mul(I.add(S)).evalm());
}

template <typename Engine>
void compare(const char* engine) {
  const Derivation der = derive();
  const ClosedForms cf = derive_closed_forms();
  const symbol &m1 = sym("m1"), &m2 = sym("m2"), &eps = sym("eps");
  const ex inputs[kInputs] = {m1, der.body[0].r(0, 0), der.body[0].J(0, 0), der.body[0].J(0, 1), eps};
  // K and the Full Impact in the case's inputs: m' by the masses, J^-1 by the tensor's entries.
  exmap in_inputs{{sym("mp"), m1 * m2 / (m1 + m2)}};
  for (const Body& b : der.body) {
    const matrix Jinv = ex_to<matrix>(b.J.inverse());
    for (int p = 0; p < 3; ++p)
      for (int q = 0; q < 3; ++q) in_inputs[b.Jinv(p, q)] = Jinv(p, q);
  }
  matrix K(3, 3);
  for (int p = 0; p < 3; ++p)
    for (int q = 0; q < 3; ++q) K(p, q) = der.K(p, q).subs(in_inputs);
  const char* names[3][3] = {{"a1", "b1", "c1"}, {"a2", "b2", "c2"}, {"a3", "b3", "c3"}};
  exmap k_entries{{sym("mp"), m1 * m2 / (m1 + m2)}};
  for (int p = 0; p < 3; ++p)
    for (int q = 0; q < 3; ++q) k_entries[sym(names[p][q])] = K(p, q);

  Draw d;
  int compared = 0;
  for (int n = 0; n < 6; ++n) {
    exmap v;
    impact3d::Scene<Dual> s;
    s.R_WC = impact3d::Mat3<Dual>::Identity();
    for (int b = 0; b < 2; ++b) {
      const Body& body = der.body[b];
      auto& rb = s.body[b];
      const numeric mass = numeric(1000) + abs(d()) * 8;
      v[body.m] = mass;
      rb.mass = seeded(mass.to_double(), b == 0 ? 0 : -1);
      for (int p = 0; p < 3; ++p)
        for (int q = p; q < 3; ++q) {
          const numeric x = p == q ? numeric(800) + abs(d()) * 16 : d();
          v[body.J(p, q)] = x;
          const int index = b == 0 && p == 0 && q == 0 ? 2 : b == 0 && p == 0 && q == 1 ? 3 : -1;
          rb.J_B(p, q) = rb.J_B(q, p) = seeded(x.to_double(), index);
        }
      // T_i = R_CB = R_WB (R_WC = I), rational, entered as the body's rotation.
      const matrix T = cayley(d() / 64, d() / 64, d() / 64);
      for (int p = 0; p < 3; ++p) {
        const numeric x = d() / 32;
        v[body.r(p, 0)] = x;
        rb.p_CgIc_B(p) = seeded(x.to_double(), b == 0 && p == 0 ? 1 : -1);
        for (int q = 0; q < 3; ++q) {
          v[body.T(p, q)] = T(p, q);
          rb.R_WB(p, q) = seeded(to_double(T(p, q)), -1);
        }
        rb.w_B(p) = seeded(0, -1);
      }
      rb.v_W = impact3d::Vec3<Dual>(seeded(b == 0 ? 20 : 0, -1), seeded(b == 0 ? 0 : 5, -1), seeded(0, -1));
    }
    const numeric e(1, 8);
    v[eps] = e;
    s.restitution = seeded(e.to_double(), 4);
    const impact3d::Problem<Dual> prob = impact3d::make_problem<Engine>(s);
    const auto P = Engine::try_full_impact(prob, prob.restitution);
    REQUIRE(P);
    // V of the closed form is the problem's (the inputs differentiated do not move it: no rotation).
    exmap at = v;
    const char* vn[3] = {"Vn", "Vt", "Vz"};
    for (int i = 0; i < 3; ++i) at[sym(vn[i])] = prob.V_ri(i).value();
    matrix P_sym(3, 1);
    for (int i = 0; i < 3; ++i) P_sym(i, 0) = cf.full_impact(i, 0).subs(k_entries);
    auto check = [&](const ex& expr, const Dual& ad, const std::string& what) {
      double derivative[kInputs], largest = 0;
      for (int j = 0; j < kInputs; ++j) {
        derivative[j] = to_double(normal(expr.diff(ex_to<symbol>(inputs[j])).subs(at)));
        largest = std::max(largest, std::fabs(derivative[j]));
      }
      for (int j = 0; j < kInputs; ++j) {
        INFO(engine << " " << what << " by input " << j << ": GiNaC " << derivative[j] << ", AD " << ad.derivatives()[j]);
        CHECK(std::fabs(ad.derivatives()[j] - derivative[j]) <= 256 * kEps * largest);
        ++compared;
      }
    };
    for (int p = 0; p < 3; ++p)
      for (int q = 0; q < 3; ++q) check(K(p, q), prob.K(p, q), "K(" + std::to_string(p) + "," + std::to_string(q) + ")");
    for (int i = 0; i < 3; ++i) check(P_sym(i, 0), (*P)(i), "P_FI(" + std::to_string(i) + ")");
  }
  CHECK(compared == 6 * 12 * kInputs);
}

}  // namespace

TEST_CASE("AD derivatives of K and the Full Impact equal GiNaC's symbolic derivatives", "[check]") {
  compare<impact3d::GeneratedEngine>("generated");
  compare<impact3d::direct::DirectEngine>("direct");
}
