// |(a, b)|, the length of a vector in a plane, for the few each solve takes. At double, while neither
// square can overflow and the larger cannot underflow (the larger magnitude in [2^-450, 2^500]), it is
// the root of the sum of squares: four roundings, each of u = eps/2, put it within eps (1 + eps/4) of
// the exact length (tests/mechanics/check_planar_norm.cpp; a smaller square that underflows is under 2^-120 of
// the sum). glibc's hypot is closer (about half that) at several times the cost, a tenth of a lean
// pc-crash solve (BENCHMARKS.md); the rounding bounds count one eps for either. A build that fuses
// the sum into a multiply-add rounds once less. Outside that range, and at every other scalar, it is
// std::hypot, with its scaling and its infinities and NaN.
#pragma once

#include <cmath>
#include <type_traits>

namespace impact3d {

template <typename Scalar>
Scalar planar_norm(const Scalar& a, const Scalar& b) {
  if constexpr (std::is_same_v<Scalar, double>) {
    // Not std::fmax, which is a call into libm. With one NaN, `larger` is the other magnitude or NaN:
    // the root is then NaN, or hypot has the NaN and the other (inf when that is infinite), as it must.
    const double fa = std::fabs(a), fb = std::fabs(b);
    const double larger = fa > fb ? fa : fb;
    if (larger >= 0x1p-450 && larger <= 0x1p500) return std::sqrt(a * a + b * b);
  }
  using std::hypot;
  return hypot(a, b);
}

}  // namespace impact3d
