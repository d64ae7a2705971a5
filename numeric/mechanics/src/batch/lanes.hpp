// pc-crash, Wach and Brach on one group of SIMD lanes, through the generated kernels instantiated on
// xsimd batches.
// Included only by lanes_arch.cpp, which CMake compiles once per instruction set: nothing here may
// instantiate code shared with other translation units (only batch types and raw pointers), so that no
// wider instruction leaks into code the whole program links.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>

#include <xsimd/xsimd.hpp>

#include <Eigen/Core>

#include "impact3d/generated/brach.hpp"
#include "impact3d/generated/coefficient_matrix.hpp"
#include "impact3d/generated/full_impact.hpp"
#include "impact3d/generated/solution_plane.hpp"
#include "impact3d/mechanics/batch/columns.hpp"
#include "impact3d/mechanics/rotation.hpp"
#include "lanes_entry.hpp"

// Eigen holds batches as the scalar of fixed-size matrices that the kernels only index.
namespace Eigen {
template <typename T, typename A>
struct NumTraits<xsimd::batch<T, A>> : GenericNumTraits<T> {
  using Real = xsimd::batch<T, A>;
  using NonInteger = Real;
  using Nested = Real;
  using Literal = Real;
  enum { IsComplex = 0, IsInteger = 0, IsSigned = 1, RequireInitialization = 1, ReadCost = 1, AddCost = 1, MulCost = 1 };
};
}  // namespace Eigen

namespace impact3d::batch::lanes {

template <typename B>
using M3 = Eigen::Matrix<B, 3, 3>;
template <typename B>
using V3 = Eigen::Matrix<B, 3, 1>;

// sin_cos_deg (rotation.hpp) on lanes: quarter turns taken out exactly, the rest by xsimd's sincos.
// Multiplications replace the scalar path's divisions (a division costs a lane group some 16 cycles):
// the quarter turn may then differ from the scalar path's where deg / 90 is within an ulp of a half
// turn, where either gives a rest of 45 degrees, and the radians by an ulp; multiples of 90 stay exact.
template <typename B>
SinCos<B> sin_cos_deg(const B& deg) {
  const B quarter(90.0), zero(0.0), one(1.0);
  const B turns = xsimd::floor(deg * B(1.0 / 90.0) + B(0.5));
  const B rest = deg - turns * quarter;
  const B q = turns - B(4.0) * xsimd::floor(turns * B(0.25));
  // |rad| <= pi/4: xsimd's polynomials for that range, called directly (what xsimd::sincos computes
  // there, bit for bit), so that its general reduction, and the inline scalar function it falls back to
  // for huge arguments, which every lane object would define, is not compiled in.
  const B rad = rest * B(3.141592653589793115997963468544185161590576171875 / 180.0), z = rad * rad;
  const auto exact = rest == zero;
  const B s = xsimd::select(exact, zero, xsimd::kernel::detail::sin_eval(z, rad));
  const B c = xsimd::select(exact, one, xsimd::kernel::detail::cos_eval(z));
  const auto q1 = q == one, q2 = q == B(2.0), q3 = q == B(3.0);
  return {xsimd::select(q1, c, xsimd::select(q2, -s, xsimd::select(q3, -c, s))),
          xsimd::select(q1, -s, xsimd::select(q2, -c, xsimd::select(q3, s, c)))};
}

// rotation_zyx_deg_closed on lanes: the lanes' sines and cosines, rotation.hpp's closed form.
template <typename B>
M3<B> rotation(const B& yaw, const B& pitch, const B& roll) {
  return rotation_zyx(sin_cos_deg(yaw), sin_cos_deg(pitch), sin_cos_deg(roll));
}

// A^T B, summed in the order Eigen's product sums.
template <typename B>
M3<B> transpose_times(const M3<B>& a, const M3<B>& b) {
  M3<B> r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) r(i, j) = a(0, i) * b(0, j) + a(1, i) * b(1, j) + a(2, i) * b(2, j);
  return r;
}

