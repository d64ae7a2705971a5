// The figures of `impact3d reconstruct --plot DIR`: rec_plan, a plan view of each vehicle's CG relative
// to the impulse centre with its reconstructed velocity before and after the impact and the evidence of
// its post-impact velocity (1-sd ellipses); rec_chi2, chi2 over the first two unknowns with the
// confidence contours (joint with two unknowns, conditional on the others with more), when both are
// determined. Every number comes from the fit; no user text reaches
// gnuplot but as quoted data.
#pragma once

#include <string>

#include "impact3d/cli/gnuplot.hpp"
#include "impact3d/case_format/read_evidence.hpp"
#include "impact3d/studies/reconstruct.hpp"

namespace impact3d::cli {

struct ReconstructFigures {
  const std::string& case_text;
  const case_format::EvidenceSpec& evidence;
  const studies::ReconstructOptions& options;
  const studies::Reconstruction& reconstruction;
};

// Returns the images written, one name and line end each.
std::string reconstruct_figures(const ReconstructFigures& f, const OutputDir& dir, bool png);

}  // namespace impact3d::cli
