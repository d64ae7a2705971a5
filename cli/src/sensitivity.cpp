#include "sensitivity.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <fmt/format.h>

#include "gnuplot.hpp"
#include "impact3d/io/limits.hpp"
#include "impact3d/io/read_case.hpp"
#include "impact3d/io/sensitivity.hpp"
#include "impact3d/io/strategy_kinds.hpp"
#include "impact3d/io/strategy_option.hpp"

namespace impact3d::cli {

namespace {

constexpr std::size_t kTornadoBars = 12;

// The inputs that move ΔV of `vehicle` most, by elasticity: one bar each, largest on top. Input paths
// are the program's own spellings; they reach gnuplot only as data.
std::string tornado(const io::SensitivityRun& run, std::size_t k, int vehicle, const OutputDir& dir, bool png) {
  const auto& outputs = io::monte_carlo_outputs();
  const std::string path = fmt::format("vehicles[{}].delta_v_magnitude", vehicle);
  std::size_t c = 0;
  while (c < outputs.size() && outputs[c].text != path) ++c;
  const auto& r = run.results[k];
  if (c == outputs.size() || !r.written[c] || !std::isfinite(r.values[c])) return {};
  std::vector<std::pair<double, std::size_t>> bars;
  for (std::size_t j = 0; j < run.inputs.size(); ++j) {
    const double e = io::elasticity(run.derivative(k, c, j), run.input_values[j], r.values[c]);
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
      gnuplot_string(fmt::format("{} ({}): vehicle {} delta-V {:.4g}", io::strategy_label(r.strategy), r.regime, vehicle + 1,
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
  io::SensitivityOptions so;
  so.engine = o.engine;
  if (o.strategies.size() > io::limits::kStrategies)
    throw io::CaseError("--strategy", fmt::format("more than {} strategies", io::limits::kStrategies));
  for (std::size_t i = 0; i < o.strategies.size(); ++i)
    so.strategies.push_back(io::read_strategy_option(o.strategies[i], static_cast<int>(i)));
  if (!o.plot_dir.empty()) require_gnuplot();
  const io::SensitivityRun run = io::sensitivity(io::read_text_file(o.case_path), so);
  if (!o.plot_dir.empty()) {
    const OutputDir dir(o.plot_dir);
    for (std::size_t k = 0; k < run.results.size(); ++k)
      for (int v = 0; v < 2; ++v) (void)tornado(run, k, v, dir, o.png);
  }
  const std::string out = o.format == "json" ? io::sensitivity_json(run) : io::sensitivity_text(run);
  std::fwrite(out.data(), 1, out.size(), stdout);
  return 0;
}

}  // namespace impact3d::cli
