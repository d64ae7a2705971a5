// A sensitivity run written out: the contract's JSON and a text report. Numbers as the shortest decimal
// that reads back as the same double (fmt's), the same on every platform.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "impact3d/case_format/escape.hpp"
#include "impact3d/case_format/json_number.hpp"
#include "impact3d/case_format/json_writer.hpp"
#include "impact3d/case_format/present.hpp"
#include "impact3d/case_format/result_json.hpp"
#include "impact3d/studies/sensitivity.hpp"
#include "impact3d/case_format/strategy_kinds.hpp"
#include "impact3d/mechanics/problem.hpp"

namespace impact3d::studies {
using namespace case_format;  // the studies are written in the case format's terms

namespace {

// output -> { input -> value } for the outputs the document writes.
template <typename Value>
void by_output(JsonWriter& w, const SensitivityRun& run, const SensitivityResult& r, Value&& value) {
  const auto& outputs = monte_carlo_outputs();
  w.begin_object();
  for (std::size_t c = 0; c < outputs.size(); ++c) {
    if (!r.written[c]) continue;
    w.key(outputs[c].text).begin_object();
    for (std::size_t j = 0; j < run.inputs.size(); ++j) put_shortest(w.key(run.inputs[j]), value(c, j));
    w.end_object();
  }
  w.end_object();
}

}  // namespace

std::string sensitivity_json(const SensitivityRun& run) {
  const std::size_t n = run.inputs.size();
  JsonWriter w;
  w.begin_object();
  w.key("units").string(units_name(run.units));
  w.key("engine").string(engine_name(run.engine));
  w.key("precision").string("double");
  w.key("inputs").begin_object();
  for (std::size_t j = 0; j < n; ++j) put_shortest(w.key(run.inputs[j]), run.input_values[j]);
  w.end_object();
  w.key("fixed").begin_object();
  for (const auto& [path, why] : run.fixed) w.key(path).string(why);
  w.end_object();
  w.key("results").begin_array();
  for (const auto& r : run.results) {
    w.begin_object();
    w.key("strategy");
    write_strategy_echo(w, r.strategy);
    w.key("regime").string(r.regime);
    if (r.margin_of.empty()) {
      w.key("regime_margin").null();
    } else {
      put_shortest(w.key("regime_margin"), r.regime_margin);
      w.key("regime_margin_of").string(r.margin_of);
      w.key("regime_margin_derivatives").begin_object();
      for (std::size_t j = 0; j < n; ++j) put_shortest(w.key(run.inputs[j]), r.margin_derivatives[j]);
      w.end_object();
      // Where the linearized margin reaches zero when one input alone moves: how far the derivatives hold.
      w.key("regime_switch_estimate").begin_object();
      for (std::size_t j = 0; j < n; ++j)
        if (r.margin_derivatives[j] != 0 && std::isfinite(r.margin_derivatives[j]))
          put_shortest(w.key(run.inputs[j]), run.input_values[j] - r.regime_margin / r.margin_derivatives[j]);
      w.end_object();
    }
    w.key("warnings").begin_array();
    for (const auto& name : r.warnings) w.string(name);
    w.end_array();
    w.key("values").begin_object();
    const auto& outputs = monte_carlo_outputs();
    for (std::size_t c = 0; c < outputs.size(); ++c)
      if (r.written[c]) put_shortest(w.key(outputs[c].text), r.values[c]);
    w.end_object();
    w.key("derivatives");
    by_output(w, run, r, [&](std::size_t c, std::size_t j) { return r.derivatives[c * n + j]; });
    w.key("elasticities");
    by_output(w, run, r, [&](std::size_t c, std::size_t j) {
      return elasticity(r.derivatives[c * n + j], run.input_values[j], r.values[c]);
    });
    w.end_object();
  }
  w.end_array();
  w.end_object();
  return std::move(w).str();
}

std::string sensitivity_text(const SensitivityRun& run, std::size_t top) {
  const std::size_t n = run.inputs.size();
  const auto& outputs = monte_carlo_outputs();
  std::string out = fmt::format("Sensitivities, regime held fixed: {} inputs, {} engine, double\n", n,
                                engine_name(run.engine));
  out += fmt::format("units: {} ({}, {}, {}); angles in degrees\n", units_name(run.units), unit_label(run.units, "velocity"),
                     unit_label(run.units, "energy"), unit_label(run.units, "angular_velocity"));
  for (const auto& [path, why] : run.fixed) out += fmt::format("not differentiated: {}: {}\n", path, why);
  static const char* kShown[] = {"vehicles[0].delta_v_magnitude", "vehicles[1].delta_v_magnitude", "vehicles[0].pdof_deg",
                                 "vehicles[1].pdof_deg", "vehicles[0].angular_velocity[2]", "vehicles[1].angular_velocity[2]",
                                 "energy.loss"};
  for (const auto& r : run.results) {
    out += fmt::format("\n{}: {}", printable(strategy_label(r.strategy)), r.regime);
    if (!r.margin_of.empty()) out += fmt::format(", {} = {:.4g}", r.margin_of, r.regime_margin);
    out += '\n';
    for (const auto& name : r.warnings) out += fmt::format("  warning: {}\n", name);
    for (const char* shown : kShown) {
      std::size_t c = 0;
      while (c < outputs.size() && outputs[c].text != shown) ++c;
      if (c == outputs.size() || !r.written[c]) continue;
      out += fmt::format("  {} = {:.6g}\n    {:<35} {:>11} {:>11}\n", shown, r.values[c], "input", "d/dx", "elasticity");
      // Ranked by the change a 100 % change of the input would make to first order, |d x|.
      std::vector<std::size_t> order;
      for (std::size_t j = 0; j < n; ++j)
        if (std::isfinite(r.derivatives[c * n + j]) && r.derivatives[c * n + j] * run.input_values[j] != 0) order.push_back(j);
      std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return std::fabs(r.derivatives[c * n + a] * run.input_values[a]) > std::fabs(r.derivatives[c * n + b] * run.input_values[b]);
      });
      if (order.size() > top) order.resize(top);
      for (std::size_t j : order) {
        const double d = r.derivatives[c * n + j], e = elasticity(d, run.input_values[j], r.values[c]);
        out += fmt::format("    {:<35} {:>11.4g} {:>11.3g}\n", run.inputs[j], d, e);
      }
    }
  }
  return out;
}

}  // namespace impact3d::studies
