// --precision exact: the 100-digit result, and beside it every rational quantity as an exact fraction
// (or, per strategy, which quantity needs a square root).
#include <fmt/format.h>

#include <stdexcept>

#include "render_exact.hpp"

#include "impact3d/case_format/read_case.hpp"
#include "impact3d/studies/precision.hpp"
#include "impact3d/case_format/report_text.hpp"
#include "impact3d/case_format/result_csv.hpp"
#include "impact3d/mechanics/exact_analysis.hpp"

namespace impact3d::studies {
using namespace case_format;  // the studies are written in the case format's terms
#if IMPACT3D_MULTIPRECISION
namespace {

struct ExactText {
  UnitFactors<rational> f;
  bool angular_exact;  // US angular velocities (deg/s) need pi
  std::string q(const rational& x, const rational& factor) const {
    std::ostringstream os;
    os << rational(x / factor);
    return os.str();
  }
  std::vector<std::string> v(const Vec3<rational>& x, const rational& factor) const {
    return {q(x.x(), factor), q(x.y(), factor), q(x.z(), factor)};
  }
};

void string_array(JsonWriter& w, const std::vector<std::string>& items) {
  w.begin_array();
  for (const auto& s : items) w.string(s);
  w.end_array();
}

void write_exact(JsonWriter& w, const CaseSpec& spec, const std::string& scene_not_rational,
                 const std::optional<ExactAnalysis>& x) {
  w.key("exact").begin_object();
  w.key("note").string("every quantity below is rational and given exactly as a string p/q in the case's units; the "
                       "numbers above are the same computation at 100 digits");
  if (!x) {
    w.key("not_rational").string(scene_not_rational);
    w.end_object();
    return;
  }
  const ExactText t{unit_factors<rational>(spec.units), spec.units == Units::SI};
  const rational one(1);
  w.key("coefficients").begin_object();
  w.key("m_prime").string(t.q(x->m_prime, t.f.mass));
  w.key("K").begin_array();
  for (int k = 0; k < 3; ++k) string_array(w, t.v(x->K.row(k).transpose(), one));
  w.end_array();
  w.end_object();
  w.key("max_energy_loss_impulse");
  string_array(w, t.v(x->P_max_loss, t.f.impulse));
  w.key("results").begin_array();
  for (const auto& r : x->results) {
    w.begin_object();
    if (!r.solution) {
      w.key("not_rational").string(r.not_rational);
      w.end_object();
      continue;
    }
    const auto& s = *r.solution;
    w.key("impulse_ratio").begin_object();
    for (const auto& [name, v] : {std::pair{"mu", s.impulse.mu}, std::pair{"mu_t", s.impulse.mu_t}, std::pair{"mu_z", s.impulse.mu_z}})
      if (v) w.key(name).string(t.q(*v, one));
    w.end_object();
    w.key("limits").begin_object();
    for (const auto& [name, v] : {std::pair{"gir", s.impulse.gir}, std::pair{"cir", s.impulse.cir},
                                  std::pair{"mu_t_critical", s.impulse.mu_t_critical},
                                  std::pair{"mu_z_critical", s.impulse.mu_z_critical}})
      if (v) w.key(name).string(t.q(*v, one));
    w.end_object();
    w.key("impulse").begin_object();
    w.key("contact");
    string_array(w, t.v(s.impulse.P_C, t.f.impulse));
    w.key("world");
    string_array(w, t.v(s.P_W, t.f.impulse));
    w.end_object();
    w.key("relative_velocity_after");
    string_array(w, t.v(s.V_rf, t.f.velocity));
    w.key("vehicles").begin_array();
    for (int i = 0; i < 2; ++i) {
      w.begin_object();
      w.key("velocity");
      string_array(w, t.v(s.after[i].v_W, t.f.velocity));
      if (t.angular_exact) {
        w.key("angular_velocity");
        string_array(w, t.v(s.after[i].w_B, t.f.angular_velocity));
      } else {
        w.key("angular_velocity").string("not rational in deg/s (pi / 180)");
      }
      w.key("delta_v");
      string_array(w, t.v(s.change[i].dv_W, t.f.velocity));
      w.end_object();
    }
    w.end_array();
    w.key("energy").begin_object();
    w.key("before").string(t.q(s.energy_before, t.f.energy));
    w.key("after").string(t.q(s.energy_after, t.f.energy));
    w.key("loss").string(t.q(s.energy_loss, t.f.energy));
    w.end_object();
    w.end_object();
  }
  w.end_array();
  w.end_object();
}

std::string exact_text(const CaseSpec& spec, const std::string& scene_not_rational, const std::optional<ExactAnalysis>& x) {
  std::string s = "\nExact (rational arithmetic; fractions in the case's units)\n";
  if (!x) return s + "  not rational: " + scene_not_rational + "\n";
  const ExactText t{unit_factors<rational>(spec.units), spec.units == Units::SI};
  s += "  m' = " + t.q(x->m_prime, t.f.mass) + "\n";
  for (int k = 0; k < 3; ++k) {
    const auto r = t.v(x->K.row(k).transpose(), rational(1));
    s += fmt::format("  K row {} = [{}, {}, {}]\n", k + 1, r[0], r[1], r[2]);
  }
  for (std::size_t k = 0; k < x->results.size(); ++k) {
    const auto& r = x->results[k];
    s += "  " + strategy_label(spec.strategies[k]) + ": ";
    if (!r.solution) {
      s += "not rational: " + r.not_rational + " (its values above are at 100 digits)\n";
      continue;
    }
    const auto P = t.v(r.solution->impulse.P_C, t.f.impulse), V = t.v(r.solution->V_rf, t.f.velocity);
    s += fmt::format("P = [{}, {}, {}], V_rel after = [{}, {}, {}], energy lost = {}\n", P[0], P[1], P[2], V[0], V[1], V[2],
                     t.q(r.solution->energy_loss, t.f.energy));
  }
  return s;
}

}  // namespace

std::string render_exact(const CaseSpec& spec, const RenderOptions& o) {
  std::optional<ExactAnalysis> x;
  std::string not_rational;
  try {
    x = exact_analyze(to_scene<rational>(spec), to_strategies<rational>(spec), o.engine);
  } catch (const Irrational& e) {
    not_rational = e.what();
  }
  using F = mp::float100;
  const Analysis<F> a = analyze(to_scene<F>(spec), to_strategies<F>(spec), o.engine);
  if (o.format == Format::csv) return result_csv_rows(spec, a, "exact", o.line);
  if (is_json(o.format))
    return result_json(
        spec, a, "exact", 0, false, [&](JsonWriter& w) { write_exact(w, spec, not_rational, x); }, o.format == Format::jsonl, o.pick);
  return report_text(spec, a, "exact (100 digits where not rational)", o.digits > 0 ? o.digits : 100) +
         exact_text(spec, not_rational, x);
}
#endif

}  // namespace impact3d::studies
