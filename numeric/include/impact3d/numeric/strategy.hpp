// The constraint strategies of the paper, as specified by the user, and what an engine returns for one.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "impact3d/numeric/types.hpp"

namespace impact3d {

// 3D extension of PC-Crash Full/Sliding Impact (eqs 10-20).
template <typename Scalar>
struct PcCrash {
  Scalar mu;
};

enum class WachLimit { cir, gir };

// Tangent aligned with the initial sliding velocity (eqs 21-22), ratio capped at the plane's CIR or GIR.
template <typename Scalar>
struct Wach {
  Scalar mu;
  WachLimit limit = WachLimit::cir;
};

// Independent impulse ratios (eqs 23-27); an empty ratio means "critical".
template <typename Scalar>
struct Brach {
  std::optional<Scalar> mu_t, mu_z;
};

template <typename Scalar>
using Strategy = std::variant<PcCrash<Scalar>, Wach<Scalar>, Brach<Scalar>>;

enum class Regime { full, sliding, capped, as_given };

inline const char* regime_name(Regime r) {
  switch (r) {
    case Regime::full: return "full";
    case Regime::sliding: return "sliding";
    case Regime::capped: return "capped";
    case Regime::as_given: return "as-given";
  }
  return "?";
}

enum class WarningCode {
  tensile_normal_impulse,  // P_n <= 0
  energy_gained,           // loss < 0
  plane_undefined,         // strategy plane has no direction; fallback used
  negative_ratio,          // an impulse ratio used is negative: contact-plane impulse pushes along sliding
  non_physical_limit,      // a critical/generalized ratio has no physical value (denominator <= 0)
  not_finite,              // a result is NaN or infinite at this precision
  rounding,                // the rounding bound exceeds the trusted fraction (rounding.hpp)
  undecided,               // a regime decision lies within the rounding bound of its threshold
};

struct Warning {
  WarningCode code;
  std::string text;
};

// A strategy whose constraints admit no impulse (a singular constraint system). `strategy` is the index
// of the strategy in the analysis that failed, when one did.
struct SolveError : std::runtime_error {
  using std::runtime_error::runtime_error;
  std::optional<std::size_t> strategy;
};

// What an engine determines: the impulse and the ratios and limits that decided it.
template <typename Scalar>
struct ImpulseSolution {
  Vec3<Scalar> P_C;  // impulse on vehicle 1, contact axes (n, t, z)
  Regime regime = Regime::as_given;
  std::optional<Scalar> mu, mu_t, mu_z;                           // ratios actually used
  std::optional<Scalar> gir, cir, mu_t_critical, mu_z_critical;  // limits compared against
  std::optional<PlaneAxes<Scalar>> plane;  // the solution plane used: phi_FI (eq 15) or Wach's phi (eq 21)
  std::optional<Scalar> plane_angle_deg;    // its angle from t towards z
  std::vector<Warning> warnings;
};

}  // namespace impact3d
