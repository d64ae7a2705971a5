// The rounding model: how far a result computed at a precision with unit roundoff eps can stray from the
// exact result of the same decimal inputs, and the warnings a result gets when that bound is not small.
// Every bound that impact3d, its verification and its tests hold a computed quantity to is named here,
// with what error it bounds, of what operation, and why its factor is what it is. In exact arithmetic
// every bound is zero: results are compared for equality.
//
// eps is std::numeric_limits<Scalar>::epsilon(), 2^(1 - p) for a binary type of p bits (the unit roundoff
// of scalars.hpp); a "rounding" is one operation's relative error, at most eps, and the factors below
// count roundings.
//
//   Zero          within_rounding, beyond_rounding (a ball that holds 0 is zero, undecided)
//   Results       kResultRoundings, kTrustedFraction, spd_condition, spd_condition_bound,
//                 coefficient_condition_bound, amplification, amplification_bound, quotient_factor,
//                 relative_bound, agreement_bound, precision_for
//   Solves        kSolveRoundings, solve_roundoff, velocity_scale, velocity_roundoff, energy_roundoff
//   Short sums    kArithmeticRoundings, arithmetic_roundoff, pdof_roundoff, kMomentumRoundings, momentum_roundoff
//   Inputs        kParallelRoundings, parallel_within_rounding, kOrthonormalDigits, orthonormality_tolerance
//   Reference     kExactCheckDigits, exact_check_tolerance, kEngineAgreementDigits, engine_agreement_tolerance
//
// The result bound. Relative error of an impulse <= kResultRoundings * eps * A, with the amplification
//   A = kappa(K) * cond(J) * max(1, (|v_IC1| + |v_IC2|) / V_rn):
//   - kappa(K): every impulse is a 3x3 solve with K (or its closed form);
//   - cond(J): K holds J^-1, formed from the inertia tensors (the worse of the two vehicles);
//   - (|v_IC1| + |v_IC2|) / V_rn: the decimal inputs and rotations are rounded to the type, so V_rn =
//     n.(v2 - v1) carries an absolute error of eps times the point speeds, and every impulse is
//     proportional to V_rn through the restitution constraint (a grazing contact is ill-posed).
// A ratio carries its quotient's factor (1 + |V_cp / V_n|)(1 + |mu|) besides.
#pragma once

#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>

#include <Eigen/Eigenvalues>

#include "impact3d/scalar/exact.hpp"
#include "impact3d/mechanics/kinematics.hpp"
#include "impact3d/scalar/planar_norm.hpp"
#include "impact3d/scalar/scalars.hpp"

