// The studies' mark of a number not computed: a sample that failed, an output without a derivative, a
// model value outside its domain.
#pragma once

#include <limits>

namespace impact3d::studies {
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}  // namespace impact3d::studies
