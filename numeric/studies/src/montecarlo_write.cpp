// A Monte Carlo run written out: the contract's JSON, the text report, every sample as CSV. Statistics
// are printed as the shortest decimal that reads back as the same double (fmt's), the same on every
// platform; a sample's numbers in the CSV as the result document writes them (17 digits).
#include <cmath>

#include <fmt/format.h>

#include "impact3d/case_format/csv_text.hpp"
#include "impact3d/case_format/escape.hpp"
#include "impact3d/case_format/format_double.hpp"
#include "impact3d/case_format/json_number.hpp"
#include "impact3d/case_format/json_writer.hpp"
#include "impact3d/case_format/result_json.hpp"
#include "impact3d/studies/montecarlo.hpp"
#include "impact3d/case_format/present.hpp"

namespace impact3d::studies {
using namespace case_format;  // the studies are written in the case format's terms

namespace {

double fraction(std::uint64_t count, std::uint64_t of) { return of ? static_cast<double>(count) / static_cast<double>(of) : 0.0; }

void write_summary(JsonWriter& w, const OutputSummary& o, const Linearized& lin) {
  const auto& s = o.summary;
  w.begin_object();
  const auto c = static_cast<std::size_t>(o.output - monte_carlo_outputs().data());
  if (lin.note.empty() && c < lin.mean.size()) {
    w.key("linearized").begin_object();
    put_shortest(w.key("mean"), lin.mean[c]);
    put_shortest(w.key("sd"), lin.sd[c]);
    w.end_object();
  }
  w.key("count").raw(std::to_string(s.count));
  if (o.undefined) w.key("undefined").raw(std::to_string(o.undefined));
  if (o.output->angle) w.key("angle").string(o.output->from_zero ? "[0, 360)" : "(-180, 180]");
  if (s.count) {
    put_shortest(w.key("mean"), s.mean);
    put_shortest(w.key("sd"), s.sd);
    w.key("percentiles").begin_object();
    for (std::size_t p = 0; p < uncertainty::kPercentiles.size(); ++p) put_shortest(w.key(uncertainty::kPercentileKeys[p]), s.percentile[p]);
    w.end_object();
    put_shortest(w.key("mean_se"), s.mean_se);
    w.key("percentile_se").begin_object();
    for (std::size_t p = 0; p < uncertainty::kPercentiles.size(); ++p)
      put_shortest(w.key(uncertainty::kPercentileKeys[p]), s.percentile_se[p]);
    w.end_object();
    put_shortest(w.key("min"), s.min);
    put_shortest(w.key("max"), s.max);
  }
  w.end_object();
}

// The first-order propagation beside the samples: ΔV, PDOF and the energy loss, and where the two part.
std::string linear_text(const StrategySummary& r) {
  const Linearized& lin = r.linear;
  if (!lin.note.empty()) return fmt::format("  first order: none ({})\n", printable(lin.note));
  std::string out = fmt::format("  first order, from the derivatives at the inputs' means (regime {}):\n", lin.regime);
  out += fmt::format("  {:<35} {:>9} {:>9} {:>10} {:>10}\n", "output", "mean", "sd", "MC mean", "MC sd");
  for (const auto& o : r.outputs) {
    const auto c = static_cast<std::size_t>(o.output - monte_carlo_outputs().data());
    const std::string& t = o.output->text;
    const bool shown = t.ends_with("delta_v_magnitude") || t.ends_with("pdof_deg") || t == "energy.loss";
    if (!shown || !o.summary.count || c >= lin.mean.size()) continue;
    out += fmt::format("  {:<35} {:>9.4g} {:>9.3g} {:>10.4g} {:>10.3g}\n", t, lin.mean[c], lin.sd[c], o.summary.mean, o.summary.sd);
  }
  if (lin.regime_switch)
    out += "  warning: some samples take another regime than the inputs' means take;\n"
           "    the first order holds within one regime\n";
  if (!lin.differs.empty()) {
    out += fmt::format("  warning: {} outputs where the first order misses the samples' mean or sd\n"
                       "    by > 10 % of the sd + 4 SE (non-linearity, or a regime switch in range):",
                       lin.differs.size());
    std::size_t column = 80;
    for (const auto& path : lin.differs) {
      if (column + path.size() + 1 > 77) out += "\n   ", column = 3;
      out += " " + path, column += path.size() + 1;
    }
    out += "\n";
  }
  return out;
}

}  // namespace

std::string montecarlo_json(const MonteCarloRun& run) {
  JsonWriter w;
  w.begin_object();
  w.key("samples").raw(std::to_string(run.samples));
  w.key("seed").raw(std::to_string(run.seed));
  w.key("precision").string(run.precision);
  w.key("units").string(units_name(run.units));
  w.key("inputs").begin_array();
  for (const auto& in : run.inputs) w.string(in);
  w.end_array();
  w.key("results").begin_array();
  for (const auto& r : run.results) {
    w.begin_object();
    w.key("strategy");
    write_strategy_echo(w, r.strategy);
    w.key("solved").raw(std::to_string(r.solved));
    w.key("rejected").begin_object();
    for (const auto& rej : r.rejected) w.key(rej.reason).raw(std::to_string(rej.count));
    w.end_object();
    w.key("rejections").begin_array();
    for (const auto& rej : r.rejected) {
      w.begin_object();
      w.key("reason").string(rej.reason);
      w.key("count").raw(std::to_string(rej.count));
      w.key("first_sample").raw(std::to_string(rej.first));
      w.key("message").string(rej.message);
      w.end_object();
    }
    w.end_array();
    w.key("regime_probability").begin_object();
    for (std::size_t k = 0; k < kRegimeNames.size(); ++k)
      if (r.regimes[k]) put_shortest(w.key(kRegimeNames[k]), fraction(r.regimes[k], r.solved));
    w.end_object();
    w.key("warning_probability").begin_object();
    for (std::size_t k = 0; k < kWarningNames.size(); ++k) put_shortest(w.key(kWarningNames[k]), fraction(r.warnings[k], r.solved));
    w.end_object();
    w.key("linearization").begin_object();
    if (!r.linear.note.empty()) {
      w.key("note").string(r.linear.note);
    } else {
      w.key("regime").string(r.linear.regime);
      w.key("regime_switch").raw(r.linear.regime_switch ? "true" : "false");
      w.key("differs").begin_array();
      for (const auto& path : r.linear.differs) w.string(path);
      w.end_array();
    }
    w.end_object();
    w.key("outputs").begin_object();
    for (const auto& o : r.outputs) {
      w.key(o.output->text);
      write_summary(w, o, r.linear);
    }
    w.end_object();
    w.end_object();
  }
  w.end_array();
  w.end_object();
  return std::move(w).str();
}

std::string montecarlo_text(const MonteCarloRun& run) {
  std::string out = fmt::format("Monte Carlo: {} samples, seed {}, {} precision\n", run.samples, run.seed, run.precision);
  out += fmt::format("units: {} ({}, {}, {}, {}); angles in degrees\n", units_name(run.units), unit_label(run.units, "velocity"),
                     unit_label(run.units, "angular_velocity"), unit_label(run.units, "impulse"), unit_label(run.units, "energy"));
  out += "uncertain inputs:\n";
  for (const auto& in : run.inputs) out += "  " + printable(in) + "\n";
  for (const auto& r : run.results) {
    out += fmt::format("\n{}\n", printable(strategy_label(r.strategy)));
    out += fmt::format("  solved {} of {}", r.solved, run.samples);
    for (const auto& rej : r.rejected) out += fmt::format("; rejected {}: {}", printable(rej.reason), rej.count);
    out += "\n";
    for (const auto& rej : r.rejected)
      out += fmt::format("    first {} (sample {}): {}\n", printable(rej.reason), rej.first, printable(rej.message));
    out += "  regime:";
    for (std::size_t k = 0; k < kRegimeNames.size(); ++k)
      if (r.regimes[k]) out += fmt::format(" {} {:.4g} %", kRegimeNames[k], 100 * fraction(r.regimes[k], r.solved));
    out += "\n  warnings:";
    bool any = false;
    for (std::size_t k = 0; k < kWarningNames.size(); ++k)
      if (r.warnings[k]) out += fmt::format(" {} {:.4g} %;", kWarningNames[k], 100 * fraction(r.warnings[k], r.solved)), any = true;
    out += any ? "\n" : " none\n";
    // 79 columns: the path, then mean, sd and the 95 % interval; the JSON has every percentile.
    out += fmt::format("  {:<35} {:>9} {:>9} {:>10} {:>10}\n", "output", "mean", "sd", "2.5 %", "97.5 %");
    for (const auto& o : r.outputs) {
      const auto& s = o.summary;
      if (!s.count) {
        out += fmt::format("  {:<35} undefined in every sample\n", o.output->text);
        continue;
      }
      out += fmt::format("  {:<35} {:>9.4g} {:>9.3g} {:>10.4g} {:>10.4g}", o.output->text, s.mean, s.sd, s.percentile[1],
                         s.percentile[7]);
      if (o.undefined) out += fmt::format("  ({} undefined)", o.undefined);
      out += "\n";
    }
    out += linear_text(r);
  }
  return out;
}

void samples_csv(const MonteCarloRun& run, const std::function<void(std::string_view)>& write) {
  const std::size_t outputs = monte_carlo_outputs().size(), inputs = run.inputs.size();
  std::string line = "sample";
  for (const auto& in : run.inputs) line += ',', put_csv_text(line, in);
  for (std::size_t k = 0; k < run.results.size(); ++k) {
    line += fmt::format(",results[{}].regime,results[{}].rejected", k, k);
    for (const auto& o : run.results[k].outputs) line += fmt::format(",results[{}].{}", k, o.output->text);
  }
  line += '\n';
  write(line);
  char buf[32];
  auto number = [&](double x) {
    if (std::isfinite(x)) line.append(buf, format_g17(buf, x));
  };
  for (std::uint64_t i = 0; i < run.samples; ++i) {
    line = std::to_string(i);
    for (std::size_t c = 0; c < inputs; ++c) line += ',', number(run.inputs_of[i * inputs + c]);
    for (std::size_t k = 0; k < run.results.size(); ++k) {
      const int regime = run.regime_of[k][i];
      line += ',';
      if (regime >= 0) line += kRegimeNames[static_cast<std::size_t>(regime)];
      line += ',';
      if (const std::uint16_t reason = run.reason_of[k][i]) put_csv_text(line, run.reasons[reason - 1u]);
      for (const auto& o : run.results[k].outputs) {
        const auto c = static_cast<std::size_t>(o.output - monte_carlo_outputs().data());
        line += ',';
        number(run.outputs_of[(k * outputs + c) * run.samples + i]);
      }
    }
    line += '\n';
    write(line);
  }
}

}  // namespace impact3d::studies
