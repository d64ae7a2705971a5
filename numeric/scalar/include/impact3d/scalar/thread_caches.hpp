// MPFR and FLINT keep caches per thread (pi, the arctangent's tables, Arb's powers and working memory),
// which a thread must free before it ends or they are lost with it. Every thread impact3d starts that may
// compute at 100 digits or in balls holds a ThreadCaches for its whole life.
#pragma once

namespace impact3d {

// This thread's caches freed (nothing without multiprecision); they are rebuilt if it computes again.
void free_thread_caches();

// What the multiprecision numbers fill on first use and share between threads (std::numeric_limits,
// see thread_caches.cpp) filled now. Called by a thread about to start others, so that the guarantee
// does not rest on the compiler running the start-up fill (multiprecision.hpp's limits_filled) before
// main, which the standard lets it defer.
void fill_shared_before_threads();

struct ThreadCaches {
  ThreadCaches() = default;
  ThreadCaches(const ThreadCaches&) = delete;
  ThreadCaches& operator=(const ThreadCaches&) = delete;
  ~ThreadCaches() { free_thread_caches(); }
};

}  // namespace impact3d
