// `impact3d montecarlo` as a library (many-cases.md, "montecarlo"): a case solved for every sample of
// its uncertain inputs, and each result's outputs summarized. A sample is the case with the sampled
// numbers written at their paths and solved exactly as `solve` would solve that case; its outputs are
// the numbers of the result document at the paths of monte_carlo_outputs(), taken as the document is
// written (json_pick.hpp). A sample that the case's rules refuse, that does not approach, or whose
// strategy has no solution is counted by its reason, never dropped.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "impact3d/case_format/case_spec.hpp"
#include "impact3d/case_format/result_outputs.hpp"
#include "impact3d/studies/precision.hpp"
#include "impact3d/case_format/read_uncertainty.hpp"
#include "impact3d/mechanics/problem.hpp"
#include "impact3d/mechanics/strategy.hpp"
#include "impact3d/uncertainty/statistics.hpp"

namespace impact3d::studies {

using case_format::JsonPath;
using case_format::OutputPath;
using case_format::monte_carlo_outputs;
using case_format::StrategySpec;
using case_format::UncertaintySpec;


// The warnings of a result, counted by code: their spelling in the output.
inline constexpr std::array<std::string_view, 8> kWarningNames{"tensile normal impulse", "energy gained", "plane undefined",
                                                               "negative ratio", "non-physical limit", "not finite",
                                                               "rounding", "undecided"};
inline constexpr std::array<std::string_view, 4> kRegimeNames{"full", "sliding", "capped", "as-given"};

struct MonteCarloOptions {
  PrecisionChoice precision = floating_precision<double>();  // not exact
  Engine engine = Engine::generated;
  unsigned jobs = 0;                       // threads; 0: every core
  std::vector<StrategySpec> strategies;    // replace the case's, when not empty
  bool keep_samples = false;               // keep every sample's inputs and outputs (samples_csv)
  // Called on the calling thread about ten times a second with the samples done, and once at the end.
  std::function<void(std::uint64_t done)> progress;
};

struct OutputSummary {
  const OutputPath* output;
  std::uint64_t undefined = 0;  // solved samples whose document has null here (a PDOF of no ΔV)
  uncertainty::Summary summary;
};

struct Rejections {
  std::string reason;        // "not approaching", "no solution", "invalid $.vehicles[0].mass"
  std::uint64_t count = 0;
  std::uint64_t first = 0;   // the first sample (0-based) rejected so
  std::string message;       // and its one-line problem, as `solve` prints it
};

// The first-order propagation beside the samples: each output's value at the inputs' means, and its
// standard deviation from the derivatives there (sensitivity.hpp) and the inputs' covariance
// (moments.hpp; a pair's correlation taken as its normal-score rho, exact for normal inputs).
struct Linearized {
  std::string note;              // why none was made; empty when made
  std::string regime;            // the strategy's regime at the means
  std::vector<double> mean, sd;  // per output of monte_carlo_outputs(); NaN where the result has none
  // Outputs whose Monte Carlo mean or sd the linearization misses by more than 10 % of the sd plus 4
  // standard errors: non-linearity, or a regime switch, within the input ranges.
  std::vector<std::string> differs;
  bool regime_switch = false;  // the samples took another regime than the means' in some sample
};

struct StrategySummary {
  StrategySpec strategy;  // as the case (or the options) give it: its echo is the document's
  std::uint64_t solved = 0;
  std::vector<Rejections> rejected;  // by reason, in the order of the reasons' text
  std::array<std::uint64_t, kRegimeNames.size()> regimes{};
  std::array<std::uint64_t, kWarningNames.size()> warnings{};  // solved samples with that warning
  std::vector<OutputSummary> outputs;  // in the order of monte_carlo_outputs(), those ever written
  Linearized linear;
};

struct MonteCarloRun {
  std::uint64_t samples = 0, seed = 0;
  std::string precision;
  Units units = Units::SI;          // the case's: every output is in them
  std::vector<std::string> inputs;  // the uncertain inputs' paths, as written
  // Whether each sample was written straight into the read case (every input a number the reader
  // checks on its own, by a range the distribution stays within), rather than read again from text.
  bool direct = false;
  std::vector<StrategySummary> results;
  // With keep_samples: sample i's inputs at inputs_of[i * inputs.size()]; output c of result k at
  // outputs_of[(k * monte_carlo_outputs().size() + c) * samples + i] (NaN where the sample was rejected
  // or the document has null); its regime (kRegimeNames, or -1: not solved) and its rejection (0: none,
  // r + 1: reasons[r]).
  std::vector<double> inputs_of;
  std::vector<double> outputs_of;
  std::vector<std::vector<std::int8_t>> regime_of;
  std::vector<std::vector<std::uint16_t>> reason_of;
  std::vector<std::string> reasons;
};

// The memory a run may take: every output of every sample is kept for the percentiles
// (docs/limits-and-exit-status.md, "Input limits"). A run is sized before its first sample by run_bytes_per_sample.
inline constexpr std::uint64_t kMaxRunBytes = std::uint64_t{2} << 30;
// The threads that summarize the outputs, at most (each holds two columns of the samples' values),
// so that the memory a run takes does not grow with --jobs.
inline constexpr unsigned kSummaryThreads = 4;
std::uint64_t run_bytes_per_sample(std::size_t results, std::size_t inputs, bool keep_samples);

// Throws CaseError: for the uncertainty file's problems at its JSON path ("$.inputs[2].path: ...",
// "$.inputs[0].distribution: ..."), for the case's at the case's, for a run that would take more
// than kMaxRunBytes at "$.samples", and for a strategy that solved no sample at "$" (its commonest
// reason named).
MonteCarloRun montecarlo(const std::string& case_text, const UncertaintySpec& u, const MonteCarloOptions& o);

// The contract's JSON document (many-cases.md), and the text report.
std::string montecarlo_json(const MonteCarloRun& run);
std::string montecarlo_text(const MonteCarloRun& run);

// Every sample as CSV (a run with keep_samples): a header, then one row per sample in sample order:
// `sample`, each input, then for each result `results[k].regime`, `results[k].rejected` and its
// outputs. `write` takes the text in pieces.
void samples_csv(const MonteCarloRun& run, const std::function<void(std::string_view)>& write);

}  // namespace impact3d::studies
