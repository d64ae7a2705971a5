// libFuzzer harness: any bytes as an evidence file, read and, when valid, reconstructed on the Figure 8
// case with its sliding pc-crash strategy; the reader and the fit must reject with a CaseError or
// finish (the minimizer's evaluations are bounded), never crash or hang.
#include <cstddef>
#include <cstdint>
#include <string>

#include "figure8_case.hpp"
#include "impact3d/case_format/read_case.hpp"
#include "impact3d/case_format/read_evidence.hpp"
#include "impact3d/studies/reconstruct.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace impact3d;
  try {
    const case_format::EvidenceSpec spec = case_format::read_evidence(std::string(reinterpret_cast<const char*>(data), size));
    studies::ReconstructOptions o;
    o.strategy = case_format::read_case(fuzz::kFigure8).strategies[1];
    const studies::Reconstruction r = studies::reconstruct(fuzz::kFigure8, spec, o);
    (void)studies::reconstruction_json(r);
    (void)studies::reconstruction_text(r);
  } catch (const case_format::CaseError&) {
  }
  return 0;
}
