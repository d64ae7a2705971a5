// The generated kernels against the direct 3x3 solves, over thousands of seeded random collisions:
// every strategy, tilted and rolled contact frames, pitched and rolled vehicles, products of inertia.
// Errors are measured in units of epsilon times the condition that bounds them, and the worst case is
// reported.
#include <catch2/catch.hpp>

#include <iostream>

#include <fmt/format.h>

#include "support.hpp"

namespace check_engines {

using namespace impact3d;
using namespace impact3d::test;

namespace {

struct Worst {
  std::string quantity;
  double max = 0, sum_sq = 0;
  long count = 0;
  int case_index = -1;
  void add(double units, int index) {
    sum_sq += units * units;
    ++count;
    if (units > max) {
      max = units;
      case_index = index;
    }
  }
};

Strategy<double> random_strategy(std::mt19937_64& g) {
  std::uniform_real_distribution<double> u(0, 1);
  switch (static_cast<int>(u(g) * 6)) {
    case 0: return PcCrash<double>{1.5 * u(g)};
    case 1: return Wach<double>{1.2 * u(g), WachLimit::cir};
    case 2: return Wach<double>{1.2 * u(g), WachLimit::gir};
    case 3: return Brach<double>{-0.5 + u(g), -0.3 + 0.6 * u(g)};
    case 4: return Brach<double>{std::nullopt, -0.3 + 0.6 * u(g)};
    default: return u(g) < 0.5 ? Strategy<double>(Brach<double>{-0.5 + u(g), std::nullopt})
                               : Strategy<double>(Brach<double>{std::nullopt, std::nullopt});
  }
}

}  // namespace

TEST_CASE("generated and direct engines agree over 10000 random collisions, in units of epsilon", "[engines]") {
  std::mt19937_64 g(2024);
  Worst K{"K, |dK| / (eps |K| cond J)"}, P{"impulse, |dP| / (eps |P| kappa cond J)"},
      V{"V_rf, |dV| / (eps |V| kappa cond J)"}, E{"energy loss, |dE| / (eps E kappa cond J)"},
      R{"ratios used and limits, |dmu| / (eps kappa cond J (1 + |mu|)^2)"};
  const int cases = 10000;
  for (int n = 0; n < cases; ++n) {
    const Scene<double> s = random_scene(g);
    std::vector<Strategy<double>> st;
    for (int k = 0; k < 4; ++k) st.push_back(random_strategy(g));
    const auto a = analyze(s, st, Engine::generated), b = analyze(s, st, Engine::direct);
    const double cj = inertia_condition(s), scale = a.kappa * cj;
    K.add((a.K - b.K).norm() / (eps * b.K.norm() * cj), n);
    for (std::size_t k = 0; k < st.size(); ++k) {
      const auto &x = a.solutions[k], &y = b.solutions[k];
      REQUIRE(x.impulse.regime == y.impulse.regime);
      P.add((x.impulse.P_C - y.impulse.P_C).norm() / (eps * y.impulse.P_C.norm() * scale), n);
      V.add((x.V_rf - y.V_rf).norm() / (eps * velocity_scale(s) * scale), n);
      E.add(std::abs(x.energy_loss - y.energy_loss) / (eps * y.energy_before * scale), n);
      const std::optional<double>* pairs[][2] = {{&x.impulse.mu, &y.impulse.mu},
                                                 {&x.impulse.mu_t, &y.impulse.mu_t},
                                                 {&x.impulse.mu_z, &y.impulse.mu_z},
                                                 {&x.impulse.gir, &y.impulse.gir},
                                                 {&x.impulse.cir, &y.impulse.cir},
                                                 {&x.impulse.mu_t_critical, &y.impulse.mu_t_critical},
                                                 {&x.impulse.mu_z_critical, &y.impulse.mu_z_critical}};
      for (auto& pr : pairs) {
        REQUIRE(pr[0]->has_value() == pr[1]->has_value());
        if (!pr[0]->has_value()) continue;
        const double mu = **pr[1];
        R.add(std::abs(**pr[0] - mu) / (eps * scale * (1 + std::abs(mu)) * (1 + std::abs(mu))), n);
      }
    }
  }
  std::cout << fmt::format("engine agreement over {} cases (max, rms in the units shown; worst case index):\n", cases);
  for (const Worst* w : {&K, &P, &V, &E, &R})
    std::cout << fmt::format("  {:<72} max {:8.3f}  rms {:7.3f}  case {}\n", w->quantity, w->max,
                             std::sqrt(w->sum_sq / w->count), w->case_index);
  // Bounds. In these units each engine's forward error is about the number of roundings on its path
  // that do not cancel: a handful for K (products and sums of O(1) terms after the inverse, whose own
  // error the cond J factor carries), one solve or closed form more for the impulses, states and energy,
  // and for the ratios a quotient whose first-order error (dN - mu dD) / D is what (1 + |mu|)^2 bounds.
  // The difference of two engines is at most the sum: 16 units for K, 32 for the rest.
  // Every collision is compared (nothing skips one); a ratio is compared where the strategy reports it
  // (pc-crash and wach report mu, gir and cir; brach its given or critical mu_t, mu_z and the critical
  // values), so the ratio tally depends on the strategies drawn.
  CHECK(K.count == cases);
  CHECK(P.count == 4 * cases);
  CHECK(R.count >= 3 * 4 * cases);  // at least three per result: mu, gir, cir or brach's two and a critical
  CHECK(K.max <= 16);
  CHECK(P.max <= 32);
  CHECK(V.max <= 32);
  CHECK(E.max <= 32);
  CHECK(R.max <= 32);
}

}  // namespace check_engines
