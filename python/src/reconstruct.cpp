#include "reconstruct.hpp"

#include "impact3d/case_format/read_evidence.hpp"
#include "impact3d/studies/reconstruct.hpp"
#include "impact3d/case_format/strategy_option.hpp"
#include "solve.hpp"

namespace impact3d::python {

std::string reconstruct_json(const Case& c, const std::string& evidence_text, const std::string& evidence_source,
                             const std::string& strategy, const std::string& engine) {
  studies::ReconstructOptions o;
  o.engine = engine_named(engine);
  if (!strategy.empty()) o.strategy = guarded("", [&] { return case_format::read_strategy_option(strategy, 0); });
  const case_format::EvidenceSpec evidence = guarded(evidence_source, [&] { return case_format::read_evidence(evidence_text); });
  try {
    return studies::reconstruction_json(studies::reconstruct(c.text, evidence, o));
  } catch (const case_format::CaseError& e) {
    // The evidence file's fields name it, the case's the case (as the command line does).
    const bool evidence_field = e.path.rfind("$.unknowns", 0) == 0 || e.path.rfind("$.evidence", 0) == 0;
    return guarded(evidence_field ? evidence_source : c.source, [&]() -> std::string { throw e; });
  }
}

}  // namespace impact3d::python
