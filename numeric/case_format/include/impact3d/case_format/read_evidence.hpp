// The evidence file of `impact3d reconstruct` (many-cases.md, "reconstruct"): the unknowns to solve for
// and what is known after the impact, each with its standard deviation. Read as hostile input: every
// problem is one CaseError naming the JSON path of the offending field. Whether a path names a number
// of the case, and whether the case's strategy writes an output, is the reconstruction's to check.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "impact3d/case_format/json_path.hpp"

namespace impact3d::case_format {

struct Unknown {
  // speed: |v| of vehicle `vehicle`, its direction kept; heading (an extension of the contract): the
  // deviation in degrees of vehicle `vehicle`'s velocity from the case's direction, turned about the
  // world z axis; path: a numeric input of the case.
  enum class Kind { speed, heading, path } kind = Kind::path;
  int vehicle = 0;
  JsonPath path;
  std::string path_text;  // as messages spell it ("$.restitution")
  std::optional<double> start;
  std::string label() const;  // "speed[0]", "heading[1]", or the path
};

struct EvidenceItem {
  // output: a number (or vector) of the strategy's result document; speed (an extension of the
  // contract): vehicle `vehicle`'s pre-impact speed as known, from a recorder or a witness mark.
  enum class Kind { output, speed } kind = Kind::output;
  int vehicle = 0;
  std::string output;                 // as messages spell it ("vehicles[0].velocity")
  std::vector<std::size_t> outputs;   // places in monte_carlo_outputs(), one per component
  std::vector<double> value, sd;      // per component
};

struct EvidenceSpec {
  std::vector<Unknown> unknowns;
  std::vector<EvidenceItem> evidence;
  std::size_t components() const;
};

// Limits (docs/limits-and-exit-status.md): a speed and a heading per vehicle and eight more inputs, so that the
// derivatives of a fit take one pass of the dual numbers (autodiff.hpp); evidence far beyond a
// reconstruction's.
inline constexpr std::size_t kMaxPathUnknowns = 8;
inline constexpr std::size_t kMaxEvidence = 256;

// Throws CaseError.
EvidenceSpec read_evidence(const std::string& json_text);

}  // namespace impact3d::case_format
