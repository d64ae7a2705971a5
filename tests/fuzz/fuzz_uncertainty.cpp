// libFuzzer harness: any bytes as an uncertainty file, read and, when valid, its first samples drawn
// and a three-sample Monte Carlo run on the Figure 8 case; the reader and the runner must reject with
// a CaseError or finish, never crash or hang.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "figure8_case.hpp"
#include "impact3d/io/case_spec.hpp"
#include "impact3d/io/montecarlo.hpp"
#include "impact3d/io/read_uncertainty.hpp"


extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace impact3d;
  try {
    const io::UncertaintySpec spec = io::read_uncertainty(std::string(reinterpret_cast<const char*>(data), size));
    const uncertainty::Sampler sampler = io::make_sampler(spec);
    std::vector<double> values(sampler.size());
    for (std::uint64_t i = 0; i < 4; ++i) sampler.draw(i, values.data());
    io::UncertaintySpec few = spec;
    few.samples = 3;
    io::MonteCarloOptions o;
    o.jobs = 1;
    o.keep_samples = true;
    const io::MonteCarloRun run = io::montecarlo(fuzz::kFigure8, few, o);
    (void)io::montecarlo_json(run);
    (void)io::montecarlo_text(run);
    io::samples_csv(run, [](std::string_view) {});
  } catch (const io::CaseError&) {
  }
  return 0;
}
