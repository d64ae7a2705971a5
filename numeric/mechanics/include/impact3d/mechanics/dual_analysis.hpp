// analyze() on dual numbers (autodiff.hpp), compiled once (numeric/mechanics/src/dual_analysis.cpp) for the
// sensitivities and the reconstruction's fits, each of which would otherwise instantiate the whole
// mechanics at Dual again.
#pragma once

#include "impact3d/mechanics/analysis.hpp"
#include "impact3d/scalar/autodiff.hpp"

namespace impact3d {
extern template Analysis<Dual> analyze(const Scene<Dual>&, const std::vector<Strategy<Dual>>&, Engine);
}  // namespace impact3d