namespace impact3d::rounding {

// Whether the model below applies: exact types do not round, and an enclosure (ball.hpp) carries its
// own rounding in its radius.
template <typename Scalar>
inline constexpr bool tracks_rounding_v = !is_exact_v<Scalar> && !is_enclosure_v<Scalar>;

// Whether x is zero as far as the arithmetic can tell: |x| <= tol, its rounding bound. For a ball the
// comparison is a decision, and where x's ball holds 0 the exact value may be zero or not: then it is
// undecided, the zero branch is taken, and the other is the alternative (ball.hpp, ball_within).
template <typename Scalar>
bool within_rounding(const Scalar& x, const Scalar& tol) {
  if constexpr (is_enclosure_v<Scalar>) {
    return EnclosureTraits<Scalar>::within(x, tol);
  } else {
    using std::abs;
    return abs(x) <= tol;
  }
}

// Its negation, but false for a NaN, as |x| > tol is.
template <typename Scalar>
bool beyond_rounding(const Scalar& x, const Scalar& tol) {
  if constexpr (is_enclosure_v<Scalar>) {
    return !EnclosureTraits<Scalar>::within(x, tol);
  } else {
    using std::abs;
    return abs(x) > tol;
  }
}

// ---- Results ------------------------------------------------------------------------------------------

// The roundings on each path from the decimal inputs to an impulse that do not cancel: the solve's
// kSolveRoundings (below) and as many again for forming K (J^-1, the lever arms, the rotations) and the
// right-hand side from the rounded inputs, each of those a solve or a short sum of the same kind. It is
// the bound `impact3d verify` checks every precision against (100-digit reference) and the engines
// against each other; the largest it measures stays well inside it.
inline constexpr double kResultRoundings = 32;
// A result is trusted when its bound is at most this fraction of it: six significant digits, more than
// any input of a reconstruction carries. Beyond it the result is flagged and a precision suggested.
inline constexpr double kTrustedFraction = 1e-6;

// 2-norm condition of a symmetric matrix that should be positive definite; infinity when rounding made
// it indefinite or singular (the computation at this precision cannot be trusted at all).
template <typename Scalar>
Scalar spd_condition(const Mat3<Scalar>& M) {
  if constexpr (is_exact_v<Scalar>) {
    return Scalar(1);
  } else if constexpr (is_enclosure_v<Scalar>) {
    return EnclosureTraits<Scalar>::spd_condition(M);
  } else {
    Eigen::SelfAdjointEigenSolver<Mat3<Scalar>> eig(M, Eigen::EigenvaluesOnly);
    const Scalar lo = eig.eigenvalues().minCoeff(), hi = eig.eigenvalues().maxCoeff();
    if (!(lo > Scalar(0)) || !is_finite(hi)) return std::numeric_limits<Scalar>::infinity();
    return hi / lo;
  }
}

// tr(M) tr(M^-1) of the symmetric M with upper triangle m = (a, b, c, d, e, f), tr(M^-1) as the trace
// of the adjugate (the principal 2x2 minors) over the determinant; empty where M fails Sylvester's test
// (a or the leading 2x2 minor not positive) or the computed determinant is not above det_floor, below
// which it may be rounding noise (each caller says why its floor suffices). For M positive definite,
// with eigenvalues l1 >= l2 >= l3 > 0, tr(M) >= l1 and tr(M^-1) = 1/l1 + 1/l2 + 1/l3 >= 1/l3: the
// product is at least kappa = l1 / l3 and at most 9 kappa. One division and no root.
template <typename T>
std::optional<T> trace_condition(const std::array<T, 6>& m, const T& det_floor) {
  const T &a = m[0], &b = m[1], &c = m[2], &d = m[3], &e = m[4], &f = m[5];
  const T A = d * f - e * e, B = c * e - b * f, C = b * e - c * d;  // first column of the adjugate
  const T D = a * f - c * c, F = a * d - b * b;
  const T det = a * A + b * B + c * C;
  if (!(a > T(0)) || !(F > T(0)) || !(det > det_floor)) return std::nullopt;
  return (a + d + f) * (A + D + F) / det;
}

// tr(M) tr(M^-1) for a multiprecision M, computed in double, where that bounds it. M's entries are
// rounded to double (a perturbation within 2^-53 ||M||) and scaled by a power of two so that the largest
// is in [1/2, 1): for a positive definite M, lambda_max is then in [1/2, 3]. The double determinant is
// trusted only above 2^-30: its error is within about 10 u ||M||^3 < 2^-44 (u = 2^-53), so its relative
// error is below 2^-14; the adjugate's trace, at least lambda_max lambda_mid = det / lambda_min >=
// det / 3 > 2^-32, carries three minors' errors (within 3 u m^2 each, m the largest entry, at most 1),
// below 2^-17 of it; the product is within 2^-13 of the exact one, and times 1 + 2^-10 above it. The
// guard loses no matrix the bound serves: a product at most 2^12 means kappa <= 2^12 and det >=
// lambda_max^3 / kappa^2 >= 2^-27.
// Without it a nearly singular M (two eigenvalues 2^-50 of the third) rounds to a determinant of
// rounding noise that can pass for a small one. Elsewhere (an entry outside [2^-900, 2^900], M
// indefinite or worse conditioned) empty: the scalar's own arithmetic decides. The lean path uses the
// bound only to decide what is far from a limit, so a larger valid bound changes no result.
template <typename Scalar>
std::optional<double> spd_condition_bound_in_double(const Mat3<Scalar>& M) {
  std::array<double, 6> m = {to_double(M(0, 0)), to_double(M(0, 1)), to_double(M(0, 2)),
                              to_double(M(1, 1)), to_double(M(1, 2)), to_double(M(2, 2))};
  double big = 0;
  for (const double x : m) {
    if (!std::isfinite(x)) return std::nullopt;
    big = std::fabs(x) > big ? std::fabs(x) : big;
  }
  if (!(big >= 0x1p-900 && big <= 0x1p900)) return std::nullopt;
  int e2;
  std::frexp(big, &e2);
  for (double& x : m) x = std::ldexp(x, -e2);
  const std::optional<double> k = trace_condition(m, 0x1p-30);
  if (!k || !(*k <= 0x1p12)) return std::nullopt;
  return *k * (1 + 0x1p-10);
}

// An upper bound of spd_condition without eigenvalues, for the lean path's inertia tensors: tr(M)
// tr(M^-1) (trace_condition), at least lambda_max / lambda_min and at most nine times it; infinity where
// M fails Sylvester's test (a leading minor not positive), as spd_condition is where M is indefinite,
// and where the computed determinant is not above 2^20 eps m^3 (m the largest entry): its error is within
// about 10 eps m^3, so a smaller one may be noise (two eigenvalues far below the third, M nearly of rank
// one), and the product could fall far below kappa; infinity then sends every decision to the computed
// kappa (so does an m^3 that overflows; one that underflows leaves det > 0, the test before). Above the
// guard the determinant's and the adjugate trace's errors stay below 2^-15 of them (the argument of the
// double bound above, with 2^20 eps m^3 in place of 2^-30). Beyond long double, in double where that
// bounds it (above).
template <typename Scalar>
Scalar spd_condition_bound(const Mat3<Scalar>& M) {
  if constexpr (is_exact_v<Scalar>) {
    return Scalar(1);
  } else if constexpr (is_enclosure_v<Scalar>) {
    return EnclosureTraits<Scalar>::spd_condition(M);
  } else {
    if constexpr (std::numeric_limits<Scalar>::digits > 64)
      if (const std::optional<double> k = spd_condition_bound_in_double(M)) return Scalar(*k);
    using std::abs;
    const std::array<Scalar, 6> m = {M(0, 0), M(0, 1), M(0, 2), M(1, 1), M(1, 2), M(2, 2)};
    Scalar big = abs(m[0]);
    for (std::size_t i = 1; i < m.size(); ++i)
      if (const Scalar x = abs(m[i]); x > big) big = x;
    const std::optional<Scalar> k = trace_condition<Scalar>(
        m, Scalar(0x1p20) * std::numeric_limits<Scalar>::epsilon() * big * big * big);
    return k && is_finite(*k) ? *k : std::numeric_limits<Scalar>::infinity();
  }
}

// An upper bound of spd_condition(K) for the coefficient matrix of eq 9, for the lean path: its trace.
// K = I + m' sum_i T_i [r_i]x^T J_i^-1 [r_i]x T_i^T is the identity plus a positive semidefinite part
// when m' > 0 and the inertia tensors are positive definite, so lambda_min >= 1 and kappa <= lambda_max
// <= tr(K) (at most 3 lambda_max). That is a property of the exact K of the rounded inputs; the computed
// K's smallest eigenvalue is at least 1 - ||E||, E its rounding. The lean path takes the bound only
// while the amplification bound, infinite unless both tensors pass spd_condition_bound's test, puts
// kResultRoundings eps kappa_bound times the tensors' bound (and the cancellation's factor) within
// kTrustedFraction: E, some kSolveRoundings eps cond(J) ||K|| (forming K), is then below 10^-6, and
// every use doubles the bound. Infinity where m' is not positive or the trace is not finite. Two
// additions, where spd_condition_bound takes a division and some twenty products.
template <typename Scalar>
Scalar coefficient_condition_bound(const Mat3<Scalar>& K, const Scalar& m_prime) {
  if constexpr (is_exact_v<Scalar>) {
    return Scalar(1);
  } else if constexpr (is_enclosure_v<Scalar>) {
    return EnclosureTraits<Scalar>::spd_condition(K);
  } else {
    const Scalar trace = K(0, 0) + K(1, 1) + K(2, 2);
    return m_prime > Scalar(0) && is_finite(trace) ? trace : std::numeric_limits<Scalar>::infinity();
  }
}

// The amplification A above from the conditions of K and of the inertia tensors (computed or bounded),
// the normal approach speed V_rn (> 0 for an impact) and the point speeds |v_IC1| + |v_IC2|; infinite
// where either condition is.
template <typename Scalar>
Scalar amplification_of(const Scalar& point_speeds, const Scalar& V_rn, const Scalar& kappa_K, const Scalar& cond_J) {
  if constexpr (!tracks_rounding_v<Scalar>) {
    return Scalar(1);
  } else {
    using std::max;
    const Scalar cancellation = max(Scalar(1), Scalar(point_speeds / V_rn));
    const Scalar a = kappa_K * cond_J * cancellation;
    return is_finite(a) && a > Scalar(0) ? a : std::numeric_limits<Scalar>::infinity();
  }
}

// |v_IC1| + |v_IC2|, the speeds whose rounding V_rn carries.
template <typename Scalar>
Scalar point_speeds(const Vec3<Scalar>& v_Ic0_W, const Vec3<Scalar>& v_Ic1_W) {
  return v_Ic0_W.norm() + v_Ic1_W.norm();
}

// spd_condition of an inertia tensor. Many solves of one collision (a Monte Carlo run, a sweep) mostly
// vary other inputs than the tensors: at double each thread keeps the last two tensors' conditions and
// gives them again for a tensor identical bit for bit, which changes no result.
template <typename Scalar>
Scalar inertia_condition(const Mat3<Scalar>& J) {
  if constexpr (std::is_same_v<Scalar, double>) {
    struct Kept {
      Mat3<double> J;
      double condition;
    };
    thread_local std::array<std::optional<Kept>, 2> kept;
    thread_local std::size_t next = 0;
    for (const auto& k : kept)
      if (k && std::memcmp(k->J.data(), J.data(), sizeof(double) * 9) == 0) return k->condition;
    const double c = spd_condition(J);
    kept[next] = Kept{J, c};
    next ^= 1;
    return c;
  } else {
    return spd_condition(J);
  }
}

// The amplification A above; exact arithmetic has nothing to amplify.
template <typename Scalar>
Scalar amplification(const Scene<Scalar>& s, const Scalar& point_speeds, const Scalar& V_rn, const Scalar& kappa_K) {
  if constexpr (!tracks_rounding_v<Scalar>) return Scalar(1);
  using std::max;
  return amplification_of(point_speeds, V_rn, kappa_K,
                          Scalar(max(inertia_condition(s.body[0].J_B), inertia_condition(s.body[1].J_B))));
}

// An upper bound of the amplification from spd_condition_bound, for the lean path.
template <typename Scalar>
Scalar amplification_bound(const Scene<Scalar>& s, const Scalar& point_speeds, const Scalar& V_rn, const Scalar& kappa_K_bound) {
  using std::max;
  return amplification_of(point_speeds, V_rn, kappa_K_bound,
                          Scalar(max(spd_condition_bound(s.body[0].J_B), spd_condition_bound(s.body[1].J_B))));
}

// The quotient's factor of a ratio u.P / P_n, 1 + |V_cp / V_n|: ratios and the decisions taken on them
// carry it besides the amplification.
template <typename Scalar>
Scalar quotient_factor(const Vec3<Scalar>& V_ri) {
  return Scalar(1) + planar_norm(V_ri.y(), V_ri.z()) / V_ri.x();
}

// The relative bound of an impulse at this precision: kResultRoundings * eps * amplification. With
// inputs held exactly in the type (a scene built in double, as the tests build them) the amplification
// is kappa(K), to the conditioning of J.
template <typename Scalar>
Scalar relative_bound(const Scalar& amplification) {
  if constexpr (!tracks_rounding_v<Scalar>) return Scalar(0);
  else return Scalar(kResultRoundings) * std::numeric_limits<Scalar>::epsilon() * amplification;
}

// Two computations of one result (two engines, two precisions, a frame and its rotation, a closed form
// and a solve) are each within relative_bound of the exact value, so within twice it of each other.
template <typename Scalar>
Scalar agreement_bound(const Scalar& amplification) {
  if constexpr (!tracks_rounding_v<Scalar>) return Scalar(0);
  else return Scalar(2 * kResultRoundings) * std::numeric_limits<Scalar>::epsilon() * amplification;
}

// The narrowest precision whose bound for `amplification` is within the trusted fraction; empty when
// none is (or the amplification is not finite, as when K or J is not positive definite here).
inline std::string precision_for(double amplification) {
  if (!std::isfinite(amplification)) return "";
  for (const auto& p : kPrecisions)
    if (kResultRoundings * p.unit_roundoff * amplification <= kTrustedFraction) return std::string(p.name);
  return "";
}

// ---- Solves -------------------------------------------------------------------------------------------

// A quantity computed through one 3x3 solve with K, from terms of size `scale`, has a forward error of
// about eps * kappa(K) * scale: the solve's backward error (a few eps for LU with pivoting, or for the
// generated closed forms, which are Cramer's rule on the same system) and the rows' own roundings, both
// magnified by kappa (|dx|/|x| <= kappa (|dA|/|A| + |db|/|b|) to first order). Each row is assembled from
// K, m', V_ri and a plane's axes by a handful of products and sums, about four roundings an entry; on
// matrix and right-hand side together, with the solve's own, 16 covers them.
inline constexpr double kSolveRoundings = 16;

// kSolveRoundings * eps * kappa * scale. A direction (the solution plane of pc-crash or Wach) whose
// length is below it is noise: Problem::negligible.
template <typename Scalar>
Scalar solve_roundoff(const Scalar& kappa, const Scalar& scale) {
  if constexpr (!tracks_rounding_v<Scalar>) return Scalar(0);
  else return Scalar(kSolveRoundings) * std::numeric_limits<Scalar>::epsilon() * kappa * scale;
}

// The size of the velocities a post-impact relative velocity is made of: it is V_ri plus the change the
// impulse makes at the two impulse centres, a difference of point velocities of at most this size.
template <typename Scalar>
Scalar velocity_scale(const Scene<Scalar>& s) {
  return v_Ic_W(s.body[0]).norm() + v_Ic_W(s.body[1]).norm() + relative_velocity_C(s).norm();
}

// A post-impact relative velocity below this is zero at this precision: velocity_scale through a solve
// of condition kappa. The regime decisions (sliding stopped or reversed, separating or not, the volume
// of Figure 2) are taken against it, and the text report prints a velocity below it as 0.
template <typename Scalar>
Scalar velocity_roundoff(const Scene<Scalar>& s, const Scalar& kappa) {
  if constexpr (!tracks_rounding_v<Scalar>) return Scalar(0);  // and no norm, which is not rational
  else return solve_roundoff(kappa, velocity_scale(s));
}

// The kinetic energy loss is a difference of energies of size energy_before, of states after a solve of
// condition kappa: a loss below -energy_roundoff is a gain beyond rounding (the energy_gained warning).
// At restitution 1 without sliding the exact loss is zero and the computed one of either sign.
template <typename Scalar>
Scalar energy_roundoff(const Scalar& kappa, const Scalar& energy_before) {
  return solve_roundoff(kappa, energy_before);
}

// ---- Short sums ---------------------------------------------------------------------------------------

// A quantity formed by a short, fixed sequence of products and sums with no solve (a vector turned by a
// rotation; the entries of K from J^-1, the lever arms and the rotations) is off by at most
// gamma_n = n eps / (1 - n eps) of the sum of its terms' magnitudes, n the operations on its longest
// path: three for a component of a rotated 3-vector (and one more for a planar length, planar_norm),
// under a dozen for an entry of K. 16 covers them with room; structural zeros and symmetries of such a
// quantity hold to this, relative to its size.
inline constexpr double kArithmeticRoundings = 16;

// kArithmeticRoundings * eps * scale.
template <typename Scalar>
Scalar arithmetic_roundoff(const Scalar& scale) {
  if constexpr (!tracks_rounding_v<Scalar>) return Scalar(0);
  else return Scalar(kArithmeticRoundings) * std::numeric_limits<Scalar>::epsilon() * scale;
}

// The principal direction of force is the angle of Delta-V's body x-y part, R^T Delta-V: each component
// a three-term dot product with an orthonormal row, off by gamma_3 |Delta-V|. A vertical Delta-V thus
// shows an x-y part of a few eps |Delta-V|, whose angle is noise: below this there is no PDOF.
template <typename Scalar>
Scalar pdof_roundoff(const Scalar& delta_v) {
  return arithmetic_roundoff(delta_v);
}

// Momentum is conserved by every impulse law: the pair's linear momentum, and each vehicle's angular
// momentum about its impulse centre (the impulse has no moment there). Computed from the states, the
// residual after - before is made of: the states' update by P (v + P/m; w + J^-1 (r x P) by Cholesky,
// whose residual is backward stable, a few eps ||J|| |dw|, with no condition number), and the momenta's
// own products and sums (a rotation, a cross product, J w: under ten roundings a component). Relative to
// `momentum_scale` (1-norms, rational: the terms' magnitudes before and after), 32 covers them with room.
// The report prints the residual over this bound: at most 1 when the states conserve momentum.
inline constexpr double kMomentumRoundings = 32;

template <typename Scalar>
Scalar momentum_roundoff(const Scalar& scale) {
  if constexpr (!tracks_rounding_v<Scalar>) return Scalar(0);
  else return Scalar(kMomentumRoundings) * std::numeric_limits<Scalar>::epsilon() * scale;
}

// ---- Inputs -------------------------------------------------------------------------------------------

// A contact frame given by vectors: the tangent is t less its component along n, of length |t| sin(theta),
// which carries the rounding of t and of the projection, so the frame's tangent and third axis have a
// relative error of about eps / sin(theta). With sin^2(theta) = |n x t|^2 / (|n|^2 |t|^2) <= 64 eps,
// sin(theta) <= 8 sqrt(eps) and the frame would keep fewer than half the precision's digits (an error
// of sqrt(eps) / 8 or more): the tangent is refused as parallel to the normal. The squared norms are
// compared so that no root is taken (exact types have none).
inline constexpr double kParallelRoundings = 64;

// Whether |n x t|^2 = across is lost against |n|^2 |t|^2 = scale: true when the tangent is parallel.
template <typename Scalar>
bool parallel_within_rounding(const Scalar& across, const Scalar& scale) {
  if constexpr (is_exact_v<Scalar>) return across == Scalar(0);
  else return !(across > Scalar(kParallelRoundings) * std::numeric_limits<Scalar>::epsilon() * scale);
}

// An orientation matrix written in decimals is a rotation when R R^T = I within 10^-12 in every entry,
// the same at every precision so that every precision accepts or refuses a case alike. It bounds the
// writing of the input, not the rounding of a type: entries written to d significant digits are off by
// up to 5 * 10^-d each, and an entry of R R^T - I, a sum of three products of entries of at most 1, by
// about 3 * 10^(1 - d); d = 13 passes. Exact arithmetic asks for R R^T = I exactly.
inline constexpr int kOrthonormalDigits = 12;

template <typename Scalar>
Scalar orthonormality_tolerance() {
  long long inverse = 1;  // 10^kOrthonormalDigits, exact in every type
  for (int i = 0; i < kOrthonormalDigits; ++i) inverse *= 10;
  return Scalar(1) / Scalar(inverse);
}

// ---- The 100-digit reference --------------------------------------------------------------------------

// `impact3d verify` holds the 100-digit solve (unit roundoff 10^-99) to the exact fractions, wherever a
// case's rotations are rational, within 10^-95 of the impulse's norm: 99 digits less 1.5 for
// kResultRoundings and 2.5 for an amplification up to about 300. It is fixed, not the case's
// relative_bound, so that it does not loosen when a harder case is added; the suite's rational cases
// meet it, the grazing approach among them (its 100-digit relative_bound is 10^-91: the bound is a
// worst case).
inline constexpr int kExactCheckDigits = 95;

template <typename F>
F exact_check_tolerance() {
  return F(("1e-" + std::to_string(kExactCheckDigits)).c_str());
}

// The reference generator solves each case at 100 digits by both engines and refuses a case whose
// impulses differ by more than 10^-80 relative: each engine is within relative_bound of the exact value
// (below 10^-91 in the suite), so 80 digits leave room for an amplification up to about 10^17.
inline constexpr int kEngineAgreementDigits = 80;

template <typename F>
F engine_agreement_tolerance() {
  return F(("1e-" + std::to_string(kEngineAgreementDigits)).c_str());
}

}  // namespace impact3d::rounding
