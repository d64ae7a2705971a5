// The numbers of a result (the contract's result document) that the studies read: Monte Carlo summarizes
// them, evidence names them, the sensitivities differentiate them.
#pragma once

#include <string>
#include <vector>

#include "impact3d/case_format/json_path.hpp"

namespace impact3d::case_format {

// An output of each result: its path inside one result ("vehicles[0].delta_v_magnitude"), and whether
// it is an angle in degrees, wrapping at +-180 or, `from_zero`, at 0 and 360.
struct OutputPath {
  std::string text;
  JsonPath path;
  bool angle = false, from_zero = false;
};

// Every number of a result that a Monte Carlo run summarizes: the impulse, the relative velocity, the
// ratios and limits used, sliding and swerve, each vehicle's post-impact velocities, ΔV and PDOF, the
// energy, and an integrated impulse's swerve, final direction and normal work. An output a strategy
// does not write (brach has no "gir", only stronge a "swerve_deg") is left out of its summary.
const std::vector<OutputPath>& monte_carlo_outputs();

}  // namespace impact3d::case_format
