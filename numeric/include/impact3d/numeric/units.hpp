// The contract's unit systems. Factors are exact rationals (1 lb = 0.45359237 kg, 1 ft = 0.3048 m,
// 1 mph = 0.44704 m/s, g0 = 9.80665 m/s^2), built in the target type.
#pragma once

#include "impact3d/numeric/types.hpp"

namespace impact3d {

enum class Units { SI, US };

// Multiply a value in the case's units by these to get SI.
template <typename Scalar>
struct UnitFactors {
  Scalar mass, length, velocity, inertia, angular_velocity, impulse, energy;
};

template <typename Scalar>
UnitFactors<Scalar> unit_factors(Units u) {
  const Scalar one(1);
  if (u == Units::SI) return {one, one, one, one, one, one, one};
  const Scalar lb = ratio<Scalar>(45359237, 100000000);
  const Scalar ft = ratio<Scalar>(3048, 10000);
  const Scalar g0 = ratio<Scalar>(980665, 100000);
  const Scalar lbf = lb * g0;
  UnitFactors<Scalar> f;
  f.mass = lb;                          // pound-mass
  f.length = ft;
  f.velocity = ratio<Scalar>(44704, 100000);
  f.inertia = lbf * ft;                 // lbf ft s^2 = slug ft^2
  // deg/s: pi / 180 has no exact value; exact cases in US units must have no angular velocity.
  if constexpr (std::numeric_limits<Scalar>::is_exact) f.angular_velocity = Scalar(0);
  else f.angular_velocity = pi<Scalar>() / Scalar(180);
  f.impulse = lbf;                      // lbf s
  f.energy = lbf * ft;                  // ft lbf
  return f;
}

inline const char* units_name(Units u) { return u == Units::SI ? "SI" : "US"; }

}  // namespace impact3d
