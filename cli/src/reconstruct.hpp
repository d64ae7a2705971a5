// `impact3d reconstruct CASE --evidence E` (../shared/spec/many-cases.md): the unknowns of an evidence
// file solved for by weighted least squares on the case's strategy.
#pragma once

#include <string>

#include "impact3d/mechanics/problem.hpp"

namespace impact3d::cli {

struct ReconstructCliOptions {
  std::string case_path, evidence_path;
  std::string format = "text";  // text or json
  std::string strategy;         // replaces the case's, when given
  Engine engine = Engine::generated;
  std::string plot_dir;  // the figures, when given (reconstruct_plot.hpp)
  bool png = false;
};

// Writes the report to standard output; returns the exit status (0). Throws case_format::CaseError naming the
// file (the case's or the evidence's) and the JSON path of a bad input.
int reconstruct(const ReconstructCliOptions& o);

}  // namespace impact3d::cli