template <typename B>
V3<B> times(const M3<B>& a, const V3<B>& v) {
  V3<B> r;
  for (int i = 0; i < 3; ++i) r(i) = a(i, 0) * v(0) + a(i, 1) * v(1) + a(i, 2) * v(2);
  return r;
}

template <typename B>
B norm(const V3<B>& v) {
  return xsimd::sqrt(v(0) * v(0) + v(1) * v(1) + v(2) * v(2));
}

// rounding::spd_condition_bound on lanes: tr(M) tr(M^-1), infinite where Sylvester's test fails or the
// determinant is not above 2^20 eps m^3 (m the largest entry; below that it may be rounding noise).
template <typename B>
B spd_condition_bound(const M3<B>& M) {
  const B a = M(0, 0), b = M(0, 1), c = M(0, 2), d = M(1, 1), e = M(1, 2), f = M(2, 2), zero(0.0);
  const B A = d * f - e * e, Bc = c * e - b * f, C = b * e - c * d;
  const B D = a * f - c * c, F = a * d - b * b;
  const B det = a * A + b * Bc + c * C;
  const B m = xsimd::max(xsimd::max(xsimd::max(xsimd::abs(a), xsimd::abs(b)), xsimd::max(xsimd::abs(c), xsimd::abs(d))),
                         xsimd::max(xsimd::abs(e), xsimd::abs(f)));
  const B k = (a + d + f) * (A + D + F) / det;
  const auto spd = (a > zero) && (F > zero) && (det > B(0x1p20 * std::numeric_limits<double>::epsilon()) * m * m * m) &&
                   xsimd::isfinite(k);
  return xsimd::select(spd, k, B(std::numeric_limits<double>::infinity()));
}

template <typename B>
struct Body {
  B mass;
  M3<B> J, R_WB;
  V3<B> v, w, r;
};

template <typename B>
Body<B> load_body(const VehicleColumns& c, std::size_t i) {
  Body<B> b;
  b.mass = B::load_unaligned(c.mass + i);
  const int entry[3][3] = {{xx, xy, xz}, {xy, yy, yz}, {xz, yz, zz}};
  for (int p = 0; p < 3; ++p) {
    for (int q = 0; q < 3; ++q) b.J(p, q) = B::load_unaligned(c.J_B[entry[p][q]] + i);
    b.v(p) = B::load_unaligned(c.v_W[p] + i);
    b.w(p) = B::load_unaligned(c.w_B[p] + i);
    b.r(p) = B::load_unaligned(c.p_CgIc_B[p] + i);
  }
  b.R_WB = rotation(B::load_unaligned(c.yaw_deg + i), B::load_unaligned(c.pitch_deg + i), B::load_unaligned(c.roll_deg + i));
  return b;
}

// v_Ic_W (kinematics.hpp) on lanes.
template <typename B>
V3<B> v_Ic(const Body<B>& b) {
  V3<B> wxr;
  wxr(0) = b.w(1) * b.r(2) - b.w(2) * b.r(1);
  wxr(1) = b.w(2) * b.r(0) - b.w(0) * b.r(2);
  wxr(2) = b.w(0) * b.r(1) - b.w(1) * b.r(0);
  const V3<B> turned = times(b.R_WB, wxr);
  V3<B> out;
  for (int k = 0; k < 3; ++k) out(k) = b.v(k) + turned(k);
  return out;
}

// What every strategy starts from, as the scalar path's Problem (make_problem, bounded): m', K, V_ri, and
// the cheap bounds of kappa(K) and of the amplification, with the result bound they give.
template <typename B>
struct LaneProblem {
  B m_prime, e, kappa, bound;  // bound: rounding::relative_bound(amplification) times the quotient's factor
  B K_max;                     // the largest diagonal entry of K, which bounds every entry (K is SPD)
  M3<B> K;
  V3<B> V;  // V_ri, contact axes
  // Not approaching, m' not positive or K not finite, eps not in [0, 1] (the signs below rest on
  // m'(1 + eps) V_rn > 0, and on its two products adding without cancellation, fused or not), or the
  // rounding not trusted.
  typename B::batch_bool_type doubt;
};

