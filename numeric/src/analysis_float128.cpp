// Explicit instantiation at quadruple precision (one type a file: each takes a while to compile).
#include "impact3d/numeric/analysis.hpp"
#include "impact3d/numeric/multiprecision.hpp"

namespace impact3d {
template Analysis<mp::float128> analyze(const Scene<mp::float128>&, const std::vector<Strategy<mp::float128>>&, Engine);
}  // namespace impact3d
