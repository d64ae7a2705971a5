// Rotations as the case-format contract defines them: active, intrinsic z-y'-x'', angles in degrees.
#pragma once

#include <cmath>

#include "impact3d/scalar/exact.hpp"
#include "impact3d/scalar/sin_cos_radians.hpp"
#include "impact3d/scalar/types.hpp"

namespace impact3d {

template <typename Scalar>
struct SinCos {
  Scalar s, c;
};

// sin and cos of an angle in degrees, reduced by quarter turns first so that multiples of 90 degrees
// give exact 0 and +-1 (cos(pi/2) in floating point is 6e-17, which would invent a vertical sliding
// velocity in every level, right-angle case).
template <typename Scalar>
struct DegreeConstants {
  Scalar quarter{90}, half = ratio<Scalar>(1, 2), fourth = ratio<Scalar>(1, 4);
};
template <typename Scalar>
struct RadianConstants {
  Scalar pi_ = pi<Scalar>(), straight{180};
};

// Built once per type: at 100 digits each construction is an MPFR call and 1/2 a division. A ball
// builds them each time, at its thread's working precision; so does a dual: Eigen's AutoDiffScalar resizes a constant's empty derivatives in place, so
// a kept one would carry one sensitivity's number of inputs into the next.
template <typename Constants, typename Scalar>
decltype(auto) constants() {
  if constexpr (is_dual_v<Scalar> || is_enclosure_v<Scalar>) {  // a ball's pi at the thread's working precision
    return Constants{};
  } else {
    static const Constants kept;
    return (kept);
  }
}

template <typename Scalar>
SinCos<Scalar> sin_cos_deg(const Scalar& deg) {
  // turns / 4 as turns * 1/4 is the same number (a power of two).
  const auto& [quarter, half, fourth] = constants<DegreeConstants<Scalar>, Scalar>();
  Scalar turns = floor_of(Scalar(deg / quarter + half));
  Scalar rest = deg - turns * quarter;  // in [-45, 45]
  Scalar q = turns - Scalar(4) * floor_of(Scalar(turns * fourth));
  Scalar s(0), c(1);
  if constexpr (is_exact_v<Scalar>) {
    if (rest != Scalar(0)) throw Irrational("an angle that is not a multiple of 90 degrees (its sine and cosine)");
  } else {
    const auto& [pi_, straight] = constants<RadianConstants<Scalar>, Scalar>();
    const Scalar rad = rest * pi_ / straight;
    // A dual still needs the derivative at a multiple of 90 degrees (its value there is exact anyway).
    if (rest != Scalar(0) || is_dual_v<Scalar>) SinCosRadians<Scalar>::of(rad, s, c);
  }
  // The quarter turn q by selection rather than branches (random angles would mispredict them):
  // odd q exchanges sine and cosine, q >= 2 negates the sine, q = 1 or 2 the cosine.
  const bool odd = q == Scalar(1) || q == Scalar(3), negate_s = q >= Scalar(2), negate_c = q == Scalar(1) || q == Scalar(2);
  const Scalar s_out = odd ? c : s, c_out = odd ? s : c;
  return {negate_s ? Scalar(-s_out) : s_out, negate_c ? Scalar(-c_out) : c_out};
}

template <typename Scalar>
Mat3<Scalar> rot_x(const SinCos<Scalar>& a) {
  Mat3<Scalar> r;
  r << Scalar(1), Scalar(0), Scalar(0),  //
      Scalar(0), a.c, -a.s,              //
      Scalar(0), a.s, a.c;
  return r;
}

template <typename Scalar>
Mat3<Scalar> rot_y(const SinCos<Scalar>& a) {
  Mat3<Scalar> r;
  r << a.c, Scalar(0), a.s,         //
      Scalar(0), Scalar(1), Scalar(0),  //
      -a.s, Scalar(0), a.c;
  return r;
}

template <typename Scalar>
Mat3<Scalar> rot_z(const SinCos<Scalar>& a) {
  Mat3<Scalar> r;
  r << a.c, -a.s, Scalar(0),  //
      a.s, a.c, Scalar(0),    //
      Scalar(0), Scalar(0), Scalar(1);
  return r;
}

// Rz(yaw) * Ry(pitch) * Rx(roll): maps body (or contact) coordinates to world coordinates.
template <typename Scalar>
Mat3<Scalar> rotation_zyx_deg(const Scalar& yaw, const Scalar& pitch, const Scalar& roll) {
  return rot_z(sin_cos_deg(yaw)) * rot_y(sin_cos_deg(pitch)) * rot_x(sin_cos_deg(roll));
}

// The same rotation in closed form from the sines and cosines, a third of the operations, for the lean
// path and batches (raw_collision.hpp). Its entries equal rotation_zyx_deg's bit for bit but for the sign of some zeros
// (the product adds zero terms that this form leaves out; tests/mechanics/check_rotation.cpp). Entry by entry, not
// by Eigen's comma initializer, which kept GCC from inlining it into compute_scene: the call and the
// copies cost a tenth of a lean pc-crash solve in double (BENCHMARKS.md).
template <typename Scalar>
Mat3<Scalar> rotation_zyx(const SinCos<Scalar>& z, const SinCos<Scalar>& y, const SinCos<Scalar>& x) {
  const Scalar zc_ys = z.c * y.s, zs_ys = z.s * y.s;
  Mat3<Scalar> r;
  r(0, 0) = z.c * y.c, r(0, 1) = -z.s * x.c + zc_ys * x.s, r(0, 2) = z.s * x.s + zc_ys * x.c;
  r(1, 0) = z.s * y.c, r(1, 1) = z.c * x.c + zs_ys * x.s, r(1, 2) = -z.c * x.s + zs_ys * x.c;
  r(2, 0) = -y.s, r(2, 1) = y.c * x.s, r(2, 2) = y.c * x.c;
  return r;
}

template <typename Scalar>
Mat3<Scalar> rotation_zyx_deg_closed(const Scalar& yaw, const Scalar& pitch, const Scalar& roll) {
  return rotation_zyx(sin_cos_deg(yaw), sin_cos_deg(pitch), sin_cos_deg(roll));
}

// Contact frame from a normal and a tangent given in world axes: n normalised, t made orthogonal to n
// (Gram-Schmidt) and normalised, z = n x t. Columns of the result are n, t, z. The caller has checked
// that n is non-zero and t is not parallel to n.
template <typename Scalar>
Vec3<Scalar> unit(const Vec3<Scalar>& v, const char* what) {
  if constexpr (is_exact_v<Scalar>) {
    return v / exact_sqrt(v.squaredNorm(), std::string("the length of ") + what);
  } else {
    (void)what;
    return v.normalized();
  }
}

template <typename Scalar>
Mat3<Scalar> contact_frame_from_vectors(const Vec3<Scalar>& normal, const Vec3<Scalar>& tangent) {
  const Vec3<Scalar> n = unit(normal, "the contact normal");
  const Vec3<Scalar> t = unit(Vec3<Scalar>(tangent - n * n.dot(tangent)), "the contact tangent (made orthogonal to the normal)");
  Mat3<Scalar> r;
  r.col(0) = n;
  r.col(1) = t;
  r.col(2) = n.cross(t);
  return r;
}

}  // namespace impact3d
