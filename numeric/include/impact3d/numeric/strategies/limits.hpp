// Shared handling of a critical or generalized impulse ratio that came out non-finite.
#pragma once

#include <cmath>
#include <string>

#include "impact3d/numeric/strategy.hpp"

namespace impact3d::strategies {

template <typename Scalar>
void flag_if_not_finite(ImpulseSolution<Scalar>& out, const Scalar& value, const std::string& name) {
  using std::isfinite;
  if (!isfinite(value))
    out.warnings.push_back({WarningCode::non_physical_limit,
                            name + " is undefined: the normal impulse of the solution that defines it is zero"});
}

template <typename Scalar>
void flag_if_negative_ratio(ImpulseSolution<Scalar>& out, const Scalar& mu, const std::string& name) {
  if (mu < Scalar(0))
    out.warnings.push_back({WarningCode::negative_ratio,
                            name + " used is negative: the contact-plane impulse acts along the initial sliding"});
}

}  // namespace impact3d::strategies