template <typename B>
LaneProblem<B> problem(const CollisionColumns& in, std::size_t i) {
  constexpr double eps = std::numeric_limits<double>::epsilon();
  const B zero(0.0), one(1.0), inf(std::numeric_limits<double>::infinity());
  LaneProblem<B> p;
  const Body<B> b0 = load_body<B>(in.vehicle[0], i), b1 = load_body<B>(in.vehicle[1], i);
  const M3<B> R_WC = rotation(B::load_unaligned(in.normal_yaw_deg + i), B::load_unaligned(in.normal_pitch_deg + i),
                              B::load_unaligned(in.tangent_roll_deg + i));
  p.e = B::load_unaligned(in.restitution + i);
  p.m_prime = b0.mass * b1.mass / (b0.mass + b1.mass);
  p.K = generated::coefficient_matrix(p.m_prime, b0.J, b1.J, b0.r, b1.r, transpose_times(R_WC, b0.R_WB),
                                      transpose_times(R_WC, b1.R_WB));
  const V3<B> v0 = v_Ic(b0), v1 = v_Ic(b1);
  V3<B> dv;
  for (int k = 0; k < 3; ++k) dv(k) = v1(k) - v0(k);
  for (int k = 0; k < 3; ++k) p.V(k) = R_WC(0, k) * dv(0) + R_WC(1, k) * dv(1) + R_WC(2, k) * dv(2);

  // Amplification bound (rounding.hpp): kappa(K) cond(J) max(1, (|v_IC1| + |v_IC2|) / V_rn), bounded.
  const B cond_J = xsimd::max(spd_condition_bound(b0.J), spd_condition_bound(b1.J));
  p.kappa = p.K(0, 0) + p.K(1, 1) + p.K(2, 2);  // rounding::coefficient_condition_bound (m' > 0: doubt below)
  const B cancellation = xsimd::max(one, (norm(v0) + norm(v1)) / p.V(0));
  B amplification = p.kappa * cond_J * cancellation;
  amplification = xsimd::select(xsimd::isfinite(amplification) && amplification > zero, amplification, inf);
  // The rounding bound of rounding.hpp with the bounded amplification.
  const B quotient = one + xsimd::hypot(p.V(1), p.V(2)) / p.V(0);
  p.bound = B(32.0 * eps) * amplification * quotient;
  p.K_max = xsimd::max(p.K(0, 0), xsimd::max(p.K(1, 1), p.K(2, 2)));
  p.doubt = !(p.V(0) > zero) || !xsimd::isfinite(p.K(0, 0)) || !(p.m_prime > zero) || !xsimd::isfinite(p.m_prime) ||
            !(p.e >= zero && p.e <= one) || !(p.bound <= B(1e-6 / 2));
  return p;
}

template <typename B>
typename B::batch_bool_type all_finite(const V3<B>& v) {
  return xsimd::isfinite(v(0)) && xsimd::isfinite(v(1)) && xsimd::isfinite(v(2));
}

// Thrice a bound: the scalar path's own test (once) and the difference between the lane's value and the
// scalar path's, up to agreement_bound (twice). A quotient's denominator is held to the bound relative
// to the size its terms can reach: K's entries are at most K_max, and their rounding (like V_ri's) is
// of the order of the bound times that, not of the entries themselves.
template <typename B>
typename B::batch_bool_type within_thrice(const B& x, const B& bound) {
  return xsimd::abs(x) <= B(3.0) * bound;
}

// A quotient's denominator, and the size its terms can reach (for the plane ratios and the GIR, the
// numerator's too): its rounding is of the order of the bound times the size.
template <typename B>
struct Den {
  B den, size;
};

// Whether the denominator's sign, or its being zero, could differ between the lanes and solve_lean.
template <typename B>
typename B::batch_bool_type doubtful(const Den<B>& d, const B& bound) {
  return within_thrice(d.den, bound * d.size);
}

