// Post-impact reporting on random collisions: the swerve against the final sliding rotated here.
#include <catch2/catch.hpp>
#include <cmath>

#include "plane_closed_forms.hpp"

namespace check_post_impact {

using namespace impact3d;
using namespace impact3d::test;

TEST_CASE("swerve: the angle and the across-component of the final sliding", "[swerve]") {
  std::mt19937_64 g(111);
  int checked = 0;
  for (int n = 0; n < 200; ++n) {
    const Scene<double> s = random_scene(g);
    const auto a = analyze(s, {PcCrash<double>{0.1}});
    const auto& sol = a.solutions[0];
    REQUIRE(sol.swerve_speed);
    // Rotate the initial sliding onto +t: the final sliding's components are then (along, across).
    const auto [along, across] = plane_components(std::atan2(sol.V_ri.z(), sol.V_ri.y()), sol.V_rf);
    // Both sides rotate the same post-impact velocity, whose error is the solve's (eps kappa scale);
    // an angle then errs by that over the final sliding speed (radians), twice for two evaluations.
    const double vtol = rounding::velocity_roundoff(s, a.kappa);
    CHECK(std::abs(*sol.swerve_speed - across) <= vtol);
    REQUIRE(sol.swerve_deg);
    const double deg_tol = 2 * vtol / sol.sliding_after * 180 / M_PI;
    // The angle off the line of the initial sliding: a reversal along it is no swerve.
    CHECK(std::abs(*sol.swerve_deg - std::atan2(across, std::abs(along)) * 180 / M_PI) <= deg_tol);
    REQUIRE(sol.sliding_along);
    CHECK(std::abs(*sol.sliding_along - along) <= vtol);
    REQUIRE(sol.reversed);
    if (std::abs(along) > 2 * vtol) CHECK(*sol.reversed == (along < 0));
    ++checked;
  }
  CHECK(checked == 200);  // nothing in the loop skips a case
}

TEST_CASE("the figure's volume letters lie in the volumes the post-impact state names", "[figures][volumes]") {
  std::mt19937_64 g(4242);
  int checked = 0;
  for (int n = 0; n < 200; ++n) {
    const Scene<double> s = random_scene(g);
    const auto a = analyze(s, {PcCrash<double>{0.4}});
    const auto& p = a.problem();
    const auto points = volume_points(a.space, a.space.P_max_loss.norm() / 3);
    REQUIRE(points.size() == 4);
    std::string letters;
    for (const auto& v : points) {
      // The post-impact relative velocity of that impulse (eq 9) and post_impact.hpp's rules: separating
      // where V_rf,n < 0 (A, B), the t sliding continued where V_rf,t keeps V_ri,t's sign (A, D).
      const Vec3<double> V_rf = p.V_ri - p.K * v.P / p.m_prime;
      const bool separating = V_rf.x() < 0, continued = V_rf.y() * p.V_ri.y() > 0;
      const char want = separating ? (continued ? 'A' : 'B') : (continued ? 'D' : 'C');
      CHECK(v.letter == want);
      letters += v.letter;
      ++checked;
    }
    std::sort(letters.begin(), letters.end());
    CHECK(letters == "ABCD");
  }
  CHECK(checked == 800);
}

}  // namespace check_post_impact
