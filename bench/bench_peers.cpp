// pc-crash from raw parameters (angles, full tensors, velocities, impulse centres) to the impulse, side by
// side in one run: impact3d's SIMD batches (each instruction set this CPU runs), its scalar lean path
// (impulse only, and with the post-impact velocities; both engines), analyze, and the naive scalar peer
// (bench/naive/pc_crash.hpp), on the same seeded random approaching collisions; Wach and Brach on the
// lanes and on the scalar lean path, on the same collisions.
// tests/mechanics/check_naive_peers.cpp holds the peer to impact3d, tests/mechanics/check_batch.cpp the batches to the lean
// path, tests/mechanics/check_lean.cpp the lean path to analyze.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <optional>
#include <random>
#include <vector>

#include "impact3d/mechanics/analysis.hpp"
#include "impact3d/mechanics/batch/columns.hpp"
#include "impact3d/scalar/limb_product.hpp"
#include "impact3d/scalar/multiprecision.hpp"
#include "peer_collisions.hpp"

using namespace impact3d;

namespace {

// 1024 collisions at mu = 0.5 and eps = 0.1, as in the measurements.
const std::vector<bench::NaiveCase>& cases() {
  static const std::vector<bench::NaiveCase> all = [] {
    auto cs = bench::random_collisions(1024, 11);
    for (auto& c : cs) c.mu = 0.5, c.restitution = 0.1;
    return cs;
  }();
  return all;
}

void pc_crash_naive(benchmark::State& state) {
  const auto& cs = cases();
  for (auto _ : state)
    for (const auto& c : cs) benchmark::DoNotOptimize(bench::naive_pc_crash(c));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * cs.size()));
}

template <Engine E>
void pc_crash_analyze(benchmark::State& state) {
  const auto& cs = cases();
  for (auto _ : state)
    for (const auto& c : cs) benchmark::DoNotOptimize(analyze(bench::scene_of(c), {PcCrash<double>{c.mu}}, E));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * cs.size()));
}

const std::vector<RawCollision<double>>& raw_cases() {
  static const std::vector<RawCollision<double>> all = [] {
    std::vector<RawCollision<double>> out;
    for (const auto& c : cases()) out.push_back(bench::raw_of(c));
    return out;
  }();
  return all;
}

template <Engine E, Want W>
void pc_crash_lean(benchmark::State& state) {
  const auto& cs = cases();
  const auto& raw = raw_cases();
  for (auto _ : state)
    for (std::size_t k = 0; k < raw.size(); ++k)
      benchmark::DoNotOptimize(solve_lean(raw[k], Strategy<double>(PcCrash<double>{cs[k].mu}), W, E));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * raw.size()));
}

// The first n collisions at 100 digits, their raw parameters the same decimals (a double converts exactly).
std::vector<RawCollision<mp::float100>> raw_100(std::size_t n) {
  std::vector<RawCollision<mp::float100>> raw;
  for (std::size_t k = 0; k < n; ++k) raw.push_back(bench::raw_as<mp::float100>(raw_cases()[k]));
  return raw;
}

// At 100 digits (MPFR, numbers in the object rather than on the heap): the first 64 collisions.
template <bool Lean>
void pc_crash_100(benchmark::State& state) {
  using F = mp::float100;
  const auto& cs = cases();
  const std::vector<RawCollision<F>> raw = raw_100(64);
  for (auto _ : state)
    for (std::size_t k = 0; k < raw.size(); ++k) {
      if constexpr (Lean)
        benchmark::DoNotOptimize(solve_lean(raw[k], Strategy<F>(PcCrash<F>{F(cs[k].mu)}), Want::impulse, Engine::generated));
      else
        benchmark::DoNotOptimize(analyze(scene_of(raw[k]), {PcCrash<F>{F(cs[k].mu)}}, Engine::generated));
    }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * raw.size()));
}

// Of which the raw parameters to a scene (nine sines and cosines, and the rotations).
void scene_of_100(benchmark::State& state) {
  const std::vector<RawCollision<mp::float100>> raw = raw_100(64);
  for (auto _ : state)
    for (const auto& r : raw) benchmark::DoNotOptimize(scene_of(r));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * raw.size()));
}

// The exact product of two 6-limb significands, which a 100-digit collision takes about 480 times:
// limb_product.hpp's assembly (argument 0) beside GMP's mpn_mul_n (1), on the same 1024 drawn pairs; and
// the assembly's top product (2: 21 of the 36 limb products, FixedFloat's where it decides the rounding).
void pc_crash_100_digits_product(benchmark::State& state) {
  namespace lp = mp::limb_product;
  const auto route = state.range(0);
  if (route != 1 && !lp::kAvailable) {
    state.SkipWithError("this processor lacks mulx or adx");
    return;
  }
  state.SetLabel(route == 0 ? "mulx/adx assembly" : route == 1 ? "GMP mpn_mul_n" : "mulx/adx top product");
  std::mt19937_64 g(12);
  std::vector<lp::Limb> a(6 * 1024), b(6 * 1024);
  for (auto& x : a) x = g();
  for (auto& x : b) x = g();
  lp::Limb w[12], top[7];
  for (auto _ : state)
    for (std::size_t k = 0; k < 1024; ++k) {
      if (route == 0) lp::multiply6(w, &a[6 * k], &b[6 * k]);
      else if (route == 1) mpn_mul_n(w, &a[6 * k], &b[6 * k], 6);
      else lp::multiply6_high(top, &a[6 * k], &b[6 * k]);
      benchmark::DoNotOptimize(w);
      benchmark::DoNotOptimize(top);
    }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * 1024));
}

