// Never silently wrong: on ill-conditioned random collisions (a first vehicle with a tiny yaw inertia
// or a near-singular tensor, kappa(K) up to 1e12 and beyond), every result that double or long double
// does not flag agrees with the 50-digit solve of the same decimal text within its own rounding bound,
// and takes the same regime unless it says the regime is undecided. (That text and JSON print no NaN or
// infinity without a warning is check_extreme_input.cpp; the named tensor is exam_precision_flags.cpp.)
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <thread>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "impact3d/case_format/read_case.hpp"
#include "impact3d/scalar/multiprecision.hpp"
#include "impact3d/mechanics/precision_warnings.hpp"

namespace check_precision_flags {

using namespace impact3d;

namespace {

using F = mp::float50;

// The Figure 8 collision, with vehicle 1's inertia replaced by an ill-conditioned tensor written to six
// digits, a random contact and random strategies; the literal text is what every precision converts.
std::string ill_conditioned_case(std::mt19937_64& g) {
  std::uniform_real_distribution<double> u(0, 1);
  auto in = [&](double a, double b) { return a + (b - a) * u(g); };
  const double izz = std::pow(10.0, in(-6, 1)), ixx = in(300, 800), ixz = in(-0.999, 0.999) * std::sqrt(ixx * izz);
  return fmt::format(R"({{"vehicles": [
      {{"mass": {:.6g}, "inertia": [[{:.6g}, 0, {:.6g}], [0, {:.6g}, 0], [{:.6g}, 0, {:.6g}]],
        "velocity": [{:.6g}, {:.6g}, 0], "angular_velocity": [0, 0, {:.6g}], "impulse_center": [{:.6g}, {:.6g}, {:.6g}]}},
      {{"mass": {:.6g}, "inertia": {{"Ixx": 1100, "Iyy": 5600, "Izz": 5900}}, "orientation_deg": {{"yaw": {:.6g}}},
        "velocity": [{:.6g}, {:.6g}, 0], "impulse_center": [2.6, {:.6g}, -0.15]}}],
    "contact": {{"normal_yaw_deg": {:.6g}, "normal_pitch_deg": {:.6g}}}, "restitution": {:.6g},
    "strategy": [{{"name": "pc-crash", "mu": {:.6g}}}, {{"name": "wach", "mu": {:.6g}}},
                 {{"name": "brach", "mu_t": "critical", "mu_z": {:.6g}}}]}})",
                     in(1000, 2500), ixx, ixz, in(1500, 3000), ixz, izz, in(5, 25), in(-3, 3), in(-0.5, 0.5), in(-1, 1),
                     in(-1, 1), in(-0.3, 0.3), in(1500, 3000), in(60, 120), in(-3, 3), in(5, 25), in(-1, 1), in(60, 120),
                     in(-10, 10), in(0, 0.6), in(0.1, 1.2), in(0.1, 1.2), in(-0.2, 0.2));
}

bool has(const std::vector<Warning>& ws, WarningCode c) {
  for (const auto& w : ws)
    if (w.code == c) return true;
  return false;
}

struct Tally {
  int cases = 0;  // collisions the 50-digit reference solves: the ones held to it
  int results = 0, flagged = 0, unflagged = 0, solve_errors = 0;
};

// Every result of `a` either carries a rounding or not-finite warning, or lies within its bound of `ref`.
template <typename T>
void check(const Analysis<T>& a, const Analysis<F>& ref, Tally& t) {
  const double eps = static_cast<double>(std::numeric_limits<T>::epsilon());
  for (std::size_t k = 0; k < a.solutions.size(); ++k) {
    const auto& s = a.solutions[k];  // apart: one auto declaration may not deduce two types
    const auto& r = ref.solutions[k];
    ++t.results;
    if (has(s.warnings, WarningCode::rounding) || has(s.warnings, WarningCode::not_finite)) {
      ++t.flagged;
      continue;
    }
    ++t.unflagged;
    INFO("result " << k << ", amplification " << static_cast<double>(a.amplification));
    // The bound the warning promises: 32 eps A (1 + |V_cp / V_n|) relative to |P| (rounding.hpp).
    const double q = 1 + static_cast<double>(hypot(r.V_ri.y(), r.V_ri.z()) / r.V_ri.x());
    const double bound = rounding::kResultRoundings * eps * static_cast<double>(a.amplification) * q;
    CHECK(bound <= rounding::kTrustedFraction);
    double err = 0;
    for (int i = 0; i < 3; ++i) {
      const double d = static_cast<double>(F(case_format::scalar_to_text(s.impulse.P_C(i), 25)) - r.impulse.P_C(i));
      err += d * d;
    }
    CHECK(std::sqrt(err) <= bound * static_cast<double>(r.impulse.P_C.norm()));
    if (!has(s.warnings, WarningCode::undecided)) CHECK(s.impulse.regime == r.impulse.regime);
  }
}