// How much more a quotient's rounding can be than its terms': size / |den|, at least 1; relative to
// 1 + |quotient| where `size` bounds the numerator too, and for eqs 25 and 26 (whose numerators grow with
// the other ratio) relative to 1 + |t| + |z|, which normal_den's size carries.
template <typename B>
B amplified(const Den<B>& d) {
  return xsimd::max(B(1.0), d.size / xsimd::abs(d.den));
}

// A plane ratio's denominator (eqs 19-20), Vcp pb1 - V_rn (1 + eps) pb2, at eps = 0 for the GIR; its size
// bounds the numerator's, Vcp pa1 - V_rn (1 + eps) pa2, too (|c|, |s| <= 1, every entry of K at most
// K_max).
template <typename B>
Den<B> plane_ratio_den(const LaneProblem<B>& p, const B& c, const B& s, const B& e) {
  const B Vcp = p.V(1) * c + p.V(2) * s;
  const B pb1 = p.K(0, 1) * c + p.K(0, 2) * s;
  const B pb2 = (p.K(1, 1) * c + p.K(2, 1) * s) * c + (p.K(1, 2) * c + p.K(2, 2) * s) * s;
  const B rise = p.V(0) * (B(1.0) + e);
  return {Vcp * pb1 - rise * pb2, p.K_max * (B(2.0) * xsimd::abs(Vcp) + B(4.0) * rise)};
}

// The normal impulse's denominator for ratios t and z of it (eqs 18, 24), K_nn + K_nt t + K_nz z, and its
// size when t and z carry a rounding `amp` times the bound relative to 1 + |ratio| (a critical ratio's;
// zero for ratios given).
template <typename B>
Den<B> normal_den(const LaneProblem<B>& p, const B& t, const B& z, const B& amp) {
  return {p.K(0, 0) + p.K(0, 1) * t + p.K(0, 2) * z,
          p.K_max * (B(1.0) + xsimd::abs(t) + xsimd::abs(z)) * (B(1.0) + B(2.0) * amp)};
}

// A solution plane through n along (y, z), the in-plane part of a vector of norm `magnitude` (as
// strategies' solution_plane): its axes, whether its direction could be lost in rounding
// (Problem::negligible, bounded), and the bound of what rests on it, widened by magnitude / length: the
// direction carries the vector's rounding relative to its in-plane part.
template <typename B>
struct LanePlane {
  B length, c, s, bound;
  typename B::batch_bool_type doubt;
};

template <typename B>
LanePlane<B> plane_of(const LaneProblem<B>& p, const B& y, const B& z, const B& magnitude) {
  constexpr double eps = std::numeric_limits<double>::epsilon();
  const B length = xsimd::hypot(y, z);
  return {length, y / length, z / length, p.bound * xsimd::max(B(1.0), magnitude / length),
          within_thrice(length, B(16.0 * eps) * p.kappa * magnitude)};
}

// A warning no lane of this strategy gives.
template <typename B>
typename B::batch_bool_type never() {
  return typename B::batch_bool_type(false);
}

// The rows' impulses, and for the rows not deferred their regime (a Regime's value on each lane) and
// their warnings: a tensile normal impulse, a negative ratio.
template <typename B>
void store(const ImpulseColumns& out, std::size_t i, const V3<B>& P, const B& regime,
           const typename B::batch_bool_type& deferred, const typename B::batch_bool_type& tensile,
           const typename B::batch_bool_type& negative) {
  const B zero(0.0), one(1.0);
  for (int k = 0; k < 3; ++k) P(k).store_unaligned(out.P_C[k] + i);
  alignas(64) double regime_lane[B::size], deferred_lane[B::size], tensile_lane[B::size], negative_lane[B::size];
  regime.store_aligned(regime_lane);
  xsimd::select(deferred, one, zero).store_aligned(deferred_lane);
  xsimd::select(tensile, one, zero).store_aligned(tensile_lane);
  xsimd::select(negative, one, zero).store_aligned(negative_lane);
  constexpr WarningSet kTensile = warning_bit(WarningCode::tensile_normal_impulse);
  constexpr WarningSet kNegative = warning_bit(WarningCode::negative_ratio);
  for (std::size_t l = 0; l < B::size; ++l) {
    out.status[i + l] = deferred_lane[l] != 0.0 ? kDeferred : std::uint8_t(0);
    out.regime[i + l] = static_cast<std::uint8_t>(regime_lane[l]);
    out.warnings[i + l] =
        (tensile_lane[l] != 0.0 ? kTensile : WarningSet(0)) | (negative_lane[l] != 0.0 ? kNegative : WarningSet(0));
  }
}

