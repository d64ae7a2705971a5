// The one parallel loop of batch, Monte Carlo and Python's solve_batch: items [0, n) in consecutive
// chunks, taken in turn by whichever thread is free. Item i is processed once and lands where the loop's
// body puts it (at index i), so a result never depends on the number of threads; a body that keeps
// state per thread is told which thread it runs on.
#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <system_error>
#include <thread>

#include "impact3d/scalar/helper_thread.hpp"
#include "impact3d/scalar/thread_caches.hpp"

namespace impact3d {

class ParallelChunks {
 public:
  // Wraps the making of each helper thread (to make it with signals masked, say); by default, makes it.
  using MakeHelper = std::function<void(const std::function<void()>& make)>;

  // `jobs` threads in all, the caller one of them (0: the hardware's). Helpers are made as a run first
  // needs them and kept for the next runs; a system that refuses more leaves the work to those running.
  explicit ParallelChunks(unsigned jobs, MakeHelper make_helper = {})
      : jobs_(jobs ? jobs : std::max(1u, std::thread::hardware_concurrency())), make_helper_(std::move(make_helper)) {}

  unsigned jobs() const { return jobs_; }

  // What the calling thread does beside its share. `first(helpers)` runs once the helpers have started,
  // before the caller takes a chunk (batch reads its next block there). With `report`, the caller takes
  // no chunk while a helper runs: it calls report(items done) every 100 ms and once at the end.
  struct Caller {
    std::function<void(unsigned helpers)> first;
    std::function<void(std::size_t done)> report;
  };

  // body(thread, begin, end) for each chunk [begin, end), thread < jobs(). The first exception a body
  // throws stops the others at their next chunk and is rethrown here once every thread has finished.
  template <typename Body>
  void run(std::size_t n, std::size_t chunk, Body&& body, const Caller& caller = {}) {
    chunk = std::max<std::size_t>(chunk, 1);
    const std::size_t chunks = n / chunk + (n % chunk != 0);
    const bool reports = static_cast<bool>(caller.report);
    // The caller is thread 0 unless it only reports; then the helpers are threads 0, 1, ...
    const std::size_t wanted = std::min<std::size_t>(reports ? jobs_ : jobs_ - 1, reports ? chunks : chunks - (chunks > 0));
    grow(static_cast<unsigned>(wanted));
    const unsigned helpers = static_cast<unsigned>(std::min<std::size_t>(wanted, helpers_.size()));
    const unsigned offset = reports && helpers > 0 ? 0 : 1;

    std::atomic<std::size_t> next{0}, done{0};
    std::atomic<bool> failed{false};
    std::exception_ptr error;
    std::mutex error_lock;
    auto record = [&] {
      const std::lock_guard lock(error_lock);
      if (!error) error = std::current_exception();
      failed = true;
    };
    auto work = [&](unsigned thread) {
      try {
        for (std::size_t begin; !failed && (begin = next.fetch_add(chunk)) < n;) {
          const std::size_t end = std::min(n, begin + chunk);
          body(thread, begin, end);
          done += end - begin;
        }
      } catch (...) {
        record();
      }
    };
    for (unsigned t = 0; t < helpers; ++t) helpers_[t].start([&work, t, offset] { work(t + offset); });
    // Whatever the caller's part throws, the helpers, which read this frame, are waited for first.
    try {
      if (caller.first) caller.first(helpers);
      if (reports && helpers > 0) {
        while (done < n && !failed) {
          caller.report(done);
          std::this_thread::sleep_for(std::chrono::milliseconds(100));
        }
      }
    } catch (...) {
      record();
    }
    if (!(reports && helpers > 0)) work(0);
    for (unsigned t = 0; t < helpers; ++t) helpers_[t].wait();
    if (reports && !failed) caller.report(done);
    if (error) std::rethrow_exception(error);
  }

 private:
  void grow(unsigned wanted) {
    if (helpers_.size() >= wanted || refused_) return;
    fill_shared_before_threads();  // before the first helper starts (thread_caches.hpp)
    try {
      while (helpers_.size() < wanted) {
        if (make_helper_) make_helper_([&] { helpers_.emplace_back(); });
        else helpers_.emplace_back();
      }
    } catch (const std::system_error&) {
      refused_ = true;  // no more threads to be had: those made share the work
    }
  }

  unsigned jobs_;
  MakeHelper make_helper_;
  bool refused_ = false;
  std::deque<HelperThread> helpers_;  // a deque: a helper never moves once made
};

}  // namespace impact3d
