// The person-readable report: each quantity with the paper equation it comes from, strategies side by side.
#pragma once

#include <string>
#include <vector>

#include <fmt/format.h>

#include "impact3d/io/escape.hpp"
#include "impact3d/io/present.hpp"
#include "impact3d/io/strategy_kinds.hpp"
#include "impact3d/numeric/analysis.hpp"

namespace impact3d::io {


// Rows of a label and one cell per column, printed aligned.
class Table {
 public:
  void row(const std::string& label, std::vector<std::string> cells) { rows_.push_back({label, std::move(cells)}); }
  void heading(const std::string& text) { rows_.push_back({text, {}, true}); }
  std::string str() const {
    std::size_t label_w = 0, cell_w = 0;
    for (const auto& r : rows_) {
      if (r.heading) continue;
      label_w = std::max(label_w, r.label.size());
      for (const auto& c : r.cells) cell_w = std::max(cell_w, c.size());
    }
    std::string out;
    for (const auto& r : rows_) {
      if (r.heading) {
        out += "\n" + r.label + "\n";
        continue;
      }
      std::string line = fmt::format("  {:<{}}", r.label, label_w);
      for (const auto& c : r.cells) line += fmt::format("  {:>{}}", c, cell_w);
      while (!line.empty() && line.back() == ' ') line.pop_back();
      out += line + "\n";
    }
    return out;
  }

