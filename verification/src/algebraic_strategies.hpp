// A case's strategies that have fractions and enclosures, with their index in the case: stronge
// integrates through events at transcendental roots and has neither, so verify's exact check and
// --certify leave it out and hold it to the 100-digit solve within its stated bound instead.
#pragma once

#include <cstddef>
#include <variant>
#include <vector>

#include "impact3d/case_format/to_scene.hpp"

namespace impact3d::verification {

template <typename T>
struct AlgebraicStrategies {
  std::vector<Strategy<T>> strategies;
  std::vector<std::size_t> index;  // of each in the case's list
};

template <typename T>
AlgebraicStrategies<T> algebraic_strategies(const case_format::CaseSpec& spec) {
  AlgebraicStrategies<T> out;
  const std::vector<Strategy<T>> all = case_format::to_strategies<T>(spec);
  for (std::size_t k = 0; k < all.size(); ++k)
    if (!std::holds_alternative<Stronge<T>>(all[k])) out.strategies.push_back(all[k]), out.index.push_back(k);
  return out;
}

}  // namespace impact3d::verification
