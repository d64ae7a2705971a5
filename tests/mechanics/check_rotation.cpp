// Rotations at seeded random angles against the library's sin and cos and the paper's Appendix A
// transformation, typed in here. The exact quarter turns and the frame from vectors are in
// exam_rotation.cpp.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include <boost/math/constants/constants.hpp>

#include "impact3d/scalar/multiprecision.hpp"
#include "support.hpp"

namespace check_rotation {

using namespace impact3d;
using namespace impact3d::test;

TEST_CASE("sin_cos_deg agrees with sin and cos of the angle in radians", "[rotation]") {
  std::mt19937_64 g(11);
  std::uniform_real_distribution<double> u(-720, 720);
  int checked = 0;
  for (int k = 0; k < 2000; ++k) {
    const double deg = u(g);
    const auto sc = sin_cos_deg(deg);
    // The reference rounds deg * pi / 180 once at |angle| up to 4 pi, an absolute error of a few eps
    // times 4 pi; the reduced form rounds less. 32 eps covers both.
    const double rad = deg * M_PI / 180;
    CHECK(std::abs(sc.s - std::sin(rad)) <= 32 * eps);
    CHECK(std::abs(sc.c - std::cos(rad)) <= 32 * eps);
    ++checked;
  }
  CHECK(checked == 2000);  // nothing in the loop skips a case
}

// Appendix A: heading gamma, attitude theta, roll phi.
M3 paper_T(double gamma_deg, double theta_deg, double phi_deg) {
  const double g = gamma_deg * M_PI / 180, t = theta_deg * M_PI / 180, p = phi_deg * M_PI / 180;
  using std::cos;
  using std::sin;
  M3 T;
  T << cos(g) * cos(t), sin(g) * cos(t), -sin(t),  //
      -sin(g) * cos(p) + cos(g) * sin(t) * sin(p), cos(g) * cos(p) + sin(g) * sin(t) * sin(p), cos(t) * sin(p),  //
      sin(g) * sin(p) + cos(g) * sin(t) * cos(p), -cos(g) * sin(p) + sin(g) * sin(t) * cos(p), cos(t) * cos(p);
  return T;
}

TEST_CASE("T_i of a level vehicle is the paper's T with gamma = normal_yaw - yaw", "[rotation]") {
  std::mt19937_64 g(12);
  std::uniform_real_distribution<double> u(-180, 180), small(-40, 40);
  int checked = 0;
  for (int k = 0; k < 500; ++k) {
    const double yaw = u(g), nyaw = u(g), npitch = small(g), roll = small(g);
    Scene<double> s;
    s.body[0].R_WB = rotation_zyx_deg(yaw, 0.0, 0.0);
    s.R_WC = rotation_zyx_deg(nyaw, npitch, roll);
    const M3 T = R_CB(s, 0), ref = paper_T(nyaw - yaw, npitch, roll);
    // Both are products of three rotations built from sines and cosines accurate to a few eps.
    CHECK((T - ref).cwiseAbs().maxCoeff() <= 32 * eps);
    ++checked;
  }
  CHECK(checked == 500);  // nothing in the loop skips a case
}

TEST_CASE("rotation_zyx_deg_closed equals rotation_zyx_deg entry by entry, but for the sign of zeros", "[rotation]") {
  // The product of three matrices adds zero terms the closed form leaves out: x + 0 and x agree unless
  // x is -0. Compared as values (-0 == 0), at random angles and at every combination of quarter turns,
  // half-quarter turns and tiny angles.
  std::mt19937_64 g(17);
  std::uniform_real_distribution<double> u(-400, 400);
  const double special[] = {0, -0.0, 90, -90, 180, -180, 270, 45, 30, 360, 1e-300, -1e-300, 720, -45};
  int compared = 0, differing = 0;
  auto check = [&](double a, double b, double c) {
    ++compared;
    differing += rotation_zyx_deg_closed(a, b, c) != rotation_zyx_deg(a, b, c);
  };
  for (double a : special)
    for (double b : special)
      for (double c : special) check(a, b, c);
  for (int i = 0; i < 100000; ++i) {
    const double c = u(g), b = u(g), a = u(g);  // the last first, as draw3 (support.hpp)
    check(a, b, c);
  }
  CHECK(differing == 0);
  CHECK(compared == 14 * 14 * 14 + 100000);
}

// SinCosRadians<float100> takes Arb's enclosures of both and keeps the MPFR number their ends round to,
// leaving MPFR to decide where they round apart and for zero, tiny, infinite and NaN arguments
// (numeric/scalar/src/mpfr_sin_cos.cpp). Boost's sin and cos are mpfr_sin and mpfr_cos, correctly rounded, so
// the two must be the same numbers, bit for bit, sign of zero included.
namespace {
// The same number, the sign of zero included (-0 == 0 would pass a sine of the wrong sign), or both NaN.
bool same_number(const mp::float100& a, const mp::float100& b) {
  return (a == b && signbit(a) == signbit(b)) || (isnan(a) && isnan(b));
}
}  // namespace

TEST_CASE("at 100 digits SinCosRadians gives Boost's sin and cos bit for bit", "[rotation]") {
  using F = mp::float100;
  std::mt19937_64 g(12);
  std::uniform_real_distribution<double> u(-3.2, 3.2);
  int checked = 0, mismatched = 0;
  auto check = [&](const F& rad) {
    F s, c;
    SinCosRadians<F>::of(rad, s, c);
    const F bs = boost::multiprecision::sin(rad), bc = boost::multiprecision::cos(rad);
    if (!same_number(s, bs) || !same_number(c, bc)) {
      ++mismatched;
      UNSCOPED_INFO("at " << rad.str(110, std::ios_base::scientific));
    }
    ++checked;
  };
  for (int k = 0; k < 20000; ++k) check(F(u(g)) / F(3));  // not a double: every digit of the 100 in play
  const F pi = boost::math::constants::pi<F>();
  for (const F& x : {F(0), F(-0.0), F(1), F(-1), pi / 4, -pi / 4, pi / 2, pi, F(1e6), F(-1e30), ldexp(F(1), -999),
                     ldexp(F(-1), -1001), ldexp(F(1), -1100), F(1) / F(3) * ldexp(F(1), -500)})
    check(x);
  check(std::numeric_limits<F>::infinity());
  check(std::numeric_limits<F>::quiet_NaN());
  CHECK(mismatched == 0);
  CHECK(checked == 20000 + 14 + 2);
}

// MPFR lets a result be the argument itself; so does SinCosRadians<float100>, whether Arb's enclosures
// decide (a third) or MPFR computes after all (pi / 2, whose cosine Arb encloses too widely).
TEST_CASE("at 100 digits SinCosRadians takes its argument in place of either result", "[rotation]") {
  using F = mp::float100;
  const F pi = boost::math::constants::pi<F>();
  int checked = 0;
  for (const F& x : {F(1) / F(3), pi / 2, F(0), F(-0.0)}) {
    F s = x, c;
    SinCosRadians<F>::of(s, s, c);
    CHECK(same_number(s, boost::multiprecision::sin(x)));
    CHECK(same_number(c, boost::multiprecision::cos(x)));
    F s2, c2 = x;
    SinCosRadians<F>::of(c2, s2, c2);
    CHECK(same_number(s2, boost::multiprecision::sin(x)));
    CHECK(same_number(c2, boost::multiprecision::cos(x)));
    ++checked;
  }
  CHECK(checked == 4);
}

}  // namespace check_rotation
