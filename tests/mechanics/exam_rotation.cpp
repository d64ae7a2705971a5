// Rotations, named known answers:
//  - sin and cos of whole quarter turns are exactly 0 and +-1 (sin(k 90 deg), cos(k 90 deg) for integer
//    k), so sin_cos_deg, which reduces degrees before converting, must return them with no rounding;
//  - the contact frame built from a normal and a tangent vector is the one the case-format contract
//    defines: n = normal / |normal|, t = the tangent made orthogonal to n, z = n x t (a rotation).
#include <catch2/catch.hpp>
#include <cmath>

#include "support.hpp"

namespace exam_rotation {

using namespace impact3d;
using namespace impact3d::test;

TEST_CASE("sin_cos_deg is exact at quarter turns", "[rotation]") {
  // Exact values: 450 = 360 + 90, 3600 = 10 turns, -3690 = -10 turns - 90.
  const double angles[] = {0, 90, 180, 270, 360, -90, -180, 450, 3600, -3690};
  const double s_ref[] = {0, 1, 0, -1, 0, -1, 0, 1, 0, -1};
  const double c_ref[] = {1, 0, -1, 0, 1, 0, -1, 0, 1, 0};
  for (int k = 0; k < 10; ++k) {
    INFO(angles[k] << " deg");
    const auto sc = sin_cos_deg(angles[k]);
    CHECK(sc.s == s_ref[k]);
    CHECK(sc.c == c_ref[k]);
  }
}

TEST_CASE("contact frame from vectors is right-handed and keeps the normal", "[rotation]") {
  // Known answer from the contract's definition (case-format.md, "Contact frame"): the columns of R are
  // n, t, z with n = normal / |normal|, t in the plane of normal and tangent on the tangent's side, and
  // R a rotation. Each is a few roundings (a normalisation, a Gram-Schmidt step, a cross product) of
  // O(1) values, hence a few eps.
  const V3 normal(0.3, -2.0, 0.4), tangent(1.0, 0.5, 0.2);
  const M3 R = contact_frame_from_vectors(normal, tangent);
  CHECK((R.transpose() * R - M3::Identity()).cwiseAbs().maxCoeff() <= 8 * eps);
  CHECK(std::abs(R.determinant() - 1.0) <= 8 * eps);
  CHECK((R.col(0) - normal.normalized()).norm() <= 4 * eps);
  CHECK(std::abs(R.col(1).dot(normal)) <= 8 * eps * normal.norm());
  // The tangent stays in the plane of the given normal and tangent.
  CHECK(std::abs(R.col(1).dot(normal.cross(tangent).normalized())) <= 8 * eps);
  CHECK(R.col(1).dot(tangent) > 0);
}

}  // namespace exam_rotation
