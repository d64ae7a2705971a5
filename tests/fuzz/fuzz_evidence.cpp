// libFuzzer harness: any bytes as an evidence file, read and, when valid, reconstructed on the Figure 8
// case with its sliding pc-crash strategy; the reader and the fit must reject with a CaseError or
// finish (the minimizer's evaluations are bounded), never crash or hang.
#include <cstddef>
#include <cstdint>
#include <string>

#include "figure8_case.hpp"
#include "impact3d/io/read_case.hpp"
#include "impact3d/io/read_evidence.hpp"
#include "impact3d/io/reconstruct.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace impact3d;
  try {
    const io::EvidenceSpec spec = io::read_evidence(std::string(reinterpret_cast<const char*>(data), size));
    io::ReconstructOptions o;
    o.strategy = io::read_case(fuzz::kFigure8).strategies[1];
    const io::Reconstruction r = io::reconstruct(fuzz::kFigure8, spec, o);
    (void)io::reconstruction_json(r);
    (void)io::reconstruction_text(r);
  } catch (const io::CaseError&) {
  }
  return 0;
}
