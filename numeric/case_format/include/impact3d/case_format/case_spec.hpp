// A case file as written (contract: shared spec case-format.md), before any arithmetic. Numbers keep
// their literal text so that every precision converts the same decimal, never a rounded double.
#pragma once

#include <array>
#include <functional>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "impact3d/case_format/limits.hpp"
#include "impact3d/mechanics/strategy.hpp"
#include "impact3d/mechanics/units.hpp"

namespace impact3d::case_format {

// Bad input: `path` is the JSON path of the offending field ("$.vehicles[0].mass").
struct CaseError : std::runtime_error {
  std::string path;
  CaseError(std::string p, const std::string& what) : std::runtime_error(what), path(std::move(p)) {}
  std::string line() const { return path + ": " + what(); }
};

struct Number {
  std::string text;  // the literal as written in the file
  double value;      // the literal correctly rounded to double: the double engine's input (to_scene), validation, messages
};

using Vector3 = std::array<Number, 3>;

// The vehicle's box for the collision diagram (no part of the mechanics), in length units.
struct DimensionsSpec {
  Number length, width;
  std::optional<Number> height, cg_to_front;  // default: none drawn in elevation; length / 2
};

struct VehicleSpec {
  std::string name;
  Number mass;
  std::array<Vector3, 3> inertia;  // full tensor (the diagonal shorthand is expanded, zeros off-diagonal)
  std::string inertia_path;
  bool inertia_principal = false;  // written as {"Ixx", "Iyy", "Izz"}
  Number yaw, pitch, roll;
  // Alternatively the orientation as a rotation matrix R_WB (rows), e.g. rational for exact arithmetic.
  std::optional<std::array<Vector3, 3>> orientation_matrix;
  std::string orientation_path;
  Vector3 velocity, angular_velocity, impulse_center;
  std::optional<DimensionsSpec> dimensions;
};

struct ContactSpec {
  bool by_vectors = false;
  Number normal_yaw, normal_pitch, tangent_roll;
  Vector3 normal, tangent;
  std::string path;
};

// A strategy as written: its row of strategy_kinds.hpp and the values of that row's keys.
struct StrategySpec {
  std::size_t kind = 0;
  std::map<std::string, std::optional<Number>, std::less<>> numbers;  // empty: "critical"
  std::map<std::string, std::string, std::less<>> choices;            // every choice, defaults filled in
  std::string path;

  const std::optional<Number>& number(std::string_view key) const {
    static const std::optional<Number> none;
    const auto it = numbers.find(key);
    return it == numbers.end() ? none : it->second;
  }
  std::string choice(std::string_view key) const {
    const auto it = choices.find(key);
    return it == choices.end() ? std::string() : it->second;
  }
};

// How the energy loss is split between the vehicles for EES (reconstruction.hpp): "share" in the ratio
// of the two values, "stiffness" in inverse ratio of two linear crush stiffnesses (any one unit).
// Absent: in inverse ratio of the masses.
struct EnergySplitSpec {
  std::string rule;  // "share" | "stiffness"
  std::array<Number, 2> values;
  std::string path;
};

struct CaseSpec {
  std::string name;
  std::string description;  // what the case exercises, one line (optional; echoed in the result)
  Units units = Units::SI;
  std::array<VehicleSpec, 2> vehicles;
  ContactSpec contact;
  Number restitution;
  std::optional<EnergySplitSpec> energy_split;
  std::vector<StrategySpec> strategies;
  bool strategy_is_array = false;
};

// A strategy with no solution as bad input at its path in the case ($.strategy[2]), or at "$" when the
// failure belongs to no one strategy.
CaseError no_solution(const CaseSpec& spec, const SolveError& e);

// Parses and validates everything that needs no arithmetic; throws CaseError.
CaseSpec read_case(const std::string& json_text);
// The same from a parsed tree (json_tree.hpp): for variants of one case, parsed once.
struct JsonValue;
CaseSpec read_case_tree(const JsonValue& root);

// The whole file, at most `max_bytes`; CaseError (path = the file) when it cannot be read or is larger.
std::string read_text_file(const std::string& path, std::size_t max_bytes = limits::kCaseFileBytes);

}  // namespace impact3d::case_format