template <typename B>
B regime_value(Regime r) {
  return B(static_cast<double>(static_cast<int>(r)));
}

// Rows [i, i + B::size) of `in`: impulses, regimes and warnings of the rows decided on the lanes, status
// kDeferred for the others.
// Flattened: everything it calls is inlined, so that the independent chains (nine sines and cosines,
// two bodies) interleave instead of waiting on each other's latency through calls.
template <typename B>
[[gnu::flatten]] void pc_crash(const CollisionColumns& in, const ImpulseColumns& out, std::size_t i) {
  using Mask = typename B::batch_bool_type;
  const B zero(0.0);
  const LaneProblem<B> p = problem<B>(in, i);
  const M3<B>& K = p.K;
  const V3<B>& V_ri = p.V;
  const B mu = B::load_unaligned(in.mu + i);

  const V3<B> P_fi = generated::full_impact(K, p.m_prime, p.e, V_ri);
  // phi_FI's plane.
  const B scale = norm(P_fi);
  const LanePlane<B> plane = plane_of(p, P_fi(1), P_fi(2), scale);
  const B &P_cp = plane.length, &c = plane.c, &s = plane.s;
  const B gir = P_cp / P_fi(0);
  const B cir = xsimd::select(p.e == zero, generated::plane_generalized_ratio(K, V_ri, c, s),
                              generated::plane_critical_ratio(K, p.e, V_ri, c, s));
  const V3<B> P_sl = generated::plane_impulse(K, p.m_prime, p.e, V_ri, c, s, mu);
  const Mask full = mu >= gir;
  V3<B> P;
  for (int k = 0; k < 3; ++k) P(k) = xsimd::select(full, P_fi(k), P_sl(k));

  // The decision on the GIR, within the rounding bound of rounding.hpp widened by what the GIR's own
  // denominator P_n,FI amplifies (|P_FI| / P_n,FI); that denominator, the CIR's (solve_lean reports the
  // CIR and goes singular where it is not finite) and the sliding impulse's (whose sign is the normal
  // impulse's) clear of zero, the last two by the plane's bound.
  const Den<B> gir_den{P_fi(0), scale};
  const B& plane_bound = plane.bound;
  const Mask undecided_doubt = within_thrice(mu - gir, p.bound * (B(1.0) + xsimd::abs(gir)) * amplified(gir_den)) ||
                               doubtful(gir_den, p.bound) || doubtful(plane_ratio_den(p, c, s, p.e), plane_bound);
  const Mask sliding_doubt = !full && doubtful(normal_den(p, mu * c, mu * s, zero), plane_bound);
  const Mask finite = all_finite(P) && xsimd::isfinite(gir) && xsimd::isfinite(cir) && all_finite(P_fi);
  const Mask deferred = p.doubt || !finite || plane.doubt || undecided_doubt || sliding_doubt;
  store(out, i, P, xsimd::select(full, regime_value<B>(Regime::full), regime_value<B>(Regime::sliding)), deferred,
        !(P(0) > zero), never<B>());
}

