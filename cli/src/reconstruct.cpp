#include "reconstruct.hpp"

#include <cstdio>

#include "impact3d/case_format/read_case.hpp"
#include "impact3d/case_format/read_evidence.hpp"
#include "impact3d/studies/reconstruct.hpp"
#include "impact3d/case_format/strategy_option.hpp"
#include "impact3d/cli/reconstruct_plot.hpp"
#include "impact3d/cli/user_error.hpp"

namespace impact3d::cli {

int reconstruct(const ReconstructCliOptions& o) {
  studies::ReconstructOptions ro;
  ro.engine = o.engine;
  if (!o.plot_dir.empty()) require_gnuplot();
  if (!o.strategy.empty()) ro.strategy = case_format::read_strategy_option(o.strategy, 0);
  // The case on its own first, so that its problems name it; then the evidence file's.
  std::string case_text;
  try {
    case_text = case_format::read_text_file(o.case_path);
    (void)case_format::read_case(case_text);
  } catch (const case_format::CaseError& e) {
    throw in_file(o.case_path, e);
  }
  case_format::EvidenceSpec evidence;
  try {
    evidence = case_format::read_evidence(case_format::read_text_file(o.evidence_path));
  } catch (const case_format::CaseError& e) {
    throw in_file(o.evidence_path, e);
  }
  studies::Reconstruction r;
  try {
    r = studies::reconstruct(case_text, evidence, ro);
    if (!o.plot_dir.empty()) (void)reconstruct_figures({case_text, evidence, ro, r}, OutputDir(o.plot_dir), o.png);
  } catch (const case_format::CaseError& e) {
    const bool evidence_field = e.path.rfind("$.unknowns", 0) == 0 || e.path.rfind("$.evidence", 0) == 0;
    throw in_file(evidence_field ? o.evidence_path : o.case_path, e);
  }
  const std::string out = o.format == "json" ? studies::reconstruction_json(r) : studies::reconstruction_text(r);
  std::fwrite(out.data(), 1, out.size(), stdout);
  return 0;
}

}  // namespace impact3d::cli