// The same collisions as columns, solved on the lanes of one instruction set (the argument's index into
// batch::simd_available(), widest first).
void pc_crash_simd(benchmark::State& state) {
  const auto sets = batch::simd_available();
  const auto set = static_cast<std::size_t>(state.range(0));
  if (set >= sets.size() || !batch::use_simd(sets[set])) {
    state.SkipWithError("instruction set not available on this CPU");
    return;
  }
  state.SetLabel(sets[set]);
  const auto& cs = cases();
  batch::CollisionTable table(cs.size());
  for (std::size_t k = 0; k < cs.size(); ++k) table.set(k, raw_cases()[k], cs[k].mu);
  batch::ImpulseTable out(cs.size());
  const batch::CollisionColumns in = table.columns();
  const batch::ImpulseColumns o = out.columns();
  for (auto _ : state) {
    batch::pc_crash_columns(in, o, 0, cs.size());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * cs.size()));
  batch::use_simd(sets[0]);
}

// Wach and Brach on the same collisions, the widest lanes (batch::wach_columns, brach_columns) against
// the scalar lean path: 0 Wach capped at the CIR, 1 Brach with both ratios given, 2 Brach on the
// Critical Impulse Line (both critical).
Strategy<double> other_strategy(std::int64_t which, double mu) {
  if (which == 0) return Wach<double>{mu, WachLimit::cir};
  if (which == 1) return Brach<double>{0.8 * mu, 0.2 * mu};
  return Brach<double>{std::nullopt, std::nullopt};
}

void strategy_simd(benchmark::State& state) {
  const auto& cs = cases();
  batch::CollisionTable table(cs.size());
  std::vector<double> mu_t(cs.size()), mu_z(cs.size());
  for (std::size_t k = 0; k < cs.size(); ++k) {
    table.set(k, raw_cases()[k], cs[k].mu);
    mu_t[k] = 0.8 * cs[k].mu, mu_z[k] = 0.2 * cs[k].mu;
  }
  batch::ImpulseTable out(cs.size());
  const batch::CollisionColumns in = table.columns();
  const batch::ImpulseColumns o = out.columns();
  state.SetLabel(state.range(0) == 0 ? "wach cir" : state.range(0) == 1 ? "brach given" : "brach both critical");
  for (auto _ : state) {
    if (state.range(0) == 0) batch::wach_columns(in, WachLimit::cir, o, 0, cs.size());
    else if (state.range(0) == 1) batch::brach_columns(in, mu_t.data(), mu_z.data(), o, 0, cs.size());
    else batch::brach_columns(in, nullptr, nullptr, o, 0, cs.size());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * cs.size()));
}

void strategy_lean(benchmark::State& state) {
  const auto& cs = cases();
  const auto& raw = raw_cases();
  state.SetLabel(state.range(0) == 0 ? "wach cir" : state.range(0) == 1 ? "brach given" : "brach both critical");
  for (auto _ : state)
    for (std::size_t k = 0; k < raw.size(); ++k)
      benchmark::DoNotOptimize(solve_lean(scene_of(raw[k]), other_strategy(state.range(0), cs[k].mu)));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * raw.size()));
}

// Stronge's integration (stronge/integrate.hpp) on the scalar lean path, beside pc-crash on the same
// collisions (issue 59's targets: 5 us a case at double, 5 ms at 100 digits): energetic restitution at
// the same mu and eps; at 100 digits the first 16 collisions.
void stronge_lean(benchmark::State& state) {
  const auto& cs = cases();
  const auto& raw = raw_cases();
  for (auto _ : state)
    for (std::size_t k = 0; k < raw.size(); ++k)
      benchmark::DoNotOptimize(solve_lean(raw[k], Strategy<double>(Stronge<double>{cs[k].mu}), Want::impulse, Engine::generated));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * raw.size()));
}

void stronge_lean_100(benchmark::State& state) {
  using F = mp::float100;
  const auto& cs = cases();
  const std::vector<RawCollision<F>> raw = raw_100(16);
  for (auto _ : state)
    for (std::size_t k = 0; k < raw.size(); ++k)
      benchmark::DoNotOptimize(solve_lean(raw[k], Strategy<F>(Stronge<F>{F(cs[k].mu)}), Want::impulse, Engine::generated));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * raw.size()));
}

}  // namespace

BENCHMARK(pc_crash_simd)->DenseRange(0, 2);
BENCHMARK(strategy_simd)->Name("wach_brach_simd")->DenseRange(0, 2);
BENCHMARK(strategy_lean)->Name("wach_brach_lean")->DenseRange(0, 2);
// The least of the repetitions beside the mean: this host's load only ever adds time, so the least is
// the steadier figure for comparing routes measured in one run (BENCHMARKS.md gives both).
static double least(const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); }
BENCHMARK(pc_crash_lean<Engine::generated, Want::impulse>)->ComputeStatistics("min", least);
BENCHMARK(pc_crash_lean<Engine::direct, Want::impulse>);
BENCHMARK(pc_crash_lean<Engine::generated, Want::velocities>);
BENCHMARK(pc_crash_naive)->ComputeStatistics("min", least);
BENCHMARK(pc_crash_analyze<Engine::generated>);
BENCHMARK(pc_crash_analyze<Engine::direct>);
BENCHMARK(pc_crash_100<true>)->Name("pc_crash_lean_100_digits")->ComputeStatistics("min", least);
BENCHMARK(pc_crash_100<false>)->Name("pc_crash_analyze_100_digits");
BENCHMARK(scene_of_100)->Name("pc_crash_scene_of_100_digits");
BENCHMARK(stronge_lean)->ComputeStatistics("min", least);
BENCHMARK(stronge_lean_100)->Name("stronge_lean_100_digits")->Unit(benchmark::kMillisecond)->ComputeStatistics("min", least);
BENCHMARK(pc_crash_100_digits_product)->DenseRange(0, 2);