 private:
  struct Row {
    std::string label;
    std::vector<std::string> cells;
    bool heading = false;
  };
  std::vector<Row> rows_;
};

template <typename Scalar>
std::string report_text(const CaseSpec& c, const Analysis<Scalar>& a, const std::string& precision, int digits) {
  using io::unit_label;
  const Present<Scalar> p(c.units, digits);
  const auto& f = p.f;
  const auto U = [&](const char* q) { return std::string(" [") + unit_label(c.units, q) + "]"; };
  const char* axis[3] = {"n", "t", "z"};
  // Names and descriptions are the case author's text: escaped, so that no control character reaches a
  // terminal.
  std::string out = fmt::format("impact3d: {} (units {}, precision {}, {} engine)\n",
                                c.name.empty() ? "unnamed case" : io::printable(c.name), units_name(c.units), precision,
                                engine_name(a.engine));
  if (!c.description.empty()) out += io::printable(c.description) + "\n";

  Table cs;
  cs.heading("Case (eqs 4-9; impulse space as in Figure 2)");
  cs.row("m' = m1 m2 / (m1 + m2) (eq 9)" + U("mass"), {p.num(a.m_prime, f.mass)});
  for (int k = 0; k < 3; ++k)
    cs.row(fmt::format("K row {} (a{}, b{}, c{}) (eq 9)", k + 1, k + 1, k + 1, k + 1),
           p.vec(a.K.row(k).transpose(), Scalar(1)));
  cs.row("det K, condition number of K", {p.num(Scalar(a.K.determinant())), p.num(a.kappa)});
  for (int i = 0; i < 2; ++i)
    for (int k = 0; k < 3; ++k)
      cs.row(fmt::format("T{} row {} (vehicle -> contact, eq 5)", i + 1, axis[k]), p.vec(a.T[i].row(k).transpose(), Scalar(1)));
  cs.row("V_rel before (n, t, z) (eq 6)" + U("velocity"), p.vec(a.V_ri, f.velocity));
  cs.row("max-energy-loss impulse (eqs 10-12, eps = 0)" + U("impulse"), p.vec(a.space.P_max_loss, f.impulse));
  cs.row("Critical Impulse Line direction (n, t, z)", p.vec(a.space.cil_direction, Scalar(1)));
  const char* plane[3] = {"max-compression plane normal", "t no-sliding plane normal", "z no-sliding plane normal"};
  for (int k = 0; k < 3; ++k) cs.row(plane[k], p.vec(a.space.plane_normal.row(k).transpose(), Scalar(1)));
  out += cs.str();

  Table t;
  t.heading("Results, restitution eps = " + c.restitution.text);
  std::vector<std::string> head;
  for (const auto& s : c.strategies) head.push_back(io::strategy_label(s));
  t.row("strategy", head);
  auto each = [&](const std::string& label, auto cell) {
    std::vector<std::string> cells;
    for (const auto& s : a.solutions) cells.push_back(cell(s));
    t.row(label, cells);
  };
  // A post-impact relative velocity inside the rounding bound is zero: say so instead of printing noise.
  auto vel = [&](const auto& s, const Scalar& v) {
    using std::abs;
    if (abs(v) > s.velocity_roundoff || !is_finite(s.velocity_roundoff)) return p.num(v, f.velocity);
    return "0 (|x| < " + io::scalar_to_text(Scalar(s.velocity_roundoff / f.velocity), 1) + ")";
  };
  auto opt = [&](const std::optional<Scalar>& v) { return v ? p.num(*v) : std::string("-"); };
  each("regime (eq 14 / cap of eqs 19-20)", [&](const auto& s) { return std::string(regime_name(s.impulse.regime)); });
  each("GIR (eqs 14, 20)", [&](const auto& s) { return opt(s.impulse.gir); });
  each("CIR on the solution plane (eq 19)", [&](const auto& s) { return opt(s.impulse.cir); });
  each("mu_t critical (eq 25 / 27)", [&](const auto& s) { return opt(s.impulse.mu_t_critical); });
  each("mu_z critical (eq 26 / 27)", [&](const auto& s) { return opt(s.impulse.mu_z_critical); });
  each("impulse ratio used (eqs 16, 22)", [&](const auto& s) { return opt(s.impulse.mu); });
  each("mu_t, mu_z used (eq 24)", [&](const auto& s) {
    return s.impulse.mu_t ? p.num(*s.impulse.mu_t) + ", " + p.num(*s.impulse.mu_z) : std::string("-");
  });
  each("solution plane angle [deg] (eqs 15, 21)", [&](const auto& s) { return opt(s.impulse.plane_angle_deg); });
  for (int k = 0; k < 3; ++k)
    each(fmt::format("P_{} (eqs 10-12, 18, 24)", axis[k]) + U("impulse"),
         [&](const auto& s) { return p.num(s.impulse.P_C(k), f.impulse); });
  const char* world[3] = {"x", "y", "z"};
  for (int k = 0; k < 3; ++k)
    each(fmt::format("P world {} (on vehicle 1)", world[k]) + U("impulse"), [&](const auto& s) { return p.num(s.P_W(k), f.impulse); });
  for (int k = 0; k < 3; ++k)
    each(fmt::format("V_rel after, {} (eq 9)", axis[k]) + U("velocity"), [&](const auto& s) { return vel(s, s.V_rf(k)); });
  each("effective restitution -V_rnf/V_rni", [&](const auto& s) { return p.num(s.restitution_effective); });
  each("sliding speed before" + U("velocity"), [&](const auto& s) { return p.num(s.sliding_before, f.velocity); });
  each("sliding speed after" + U("velocity"), [&](const auto& s) { return vel(s, s.sliding_after); });
  each("swerve angle [deg]", [&](const auto& s) { return opt(s.swerve_deg); });
  each("swerve speed (across initial sliding)" + U("velocity"),
       [&](const auto& s) { return s.swerve_speed ? vel(s, *s.swerve_speed) : std::string("-"); });
  each("t sliding (Figure 2)", [&](const auto& s) { return std::string(axis_change_name(s.t_change)); });
  each("z sliding (Figure 2)", [&](const auto& s) { return std::string(axis_change_name(s.z_change)); });
  each("impulse-space volume (Figure 2)", [&](const auto& s) { return s.volume; });
  for (int i = 0; i < 2; ++i) {
    const std::string who = fmt::format("vehicle {} ({})", i + 1, io::printable(c.vehicles[i].name));
    for (int k = 0; k < 3; ++k)
      each(fmt::format("{} velocity after {}", who, world[k]) + U("velocity"),
           [&](const auto& s) { return p.num(s.after[i].v_W(k), f.velocity); });
    for (int k = 0; k < 3; ++k)
      each(fmt::format("{} angular velocity after {} (body)", who, world[k]) + U("angular_velocity"),
           [&](const auto& s) { return p.num(s.after[i].w_B(k), f.angular_velocity); });
    each(who + " Delta-V" + U("velocity"), [&](const auto& s) { return p.num(s.change[i].dv, f.velocity); });
    each(who + " PDOF [deg] (clock)", [&](const auto& s) {
      const auto& ch = s.change[i];
      return ch.pdof_deg ? fmt::format("{} ({} o'clock)", p.num(*ch.pdof_deg), *ch.clock) : std::string("-");
    });
  }
  each("kinetic energy before" + U("energy"), [&](const auto& s) { return p.num(s.energy_before, f.energy); });
  each("kinetic energy after" + U("energy"), [&](const auto& s) { return p.num(s.energy_after, f.energy); });
  each("kinetic energy lost" + U("energy"), [&](const auto& s) { return p.num(s.energy_loss, f.energy); });
  each("rounding bound of the impulse, relative", [&](const auto& s) { return io::scalar_to_text(s.rounding_bound, 2); });
  out += t.str();

  std::string warnings;
  for (std::size_t k = 0; k < a.solutions.size(); ++k)
    for (const auto& w : a.solutions[k].warnings)
      warnings += fmt::format("  WARNING [{}]: {}\n", head[k], w.text);
  out += warnings.empty() ? "\nNo warnings.\n" : "\nWarnings\n" + warnings;
  return out;
}

}  // namespace impact3d::io