// The conditions Wach's and Brach's rows share with solve_lean beyond the problem's: the maximum-energy-
// loss impulse (eps = 0) is not singular, K and V_ri are finite, and the sign of the normal impulse, on
// which its tensile warning rests, is clear: that of its numerator V_rn eps m' + V_rn m', positive (the
// problem's doubt), times that of its denominator, which must be clear of zero by `bound`.
template <typename B>
typename B::batch_bool_type shared_doubt(const LaneProblem<B>& p, const V3<B>& P, const Den<B>& den, const B& bound) {
  const V3<B> P_0 = generated::full_impact(p.K, p.m_prime, B(0.0), p.V);
  typename B::batch_bool_type finite = all_finite(p.V) && all_finite(P_0) && all_finite(P);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) finite = finite && xsimd::isfinite(p.K(r, c));
  return p.doubt || !finite || doubtful(den, bound);
}


// Wach (strategies/wach.hpp): the plane of the initial sliding velocity (eq 21), mu capped at its CIR
// (at_cir) or GIR.
template <typename B>
[[gnu::flatten]] void wach(const CollisionColumns& in, bool at_cir, const ImpulseColumns& out, std::size_t i) {
  using Mask = typename B::batch_bool_type;
  const B zero(0.0), one(1.0);
  const LaneProblem<B> p = problem<B>(in, i);
  const B mu = B::load_unaligned(in.mu + i);
  // The plane of the initial sliding velocity; everything below rests on it, so takes its bound.
  const LanePlane<B> plane = plane_of(p, p.V(1), p.V(2), norm(p.V));
  const B &c = plane.c, &s = plane.s, &bound = plane.bound;
  const B gir = generated::plane_generalized_ratio(p.K, p.V, c, s);
  const B cir = xsimd::select(p.e == zero, gir, generated::plane_critical_ratio(p.K, p.e, p.V, c, s));
  const B limit = at_cir ? cir : gir;
  // Both caps' denominators (eqs 19-20) clear of zero, where a ratio would jump between huge values of
  // either sign: solve_lean forms both and goes singular where either is not finite. The cap used
  // carries the rounding its denominator amplifies into the decisions on it.
  const Den<B> cir_den = plane_ratio_den(p, c, s, p.e), gir_den = plane_ratio_den(p, c, s, zero);
  const B amp = amplified(at_cir ? cir_den : gir_den);
  const Mask cap_doubt = doubtful(cir_den, bound) || doubtful(gir_den, bound);
  const Mask undecided_doubt = within_thrice(mu - limit, bound * (one + xsimd::abs(limit)) * amp);
  const Mask capped = mu >= limit;
  const B used = xsimd::select(capped, limit, mu);
  // A negative ratio carries a warning (strategies/limits.hpp). An uncapped ratio is mu itself; a cap's
  // sign is the scalar path's to decide where it lies within the bound of zero.
  const Mask sign_doubt = capped && within_thrice(used, bound * (one + xsimd::abs(used)) * amp);
  const V3<B> P = generated::plane_impulse(p.K, p.m_prime, p.e, p.V, c, s, used);
  const Mask finite = xsimd::isfinite(gir) && xsimd::isfinite(cir);
  // In the plane, K_nn + K_nt c mu + K_nz s mu.
  const Den<B> den = normal_den(p, used * c, used * s, xsimd::select(capped, amp, zero));
  const Mask deferred =
      shared_doubt(p, P, den, bound) || !finite || plane.doubt || cap_doubt || undecided_doubt || sign_doubt;
  store(out, i, P, xsimd::select(capped, regime_value<B>(Regime::capped), regime_value<B>(Regime::sliding)), deferred,
        !(P(0) > zero), used < zero);
}

