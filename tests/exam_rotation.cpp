// Rotations: exact values at quarter turns, and the contact frame built from given vectors.
#include <catch2/catch.hpp>
#include <cmath>

#include "support.hpp"

using namespace impact3d;
using namespace impact3d::test;

TEST_CASE("sin_cos_deg is exact at quarter turns", "[rotation]") {
  const double angles[] = {0, 90, 180, 270, 360, -90, -180, 450, 3600, -3690};
  const double s_ref[] = {0, 1, 0, -1, 0, -1, 0, 1, 0, -1};
  const double c_ref[] = {1, 0, -1, 0, 1, 0, -1, 0, 1, 0};
  for (int k = 0; k < 10; ++k) {
    const auto sc = sin_cos_deg(angles[k]);
    CHECK(sc.s == s_ref[k]);
    CHECK(sc.c == c_ref[k]);
  }
}

TEST_CASE("contact frame from vectors is right-handed and keeps the normal", "[rotation]") {
  const V3 normal(0.3, -2.0, 0.4), tangent(1.0, 0.5, 0.2);
  const M3 R = contact_frame_from_vectors(normal, tangent);
  CHECK((R.transpose() * R - M3::Identity()).cwiseAbs().maxCoeff() <= 8 * eps);
  CHECK(R.determinant() == Approx(1.0).margin(8 * eps));
  CHECK((R.col(0) - normal.normalized()).norm() <= 4 * eps);
  CHECK(std::abs(R.col(1).dot(normal)) <= 8 * eps * normal.norm());
  // The tangent stays in the plane of the given normal and tangent.
  CHECK(std::abs(R.col(1).dot(normal.cross(tangent).normalized())) <= 8 * eps);
  CHECK(R.col(1).dot(tangent) > 0);
}
