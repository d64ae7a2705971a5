// Facts of the derivation that no printed equation states, checked on every run of the generator.
#pragma once

#include <string>
#include <vector>

#include "closed_forms.hpp"
#include "model.hpp"

namespace impact3d::symbolic {

// Each returns its statement; throws std::runtime_error if it does not hold.
std::vector<std::string> self_checks(const Derivation& d, const ClosedForms& c);

}  // namespace impact3d::symbolic
