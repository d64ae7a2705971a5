// Stronge's integrated impulse (mechanics/stronge/) against answers from independent routes: the
// frictionless impulse (Brach at zero ratios), the Full Impact where the contact sticks throughout
// (pc-crash's eqs 10-12), the planar impact's piecewise-linear closed form derived here by hand, and the
// isotropic contact's straight-line slide; at double and at 50 digits.
#include <catch2/catch.hpp>

#include <cmath>

#include "impact3d/mechanics/stronge/integrate.hpp"
#include "support.hpp"

namespace exam_stronge {

using namespace impact3d;
using namespace impact3d::test;
using stronge::RestitutionLaw;

namespace {

constexpr RestitutionLaw kLaws[] = {RestitutionLaw::energetic, RestitutionLaw::poisson, RestitutionLaw::newton};

template <typename Scalar>
Scalar relative_gap(const Vec3<Scalar>& a, const Vec3<Scalar>& b) {
  return (a - b).norm() / b.norm();
}

// The planar impact (K_tz = K_nz = 0, V_zi = 0) by hand. With f = dP_t/dp, eq 9 gives
//   m' dV_n/dp = -(K_nn + K_nt f),   m' dV_t/dp = -(K_tn + K_tt f),
// and f = mu sign(V_t) while sliding. Sliding stops at p_s = -m' V_ti / (K_tn + mu s K_tt) if that is
// positive (s = sign V_ti); then the contact sticks with f = r = -K_tn / K_tt if |r| <= mu, else slides
// back with f = -mu s. V_n is piecewise linear in p, and the normal work W = int V_n dp piecewise
// quadratic: compression ends at V_n = 0, the impact where W = (1 - e^2) W_c (energetic), p = (1 + e)
// p_c (Poisson) or V_n = -e V_ni (Newton).
template <typename Scalar>
struct PlanarImpact {
  Scalar p_f, P_t;
  bool sticks = false, reverses = false;
};

template <typename Scalar>
PlanarImpact<Scalar> planar_by_hand(const Mat3<Scalar>& K, const Scalar& m, const Vec3<Scalar>& V_i, const Scalar& mu,
                                    const Scalar& e, RestitutionLaw law) {
  using std::sqrt;
  PlanarImpact<Scalar> out;
  // Segments of constant f: [p0, p1) with V_n(p0), W(p0).
  Scalar p(0), V_n = V_i(0), V_t = V_i(1), W(0), P_t(0);
  Scalar f = V_t > Scalar(0) ? mu : V_t < Scalar(0) ? Scalar(-mu) : Scalar(0);
  bool sliding = V_t != Scalar(0);
  if (!sliding) {
    const Scalar r = -K(1, 0) / K(1, 1);
    f = abs(r) <= mu ? r : (r > Scalar(0) ? mu : Scalar(-mu));
    out.sticks = abs(r) <= mu;
    sliding = !out.sticks;  // from rest, out along the direction of r
  }
  bool compressing = true;
  Scalar p_c(0), W_c(0);
  for (int segment = 0; segment < 6; ++segment) {
    const Scalar dn = -(K(0, 0) + K(0, 1) * f) / m, dt = -(K(1, 0) + K(1, 1) * f) / m;
    // The candidates for this segment's end, as increments of p.
    Scalar stop = Scalar(1e300);
    if (sliding && V_t * dt < Scalar(0)) stop = -V_t / dt;
    Scalar event;
    if (compressing) {
      event = -V_n / dn;
    } else if (law == RestitutionLaw::energetic) {
      // W + V_n d + dn d^2 / 2 = (1 - e^2) W_c, the root with V_n < 0 decreasing.
      const Scalar left = W - (Scalar(1) - e * e) * W_c;
      event = Scalar(2) * left / (sqrt(V_n * V_n - Scalar(2) * dn * left) - V_n);
    } else if (law == RestitutionLaw::poisson) {
      event = (Scalar(1) + e) * p_c - p;
    } else {
      event = (V_n + e * V_i(0)) / -dn;
    }
    const Scalar d = stop < event ? stop : event;
    W += V_n * d + dn * d * d / Scalar(2);
    V_n += dn * d, V_t += dt * d, P_t += f * d, p += d;
    if (stop < event) {
      sliding = false;
      const Scalar r = -K(1, 0) / K(1, 1);
      if (abs(r) <= mu) {
        f = r, out.sticks = true;
      } else {
        f = -f, out.reverses = true, sliding = true;
        V_t = Scalar(0);
      }
      continue;
    }
    if (compressing) {
      compressing = false, p_c = p, W_c = W;
      if (e == Scalar(0)) break;
      continue;
    }
    break;
  }
  out.p_f = p, out.P_t = P_t;
  return out;
}

template <typename Scalar>
Mat3<Scalar> planar_K() {
  Mat3<Scalar> K;
  K << ratio<Scalar>(16, 10), ratio<Scalar>(5, 10), Scalar(0), ratio<Scalar>(5, 10), ratio<Scalar>(21, 10), Scalar(0),
      Scalar(0), Scalar(0), ratio<Scalar>(18, 10);
  return K;
}

}  // namespace

// 256 eps: the closed form's three or four segments and the integration's events each carry a few
// roundings of quantities of order one (K's entries, |V_i| = 1 after scaling), and a bisected event
// lands within one ulp of its root; 256 is far above that sum and far below any modelling difference.
TEMPLATE_TEST_CASE("the planar impact follows the hand-derived piecewise-linear solution", "[stronge]", double
#if IMPACT3D_MULTIPRECISION
                   ,
                   mp::float50
#endif
) {
  using S = TestType;
  const S eps_s = std::numeric_limits<S>::epsilon();
  const Mat3<S> K = planar_K<S>();
  const S m(900);
  struct Row {
    Vec3<S> V_i;
    S mu, e;
    bool sticks, reverses;
  };
  const Row rows[] = {
      {Vec3<S>(S(8), S(5), S(0)), ratio<S>(3, 10), ratio<S>(5, 10), true, false},   // slides, then sticks
      {Vec3<S>(S(8), S(5), S(0)), ratio<S>(1, 10), ratio<S>(8, 10), false, true},   // slides, then back
      {Vec3<S>(S(8), S(0), S(0)), ratio<S>(3, 10), ratio<S>(5, 10), true, false},   // sticks from the start
      {Vec3<S>(S(8), S(-7), S(0)), ratio<S>(2, 10), S(0), false, false},     // slides throughout
  };
  int checked = 0;
  for (const Row& row : rows)
    for (const RestitutionLaw law : kLaws) {
      const auto hand = planar_by_hand<S>(K, m, row.V_i, row.mu, row.e, law);
      CHECK(hand.sticks == row.sticks);
      CHECK(hand.reverses == row.reverses);
      const auto got = stronge::integrate<S>(K, m, row.V_i, row.mu, row.e, law);
      REQUIRE(got.failure == nullptr);
      const Vec3<S> expected(hand.p_f, hand.P_t, S(0));
      CHECK(to_double(relative_gap(got.P_C, expected) / eps_s) <= 256);
      CHECK(to_double(abs(got.swerve_deg)) == 0);
      bool stuck = false, reversed = false;
      for (const auto& ev : got.events) {
        stuck = stuck || ev.kind == stronge::EventKind::stick;
        reversed = reversed || ev.kind == stronge::EventKind::reversal;
      }
      CHECK(stuck == row.sticks);
      CHECK(reversed == row.reverses);
      ++checked;
    }
  CHECK(checked == 12);
}

// 64 eps: with mu = 0 the normal velocity falls linearly and every law ends at (1 + e) p_c; Brach's
// closed form at zero ratios is one division of the same order one quantities.
TEST_CASE("frictionless: P = (p_f, 0, 0) for every law, Brach's impulse at zero ratios", "[stronge]") {
  std::mt19937_64 g(591);
  int checked = 0;
  for (int n = 0; n < 50; ++n) {
    const Scene<double> s = random_scene(g);
    const Problem<double> p = make_problem<GeneratedEngine>(s);
    const V3 brach = *GeneratedEngine::try_brach_impulse(p, std::optional<double>(0.0), std::optional<double>(0.0));
    for (const RestitutionLaw law : kLaws) {
      const auto got = stronge::integrate(p.K, p.m_prime, p.V_ri, 0.0, p.restitution, law);
      REQUIRE(got.failure == nullptr);
      CHECK(relative_gap(got.P_C, brach) / eps <= 64);
      ++checked;
    }
  }
  CHECK(checked == 150);
}

// A rounding bound of the Full Impact's 3x3 solve: kappa(K) roundings, and the integration's own few.
TEST_CASE("no initial sliding and sticking throughout: the Full Impact (eqs 10-12) for every law", "[stronge]") {
  std::mt19937_64 g(592);
  int checked = 0;
  for (int n = 0; n < 50; ++n) {
    const Scene<double> s = random_scene(g);
    Problem<double> p = make_problem<GeneratedEngine>(s);
    p.V_ri = V3(p.V_ri.x(), 0, 0);
    const auto r = stronge::GeneratedForms::stick_ratio(p.K);
    REQUIRE(r);
    const double mu = 1.01 * std::hypot((*r)[0], (*r)[1]);
    const V3 full = *GeneratedEngine::try_full_impact(p, p.restitution);
    for (const RestitutionLaw law : kLaws) {
      const auto got = stronge::integrate(p.K, p.m_prime, p.V_ri, mu, p.restitution, law);
      REQUIRE(got.failure == nullptr);
      REQUIRE(got.events.size() == 3);
      CHECK(got.events[0].kind == stronge::EventKind::stick);
      CHECK(relative_gap(got.P_C, full) / eps <= 64 * p.kappa);
      ++checked;
    }
  }
  CHECK(checked == 150);
}

// The isotropic contact (A = a I, K_nt = K_nz = 0): u falls along its first direction at mu a / m' and
// sticks at p_s = m' |u_i| / (mu a); V_n falls at K_nn / m' throughout, so every law ends at
// p_f = (1 + e) m' V_ni / K_nn. 64 eps: a few roundings of order one quantities.
TEST_CASE("isotropic contact: no swerve, a straight slide to rest, the closed form", "[stronge]") {
  M3 K;
  K << 1.7, 0, 0, 0, 2.3, 0, 0, 0, 2.3;
  const double m = 1100, e = 0.3;
  int checked = 0;
  // The second approach slides at 1/180 of the approach speed: below kApproach from the start, so its
  // whole slide is followed in tau (approach_series.hpp).
  for (const V3& V_i : {V3(9, -4, 3), V3(9, -0.04, 0.03)})
  for (const double mu : {0.05, 0.4, 2.0})
    for (const RestitutionLaw law : kLaws) {
      const auto got = stronge::integrate(K, m, V_i, mu, e, law);
      REQUIRE(got.failure == nullptr);
      const double p_f = (1 + e) * m * V_i.x() / K(0, 0), rho = std::hypot(V_i.y(), V_i.z());
      const double p_s = m * rho / (mu * K(1, 1));
      const double slid = mu * std::min(p_f, p_s);
      const V3 expected(p_f, slid * V_i.y() / rho, slid * V_i.z() / rho);
      CHECK(relative_gap(got.P_C, expected) / eps <= 64);
      INFO("swerve " << got.swerve_deg << " deg in " << got.steps << " steps");
      // Each step's turn is the angle between two directions each rounded to an eps or two: 4 eps rad a step.
      CHECK(got.swerve_deg <= 4 * eps * got.steps * 180 / M_PI);
      ++checked;
    }
  CHECK(checked == 18);
}

// Newton's law gains energy when sliding stops during compression (Stronge, Impact Mechanics, sec. 5.3;
// Kane and Levinson's example): the tangential coupling K_nt < 0 speeds the normal approach's reversal
// once the friction no longer opposes it, and V_nf = -e V_ni is then reached only after more
// restitution impulse than the compression's. The planar hand solution above gives the end state; its
// energy (m'/2) V^T K^-1 V (m' dV = -K dP, so the change is the contact impulse's work) is by hand.
// The energetic law on the same impact loses energy, as it always must.
TEST_CASE("Newton's law gains energy where sliding stops during compression; the energetic law does not",
          "[stronge]") {
  M3 K;
  K << 0.56, -0.64, 0, -0.64, 2.38, 0, 0, 0, 1.8;
  const double m = 1, mu = 0.8, e = 0.96;
  const V3 V_i(1, -1.4, 0);
  auto energy = [&](const V3& V) {
    // The planar block's inverse by hand: [K_tt, -K_nt; -K_nt, K_nn] / det.
    const double det = K(0, 0) * K(1, 1) - K(0, 1) * K(0, 1);
    return m * (K(1, 1) * V.x() * V.x() - 2 * K(0, 1) * V.x() * V.y() + K(0, 0) * V.y() * V.y()) / det / 2;
  };
  const auto hand_newton = planar_by_hand<double>(K, m, V_i, mu, e, RestitutionLaw::newton);
  REQUIRE(hand_newton.sticks);
  const V3 V_f = V_i - K * V3(hand_newton.p_f, hand_newton.P_t, 0) / m;
  CHECK(std::fabs(V_f.x() + e * V_i.x()) <= 16 * eps);
  // Lost: negative, by a fifth of the approach's energy, far beyond any rounding.
  CHECK(energy(V_i) - energy(V_f) < -0.1 * energy(V_i));

  const auto got = stronge::integrate(K, m, V_i, mu, e, RestitutionLaw::newton);
  REQUIRE(got.failure == nullptr);
  REQUIRE(got.events.size() == 4);
  CHECK(got.events[1].kind == stronge::EventKind::stick);  // before compression ends
  CHECK(got.events[2].kind == stronge::EventKind::compression_end);
  CHECK(std::fabs(energy(got.V_rf) - energy(V_f)) <= 64 * eps * energy(V_i));

  const auto energetic = stronge::integrate(K, m, V_i, mu, e, RestitutionLaw::energetic);
  REQUIRE(energetic.failure == nullptr);
  CHECK(energy(V_i) - energy(energetic.V_rf) > 0);
}

}  // namespace exam_stronge
