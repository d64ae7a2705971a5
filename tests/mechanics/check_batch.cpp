// The SIMD batches (mechanics/batch/columns.hpp) against the scalar lean path, row by row, on seeded random
// raw collisions (bench/peer_collisions.hpp, both regimes) mixed with rows the lanes must not decide:
// separating, mu exactly at the GIR, an undefined phi_FI plane, an overflowing mass, a NaN input.
//
// Rows decided on the lanes differ from solve_lean only by roundings of the kind the rounding model
// counts: the vectorized sine and cosine (measured below against the scalar ones, in ulps), fused
// multiply-adds and the lanes' hypot, each a relative error of an ulp or two in an input or an
// operation. Both computations are then within rounding::relative_bound (kResultRoundings eps A) of the
// exact impulse of the same rows, so within agreement_bound (2 kResultRoundings eps A) of each other,
// A the case's amplification (rounding.hpp). Everything decided is equal: status, regime, warning codes.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <functional>
#include <optional>
#include <string>
#include <limits>
#include <random>

#include "impact3d/mechanics/batch/columns.hpp"
#include "impact3d/mechanics/lean.hpp"
#include "peer_collisions.hpp"

namespace check_batch {

using namespace impact3d;

namespace {

// Distance in units in the last place, through the ordered integer representation.
double ulps(double a, double b) {
  if (a == b) return 0;
  auto key = [](double x) {
    std::int64_t i;
    std::memcpy(&i, &x, sizeof i);
    return i < 0 ? std::numeric_limits<std::int64_t>::min() - i : i;
  };
  return std::abs(static_cast<double>(key(a) - key(b)));
}

// Rows every strategy's lanes must leave to the scalar path, made from a random one.
enum class Special { separating, head_on, overflowing, nan_input };

RawCollision<double> made(RawCollision<double> r, Special kind) {
  switch (kind) {
    case Special::separating:
      for (auto& v : r.vehicle) v.v_W = -v.v_W, v.w_B = -v.w_B;
      break;
    case Special::head_on:  // along the normal: no contact-plane impulse nor sliding, the planes undefined
      for (int i = 0; i < 2; ++i) {
        auto& v = r.vehicle[i];
        v.J_B = Mat3<double>(Vec3<double>(500, 2500, 2800).asDiagonal());
        v.yaw_deg = v.pitch_deg = v.roll_deg = 0;
        v.v_W = Vec3<double>(i == 0 ? 10 : -10, 0, 0), v.w_B.setZero(), v.p_CgIc_B = Vec3<double>(i == 0 ? 2 : -2, 0, 0);
      }
      r.normal_yaw_deg = 180, r.normal_pitch_deg = 0, r.tangent_roll_deg = 0;
      break;
    case Special::overflowing:  // masses whose m' overflows: a singular system
      r.vehicle[0].mass = r.vehicle[1].mass = 1e300;
      break;
    case Special::nan_input:  // a NaN product of inertia: K is NaN, every closed form too
      r.vehicle[1].J_B(0, 1) = std::numeric_limits<double>::quiet_NaN();
      break;
  }
  return r;
}

struct Rows {
  std::vector<RawCollision<double>> rows;
  std::vector<double> mus;
  std::size_t random = 0;
};

// `random` seeded random collisions with `special` rows among them, spread over lane positions (the
// k-th before random row `spacing` k + k % 7), each random row k changed by `change` (its collision and
// mu), and the last `short_tail` rows dropped: a tail shorter than any lane group.
template <typename Change>
Rows mixed_rows(std::size_t random, std::uint64_t seed, std::size_t special, std::size_t spacing, std::size_t short_tail,
                Change change) {
  Rows out;
  for (const auto& c : bench::random_collisions(random, seed)) out.rows.push_back(bench::raw_of(c)), out.mus.push_back(c.mu);
  out.random = out.rows.size();
  for (std::size_t k = 0; k < special; ++k) {
    RawCollision<double> r = out.rows[k];
    double mu = out.mus[k];
    change(k, r, mu);
    const auto at = static_cast<std::ptrdiff_t>(spacing * k + k % 7);
    out.rows.insert(out.rows.begin() + at, r);
    out.mus.insert(out.mus.begin() + at, mu);
  }
  out.rows.resize(out.rows.size() - short_tail);
  out.mus.resize(out.rows.size());
  return out;
}

// What the rows compared showed.
struct Tally {
  int statuses[3] = {0, 0, 0}, regimes[4] = {0, 0, 0, 0};  // by Status, and by Regime of the solved rows
  int undecided = 0, undefined = 0, negative = 0, tensile = 0;  // rows with each warning
  int warned = 0;                                             // solved rows with any warning
  double worst = 0;                                           // |dP| / (eps A |P|)
};

// Each row of `out` against solve_lean with the row's strategy: the same status, warning codes and
// regime, and the impulse within agreement_bound.
template <typename StrategyOf>
Tally compare_rows(const std::vector<RawCollision<double>>& rows, batch::ImpulseTable& out, StrategyOf strategy_of) {
  Tally t;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Scene<double> s = scene_of(rows[i]);
    const auto r = solve_lean(s, strategy_of(i));
    INFO("row " << i);
    REQUIRE(out.status[i] == static_cast<std::uint8_t>(r.status));
    ++t.statuses[out.status[i]];
    CHECK(out.warnings[i] == r.warnings);
    t.undecided += has_warning(r.warnings, WarningCode::undecided);
    t.undefined += has_warning(r.warnings, WarningCode::plane_undefined);
    t.negative += has_warning(r.warnings, WarningCode::negative_ratio);
    t.tensile += has_warning(r.warnings, WarningCode::tensile_normal_impulse);
    if (r.status != Status::solved) {
      CHECK(std::isnan(out.P_C[0][i]));
      continue;
    }
    REQUIRE(out.regime[i] == static_cast<std::uint8_t>(r.impulse.regime));
    ++t.regimes[out.regime[i]];
    t.warned += r.warnings != 0;
    const Vec3<double> P(out.P_C[0][i], out.P_C[1][i], out.P_C[2][i]);
    const double A = make_problem<GeneratedEngine>(s).amplification;
    const double err = (P - r.impulse.P_C).norm() / r.impulse.P_C.norm();
    CHECK(err <= rounding::agreement_bound(A));
    t.worst = std::max(t.worst, err / (std::numeric_limits<double>::epsilon() * A));
  }
  return t;
}

}  // namespace

