// The normal constraint shared by every strategy, on seeded random collisions: V_rnf = -e V_rni.
#include <catch2/catch.hpp>

#include "support.hpp"

namespace check_restitution {

using namespace impact3d;
using namespace impact3d::test;

TEST_CASE("post-impact normal relative velocity is -eps times the initial one, every strategy", "[restitution]") {
  std::mt19937_64 g(41);
  int checked = 0;
  for (int n = 0; n < 300; ++n) {
    const Scene<double> s = random_scene(g);
    const Analysis<double> a = analyze(s, every_strategy(0.5));
    for (const auto& sol : a.solutions) {
      // V_rf comes from the post-impact point velocities, a difference of velocities of size
      // velocity_scale after a solve of condition kappa(K).
      const double tol = rounding::velocity_roundoff(s, a.kappa);
      CHECK(std::abs(sol.V_rf.x() + s.restitution * sol.V_ri.x()) <= tol);
    }
    ++checked;
  }
  CHECK(checked == 300);  // nothing in the loop skips a case
}

}  // namespace check_restitution
