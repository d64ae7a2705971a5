// Explicit instantiations for the default scalar types.
#include "impact3d/numeric/analysis.hpp"

namespace impact3d {

template Analysis<double> analyze(const Scene<double>&, const std::vector<Strategy<double>>&, Engine);
template Analysis<long double> analyze(const Scene<long double>&, const std::vector<Strategy<long double>>&, Engine);

}  // namespace impact3d
