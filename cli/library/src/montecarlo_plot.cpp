#include "impact3d/cli/montecarlo_plot.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "impact3d/cli/gnuplot.hpp"
#include "impact3d/case_format/escape.hpp"
#include "impact3d/case_format/strategy_kinds.hpp"
#include "impact3d/cli/user_error.hpp"

namespace impact3d::cli {

namespace {

constexpr int kBins = 50;
constexpr std::uint64_t kScatterPoints = 5000;  // the first solved samples: already a random subset

struct Drawing {
  const studies::MonteCarloRun& run;
  const OutputDir& dir;
  bool png;
  std::string written, warnings;
};

std::string header(const Drawing& d, const std::string& title, const std::string& xlabel, const std::string& ylabel) {
  return fmt::format(
      "{}set datafile separator comma\nset grid\nset key below noenhanced\n"
      "set title {} noenhanced\nset xlabel {} noenhanced\nset ylabel {} noenhanced\n",
      gnuplot_terminal(d.png, 800, 550), gnuplot_string(title), gnuplot_string(xlabel), gnuplot_string(ylabel));
}

void draw(Drawing& d, const std::string& name, const std::string& script) {
  d.written += draw_figure(d.dir, name, script, d.png, d.warnings);
}

std::size_t output_index(const std::string& path) {
  const auto& all = case_format::monte_carlo_outputs();
  for (std::size_t c = 0; c < all.size(); ++c)
    if (all[c].text == path) return c;
  return all.size();
}

// The value as drawn: an angle unwrapped about its summary's mean, so that a spread across the wrap is
// one hump, as the percentiles are.
double drawn(const studies::OutputSummary& o, double x) {
  if (!o.output->angle) return x;
  double v = x - o.summary.mean;
  while (v > 180) v -= 360;
  while (v <= -180) v += 360;
  return o.summary.mean + v;
}

double column(const studies::MonteCarloRun& run, std::size_t k, std::size_t c, std::uint64_t i) {
  return run.outputs_of[(k * case_format::monte_carlo_outputs().size() + c) * run.samples + i];
}

const studies::OutputSummary* summary_of(const studies::StrategySummary& s, std::size_t c) {
  for (const auto& o : s.outputs)
    if (o.output == &case_format::monte_carlo_outputs()[c]) return &o;
  return nullptr;
}

void histogram(Drawing& d, std::size_t k, const studies::OutputSummary& o, const std::string& name) {
  const auto& run = d.run;
  const std::size_t c = static_cast<std::size_t>(o.output - case_format::monte_carlo_outputs().data());
  std::vector<double> values;
  for (std::uint64_t i = 0; i < run.samples; ++i)
    if (const double x = column(run, k, c, i); std::isfinite(x)) values.push_back(drawn(o, x));
  if (values.empty()) return;
  const auto [mn, mx] = std::minmax_element(values.begin(), values.end());
  const double lo = *mn, hi = *mx;
  const double width = hi > lo ? (hi - lo) / kBins : std::max(1.0, std::fabs(lo)) * 1e-3;
  std::vector<std::uint64_t> counts(kBins, 0);
  for (double x : values) counts[static_cast<std::size_t>(std::clamp((x - lo) / width, 0.0, kBins - 1.0))]++;
  std::string dat;
  for (int b = 0; b < kBins; ++b) dat += fmt::format("{:.17g},{}\n", lo + (b + 0.5) * width, counts[static_cast<std::size_t>(b)]);
  d.dir.write(name + ".dat", dat);
  std::string script = header(d, fmt::format("{}: {} ({} samples)", case_format::strategy_label(run.results[k].strategy), o.output->text, values.size()),
                              o.output->text + (o.output->angle ? " (deg, unwrapped about the mean)" : ""), "samples");
  script += fmt::format("set style fill solid 0.4\nset boxwidth {:.17g}\n", width);
  // The percentiles the summary reports, as vertical lines: 2.5 and 97.5 dashed, the median solid.
  const std::array<std::pair<std::size_t, const char*>, 3> marks{{{1, "dt 2"}, {4, "dt 1"}, {7, "dt 2"}}};
  std::string lines;
  for (const auto& [p, dash] : marks) {
    const double x = drawn(o, o.summary.percentile[p]);
    script += fmt::format("set arrow from {:.17g}, graph 0 to {:.17g}, graph 1 nohead lw 2 lc rgb '#c03030' {}\n", x, x, dash);
    script += fmt::format("set label {} at {:.17g}, graph 0.97 left offset 0.5,0 noenhanced\n",
                          gnuplot_string(fmt::format("{} %: {:.4g}", uncertainty::kPercentileKeys[p], o.summary.percentile[p])), x);
  }
  script += fmt::format("plot '{}.dat' using 1:2 with boxes lc rgb '#3060a0' title {}\n", name,
                        gnuplot_string(fmt::format("mean {:.4g}, sd {:.3g}; percentiles 2.5, 50, 97.5 marked", o.summary.mean, o.summary.sd)));
  draw(d, name, script);
}

void scatter(Drawing& d, std::size_t k, std::size_t cx, std::size_t cy, const std::string& name) {
  const auto& run = d.run;
  std::string dat;
  std::uint64_t n = 0;
  for (std::uint64_t i = 0; i < run.samples && n < kScatterPoints; ++i) {
    const double x = column(run, k, cx, i), y = column(run, k, cy, i);
    if (std::isfinite(x) && std::isfinite(y)) dat += fmt::format("{:.17g},{:.17g}\n", x, y), ++n;
  }
  if (!n) return;
  d.dir.write(name + ".dat", dat);
  const auto& all = case_format::monte_carlo_outputs();
  std::string script = header(d, fmt::format("{}: {} against {} ({} samples)", case_format::strategy_label(run.results[k].strategy), all[cy].text,
                                             all[cx].text, n),
                              all[cx].text, all[cy].text);
  script += fmt::format("plot '{}.dat' using 1:2 with points pt 7 ps 0.3 lc rgb '#3060a0' notitle\n", name);
  draw(d, name, script);
}

// ΔV of both vehicles against input j.
void against_input(Drawing& d, std::size_t k, std::size_t j, const std::string& name) {
  const auto& run = d.run;
  const std::size_t inputs = run.inputs.size();
  const std::size_t dv[2] = {output_index("vehicles[0].delta_v_magnitude"), output_index("vehicles[1].delta_v_magnitude")};
  std::string dat;
  std::uint64_t n = 0;
  for (std::uint64_t i = 0; i < run.samples && n < kScatterPoints; ++i) {
    const double a = column(run, k, dv[0], i), b = column(run, k, dv[1], i);
    if (!std::isfinite(a) || !std::isfinite(b)) continue;
    dat += fmt::format("{:.17g},{:.17g},{:.17g}\n", run.inputs_of[i * inputs + j], a, b), ++n;
  }
  if (!n) return;
  d.dir.write(name + ".dat", dat);
  std::string script = header(d, fmt::format("{}: delta-V against {} ({} samples)", case_format::strategy_label(run.results[k].strategy),
                                             run.inputs[j], n),
                              run.inputs[j], "delta_v_magnitude");
  script += fmt::format("plot '{0}.dat' using 1:2 with points pt 7 ps 0.3 lc rgb '#3060a0' title 'vehicles[0]', \\\n"
                        "     '{0}.dat' using 1:3 with points pt 5 ps 0.3 lc rgb '#c06020' title 'vehicles[1]'\n",
                        name);
  draw(d, name, script);
}

}  // namespace

void check_plot_options(const MonteCarloPlotOptions& o) {
  for (const std::string* path : {&o.scatter_x, &o.scatter_y})
    if (output_index(*path) == case_format::monte_carlo_outputs().size())
      throw case_format::CaseError("--scatter", fmt::format("{} is not an output (docs/montecarlo-and-sensitivity.md)", case_format::quoted(*path)));
  require_gnuplot();
}

std::string montecarlo_plot(const studies::MonteCarloRun& run, const MonteCarloPlotOptions& o) {
  const std::size_t cx = output_index(o.scatter_x), cy = output_index(o.scatter_y);
  const OutputDir dir(o.out_dir);
  Drawing d{run, dir, o.png, "", ""};
  for (std::size_t k = 0; k < run.results.size(); ++k) {
    const auto& s = run.results[k];
    for (const char* path : {"vehicles[0].delta_v_magnitude", "vehicles[1].delta_v_magnitude", "vehicles[0].pdof_deg",
                             "vehicles[1].pdof_deg", "energy.loss"}) {
      const studies::OutputSummary* summary = summary_of(s, output_index(path));
      if (summary && summary->summary.count) {
        std::string slug = path;
        std::replace_if(slug.begin(), slug.end(), [](char ch) { return ch == '[' || ch == ']' || ch == '.'; }, '_');
        slug.erase(std::unique(slug.begin(), slug.end(), [](char a, char b) { return a == '_' && b == '_'; }), slug.end());
        histogram(d, k, *summary, fmt::format("mc{}_hist_{}", k, slug));
      }
    }
    if (summary_of(s, cx) && summary_of(s, cy)) scatter(d, k, cx, cy, fmt::format("mc{}_scatter", k));
    for (std::size_t j = 0; j < run.inputs.size(); ++j) against_input(d, k, j, fmt::format("mc{}_dv_vs_input{}", k, j));
  }
  std::fputs(d.warnings.c_str(), stderr);
  return d.written;
}

}  // namespace impact3d::cli
