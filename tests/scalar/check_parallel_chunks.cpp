// The one parallel loop (numeric/scalar/include/impact3d/scalar/parallel_chunks.hpp): every item is
// processed exactly once, by a thread below jobs(), whatever the number of threads and the chunk; a
// result written at each item's index is the same bit for bit at any number of threads; the first
// exception comes out of run() after every thread has stopped; the caller's hooks run as documented.
// Known answers by counting; the values per item are exact integers.
#include <catch2/catch.hpp>

#include <atomic>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "impact3d/scalar/parallel_chunks.hpp"

namespace check_parallel_chunks {

using impact3d::ParallelChunks;

namespace {

// Item i's value: a hash of i, so that a misplaced item is seen.
std::uint64_t value_of(std::size_t i) {
  std::uint64_t x = i + 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  return x ^ (x >> 27);
}

}  // namespace

TEST_CASE("every item is processed once and lands at its index, at any number of threads and chunk", "[parallel]") {
  int runs = 0;
  for (unsigned jobs : {1u, 2u, 3u, 7u})
    for (std::size_t n : {std::size_t{0}, std::size_t{1}, std::size_t{5}, std::size_t{1000}, std::size_t{4097}})
      for (std::size_t chunk : {std::size_t{1}, std::size_t{64}, std::size_t{4096}}) {
        ParallelChunks pool(jobs);
        std::vector<std::uint64_t> out(n, 0);
        std::vector<std::atomic<int>> seen(n);
        std::atomic<bool> thread_in_range{true};
        pool.run(n, chunk, [&](unsigned thread, std::size_t begin, std::size_t end) {
          if (thread >= pool.jobs()) thread_in_range = false;
          for (std::size_t i = begin; i < end; ++i) out[i] = value_of(i), ++seen[i];
        });
        CHECK(thread_in_range);
        std::size_t wrong = 0;
        for (std::size_t i = 0; i < n; ++i) wrong += seen[i] != 1 || out[i] != value_of(i);
        INFO("jobs " << jobs << ", n " << n << ", chunk " << chunk);
        CHECK(wrong == 0);
        ++runs;
      }
  CHECK(runs == 4 * 5 * 3);
}

TEST_CASE("a pool kept for many runs serves each of them", "[parallel]") {
  ParallelChunks pool(3);
  std::uint64_t total = 0;
  constexpr int kRuns = 200;
  for (int r = 0; r < kRuns; ++r) {
    std::vector<std::uint64_t> out(97);
    pool.run(out.size(), 5, [&](unsigned, std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) out[i] = i + 1;
    });
    for (auto x : out) total += x;
  }
  CHECK(total == static_cast<std::uint64_t>(kRuns) * 97 * 98 / 2);
}

TEST_CASE("the first exception comes out of run once every thread has stopped", "[parallel]") {
  for (unsigned jobs : {1u, 2u, 4u}) {
    ParallelChunks pool(jobs);
    std::atomic<int> running{0}, after{0};
    bool thrown = false;
    try {
      pool.run(100000, 10, [&](unsigned, std::size_t begin, std::size_t) {
        ++running;
        if (begin == 500) {
          --running;
          throw std::runtime_error("item 500");
        }
        --running;
      });
    } catch (const std::runtime_error& e) {
      thrown = std::string(e.what()) == "item 500";
      after = running.load();
    }
    INFO("jobs " << jobs);
    CHECK(thrown);
    CHECK(after == 0);  // no body still running when run() returned
    // The pool still serves.
    std::atomic<std::size_t> sum{0};
    pool.run(10, 1, [&](unsigned, std::size_t b, std::size_t) { sum += b; });
    CHECK(sum == 45);
  }
}

TEST_CASE("the caller's first hook runs once with the helpers started; report sees every item done", "[parallel]") {
  for (unsigned jobs : {1u, 2u, 3u}) {
    ParallelChunks pool(jobs);
    std::vector<unsigned> firsts;
    std::vector<std::size_t> reports;
    std::atomic<std::size_t> items{0};
    ParallelChunks::Caller caller;
    caller.first = [&](unsigned helpers) { firsts.push_back(helpers); };
    caller.report = [&](std::size_t done) { reports.push_back(done); };
    pool.run(3000, 7, [&](unsigned, std::size_t b, std::size_t e) { items += e - b; }, caller);
    INFO("jobs " << jobs);
    CHECK(items == 3000);
    REQUIRE(firsts.size() == 1);
    CHECK(firsts[0] == jobs);  // reporting, the caller takes no chunk: every job is a helper
    REQUIRE(!reports.empty());
    CHECK(reports.back() == 3000);
    // Without a report the caller works: one helper fewer.
    firsts.clear();
    pool.run(3000, 7, [&](unsigned, std::size_t, std::size_t) {}, {caller.first, {}});
    REQUIRE(firsts.size() == 1);
    CHECK(firsts[0] == jobs - 1);
  }
}

}  // namespace check_parallel_chunks
