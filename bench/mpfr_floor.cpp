// What the 100-digit lean route (pc_crash_lean_100_digits in bench_peers.cpp: raw parameters to the
// pc-crash impulse, 64 seeded random collisions) asks of MPFR when every operation is an MPFR call (its
// numbers Boost's, as analyze computes), and what those operations cost by themselves: the time no other
// arrangement of the same computation can go below while each operation is a call into MPFR. The library's
// route computes the same numbers in FixedFloat (lean_twin.hpp), whose own +, - and x skip those calls;
// its time is printed beside. BENCHMARKS.md reads the table.
//
// The MPFR entry points the route reaches are defined here, counting each call before passing it on to
// the library's own (dlsym, RTLD_NEXT): the route is linked into this program, so its calls bind to
// these. The first pass records every operand; each operation is then timed alone on those operands,
// the same exponents, signs and cancellations the route met.
#include <dlfcn.h>
#include <mpfr.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <memory>
#include <vector>

#include <arb.h>

#include "impact3d/mechanics/lean.hpp"
#include "impact3d/scalar/multiprecision.hpp"
#include "impact3d/mechanics/raw_collision.hpp"
#include "peer_collisions.hpp"

namespace {

enum Op {
  kMul, kSqr, kAdd, kSub, kDiv, kSqrt, kFloor, kNeg, kAddUi, kSinCos, kMpfrSinCos,  // timed: the floor
  kCopy,                                                                           // timed, beside it
  kSetInt, kCompare, kScale, kAtan2, kGetD, kOps                                  // counted
};
const char* const kName[kOps] = {"mpfr_mul", "mpfr_sqr", "mpfr_add", "mpfr_sub", "mpfr_div", "mpfr_sqrt", "mpfr_floor",
                                 "mpfr_neg", "mpfr_add_ui (timed adding 1)", "sin_cos (Arb)",
                                 "mpfr_sin_cos (where Arb does not decide)", "mpfr_set (copy)",
                                 "integer constants and zeros", "comparisons", "mpfr_mul_2ui, mpfr_div_2ui", "mpfr_atan2",
                                 "mpfr_get_d"};
constexpr int kTimed = kCopy + 1;

bool counting = false, recording = false;
long calls[kOps] = {};
// Entry points in progress: MPFR calls its own exported functions through the same symbols, and only the
// route's calls, the outermost, are counted.
int depth = 0;

// An operand kept at its own precision.
struct Kept {
  mpfr_t x;
  explicit Kept(mpfr_srcptr v) {
    mpfr_init2(x, mpfr_get_prec(v));
    mpfr_set(x, v, MPFR_RNDN);
  }
  Kept(const Kept&) = delete;
  Kept& operator=(const Kept&) = delete;
  ~Kept() { mpfr_clear(x); }
};
struct Operands {
  std::unique_ptr<Kept> a, b;
};
std::vector<Operands> operands[kOps];

void note(Op op, mpfr_srcptr a, mpfr_srcptr b) {
  if (!counting) return;
  ++calls[op];
  if (!recording || op >= kTimed) return;
  counting = false;  // keeping them copies them, through the functions below
  operands[op].push_back({std::make_unique<Kept>(a), b ? std::make_unique<Kept>(b) : nullptr});
  counting = true;
}

// One call of an entry point: noted when it is the route's own.
struct Call {
  Call(Op op, mpfr_srcptr a = nullptr, mpfr_srcptr b = nullptr) {
    if (depth++ == 0) note(op, a, b);
  }
  ~Call() { --depth; }
  Call(const Call&) = delete;
  Call& operator=(const Call&) = delete;
};

// The library's own function: resolved at the first call, which may come before this file's statics.
template <typename F>
F next(const char* name) {
  return reinterpret_cast<F>(dlsym(RTLD_NEXT, name));
}
#define IMPACT3D_REAL(name, type)         \
  type real_##name() {                    \
    static const type f = next<type>(#name); \
    return f;                             \
  }
using Binary = int (*)(mpfr_ptr, mpfr_srcptr, mpfr_srcptr, mpfr_rnd_t);
using Unary = int (*)(mpfr_ptr, mpfr_srcptr, mpfr_rnd_t);
IMPACT3D_REAL(mpfr_mul, Binary)
IMPACT3D_REAL(mpfr_add, Binary)
IMPACT3D_REAL(mpfr_sub, Binary)
IMPACT3D_REAL(mpfr_div, Binary)
IMPACT3D_REAL(mpfr_sqr, Unary)
IMPACT3D_REAL(mpfr_sqrt, Unary)
IMPACT3D_REAL(mpfr_rint, Unary)
using Set4 = int (*)(mpfr_ptr, mpfr_srcptr, mpfr_rnd_t, int);
using SetUi = int (*)(mpfr_ptr, unsigned long, mpfr_exp_t, mpfr_rnd_t);
using SetSi = int (*)(mpfr_ptr, long, mpfr_exp_t, mpfr_rnd_t);
using Cmp3 = int (*)(mpfr_srcptr, mpfr_srcptr, int);
using ArbSinCos = void (*)(arb_t, arb_t, const arb_t, slong);
using SinCos = int (*)(mpfr_ptr, mpfr_ptr, mpfr_srcptr, mpfr_rnd_t);
using CmpSi = int (*)(mpfr_srcptr, long, mpfr_exp_t);
using Test2 = int (*)(mpfr_srcptr, mpfr_srcptr);
using Scale = int (*)(mpfr_ptr, mpfr_srcptr, unsigned long, mpfr_rnd_t);
using GetD = double (*)(mpfr_srcptr, mpfr_rnd_t);
IMPACT3D_REAL(mpfr_set4, Set4)
IMPACT3D_REAL(mpfr_set_ui_2exp, SetUi)
IMPACT3D_REAL(mpfr_set_si_2exp, SetSi)
IMPACT3D_REAL(mpfr_cmp3, Cmp3)
IMPACT3D_REAL(arb_sin_cos, ArbSinCos)
IMPACT3D_REAL(mpfr_neg, Unary)
IMPACT3D_REAL(mpfr_sin_cos, SinCos)
IMPACT3D_REAL(mpfr_cmp_si_2exp, CmpSi)
IMPACT3D_REAL(mpfr_equal_p, Test2)
IMPACT3D_REAL(mpfr_mul_2ui, Scale)
IMPACT3D_REAL(mpfr_div_2ui, Scale)
IMPACT3D_REAL(mpfr_add_ui, Scale)
IMPACT3D_REAL(mpfr_atan2, Binary)
IMPACT3D_REAL(mpfr_get_d, GetD)
#undef IMPACT3D_REAL

}  // namespace

