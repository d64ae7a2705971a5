// Why a comparison fails, when most of its failures have one cause: the other tool's sign convention,
// its numbering of the vehicles, or its units.
#pragma once

#include <string>
#include <unordered_map>
#include <vector>

namespace impact3d::verification::detail {

// A failing number: the reference value, the other tool's, and the tolerance it was held to.
struct NumericFailure {
  std::string leaf;  // dotted path below its result (vehicles.0.delta_v.1) or from the top (coefficients.K.0.1)
  double reference, other, rtol, atol;
  const std::unordered_map<std::string, double>* result_numbers;  // the reference result's numbers, or null
};

// One line per cause that explains more than half of the failures (empty when none does).
std::vector<std::string> diagnose(const std::vector<NumericFailure>& failures);

}  // namespace impact3d::verification::detail
