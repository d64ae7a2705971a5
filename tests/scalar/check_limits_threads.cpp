// std::numeric_limits of the multiprecision numbers read first by two threads at once (batch --jobs,
// Monte Carlo on threads): Boost 1.74 left a window in which a thread read float100's epsilon as 0 or 1,
// and a batch row at 100 digits then differed from solve's. The race can happen once per process, so
// limits_race_probe races two threads in each of many fresh processes. Without the start-up fill
// (multiprecision.hpp's limits_filled), 114 of 500 such processes read a wrong value on the project's idle machine (some
// copied a number half written, which MPFR then refused) and 24 of 300 on the same machine under a full
// build's load; at the lower rate 200 runs would all pass with probability 0.92^200 < 1e-7. (float50's
// half of the probe cannot fail with Boost 1.74, which fills those itself; it guards the default.)
#include <catch2/catch.hpp>

#include "cli_process.hpp"

namespace check_limits_threads {

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

}  // namespace check_limits_threads
