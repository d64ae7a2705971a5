// The lane kernels, one per instruction set (lanes_arch.cpp compiled with its flags). Each solves the
// whole lane groups of rows [begin, end) and returns where it stopped; the rest of the rows, and the rows
// it marks lanes::kDeferred, are the caller's to solve on the scalar path.
#pragma once

#include <cstddef>
#include <cstdint>

#include "impact3d/mechanics/batch/columns.hpp"

namespace impact3d::batch::lanes {

// Status value of a row the lanes leave to the scalar path.
inline constexpr std::uint8_t kDeferred = 0xff;

#define IMPACT3D_BATCH_ARCHES(X) X(avx512f, 8) X(avx2_fma, 4) X(sse2, 2)

#define IMPACT3D_DECLARE_LANES_(name, width)                                                                        \
  std::size_t pc_crash_##name(const CollisionColumns& in, const ImpulseColumns& out, std::size_t begin, std::size_t end); \
  std::size_t wach_##name(const CollisionColumns& in, bool at_cir, const ImpulseColumns& out, std::size_t begin,        \
                          std::size_t end);                                                                           \
  std::size_t brach_##name(const CollisionColumns& in, const double* mu_t, const double* mu_z,                          \
                           const ImpulseColumns& out, std::size_t begin, std::size_t end);                            \
  std::size_t sin_cos_##name(const double* deg, double* s, double* c, std::size_t n);
IMPACT3D_BATCH_ARCHES(IMPACT3D_DECLARE_LANES_)
#undef IMPACT3D_DECLARE_LANES_

}  // namespace impact3d::batch::lanes