extern "C" {
int mpfr_mul(mpfr_ptr r, mpfr_srcptr a, mpfr_srcptr b, mpfr_rnd_t m) {
  const Call call(kMul, a, b);
  return real_mpfr_mul()(r, a, b, m);
}
int mpfr_add(mpfr_ptr r, mpfr_srcptr a, mpfr_srcptr b, mpfr_rnd_t m) {
  const Call call(kAdd, a, b);
  return real_mpfr_add()(r, a, b, m);
}
int mpfr_sub(mpfr_ptr r, mpfr_srcptr a, mpfr_srcptr b, mpfr_rnd_t m) {
  const Call call(kSub, a, b);
  return real_mpfr_sub()(r, a, b, m);
}
int mpfr_div(mpfr_ptr r, mpfr_srcptr a, mpfr_srcptr b, mpfr_rnd_t m) {
  const Call call(kDiv, a, b);
  return real_mpfr_div()(r, a, b, m);
}
int mpfr_sqr(mpfr_ptr r, mpfr_srcptr a, mpfr_rnd_t m) {
  const Call call(kSqr, a);
  return real_mpfr_sqr()(r, a, m);
}
int mpfr_sqrt(mpfr_ptr r, mpfr_srcptr a, mpfr_rnd_t m) {
  const Call call(kSqrt, a);
  return real_mpfr_sqrt()(r, a, m);
}
int mpfr_rint(mpfr_ptr r, mpfr_srcptr a, mpfr_rnd_t m) {
  const Call call(kFloor, a);
  return real_mpfr_rint()(r, a, m);
}
int mpfr_neg(mpfr_ptr r, mpfr_srcptr a, mpfr_rnd_t m) {
  const Call call(kNeg, a);
  return real_mpfr_neg()(r, a, m);
}
int mpfr_sin_cos(mpfr_ptr s, mpfr_ptr c, mpfr_srcptr x, mpfr_rnd_t m) {
  const Call call(kMpfrSinCos, x);
  return real_mpfr_sin_cos()(s, c, x, m);
}
int mpfr_set4(mpfr_ptr r, mpfr_srcptr a, mpfr_rnd_t m, int s) {
  const Call call(kCopy, a);
  return real_mpfr_set4()(r, a, m, s);
}
int mpfr_set_ui_2exp(mpfr_ptr r, unsigned long i, mpfr_exp_t e, mpfr_rnd_t m) {
  const Call call(kSetInt);
  return real_mpfr_set_ui_2exp()(r, i, e, m);
}
int mpfr_set_si_2exp(mpfr_ptr r, long i, mpfr_exp_t e, mpfr_rnd_t m) {
  const Call call(kSetInt);
  return real_mpfr_set_si_2exp()(r, i, e, m);
}
int mpfr_cmp3(mpfr_srcptr a, mpfr_srcptr b, int s) {
  const Call call(kCompare);
  return real_mpfr_cmp3()(a, b, s);
}
int mpfr_cmp_si_2exp(mpfr_srcptr a, long i, mpfr_exp_t e) {
  const Call call(kCompare);
  return real_mpfr_cmp_si_2exp()(a, i, e);
}
int mpfr_equal_p(mpfr_srcptr a, mpfr_srcptr b) {
  const Call call(kCompare);
  return real_mpfr_equal_p()(a, b);
}
int mpfr_mul_2ui(mpfr_ptr r, mpfr_srcptr a, unsigned long i, mpfr_rnd_t m) {
  const Call call(kScale);
  return real_mpfr_mul_2ui()(r, a, i, m);
}
int mpfr_div_2ui(mpfr_ptr r, mpfr_srcptr a, unsigned long i, mpfr_rnd_t m) {
  const Call call(kScale);
  return real_mpfr_div_2ui()(r, a, i, m);
}
int mpfr_add_ui(mpfr_ptr r, mpfr_srcptr a, unsigned long i, mpfr_rnd_t m) {
  const Call call(kAddUi, a);
  return real_mpfr_add_ui()(r, a, i, m);
}
int mpfr_atan2(mpfr_ptr r, mpfr_srcptr a, mpfr_srcptr b, mpfr_rnd_t m) {
  const Call call(kAtan2);
  return real_mpfr_atan2()(r, a, b, m);
}
double mpfr_get_d(mpfr_srcptr a, mpfr_rnd_t m) {
  const Call call(kGetD);
  return real_mpfr_get_d()(a, m);
}
// One for each sine-cosine pair (numeric/scalar/src/mpfr_sin_cos.cpp), which is what is timed.
void arb_sin_cos(arb_t s, arb_t c, const arb_t x, slong prec) {
  if (counting && depth == 0) {
    ++calls[kSinCos];
    if (recording) {
      counting = false;
      mpfr_t mid;
      mpfr_init2(mid, prec - 32);  // the result's precision: mpfr_sin_cos.cpp encloses at 32 bits more
      arf_get_mpfr(mid, arb_midref(x), MPFR_RNDN);
      operands[kSinCos].push_back({std::make_unique<Kept>(mid), nullptr});
      mpfr_clear(mid);
      counting = true;
    }
  }
  real_arb_sin_cos()(s, c, x, prec);
}
}

