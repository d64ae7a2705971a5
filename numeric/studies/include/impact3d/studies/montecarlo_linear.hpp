// The first-order propagation of a Monte Carlo run's inputs (montecarlo.hpp, Linearized), made after
// the samples so that it can be compared with them.
#pragma once

#include "impact3d/case_format/case_variants.hpp"
#include "impact3d/studies/montecarlo.hpp"
#include "impact3d/case_format/read_uncertainty.hpp"

namespace impact3d::studies {

using case_format::CaseVariants;

// Fills each result's `linear`; where no linearization can be made (the case at the means refused, an
// input that is not differentiated), its `note` says why.
void linearize(MonteCarloRun& run, CaseVariants& variants, const UncertaintySpec& u, const MonteCarloOptions& o);

}  // namespace impact3d::studies
