#include "impact3d/scalar/thread_caches.hpp"

#if IMPACT3D_MULTIPRECISION
#include <flint/flint.h>
#include <mpfr.h>

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
namespace mp {
const bool limits_filled = (fill_shared_before_threads(), true);
}  // namespace mp
#endif

void fill_shared_before_threads() {
#if IMPACT3D_MULTIPRECISION
  mp::fill_limits<mp::float50>();
  mp::fill_limits<mp::float100>();
#endif
}

}  // namespace impact3d
