// dual_analysis.hpp's one instantiation.
#include "impact3d/mechanics/dual_analysis.hpp"

namespace impact3d {
template Analysis<Dual> analyze(const Scene<Dual>&, const std::vector<Strategy<Dual>>&, Engine);
}  // namespace impact3d