// The widest instruction set again when a test case ends, whatever it chose.
struct WidestAfter {
  ~WidestAfter() { batch::use_simd(batch::simd_available().at(0)); }
};

// Every instruction set this CPU runs, one after the other (the widest is what users get).
#define FOR_EACH_SIMD()                                                   \
  const WidestAfter restore;                                              \
  const std::string simd = GENERATE(from_range(batch::simd_available())); \
  REQUIRE(batch::use_simd(simd));                                         \
  INFO("instruction set " << simd);

TEST_CASE("the lanes' sine and cosine of degrees are within 4 ulps of the scalar path's", "[batch]") {
  FOR_EACH_SIMD();
  // Both reduce by quarter turns to [-45, 45] degrees. The scalar path takes radians as (rest pi) / 180,
  // two roundings, the lanes as rest (pi / 180), one rounding of a rounded constant: the radians differ
  // by up to 2 ulps, which sine near 0 keeps. glibc documents its sin and cos within an ulp; xsimd's are
  // Cephes-style polynomials on [-pi/4, pi/4] with no stated bound, so this measurement is what holds
  // them to an ulp: 4 ulps in all. Multiples of 90 degrees are exact on both.
  std::mt19937_64 g(3);
  std::uniform_real_distribution<double> u(-720, 720);
  std::vector<double> deg;
  for (int k = -8; k <= 8; ++k) deg.push_back(45.0 * k);
  for (double x : {1e-300, -1e-300, 1e-10, 89.999999999, 0.5, -0.0}) deg.push_back(x);
  while (deg.size() < 100003) deg.push_back(u(g));
  std::vector<double> s(deg.size()), c(deg.size());
  batch::sin_cos_deg_columns(deg.data(), s.data(), c.data(), deg.size());
  double worst = 0;
  std::size_t exact_quarters = 0;
  for (std::size_t i = 0; i < deg.size(); ++i) {
    const SinCos<double> r = sin_cos_deg(deg[i]);
    worst = std::max({worst, ulps(s[i], r.s), ulps(c[i], r.c)});
    if (std::fmod(deg[i], 90.0) == 0) {
      exact_quarters += s[i] == r.s && c[i] == r.c;
      CHECK(std::abs(s[i]) + std::abs(c[i]) == 1);
    }
  }
  INFO(batch::simd_name() << ": worst " << worst << " ulps over " << deg.size() << " angles");
  CHECK(worst <= 4);
  CHECK(exact_quarters == 10);  // -360, -270, ..., 360 from the grid of 45s, and -0
}

