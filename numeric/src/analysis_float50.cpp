// Explicit instantiation at 50 decimal digits (Boost cpp_bin_float).
#include "impact3d/numeric/analysis.hpp"
#include "impact3d/numeric/multiprecision.hpp"

namespace impact3d {
template Analysis<mp::float50> analyze(const Scene<mp::float50>&, const std::vector<Strategy<mp::float50>>&, Engine);
}  // namespace impact3d