namespace {

using namespace impact3d;
using F = mp::float100;

template <typename Fn>
double best_ns(Fn&& run, std::size_t n) {
  double best = 1e300;
  for (int r = 0; r < 15; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    run();
    const std::chrono::duration<double, std::nano> took = std::chrono::steady_clock::now() - t0;
    best = std::min(best, took.count() / double(n));
  }
  return best;
}

// One call of op on each recorded operand (or pair), into results of the first operand's precision. In
// groups of 64 operands, each group timed on its own best run: in the route an operand has just been
// computed and is in the cache, and so it is here (timed across all 30 000 of them at once, the loads
// from memory doubled the time of an addition).
template <typename Call>
double time_calls(const std::vector<Operands>& ops, Call call) {
  mpfr_t r, r2;
  mpfr_init2(r, mpfr_get_prec(ops[0].a->x));
  mpfr_init2(r2, mpfr_get_prec(ops[0].a->x));
  double total = 0;
  for (std::size_t begin = 0; begin < ops.size(); begin += 64) {
    const std::size_t end = std::min(ops.size(), begin + 64);
    total += best_ns(
                 [&] {
                   for (std::size_t k = begin; k < end; ++k) {
                     call(r, r2, ops[k].a->x, ops[k].b ? ops[k].b->x : nullptr);
                     asm volatile("" ::"r"(r), "r"(r2) : "memory");
                   }
                 },
                 1) ;
  }
  mpfr_clear(r);
  mpfr_clear(r2);
  return total / double(ops.size());
}

double time_op(Op op) {
  const auto& ops = operands[op];
  if (ops.empty()) return 0;
  const auto binary = [&](Binary f) {
    return time_calls(ops, [f](mpfr_ptr r, mpfr_ptr, mpfr_srcptr a, mpfr_srcptr b) { f(r, a, b, MPFR_RNDN); });
  };
  const auto unary = [&](Unary f, mpfr_rnd_t m) {
    return time_calls(ops, [f, m](mpfr_ptr r, mpfr_ptr, mpfr_srcptr a, mpfr_srcptr) { f(r, a, m); });
  };
  switch (op) {
    case kMul: return binary(real_mpfr_mul());
    case kAdd: return binary(real_mpfr_add());
    case kSub: return binary(real_mpfr_sub());
    case kDiv: return binary(real_mpfr_div());
    case kSqr: return unary(real_mpfr_sqr(), MPFR_RNDN);
    case kSqrt: return unary(real_mpfr_sqrt(), MPFR_RNDN);
    case kFloor: return unary(real_mpfr_rint(), MPFR_RNDD);
    case kNeg: return unary(real_mpfr_neg(), MPFR_RNDN);
    case kAddUi: {
      const Scale f = real_mpfr_add_ui();
      return time_calls(ops, [f](mpfr_ptr r, mpfr_ptr, mpfr_srcptr a, mpfr_srcptr) { f(r, a, 1, MPFR_RNDN); });
    }
    case kSinCos: return time_calls(ops, [](mpfr_ptr s, mpfr_ptr c, mpfr_srcptr a, mpfr_srcptr) { mp::sin_cos(s, c, a); });
    case kMpfrSinCos: {
      const SinCos f = real_mpfr_sin_cos();
      return time_calls(ops, [f](mpfr_ptr s, mpfr_ptr c, mpfr_srcptr a, mpfr_srcptr) { f(s, c, a, MPFR_RNDN); });
    }
    case kCopy: {
      const Set4 f = real_mpfr_set4();
      return time_calls(ops, [f](mpfr_ptr r, mpfr_ptr, mpfr_srcptr a, mpfr_srcptr) { f(r, a, MPFR_RNDN, mpfr_signbit(a) ? -1 : 1); });
    }
    default: return 0;
  }
}

}  // namespace

