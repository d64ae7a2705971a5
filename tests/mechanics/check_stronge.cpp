// Stronge's integrated impulse (mechanics/stronge/) on seeded random collisions, by consistency:
// - the double integration holds the 50-digit one within the two integrations' stated error bounds, also
//   nearly plastic, where rounding moves the energetic end farthest;
// - the total turning of the sliding direction is at least its net turn;
// - the kinetic energy the impact takes, from the end state, is the normal work (W_c - W_r) plus the
//   friction's, which is never negative; under the energetic law W_r = e^2 W_c, so it never gains;
// - solved as a strategy, the result is the integration's and its rounding bound holds the integration's;
// - the path the figures draw runs from the start to the end state in order of p, through every event,
//   each of its points on eq 9's line V = V_ri - K P / m'.
#include <catch2/catch.hpp>

#include <cmath>

#include "impact3d/mechanics/stronge/integrate.hpp"
#include "support.hpp"

namespace check_stronge {

using namespace impact3d;
using namespace impact3d::test;
using stronge::RestitutionLaw;

namespace {

constexpr RestitutionLaw kLaws[] = {RestitutionLaw::energetic, RestitutionLaw::poisson, RestitutionLaw::newton};

// (m'/2) V^T K^-1 V: the pair's kinetic energy that the relative velocity V carries (m' dV = -K dP, so
// its change is -integral V . dP, the work of the contact impulse).
double relative_energy(const M3& K, double m_prime, const V3& V) { return m_prime * V.dot(K.ldlt().solve(V)) / 2; }

struct Draw {
  Problem<double> p;
  double mu;
};

Draw draw_collision(std::mt19937_64& g) {
  std::uniform_real_distribution<double> u(0, 1);
  const Scene<double> s = random_scene(g);
  return {make_problem<GeneratedEngine>(s), 1.2 * u(g)};
}

}  // namespace

// The bound each precision states covers its truncation, its events and a stop taken at 16 eps;
// 64 eps of double covers the roundings of the final scaling by m' |V_ri| and of K's entries, which
// the two runs share exactly (the 50-digit one starts from the same doubles).
TEST_CASE("double holds the 50-digit integration within the two stated bounds", "[stronge]") {
#if IMPACT3D_MULTIPRECISION
  using W = mp::float50;
  std::mt19937_64 g(5901);
  int checked = 0, stopped = 0;
  double worst = 0;
  for (int n = 0; n < 20; ++n) {
    const Draw d = draw_collision(g);
    for (const RestitutionLaw law : kLaws) {
      const auto lo = stronge::integrate(d.p.K, d.p.m_prime, d.p.V_ri, d.mu, d.p.restitution, law, true);
      const auto hi = stronge::integrate<W>(d.p.K.cast<W>(), W(d.p.m_prime), d.p.V_ri.cast<W>(), W(d.mu), W(d.p.restitution),
                                            law, true);
      REQUIRE(lo.failure == nullptr);
      REQUIRE(hi.failure == nullptr);
      const V3 reference = hi.P_C.cast<double>();
      const double gap = (lo.P_C - reference).norm() / reference.norm();
      const double bound = lo.relative_error + static_cast<double>(hi.relative_error) + 64 * eps;
      CHECK(gap <= bound);
      worst = std::max(worst, gap / bound);
      for (const auto& ev : lo.events) stopped += ev.kind == stronge::EventKind::stick || ev.kind == stronge::EventKind::reversal;
      ++checked;
    }
  }
  WARN("worst gap " << worst << " of its bound; " << stopped << " of " << checked << " stopped sliding");
  CHECK(checked == 60);
  CHECK(stopped > 0);  // the draws reach the stop, where the bound is widest
#else
  WARN("built without multiprecision: nothing to compare against");
#endif
}

// Nearly plastic, the energetic end is where W, nearly flat in p (V_n near 0), has released e^2 W_c:
// the normal work's rounding moves it by about eps W_c / |V_n| there, many eps of the impulse, which the
// stated bound must carry (the 64 eps of the test above do not).
TEST_CASE("nearly plastic, the stated bound carries the end's location under the work's rounding", "[stronge]") {
#if IMPACT3D_MULTIPRECISION
  using W = mp::float50;
  std::mt19937_64 g(5907);
  int checked = 0;
  double widest = 0;  // the largest gap, in eps
  for (int n = 0; n < 20; ++n) {
    const Draw d = draw_collision(g);
    for (const double e : {1e-4, 1e-6}) {
      const auto lo = stronge::integrate(d.p.K, d.p.m_prime, d.p.V_ri, d.mu, e, RestitutionLaw::energetic, false);
      const auto hi = stronge::integrate<W>(d.p.K.cast<W>(), W(d.p.m_prime), d.p.V_ri.cast<W>(), W(d.mu), W(e),
                                            RestitutionLaw::energetic, false);
      REQUIRE(lo.failure == nullptr);
      REQUIRE(hi.failure == nullptr);
      const V3 reference = hi.P_C.cast<double>();
      const double gap = (lo.P_C - reference).norm() / reference.norm();
      CHECK(gap <= lo.relative_error + static_cast<double>(hi.relative_error) + 64 * eps);
      widest = std::max(widest, gap / eps);
      ++checked;
    }
  }
  WARN("widest gap " << widest << " eps");
  CHECK(checked == 40);
  CHECK(widest > 64);  // the draws reach the effect
#else
  WARN("built without multiprecision: nothing to compare against");
#endif
}

TEST_CASE("the swerve is at least the sliding direction's net turn",
          "[stronge]") {
  std::mt19937_64 g(5902);
  int checked = 0;
  for (int n = 0; n < 200; ++n) {
    const Draw d = draw_collision(g);
    const auto h = stronge::integrate(d.p.K, d.p.m_prime, d.p.V_ri, d.mu, d.p.restitution, RestitutionLaw::energetic);
    REQUIRE(h.failure == nullptr);
    CHECK(h.swerve_deg >= 0);
    bool stopped = false;
    for (const auto& ev : h.events) stopped = stopped || ev.kind == stronge::EventKind::stick || ev.kind == stronge::EventKind::reversal;
    if (stopped || !h.final_direction_deg) continue;
    const double start = std::atan2(d.p.V_ri.z(), d.p.V_ri.y()) * 180 / M_PI;
    const double turn = std::remainder(*h.final_direction_deg - start, 360.0);
    // Both directions come from atan2 of quantities known to a few eps of the sliding speed: 1e-9 degrees
    // is far above that for any slide not about to stop (which the loop skips) and far below a turn.
    CHECK(std::fabs(turn) <= h.swerve_deg + 1e-9);
    ++checked;
  }
  WARN(checked << " of 200 slid throughout");
  CHECK(checked > 20);
}

// The tolerance: the energies are quadratic in V, so an impulse error of error_bound m' |V_ri| moves them
// by about 2 |V| of it; the normal work is integrated with the same bound; 64 kappa eps for the solve
// with K^-1 and the sums of energies of order m' |V_ri|^2.
TEST_CASE("the energy taken is the normal work plus the friction's; the energetic law never gains", "[stronge]") {
  std::mt19937_64 g(5903);
  int checked = 0, newton_gained = 0, frictionless = 0;
  for (int n = 0; n < 200; ++n) {
    Draw d = draw_collision(g);
    if (n % 10 == 0) d.mu = 0;  // frictionless: the energy taken is the normal work exactly
    for (const RestitutionLaw law : kLaws) {
      const auto h = stronge::integrate(d.p.K, d.p.m_prime, d.p.V_ri, d.mu, d.p.restitution, law);
      REQUIRE(h.failure == nullptr);
      const double v0 = d.p.V_ri.norm(), scale = d.p.m_prime * v0 * v0;
      const double tol = (4 * h.error_bound * (1 + h.V_rf.norm() / v0) + 64 * d.p.kappa * eps) * scale;
      const double taken = relative_energy(d.p.K, d.p.m_prime, d.p.V_ri) - relative_energy(d.p.K, d.p.m_prime, h.V_rf);
      const double normal = h.work_compression - h.work_restitution;
      CHECK(taken >= normal - tol);  // friction's work mu |u| dp is never negative
      if (d.mu == 0) CHECK(std::fabs(taken - normal) <= tol);
      if (law == RestitutionLaw::energetic) {
        const double e = d.p.restitution;
        CHECK(std::fabs(h.work_restitution - e * e * h.work_compression) <= tol);
        CHECK(taken >= -tol);
      }
      newton_gained += law == RestitutionLaw::newton && taken < -tol;
      frictionless += d.mu == 0;
      ++checked;
    }
  }
  WARN("Newton's law gained energy in " << newton_gained << " of 200");
  CHECK(checked == 600);
  CHECK(frictionless == 60);
}

TEST_CASE("solved as a strategy: the integration's impulse, regime and bound",
          "[stronge]") {
  std::mt19937_64 g(5904);
  int checked = 0;
  for (int n = 0; n < 50; ++n) {
    const Scene<double> s = random_scene(g);
    const Problem<double> p = make_problem<GeneratedEngine>(s);
    for (const RestitutionLaw law : kLaws) {
      const Solution<double> sol = solve_one(s, Stronge<double>{0.5, law});
      const auto h = stronge::integrate(p.K, p.m_prime, p.V_ri, 0.5, p.restitution, law);
      CHECK((sol.impulse.P_C - h.P_C).norm() <= 4 * eps * h.P_C.norm());
      CHECK(*sol.impulse.mu <= 0.5 * (1 + 8 * eps));
      CHECK((sol.impulse.regime == Regime::full) == !h.final_direction_deg.has_value());
      // The integration's bound is part of the rounding bound the warning is decided on.
      CHECK(sol.rounding_bound >= h.relative_error);
      CHECK(sol.rounding_bound > 0);
      ++checked;
    }
  }
  CHECK(checked == 150);
}

// Eq 9's residual at a point: 64 eps of |V_ri| + |K| |P| / m' for the product and sums; beside it, in
// the slides followed in tau the tangential velocity is the steps' own (carried, not U_i - K P), which
// may drift from the line by the integration's error, error_bound |V_ri|. The end state matches the
// last point to 8 eps: one formula's operations in another order.
TEST_CASE("the recorded path runs from the start to the end through every event, on eq 9's line", "[stronge]") {
  std::mt19937_64 g(5905);
  int checked = 0, points = 0, stopped = 0;
  for (int n = 0; n < 100; ++n) {
    const Draw d = draw_collision(g);
    const RestitutionLaw law = kLaws[n % 3];
    const auto h = stronge::integrate(d.p.K, d.p.m_prime, d.p.V_ri, d.mu, d.p.restitution, law, true);
    REQUIRE(h.failure == nullptr);
    REQUIRE(h.path.size() >= 2);
    const double v0 = d.p.V_ri.norm(), p0 = d.p.m_prime * v0;
    CHECK(h.path.front().P_C.norm() == 0);
    CHECK((h.path.front().V_C - d.p.V_ri).norm() <= 2 * eps * v0);  // V_ri / v0 * v0
    CHECK((h.path.back().P_C - h.P_C).norm() <= 8 * eps * h.P_C.norm());
    CHECK((h.path.back().V_C - h.V_rf).norm() <= 8 * eps * v0);
    bool ordered = true, on_line = true;
    for (std::size_t i = 0; i < h.path.size(); ++i) {
      const auto& q = h.path[i];
      if (i) ordered = ordered && q.P_C.x() >= h.path[i - 1].P_C.x();
      const V3 line = d.p.V_ri - d.p.K * q.P_C / d.p.m_prime;
      const double tol = 64 * eps * (v0 + d.p.K.norm() * q.P_C.norm() / d.p.m_prime) + h.error_bound * v0;
      on_line = on_line && (q.V_C - line).norm() <= tol;
      ++points;
    }
    CHECK(ordered);
    CHECK(on_line);
    // Every event's p is a point of the path: the steps end there.
    for (const auto& ev : h.events) {
      bool found = false;
      for (const auto& q : h.path) found = found || std::fabs(q.P_C.x() - ev.p) <= 8 * eps * p0;
      CHECK(found);
      stopped += ev.kind == stronge::EventKind::stick || ev.kind == stronge::EventKind::reversal;
    }
    ++checked;
  }
  CHECK(checked == 100);
  CHECK(stopped > 0);
  CHECK(points >= 100 * stronge::kPathPoints);
}

}  // namespace check_stronge
