// The person-readable report, no wider than 80 columns: the reconstruction summary first, one block per
// strategy (what a reconstruction is compared against), then the detail, each quantity with the paper
// equation it comes from.
#pragma once

#include <string>
#include <vector>

#include <fmt/format.h>

#include "impact3d/case_format/escape.hpp"
#include "impact3d/case_format/report_summary.hpp"
#include "impact3d/case_format/present.hpp"
#include "impact3d/case_format/strategy_kinds.hpp"
#include "impact3d/case_format/text_table.hpp"
#include "impact3d/mechanics/analysis.hpp"

namespace impact3d::case_format {

template <typename Scalar>
std::string report_text(const CaseSpec& c, const Analysis<Scalar>& a, const std::string& precision, int digits) {
  using case_format::unit_label;
  const Present<Scalar> p(c.units, digits);
  const auto& f = p.f;
  const ReportCells<Scalar> cell{p};
  const auto U = [&](const char* q) { return std::string(" [") + unit_label(c.units, q) + "]"; };
  const char* axis[3] = {"n", "t", "z"};
  // Names and descriptions are the case author's text: escaped, so that no control character reaches a
  // terminal.
  std::string out = wrap(fmt::format("impact3d: {} (units {}, precision {}, {} engine)",
                                     c.name.empty() ? "unnamed case" : case_format::printable(c.name), units_name(c.units), precision,
                                     engine_name(a.engine)));
  if (!c.description.empty()) out += wrap(case_format::printable(c.description));
  for (int i = 0; i < 2; ++i) out += wrap(fmt::format("vehicle {}: {}", i + 1, case_format::printable(c.vehicles[i].name)), kTextWidth, "");
  std::vector<std::string> head;
  for (const auto& s : c.strategies) head.push_back(case_format::strategy_label(s));

  const std::string split_rule = c.energy_split ? c.energy_split->rule : "mass";
  const auto& share = a.solutions.empty() ? std::array<Scalar, 2>{} : a.solutions[0].deformation.share;
  Table sum;
  const char* how = split_rule == "share" ? "as given" : split_rule == "stiffness" ? "in inverse ratio of stiffness"
                                                                                   : "in inverse ratio of mass";
  sum.heading(fmt::format("Summary (restitution eps = {}; yaw rates in deg/s; EES from the energy lost, split "
                          "{}: vehicle 1 {}, vehicle 2 {})",
                          c.restitution.text, how, p.num(share[0]), p.num(share[1])));
  for (std::size_t k = 0; k < a.solutions.size(); ++k) {
    sum.heading(head[k]);
    const auto& s = a.solutions[k];
    for (const auto& r : summary_rows(c, s, p)) sum.row(r.label, r.cells);
    if (s.warnings.empty()) sum.row("warnings", {"none"});
    for (const auto& w : s.warnings) sum.note("WARNING: ", w.text);
  }
  out += sum.str();

  Table cs;
  cs.heading("Detail: the case (eqs 4-9; impulse space as in Figure 2)");
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

  for (std::size_t k = 0; k < a.solutions.size(); ++k) {
    const auto& s = a.solutions[k];
    const auto& imp = s.impulse;
    Table t;
    t.heading("Detail: " + head[k]);
    t.row("regime (eq 14 / cap of eqs 19-20)", {std::string(regime_name(imp.regime))});
    t.row("GIR (eqs 14, 20)", {cell.opt(imp.gir)});
    t.row("CIR on the solution plane (eq 19)", {cell.opt(imp.cir)});
    t.row("mu_t critical (eq 25 / 27)", {cell.opt(imp.mu_t_critical)});
    t.row("mu_z critical (eq 26 / 27)", {cell.opt(imp.mu_z_critical)});
    t.row("impulse ratio used (eqs 16, 22)", {cell.opt(imp.mu)});
    t.row("mu_t, mu_z used (eq 24)", imp.mu_t ? std::vector<std::string>{p.num(*imp.mu_t), p.num(*imp.mu_z)}
                                               : std::vector<std::string>{"-"});
    t.row("solution plane angle [deg] (eqs 15, 21)", {cell.opt(imp.plane_angle_deg)});
    t.row("P (n, t, z) (eqs 10-12, 18, 24)" + U("impulse"), p.vec(imp.P_C, f.impulse));
    t.row("P world (x, y, z), on vehicle 1" + U("impulse"), p.vec(s.P_W, f.impulse));
    t.row("V_rel after (n, t, z) (eq 9)" + U("velocity"), {cell.vel(s, s.V_rf.x()), cell.vel(s, s.V_rf.y()), cell.vel(s, s.V_rf.z())});
    t.row("effective restitution -V_rnf/V_rni", {p.num(s.restitution_effective)});
    t.row("sliding speed after" + U("velocity"), {cell.vel(s, s.sliding_after)});
    t.row("t sliding (Figure 2)", {std::string(axis_change_name(s.t_change))});
    t.row("z sliding (Figure 2)", {std::string(axis_change_name(s.z_change))});
    t.row("impulse-space volume (Figure 2)", {s.volume});
    for (int i = 0; i < 2; ++i) {
      t.row(fmt::format("vehicle {} velocity after (x, y, z)", i + 1) + U("velocity"), p.vec(s.after[i].v_W, f.velocity));
      t.row(fmt::format("vehicle {} angular velocity after (body)", i + 1) + U("angular_velocity"),
            p.vec(s.after[i].w_B, f.angular_velocity));
      t.row(fmt::format("vehicle {} Delta-V (x, y, z)", i + 1) + U("velocity"), p.vec(s.change[i].dv_W, f.velocity));
    }
    const Scalar f_angular = f.impulse * f.length;
    const auto& m = s.momentum;
    t.row("linear momentum before (x, y, z)" + U("impulse"), p.vec(m.linear_before_W, f.impulse));
    t.row("linear momentum after (x, y, z)" + U("impulse"), p.vec(m.linear_after_W, f.impulse));
    for (int i = 0; i < 2; ++i) {
      t.row(fmt::format("vehicle {} angular momentum about its impulse centre (body axes)", i + 1) +
                U("angular_momentum") + ", before",
            p.vec(m.angular_before_B[i], f_angular));
      t.row("  after", p.vec(m.angular_after_B[i], f_angular));
    }
    out += t.str();
  }
  return out;
}

// Compiled once per scalar of the list, in case_format/src/instantiate.cpp (with render), not in every
// object that writes at one of them.
#define IMPACT3D_EXTERN_REPORT_TEXT_(type, name, u) \
  extern template std::string report_text<type>(const CaseSpec&, const Analysis<type>&, const std::string&, int);
IMPACT3D_SCALARS(IMPACT3D_EXTERN_REPORT_TEXT_)
#undef IMPACT3D_EXTERN_REPORT_TEXT_

}  // namespace impact3d::case_format
