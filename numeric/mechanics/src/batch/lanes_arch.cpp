// The lane kernel for one instruction set: numeric/CMakeLists.txt compiles this file once per entry of
// IMPACT3D_BATCH_ARCHES with IMPACT3D_BATCH_ARCH_NAME, IMPACT3D_BATCH_ARCH_TYPE and that set's flags.
#include "lanes.hpp"
#include "lanes_entry.hpp"

namespace impact3d::batch::lanes {

#define IMPACT3D_LANES_NAME_(what, name) what##_##name
#define IMPACT3D_LANES_NAME(what, name) IMPACT3D_LANES_NAME_(what, name)
#define IMPACT3D_SIN_COS_NAME(name) IMPACT3D_LANES_NAME(sin_cos, name)

using B = xsimd::batch<double, IMPACT3D_BATCH_ARCH_TYPE>;

std::size_t IMPACT3D_LANES_NAME(pc_crash, IMPACT3D_BATCH_ARCH_NAME)(const CollisionColumns& in, const ImpulseColumns& out,
                                                                   std::size_t begin, std::size_t end) {
  std::size_t i = begin;
  for (; i + B::size <= end; i += B::size) pc_crash<B>(in, out, i);
  return i;
}

std::size_t IMPACT3D_LANES_NAME(wach, IMPACT3D_BATCH_ARCH_NAME)(const CollisionColumns& in, bool at_cir,
                                                               const ImpulseColumns& out, std::size_t begin,
                                                               std::size_t end) {
  std::size_t i = begin;
  for (; i + B::size <= end; i += B::size) wach<B>(in, at_cir, out, i);
  return i;
}

std::size_t IMPACT3D_LANES_NAME(brach, IMPACT3D_BATCH_ARCH_NAME)(const CollisionColumns& in, const double* mu_t,
                                                                const double* mu_z, const ImpulseColumns& out,
                                                                std::size_t begin, std::size_t end) {
  std::size_t i = begin;
  for (; i + B::size <= end; i += B::size) brach<B>(in, mu_t, mu_z, out, i);
  return i;
}

std::size_t IMPACT3D_SIN_COS_NAME(IMPACT3D_BATCH_ARCH_NAME)(const double* deg, double* s, double* c, std::size_t n) {
  std::size_t i = 0;
  for (; i + B::size <= n; i += B::size) {
    const SinCos<B> r = sin_cos_deg(B::load_unaligned(deg + i));
    r.s.store_unaligned(s + i);
    r.c.store_unaligned(c + i);
  }
  return i;
}

}  // namespace impact3d::batch::lanes
