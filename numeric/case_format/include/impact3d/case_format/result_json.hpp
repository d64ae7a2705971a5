// The result document of the contract (shared spec case-format.md, "Result"), with the extra keys
// documented in docs/case-format.md: impulse-space geometry, sliding and swerve, Delta-V magnitude and PDOF.
#pragma once

#include <functional>

#include "impact3d/case_format/json_writer.hpp"
#include "impact3d/case_format/present.hpp"
#include "impact3d/case_format/strategy_kinds.hpp"
#include "impact3d/mechanics/analysis.hpp"

namespace impact3d::case_format {

inline void write_strategy_echo(JsonWriter& w, const StrategySpec& s) {
  const KindRow row = strategy_kind(s.kind);
  w.begin_object();
  w.key("name").string(row.name);
  for (const auto& p : row.parameters) {
    w.key(p.key);
    if (p.type == ParameterType::choice) w.string(s.choice(p.key));
    else if (const auto& n = s.number(p.key)) w.raw(n->text);
    else w.string("critical");
  }
  w.end_object();
}

template <typename Scalar>
void write_optional(JsonWriter& w, std::string_view key, const std::optional<Scalar>& v, const Present<Scalar>& p) {
  if (v) p.put(w.key(key), *v);
}

template <typename Scalar>
void write_matrix(JsonWriter& w, const Mat3<Scalar>& m, const Present<Scalar>& p) {
  w.begin_array();
  for (int k = 0; k < 3; ++k) p.put_vec(w, m.row(k).transpose(), Scalar(1));
  w.end_array();
}

// An integrated impulse's course (stronge): the contract's `events` and `swerve_deg`, and this
// program's `final_direction_deg`, `normal_work` and `integration` (docs/case-format.md).
template <typename Scalar>
void write_history(JsonWriter& w, const stronge::History<Scalar>& h, const Present<Scalar>& p) {
  const auto& f = p.f;
  w.key("events").begin_array();
  for (const auto& e : h.events) {
    w.begin_object();
    w.key("kind").string(stronge::event_name(e.kind));
    p.put(w.key("p"), e.p, f.impulse);
    p.put_vec(w.key("relative_velocity"), e.V_C, f.velocity);
    p.put(w.key("normal_work"), e.normal_work, f.energy);
    w.end_object();
  }
  w.end_array();
  p.put(w.key("swerve_deg"), h.swerve_deg);
  if (h.final_direction_deg) p.put(w.key("final_direction_deg"), *h.final_direction_deg);
  else w.key("final_direction_deg").null();
  w.key("normal_work").begin_object();
  p.put(w.key("compression"), h.work_compression, f.energy);
  p.put(w.key("restitution"), h.work_restitution, f.energy);
  w.end_object();
  w.key("integration").begin_object();
  w.key("steps").number([&](auto& out) { out += std::to_string(h.steps); });
  w.key("error_bound").number([&](auto& out) { append_scalar(out, h.error_bound, 3); });
  w.key("diverging_directions").number([&](auto& out) { out += std::to_string(h.diverging_directions); });
  w.end_object();
}

// `snap`: print post-impact relative velocities inside the computation's rounding bound as 0 (the
// reference suite does, so that no digit of rounding noise is printed as significant).
// `split_rule`: how the case splits the energy loss for EES ("mass", "share", "stiffness").
template <typename Scalar>
void write_solution(JsonWriter& w, const StrategySpec& spec, const VehicleSpec* veh, const Solution<Scalar>& s,
                    const Present<Scalar>& p, bool snap, const std::string& split_rule = "mass",
                    const std::function<void(JsonWriter&)>& more = {}) {
  const auto& f = p.f;
  auto snapped = [&](const Scalar& v) {
    using std::abs;
    return snap && abs(v) <= s.velocity_roundoff;
  };
  auto vel = [&](JsonWriter& to, const Scalar& v) {
    if (snapped(v)) to.raw("0");
    else p.put(to, v, f.velocity);
  };
  const auto& imp = s.impulse;
  w.begin_object();
  w.key("strategy");
  write_strategy_echo(w, spec);
  w.key("regime").string(regime_name(imp.regime));
  w.key("impulse_ratio").begin_object();
  write_optional(w, "mu", imp.mu, p);
  write_optional(w, "mu_t", imp.mu_t, p);
  write_optional(w, "mu_z", imp.mu_z, p);
  w.end_object();
  w.key("limits").begin_object();
  write_optional(w, "gir", imp.gir, p);
  write_optional(w, "cir", imp.cir, p);
  write_optional(w, "mu_t_critical", imp.mu_t_critical, p);
  write_optional(w, "mu_z_critical", imp.mu_z_critical, p);
  w.end_object();
  if (imp.plane_angle_deg) p.put(w.key("plane_angle_deg"), *imp.plane_angle_deg);
  w.key("impulse").begin_object();
  p.put_vec(w.key("contact"), imp.P_C, f.impulse);
  p.put_vec(w.key("world"), s.P_W, f.impulse);
  w.end_object();
  w.key("relative_velocity").begin_object();
  p.put_vec(w.key("before"), s.V_ri, f.velocity);
  w.key("after").number_row(3, [&](auto& out, int i) {
    if (snapped(s.V_rf[i])) out += '0';
    else append_scalar(out, Scalar(s.V_rf[i] / f.velocity), p.digits);
  });
  w.end_object();
  w.key("sliding").begin_object();
  p.put(w.key("before"), s.sliding_before, f.velocity);
  vel(w.key("after"), s.sliding_after);
  if (s.swerve_deg) p.put(w.key("swerve_angle_deg"), *s.swerve_deg); else w.key("swerve_angle_deg").null();
  if (s.swerve_speed) vel(w.key("swerve_speed"), *s.swerve_speed); else w.key("swerve_speed").null();
  if (s.sliding_along) vel(w.key("along"), *s.sliding_along); else w.key("along").null();
  if (s.reversed) w.key("reversed").boolean(*s.reversed); else w.key("reversed").null();
  w.end_object();
  if (imp.history) write_history(w, *imp.history, p);
  w.key("impulse_space").begin_object();
  p.put(w.key("restitution_effective"), s.restitution_effective);
  w.key("t_sliding").string(axis_change_name(s.t_change));
  w.key("z_sliding").string(axis_change_name(s.z_change));
  w.key("volume").string(s.volume);
  w.end_object();
  w.key("vehicles").begin_array();
  for (int i = 0; i < 2; ++i) {
    const auto& c = s.change[i];
    w.begin_object();
    w.key("name").string(veh[i].name);
    p.put_vec(w.key("velocity"), s.after[i].v_W, f.velocity);
    p.put_vec(w.key("angular_velocity"), s.after[i].w_B, f.angular_velocity);
    p.put_vec(w.key("delta_v"), c.dv_W, f.velocity);
    p.put(w.key("delta_v_magnitude"), c.dv, f.velocity);
    if (c.pdof_deg) p.put(w.key("pdof_deg"), *c.pdof_deg); else w.key("pdof_deg").null();
    if (c.clock) w.key("pdof_clock").number([&](auto& out) { out += std::to_string(*c.clock); }); else w.key("pdof_clock").null();
    const auto& m = s.motion[i];
    p.put_vec(w.key("delta_v_vehicle"), m.dv_B, f.velocity);
    p.put(w.key("speed_after"), m.speed_after, f.velocity);
    write_optional(w, "heading_after_deg", m.heading_after_deg, p);
    if (!m.heading_after_deg) w.key("heading_after_deg").null();
    p.put(w.key("yaw_rate_after"), m.yaw_rate_after, f.angular_velocity);
    p.put(w.key("deformation_energy"), s.deformation.energy[i], f.energy);
    if (s.deformation.ees[i]) p.put(w.key("ees"), *s.deformation.ees[i], f.velocity); else w.key("ees").null();
    w.end_object();
  }
  w.end_array();
  w.key("energy").begin_object();
  p.put(w.key("before"), s.energy_before, f.energy);
  p.put(w.key("after"), s.energy_after, f.energy);
  p.put(w.key("loss"), s.energy_loss, f.energy);
  w.key("split").begin_object();
  w.key("rule").string(split_rule);
  w.key("share").number_row(2, [&](auto& out, int i) { append_scalar(out, s.deformation.share[i], p.digits); });
  w.end_object();
  w.end_object();
  const auto& mo = s.momentum;
  const Scalar f_angular = f.impulse * f.length;
  auto residual = [&](JsonWriter& to, const Scalar& r) { to.number([&](auto& out) { append_scalar(out, r, 3); }); };
  if (!w.key("momentum").unpicked()) {
    w.begin_object();
    w.key("linear").begin_object();
    p.put_vec(w.key("before"), mo.linear_before_W, f.impulse);
    p.put_vec(w.key("after"), mo.linear_after_W, f.impulse);
    residual(w.key("residual_over_bound"), mo.linear_residual);
    w.end_object();
    w.key("angular_about_impulse_centre").begin_array();
    for (int i = 0; i < 2; ++i) {
      w.begin_object();
      p.put_vec(w.key("before"), mo.angular_before_B[i], f_angular);
      p.put_vec(w.key("after"), mo.angular_after_B[i], f_angular);
      residual(w.key("residual_over_bound"), mo.angular_residual[i]);
      w.end_object();
    }
    w.end_array();
    w.end_object();
  }
  w.key("rounding_bound").number([&](auto& out) { append_scalar(out, s.rounding_bound, 3); });
  w.key("warnings").begin_array();
  for (const auto& warning : s.warnings) w.string(warning.text);
  w.end_array();
  if (more) more(w);
  w.end_object();
}

// `c.units`: the unit system the numbers are written in (render sets it from --units).
// `digits`: significant digits of every number; 0 means every digit the precision holds (max_digits10).
// `extra`, when given, writes further top-level keys (the exact fractions of --precision exact).
// `one_line`: the document on one line (JSON Lines), else indented. `pick`: see json_writer.hpp.
// `per_result`, when given, writes further keys into result k (the decisions of --precision certified).
template <typename Scalar>
std::string result_json(const CaseSpec& c, const Analysis<Scalar>& a, const std::string& precision, int digits = 0,
                        bool snap_zeros = false, const std::function<void(JsonWriter&)>& extra = {},
                        bool one_line = false, JsonPick* pick = nullptr,
                        const std::function<void(JsonWriter&, std::size_t)>& per_result = {}) {
  const Present<Scalar> p(c.units, digits > 0 ? digits : std::numeric_limits<Scalar>::max_digits10);
  const auto& f = p.f;
  JsonWriter w(one_line, pick);
  w.begin_object();
  w.key("name").string(c.name);
  if (!c.description.empty()) w.key("description").string(c.description);
  w.key("units").string(units_name(c.units));
  w.key("precision").string(precision);
  w.key("engine").string(engine_name(a.engine));
  if (!w.key("coefficients").unpicked()) {
    w.begin_object();
    p.put(w.key("m_prime"), a.m_prime, f.mass);
    w.key("K");
    write_matrix(w, a.K, p);
    p.put(w.key("det_K"), Scalar(a.K.determinant()));
    p.put(w.key("condition_K"), a.kappa);
    w.key("T").begin_array();
    for (int i = 0; i < 2; ++i) write_matrix(w, a.T[i], p);
    w.end_array();
    w.end_object();
  }
  if (!w.key("impulse_space").unpicked()) {
    w.begin_object();
    p.put_vec(w.key("max_energy_loss_impulse"), a.space.P_max_loss, f.impulse);
    w.key("critical_impulse_line").begin_object();
    p.put_vec(w.key("point"), a.space.P_max_loss, f.impulse);
    p.put_vec(w.key("direction"), a.space.cil_direction, Scalar(1));
    w.end_object();
    w.key("planes").begin_object();
    const char* names[3] = {"max_compression", "t_no_sliding", "z_no_sliding"};
    for (int k = 0; k < 3; ++k) {
      w.key(names[k]).begin_object();
      p.put_vec(w.key("normal"), a.space.plane_normal.row(k).transpose(), Scalar(1));
      p.put(w.key("offset"), a.space.plane_offset(k), f.impulse);
      w.end_object();
    }
    w.key("restitution").begin_object();
    p.put_vec(w.key("normal"), a.space.plane_normal.row(0).transpose(), Scalar(1));
    p.put(w.key("offset"), a.space.restitution_offset, f.impulse);
    w.end_object();
    w.end_object();
    w.end_object();
  }
  w.key("results").begin_array();
  for (std::size_t k = 0; k < a.solutions.size(); ++k)
    write_solution(w, c.strategies[k], c.vehicles.data(), a.solutions[k], p, snap_zeros,
                   c.energy_split ? c.energy_split->rule : std::string("mass"),
                   per_result ? std::function<void(JsonWriter&)>([&](JsonWriter& to) { per_result(to, k); })
                              : std::function<void(JsonWriter&)>());
  w.end_array();
  if (extra) extra(w);
  w.end_object();
  return std::move(w).str();
}

// Compiled once per scalar of the list, in case_format/src/instantiate.cpp (with render), not in every
// object that writes at one of them.
#define IMPACT3D_EXTERN_RESULT_JSON_(type, name, u) \
  extern template std::string result_json<type>(const CaseSpec&, const Analysis<type>&, const std::string&, int, bool, \
                                                 const std::function<void(JsonWriter&)>&, bool, JsonPick*,                \
                                                 const std::function<void(JsonWriter&, std::size_t)>&);
IMPACT3D_SCALARS(IMPACT3D_EXTERN_RESULT_JSON_)
#undef IMPACT3D_EXTERN_RESULT_JSON_

}  // namespace impact3d::case_format
