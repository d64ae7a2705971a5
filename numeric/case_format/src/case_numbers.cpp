// The numeric inputs of a read case by their paths (case_numbers.hpp).
#include "impact3d/case_format/case_numbers.hpp"

#include <fmt/format.h>

#include "impact3d/case_format/json_path.hpp"

namespace impact3d::case_format {

std::vector<std::pair<std::string, Number*>> single_numbers(CaseSpec& spec) {
  std::vector<std::pair<std::string, Number*>> out;
  for (int v = 0; v < 2; ++v) {
    VehicleSpec& veh = spec.vehicles[static_cast<std::size_t>(v)];
    const std::string at = fmt::format("$.vehicles[{}].", v);
    out.emplace_back(at + "mass", &veh.mass);
    out.emplace_back(at + "orientation_deg.yaw", &veh.yaw);
    out.emplace_back(at + "orientation_deg.pitch", &veh.pitch);
    out.emplace_back(at + "orientation_deg.roll", &veh.roll);
    for (int k = 0; k < 3; ++k) {
      out.emplace_back(fmt::format("{}velocity[{}]", at, k), &veh.velocity[static_cast<std::size_t>(k)]);
      out.emplace_back(fmt::format("{}angular_velocity[{}]", at, k), &veh.angular_velocity[static_cast<std::size_t>(k)]);
      out.emplace_back(fmt::format("{}impulse_center[{}]", at, k), &veh.impulse_center[static_cast<std::size_t>(k)]);
    }
  }
  if (!spec.contact.by_vectors) {
    out.emplace_back("$.contact.normal_yaw_deg", &spec.contact.normal_yaw);
    out.emplace_back("$.contact.normal_pitch_deg", &spec.contact.normal_pitch);
    out.emplace_back("$.contact.tangent_roll_deg", &spec.contact.tangent_roll);
  }
  out.emplace_back("$.restitution", &spec.restitution);
  for (auto& st : spec.strategies)
    for (auto& [key, number] : st.numbers)
      if (number) out.emplace_back(st.path + "." + key, &*number);
  for (auto& [path, number] : out) path = path_text(parse_json_path(path, "single_numbers"));
  return out;
}

CaseInputs case_inputs(CaseSpec& spec) {
  CaseInputs out;
  // A strategy given by an option is named as the option's messages name it ("--strategy[0].mu").
  auto add = [&](const std::string& path, std::vector<Number*> numbers) {
    out.inputs.push_back({path.rfind('$', 0) == 0 ? path_text(parse_json_path(path, "case_inputs")) : path, std::move(numbers)});
  };
  auto vec = [&](const std::string& at, Vector3& v) {
    for (std::size_t k = 0; k < 3; ++k) add(fmt::format("{}[{}]", at, k), {&v[k]});
  };
  for (std::size_t v = 0; v < 2; ++v) {
    VehicleSpec& veh = spec.vehicles[v];
    const std::string at = fmt::format("$.vehicles[{}].", v);
    add(at + "mass", {&veh.mass});
    if (veh.inertia_principal) {
      const char* keys[3] = {"Ixx", "Iyy", "Izz"};
      for (std::size_t i = 0; i < 3; ++i) add(fmt::format("{}inertia.{}", at, keys[i]), {&veh.inertia[i][i]});
    } else {
      for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = i; j < 3; ++j)
          add(fmt::format("{}inertia[{}][{}]", at, i, j),
              i == j ? std::vector<Number*>{&veh.inertia[i][i]} : std::vector<Number*>{&veh.inertia[i][j], &veh.inertia[j][i]});
    }
    if (veh.orientation_matrix) {
      out.fixed.emplace_back(veh.orientation_path, "the entries of a rotation matrix cannot move one at a time and stay a rotation");
    } else {
      add(at + "orientation_deg.yaw", {&veh.yaw});
      add(at + "orientation_deg.pitch", {&veh.pitch});
      add(at + "orientation_deg.roll", {&veh.roll});
    }
    vec(at + "velocity", veh.velocity);
    vec(at + "angular_velocity", veh.angular_velocity);
    vec(at + "impulse_center", veh.impulse_center);
  }
  if (spec.contact.by_vectors) {
    vec("$.contact.normal", spec.contact.normal);
    vec("$.contact.tangent", spec.contact.tangent);
  } else {
    add("$.contact.normal_yaw_deg", {&spec.contact.normal_yaw});
    add("$.contact.normal_pitch_deg", {&spec.contact.normal_pitch});
    add("$.contact.tangent_roll_deg", {&spec.contact.tangent_roll});
  }
  add("$.restitution", {&spec.restitution});
  for (auto& st : spec.strategies)
    for (auto& [key, number] : st.numbers)
      if (number) add(st.path + "." + key, {&*number});
  return out;
}

}  // namespace impact3d::case_format
