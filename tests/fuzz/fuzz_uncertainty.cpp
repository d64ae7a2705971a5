// libFuzzer harness: any bytes as an uncertainty file, read and, when valid, its first samples drawn;
// the reader must reject with a CaseError or the draws must finish, never crash or hang.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "impact3d/io/case_spec.hpp"
#include "impact3d/io/read_uncertainty.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace impact3d;
  try {
    const io::UncertaintySpec spec = io::read_uncertainty(std::string(reinterpret_cast<const char*>(data), size));
    const uncertainty::Sampler sampler = io::make_sampler(spec);
    std::vector<double> values(sampler.size());
    for (std::uint64_t i = 0; i < 4; ++i) sampler.draw(i, values.data());
  } catch (const io::CaseError&) {
  }
  return 0;
}