TEST_CASE("the SIMD batch gives solve_lean's status, regime and warnings on every row, and its impulse within "
          "agreement_bound",
          "[batch]") {
  FOR_EACH_SIMD();
  // Rows the lanes must leave to the scalar path, and mu exactly at the GIR: undecided.
  const Rows mixed = mixed_rows(4000, 29, 40, 97, 3, [](std::size_t k, RawCollision<double>& r, double& mu) {
    const Special kinds[] = {Special::separating, Special::separating, Special::head_on, Special::overflowing,
                             Special::nan_input};
    if (k % 5 == 1) mu = *solve_lean(scene_of(r), Strategy<double>(PcCrash<double>{0})).impulse.gir;
    else r = made(r, kinds[k % 5]);
  });
  const auto& rows = mixed.rows;
  const auto& mus = mixed.mus;
  const std::size_t n_random = mixed.random;
  batch::CollisionTable table(rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) table.set(i, rows[i], mus[i]);
  batch::ImpulseTable out(rows.size());
  const batch::CollisionColumns in = table.columns();
  // Two ranges, as two threads would split it.
  const std::size_t on_scalar = batch::pc_crash_columns(in, out.columns(), 0, rows.size() / 2 + 1) +
                                batch::pc_crash_columns(in, out.columns(), rows.size() / 2 + 1, rows.size());

  for (std::size_t i = 0; i < rows.size(); ++i)
    CHECK(batch::row_of(in, i).vehicle[1].J_B(2, 1) == rows[i].vehicle[1].J_B(2, 1));
  const Tally t = compare_rows(rows, out, [&](std::size_t i) { return Strategy<double>(PcCrash<double>{mus[i]}); });
  const int solved = t.statuses[0];
  INFO(batch::simd_name() << ": worst " << t.worst << " eps A over " << solved << " rows");
  CHECK(rows.size() == n_random + 40 - 3);
  CHECK(t.statuses[1] == 8);   // the separating rows
  CHECK(t.statuses[2] == 16);  // the overflowing and the NaN rows
  CHECK(solved + t.statuses[1] + t.statuses[2] == static_cast<int>(rows.size()));
  CHECK(t.undecided >= 8);
  CHECK(t.undefined >= 8);
  CHECK(t.regimes[static_cast<int>(Regime::full)] > 500);
  CHECK(t.regimes[static_cast<int>(Regime::sliding)] > 500);
  CHECK(t.regimes[static_cast<int>(Regime::full)] + t.regimes[static_cast<int>(Regime::sliding)] == solved);
  // The lanes decided every row but the 40 built for the scalar path (each fails a lane's test: not
  // approaching, not finite, a plane or a regime within thrice the cheap bound), the two ranges' tails
  // (under a lane group each) and the few random rows whose decisions fall within thrice the cheap bound.
  INFO(on_scalar << " rows on the scalar path");
  CHECK(on_scalar >= 40);
  CHECK(on_scalar <= 40 + 2 * 8 + 20);
  CHECK(t.worst <= 2 * rounding::kResultRoundings);
}

