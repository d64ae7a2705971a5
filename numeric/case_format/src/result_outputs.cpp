// The numbers of a result the studies read, by their paths.
#include "impact3d/case_format/result_outputs.hpp"

#include <fmt/format.h>

namespace impact3d::case_format {

const std::vector<OutputPath>& monte_carlo_outputs() {
  static const std::vector<OutputPath> outputs = [] {
    std::vector<OutputPath> v;
    auto add = [&](std::string text, bool angle = false, bool from_zero = false) {
      JsonPath path = parse_json_path(text, "monte_carlo_outputs");
      v.push_back({std::move(text), std::move(path), angle, from_zero});
    };
    for (const char* k : {"mu", "mu_t", "mu_z"}) add(fmt::format("impulse_ratio.{}", k));
    for (const char* k : {"gir", "cir", "mu_t_critical", "mu_z_critical"}) add(fmt::format("limits.{}", k));
    add("plane_angle_deg", true);
    for (const char* group : {"impulse.contact", "impulse.world", "relative_velocity.before", "relative_velocity.after"})
      for (int i = 0; i < 3; ++i) add(fmt::format("{}[{}]", group, i));
    add("sliding.before");
    add("sliding.after");
    add("sliding.swerve_angle_deg");  // in [-90, 90]: off the line of the initial sliding, not around a circle
    add("sliding.swerve_speed");
    add("sliding.along");
    add("impulse_space.restitution_effective");
    for (int veh = 0; veh < 2; ++veh) {
      for (const char* group : {"velocity", "angular_velocity", "delta_v"})
        for (int i = 0; i < 3; ++i) add(fmt::format("vehicles[{}].{}[{}]", veh, group, i));
      add(fmt::format("vehicles[{}].delta_v_magnitude", veh));
      add(fmt::format("vehicles[{}].pdof_deg", veh), true, true);  // [0, 360)
      for (int i = 0; i < 3; ++i) add(fmt::format("vehicles[{}].delta_v_vehicle[{}]", veh, i));
      add(fmt::format("vehicles[{}].speed_after", veh));
      add(fmt::format("vehicles[{}].heading_after_deg", veh), true);  // (-180, 180]
      add(fmt::format("vehicles[{}].yaw_rate_after", veh));
      add(fmt::format("vehicles[{}].deformation_energy", veh));
      add(fmt::format("vehicles[{}].ees", veh));
    }
    for (const char* k : {"before", "after", "loss"}) add(fmt::format("energy.{}", k));
    // An integrated impulse's course (stronge only).
    add("swerve_deg");
    add("final_direction_deg", true);  // (-180, 180]
    add("normal_work.compression");
    add("normal_work.restitution");
    return v;
  }();
  return outputs;
}

}  // namespace impact3d::case_format