template <typename T>
void sweep(Engine engine, Tally& t, int cases) {
  std::mt19937_64 g(20261121);
  for (int i = 0; i < cases; ++i) {
    const case_format::CaseSpec spec = case_format::read_case(ill_conditioned_case(g));
    Analysis<F> ref;
    try {
      ref = analyze(case_format::to_scene<F>(spec), case_format::to_strategies<F>(spec), Engine::direct);
    } catch (const std::exception&) {
      continue;  // not approaching, or no impulse even at 50 digits: nothing to hold the precision to
    }
    ++t.cases;
    try {
      check(analyze(case_format::to_scene<T>(spec), case_format::to_strategies<T>(spec), engine), ref, t);
    } catch (const SolveError&) {
      ++t.solve_errors;  // refusing is not silently wrong
    }
  }
}

}  // namespace

TEST_CASE("unflagged results hold their rounding bound on ill-conditioned collisions", "[precision]") {
  for (Engine engine : {Engine::generated, Engine::direct}) {
    Tally d, ld;
    sweep<double>(engine, d, 300);
    sweep<long double>(engine, ld, 300);
    INFO(engine_name(engine));
    // The sweep must exercise both sides of the flag, or it shows nothing.
    // Skipped: collisions the 50-digit solve refuses (not approaching, or no impulse), 10 of these 300.
    // At least 90% must be held to the reference.
    CHECK(d.cases >= 270);
    CHECK(ld.cases == d.cases);  // the same seeded collisions at both precisions
    CHECK(d.results >= 600);
    CHECK(ld.results >= 600);
    CHECK(d.flagged >= 100);
    CHECK(d.unflagged >= 100);
    CHECK(ld.unflagged > d.unflagged);
    WARN(fmt::format("{}: double {} results, {} flagged, {} refused; long double {} results, {} flagged", engine_name(engine),
                     d.results, d.flagged, d.solve_errors, ld.results, ld.flagged));
  }
}


TEST_CASE("the kept inertia conditions are each tensor's own, in any order and on any thread", "[precision]") {
  // rounding::inertia_condition keeps two tensors' conditions per thread: a third tensor, or a tensor
  // that differs in one bit, must never get another's.
  std::mt19937_64 g(77);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Mat3<double>> tensors;
  for (int k = 0; k < 4; ++k) {
    Mat3<double> A;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) A(i, j) = u(g);
    tensors.push_back(A * A.transpose() + Mat3<double>::Identity() * std::pow(10.0, -3 * k));
  }
  tensors.push_back(tensors[0]);
  tensors.back()(2, 2) *= 1.001;  // close to the first, with another condition
  REQUIRE(rounding::spd_condition(tensors[0]) != rounding::spd_condition(tensors[4]));
  std::uniform_int_distribution<std::size_t> pick(0, tensors.size() - 1);
  std::vector<std::size_t> order(2000);
  for (auto& o : order) o = pick(g);
  auto run = [&] {
    int wrong = 0, checked = 0;
    for (std::size_t o : order) {
      wrong += rounding::inertia_condition(tensors[o]) != rounding::spd_condition(tensors[o]);
      ++checked;
    }
    return std::pair{wrong, checked};
  };
  std::pair<int, int> other;
  std::thread t([&] { other = run(); });
  const auto own = run();
  t.join();
  CHECK(own.first == 0);
  CHECK(other.first == 0);
  CHECK(own.second + other.second == 4000);
}

}  // namespace check_precision_flags