// Wach and Brach on lanes, against solve_lean with the same strategy, row by row, as pc-crash above:
// every cap (CIR, GIR) and every form of Brach (both ratios given, either critical, both critical), on
// random collisions mixed with rows the lanes must leave to the scalar path: separating, an overflowing
// mass, a NaN input, a head-on impact (Wach's plane undefined: no initial sliding velocity), mu exactly
// at Wach's CIR (undecided) and a negative mu (a negative ratio). Random rows give negative caps and
// tensile normal impulses too, which the lanes decide and flag themselves where the sign is clear.
TEST_CASE("wach_columns and brach_columns give solve_lean's status, regime and warnings on every row, and its "
          "impulse within agreement_bound",
          "[batch]") {
  FOR_EACH_SIMD();
  const Rows mixed = mixed_rows(1500, 41, 48, 31, 5, [](std::size_t k, RawCollision<double>& r, double& mu) {
    const Special kinds[] = {Special::separating, Special::overflowing, Special::nan_input, Special::head_on};
    if (k % 6 == 4) mu = *solve_lean(scene_of(r), Strategy<double>(Wach<double>{0, WachLimit::cir})).impulse.cir;
    else if (k % 6 == 5) mu = -0.3;
    else r = made(r, kinds[k % 6]);
  });
  const auto& rows = mixed.rows;
  const auto& mus = mixed.mus;
  const std::size_t n_random = mixed.random;
  // Brach's ratios: mu_t from mu, mu_z of both signs.
  std::vector<double> mu_t(rows.size()), mu_z(rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) mu_t[i] = 0.8 * mus[i], mu_z[i] = 0.2 * mus[i] * (i % 3 == 0 ? -1 : 1);
  batch::CollisionTable table(rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) table.set(i, rows[i], mus[i]);
  const batch::CollisionColumns in = table.columns();
  const std::size_t half = rows.size() / 2 + 3;

  struct Variant {
    const char* name;
    std::function<std::size_t(const batch::ImpulseColumns&, std::size_t, std::size_t)> run;
    std::function<Strategy<double>(std::size_t)> strategy;
  };
  const auto given = [](const std::vector<double>& column, std::size_t i) { return std::optional<double>(column[i]); };
  const std::vector<Variant> variants = {
      {"wach cir", [&](auto& o, auto b, auto e) { return batch::wach_columns(in, WachLimit::cir, o, b, e); },
       [&](std::size_t i) { return Strategy<double>(Wach<double>{mus[i], WachLimit::cir}); }},
      {"wach gir", [&](auto& o, auto b, auto e) { return batch::wach_columns(in, WachLimit::gir, o, b, e); },
       [&](std::size_t i) { return Strategy<double>(Wach<double>{mus[i], WachLimit::gir}); }},
      {"brach given", [&](auto& o, auto b, auto e) { return batch::brach_columns(in, mu_t.data(), mu_z.data(), o, b, e); },
       [&](std::size_t i) { return Strategy<double>(Brach<double>{given(mu_t, i), given(mu_z, i)}); }},
      {"brach mu_t critical", [&](auto& o, auto b, auto e) { return batch::brach_columns(in, nullptr, mu_z.data(), o, b, e); },
       [&](std::size_t i) { return Strategy<double>(Brach<double>{std::nullopt, given(mu_z, i)}); }},
      {"brach mu_z critical", [&](auto& o, auto b, auto e) { return batch::brach_columns(in, mu_t.data(), nullptr, o, b, e); },
       [&](std::size_t i) { return Strategy<double>(Brach<double>{given(mu_t, i), std::nullopt}); }},
      {"brach both critical", [&](auto& o, auto b, auto e) { return batch::brach_columns(in, nullptr, nullptr, o, b, e); },
       [&](std::size_t)  { return Strategy<double>(Brach<double>{std::nullopt, std::nullopt}); }},
  };
  int checked_variants = 0, brach_tensile = 0, lanes_warned = 0;
  for (const Variant& v : variants) {
    INFO(v.name);
    batch::ImpulseTable out(rows.size());
    // Two ranges, as two threads would split it.
    const std::size_t on_scalar = v.run(out.columns(), 0, half) + v.run(out.columns(), half, rows.size());
    const Tally t = compare_rows(rows, out, v.strategy);
    const auto& statuses = t.statuses;
    const auto& regimes = t.regimes;
    INFO("negative " << t.negative << ", tensile " << t.tensile << ", undecided " << t.undecided << ", undefined "
                      << t.undefined);
    INFO(batch::simd_name() << ": worst " << t.worst << " eps A over " << statuses[0] << " rows, " << on_scalar
                            << " on the scalar path");
    CHECK(statuses[1] == 8);   // the separating rows
    CHECK(statuses[2] >= 16);  // the overflowing and the NaN rows, and for Brach any singular critical ratio
    CHECK(statuses[0] + statuses[1] + statuses[2] == static_cast<int>(rows.size()));
    CHECK(statuses[0] > 1400);
    if (v.name[0] == 'w') {
      CHECK(t.undefined >= 8);  // the head-on rows
      CHECK(t.negative >= 50);  // mu = -0.3, below either cap, and the random rows whose cap is negative
      CHECK(t.tensile >= 20);
      CHECK(regimes[static_cast<int>(Regime::capped)] > 100);
      CHECK(regimes[static_cast<int>(Regime::sliding)] > 100);
      if (std::string(v.name) == "wach cir") CHECK(t.undecided >= 8);
    } else {
      CHECK(regimes[static_cast<int>(Regime::as_given)] == statuses[0]);
      brach_tensile += t.tensile;
    }
    // Rows with a warning beyond those the scalar path solved were decided, and flagged, on the lanes.
    lanes_warned += std::max(0, t.warned - static_cast<int>(on_scalar));
    if (v.name[0] == 'w') CHECK(t.warned - static_cast<int>(on_scalar) >= 40);
    // The lanes decided all but the rows built for the scalar path, the two ranges' tails (under a lane
    // group each) and the few random rows whose decisions fall within thrice the cheap bound.
    CHECK(on_scalar >= 24);
    CHECK(on_scalar <= 48 + 2 * 8 + 30);
    CHECK(t.worst <= 2 * rounding::kResultRoundings);
    ++checked_variants;
  }
  CHECK(checked_variants == 6);
  CHECK(brach_tensile >= 50);  // ratios that tip the normal impulse
  CHECK(lanes_warned >= 2 * 40 + 20);  // Wach's at least, and Brach's tensile rows beyond its scalar ones
  CHECK(rows.size() == n_random + 48 - 5);
}

