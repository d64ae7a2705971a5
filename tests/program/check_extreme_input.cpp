// The CLI on seeded random extreme but valid collisions: text and JSON take the same course, and neither
// prints a NaN or an infinity without a warning that says so.
#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "cli_process.hpp"

namespace check_extreme_input {

namespace fs = std::filesystem;
using namespace impact3d::test;

// Extreme but valid collisions (masses, inertias, lever arms and speeds over many decades): text and
// JSON take the same course, and neither prints a NaN or an infinity without a warning that says so.
TEST_CASE("extreme cases: no NaN or infinity without a warning, text and JSON agree", "[bad-input]") {
  std::mt19937_64 g(8);
  std::uniform_real_distribution<double> u(0, 1);
  auto decades = [&](double lo, double hi) { return std::pow(10.0, lo + (hi - lo) * u(g)); };
  auto signed_decades = [&](double lo, double hi) {
    const double sign = u(g) < 0.5 ? -1 : 1;
    return sign * decades(lo, hi);
  };
  const fs::path dir = fresh_directory("impact3d-extreme");
  int solved = 0, rejected = 0;
  for (int i = 0; i < 60; ++i) {
    std::string vehicles;
    for (int k = 0; k < 2; ++k) {
      // Each number in a statement of its own, the last first (the order of a call's arguments is
      // unspecified; this is the order GCC gave them when they were drawn inside the call).
      const double r_z = signed_decades(-6, 2), r_y = signed_decades(-6, 5), r_x = signed_decades(-6, 5);
      const double w_z = signed_decades(-6, 3), v_y = signed_decades(-6, 6), v_x = signed_decades(-6, 6);
      const double pitch = 178 * u(g) - 89, yaw = 360 * u(g) - 180;
      const double izz = decades(-6, 9), iyy = decades(-6, 9), ixx = decades(-6, 9), mass = decades(-6, 11);
      vehicles += fmt::format(R"({}{{"mass": {:.6g}, "inertia": {{"Ixx": {:.6g}, "Iyy": {:.6g}, "Izz": {:.6g}}},
          "orientation_deg": {{"yaw": {:.6g}, "pitch": {:.6g}}}, "velocity": [{:.6g}, {:.6g}, 0],
          "angular_velocity": [0, 0, {:.6g}], "impulse_center": [{:.6g}, {:.6g}, {:.6g}]}})",
                              k ? "," : "", mass, ixx, iyy, izz, yaw, pitch, v_x, v_y, w_z, r_x, r_y, r_z);
    }
    const double wach_mu = 2 * u(g), pc_crash_mu = 2 * u(g), restitution = u(g);
    const double normal_pitch = 178 * u(g) - 89, normal_yaw = 360 * u(g) - 180;
    std::ofstream(dir / "case.json") << fmt::format(
        R"({{"vehicles": [{}], "contact": {{"normal_yaw_deg": {:.6g}, "normal_pitch_deg": {:.6g}}}, "restitution": {:.6g},
            "strategy": [{{"name": "pc-crash", "mu": {:.6g}}}, {{"name": "wach", "mu": {:.6g}, "limit": "gir"}},
                         {{"name": "brach", "mu_t": "critical", "mu_z": "critical"}}]}})",
        vehicles, normal_yaw, normal_pitch, restitution, pc_crash_mu, wach_mu);
    const Run text = run_argv({"solve", "case.json"}, dir.string());
    const Run json = run_argv({"solve", "case.json", "--format", "json"}, dir.string());
    INFO(slurp(dir / "case.json"));
    REQUIRE(text.status == json.status);
    CHECK(text.err == json.err);
    if (text.status != 0) {
      CHECK(text.status == 1);
      ++rejected;
      continue;
    }
    ++solved;
    const bool warned = text.out.find("not finite:") != std::string::npos || text.out.find("rounding:") != std::string::npos;
    for (const char* bad : {"nan", "inf"}) CHECK((text.out.find(bad) == std::string::npos || warned));
    const auto doc = nlohmann::json::parse(json.out);  // valid JSON: a non-finite number is null
    std::size_t json_warnings = 0;
    for (const auto& r : doc["results"]) json_warnings += r["warnings"].size();
    std::size_t text_warnings = 0;
    for (std::size_t p = 0; (p = text.out.find("\n  WARNING: ", p)) != std::string::npos; ++p) ++text_warnings;
    CHECK(json_warnings == text_warnings);
  }
  fs::remove_all(dir);
  CHECK(solved + rejected == 60);
  // Rejected (exit 1, one line, the same for text and JSON): draws that do not approach, that the reader
  // refuses or that have no solution, 29 of these 60. The solved ones are the ones checked for NaN and warnings: at
  // least 20.
  CHECK(solved >= 20);
}

}  // namespace check_extreme_input
