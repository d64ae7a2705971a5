// The sine and cosine of one angle in radians, for rotation.hpp. A scalar whose library computes both
// at once specializes this (multiprecision.hpp: MPFR's two correctly rounded results, from Arb's
// enclosures where they decide them, numeric/scalar/src/mpfr_sin_cos.cpp).
#pragma once

#include <cmath>

namespace impact3d {

template <typename Scalar>
struct SinCosRadians {
  static void of(const Scalar& rad, Scalar& s, Scalar& c) {
    using std::cos;
    using std::sin;
    s = sin(rad);
    c = cos(rad);
  }
};

}  // namespace impact3d
