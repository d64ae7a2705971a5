// The uncertainty file of `impact3d montecarlo` (many-cases.md, "montecarlo"): which inputs of the case
// vary, by their JSON paths, with which distribution, and how they are correlated. Read as hostile
// input: every problem is one CaseError naming the JSON path of the offending field.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "impact3d/case_format/json_path.hpp"
#include "impact3d/uncertainty/sampler.hpp"

namespace impact3d::case_format {

struct UncertainInput {
  std::string path_text;  // as written ("$.vehicles[1].velocity[1]")
  JsonPath path;
  uncertainty::Distribution distribution;
};

struct UncertaintySpec {
  std::uint64_t samples = 10000;  // when the file does not say
  std::uint64_t seed = 0;
  std::vector<UncertainInput> inputs;
  std::vector<uncertainty::Correlation> correlations;  // a, b: places in `inputs`
};

// Limits (docs/limits-and-exit-status.md): far above what a reconstruction needs, so that no file can ask for
// unbounded work or memory.
inline constexpr std::uint64_t kMaxSamples = 10'000'000;
inline constexpr std::size_t kMaxUncertainInputs = 256;
inline constexpr std::size_t kMaxDiscreteValues = 10'000;

// Throws CaseError. Checks the file on its own (the paths' syntax, the parameters, the correlations'
// positive definiteness); whether each path names a number of the case is the case's to check.
UncertaintySpec read_uncertainty(const std::string& json_text);

// The sampler of a read file (the correlations were checked by read_uncertainty).
uncertainty::Sampler make_sampler(const UncertaintySpec& spec);

}  // namespace impact3d::case_format
