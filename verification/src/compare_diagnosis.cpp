#include "compare_diagnosis.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <optional>
#include <string>

#include <fmt/format.h>

namespace impact3d::verification::detail {
namespace {

// Exact definitions (docs/case-format.md, Units). Each is tried both ways.
struct UnitFactor {
  double factor;  // other = reference x factor
  std::string what;
};
const std::vector<UnitFactor>& unit_factors() {
  static const std::vector<UnitFactor> factors = [] {
    const struct {
      double f;
      const char* from;
      const char* to;
    } base[] = {{1 / 0.44704, "m/s", "mph"},
                {3.6, "m/s", "km/h"},
                {1 / 0.44704 / 3.6, "km/h", "mph"},
                {1 / 4.4482216152605, "N s", "lbf s"},
                {1 / 1.3558179483314004, "J (or kg m^2)", "ft lbf (or slug ft^2)"},
                {1 / 0.45359237, "kg", "lb"},
                {1 / 0.3048, "m", "ft"},
                {180 / std::numbers::pi, "rad (or rad/s)", "deg (or deg/s)"}};
    std::vector<UnitFactor> out;
    for (const auto& b : base) {
      out.push_back({b.f, fmt::format("x {:.6g}, {} -> {}", b.f, b.from, b.to)});
      out.push_back({1 / b.f, fmt::format("x {:.6g}, {} -> {}", 1 / b.f, b.to, b.from)});
    }
    return out;
  }();
  return factors;
}

// A diagnosis looks for a pattern, not a pass: another tool's numbers printed to 6 digits are still
// "the reference negated" though they fail a 1e-9 comparison. So each looks within the comparison's
// tolerance or 1e-4 relative, whichever is wider.
constexpr double kDiagnosisRtol = 1e-4;

bool close(double want, double got, double rtol, double atol) {
  return std::fabs(got - want) <= atol + std::max(rtol, kDiagnosisRtol) * std::fabs(want);
}

// The first part of a path: the quantity a failure belongs to (impulse, vehicles, energy, coefficients).
std::string group(const std::string& leaf) { return leaf.substr(0, leaf.find('.')); }

std::string groups(const std::map<std::string, int>& by_group) {
  std::string s;
  for (const auto& [g, n] : by_group) s += fmt::format("{}{} {}", s.empty() ? "" : ", ", g, n);
  return s;
}

// The same path with vehicles 0 and 1 exchanged, or nothing when the path is not a vehicle's.
std::optional<std::string> other_vehicle(const std::string& leaf) {
  if (leaf.rfind("vehicles.0.", 0) == 0) return "vehicles.1." + leaf.substr(11);
  if (leaf.rfind("vehicles.1.", 0) == 0) return "vehicles.0." + leaf.substr(11);
  return std::nullopt;
}

}  // namespace

std::vector<std::string> diagnose(const std::vector<NumericFailure>& failures) {
  std::vector<std::string> out;
  const std::size_t n = failures.size();
  // The failures a cause explains, by quantity; it is named when it explains more than half of them.
  struct Tally {
    std::size_t count = 0;
    std::map<std::string, int> by_group;
  };
  const auto tally = [&](const std::function<bool(const NumericFailure&)>& explained) {
    Tally t;
    for (const auto& f : failures)
      if (explained(f)) {
        ++t.count;
        ++t.by_group[group(f.leaf)];
      }
    return t;
  };
  const auto most = [&](const Tally& t) { return 2 * t.count > n; };

  // A value within atol of zero has no sign and no unit to speak of.
  const auto signed_value = [](const NumericFailure& f) { return std::fabs(f.reference) > f.atol; };
  const auto negated = [&](const NumericFailure& f) { return signed_value(f) && close(-f.reference, f.other, f.rtol, f.atol); };
  const auto other_vehicles_value = [&](const NumericFailure& f) {
    const auto swapped = other_vehicle(f.leaf);
    if (!swapped || !f.result_numbers) return false;
    const auto it = f.result_numbers->find(*swapped);
    return it != f.result_numbers->end() && close(it->second, f.other, f.rtol, f.atol);
  };

  if (const Tally t = tally(negated); most(t))
    out.push_back(fmt::format(
        "diagnosis: {} of {} failing numbers are the reference negated ({}): the other tool may use the opposite sign "
        "convention. Here the normal n points into vehicle 1, P is the impulse on vehicle 1, and the relative velocity "
        "is vehicle 2's minus vehicle 1's at the impulse centre (docs/case-format.md).",
        t.count, n, groups(t.by_group)));

  // Vehicles numbered the other way exchange the vehicles' fields, and negate the impulse on vehicle 1
  // and the relative velocity: both count, once some vehicle field is seen exchanged.
  if (std::any_of(failures.begin(), failures.end(), other_vehicles_value))
    if (const Tally t = tally([&](const NumericFailure& f) { return other_vehicle(f.leaf) ? other_vehicles_value(f) : negated(f); });
        most(t))
      out.push_back(fmt::format(
          "diagnosis: {} of {} failing numbers are what numbering the vehicles the other way gives: the other vehicle's "
          "values, or the impulse and relative velocity negated ({}). Here vehicle 1 is the one the normal points into "
          "(docs/case-format.md).",
          t.count, n, groups(t.by_group)));

  std::map<std::string, int> by_factor;
  if (const Tally t = tally([&](const NumericFailure& f) {
        if (!signed_value(f)) return false;
        for (const auto& u : unit_factors())
          if (close(u.factor * f.reference, f.other, f.rtol, f.atol)) {
            ++by_factor[u.what];
            return true;
          }
        return false;
      });
      most(t)) {
    std::string factors;
    for (const auto& [what, k] : by_factor) factors += fmt::format("{}{}: {}", factors.empty() ? "" : "; ", what, k);
    out.push_back(fmt::format(
        "diagnosis: {} of {} failing numbers differ from the reference by a unit factor ({}; by quantity: {}): the other "
        "tool may write other units. The reference is in its case's units (docs/case-format.md).",
        t.count, n, factors, groups(t.by_group)));
  }
  return out;
}

}  // namespace impact3d::verification::detail
