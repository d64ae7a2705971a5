// The certified scalar's arithmetic, comparisons and text (scalar/ball.hpp).
#include "impact3d/scalar/ball.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <new>
#include <stdexcept>

namespace impact3d {
namespace {

// An exact binary number as decimal text, `digits` significant digits, rounded as `rnd` says; `conv` is
// MPFR's conversion letter (g: shortest of fixed and scientific, e: scientific).
std::string arf_text(const arf_t x, int digits, mpfr_rnd_t rnd, char conv = 'g') {
  if (arf_is_nan(x)) return "nan";
  if (arf_is_inf(x)) return arf_sgn(x) > 0 ? "inf" : "-inf";
  mpfr_t m;
  mpfr_init2(m, std::max<long>(arf_bits(x), 2));
  arf_get_mpfr(m, x, MPFR_RNDN);  // exact: m holds every bit of x
  const char format[] = {'%', '.', '*', 'R', "NDUZ"[rnd == MPFR_RNDN ? 0 : rnd == MPFR_RNDD ? 1 : rnd == MPFR_RNDU ? 2 : 3], conv, 0};
  char* s = nullptr;
  const int n = mpfr_asprintf(&s, format, conv == 'e' ? digits - 1 : digits, m);
  mpfr_clear(m);
  if (n < 0 || !s) throw std::bad_alloc();
  std::string out(s);
  mpfr_free_str(s);
  return out;
}

Ball bound(const Ball& x, bool upper) {
  Ball r;
  arf_t b;
  arf_init(b);
  if (upper) arb_get_ubound_arf(b, x.get(), ARF_PREC_EXACT);
  else arb_get_lbound_arf(b, x.get(), ARF_PREC_EXACT);
  arb_set_arf(r.get(), b);
  arf_clear(b);
  return r;
}

// Digits d (d[0] nonzero, exponent e) as a plain decimal when it is short, else in scientific form.
std::string decimal_of(bool negative, const std::string& d, long e) {
  std::string s = negative ? "-" : "";
  const long n = static_cast<long>(d.size());
  // Plain only where no zero would be padded on: a padded zero would read as a certified digit.
  if (e >= 0 && e < 21 && n >= e + 1) {
    s += d.substr(0, static_cast<std::size_t>(e + 1));
    if (n > e + 1) s.append(".").append(d, static_cast<std::size_t>(e + 1));
  } else if (e < 0 && e > -7) {
    s += "0.";
    s.append(static_cast<std::size_t>(-e - 1), '0');
    s += d;
  } else {
    s += d.substr(0, 1);
    if (n > 1) s.append(".").append(d, 1);
    s.append("e").append(std::to_string(e));
  }
  return s;
}

std::string difference_detail(const Ball& d) {
  arf_t lo, hi;
  arf_init(lo);
  arf_init(hi);
  arb_get_lbound_arf(lo, d.get(), ARF_PREC_EXACT);
  arb_get_ubound_arf(hi, d.get(), ARF_PREC_EXACT);
  std::string s = "the difference lies in [" + arf_text(lo, 3, MPFR_RNDD, 'e') + ", " + arf_text(hi, 3, MPFR_RNDU, 'e') +
                  "] at " + std::to_string(ball_bits) + " bits";
  arf_clear(lo);
  arf_clear(hi);
  return s;
}

// FLINT and Arb keep per-thread caches (pi, powers of ten) until flint_cleanup: the main thread's are
// freed at exit, before a leak checker looks.
const int kCleanupAtExit = std::atexit(flint_cleanup);

}  // namespace

Ball::Ball(const std::string& decimal) {
  arb_init(x_);
  if (arb_set_str(x_, decimal.c_str(), ball_bits) != 0) {
    arb_clear(x_);
    throw std::invalid_argument("not a decimal number: " + decimal);
  }
}

Ball Ball::radius() const {
  Ball r;
  arb_get_rad_arb(r.x_, x_);
  return r;
}
Ball Ball::midpoint() const {
  Ball r;
  arb_get_mid_arb(r.x_, x_);
  return r;
}
Ball Ball::lower() const { return bound(*this, false); }
Ball Ball::upper() const { return bound(*this, true); }

Ball Ball::pi() {
  Ball r;
  arb_const_pi(r.x_, ball_bits);
  return r;
}

Ball Ball::hull(const Ball& a, const Ball& b) {
  Ball r;
  arb_union(r.x_, a.x_, b.x_, ball_bits);
  return r;
}

int Ball::precision_digits() { return static_cast<int>(std::ceil(static_cast<double>(ball_bits) * 0.30102999566398120)) + 1; }

void Ball::append_text(std::string& out, int digits) const {
  if (!finite()) {
    out += "nan";
    return;
  }
  const int d = std::clamp(digits, 1, precision_digits());
  switch (ball_text) {
    case BallText::midpoint: out += arf_text(arb_midref(x_), d, MPFR_RNDN); return;
    case BallText::lower: out += arf_text(arb_midref(lower().x_), d, MPFR_RNDD); return;
    case BallText::upper: out += arf_text(arb_midref(upper().x_), d, MPFR_RNDU); return;
    case BallText::certified: break;
  }
  if (exact() && arf_is_zero(arb_midref(x_))) {
    out += '0';
    return;
  }
  // The most digits n <= d to which every point of the ball rounds alike: its bounds do (rounding is
  // monotone). Fewer than asked: the radius says how far the value may lie.
  const Ball lo = lower(), hi = upper();
  bool found = false;
  for (int n = d; n >= 1 && !found; --n) {
    const std::string a = arf_text(arb_midref(lo.x_), n, MPFR_RNDN, 'e');
    if (a != arf_text(arb_midref(hi.x_), n, MPFR_RNDN, 'e')) continue;
    const bool negative = a[0] == '-';
    const auto epos = a.find('e');
    std::string digits;
    for (std::size_t k = negative ? 1 : 0; k < epos; ++k)
      if (a[k] != '.') digits += a[k];
    const std::string m = decimal_of(negative, digits, std::strtol(a.c_str() + epos + 1, nullptr, 10));
    out += m;
    if (n == d) return;
    // Fewer digits than asked: how far from the printed m the ball reaches, rounded up, so that
    // m(+-r) is itself an enclosure.
    const Ball printed(m);
    // Appended piece by piece, not "(+-" + a temporary: GCC 12's false -Wrestrict (PR 105329).
    out += "(+-";
    out += arf_text(arb_midref(hull(abs(printed - lo), abs(hi - printed)).upper().x_), 2, MPFR_RNDU);
    out += ')';
    found = true;
  }
  if (!found) {  // no digit shared: the bounds themselves, rounded outward
    out += '[';
    out += arf_text(arb_midref(lo.x_), 2, MPFR_RNDD);
    out += ", ";
    out += arf_text(arb_midref(hi.x_), 2, MPFR_RNDU);
    out += ']';
  }
}

double Ball::upper_double() const {
  if (!finite()) return std::numeric_limits<double>::infinity();
  return arf_get_d(arb_midref(upper().x_), ARF_RND_CEIL);
}

Ball operator+(const Ball& a, const Ball& b) {
  Ball r;
  arb_add(r.get(), a.get(), b.get(), ball_bits);
  return r;
}
Ball operator-(const Ball& a, const Ball& b) {
  Ball r;
  arb_sub(r.get(), a.get(), b.get(), ball_bits);
  return r;
}
Ball operator*(const Ball& a, const Ball& b) {
  Ball r;
  arb_mul(r.get(), a.get(), b.get(), ball_bits);
  return r;
}
Ball operator/(const Ball& a, const Ball& b) {
  Ball r;
  arb_div(r.get(), a.get(), b.get(), ball_bits);
  return r;
}

namespace {
// Whether d > 0 (strict) or d >= 0, recorded in the thread's decision log. Undecided, the answer is
// `prefer` where given, else the midpoints' (false for a NaN); the log's flip turns it.
bool decide(const Ball& d, bool strict, const bool* prefer, bool nan) {
  const bool yes = strict ? arb_is_positive(d.get()) : arb_is_nonnegative(d.get());
  const bool no = strict ? arb_is_nonpositive(d.get()) : arb_is_negative(d.get());
  DecisionLog* log = DecisionLog::current;
  const char* name = DecisionLog::current_name;
  if (yes || no) {
    if (log && name)
      log->record(name, arb_is_zero(d.get()) ? DecisionStatus::tie : DecisionStatus::decided, difference_detail(d));
    return yes;
  }
  const int c = arf_sgn(arb_midref(d.get()));
  bool answer = prefer ? *prefer : !nan && (strict ? c > 0 : c >= 0);
  if (!log) return answer;
  if (name && log->flip == name) answer = !answer;
  log->record(name ? name : decision_names::unnamed, DecisionStatus::undecided,
              difference_detail(d) + ", which contains 0; branch taken: " + (answer ? "true" : "false"));
  return answer;
}
}  // namespace

bool ball_less(const Ball& a, const Ball& b, bool strict) {
  Ball d;
  arb_sub(d.get(), b.get(), a.get(), ball_bits);  // a < b: b - a > 0
  return decide(d, strict, nullptr, arf_is_nan(arb_midref(a.get())) || arf_is_nan(arb_midref(b.get())));
}

bool ball_within(const Ball& x, const Ball& tol) {
  Ball magnitude, d;
  arb_abs(magnitude.get(), x.get());
  arb_sub(d.get(), tol.get(), magnitude.get(), ball_bits);  // |x| <= tol: tol - |x| >= 0
  const bool zero_inside = arb_contains_zero(x.get());
  return decide(d, false, zero_inside ? &zero_inside : nullptr,
                arf_is_nan(arb_midref(x.get())) || arf_is_nan(arb_midref(tol.get())));
}

namespace {
// f(r, x, ball_bits), as Arb's functions of one ball at a precision take it.
template <typename F>
Ball of_one(const Ball& x, F f) {
  Ball r;
  f(r.get(), x.get(), ball_bits);
  return r;
}
}  // namespace

Ball abs(const Ball& x) {
  Ball r;
  arb_abs(r.get(), x.get());
  return r;
}
Ball sqrt(const Ball& x) { return of_one(x, arb_sqrt); }
Ball sin(const Ball& x) { return of_one(x, arb_sin); }
Ball cos(const Ball& x) { return of_one(x, arb_cos); }
Ball acos(const Ball& x) { return of_one(x, arb_acos); }
Ball hypot(const Ball& a, const Ball& b) {
  Ball r;
  arb_hypot(r.get(), a.get(), b.get(), ball_bits);
  return r;
}
Ball atan2(const Ball& y, const Ball& x) {
  Ball r;
  arb_atan2(r.get(), y.get(), x.get(), ball_bits);
  return r;
}
Ball floor(const Ball& x) {
  Ball r;
  arf_t f;
  arf_init(f);
  arf_floor(f, arb_midref(x.get()));
  arb_set_arf(r.get(), f);
  arf_clear(f);
  return r;
}

// The eigenvalues of a symmetric 3x3 matrix in closed form (the trigonometric solution of its
// characteristic cubic): q + 2 p cos(phi + 2 pi k / 3), phi = acos(det((M - q I) / p) / 2) / 3. Where the
// cubic's roots nearly coincide the enclosure of phi is wide; the eigenvalues then still lie in
// [q - 2p, q + 2p], which bounds the condition. Arb's predicates, not the comparison operators: nothing
// here is a decision of the mechanics.
Ball EnclosureTraits<Ball>::spd_condition(const Mat3<Ball>& M) {
  const Ball three(3), two(2), six(6);
  auto sq = [](const Ball& x) {
    Ball r;
    arb_sqr(r.get(), x.get(), ball_bits);
    return r;
  };
  const Ball q = (M(0, 0) + M(1, 1) + M(2, 2)) / three;
  const Ball p1 = sq(M(0, 1)) + sq(M(0, 2)) + sq(M(1, 2));
  const Ball p2 = sq(M(0, 0) - q) + sq(M(1, 1) - q) + sq(M(2, 2) - q) + two * p1;
  if (arb_is_zero(p2.get())) return arb_is_positive(q.get()) ? Ball(1) : std::numeric_limits<Ball>::infinity();
  Ball p;
  arb_sqrtpos(p.get(), (p2 / six).get(), ball_bits);
  Mat3<Ball> B = M;
  for (int i = 0; i < 3; ++i) B(i, i) -= q;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) B(i, j) /= p;
  Ball r = B.determinant() / two;
  Ball unit;  // [-1, 1]: r is a cosine
  arb_zero(unit.get());
  mag_one(arb_radref(unit.get()));
  Ball clamped;
  if (arb_intersection(clamped.get(), r.get(), unit.get(), ball_bits)) r = clamped;
  const Ball phi = acos(r) / three;
  const Ball hi = q + two * p * cos(phi), lo = q + two * p * cos(phi + two * Ball::pi() / three);
  Ball kappa = hi / lo;
  if (!arb_is_positive(lo.get()) || !kappa.finite()) {
    const Ball floor_lo = q - two * p;
    if (!arb_is_positive(floor_lo.get())) return std::numeric_limits<Ball>::infinity();
    kappa = Ball::hull(Ball(1), (q + two * p) / floor_lo);
  }
  return kappa;
}

}  // namespace impact3d
