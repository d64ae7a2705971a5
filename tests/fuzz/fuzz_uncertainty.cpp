// libFuzzer harness: any bytes as an uncertainty file, read and, when valid, its first samples drawn
// and a three-sample Monte Carlo run on the Figure 8 case; the reader and the runner must reject with
// a CaseError or finish, never crash or hang.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "figure8_case.hpp"
#include "impact3d/case_format/case_spec.hpp"
#include "impact3d/studies/montecarlo.hpp"
#include "impact3d/case_format/read_uncertainty.hpp"


extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace impact3d;
  try {
    const case_format::UncertaintySpec spec = case_format::read_uncertainty(std::string(reinterpret_cast<const char*>(data), size));
    const uncertainty::Sampler sampler = case_format::make_sampler(spec);
    std::vector<double> values(sampler.size());
    for (std::uint64_t i = 0; i < 4; ++i) sampler.draw(i, values.data());
    case_format::UncertaintySpec few = spec;
    few.samples = 3;
    studies::MonteCarloOptions o;
    o.jobs = 1;
    o.keep_samples = true;
    const studies::MonteCarloRun run = studies::montecarlo(fuzz::kFigure8, few, o);
    (void)studies::montecarlo_json(run);
    (void)studies::montecarlo_text(run);
    studies::samples_csv(run, [](std::string_view) {});
  } catch (const case_format::CaseError&) {
  }
  return 0;
}
