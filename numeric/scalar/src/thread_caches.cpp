#include "impact3d/scalar/thread_caches.hpp"

#if IMPACT3D_MULTIPRECISION
#include <flint/flint.h>
#include <mpfr.h>

#include <limits>

#include "impact3d/scalar/multiprecision.hpp"
#endif

namespace impact3d {

void free_thread_caches() {
#if IMPACT3D_MULTIPRECISION
  mpfr_free_cache2(MPFR_FREE_LOCAL_CACHE);
  flint_cleanup();
#endif
}

#if IMPACT3D_MULTIPRECISION
namespace {
// Boost 1.74 computes std::numeric_limits' epsilon, round_error, min, max, infinity and quiet_NaN of
// its MPFR numbers on the first call, and marks each computed before computing it: a second thread
// calling in that window reads 0 or 1 (for epsilon, or for infinity), or a number half copied. Boost
// fills them at start-up only for the MPFR numbers with expression templates, not for float100 (et_off),
// so the first rows of a batch at 100 digits on two threads could be solved with epsilon 0 (CI saw such
// a row differ from solve's). Filling them before any thread exists closes the window. float50's
// (cpp_bin_float, whose default is already et_off) Boost fills itself; they are filled here too so that
// the guarantee does not rest on that default.
template <typename T>
void fill_limits() {
  using L = std::numeric_limits<T>;
  (void)L::epsilon(), (void)L::round_error(), (void)(L::min)(), (void)(L::max)(), (void)L::infinity(), (void)L::quiet_NaN();
}
}  // namespace

namespace mp {
// At start-up (multiprecision.hpp: every object using these numbers links this one).
const bool limits_filled = (fill_shared_before_threads(), true);
}  // namespace mp
#endif

void fill_shared_before_threads() {
#if IMPACT3D_MULTIPRECISION
  fill_limits<mp::float50>();
  fill_limits<mp::float100>();
#endif
}

}  // namespace impact3d
