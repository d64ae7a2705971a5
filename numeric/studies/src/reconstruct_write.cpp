// A reconstruction written out: the contract's JSON and a text report. Numbers as the shortest decimal
// that reads back as the same double (fmt's); NaN (an undetermined unknown, a test without degrees of
// freedom) as null.
#include <cmath>

#include <fmt/format.h>

#include "impact3d/case_format/escape.hpp"
#include "impact3d/case_format/json_number.hpp"
#include "impact3d/case_format/json_writer.hpp"
#include "impact3d/case_format/present.hpp"
#include "impact3d/studies/reconstruct.hpp"
#include "impact3d/case_format/result_json.hpp"
#include "impact3d/case_format/strategy_kinds.hpp"
#include "impact3d/mechanics/problem.hpp"

namespace impact3d::studies {
using namespace case_format;  // the studies are written in the case format's terms

namespace {

// The significance level of the chi2 test of consistency.
constexpr double kSignificance = 0.01;

void unknown_echo(JsonWriter& w, const Unknown& u) {
  w.begin_object();
  switch (u.kind) {
    case Unknown::Kind::speed: w.key("speed").raw(fmt::format("{}", u.vehicle)); break;
    case Unknown::Kind::heading: w.key("heading").raw(fmt::format("{}", u.vehicle)); break;
    case Unknown::Kind::path: w.key("path").string(u.path_text); break;
  }
  w.end_object();
}

// A fit that did not converge, or lies on a regime boundary, has no chi2 distribution to test against.
const char* chi2_test(const Fit& f) {
  if (!std::isfinite(f.p_value) || !f.converged || !f.admissible) return "untested";
  return f.p_value >= kSignificance ? "passed" : "failed";
}

void write_fit(JsonWriter& w, const Reconstruction& r, const Fit& f) {
  const std::size_t p = r.unknowns.size();
  w.key("regime").string(f.regime);
  w.key("admissible").boolean(f.admissible);
  w.key("decided_regime").string(f.decided);
  w.key("converged").boolean(f.converged);
  w.key("solver").begin_object();
  w.key("status").string(f.solver_status);
  w.key("evaluations").raw(fmt::format("{}", f.evaluations));
  w.end_object();
  w.key("estimates").begin_array();
  for (std::size_t j = 0; j < p; ++j) {
    w.begin_object();
    w.key("unknown");
    unknown_echo(w, r.unknowns[j]);
    put_shortest(w.key("value"), j < f.value.size() ? f.value[j] : NAN);
    put_shortest(w.key("sd"), j < f.sd.size() ? f.sd[j] : NAN);
    w.end_object();
  }
  w.end_array();
  w.key("correlation").begin_array();
  for (const auto& row : f.correlation) {
    w.begin_array();
    for (double c : row) put_shortest(w, c);
    w.end_array();
  }
  w.end_array();
  w.key("residuals").begin_array();
  for (const auto& e : f.residuals) {
    w.begin_object();
    w.key("evidence").raw(fmt::format("{}", e.item));
    w.key("output").string(e.output);
    put_shortest(w.key("value"), e.value);
    put_shortest(w.key("sd"), e.sd);
    put_shortest(w.key("fitted"), e.fitted);
    put_shortest(w.key("residual"), e.residual);
    put_shortest(w.key("standardized"), e.standardized);
    w.end_object();
  }
  w.end_array();
  put_shortest(w.key("chi2"), f.chi2);
  w.key("dof").raw(fmt::format("{}", f.dof));
  put_shortest(w.key("p_value"), f.p_value);
  w.key("chi2_test").string(chi2_test(f));
  w.key("identifiable").boolean(f.identifiable);
  w.key("undetermined").begin_array();
  for (const auto& u : f.undetermined) {
    w.begin_object();
    w.key("combination").begin_object();
    for (std::size_t j = 0; j < p; ++j)
      if (u.combination[j] != 0) put_shortest(w.key(r.unknowns[j].label()), u.combination[j]);
    w.end_object();
    put_shortest(w.key("relative_singular_value"), u.relative_singular_value);
    w.end_object();
  }
  w.end_array();
  w.key("warnings").begin_array();
  for (const auto& s : f.warnings) w.string(s);
  w.end_array();
}

std::string number_or_dash(double x, const char* spec) {
  return std::isfinite(x) ? fmt::format(fmt::runtime(spec), x) : std::string("-");
}

std::string fit_text(const Reconstruction& r, const Fit& f) {
  std::string out = fmt::format("regime {}{}; chi2 = {:.4g} with {} degrees of freedom, p = {} (test at {}: {})\n", f.regime,
                                f.admissible ? "" : f.decided != f.regime ? fmt::format(" (the fitted inputs decide {})", f.decided) : std::string(" (not admitted)"), f.chi2, f.dof,
                                number_or_dash(f.p_value, "{:.3g}"), kSignificance, chi2_test(f));
  out += fmt::format("  {:<34} {:>14} {:>12}\n", "unknown", "estimate", "sd");
  for (std::size_t j = 0; j < r.unknowns.size(); ++j)
    out += fmt::format("  {:<34} {:>14} {:>12}\n", printable(r.unknowns[j].label()), number_or_dash(f.value[j], "{:.8g}"),
                       number_or_dash(f.sd[j], "{:.3g}"));
  if (r.unknowns.size() > 1) {
    out += "  correlation\n";
    for (const auto& row : f.correlation) {
      out += "   ";
      for (double c : row) out += fmt::format(" {:>7}", number_or_dash(c, "{:.3f}"));
      out += '\n';
    }
  }
  out += fmt::format("  {:<34} {:>12} {:>12} {:>10}\n", "evidence", "observed", "fitted", "residual/sd");
  for (const auto& e : f.residuals)
    out += fmt::format("  {:<34} {:>12.6g} {:>12} {:>10}\n", printable(e.output), e.value, number_or_dash(e.fitted, "{:.6g}"),
                       number_or_dash(e.standardized, "{:.3g}"));
  for (const auto& w : f.warnings) out += fmt::format("  warning: {}\n", printable(w));
  return out;
}

}  // namespace

std::string reconstruction_json(const Reconstruction& r) {
  JsonWriter w;
  w.begin_object();
  w.key("units").string(units_name(r.units));
  w.key("engine").string(engine_name(r.engine));
  w.key("precision").string("double");
  w.key("strategy");
  write_strategy_echo(w, r.strategy);
  w.key("unknowns").begin_array();
  for (std::size_t j = 0; j < r.unknowns.size(); ++j) {
    w.begin_object();
    w.key("unknown");
    unknown_echo(w, r.unknowns[j]);
    w.key("label").string(r.unknowns[j].label());
    put_shortest(w.key("start"), r.start[j]);
    w.end_object();
  }
  w.end_array();
  put_shortest(w.key("significance"), kSignificance);
  write_fit(w, r, r.best);
  w.key("alternatives").begin_array();
  for (const Fit& f : r.alternatives) {
    w.begin_object();
    write_fit(w, r, f);
    w.end_object();
  }
  w.end_array();
  w.key("inadmissible").begin_array();
  for (const Fit& f : r.inadmissible) {
    w.begin_object();
    w.key("imposed_regime").string(f.imposed);
    w.key("decided_regime").string(f.decided);
    w.key("converged").boolean(f.converged);
    put_shortest(w.key("chi2"), f.chi2);
    w.end_object();
  }
  w.end_array();
  w.end_object();
  return std::move(w).str();
}

std::string reconstruction_text(const Reconstruction& r) {
  std::string out = fmt::format("Reconstruction by weighted least squares: {}, {} engine, double\n", printable(strategy_label(r.strategy)),
                                engine_name(r.engine));
  out += fmt::format("units: {} ({}, {}); headings in degrees\n", units_name(r.units), unit_label(r.units, "velocity"),
                     unit_label(r.units, "angular_velocity"));
  out += fit_text(r, r.best);
  for (const Fit& f : r.alternatives) out += "\nalternative: " + fit_text(r, f);
  for (const Fit& f : r.inadmissible)
    out += fmt::format("\nnot admissible: {} (chi2 = {:.4g}{}) decides {}\n",
                       f.imposed.empty() ? std::string("the fit") : fmt::format("the {} regime's fit", f.imposed), f.chi2,
                       f.converged ? "" : ", not converged", f.decided.empty() ? "nothing (no solution)" : f.decided);
  return out;
}

}  // namespace impact3d::studies
