// Physical results do not depend on the world's heading or on which vehicle is called 1: seeded random
// collisions solved as given and turned or relabelled.
#include <catch2/catch.hpp>

#include "support.hpp"

namespace check_invariance {

using namespace impact3d;
using namespace impact3d::test;

namespace {

// Compare two solutions that describe the same physics; `flip_z` when the contact z axis is reversed.
void check_same_physics(const Solution<double>& a, const Solution<double>& b, bool flip_z, bool swapped,
                        double tol_rel) {
  CHECK(a.impulse.regime == b.impulse.regime);
  const V3 Pa = a.impulse.P_C, Pb = b.impulse.P_C;
  const double sz = flip_z ? -1 : 1;
  const double Pscale = Pa.norm() * tol_rel;
  CHECK(std::abs(Pa.x() - Pb.x()) <= Pscale);
  CHECK(std::abs(Pa.y() - Pb.y()) <= Pscale);
  CHECK(std::abs(Pa.z() - sz * Pb.z()) <= Pscale);
  const double Vscale = a.V_ri.norm() * tol_rel;
  CHECK(std::abs(a.V_rf.x() - b.V_rf.x()) <= Vscale);
  CHECK(std::abs(a.V_rf.y() - b.V_rf.y()) <= Vscale);
  CHECK(std::abs(a.V_rf.z() - sz * b.V_rf.z()) <= Vscale);
  CHECK(a.energy_loss == Approx(b.energy_loss).epsilon(tol_rel).margin(a.energy_before * tol_rel));
  CHECK(std::abs(a.sliding_after - b.sliding_after) <= Vscale);
  for (int i = 0; i < 2; ++i) {
    const int j = swapped ? 1 - i : i;
    CHECK((a.after[i].w_B - b.after[j].w_B).norm() <= tol_rel * (1 + a.after[i].w_B.norm()));
    CHECK(a.change[i].dv == Approx(b.change[j].dv).epsilon(tol_rel).margin(Vscale));
  }
  if (a.impulse.mu) CHECK(*a.impulse.mu == Approx(*b.impulse.mu).epsilon(tol_rel).margin(tol_rel));
}

}  // namespace

TEST_CASE("turning the whole scene about world z changes no physical result", "[invariance]") {
  std::mt19937_64 g(101);
  std::uniform_real_distribution<double> u(-180, 180);
  int checked = 0;
  for (int n = 0; n < 150; ++n) {
    const Scene<double> s = random_scene(g);
    const double turn = u(g);
    const M3 Rz = rotation_zyx_deg(turn, 0.0, 0.0);
    Scene<double> r = s;
    for (auto& b : r.body) {
      b.R_WB = Rz * b.R_WB;
      b.v_W = Rz * b.v_W;
    }
    r.R_WC = Rz * s.R_WC;
    const auto strategies = every_strategy(0.4);
    const auto a = analyze(s, strategies), b = analyze(r, strategies);
    // Rotating the inputs rounds each by an eps; the solves amplify that by kappa(K).
    const double tol = 4 * rounding::agreement_bound(a.kappa);
    for (std::size_t k = 0; k < strategies.size(); ++k) {
      check_same_physics(a.solutions[k], b.solutions[k], false, false, tol);
      CHECK((Rz * a.solutions[k].P_W - b.solutions[k].P_W).norm() <= tol * a.solutions[k].P_W.norm());
      CHECK((Rz * a.solutions[k].after[0].v_W - b.solutions[k].after[0].v_W).norm() <= tol * velocity_scale(s));
    }
    ++checked;
  }
  CHECK(checked == 150);  // nothing in the loop skips a case
}

TEST_CASE("swapping which vehicle is called 1, with the normal reversed, changes no physical result", "[invariance]") {
  std::mt19937_64 g(102);
  int checked = 0;
  for (int n = 0; n < 150; ++n) {
    const Scene<double> s = random_scene(g);
    Scene<double> w = s;
    w.body = {s.body[1], s.body[0]};
    // n -> -n and t -> -t keep the frame right-handed with z unchanged; then P_z and V_rz change sign.
    w.R_WC = s.R_WC * V3(-1, -1, 1).asDiagonal();
    const std::vector<Strategy<double>> as = {PcCrash<double>{0.3}, PcCrash<double>{5.0}, Wach<double>{0.3, WachLimit::cir},
                                              Wach<double>{9.0, WachLimit::gir}, Brach<double>{0.2, -0.1},
                                              Brach<double>{std::nullopt, std::nullopt}};
    const std::vector<Strategy<double>> bs = {PcCrash<double>{0.3}, PcCrash<double>{5.0}, Wach<double>{0.3, WachLimit::cir},
                                              Wach<double>{9.0, WachLimit::gir}, Brach<double>{0.2, 0.1},
                                              Brach<double>{std::nullopt, std::nullopt}};
    const auto a = analyze(s, as), b = analyze(w, bs);
    const double tol = 4 * rounding::agreement_bound(a.kappa);
    for (std::size_t k = 0; k < as.size(); ++k) {
      check_same_physics(a.solutions[k], b.solutions[k], true, true, tol);
      CHECK((a.solutions[k].after[0].v_W - b.solutions[k].after[1].v_W).norm() <= tol * velocity_scale(s));
    }
    ++checked;
  }
  CHECK(checked == 150);  // nothing in the loop skips a case
}

}  // namespace check_invariance