// Brach (strategies/brach.hpp): the ratios as given, a null column meaning critical on every row (eqs
// 24-27); the critical ratios it reports are formed too, since a singular or undefined one is a status
// or a warning.
template <typename B>
[[gnu::flatten]] void brach(const CollisionColumns& in, const double* mu_t, const double* mu_z, const ImpulseColumns& out,
                            std::size_t i) {
  using Mask = typename B::batch_bool_type;
  const B zero(0.0);
  const LaneProblem<B> p = problem<B>(in, i);
  // A critical ratio's denominator clear of zero, where it would jump between huge values of either sign
  // (and the normal impulse's sign with it): eq 25's V_rn (1 + eps) K_tt - V_t K_nt, eq 26's likewise in
  // z, whatever the other ratio; eq 27's the determinant below. Eqs 25 and 26 give the critical ratios
  // solve_lean reports beside every impulse, and it goes singular where one is not finite.
  const B one(1.0), two(2.0), rise = p.V(0) * (one + p.e);
  const M3<B>& K = p.K;
  const auto critical_den = [&](int k) {  // k = 1: eq 25 (t), 2: eq 26 (z)
    return Den<B>{rise * K(k, k) - p.V(k) * K(0, k), p.K_max * (rise + xsimd::abs(p.V(k)))};
  };
  const Den<B> t_den = critical_den(1), z_den = critical_den(2);
  const B amp_t = amplified(t_den), amp_z = amplified(z_den);
  Mask critical_doubt = doubtful(t_den, p.bound) || doubtful(z_den, p.bound);
  B t, z, amp = zero;  // amp: what the ratios used carry beyond their own rounding (none when given)
  if (mu_t && mu_z) {
    t = B::load_unaligned(mu_t + i), z = B::load_unaligned(mu_z + i);
  } else if (mu_z) {  // eq 25
    z = B::load_unaligned(mu_z + i), t = generated::brach_critical_t(p.K, p.e, p.V, z), amp = amp_t;
  } else if (mu_t) {  // eq 26
    t = B::load_unaligned(mu_t + i), z = generated::brach_critical_z(p.K, p.e, p.V, t), amp = amp_z;
  } else {  // eq 27
    const Eigen::Matrix<B, 2, 1> both = generated::brach_critical_both(p.K, p.e, p.V);
    t = both(0), z = both(1);
    const Den<B> det{rise * (K(1, 1) * K(2, 2) - K(2, 1) * K(1, 2)) - p.V(1) * (K(0, 1) * K(2, 2) - K(2, 1) * K(0, 2)) +
                         p.V(2) * (K(0, 1) * K(1, 2) - K(1, 1) * K(0, 2)),
                     p.K_max * p.K_max * two * (rise + xsimd::abs(p.V(1)) + xsimd::abs(p.V(2)))};
    critical_doubt = critical_doubt || doubtful(det, p.bound);
    amp = amplified(det);
  }
  const V3<B> P = generated::brach_impulse(p.K, p.m_prime, p.e, p.V, t, z);
  const B ratio_t = P(1) / P(0), ratio_z = P(2) / P(0);
  const B t_c = generated::brach_critical_t(p.K, p.e, p.V, ratio_z), z_c = generated::brach_critical_z(p.K, p.e, p.V, ratio_t);
  const V3<B> P_tc = generated::brach_impulse(p.K, p.m_prime, p.e, p.V, t_c, ratio_z);
  const V3<B> P_zc = generated::brach_impulse(p.K, p.m_prime, p.e, p.V, ratio_t, z_c);
  // The critical impulses' normal denominators clear of zero too: solve_lean goes singular where one of
  // them is not finite.
  const Mask critical_impulse_doubt = doubtful(normal_den(p, t_c, ratio_z, (one + amp) * amp_t), p.bound) ||
                                      doubtful(normal_den(p, ratio_t, z_c, (one + amp) * amp_z), p.bound);
  const Mask finite = xsimd::isfinite(t) && xsimd::isfinite(z) && xsimd::isfinite(ratio_t) && xsimd::isfinite(ratio_z) &&
                      xsimd::isfinite(t_c) && xsimd::isfinite(z_c) && all_finite(P_tc) && all_finite(P_zc) &&
                      xsimd::isfinite(P_tc(1) / P_tc(0)) && xsimd::isfinite(P_zc(2) / P_zc(0));
  const Mask deferred =
      shared_doubt(p, P, normal_den(p, t, z, amp), p.bound) || !finite || critical_doubt || critical_impulse_doubt;
  store(out, i, P, regime_value<B>(Regime::as_given), deferred, !(P(0) > zero), never<B>());
}

}  // namespace impact3d::batch::lanes
