#include "impact3d/numeric/thread_caches.hpp"

#if IMPACT3D_MULTIPRECISION
#include <flint/flint.h>
#include <mpfr.h>
#endif

namespace impact3d {

void free_thread_caches() {
#if IMPACT3D_MULTIPRECISION
  mpfr_free_cache2(MPFR_FREE_LOCAL_CACHE);
  flint_cleanup();
#endif
}

}  // namespace impact3d
