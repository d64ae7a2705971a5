// The contract's unit systems, and metric-kmh for reports (SI with speeds in km/h and angular velocities
// in deg/s; a result's units, not a case's). Factors are exact rationals (1 lb = 0.45359237 kg,
// 1 ft = 0.3048 m, 1 mph = 0.44704 m/s, 1 km/h = 5/18 m/s, g0 = 9.80665 m/s^2), built in the target type.
#pragma once

#include <optional>
#include <string_view>

#include "impact3d/scalar/types.hpp"

namespace impact3d {

enum class Units { SI, US, metric_kmh };

// Multiply a value in the case's units by these to get SI.
template <typename Scalar>
struct UnitFactors {
  Scalar mass, length, velocity, inertia, angular_velocity, impulse, energy;
};

template <typename Scalar>
UnitFactors<Scalar> unit_factors(Units u) {
  const Scalar one(1);
  if (u == Units::SI) return {one, one, one, one, one, one, one};
  // deg/s: pi / 180 has no exact value (exact results are written in the case's own units).
  Scalar deg_per_s(0);
  if constexpr (!std::numeric_limits<Scalar>::is_exact) deg_per_s = pi<Scalar>() / Scalar(180);
  if (u == Units::metric_kmh) return {one, one, ratio<Scalar>(5, 18), one, deg_per_s, one, one};
  const Scalar lb = ratio<Scalar>(45359237, 100000000);
  const Scalar ft = ratio<Scalar>(3048, 10000);
  const Scalar g0 = ratio<Scalar>(980665, 100000);
  const Scalar lbf = lb * g0;
  UnitFactors<Scalar> f;
  f.mass = lb;                          // pound-mass
  f.length = ft;
  f.velocity = ratio<Scalar>(44704, 100000);
  f.inertia = lbf * ft;                 // lbf ft s^2 = slug ft^2
  f.angular_velocity = deg_per_s;       // exact cases in US units must have no angular velocity
  f.impulse = lbf;                      // lbf s
  f.energy = lbf * ft;                  // ft lbf
  return f;
}

inline const char* units_name(Units u) {
  switch (u) {
    case Units::SI: return "SI";
    case Units::US: return "US";
    case Units::metric_kmh: return "metric-kmh";
  }
  return "?";
}

// The unit system of a name units_name gives; empty for any other text.
inline std::optional<Units> units_named(std::string_view name) {
  for (Units u : {Units::SI, Units::US, Units::metric_kmh})
    if (name == units_name(u)) return u;
  return std::nullopt;
}

}  // namespace impact3d
