// The reconstruction summary of one strategy as rows of a label and cells, for the text report and the
// HTML page alike, so that both print the same numbers.
#pragma once

#include <string>
#include <vector>

#include <fmt/format.h>

#include "impact3d/case_format/case_spec.hpp"
#include "impact3d/case_format/present.hpp"
#include "impact3d/case_format/scalar_text.hpp"
#include "impact3d/case_format/strategy_kinds.hpp"
#include "impact3d/mechanics/analysis.hpp"

namespace impact3d::case_format {

struct SummaryRow {
  std::string label;
  std::vector<std::string> cells;
  bool per_vehicle = false;  // the cells are vehicle 1's and vehicle 2's
};

struct SummaryRows {
  std::vector<SummaryRow> rows;
  void row(std::string label, std::vector<std::string> cells, bool per_vehicle = false) {
    rows.push_back({std::move(label), std::move(cells), per_vehicle});
  }
};

template <typename Scalar>
struct ReportCells {
  const Present<Scalar>& p;
  // A post-impact relative velocity inside the rounding bound is zero: say so instead of printing noise.
  std::string vel(const Solution<Scalar>& s, const Scalar& v) const {
    using std::abs;
    // An enclosure's own digits say what is known: there is no rounding bound to snap to.
    if constexpr (is_enclosure_v<Scalar>) return p.num(v, p.f.velocity);
    if (abs(v) > s.velocity_roundoff || !is_finite(s.velocity_roundoff)) return p.num(v, p.f.velocity);
    return "0 (|x| < " + case_format::scalar_to_text(Scalar(s.velocity_roundoff / p.f.velocity), 1) + ")";
  }
  std::string opt(const std::optional<Scalar>& v) const { return v ? p.num(*v) : std::string("-"); }
  std::string opt(const std::optional<Scalar>& v, const Scalar& factor) const {
    return v ? p.num(*v, factor) : std::string("-");
  }
};

// An integrated impulse's course (stronge): its events with the normal impulse, V_n and the sliding
// speed there, the swerve and the normal work.
template <typename Scalar, typename Unit>
void history_rows(SummaryRows& t, const stronge::History<Scalar>& h, const Present<Scalar>& p, const Unit& U) {
  using std::sqrt;
  const auto& f = p.f;
  t.row("events: p" + U("impulse") + ", V_n, sliding" + U("velocity"), {});
  for (const auto& e : h.events)
    t.row("  " + std::string(stronge::event_name(e.kind)),
          {p.num(e.p, f.impulse), p.num(e.V_C.x(), f.velocity),
           p.num(Scalar(sqrt(e.V_C.y() * e.V_C.y() + e.V_C.z() * e.V_C.z())), f.velocity)});
  t.row("swerve during the impact [deg]", {p.num(h.swerve_deg)});
  t.row("sliding direction at the end [deg]", {h.final_direction_deg ? p.num(*h.final_direction_deg) : std::string("- (sticks)")});
  if (h.diverging_directions > 1)
    t.row("directions sliding could resume along", {fmt::format("{}, the fastest-growing taken", h.diverging_directions)});
  t.row("normal work: compression, restitution" + U("energy"),
        {p.num(h.work_compression, f.energy), p.num(h.work_restitution, f.energy)});
  t.row("integration: steps, error bound (relative)",
        {std::to_string(h.steps), case_format::scalar_to_text(h.error_bound, 2)});
}

// The summary of one strategy: what a reconstruction is compared against, per vehicle and for the pair;
// its warnings are the solution's own.
template <typename Scalar>
std::vector<SummaryRow> summary_rows(const CaseSpec& c, const Solution<Scalar>& s, const Present<Scalar>& p) {
  SummaryRows t;
  const auto& f = p.f;
  const ReportCells<Scalar> cell{p};
  const auto U = [&](const char* q) { return std::string(" [") + unit_label(c.units, q) + "]"; };
  const auto& imp = s.impulse;
  t.row("regime", {std::string(regime_name(imp.regime))});
  if (imp.mu) t.row("impulse ratio used", {p.num(*imp.mu)});
  if (imp.mu_t) t.row("impulse ratios used, t and z", {p.num(*imp.mu_t), p.num(*imp.mu_z)});
  if (imp.gir) t.row("GIR (eqs 14, 20)", {p.num(*imp.gir)});
  if (imp.cir) t.row("CIR (eq 19)", {p.num(*imp.cir)});
  t.row("impulse on vehicle 1 (n, t, z)" + U("impulse"), p.vec(imp.P_C, f.impulse));
  t.row("", {"vehicle 1", "vehicle 2"}, true);
  auto both = [&](const std::string& name, auto value) { t.row(name, {value(0), value(1)}, true); };
  both("Delta-V" + U("velocity"), [&](int i) { return p.num(s.change[i].dv, f.velocity); });
  both("  longitudinal (+ forward)", [&](int i) { return p.num(s.motion[i].dv_B.x(), f.velocity); });
  both("  lateral (+ left)", [&](int i) { return p.num(s.motion[i].dv_B.y(), f.velocity); });
  both("  vertical (+ up)", [&](int i) { return p.num(s.motion[i].dv_B.z(), f.velocity); });
  both("PDOF [deg] (clock)", [&](int i) {
    const auto& ch = s.change[i];
    return ch.pdof_deg ? fmt::format("{} ({})", p.num(*ch.pdof_deg), *ch.clock) : std::string("-");
  });
  both("speed after" + U("velocity"), [&](int i) { return p.num(s.motion[i].speed_after, f.velocity); });
  both("heading after [deg]", [&](int i) { return cell.opt(s.motion[i].heading_after_deg); });
  both("yaw rate after [deg/s]", [&](int i) { return p.num(Scalar(degrees(s.motion[i].yaw_rate_after))); });
  both("deformation energy" + U("energy"), [&](int i) { return p.num(s.deformation.energy[i], f.energy); });
  both("EES" + U("velocity"), [&](int i) { return cell.opt(s.deformation.ees[i], f.velocity); });
  t.row("sliding before" + U("velocity"), {p.num(s.sliding_before, f.velocity)});
  t.row("sliding after: along, across" + U("velocity"),
        {s.sliding_along ? cell.vel(s, *s.sliding_along) : std::string("-"),
         s.swerve_speed ? cell.vel(s, *s.swerve_speed) : std::string("-")});
  t.row("swerve off the sliding line [deg]", {cell.opt(s.swerve_deg)});
  t.row("sliding reversed", {s.reversed ? (*s.reversed ? "yes" : "no") : "-"});
  if (imp.history) history_rows(t, *imp.history, p, U);
  t.row("energy before, after, lost" + U("energy"),
        {p.num(s.energy_before, f.energy), p.num(s.energy_after, f.energy), p.num(s.energy_loss, f.energy)});
  const auto& m = s.momentum;
  t.row("momentum residual / bound: linear, angular 1, 2",
        {case_format::scalar_to_text(m.linear_residual, 2), case_format::scalar_to_text(m.angular_residual[0], 2),
         case_format::scalar_to_text(m.angular_residual[1], 2)});
  t.row("impulse rounding bound, relative", {case_format::scalar_to_text(s.rounding_bound, 2)});
  return t.rows;
}

}  // namespace impact3d::case_format
