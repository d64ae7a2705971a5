// Cases per second at each precision and engine, and where the time of one case goes: reading the
// JSON, converting the decimals to a scene, K, the strategies and their consequences, and printing.
#include <benchmark/benchmark.h>

#include <charconv>
#include <fstream>
#include <sstream>
#include <vector>

#include "impact3d/case_format/format_double.hpp"
#include "impact3d/case_format/json_tree.hpp"
#include "impact3d/case_format/read_case.hpp"
#include "impact3d/mechanics/certified.hpp"
#include "impact3d/mechanics/exact_analysis.hpp"
#include "impact3d/scalar/multiprecision.hpp"

using namespace impact3d;

namespace {

const std::string& case_text() {
  static const std::string text = [] {
    std::ifstream in(IMPACT3D_BENCH_CASE);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
  }();
  return text;
}

const case_format::CaseSpec& spec() {
  static const case_format::CaseSpec s = case_format::read_case(case_text());
  return s;
}

void read_case(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(case_format::read_case(case_text()));
}

template <typename T>
void to_scene(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(case_format::to_scene<T>(spec()));
}

template <typename T, Engine E>
void coefficient_matrix(benchmark::State& state) {
  const Scene<T> s = case_format::to_scene<T>(spec());
  for (auto _ : state) {
    if constexpr (E == Engine::generated) benchmark::DoNotOptimize(GeneratedEngine::coefficient_matrix(s));
    else benchmark::DoNotOptimize(direct::DirectEngine::coefficient_matrix(s));
  }
}

// One case: K, the impulse space and the case's four strategies with their post-impact states.
template <typename T, Engine E>
void solve(benchmark::State& state) {
  const Scene<T> s = case_format::to_scene<T>(spec());
  const auto st = case_format::to_strategies<T>(spec());
  for (auto _ : state) benchmark::DoNotOptimize(analyze(s, st, E));
  state.counters["cases/s"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

// Exact rational arithmetic on a case whose rotations are rational (K and every strategy as fractions).
void solve_exact(benchmark::State& state) {
  std::ifstream in(IMPACT3D_BENCH_EXACT_CASE);
  std::ostringstream ss;
  ss << in.rdbuf();
  const case_format::CaseSpec c = case_format::read_case(ss.str());
  const Scene<rational> s = case_format::to_scene<rational>(c);
  const auto st = case_format::to_strategies<rational>(c);
  for (auto _ : state) benchmark::DoNotOptimize(exact_analyze(s, st));
  state.counters["cases/s"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

// Ball arithmetic at state.range(0) bits (issue 14): the same analyze per strategy under a decision log,
// and once more for each decision the balls leave undecided (Figure 8's Full Impact has two: its final
// sliding is exactly -e times the initial, a zero no ball can prove). Compare with solve<float100>.
void solve_certified(benchmark::State& state) {
  const BallBits bits(state.range(0));
  const Scene<Ball> s = case_format::to_scene<Ball>(spec());
  const auto st = case_format::to_strategies<Ball>(spec());
  for (auto _ : state) benchmark::DoNotOptimize(certified_analyze(s, st));
  state.counters["cases/s"] = benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

template <typename T>
void result_json(benchmark::State& state) {
  const auto a = analyze(case_format::to_scene<T>(spec()), case_format::to_strategies<T>(spec()));
  for (auto _ : state) benchmark::DoNotOptimize(case_format::result_json(spec(), a, "p"));
}

// The 17 digits of each number in Figure 8's result document (what a batch row prints), one number per
// item, against std::to_chars at precision 17 (the same text).
const std::vector<double>& printed_numbers() {
  static const std::vector<double> numbers = [] {
    const std::string doc = case_format::result_json(spec(), analyze(case_format::to_scene<double>(spec()), case_format::to_strategies<double>(spec())), "p");
    std::vector<double> v;
    auto collect = [&](const auto& self, const case_format::JsonValue& node) -> void {
      if (node.is(case_format::JsonValue::Type::number)) v.push_back(node.number);
      for (const auto& item : node.items) self(self, item);
    };
    collect(collect, case_format::parse_json_tree(doc));
    return v;
  }();
  return numbers;
}

void format_g17(benchmark::State& state) {
  char buf[32];
  for (auto _ : state)
    for (const double x : printed_numbers()) benchmark::DoNotOptimize(case_format::format_g17(buf, x));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(printed_numbers().size()));
}

void to_chars_17(benchmark::State& state) {
  char buf[32];
  for (auto _ : state)
    for (const double x : printed_numbers())
      benchmark::DoNotOptimize(std::to_chars(buf, buf + sizeof buf, x, std::chars_format::general, 17).ptr);
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(printed_numbers().size()));
}

}  // namespace

BENCHMARK(read_case);
BENCHMARK(to_scene<double>);
BENCHMARK(to_scene<mp::float100>);
BENCHMARK(coefficient_matrix<double, Engine::generated>);
BENCHMARK(coefficient_matrix<double, Engine::direct>);
BENCHMARK(coefficient_matrix<mp::float100, Engine::generated>);
BENCHMARK(coefficient_matrix<mp::float100, Engine::direct>);
BENCHMARK(solve<double, Engine::generated>);
BENCHMARK(solve<double, Engine::direct>);
BENCHMARK(solve<long double, Engine::generated>);
BENCHMARK(solve<long double, Engine::direct>);
BENCHMARK(solve<mp::float128, Engine::generated>);
BENCHMARK(solve<mp::float128, Engine::direct>);
BENCHMARK(solve<mp::float50, Engine::generated>);
BENCHMARK(solve<mp::float50, Engine::direct>);
BENCHMARK(solve<mp::float100, Engine::generated>);
BENCHMARK(solve<mp::float100, Engine::direct>);
BENCHMARK(solve_exact);
BENCHMARK(solve_certified)->Arg(128)->Arg(256)->Arg(512);
BENCHMARK(result_json<double>);
BENCHMARK(result_json<mp::float100>);
BENCHMARK(format_g17);
BENCHMARK(to_chars_17);

BENCHMARK_MAIN();
