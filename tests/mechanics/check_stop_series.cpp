// The rest of a slide that comes to rest in closed form (stronge/stop_series.hpp: a series in the angle
// to the invariant direction it settles on) against the same slide followed step by step in tau
// (stronge/approach_series.hpp) at 50 digits until |u| is 10^-45 of its start, the last 10^-45 taken as
// a straight slide along the direction reached: the impulse still to come and the normal work, on
// seeded random collisions, each near every attracting invariant direction that shrinks the slide.
#include <catch2/catch.hpp>

#include <cmath>

#include "impact3d/mechanics/stronge/approach_series.hpp"
#include "impact3d/mechanics/stronge/generated_forms.hpp"
#include "impact3d/mechanics/stronge/stop_series.hpp"
#include "support.hpp"

namespace check_stop_series {

using namespace impact3d;
using namespace impact3d::test;

namespace {

#if IMPACT3D_MULTIPRECISION
using W = mp::float50;

struct Rest {
  Vec3<W> dP;
  W dW;
};

// From u0 with the normal velocity U_n0 (U_i = (U_n0, u0), P = 0), by Taylor steps of order 60 in tau
// whose last term is 10^-55 of the slide's scale.
Rest stepped(const Mat3<W>& K, const W& mu, const W& U_n0, const W& u0_t, const W& u0_z) {
  using std::abs;
  using std::sqrt;
  const Vec3<W> U_i(U_n0, u0_t, u0_z);
  const W rho0 = sqrt(u0_t * u0_t + u0_z * u0_z);
  W x(0), a(0), b(0), work(0), ut = u0_t, uz = u0_z;
  for (int step = 0; step < 2000; ++step) {
    const W rho = sqrt(ut * ut + uz * uz);
    if (rho <= W("1e-45") * rho0) {
      // The rest along the direction reached: x grows by rho / -g, P_t and P_z by mu times it along u.
      const W dx = rho / -stronge::GeneratedForms::direction_rates(K, mu, W(ut / rho), W(uz / rho))[0];
      const W U_n = U_n0 - (K(0, 0) * x + K(0, 1) * a + K(0, 2) * b);
      return {Vec3<W>(x + dx, a + mu * dx * ut / rho, b + mu * dx * uz / rho), work + U_n * dx};
    }
    const auto s = stronge::approach_series(K, U_i, mu, x, a, b, work, ut, uz, 60);
    W H(1e6);
    for (const auto& [v, scale] : {std::pair{&s.u_t, rho}, std::pair{&s.u_z, rho}, std::pair{&s.x, rho0}, std::pair{&s.W, rho0 * rho0}})
      for (int j = 59; j <= 60; ++j)
        if ((*v)[j] != W(0)) H = std::min(H, W(pow(W("1e-55") * scale / abs((*v)[j]), W(1) / W(j))));
    x = stronge::polynomial_at(s.x, H), a = stronge::polynomial_at(s.a, H), b = stronge::polynomial_at(s.b, H);
    work = stronge::polynomial_at(s.W, H), ut = stronge::polynomial_at(s.u_t, H), uz = stronge::polynomial_at(s.u_z, H);
  }
  FAIL("the slide did not come to rest in 2000 steps");
  return {};
}
#endif

}  // namespace

// 64 eps of the rest: the series' sums of up to `order` terms, each a few roundings of order-one
// quantities; beside it the tail's own truncation estimate (rho times its last terms). The 50-digit
// tail holds the stepped reference to 10^-40, the reference's own error being below 10^-45.
TEST_CASE("the closed-form rest of a slide is the slide followed in tau to rest", "[stronge]") {
#if IMPACT3D_MULTIPRECISION
  std::mt19937_64 g(5906);
  std::uniform_real_distribution<double> u(0, 1);
  int checked = 0;
  double worst = 0;
  for (int n = 0; n < 40 && checked < 24; ++n) {
    const Problem<double> p = make_problem<GeneratedEngine>(random_scene(g));
    const double mu = 0.1 + 1.1 * u(g);
    const Mat3<W> K = p.K.cast<W>();
    const auto map_w = stronge::TangentialMap<W>::of(K);
    const auto map_d = stronge::TangentialMap<double>::of(p.K);
    const auto dirs_w = stronge::invariant_directions<stronge::GeneratedForms>(K, W(mu));
    const auto dirs_d = stronge::invariant_directions<stronge::GeneratedForms>(p.K, mu);
    if (dirs_w.size() != dirs_d.size()) continue;
    for (std::size_t k = 0; k < dirs_w.size(); ++k) {
      if (!(dirs_w[k].growth < W(0))) continue;
      const double delta = (u(g) - 0.5) * 0.6;  // within 0.3 rad of it
      const W th = atan2(dirs_w[k].s, dirs_w[k].c) + W(delta);
      const W rho0("1e-3"), U_n0("0.7");
      const W ut = rho0 * cos(th), uz = rho0 * sin(th);
      const auto tail_w = stronge::stop_tail(K, map_w, W(mu), dirs_w[k].c, dirs_w[k].s, W(delta),
                                             W(std::numeric_limits<W>::epsilon() / rho0), 120);
      if (!tail_w.converged) continue;  // a repelling direction, or delta past the series' reach
      const Rest ref = stepped(K, W(mu), U_n0, ut, uz);
      const auto W_of = [&](const Vec3<W>& F, const W& G) {
        const Vec3<W> dP = F * rho0;
        return (U_n0 - (K.row(0) * dP)(0)) * dP(0) + rho0 * rho0 * G;
      };
      const Vec3<W> dP_w = tail_w.F * rho0;
      CHECK(static_cast<double>((dP_w - ref.dP).norm() / ref.dP.norm()) <= 1e-40);
      CHECK(static_cast<double>(abs(W_of(tail_w.F, tail_w.G) - ref.dW) / abs(ref.dW)) <= 1e-40);
      // Double, about its own invariant direction, at the angle the 50-digit start has from it.
      const double utd = static_cast<double>(ut), uzd = static_cast<double>(uz), rd = std::hypot(utd, uzd);
      const auto& d = dirs_d[k];
      const double delta_d = std::atan2(d.c * uzd / rd - d.s * utd / rd, d.c * utd / rd + d.s * uzd / rd);
      const auto tail_d = stronge::stop_tail(p.K, map_d, mu, d.c, d.s, delta_d, eps / rd, stronge::taylor_order<double>());
      REQUIRE(tail_d.converged);
      const V3 dP_ref = ref.dP.cast<double>();
      const double gap = (tail_d.F * rd - dP_ref).norm() / dP_ref.norm();
      CHECK(gap <= 64 * eps + tail_d.last / tail_d.F.norm());
      worst = std::max(worst, gap / eps);
      ++checked;
    }
  }
  WARN("worst gap at double " << worst << " eps");
  CHECK(checked >= 12);
#else
  WARN("built without multiprecision: nothing to compare against");
#endif
}

}  // namespace check_stop_series
