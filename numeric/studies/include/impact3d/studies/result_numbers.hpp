// The numbers of one result as its document writes them (result_json.hpp, write_solution), in the
// order of monte_carlo_outputs(): each value divided by its unit factor as the writer divides it, NaN
// where the writer writes null, and `written` 0 where the writer leaves the key out. At double these
// are the document's numbers bit for bit (tests/studies/check_montecarlo.cpp); at a dual type they carry their
// derivatives (sensitivity.hpp).
#pragma once

#include <limits>
#include <optional>
#include <stdexcept>

#include "impact3d/studies/montecarlo.hpp"
#include "impact3d/scalar/exact.hpp"
#include "impact3d/mechanics/post_impact.hpp"
#include "impact3d/mechanics/units.hpp"

namespace impact3d::studies {

template <typename Scalar>
void numbers_of_solution(const Solution<Scalar>& s, const UnitFactors<Scalar>& f, Scalar* v, char* written) {
  const Scalar nan(std::numeric_limits<typename DualTraits<Scalar>::Value>::quiet_NaN());
  std::size_t c = 0;
  auto put = [&](const Scalar& x) { v[c] = is_finite(x) ? x : nan, written[c++] = 1; };
  auto maybe = [&](const std::optional<Scalar>& x) {  // a key the writer leaves out when absent
    if (x) put(*x);
    else written[c++] = 0;
  };
  auto null_or = [&](const std::optional<Scalar>& x, const Scalar& factor) { put(x ? Scalar(*x / factor) : nan); };
  auto vec = [&](const Vec3<Scalar>& x, const Scalar& factor) {
    for (int k = 0; k < 3; ++k) put(Scalar(x[k] / factor));
  };
  const Scalar one(1);
  const auto& imp = s.impulse;
  maybe(imp.mu), maybe(imp.mu_t), maybe(imp.mu_z);
  maybe(imp.gir), maybe(imp.cir), maybe(imp.mu_t_critical), maybe(imp.mu_z_critical);
  maybe(imp.plane_angle_deg);
  vec(imp.P_C, f.impulse), vec(s.P_W, f.impulse);
  vec(s.V_ri, f.velocity), vec(s.V_rf, f.velocity);
  put(Scalar(s.sliding_before / f.velocity)), put(Scalar(s.sliding_after / f.velocity));
  null_or(s.swerve_deg, one), null_or(s.swerve_speed, f.velocity), null_or(s.sliding_along, f.velocity);
  put(s.restitution_effective);
  for (int i = 0; i < 2; ++i) {
    vec(s.after[i].v_W, f.velocity), vec(s.after[i].w_B, f.angular_velocity), vec(s.change[i].dv_W, f.velocity);
    put(Scalar(s.change[i].dv / f.velocity));
    null_or(s.change[i].pdof_deg, one);
    const auto& m = s.motion[i];
    vec(m.dv_B, f.velocity);
    put(Scalar(m.speed_after / f.velocity));
    null_or(m.heading_after_deg, one);
    put(Scalar(m.yaw_rate_after / f.angular_velocity));
    put(Scalar(s.deformation.energy[i] / f.energy));
    null_or(s.deformation.ees[i], f.velocity);
  }
  put(Scalar(s.energy_before / f.energy)), put(Scalar(s.energy_after / f.energy)), put(Scalar(s.energy_loss / f.energy));
  if (const auto& h = imp.history) {
    put(h->swerve_deg);
    null_or(h->final_direction_deg, one);
    put(Scalar(h->work_compression / f.energy)), put(Scalar(h->work_restitution / f.energy));
  } else {
    for (int k = 0; k < 4; ++k) written[c++] = 0;
  }
  if (c != monte_carlo_outputs().size()) throw std::logic_error("numbers_of_solution and monte_carlo_outputs disagree");
}

}  // namespace impact3d::studies
