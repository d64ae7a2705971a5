// Planes and lines cut to a figure's box (cli/library/src/figures/box_clip.cpp), on cuts of the unit cube known
// by hand: a plane parallel to a face gives the face's square, x + y + z = 3/2 the regular hexagon
// through the midpoints of six edges, a plane past a corner nothing; the main diagonal's line runs
// corner to corner.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>

#include "impact3d/cli/figures/box_clip.hpp"

namespace exam_box_clip {

using impact3d::cli::Box;
using impact3d::cli::P3;

namespace {
const Box kUnit{{0, 0, 0}, {1, 1, 1}};
bool same(const P3& a, const P3& b) { return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]) <= 1e-15; }
bool has(const std::vector<P3>& poly, const P3& q) {
  return std::any_of(poly.begin(), poly.end(), [&](const P3& p) { return same(p, q); });
}
}  // namespace

TEST_CASE("a plane parallel to a face cuts the cube in that square", "[box_clip]") {
  const auto poly = impact3d::cli::plane_in_box({0, 0, 1}, 0.5, kUnit);
  REQUIRE(poly.size() == 4);
  for (const P3& q : {P3{0, 0, 0.5}, P3{1, 0, 0.5}, P3{0, 1, 0.5}, P3{1, 1, 0.5}}) CHECK(has(poly, q));
  // In order around it: consecutive vertices are a side (length 1) apart, never a diagonal.
  for (std::size_t i = 0; i < 4; ++i) {
    const P3 &a = poly[i], &b = poly[(i + 1) % 4];
    CHECK(std::fabs(std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]) - 1) <= 1e-15);
  }
}

TEST_CASE("x + y + z = 3/2 cuts the cube in a regular hexagon", "[box_clip]") {
  const auto poly = impact3d::cli::plane_in_box({1, 1, 1}, 1.5, kUnit);
  REQUIRE(poly.size() == 6);
  for (const P3& q : {P3{1, 0.5, 0}, P3{0.5, 1, 0}, P3{0, 1, 0.5}, P3{0, 0.5, 1}, P3{0.5, 0, 1}, P3{1, 0, 0.5}}) CHECK(has(poly, q));
  for (std::size_t i = 0; i < 6; ++i) {  // sides of sqrt(2)/2
    const P3 &a = poly[i], &b = poly[(i + 1) % 6];
    CHECK(std::fabs(std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]) - std::sqrt(0.5)) <= 4e-16);
  }
}

TEST_CASE("a plane that misses the cube, or touches only a corner, gives nothing", "[box_clip]") {
  CHECK(impact3d::cli::plane_in_box({1, 1, 1}, 3.5, kUnit).empty());
  CHECK(impact3d::cli::plane_in_box({1, 1, 1}, 3, kUnit).empty());
}

TEST_CASE("a line is cut to the cube", "[box_clip]") {
  const auto diagonal = impact3d::cli::line_in_box({0.5, 0.5, 0.5}, {1, 1, 1}, kUnit);
  REQUIRE(diagonal);
  CHECK(same((*diagonal)[0], {0, 0, 0}));
  CHECK(same((*diagonal)[1], {1, 1, 1}));
  CHECK_FALSE(impact3d::cli::line_in_box({2, 2, 2}, {1, 0, 0}, kUnit));
  const auto along_x = impact3d::cli::line_in_box({-5, 0.25, 0.75}, {2, 0, 0}, kUnit);
  REQUIRE(along_x);
  CHECK(same((*along_x)[0], {0, 0.25, 0.75}));
  CHECK(same((*along_x)[1], {1, 0.25, 0.75}));
}

}  // namespace exam_box_clip
