// libFuzzer harness: any bytes as an uncertainty file, read and, when valid, its first samples drawn
// and a three-sample Monte Carlo run on the Figure 8 case; the reader and the runner must reject with
// a CaseError or finish, never crash or hang.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "impact3d/io/case_spec.hpp"
#include "impact3d/io/montecarlo.hpp"
#include "impact3d/io/read_uncertainty.hpp"

namespace {

// examples/fig8_side_impact.json, without its comments.
const char* const kFigure8 = R"({"name": "Figure 8", "units": "SI",
  "vehicles": [
    {"name": "Malibu", "mass": 1560, "inertia": [[560, 0, -40], [0, 2500, 0], [-40, 0, 2700]],
     "orientation_deg": {"yaw": 0, "pitch": 0, "roll": 0}, "velocity": [11.176, 0, 0], "angular_velocity": [0, 0, 0],
     "impulse_center": [0.35, -0.90, 0.05]},
    {"name": "Suburban", "mass": 2600, "inertia": {"Ixx": 1100, "Iyy": 5600, "Izz": 5900}, "orientation_deg": {"yaw": 90},
     "velocity": [0, 11.176, 0], "impulse_center": [2.60, 0.20, -0.15]}],
  "contact": {"normal_yaw_deg": 90, "normal_pitch_deg": 0, "tangent_roll_deg": 0},
  "restitution": 0.1,
  "strategy": [{"name": "pc-crash", "mu": 1.0}, {"name": "pc-crash", "mu": 0.4}, {"name": "wach", "mu": 0.4, "limit": "cir"},
               {"name": "brach", "mu_t": "critical", "mu_z": "critical"}]})";

}  // namespace

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
    const io::MonteCarloRun run = io::montecarlo(kFigure8, few, o);
    (void)io::montecarlo_json(run);
    (void)io::montecarlo_text(run);
    io::samples_csv(run, [](std::string_view) {});
  } catch (const io::CaseError&) {
  }
  return 0;
}
