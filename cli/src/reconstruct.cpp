#include "reconstruct.hpp"

#include <cstdio>

#include "impact3d/io/read_case.hpp"
#include "impact3d/io/read_evidence.hpp"
#include "impact3d/io/reconstruct.hpp"
#include "impact3d/io/strategy_option.hpp"
#include "reconstruct_plot.hpp"
#include "user_error.hpp"

namespace impact3d::cli {

int reconstruct(const ReconstructCliOptions& o) {
  io::ReconstructOptions ro;
  ro.engine = o.engine;
  if (!o.plot_dir.empty()) require_gnuplot();
  if (!o.strategy.empty()) ro.strategy = io::read_strategy_option(o.strategy, 0);
  // The case on its own first, so that its problems name it; then the evidence file's.
  std::string case_text;
  try {
    case_text = io::read_text_file(o.case_path);
    (void)io::read_case(case_text);
  } catch (const io::CaseError& e) {
    throw in_file(o.case_path, e);
  }
  io::EvidenceSpec evidence;
  try {
    evidence = io::read_evidence(io::read_text_file(o.evidence_path));
  } catch (const io::CaseError& e) {
    throw in_file(o.evidence_path, e);
  }
  io::Reconstruction r;
  try {
    r = io::reconstruct(case_text, evidence, ro);
    if (!o.plot_dir.empty()) (void)reconstruct_figures({case_text, evidence, ro, r}, OutputDir(o.plot_dir), o.png);
  } catch (const io::CaseError& e) {
    const bool evidence_field = e.path.rfind("$.unknowns", 0) == 0 || e.path.rfind("$.evidence", 0) == 0;
    throw in_file(evidence_field ? o.evidence_path : o.case_path, e);
  }
  const std::string out = o.format == "json" ? io::reconstruction_json(r) : io::reconstruction_text(r);
  std::fwrite(out.data(), 1, out.size(), stdout);
  return 0;
}

}  // namespace impact3d::cli
