// impact3d.solve: the contract's result document (case-format.md) as `impact3d solve --format json`
// prints it; the Python side turns its numbers into floats, Decimals or Fractions.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "case.hpp"
#include "impact3d/mechanics/problem.hpp"

namespace impact3d::python {

// `strategies`: each as solve's --strategy takes it ("pc-crash:mu=0.4" or a JSON object), replacing
// the case's when any; `engine`: "generated" or "direct"; `units`: SI, US or metric-kmh (default the
// case's). A bad option is std::invalid_argument (Python: ValueError) with the CLI's usage text.
std::string solve_json(const Case& c, const std::vector<std::string>& strategies, const std::string& engine,
                       const std::string& precision, const std::optional<std::string>& units);

// "generated" or "direct", else std::invalid_argument.
Engine engine_named(const std::string& name);

// The case's strategies replaced by `strategies` (as --strategy reads them), when any.
void replace_strategies(case_format::CaseSpec& spec, const std::vector<std::string>& strategies);

}  // namespace impact3d::python
