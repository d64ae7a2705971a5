// std::numeric_limits of the multiprecision numbers read first by two threads at once (batch --jobs,
// solve_batch, Monte Carlo on threads): Boost 1.74 left a window in which a thread read epsilon as 0 or
// 1, and a batch row at 100 digits then differed from solve's. The race can happen once per process, so
// limits_race_probe races two threads in each of many fresh processes. Without the start-up fill in
// multiprecision.hpp 114 of 500 such processes read a wrong value on the project's machine (some copied
// a number half written, which MPFR then refused), so 200 runs without one would be far beyond chance
// (0.8^200 < 1e-19).
#include <catch2/catch.hpp>

#include "cli_process.hpp"

TEST_CASE("two threads reading the multiprecision limits first read the right values", "[threads]") {
  constexpr int kRuns = 200;
  int runs = 0;
  for (int i = 0; i < kRuns; ++i) {
    const impact3d::test::Run r = impact3d::test::run_program(LIMITS_RACE_PROBE, {});
    INFO(r.out << r.err);
    REQUIRE(r.status == 0);
    ++runs;
  }
  CHECK(runs == kRuns);
}
