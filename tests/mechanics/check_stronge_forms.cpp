// The two engines' forms of Stronge's sliding map (stronge/generated_forms.hpp from GiNaC's kernels,
// direct/stronge_forms.hpp by a 3x3 solve, K times the impulse rate and the quartic by hand), by
// substitution:
// - at rational K and rational unit directions, the stick ratio, the direction rates and the invariant
//   directions' quartic of the two are equal exactly (no tolerance: both are rational functions);
// - the generated sliding right-hand side is the first Taylor coefficient of the integration's step
//   (sliding_series.hpp builds it from eq 9 by its own recurrence);
// - the impact integrated with either engine's forms agrees within the two integrations' bounds, and
//   solved through the direct engine (its own K too) within those and K's rounding.
#include <catch2/catch.hpp>

#include <cmath>

#include "impact3d/generated/stronge.hpp"
#include "impact3d/mechanics/direct/stronge_forms.hpp"
#include "impact3d/mechanics/stronge/generated_forms.hpp"
#include "impact3d/mechanics/stronge/integrate.hpp"
#include "support.hpp"

namespace check_stronge_forms {

using namespace impact3d;
using namespace impact3d::test;
using stronge::RestitutionLaw;

namespace {

constexpr RestitutionLaw kLaws[] = {RestitutionLaw::energetic, RestitutionLaw::poisson, RestitutionLaw::newton};

// Unit vectors with rational components: Pythagorean triples in each quadrant.
std::array<rational, 2> rational_direction(std::mt19937_64& g) {
  const int triples[][3] = {{3, 4, 5}, {5, 12, 13}, {8, 15, 17}, {7, 24, 25}, {20, 21, 29}, {1, 0, 1}};
  std::uniform_int_distribution<int> pick(0, 5), sign(0, 1);
  const auto& t = triples[pick(g)];
  rational c = rational(t[0]) / t[2], s = rational(t[1]) / t[2];
  if (sign(g)) std::swap(c, s);
  if (sign(g)) c = -c;
  if (sign(g)) s = -s;
  return {c, s};
}

}  // namespace

TEST_CASE("the engines' stick ratio, direction rates and invariant quartic are equal at rationals", "[stronge]") {
  std::mt19937_64 g(5910);
  std::uniform_int_distribution<int> num(-40, 40), den(1, 9);
  int checked = 0;
  for (int n = 0; n < 200; ++n) {
    // A symmetric K with a dominant tangential block (so it is invertible), rational entries.
    Mat3<rational> K;
    for (int i = 0; i < 3; ++i)
      for (int j = i; j < 3; ++j) K(i, j) = K(j, i) = rational(num(g)) / den(g) + (i == j ? rational(100) : rational(0));
    const rational mu = rational(1 + den(g)) / 7;
    const auto rg = stronge::GeneratedForms::stick_ratio(K);
    const auto rd = direct::StrongeForms::stick_ratio(K);
    REQUIRE(rg);
    REQUIRE(rd);
    CHECK(*rg == *rd);
    // The stick ratio keeps V_t and V_z: rows t and z of K (1, r) vanish.
    const Vec3<rational> dP(rational(1), (*rg)[0], (*rg)[1]);
    CHECK((K * dP)(1) == 0);
    CHECK((K * dP)(2) == 0);
    const auto [c, s] = rational_direction(g);
    CHECK(stronge::GeneratedForms::direction_rates(K, mu, c, s) == direct::StrongeForms::direction_rates(K, mu, c, s));
    const auto [c0, s0] = rational_direction(g);
    CHECK(stronge::GeneratedForms::invariant_quartic(K, mu, c0, s0) == direct::StrongeForms::invariant_quartic(K, mu, c0, s0));
    ++checked;
  }
  CHECK(checked == 200);
}

// At 50 digits: the series' order-1 coefficients are -K (1, mu u / |u|) computed by a Cauchy-product
// recurrence, the kernel's by one closed form; a few roundings of the products and the square root
// each, so 16 eps of the rate's scale 1 + mu |K|.
TEST_CASE("the generated sliding rate is the first Taylor coefficient of the integration's step", "[stronge]") {
#if IMPACT3D_MULTIPRECISION
  using W = mp::float50;
  const W eps_w = std::numeric_limits<W>::epsilon();
  std::mt19937_64 g(5911);
  std::uniform_real_distribution<double> u(0, 1);
  int checked = 0;
  for (int n = 0; n < 100; ++n) {
    const Problem<double> p = make_problem<GeneratedEngine>(random_scene(g));
    const Mat3<W> K = p.K.cast<W>();
    const W mu(1.2 * u(g)), v0 = W(p.V_ri.norm());
    const Vec3<W> U_i = p.V_ri.cast<W>() / v0;
    if (U_i(1) * U_i(1) + U_i(2) * U_i(2) == W(0)) continue;
    const auto ser = stronge::sliding_series(K, U_i, mu, W(0), W(0), W(0), W(0), 3);
    const Vec3<W> rate = generated::stronge_sliding_rate(K, W(1), mu, U_i);
    const Vec3<W> first(ser.U_n[1], ser.u_t[1], ser.u_z[1]);
    const W scale = W(1) + mu * K.cwiseAbs().maxCoeff();
    CHECK(static_cast<double>((rate - first).cwiseAbs().maxCoeff() / (eps_w * scale)) <= 16);
    // And through the dimensions: the kernel at m' and V is the dimensionless rate times v0 / (m' v0).
    const Vec3<W> dimensional = generated::stronge_sliding_rate(K, W(p.m_prime), mu, Vec3<W>(p.V_ri.cast<W>()));
    CHECK(static_cast<double>((dimensional * W(p.m_prime) - rate).cwiseAbs().maxCoeff() / (eps_w * scale)) <= 16);
    ++checked;
  }
  CHECK(checked == 100);
#else
  WARN("built without multiprecision: nothing to compare against");
#endif
}

// Both integrations state a bound relative to |P|; their difference lies within the sum, and 64 eps
// for the final scaling and the forms' own roundings, which change the path by as much.
TEST_CASE("integrated with either engine's forms, the impacts agree within the two bounds", "[stronge]") {
  std::mt19937_64 g(5912);
  std::uniform_real_distribution<double> u(0, 1);
  int checked = 0, stopped = 0;
  double worst = 0;
  for (int n = 0; n < 100; ++n) {
    const Problem<double> p = make_problem<GeneratedEngine>(random_scene(g));
    const double mu = 1.2 * u(g);
    for (const RestitutionLaw law : kLaws) {
      const auto a = stronge::integrate<double, stronge::GeneratedForms>(p.K, p.m_prime, p.V_ri, mu, p.restitution, law);
      const auto b = stronge::integrate<double, direct::StrongeForms>(p.K, p.m_prime, p.V_ri, mu, p.restitution, law);
      REQUIRE(a.failure == nullptr);
      REQUIRE(b.failure == nullptr);
      const double bound = a.relative_error + b.relative_error + 64 * eps;
      const double gap = (a.P_C - b.P_C).norm() / a.P_C.norm();
      CHECK(gap <= bound);
      worst = std::max(worst, gap / bound);
      CHECK(a.final_direction_deg.has_value() == b.final_direction_deg.has_value());
      stopped += a.diverging_directions > 0 || !a.final_direction_deg;
      ++checked;
    }
  }
  WARN("worst gap " << worst << " of its bound; " << stopped << " of " << checked << " stopped sliding");
  CHECK(checked == 300);
  CHECK(stopped > 0);
}

// Through the engines whole: the direct engine's K differs from the generated one's by its rounding
// (check_engines: 16 eps cond J), which the impulse carries with kappa.
TEST_CASE("solved through the direct engine, stronge agrees with the generated engine", "[stronge]") {
  std::mt19937_64 g(5913);
  std::uniform_real_distribution<double> u(0, 1);
  int checked = 0;
  for (int n = 0; n < 50; ++n) {
    const Scene<double> s = random_scene(g);
    const std::vector<Strategy<double>> st{Stronge<double>{1.2 * u(g), RestitutionLaw::energetic},
                                           Stronge<double>{1.2 * u(g), RestitutionLaw::newton}};
    const auto a = analyze(s, st, Engine::generated), b = analyze(s, st, Engine::direct);
    for (std::size_t k = 0; k < st.size(); ++k) {
      const auto &x = a.solutions[k].impulse, &y = b.solutions[k].impulse;
      const double bound = *x.integration_error + *y.integration_error + 64 * eps * a.kappa * inertia_condition(s);
      CHECK((x.P_C - y.P_C).norm() / x.P_C.norm() <= bound);
      ++checked;
    }
  }
  CHECK(checked == 100);
}

}  // namespace check_stronge_forms
