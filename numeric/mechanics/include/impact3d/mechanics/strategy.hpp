// The constraint strategies of the paper, as specified by the user, and what an engine returns for one.
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "impact3d/scalar/types.hpp"

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
  momentum_residual,       // the post-impact states miss a momentum balance by more than its rounding bound
};

struct Warning {
  WarningCode code;
  std::string text;
};

// The warnings of a result as a set of codes: what the lean path (lean.hpp) reports, without text.
using WarningSet = std::uint16_t;

constexpr WarningSet warning_bit(WarningCode c) { return static_cast<WarningSet>(1u << static_cast<unsigned>(c)); }

constexpr bool has_warning(WarningSet set, WarningCode c) { return (set & warning_bit(c)) != 0; }

// A strategy whose constraints admit no impulse (a singular constraint system). `strategy` is the index
// of the strategy in the analysis that failed, when one did.
struct SolveError : std::runtime_error {
  using std::runtime_error::runtime_error;
  std::optional<std::size_t> strategy;
};

// What an engine determines: the impulse and the ratios and limits that decided it.
// What the rows a strategy solved for impose on the post-impact relative velocity V_rf (contact axes n,
// t, z), exactly, whatever the rounding: for every strategy V_rnf = -eps V_rni (the restitution row);
// `full`: V_rf = -eps V_ri along t and z too (the Full Impact, eqs 10-12); `t_zero`, `z_zero`: V_rf = 0
// along that axis (Brach's critical ratio, eqs 25-27; Wach capped at its CIR on the fallback t axis,
// eq 19); `along_plane_zero`: V_rf . u = 0 along the solution plane's axis u, the initial sliding's
// direction (Wach capped at its CIR, eqs 19, 21). constraint_rows.hpp answers from them.
struct ConstraintRows {
  bool full = false, t_zero = false, z_zero = false, along_plane_zero = false;
  const char* zero_rows = "";  // the rows behind t_zero, z_zero and along_plane_zero, as a result names them
};

template <typename Scalar>
struct ImpulseSolution {
  Vec3<Scalar> P_C;  // impulse on vehicle 1, contact axes (n, t, z)
  ConstraintRows rows;  // what the constraints solved for impose on V_rf, exactly
  Regime regime = Regime::as_given;
  std::optional<Scalar> mu, mu_t, mu_z;                           // ratios actually used
  std::optional<Scalar> gir, cir, mu_t_critical, mu_z_critical;  // limits compared against
  std::optional<PlaneAxes<Scalar>> plane;  // the solution plane used: phi_FI (eq 15) or Wach's phi (eq 21)
  std::optional<Scalar> plane_angle_deg;    // its angle from t towards z
  WarningSet codes = 0;                     // the codes of `warnings`
  std::vector<Warning> warnings;            // with their text, for a report
  // What only a report prints: the warnings' text and the plane's angle. The lean path solves with it
  // off, allocates nothing and takes no arctangent; make_text is then never called.
  bool for_report = true;

  template <typename MakeText>
  void warn(WarningCode code, MakeText&& make_text) {
    codes |= warning_bit(code);
    if (for_report) warnings.push_back({code, std::string(make_text())});
  }
};

// A strategy whose constraints admit no unique impulse names the constraint system that was singular;
// it returns this rather than throwing, so that an ordinary outcome costs no exception on the lean path.
struct Singular {
  const char* what = nullptr;  // empty when the strategy solved
  explicit operator bool() const { return what != nullptr; }
};

}  // namespace impact3d
