// What every strategy shares: the schema of its parameters, its regime decision, and what an engine
// returns for one. The strategies themselves, one file each, are listed in strategies/list.hpp.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "impact3d/mechanics/stronge/history.hpp"
#include "impact3d/scalar/types.hpp"

namespace impact3d {

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

// A strategy's parameters as a case names them; the reader, the echo, --strategy and the sweeps read them.
enum class ParameterType {
  non_negative,       // a number >= 0
  ratio_or_critical,  // a number of either sign, or "critical" (stored as an empty number)
  choice,             // one of `choices`; absent means the first
};

struct Parameter {
  std::string_view key;
  ParameterType type;
  std::span<const std::string_view> choices{};  // the first is the default
};

// A value verification draws for a parameter (verify.cpp): uniform in [lo, hi], or "critical", or the
// choice named; a choice left unnamed is drawn uniformly among the parameter's choices.
struct ParameterDraw {
  double lo = 0, hi = 0;
  bool critical = false;
  std::string_view choice{};
};

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
  // An integrated impulse's error bound relative to |P_C| (strategies/stronge.hpp), which adds to the
  // rounding bound; its course, for a report.
  std::optional<Scalar> integration_error;
  std::optional<stronge::History<Scalar>> history;
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

// How a strategy decides its regime from the inputs, where it does: the decision's name (decisions.hpp),
// the limit of the solution it compares its ratio `mu` against, and the regime on either side (limit <=
// mu: when_at_most). Read by the sensitivities (the margin limit - mu), the reconstruction (the branch
// fitted) and certified rendering (an exact tie).
template <typename Scalar>
struct RegimeDecision {
  const char* decision;
  const char* margin;  // "gir - mu"
  std::optional<Scalar> ImpulseSolution<Scalar>::*limit;
  Scalar mu;
  Regime when_at_most, otherwise;
};

// A strategy whose constraints admit no unique impulse names the constraint system that was singular;
// it returns this rather than throwing, so that an ordinary outcome costs no exception on the lean path.
struct Singular {
  const char* what = nullptr;  // empty when the strategy solved
  bool own_words = false;      // `what` is the whole reason, not a constraint system's name
  explicit operator bool() const { return what != nullptr; }
};

}  // namespace impact3d
