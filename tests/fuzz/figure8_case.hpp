// The Figure 8 case the harnesses run their inputs on.
#pragma once

namespace fuzz {

// examples/fig8_side_impact.json, without its comments.
inline const char* const kFigure8 = R"({"name": "Figure 8", "units": "SI",
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

}  // namespace fuzz
