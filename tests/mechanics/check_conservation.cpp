// Conservation laws every impulse law must obey, checked from the post-impact states of seeded random
// collisions under every strategy, Stronge's integration among them.
#include <catch2/catch.hpp>

#include "support.hpp"

namespace check_conservation {

using namespace impact3d;
using namespace impact3d::test;

TEST_CASE("linear momentum of the pair is conserved by every strategy", "[conservation]") {
  std::mt19937_64 g(31);
  int checked = 0;
  for (int n = 0; n < 200; ++n) {
    const Scene<double> s = random_scene(g);
    const Analysis<double> a = analyze(s, every_floating_strategy(0.4));
    const V3 before = s.body[0].mass * s.body[0].v_W + s.body[1].mass * s.body[1].v_W;
    const double scale = s.body[0].mass * s.body[0].v_W.norm() + s.body[1].mass * s.body[1].v_W.norm();
    for (const auto& sol : a.solutions) {
      const V3 after = sol.after[0].mass * sol.after[0].v_W + sol.after[1].mass * sol.after[1].v_W;
      // m (v + P/m) rounds once in the division and once in the sum: a few eps of the momenta and |P|.
      CHECK((after - before).cwiseAbs().maxCoeff() <= 8 * eps * (scale + 2 * sol.P_W.norm()));
    }
    ++checked;
  }
  CHECK(checked == 200);  // nothing in the loop skips a case
}

TEST_CASE("each vehicle's angular momentum about its impulse centre is conserved", "[conservation]") {
  std::mt19937_64 g(32);
  int checked = 0;
  for (int n = 0; n < 200; ++n) {
    const Scene<double> s = random_scene(g);
    const Analysis<double> a = analyze(s, every_floating_strategy(0.7));
    for (const auto& sol : a.solutions)
      for (int i = 0; i < 2; ++i) {
        const auto& b = s.body[i];
        const V3 H0 = angular_momentum_about_Ic_W(b), H1 = angular_momentum_about_Ic_W(sol.after[i]);
        // Terms of size |J w| and |r| m |v| (and |r||P| for the change) each rounded a few times.
        const double scale = (b.J_B * sol.after[i].w_B).norm() + (b.J_B * b.w_B).norm() +
                             b.p_CgIc_B.norm() * (b.mass * (b.v_W.norm() + sol.after[i].v_W.norm()) + sol.P_W.norm());
        CHECK((H1 - H0).cwiseAbs().maxCoeff() <= 32 * eps * scale);
      }
    ++checked;
  }
  CHECK(checked == 200);  // nothing in the loop skips a case
}

TEST_CASE("the energy change equals -P . (V_ri + V_rf) / 2", "[conservation]") {
  // Work of an impulse on two rigid bodies at the impulse centre: dT = -P . (V_ri + V_rf) / 2, computed
  // here from the relative velocities, against the difference of kinetic energies of the states.
  std::mt19937_64 g(33);
  int checked = 0;
  for (int n = 0; n < 200; ++n) {
    const Scene<double> s = random_scene(g);
    const Analysis<double> a = analyze(s, every_floating_strategy(0.3));
    for (const auto& sol : a.solutions) {
      const double work = -sol.impulse.P_C.dot(sol.V_ri + sol.V_rf) / 2;
      // Both sides are differences of energies of size energy_before (and |P| |V|), a few eps each,
      // the relative velocity carrying the solve's kappa.
      const double tol = rounding::relative_bound(a.kappa) * (sol.energy_before + sol.impulse.P_C.norm() * velocity_scale(s));
      CHECK(std::abs(-sol.energy_loss - work) <= tol);
    }
    ++checked;
  }
  CHECK(checked == 200);  // nothing in the loop skips a case
}

}  // namespace check_conservation