int main() {
  auto cs = bench::random_collisions(1024, 11);  // bench_peers.cpp's collisions, its first 64
  std::vector<RawCollision<F>> raw;
  std::vector<F> mu;
  for (std::size_t k = 0; k < 64; ++k) {
    cs[k].mu = 0.5, cs[k].restitution = 0.1;
    raw.push_back(bench::raw_as<F>(bench::raw_of(cs[k])));
    mu.push_back(F(cs[k].mu));
  }
  // The route with Boost's numbers throughout: the scene and the solve in the scalar's own arithmetic.
  const auto route = [&] {
    int solved = 0;
    for (std::size_t k = 0; k < raw.size(); ++k)
      solved += solve_lean_with<GeneratedEngine>(compute_scene(raw[k]), Strategy<F>(PcCrash<F>{mu[k]}), Want::impulse).status ==
                Status::solved;
    return solved;
  };
  const auto twin_route = [&] {
    int solved = 0;
    for (std::size_t k = 0; k < raw.size(); ++k)
      solved += solve_lean(raw[k], Strategy<F>(PcCrash<F>{mu[k]}), Want::impulse, Engine::generated).status == Status::solved;
    return solved;
  };
  route();  // the constants built once per type are not the route's
  counting = recording = true;
  const int solved = route();
  counting = recording = false;
  const double route_ns = best_ns(route, raw.size());
  if (twin_route() != solved) {
    std::fprintf(stderr, "the two routes solved different numbers of collisions\n");
    return 1;
  }
  const double twin_ns = best_ns(twin_route, raw.size());

  const double n = double(raw.size());
  std::printf("100-digit lean route, raw parameters to the pc-crash impulse: %zu collisions (%d solved), MPFR at %ld bits\n",
              raw.size(), solved, static_cast<long>(mpfr_get_prec(operands[kMul].at(0).a->x)));
  std::printf("%-42s %10s %10s %12s\n", "operation", "per case", "ns each", "us per case");
  double floor_us = 0, copies_us = 0;
  for (int op = 0; op < kOps; ++op) {
    if (op >= kTimed) {
      std::printf("%-42s %10.1f %10s %12s\n", kName[op], calls[op] / n, "", "");
      continue;
    }
    const double each = time_op(Op(op)), us = calls[op] / n * each / 1000;
    (op == kCopy ? copies_us : floor_us) += us;
    std::printf("%-42s %10.1f %10.1f %12.2f\n", kName[op], calls[op] / n, each, us);
  }
  std::printf("arithmetic and sines alone: %.1f us a case; copies %.1f us; the route itself %.1f us\n", floor_us,
              copies_us, route_ns / 1000);
  std::printf("the library's route (solve_lean, the same numbers in FixedFloat): %.1f us a case\n", twin_ns / 1000);
}
