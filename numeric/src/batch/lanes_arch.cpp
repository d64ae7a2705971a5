// The lane kernel for one instruction set: numeric/CMakeLists.txt compiles this file once per entry of
// IMPACT3D_BATCH_ARCHES with IMPACT3D_BATCH_ARCH_NAME, IMPACT3D_BATCH_ARCH_TYPE and that set's flags.
#include "lanes.hpp"
#include "lanes_entry.hpp"

namespace impact3d::batch::lanes {

#define IMPACT3D_RUN_NAME_(name) run_##name
#define IMPACT3D_RUN_NAME(name) IMPACT3D_RUN_NAME_(name)
#define IMPACT3D_SIN_COS_NAME_(name) sin_cos_##name
#define IMPACT3D_SIN_COS_NAME(name) IMPACT3D_SIN_COS_NAME_(name)

std::size_t IMPACT3D_RUN_NAME(IMPACT3D_BATCH_ARCH_NAME)(const CollisionColumns& in, const ImpulseColumns& out,
                                                      std::size_t begin, std::size_t end) {
  using B = xsimd::batch<double, IMPACT3D_BATCH_ARCH_TYPE>;
  std::size_t i = begin;
  for (; i + B::size <= end; i += B::size) pc_crash<B>(in, out, i);
  return i;
}

std::size_t IMPACT3D_SIN_COS_NAME(IMPACT3D_BATCH_ARCH_NAME)(const double* deg, double* s, double* c, std::size_t n) {
  using B = xsimd::batch<double, IMPACT3D_BATCH_ARCH_TYPE>;
  std::size_t i = 0;
  for (; i + B::size <= n; i += B::size) {
    const SinCosB<B> r = sin_cos_deg(B::load_unaligned(deg + i));
    r.s.store_unaligned(s + i);
    r.c.store_unaligned(c + i);
  }
  return i;
}

}  // namespace impact3d::batch::lanes
