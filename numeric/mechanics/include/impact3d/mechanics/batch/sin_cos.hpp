// sin_cos_deg (rotation.hpp) of many angles on SIMD lanes: what the batches and the raw parameters of
// one collision (raw_collision.hpp) take their rotations from. Within 4 ulps of the scalar path
// (tests/mechanics/check_batch.cpp); multiples of 90 degrees exact.
#pragma once

#include <cstddef>

namespace impact3d::batch {

void sin_cos_deg_columns(const double* deg, double* s, double* c, std::size_t n);

}  // namespace impact3d::batch
