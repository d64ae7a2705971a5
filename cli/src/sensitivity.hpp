// `impact3d sensitivity CASE` (../shared/spec/many-cases.md): the derivative of every result number by
// every numeric input of the case, the regime held fixed; with --plot, a tornado figure per result.
#pragma once

#include <string>
#include <vector>

#include "impact3d/mechanics/problem.hpp"

namespace impact3d::cli {

struct SensitivityCliOptions {
  std::string case_path;
  std::string format = "text";  // text or json
  std::vector<std::string> strategies;
  Engine engine = Engine::generated;
  std::string plot_dir;  // tornado figures, when given
  bool png = false;
};

// Writes the report to standard output; returns the exit status (0). Throws case_format::CaseError naming the
// file and the JSON path of a bad input, UserError for a figure that cannot be written.
int sensitivity(const SensitivityCliOptions& o);

}  // namespace impact3d::cli
