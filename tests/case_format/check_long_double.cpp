// The same collisions (seeded random ones, and the bundled examples) at double and long double: double's
// results must sit within its own rounding bound of the wider type's (a higher precision as the
// independent value; `impact3d verify` takes every precision to 100 digits).
#include <catch2/catch.hpp>

#include "case_files.hpp"

namespace check_long_double {

using namespace impact3d;
using namespace impact3d::test;

namespace {

using LD = long double;

Scene<LD> widen(const Scene<double>& s) {
  Scene<LD> w;
  for (int i = 0; i < 2; ++i) {
    const auto& b = s.body[i];
    w.body[i] = {LD(b.mass), b.J_B.cast<LD>(), b.R_WB.cast<LD>(), b.v_W.cast<LD>(), b.w_B.cast<LD>(), b.p_CgIc_B.cast<LD>()};
  }
  w.R_WC = s.R_WC.cast<LD>();
  w.restitution = s.restitution;
  return w;
}

std::vector<Strategy<LD>> widen(const std::vector<Strategy<double>>& st) {
  std::vector<Strategy<LD>> out;
  for (const auto& s : st) {
    if (auto* p = std::get_if<PcCrash<double>>(&s)) out.push_back(PcCrash<LD>{p->mu});
    else if (auto* w = std::get_if<Wach<double>>(&s)) out.push_back(Wach<LD>{w->mu, w->limit});
    else {
      const auto& b = std::get<Brach<double>>(s);
      Brach<LD> bl;
      if (b.mu_t) bl.mu_t = *b.mu_t;
      if (b.mu_z) bl.mu_z = *b.mu_z;
      out.push_back(bl);
    }
  }
  return out;
}

void compare(const Analysis<double>& d, const Analysis<LD>& l, double scale_V) {
  // Identical inputs (widening is exact), so the difference is double's rounding: eps kappa(K) per
  // solve; the impulse-plane strategies do two dependent solves, hence 64.
  const double tol = 64 * eps * d.kappa;
  CHECK((d.K.cast<LD>() - l.K).norm() <= LD(tol) * l.K.norm());
  for (std::size_t k = 0; k < d.solutions.size(); ++k) {
    const auto& a = d.solutions[k];
    const auto& b = l.solutions[k];
    CHECK(a.impulse.regime == b.impulse.regime);
    CHECK((a.impulse.P_C.cast<LD>() - b.impulse.P_C).norm() <= LD(tol) * b.impulse.P_C.norm());
    CHECK((a.V_rf.cast<LD>() - b.V_rf).norm() <= LD(tol * scale_V));
    CHECK(std::abs(LD(a.energy_loss) - b.energy_loss) <= LD(tol) * b.energy_before);
  }
}

}  // namespace

TEST_CASE("double agrees with long double within its rounding bound: random cases", "[precision]") {
  std::mt19937_64 g(121);
  int checked = 0;
  for (int n = 0; n < 200; ++n) {
    const Scene<double> s = random_scene(g);
    const auto st = every_strategy(0.45);
    compare(analyze(s, st), analyze(widen(s), widen(st)), velocity_scale(s));
    ++checked;
  }
  CHECK(checked == 200);  // nothing in the loop skips a case
}

TEST_CASE("double agrees with long double within its rounding bound: examples read at each precision", "[precision]") {
  for (const char* name : {"fig8_side_impact.json", "offset_frontal.json", "override_pickup_into_sedan_rear.json",
                           "us_pickup_into_sedan.json"}) {
    INFO(name);
    const case_format::CaseSpec c = load_spec(example(name));
    const Scene<double> s = case_format::to_scene<double>(c);
    // Each precision converts the decimal text itself, so inputs differ by double's input rounding.
    compare(analyze(s, case_format::to_strategies<double>(c)), analyze(case_format::to_scene<LD>(c), case_format::to_strategies<LD>(c)),
            velocity_scale(s));
  }
}

}  // namespace check_long_double
