// Compiled with -ffp-contract=off (numeric/CMakeLists.txt): a fused multiply-add would round once where
// the source rounds twice, and the samples would differ between machines that have FMA and those that
// do not.
#include "impact3d/uncertainty/portable_math.hpp"

#include <cfloat>
#include <cmath>
#include <limits>

static_assert(FLT_EVAL_METHOD == 0, "double expressions must be evaluated in double (no x87 excess precision)");
static_assert(std::numeric_limits<double>::is_iec559);

namespace impact3d::uncertainty {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
// ln 2 split so that k * kLn2Hi is exact for |k| < 2^20 (kLn2Hi has 32 significant bits), as in fdlibm.
constexpr double kLn2Hi = 6.93147180369123816490e-01, kLn2Lo = 1.90821492927058770002e-10;
constexpr double kInvLn2 = 1.44269504088896338700e+00;

// p(x) = c[0] + c[1] x + ... + c[n-1] x^(n-1), Horner's order.
template <int N>
double horner(const double (&c)[N], double x) {
  double v = c[N - 1];
  for (int i = N - 2; i >= 0; --i) v = v * x + c[i];
  return v;
}

// Cody's erfc(y) = e^(-y^2) P(y) / Q(y) for y = x / sqrt 2 in [0.46875, 4] (Math. Comp. 23 (1969)
// 631-637, table III, about 18 digits): P(y) / Q(y), so that erfc(y) = e^(-x^2/2) times it.
double cody_ratio(double x) {
  static constexpr double p[9] = {1.23033935479799725272e3, 2.05107837782607146532e3, 1.71204761263407058314e3,
                                  8.81952221241769090411e2, 2.98635138197400131132e2, 6.61191906371416294775e1,
                                  8.88314979438837594118e0, 5.64188496988670089180e-1, 2.15311535474403846343e-8};
  static constexpr double q[9] = {1.23033935480374942043e3, 3.43936767414372163696e3, 4.36261909014324715820e3,
                                  3.29079923573345962678e3, 1.62138957456669018874e3, 5.37181101862009857509e2,
                                  1.17693950891312499305e2, 1.57449261107098347253e1, 1.0};
  const double y = x * 0.70710678118654752440;
  return horner(p, y) / horner(q, y);
}

// Laplace's continued fraction Q = phi / (x + 1/(x + 2/(x + 3/(x + ...)))), from a fixed depth up:
// at x = 5.5 its 60th convergent is well within 2^-56.
double laplace_fraction(double x) {
  double f = x;
  for (int k = 60; k >= 1; --k) f = x + k / f;
  return f;
}

}  // namespace

double portable_log(double x) {
  if (!(x > 0)) return x == 0 ? -kInf : kNaN;
  if (x == kInf) return kInf;
  int e = 0;
  double m = std::frexp(x, &e);  // exact: x = m 2^e, m in [1/2, 1)
  if (m < 0.70710678118654752440) m *= 2, --e;
  // ln(1 + f) = 2 atanh(s) with s = f / (2 + f), arranged as fdlibm's e_log.c arranges it so that the
  // large terms are exact: f - (f^2/2 - s (f^2/2 + R)), R = sum 2 z^k / (2k + 1), z = s^2 <= 0.0295
  // (eleven terms reach 2^-56).
  const double f = m - 1, hfsq = 0.5 * f * f, s = f / (2 + f), z = s * s;
  static constexpr double kSeries[11] = {2.0 / 3,  2.0 / 5,  2.0 / 7,  2.0 / 9,  2.0 / 11, 2.0 / 13,
                                         2.0 / 15, 2.0 / 17, 2.0 / 19, 2.0 / 21, 2.0 / 23};
  const double R = z * horner(kSeries, z);
  return e * kLn2Hi - ((hfsq - (s * (hfsq + R) + e * kLn2Lo)) - f);
}

double portable_exp(double x) {
  if (x != x) return x;
  if (x > 709.782712893383973096) return kInf;
  if (x < -745.133219101941108420) return 0;
  // x = k ln 2 + r, |r| <= ln 2 / 2 (plus a rounding); e^r by its Taylor series to r^16/16!.
  const double k = std::floor(x * kInvLn2 + 0.5);
  const double r = (x - k * kLn2Hi) - k * kLn2Lo;
  double v = 1;
  for (int n = 16; n >= 1; --n) v = 1 + v * r / n;
  return std::ldexp(v, static_cast<int>(k));
}