namespace {

// A value in [lo, hi] where f changes sign, by bisection to the last bit (nullopt if f(lo) and f(hi)
// share a sign): where a denominator of the scalar path vanishes to within its rounding.
template <typename F>
std::optional<double> root_in(F f, double lo, double hi) {
  const bool lo_negative = f(lo) < 0;
  if (lo_negative == (f(hi) < 0)) return std::nullopt;
  for (int k = 0; k < 2100; ++k) {
    const double mid = lo + (hi - lo) / 2;
    if (mid == lo || mid == hi) break;
    ((f(mid) < 0) == lo_negative ? lo : hi) = mid;
  }
  return lo;
}

// A plane ratio's denominator (eqs 19-20) on the plane (c, s), as the generated kernels form it.
double plane_ratio_den(const Problem<double>& p, double c, double s, double e) {
  const Mat3<double>& K = p.K;
  const double Vcp = p.V_ri(1) * c + p.V_ri(2) * s, pb1 = K(0, 1) * c + K(0, 2) * s;
  const double pb2 = (K(1, 1) * c + K(2, 1) * s) * c + (K(1, 2) * c + K(2, 2) * s) * s;
  return Vcp * pb1 - p.V_ri(0) * (1 + e) * pb2;
}

}  // namespace

// Rows built so that a denominator solve_lean divides by vanishes to within rounding (the restitution or
// a ratio chosen by bisection): the lanes cannot know whether solve_lean finds the quotient finite (else
// the row is singular) or which sign it takes, so every one of them must be left to it. Each is a
// denominator of a ratio the strategy reports or uses: pc-crash's CIR, Wach's unused cap, the critical
// ratios Brach reports beside ratios given (eqs 25, 26) and their impulses' normal denominators, and eq
// 25's ratio used. Beside them, rows outside the model (eps above 1 or below 0, a negative mass, whose m'
// is negative), which the lanes leave to solve_lean whatever the strategy.
TEST_CASE("the lanes leave to solve_lean every row whose ratio, used or reported, has a vanishing "
          "denominator, and every row outside the model",
          "[batch]") {
  FOR_EACH_SIMD();
  using Den = std::function<double(double)>;
  const auto problem_of = [](const RawCollision<double>& r) { return make_problem<GeneratedEngine>(scene_of(r)); };
  const auto wach_cir = [&](const RawCollision<double>& r) -> Den {
    const Problem<double> p = problem_of(r);
    const double l = std::hypot(p.V_ri(1), p.V_ri(2));
    return [p, l](double e) { return plane_ratio_den(p, p.V_ri(1) / l, p.V_ri(2) / l, e); };
  };
  const auto pc_crash_cir = [&](const RawCollision<double>& r) -> Den {
    const Problem<double> p = problem_of(r);
    return [p](double e) {
      const Vec3<double> P = generated::full_impact(p.K, p.m_prime, e, p.V_ri);
      const double l = std::hypot(P(1), P(2));
      return plane_ratio_den(p, P(1) / l, P(2) / l, e);
    };
  };
  const auto eq25 = [&](const RawCollision<double>& r) -> Den {
    const Problem<double> p = problem_of(r);
    return [p](double e) { return p.V_ri(0) * (1 + e) * p.K(1, 1) - p.V_ri(1) * p.K(0, 1); };
  };
  // Eq 26's, on rows whose contact frame is turned a quarter about n (tangent_roll + 90 degrees): the new
  // z axis is minus the old t, and the two signs cancel, so it is eq 25's of the row unturned, with as
  // many roots in [0, 1].
  const auto eq26 = [&](const RawCollision<double>& r) -> Den {
    const Problem<double> p = problem_of(r);
    return [p](double e) { return p.V_ri(0) * (1 + e) * p.K(2, 2) - p.V_ri(2) * p.K(0, 2); };
  };
  // The normal denominators of the impulses at the critical ratio of one axis, the other ratio x given.
  const auto tc_impulse = [&](const RawCollision<double>& r) -> Den {
    const Problem<double> p = problem_of(r);
    return [p](double x) {
      const double t_c = generated::brach_critical_t(p.K, p.restitution, p.V_ri, x);
      return p.K(0, 0) + p.K(0, 1) * t_c + p.K(0, 2) * x;
    };
  };
  const auto zc_impulse = [&](const RawCollision<double>& r) -> Den {
    const Problem<double> p = problem_of(r);
    return [p](double x) {
      const double z_c = generated::brach_critical_z(p.K, p.restitution, p.V_ri, x);
      return p.K(0, 0) + p.K(0, 1) * x + p.K(0, 2) * z_c;
    };
  };
  using Run = std::function<std::size_t(const batch::CollisionColumns&, const batch::ImpulseColumns&,
                                        const std::vector<double>&)>;
  struct Kind {
    const char* name;
    std::function<Den(const RawCollision<double>&)> den;
    bool ratio;  // the value varied: the ratio column, or else the restitution in [0, 1]
    Run run;
    std::function<Strategy<double>(double)> strategy;
    double turn_deg = 0;
  };
  const Run pc_crash = [](auto& in, auto& o, auto&) { return batch::pc_crash_columns(in, o, 0, in.rows); };
  const Run wach_gir = [](auto& in, auto& o, auto&) { return batch::wach_columns(in, WachLimit::gir, o, 0, in.rows); };
  const Run both_given = [](auto& in, auto& o, auto& x) { return batch::brach_columns(in, x.data(), x.data(), o, 0, in.rows); };
  const Run t_critical = [](auto& in, auto& o, auto& x) { return batch::brach_columns(in, nullptr, x.data(), o, 0, in.rows); };
  const auto brach_given = [](double x) { return Strategy<double>(Brach<double>{x, x}); };
  const std::vector<Kind> kinds = {
      {"pc-crash, its CIR", pc_crash_cir, false, pc_crash, [](double mu) { return Strategy<double>(PcCrash<double>{mu}); }},
      {"wach at the GIR, its CIR unused", wach_cir, false, wach_gir,
       [](double mu) { return Strategy<double>(Wach<double>{mu, WachLimit::gir}); }},
      {"brach given, mu_t critical (eq 25) reported", eq25, false, both_given, brach_given},
      {"brach given, mu_z critical (eq 26) reported", eq26, false, both_given, brach_given, 90},
      {"brach given, the impulse at mu_t critical", tc_impulse, true, both_given, brach_given},
      {"brach given, the impulse at mu_z critical", zc_impulse, true, both_given, brach_given},
      {"brach, mu_t critical (eq 25) used", eq25, false, t_critical,
       [](double x) { return Strategy<double>(Brach<double>{std::nullopt, x}); }},
  };
  const auto cases = bench::random_collisions(3000, 53);
  int root_singular = 0;
  for (const Kind& kind : kinds) {
    INFO(kind.name);
    std::vector<RawCollision<double>> rows;
    std::vector<double> ratios;
    for (const auto& c : cases) {
      RawCollision<double> r = bench::raw_of(c);
      r.tangent_roll_deg += kind.turn_deg;
      const auto x = kind.ratio ? root_in(kind.den(r), -4.0, 4.0) : root_in(kind.den(r), 0.0, 1.0);
      if (!x) continue;
      if (!kind.ratio) r.restitution = *x;
      rows.push_back(r), ratios.push_back(kind.ratio ? *x : c.mu);
      root_singular += solve_lean(scene_of(r), kind.strategy(ratios.back())).status == Status::singular;
      // Outside the model, beside it: eps above 1 and below 0, a negative mass.
      if (rows.size() % 8 == 1) {
        RawCollision<double> out_of_model = r;
        out_of_model.restitution = rows.size() % 16 == 1 ? 1.5 : -0.25;
        rows.push_back(out_of_model), ratios.push_back(ratios.back());
        out_of_model = r;
        out_of_model.vehicle[1].mass = -0.6 * r.vehicle[0].mass;
        rows.push_back(out_of_model), ratios.push_back(ratios.back());
      }
      if (rows.size() >= 64) break;
    }
    INFO(rows.size() << " rows");
    REQUIRE(rows.size() >= 64);
    batch::CollisionTable table(rows.size());
    for (std::size_t i = 0; i < rows.size(); ++i) table.set(i, rows[i], ratios[i]);
    batch::ImpulseTable out(rows.size());
    CHECK(kind.run(table.columns(), out.columns(), ratios) == rows.size());
    const Tally t = compare_rows(rows, out, [&](std::size_t i) { return kind.strategy(ratios[i]); });
    CHECK(t.statuses[0] >= 32);  // most are solved, a ratio huge or flagged not finite; the rest singular:
  }
  // where the denominator rounds to zero (about 100 of the 330-odd rows built on it, whose bisection
  // ended on a zero): the quotient is not finite and the row singular.
  INFO(root_singular << " rows built on a root singular");
  CHECK(root_singular >= 50);
}

}  // namespace check_batch
