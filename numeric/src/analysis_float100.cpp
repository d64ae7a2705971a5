// Explicit instantiation at 100 decimal digits (MPFR): the precision of the reference outputs.
#include "impact3d/numeric/analysis.hpp"
#include "impact3d/numeric/multiprecision.hpp"

namespace impact3d {
template Analysis<mp::float100> analyze(const Scene<mp::float100>&, const std::vector<Strategy<mp::float100>>&, Engine);
}  // namespace impact3d