double normal_quantile(double p) {
  if (!(p > 0 && p < 1)) return kNaN;
  static constexpr double a[8] = {3.3871328727963666080e0,  1.3314166789178437745e+2, 1.9715909503065514427e+3,
                                  1.3731693765509461125e+4, 4.5921953931549871457e+4, 6.7265770927008700853e+4,
                                  3.3430575583588128105e+4, 2.5090809287301226727e+3};
  static constexpr double b[8] = {1.0,                      4.2313330701600911252e+1, 6.8718700749205790830e+2,
                                  5.3941960214247511077e+3, 2.1213794301586595867e+4, 3.9307895800092710610e+4,
                                  2.8729085735721942674e+4, 5.2264952788528545610e+3};
  static constexpr double c[8] = {1.42343711074968357734e0,  4.63033784615654529590e0,  5.76949722146069140550e0,
                                  3.64784832476320460504e0,  1.27045825245236838258e0,  2.41780725177450611770e-1,
                                  2.27238449892691845833e-2, 7.74545014278341407640e-4};
  static constexpr double d[8] = {1.0,                       2.05319162663775882187e0,  1.67638483018380384940e0,
                                  6.89767334985100004550e-1, 1.48103976427480074590e-1, 1.51986665636164571966e-2,
                                  5.47593808499534494600e-4, 1.05075007164441684324e-9};
  static constexpr double e[8] = {6.65790464350110377720e0,  5.46378491116411436990e0,  1.78482653991729133580e0,
                                  2.96560571828504891230e-1, 2.65321895265761230930e-2, 1.24266094738807843860e-3,
                                  2.71155556874348757815e-5, 2.01033439929228813265e-7};
  static constexpr double f[8] = {1.0,                       5.99832206555887937690e-1, 1.36929880922735805310e-1,
                                  1.48753612908506148525e-2, 7.86869131145613259100e-4, 1.84631831751005468180e-5,
                                  1.42151175831644588870e-7, 2.04426310338993978564e-15};
  const double q = p - 0.5;
  if (std::fabs(q) <= 0.425) {
    const double r = 0.180625 - q * q;
    return q * horner(a, r) / horner(b, r);
  }
  // The tail: r = sqrt(-ln(min(p, 1 - p))); 1 - p is exact here (p >= 0.925, Sterbenz).
  double r = std::sqrt(-portable_log(q < 0 ? p : 1 - p));
  const double v = r <= 5 ? (r -= 1.6, horner(c, r) / horner(d, r)) : (r -= 5, horner(e, r) / horner(f, r));
  return q < 0 ? -v : v;
}

double normal_upper_tail(double x) {
  if (x != x) return x;
  if (x < 0) return 1 - normal_upper_tail(-x);
  if (x > 38.5) return 0;  // below the smallest subnormal
  // phi(x) with x^2 split so that the large part of the exponent is exact: x = h + l, h with 22 bits.
  const double h = std::ldexp(std::floor(std::ldexp(x, 16)), -16), l = x - h;
  const double gauss = portable_exp(-0.5 * h * h) * portable_exp(-0.5 * l * (x + h)), phi = 0.39894228040143267794 * gauss;
  if (x < 0.6640625) {
    // Q = 1/2 - phi(x) (x + x^3/3 + x^5/(3 5) + ...): positive terms; Q >= 1/4 here, so the
    // subtraction loses at most a bit.
    double term = x, sum = x;
    for (int n = 1; n < 60 && term > sum * 0x1p-56; ++n) {
      term *= x * x / (2 * n + 1);
      sum += term;
    }
    return 0.5 - phi * sum;
  }
  if (x < 5.5) {  // Cody's erfc, with e^(-y^2) = e^(-x^2/2) taken from x itself
    return 0.5 * gauss * cody_ratio(x);
  }
  return phi / laplace_fraction(x);
}

double normal_cdf(double x) { return normal_upper_tail(-x); }

double normal_mills_ratio(double x) {
  if (!(x >= 0)) return kNaN;
  if (x == kInf) return 0;
  if (x < 0.6640625) {  // 1/(2 phi) less the series of normal_upper_tail; phi >= 0.32 here
    double term = x, sum = x;
    for (int n = 1; n < 60 && term > sum * 0x1p-56; ++n) {
      term *= x * x / (2 * n + 1);
      sum += term;
    }
    return 1.25331413731550025121 * portable_exp(0.5 * x * x) - sum;
  }
  if (x < 5.5) return 1.25331413731550025121 * cody_ratio(x);  // sqrt(pi/2) P/Q
  return 1 / laplace_fraction(x);
}

}  // namespace impact3d::uncertainty
