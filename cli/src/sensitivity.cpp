#include "sensitivity.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <fmt/format.h>

#include "impact3d/cli/gnuplot.hpp"
#include "impact3d/case_format/limits.hpp"
#include "impact3d/case_format/read_case.hpp"
#include "impact3d/studies/sensitivity.hpp"
#include "impact3d/case_format/strategy_kinds.hpp"
#include "impact3d/case_format/strategy_option.hpp"

namespace impact3d::cli {

namespace {

constexpr std::size_t kTornadoBars = 12;

// The inputs that move ΔV of `vehicle` most, by elasticity: one bar each, largest on top. Input paths
// are the program's own spellings; they reach gnuplot only as data.
std::string tornado(const studies::SensitivityRun& run, std::size_t k, int vehicle, const OutputDir& dir, bool png) {
  const auto& outputs = case_format::monte_carlo_outputs();
  const std::string path = fmt::format("vehicles[{}].delta_v_magnitude", vehicle);
  std::size_t c = 0;
  while (c < outputs.size() && outputs[c].text != path) ++c;
  const auto& r = run.results[k];
  if (c == outputs.size() || !r.written[c] || !std::isfinite(r.values[c])) return {};
  std::vector<std::pair<double, std::size_t>> bars;
  for (std::size_t j = 0; j < run.inputs.size(); ++j) {
    const double e = studies::elasticity(run.derivative(k, c, j), run.input_values[j], r.values[c]);
    if (std::isfinite(e) && e != 0) bars.emplace_back(e, j);
  }
  if (bars.empty()) return {};
  std::stable_sort(bars.begin(), bars.end(), [](const auto& a, const auto& b) { return std::fabs(a.first) > std::fabs(b.first); });
  if (bars.size() > kTornadoBars) bars.resize(kTornadoBars);
  std::string data;
  for (std::size_t b = bars.size(); b-- > 0;) data += fmt::format("{},{}\n", run.inputs[bars[b].second], bars[b].first);
  const std::string name = fmt::format("sens{}_tornado_dv{}", k, vehicle);
  dir.write(name + ".dat", data);
  const std::string script = fmt::format(
      "{}set datafile separator comma\nset grid xtics\nunset key\n"
      "set title {} noenhanced\nset xlabel {} noenhanced\nset ytics noenhanced\nset yrange [-0.7:{}]\n"
      "set style fill solid 0.6\nset yzeroaxis lt -1\n"
      "plot '{}' using (0):0:(0):2:($0-0.38):($0+0.38):ytic(1) with boxxyerror lc rgb '#3060a0'\n",
      gnuplot_terminal(png, 900, static_cast<int>(200 + 30 * bars.size())),
      gnuplot_string(fmt::format("{} ({}): vehicle {} delta-V {:.4g}", case_format::strategy_label(r.strategy), r.regime, vehicle + 1,
                                 r.values[c])),
      gnuplot_string("elasticity: relative change of delta-V per relative change of the input"),
      static_cast<double>(bars.size()) - 0.3, name + ".dat");
  std::string warnings;
  const std::string written = draw_figure(dir, name, script, png, warnings);
  std::fputs(warnings.c_str(), stderr);
  return written;
}

}  // namespace

int sensitivity(const SensitivityCliOptions& o) {
  studies::SensitivityOptions so;
  so.engine = o.engine;
  if (o.strategies.size() > case_format::limits::kStrategies)
    throw case_format::CaseError("--strategy", fmt::format("more than {} strategies", case_format::limits::kStrategies));
  for (std::size_t i = 0; i < o.strategies.size(); ++i)
    so.strategies.push_back(case_format::read_strategy_option(o.strategies[i], static_cast<int>(i)));
  if (!o.plot_dir.empty()) require_gnuplot();
  const studies::SensitivityRun run = studies::sensitivity(case_format::read_text_file(o.case_path), so);
  if (!o.plot_dir.empty()) {
    const OutputDir dir(o.plot_dir);
    for (std::size_t k = 0; k < run.results.size(); ++k)
      for (int v = 0; v < 2; ++v) (void)tornado(run, k, v, dir, o.png);
  }
  const std::string out = o.format == "json" ? studies::sensitivity_json(run) : studies::sensitivity_text(run);
  std::fwrite(out.data(), 1, out.size(), stdout);
  return 0;
}

}  // namespace impact3d::cli
