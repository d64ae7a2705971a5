// pc-crash from raw parameters (angles, full tensors, velocities, impulse centres) to the impulse, side by
// side in one run: impact3d's analyze and the naive scalar peer (bench/naive/pc_crash.hpp), on the same
// seeded random approaching collisions. tests/check_naive_peers.cpp holds the peer to impact3d.
#include <benchmark/benchmark.h>

#include <vector>

#include "impact3d/numeric/analysis.hpp"
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

}  // namespace

BENCHMARK(pc_crash_naive);
BENCHMARK(pc_crash_analyze<Engine::generated>);
BENCHMARK(pc_crash_analyze<Engine::direct>);
