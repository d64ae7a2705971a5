// The lean solve (mechanics/lean.hpp) against analyze: the same strategy code on the same Problem, so the
// impulse, the regime, the ratios and the post-impact velocities must be equal bit for bit, and the
// warnings the same codes, although the lean path bounds the condition of K instead of computing it
// and computes it only when a decision falls within the bound. Seeded random collisions, every
// strategy, both engines, double, long double and 100 digits; the lanes of ordinary outcomes (not approaching, a
// singular system) become a status, and no case allocates.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <new>
#include <random>
#include <stdexcept>
#include <string>

#include "impact3d/mechanics/lean.hpp"
#include "impact3d/scalar/multiprecision.hpp"
#include "impact3d/mechanics/rotation.hpp"
#include "support.hpp"

// Every allocation of the program (mechanics_tests: a replacement is global) is counted, so that the
// lean path's "no heap per case" is measured.
// Not under AddressSanitizer, whose own operator new this replacement would mismatch: that build runs
// the comparisons only.
#ifndef IMPACT3D_SANITIZED
namespace {
std::atomic<long> allocations{0};
}  // namespace

void* operator new(std::size_t n) {
  ++allocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
#endif

namespace check_lean {

using namespace impact3d;
using namespace impact3d::test;

namespace {

template <typename T>
Scene<T> cast_scene(const Scene<double>& s) {
  Scene<T> t;
  for (int i = 0; i < 2; ++i) {
    const RigidBody<double>& b = s.body[i];
    t.body[i] = {T(b.mass), b.J_B.cast<T>(), b.R_WB.cast<T>(), b.v_W.cast<T>(), b.w_B.cast<T>(), b.p_CgIc_B.cast<T>()};
  }
  t.R_WC = s.R_WC.cast<T>();
  t.restitution = T(s.restitution);
  return t;
}

template <typename T>
Strategy<T> cast_strategy(const Strategy<double>& st) {
  if (auto* pc = std::get_if<PcCrash<double>>(&st)) return PcCrash<T>{T(pc->mu)};
  if (auto* w = std::get_if<Wach<double>>(&st)) return Wach<T>{T(w->mu), w->limit};
  const auto& b = std::get<Brach<double>>(st);
  auto opt = [](const std::optional<double>& x) { return x ? std::optional<T>(T(*x)) : std::optional<T>(); };
  return Brach<T>{opt(b.mu_t), opt(b.mu_z)};
}

WarningSet codes_of(const std::vector<Warning>& ws) {
  WarningSet set = 0;
  for (const Warning& w : ws) set |= warning_bit(w.code);
  return set;
}

// Equal and of the same sign (an exact zero's too: at 100 digits the lean path computes in
// FixedFloat, analyze in Boost's numbers), or both NaN.
template <typename T>
bool identical(const T& a, const T& b) {
  using std::signbit;
  return (a == b && signbit(a) == signbit(b)) || (a != a && b != b);
}
template <typename T, int R>
bool identical(const Eigen::Matrix<T, R, 1>& a, const Eigen::Matrix<T, R, 1>& b) {
  for (int i = 0; i < R; ++i)
    if (!identical(a(i), b(i))) return false;
  return true;
}
template <typename T>
bool same(const std::optional<T>& a, const std::optional<T>& b) {
  return a.has_value() == b.has_value() && (!a || identical(*a, *b));
}

// How many solutions of each Regime were compared.
using RegimeCounts = std::array<int, 4>;

// One scene and strategy both ways; true when a solution was compared (counted by its regime).
template <typename T>
bool compare(const Scene<T>& s, const Strategy<T>& st, Engine engine, RegimeCounts* regimes = nullptr) {
  const LeanSolution<T> lean = solve_lean(s, st, Want::velocities, engine);
  Analysis<T> a;
  try {
    a = analyze(s, {st}, engine);
  } catch (const SolveError& e) {
    INFO(e.what());
    CHECK(lean.status != Status::solved);
    if (lean.status == Status::not_approaching) CHECK(std::string(e.what()).find("not approaching") != std::string::npos);
    if (lean.status == Status::singular) CHECK(std::string(e.what()).rfind(lean.singular, 0) == 0);
    return false;
  }
  REQUIRE(lean.status == Status::solved);
  const Solution<T>& sol = a.solutions.at(0);
  const ImpulseSolution<T>& imp = sol.impulse;
  CHECK(identical(lean.impulse.P_C, imp.P_C));
  CHECK(lean.impulse.regime == imp.regime);
  CHECK(same(lean.impulse.mu, imp.mu));
  CHECK(same(lean.impulse.gir, imp.gir));
  CHECK(same(lean.impulse.cir, imp.cir));
  CHECK(same(lean.impulse.mu_t_critical, imp.mu_t_critical));
  CHECK(same(lean.impulse.mu_z_critical, imp.mu_z_critical));
  CHECK(lean.impulse.warnings.empty());  // no text on the lean path
  CHECK(identical(lean.P_W, sol.P_W));
  for (int i = 0; i < 2; ++i) {
    CHECK(identical(lean.v_W[i], sol.after[i].v_W));
    CHECK(identical(lean.w_B[i], sol.after[i].w_B));
  }
  // Every code analyze gives but energy_gained, which needs the energies the lean path does not compute.
  CHECK(lean.warnings == (codes_of(sol.warnings) & ~warning_bit(WarningCode::energy_gained)));
  // The impulse alone: the same impulse, and the same codes but a not_finite that only the velocities
  // can give.
  const LeanSolution<T> alone = solve_lean(s, st, Want::impulse, engine);
  CHECK(identical(alone.impulse.P_C, imp.P_C));
  CHECK((alone.warnings | warning_bit(WarningCode::not_finite)) == (lean.warnings | warning_bit(WarningCode::not_finite)));
  if (regimes) ++(*regimes)[static_cast<std::size_t>(imp.regime)];
  return true;
}

}  // namespace

TEMPLATE_TEST_CASE("solve_lean gives analyze's impulse, ratios, velocities and warning codes, bit for bit", "[lean]",
                   double, long double, mp::float100) {
  std::mt19937_64 g(20261121);
  std::uniform_real_distribution<double> u(0, 1);
  int compared = 0, undecided = 0, not_approaching = 0;
  RegimeCounts regimes{};
  for (int c = 0; c < 150; ++c) {
    Scene<double> s = random_scene(g);
    if (c % 10 == 9)  // the bodies separating at the impulse centre: a status, not an exception
      for (auto& b : s.body) b.v_W = -b.v_W, b.w_B = -b.w_B;
    const Scene<TestType> t = cast_scene<TestType>(s);
    for (const Strategy<double>& st : every_strategy(0.05 + 1.2 * u(g)))
      for (Engine e : kEngines) compared += compare(t, cast_strategy<TestType>(st), e, &regimes);
    if (c % 10 == 9) {
      ++not_approaching;
      CHECK(solve_lean(t, cast_strategy<TestType>(every_strategy(0.5)[0])).status == Status::not_approaching);
      continue;
    }
    // mu exactly at the GIR and at Wach's CIR: the decision falls within the bound, so the lean path
    // computes kappa(K) as analyze does and gives the same undecided warning.
    const auto a = analyze(t, {PcCrash<TestType>{0}, Wach<TestType>{0}});
    for (Engine e : kEngines) {
      const auto pc = solve_lean(t, Strategy<TestType>(PcCrash<TestType>{*a.solutions[0].impulse.gir}), Want::impulse, e);
      const auto w = solve_lean(t, Strategy<TestType>(Wach<TestType>{*a.solutions[1].impulse.cir}), Want::impulse, e);
      undecided += has_warning(pc.warnings, WarningCode::undecided) && has_warning(w.warnings, WarningCode::undecided);
      compared += compare(t, Strategy<TestType>(PcCrash<TestType>{*a.solutions[0].impulse.gir}), e);
      compared += compare(t, Strategy<TestType>(Wach<TestType>{*a.solutions[1].impulse.cir}), e);
    }
  }
  // 135 approaching scenes x (10 strategies + 2 at the threshold) x 2 engines; 15 separating x 10 x 2
  // refused alike.
  CHECK(not_approaching == 15);
  CHECK(compared == 135 * 12 * 2);
  CHECK(undecided == 135 * 2);
  // Every regime was among them: pc-crash's full and sliding, Wach's capped and sliding, Brach's as given.
  INFO("full " << regimes[0] << ", sliding " << regimes[1] << ", capped " << regimes[2] << ", as given " << regimes[3]);
  for (int n : regimes) CHECK(n > 0);
  CHECK(regimes[0] + regimes[1] + regimes[2] + regimes[3] == 135 * 10 * 2);
  CHECK(regimes[3] == 135 * 4 * 2);
}

TEMPLATE_TEST_CASE("solve_lean decides as analyze does on both sides of the undecided band, and on ill-conditioned K",
                   "[lean]", double, long double, mp::float100) {
  // mu = GIR (1 + k eps) and Wach's mu = CIR (1 + k eps) for k from 1 to 2^40 either way, through the
  // band where a decision is undecided and out of it on every scene (counted), and so through the band
  // where the lean path's cheap bound on kappa(K) calls the decision close and it must compute kappa.
  // Half the scenes have an ill-conditioned K (one body 10^6 times lighter and smaller, impulse centre
  // far out), where the bounds are wide.
  std::mt19937_64 g(20261122);
  const TestType eps = std::numeric_limits<TestType>::epsilon();
  int compared = 0, scenes = 0, straddled = 0, undecided = 0, decided = 0;
  std::string one_sided;  // the scenes the sweep did not take across the band, for the failure's message
  for (int c = 0; c < 40; ++c) {
    Scene<double> s = random_scene(g);
    if (c % 2) {
      s.body[1].mass *= 1e-6;
      s.body[1].J_B *= 1e-9;
      s.body[1].p_CgIc_B *= 40;
    }
    const Scene<TestType> t = cast_scene<TestType>(s);
    if (!(relative_velocity_C(t).x() > 0)) continue;  // not approaching: nothing to decide
    ++scenes;
    const auto a = analyze(t, {PcCrash<TestType>{0}, Wach<TestType>{0}});
    REQUIRE(a.solutions[0].impulse.gir.has_value());
    REQUIRE(a.solutions[1].impulse.cir.has_value());
    const TestType gir = *a.solutions[0].impulse.gir, cir = *a.solutions[1].impulse.cir;
    const int undecided_before = undecided, decided_before = decided;
    for (int sign : {-1, 1})
      for (int e2 = 0; e2 <= 40; e2 += 2) {
        using std::ldexp;
        const TestType f = 1 + sign * ldexp(eps, e2);
        for (const Strategy<TestType>& st : {Strategy<TestType>(PcCrash<TestType>{gir * f}), Strategy<TestType>(Wach<TestType>{cir * f})})
          for (Engine e : kEngines) {
            compared += compare(t, st, e);
            (has_warning(solve_lean(t, st, Want::impulse, e).warnings, WarningCode::undecided) ? undecided : decided)++;
          }
      }
    const bool both = undecided > undecided_before && decided > decided_before;
    straddled += both;
    if (!both)
      one_sided += "scene " + std::to_string(c) + ": " + std::to_string(undecided - undecided_before) +
                   " undecided, " + std::to_string(decided - decided_before) + " decided; ";
  }
  INFO(scenes << " scenes, " << undecided << " undecided, " << decided << " decided; " << one_sided);
  CHECK(scenes >= 30);
  CHECK(compared == scenes * 2 * 21 * 2 * 2);
  CHECK(straddled == scenes);  // on every scene the sweep reaches into the band and out of it
}

TEMPLATE_TEST_CASE("solve_lean decides as analyze does when an inertia tensor is nearly singular (a rod)", "[lean]", double,
                   long double, mp::float100) {
  // One body's inertia about its axis 10^-12 of the others (kappa(K) about 10^15): the bounds the lean
  // path starts from must still be bounds (an independent review found the double bound at 100 digits
  // below kappa here, and a decision taken on it that analyze calls undecided). mu = GIR (1 + 2^-k)
  // either way for k across the type's digits, through the undecided band and out of it.
  std::mt19937_64 g(20261127);
  const int digits = std::numeric_limits<TestType>::digits;
  int compared = 0, tried = 0, scenes = 0, singular = 0, undecided = 0, decided = 0;
  for (int c = 0; c < 12; ++c) {
    Scene<double> s = random_scene(g);
    s.body[1].J_B = Mat3<double>(Vec3<double>(2500, 2500, 1e-12).asDiagonal());
    const Scene<TestType> t = cast_scene<TestType>(s);
    if (!(relative_velocity_C(t).x() > 0)) continue;
    Analysis<TestType> a;
    try {
      a = analyze(t, {PcCrash<TestType>{0}});
    } catch (const SolveError&) {  // K singular as far as the type can tell
      ++singular;
      continue;
    }
    ++scenes;
    REQUIRE(a.solutions[0].impulse.gir.has_value());
    const TestType gir = *a.solutions[0].impulse.gir;
    for (int sign : {-1, 1})
      for (int k = 1; k <= digits; k += digits / 32) {
        using std::ldexp;
        const Strategy<TestType> st(PcCrash<TestType>{gir * (1 + sign * ldexp(TestType(1), -k))});
        for (Engine e : kEngines) {
          compared += compare(t, st, e);  // solved both ways and equal, or refused both ways
          ++tried;
          (has_warning(solve_lean(t, st, Want::impulse, e).warnings, WarningCode::undecided) ? undecided : decided)++;
        }
      }
  }
  INFO(scenes << " scenes, " << singular << " singular, " << undecided << " undecided, " << decided << " decided");
  CHECK(scenes >= 6);  // at double, K of some is singular as far as the type can tell
  CHECK(undecided > 0);
  CHECK(decided > 0);
  CHECK(tried == scenes * 2 * ((digits - 1) / (digits / 32) + 1) * 2);  // signs, k, engines
  CHECK(compared > tried / 2);
}

TEST_CASE("solve_lean reports an undefined plane, a singular system and a separating contact as analyze does",
          "[lean]") {
  // Head-on along the contact normal, impulse centres on it, no rotation: no sliding at all, so Wach's
  // plane (eq 21) is undefined, and the Full Impact has no contact-plane impulse (eq 15 undefined).
  Scene<double> s;
  for (int i = 0; i < 2; ++i) {
    s.body[i] = {1500.0, Mat3<double>(Vec3<double>(500, 2500, 2800).asDiagonal()), Mat3<double>::Identity(),
                 Vec3<double>(i == 0 ? -10 : 10, 0, 0), Vec3<double>::Zero(), Vec3<double>(i == 0 ? 2 : -2, 0, 0)};
  }
  s.R_WC = Mat3<double>::Identity();
  s.restitution = 0.2;
  if (relative_velocity_C(s).x() < 0) std::swap(s.body[0].v_W, s.body[1].v_W);
  for (Engine e : kEngines) {
    CHECK(compare(s, Strategy<double>(Wach<double>{0.4}), e));
    CHECK(compare(s, Strategy<double>(PcCrash<double>{0.4}), e));
    CHECK(has_warning(solve_lean(s, Strategy<double>(Wach<double>{0.4}), Want::impulse, e).warnings,
                      WarningCode::plane_undefined));
    CHECK(has_warning(solve_lean(s, Strategy<double>(PcCrash<double>{0.4}), Want::impulse, e).warnings,
                      WarningCode::plane_undefined));
  }
  // Masses whose product overflows: m' is infinite and every closed form divides by it.
  Scene<double> huge = s;
  for (auto& b : huge.body) b.mass = 1e300;
  // (The direct engine's LU takes a NaN matrix for invertible and gives NaN impulses, flagged
  // not_finite: no bitwise comparison there.)
  for (const Strategy<double>& st : every_strategy(0.4)) {
    const auto r = solve_lean(huge, st, Want::impulse, Engine::generated);
    CHECK(r.status == Status::singular);
    CHECK(std::string(r.singular) == "full impact");
    CHECK_FALSE(compare(huge, st, Engine::generated));
  }
}

// A Scene's J_B is read by its upper triangle in the kernels and by its lower one in the solves
// (scene.hpp): one that is not symmetric by a single ulp in any one entry is refused by both entry
// points, naming the body and the entry; the symmetric scene it came from is solved.
TEMPLATE_TEST_CASE("solve_lean and analyze refuse an inertia tensor that is not symmetric", "[lean]", double,
                   mp::float100) {
  using T = TestType;
  std::mt19937_64 g(23);
  const Scene<T> s = cast_scene<T>(random_scene(g));
  const Strategy<T> st = PcCrash<T>{T(0.4)};
  CHECK_NOTHROW(solve_lean(s, st));
  int refused = 0;
  for (int i = 0; i < 2; ++i)
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) {
        if (r == c) continue;
        Scene<T> bent = s;
        T& x = bent.body[i].J_B(r, c);
        x = x * (T(1) + std::numeric_limits<T>::epsilon());
        REQUIRE(x != bent.body[i].J_B(c, r));
        const std::string what = "body[" + std::to_string(i) + "].J_B is not symmetric: entry (" +
                                 std::to_string(std::min(r, c)) + ", " + std::to_string(std::max(r, c)) + ")";
        for (Engine e : kEngines) {
          CHECK_THROWS_WITH(solve_lean(bent, st, Want::impulse, e), Catch::Contains(what));
          CHECK_THROWS_AS(solve_lean(bent, st, Want::velocities, e), std::invalid_argument);
          CHECK_THROWS_WITH(analyze(bent, {st}, e), Catch::Contains(what));
        }
        ++refused;
      }
  CHECK(refused == 12);
}

#ifndef IMPACT3D_SANITIZED
TEST_CASE("solve_lean allocates nothing, with or without warnings", "[lean]") {
  std::mt19937_64 g(7);
  std::vector<Scene<double>> scenes;
  for (int c = 0; c < 200; ++c) scenes.push_back(random_scene(g));
  std::vector<Strategy<double>> strategies = every_strategy(0.4);
  const auto a = analyze(scenes[0], {PcCrash<double>{0}});
  strategies.push_back(PcCrash<double>{*a.solutions[0].impulse.gir});  // undecided: settles kappa
  int solved = 0, warned = 0;
  const long before = allocations.load();
  for (const auto& s : scenes)
    for (const auto& st : strategies)
      for (Want want : {Want::impulse, Want::velocities}) {
        const auto r = solve_lean(s, st, want);
        solved += r.status == Status::solved;
        warned += r.warnings != 0;
      }
  CHECK(allocations.load() - before == 0);
  CHECK(solved == 200 * 11 * 2);
  CHECK(warned >= 2);  // the threshold case at least, both ways
}
#endif

TEMPLATE_TEST_CASE("The lean path's bounds of kappa(K) and of the amplification are above the settled values where it takes them",
                   "[lean]", double, long double, mp::float100) {
  // The lean path decides on kappa_bound = tr(K) and on amplification_bound while the latter is trusted
  // (Problem::within, which doubles them; the rounding check in solve_lean_with, which halves the
  // limit); there a bound far below the eigenvalues' value that settle() computes could take a decision
  // that analyze takes the other way. This asks more: each bound at least that value. tr(K) exceeds
  // kappa(K) by at least 2 in exact arithmetic (K's eigenvalues are all at least 1), so equality is not
  // tolerated. Three families: ordinary scenes; a body 10^k times lighter, 10^1.5k times smaller in
  // inertia and struck 1 + 6k times farther out, k from 0 to 6 (kappa(K) up to about 10^7, across the
  // trusted threshold at double); a rod whose thin axis takes cond(J) from 2.5e3 to 2.5e15.
  std::mt19937_64 g(20261128);
  int scenes = 0, untrusted = 0, tensors = 0;
  std::array<int, 3> trusted{};
  int ill_conditioned = 0;  // trusted with kappa(K) above 10^3
  for (int c = 0; c < 90; ++c) {
    Scene<double> s = random_scene(g);
    if (c % 3 == 1) {
      const int k = c / 3 % 7;
      s.body[1].mass *= std::pow(10.0, -k);
      s.body[1].J_B *= std::pow(10.0, -1.5 * k);
      s.body[1].p_CgIc_B *= 1 + 6 * k;
    } else if (c % 3 == 2) {
      s.body[1].J_B = Mat3<double>(Vec3<double>(2500, 2500, std::pow(10.0, -(c / 3 % 13))).asDiagonal());
    }
    const Scene<TestType> t = cast_scene<TestType>(s);
    if (!(relative_velocity_C(t).x() > 0)) continue;  // the lean path decides nothing
    ++scenes;
    for (Engine e : kEngines) {
      const Problem<TestType> p = e == Engine::direct ? make_problem<direct::DirectEngine>(t, true)
                                                      : make_problem<GeneratedEngine>(t, true);
      const bool taken = rounding::relative_bound(p.amplification_bound) <= TestType(rounding::kTrustedFraction);
      p.settle();
      INFO("scene " << c << ", " << engine_name(e) << ": kappa " << to_double(p.kappa) << ", bound "
                    << to_double(p.kappa_bound) << "; amplification " << to_double(p.amplification) << ", bound "
                    << to_double(p.amplification_bound));
      if (!taken) {
        ++untrusted;
        continue;
      }
      ++trusted[c % 3];
      ill_conditioned += p.kappa > 1e3;
      CHECK(p.kappa < p.kappa_bound);
      CHECK(p.amplification < p.amplification_bound);
    }
    // The tensors' bound tr(J) tr(J^-1): at least cond(J), at most nine times it (and its rounding).
    for (const RigidBody<TestType>& b : t.body) {
      const TestType bound = rounding::spd_condition_bound(b.J_B), cond = rounding::spd_condition(b.J_B);
      if (!is_finite(bound)) continue;
      ++tensors;
      CHECK(bound >= cond);
      CHECK(bound <= 9 * cond * TestType(1 + 0x1p-10));
    }
  }
  INFO(scenes << " scenes; trusted: " << trusted[0] << " ordinary, " << trusted[1] << " light, " << trusted[2]
              << " rods (" << ill_conditioned << " with kappa(K) > 10^3); " << untrusted << " not");
  CHECK(scenes >= 80);
  CHECK(trusted[0] >= 50);
  CHECK(trusted[1] >= 30);
  CHECK(trusted[2] >= 4);  // at double the rod is trusted down to a thin axis of about 10^-2
  CHECK(ill_conditioned >= 20);
  if (std::numeric_limits<TestType>::digits < 100) CHECK(untrusted >= 4);
  CHECK(tensors >= 150);
  // K is the identity plus a positive semidefinite part only for m' > 0 and positive definite tensors:
  // otherwise no trace bounds it, and neither bound is taken.
  Scene<double> s = random_scene(g);
  s.body[0].mass = -1, s.body[1].mass = 3;
  const Scene<TestType> light_negative = cast_scene<TestType>(s);
  const Problem<TestType> negative = make_problem<GeneratedEngine>(light_negative, true);
  REQUIRE(negative.m_prime < 0);
  CHECK(negative.kappa_bound == std::numeric_limits<TestType>::infinity());
  s = random_scene(g);
  s.body[1].J_B(2, 2) = -1;
  const Scene<TestType> t = cast_scene<TestType>(s);
  const Problem<TestType> indefinite = make_problem<GeneratedEngine>(t, true);
  REQUIRE(indefinite.m_prime > 0);
  CHECK(indefinite.amplification_bound == std::numeric_limits<TestType>::infinity());
}

TEST_CASE("The condition bound in double is above tr(M) tr(M^-1) at 100 digits, and empty where it cannot bound it",
          "[lean]") {
  // The lean path bounds cond(J) at wide precisions in double (rounding.hpp); a bound below the exact
  // product would let a decision be taken on it that the settled kappa contradicts. The reference: the
  // same trace product by the adjugate at 100 digits, within 1e-90 of exact here.
  using F = mp::float100;
  std::mt19937_64 g(20261127);
  std::uniform_real_distribution<double> u(-1, 1);
  int bounded = 0, refused = 0;
  for (int k = 0; k < 4000; ++k) {
    // M = Q diag(l) Q^T, eigenvalues spread by up to 10^5 and scaled by 10^-200 to 10^200.
    const double roll = 180 * u(g), pitch = 90 * u(g), yaw = 180 * u(g);  // the last first, as draw3
    const Mat3<double> Q = rotation_zyx_deg(yaw, pitch, roll);
    const double spread = std::pow(10.0, 2.5 + 2.5 * u(g)), scale = std::pow(10.0, 200 * u(g));
    const Vec3<double> l(scale, scale * std::pow(spread, 0.5 + 0.5 * u(g)), scale * spread);
    Mat3<double> M = Q * l.asDiagonal() * Q.transpose();
    M = ((M + M.transpose()) / 2).eval();
    const Mat3<F> Mf = M.cast<F>();
    const F a = Mf(0, 0), b = Mf(0, 1), c = Mf(0, 2), d = Mf(1, 1), e = Mf(1, 2), f = Mf(2, 2);
    const F A = d * f - e * e, B = c * e - b * f, C = b * e - c * d, D = a * f - c * c, G = a * d - b * b;
    const F det = a * A + b * B + c * C;
    const F exact = (a + d + f) * (A + D + G) / det;
    const std::optional<double> bound = rounding::spd_condition_bound_in_double(Mf);
    if (!bound) {
      ++refused;
      CHECK(exact > F(0x1p12) * F(1 - 0x1p-20));  // only the ill-conditioned ones go to 100 digits
      continue;
    }
    ++bounded;
    CHECK(F(*bound) >= exact);
    CHECK(F(*bound) <= exact * F(1 + 0x1p-9));
    CHECK(rounding::spd_condition_bound(Mf) == F(*bound));
  }
  // Two eigenvalues 2^-40 to 2^-300 of the third (M = I + t w w^T, kappa = 1 + t exactly): rounded to
  // double, M's small part is lost and its determinant is noise. No bound may fall below kappa.
  int nearly_singular = 0;
  for (int k = 0; k < 2000; ++k) {
    const double wz = u(g), wy = u(g), wx = u(g);
    const Vec3<F> w = Vec3<double>(wx, wy, wz).cast<F>().normalized();
    using std::ldexp;
    const F t = ldexp(F(1), 40 + static_cast<int>(k % 261));
    const Mat3<F> Mn = (Mat3<F>::Identity() + t * w * w.transpose()).eval();
    const std::optional<double> bound = rounding::spd_condition_bound_in_double(Mn);
    CHECK((!bound || F(*bound) >= (1 + t) * F(1 - 0x1p-20)));
    CHECK(rounding::spd_condition_bound(Mn) >= (1 + t) * F(1 - 0x1p-20));
    ++nearly_singular;
  }
  CHECK(nearly_singular == 2000);
  INFO(bounded << " bounded in double, " << refused << " refused");
  CHECK(bounded + refused == 4000);
  CHECK(bounded > 1000);
  CHECK(refused > 1000);
  // Indefinite, out of double's range, not finite: the scalar's own arithmetic.
  Mat3<F> indefinite = Mat3<F>::Identity();
  indefinite(2, 2) = F(-1);
  CHECK(!rounding::spd_condition_bound_in_double(indefinite));
  CHECK(rounding::spd_condition_bound(indefinite) == std::numeric_limits<F>::infinity());
  Mat3<F> tiny = Mat3<F>::Identity() * F("1e-400");
  CHECK(!rounding::spd_condition_bound_in_double(tiny));
  CHECK(abs(rounding::spd_condition_bound(tiny) - F(9)) < F("1e-90"));  // tr(I) tr(I^-1)
  Mat3<F> nan = Mat3<F>::Identity();
  nan(1, 1) = std::numeric_limits<F>::quiet_NaN();
  CHECK(!rounding::spd_condition_bound_in_double(nan));
}

}  // namespace check_lean
