// `impact3d montecarlo CASE --uncertainty U` (../shared/spec/many-cases.md): the case solved for every
// sample of its uncertain inputs, summarized per strategy.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "impact3d/mechanics/problem.hpp"
#include "impact3d/cli/montecarlo_plot.hpp"

namespace impact3d::cli {

struct MonteCarloCliOptions {
  std::string case_path, uncertainty_path;
  std::string format = "text";  // text or json
  std::optional<std::uint64_t> samples, seed;  // replace the file's
  unsigned jobs = 0;
  std::string samples_out;  // every sample as CSV, when given
  MonteCarloPlotOptions plot;  // figures, when out_dir is given
  std::vector<std::string> strategies;
  std::string precision = "double";
  Engine engine = Engine::generated;
};

// Writes the summary to standard output; returns the exit status (0). Throws case_format::CaseError naming the
// file and the JSON path of a bad input, UserError for an output that cannot be written.
int montecarlo(const MonteCarloCliOptions& o);

}  // namespace impact3d::cli
