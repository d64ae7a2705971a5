// Figure 8 through the impact (examples/stronge/fig8_through_the_impact.json) by a fixed-direction
// scheme like Simbody's PLUS, which holds the sliding direction over a step and lets it turn at most 30
// degrees a step, beside the integrated answer (stronge/integrate.hpp) that follows it continuously.
//
// The scheme, written here from its description alone: in each step the impulse rate is constant,
// dP/dp = (1, mu d) with d the sliding direction at the step's start (or, once the contact has stopped,
// the stick ratio or mu times the invariant direction it slides out along, from the same forms); the
// step ends where d would have turned 30 degrees at its starting rate, where the velocity along d
// reaches zero (the contact is taken to stop), or at compression's end or the impact's end, which are
// exact within a step (V is linear in p there). Its error is first order in the turning allowed.
//
// What it shows: at 30 degrees the scheme's impulse is off by 1.5 to 1.9 % of |P| (known from this
// test's first run; held between 0.5 % and 5 %), and its error falls at least linearly with the allowed
// turn (a thirtieth of the turn, at least a tenth of the error), towards the integrated answer, an
// independent route to the same limit. The table it prints
// is docs/verification-and-compare.md's.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "case_files.hpp"
#include "impact3d/mechanics/stronge/generated_forms.hpp"
#include "impact3d/mechanics/stronge/tangential_map.hpp"

namespace exam_stronge_fixed_step {

using namespace impact3d;
using namespace impact3d::test;
using stronge::RestitutionLaw;

namespace {

using Forms = stronge::GeneratedForms;

struct Fixed {
  V3 P, V;
  int steps = 0;
  bool stopped = false;
};

// The smallest positive root of a h^2 + b h + c, c > 0 (inf when none).
double first_positive_root(double a, double b, double c) {
  const double inf = std::numeric_limits<double>::infinity();
  if (a == 0) return b < 0 ? -c / b : inf;
  const double disc = b * b - 4 * a * c;
  if (disc < 0) return inf;
  const double q = -(b + std::copysign(std::sqrt(disc), b)) / 2;
  double best = inf;
  for (const double h : {q / a, c / q})
    if (h > 0 && h < best) best = h;
  return best;
}

Fixed fixed_step(const Problem<double>& p, double mu, RestitutionLaw law, double max_turn) {
  const M3& K = p.K;
  const double m = p.m_prime, e = p.restitution, inf = std::numeric_limits<double>::infinity();
  Fixed f{V3::Zero(), p.V_ri};
  double W = 0, p_c = 0, W_c = 0;
  bool compressing = true;
  std::optional<V3> rate;  // the impulse rate once the contact has stopped
  while (f.steps < 100000) {
    ++f.steps;
    V3 dP;
    double h = inf;
    if (!rate) {
      const double rho = std::hypot(f.V(1), f.V(2)), c = f.V(1) / rho, s = f.V(2) / rho;
      const auto [growth, turning] = Forms::direction_rates(K, mu, c, s);
      dP = V3(1, mu * c, mu * s);
      if (turning != 0) h = max_turn * m * rho / std::abs(turning);
      if (growth < 0) h = std::min(h, m * rho / -growth);
    } else {
      dP = *rate;
    }
    const V3 dV = -K * dP / m;
    const double hs = h;
    if (compressing && dV(0) < 0) h = std::min(h, -f.V(0) / dV(0));
    double h_end = inf;
    if (!compressing) {
      switch (law) {
        case RestitutionLaw::energetic: h_end = first_positive_root(dV(0) / 2, f.V(0), W - (1 - e * e) * W_c); break;
        case RestitutionLaw::poisson: h_end = (1 + e) * p_c - f.P(0); break;
        case RestitutionLaw::newton: h_end = dV(0) < 0 ? (-e * p.V_ri(0) - f.V(0)) / dV(0) : inf; break;
      }
      h = std::min(h, h_end);
    }
    REQUIRE(std::isfinite(h));
    W += f.V(0) * h + dV(0) * h * h / 2;
    f.P += dP * h;
    f.V += dV * h;
    if (h == h_end) return f;
    if (compressing && h < hs && f.V(0) <= 1e-12 * p.V_ri(0)) compressing = false, p_c = f.P(0), W_c = W;
    else if (!rate && h == hs && f.V.tail<2>().dot(dP.tail<2>()) <= 1e-12 * mu * p.V_ri.norm()) {
      // Stopped: stick if the cone holds the ratio, else slide out along the fastest-growing direction.
      f.stopped = true;
      const auto r = Forms::stick_ratio(K);
      REQUIRE(r);
      if (std::hypot((*r)[0], (*r)[1]) <= mu) {
        rate = V3(1, (*r)[0], (*r)[1]);
      } else {
        std::optional<stronge::Direction<double>> best;
        for (const auto& d : stronge::invariant_directions<Forms>(K, mu))
          if (d.growth > 0 && (!best || d.growth > best->growth)) best = d;
        REQUIRE(best);
        rate = V3(1, mu * best->c, mu * best->s);
      }
    }
  }
  FAIL("the fixed-step scheme did not end");
  return f;
}

}  // namespace

TEST_CASE("Figure 8: a scheme that lets the direction turn 30 degrees a step, beside the integration",
          "[stronge][figure8]") {
  const case_format::CaseSpec c = load_spec(example("stronge/fig8_through_the_impact.json"));
  const Scene<double> scene = case_format::to_scene<double>(c);
  const std::vector<Strategy<double>> strategies{Stronge<double>{0.4, RestitutionLaw::energetic},
                                                 Stronge<double>{1.0, RestitutionLaw::energetic},
                                                 Stronge<double>{1.0, RestitutionLaw::newton}};
  const auto a = analyze(scene, strategies);
  const double turns_deg[] = {30, 10, 3, 1};
  std::string table = "| case | turn a step | steps | gap in P, of |P| | gap in V_rf (t, z), of |V_ri| |\n|---|---|---|---|---|\n";
  int checked = 0;
  for (std::size_t k = 0; k < strategies.size(); ++k) {
    const auto& st = std::get<Stronge<double>>(strategies[k]);
    const auto& sol = a.solutions[k];
    const double bound = *sol.impulse.integration_error;
    double gap_30 = 0, gap_1 = 0;
    for (const double deg : turns_deg) {
      const Fixed f = fixed_step(a, st.mu, st.law, deg * M_PI / 180);
      const double gap = (f.P - sol.impulse.P_C).norm() / sol.impulse.P_C.norm();
      const double gap_v = (f.V.tail<2>() - sol.V_rf.tail<2>()).norm() / a.V_ri.norm();
      if (deg == 30) gap_30 = gap;
      if (deg == 1) gap_1 = gap;
      table += fmt::format("| mu {}, {} | {}° | {} | {:.2e} | {:.2e} |\n", st.mu, stronge::law_name(st.law), deg,
                           f.steps, gap, gap_v);
      ++checked;
    }
    table += fmt::format("| integrated | | {} | bound {:.1e} | |\n", sol.impulse.history ? sol.impulse.history->steps : -1, bound);
    // Apart at 30 degrees by what the first run found, and at least first order towards the integration.
    CHECK(gap_30 > 0.005);
    CHECK(gap_30 < 0.05);
    CHECK(gap_1 < gap_30 / 10);
  }
  WARN(table);
  CHECK(checked == 12);
}

}  // namespace exam_stronge_fixed_step
