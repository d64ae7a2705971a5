// The sliding after the impact (along and across the initial sliding), the swerve angle and the energy
// loss against the friction ratio and against restitution. Strategies that differ only in the ratio
// swept share one mu sweep; each is marked at its own ratio, with GIR and CIR, by vertical lines.
#include <algorithm>
#include <cmath>
#include <map>

#include <fmt/format.h>

#include "impact3d/cli/figures/figure.hpp"
#include "impact3d/case_format/strategy_kinds.hpp"
#include "impact3d/case_format/to_scene.hpp"
#include "impact3d/cli/figures/views.hpp"

namespace impact3d::cli {
namespace {

struct Mark {
  std::string label;
  double x;
  const char* colour;
  const char* dash;
};

constexpr int kPanels = 4;

// One sweep figure: `x` from 0 to `top`, the case solved by `solve_at` at each; the marks drawn as
// vertical lines and listed, with their values, in NAME.marks.csv.
template <typename SolveAt>
void sweep(FigureContext& c, const std::string& name, const std::string& what, const std::string& xlabel, double top, int n,
           const std::vector<Mark>& marks, SolveAt solve_at) {
  const double fv = c.f.velocity, fe = c.f.energy;
  std::string csv = xlabel + ",sliding_along_after,sliding_across_after,swerve_deg,energy_loss\n";
  double lo[kPanels], hi[kPanels];
  std::fill(lo, lo + kPanels, INFINITY);
  std::fill(hi, hi + kPanels, -INFINITY);
  for (int i = 0; i <= n; ++i) {
    const double x = top * i / n;
    std::optional<Solution<double>> sol;
    try {
      sol = solve_at(x);
    } catch (const SolveError&) {
    }
    if (!sol) {
      csv += "\n";  // no impulse at this value: a gap in the curves
      continue;
    }
    // The report's rule: a velocity within its rounding bound is zero, not noise to draw.
    const auto velocity = [&](const std::optional<double>& v) -> double {
      if (!v) return NAN;
      return std::fabs(*v) <= sol->velocity_roundoff ? 0.0 : *v / fv;
    };
    const double y[kPanels] = {velocity(sol->sliding_along), velocity(sol->swerve_speed), sol->swerve_deg ? *sol->swerve_deg : NAN,
                               sol->energy_loss / fe};
    for (int q = 0; q < kPanels; ++q)
      if (std::isfinite(y[q])) lo[q] = std::min(lo[q], y[q]), hi[q] = std::max(hi[q], y[q]);
    const auto cell = [](double v) { return std::isfinite(v) ? fmt::format("{:.17g}", v) : std::string("NaN"); };
    csv += fmt::format("{:.17g},{},{},{},{}\n", x, cell(y[0]), cell(y[1]), cell(y[2]), cell(y[3]));
  }
  c.dir.write(name + ".csv", csv);
  std::string marks_csv = "label,value\n";
  for (const auto& m : marks) marks_csv += fmt::format("{},{:.17g}\n", m.label, m.x);
  c.dir.write(name + ".marks.csv", marks_csv);

  std::string gp = figure_head(c, what, 1000, 800);
  gp += fmt::format("set key off\nunset title\nset multiplot layout 2,2 title {}.\"\\n\".{} noenhanced\n", gnuplot_string(c.spec.name),
                    gnuplot_string(what));
  gp += fmt::format("set xrange [0:{:.17g}]\n", top);
  // Each mark's name along its line, at the top and the bottom in turn from left to right, so that
  // names of close marks do not run together.
  std::vector<std::size_t> by_x(marks.size());
  for (std::size_t i = 0; i < marks.size(); ++i) by_x[i] = i;
  std::stable_sort(by_x.begin(), by_x.end(), [&](std::size_t a, std::size_t b) { return marks[a].x < marks[b].x; });
  for (std::size_t r = 0; r < by_x.size(); ++r) {
    const Mark& m = marks[by_x[r]];
    const int tag = static_cast<int>(r) + 1;
    gp += fmt::format("set arrow {0} from {1:.17g}, graph 0 to {1:.17g}, graph 1 nohead lw 1.5 {2} lc rgb '{3}'\n", tag, m.x, m.dash, m.colour);
    gp += fmt::format("set label {} {} at {:.17g}, graph {} rotate by 90 {} offset -0.6,0 font ',9' tc rgb '{}' noenhanced\n", tag,
                      gnuplot_string(m.label), m.x, r % 2 ? "0.03" : "0.97", r % 2 ? "left" : "right", m.colour);
  }
  const char* titles[] = {"sliding after, along the initial sliding", "sliding after, across it",
                          "swerve off the sliding line", "energy loss"};
  const std::string units[] = {c.vel_unit, c.vel_unit, "deg", c.energy_unit};
  for (int q = 0; q < kPanels; ++q) {
    if (!(lo[q] <= hi[q])) {  // nothing finite to draw (no sliding after the impact: swerve undefined)
      gp += fmt::format("set title {}\nunset xlabel\nunset ylabel\nset label 99 {} at graph 0.5, 0.5 center\nset yrange [0:1]\n"
                        "unset xtics\nunset ytics\nplot 2 notitle\nunset label 99\nset xtics\nset ytics\n",
                        gnuplot_string(titles[q]),
                        gnuplot_string(q >= 1 && q <= 2 ? "no sliding to compare with, before or after" : "no value to draw"));
      continue;
    }
    const auto [y0, y1] = nonempty(lo[q], hi[q], 0);
    const double pad = 0.05 * (y1 - y0);
    gp += fmt::format("set title {}\nset xlabel {} noenhanced\nset ylabel {}\nset yrange [{:.17g}:{:.17g}]\n"
                      "plot '{}.csv' using 1:{} skip 1 with linespoints pt 7 ps 0.4 lc rgb '#333333'\n",
                      gnuplot_string(titles[q]), gnuplot_string(xlabel), gnuplot_string("[" + units[q] + "]"), y0 - pad, y1 + pad, name,
                      q + 2);
  }
  gp += "unset multiplot\n";
  c.draw(name, gp);
}

// The strategy with its friction key (strategy_kinds.hpp) set to x, written as a decimal.
case_format::StrategySpec with_ratio(const case_format::StrategySpec& spec, double x) {
  case_format::StrategySpec swept = spec;
  swept.numbers[std::string(case_format::strategy_kind(spec.kind).sweep_key)] = case_format::Number{fmt::format("{:.17g}", x), x};
  return swept;
}

}  // namespace

void sweeps(FigureContext& c) {
  const auto& strategies = c.spec.strategies;
  // Strategies alike but for the swept ratio: one mu sweep, named after the first of them.
  std::map<std::string, std::vector<std::size_t>> alike;
  std::vector<std::string> order;
  for (std::size_t k = 0; k < strategies.size(); ++k) {
    const std::string key = case_format::strategy_label(with_ratio(strategies[k], 0));
    if (!alike.count(key)) order.push_back(key);
    alike[key].push_back(k);
  }
  const double gir = c.fig.contact.gir;
  const bool by_gir = gir > 0 && std::isfinite(gir);  // no contact-plane impulse: GIR = 0, sweep [0, 1]
  for (const auto& key : order) {
    const auto& group = alike[key];
    const std::size_t first = group.front();
    const case_format::StrategySpec& spec = strategies[first];
    const std::string ratio_key(case_format::strategy_kind(spec.kind).sweep_key);
    std::vector<Mark> marks;
    double top = by_gir ? 1.5 * gir : 1.0;
    for (const std::size_t k : group) {
      if (const auto& mu = strategies[k].number(ratio_key)) {
        marks.push_back({fmt::format("{}={}", ratio_key, mu->text), mu->value, strategy_marker(k).colour, "dt 1"});
        continue;
      }
      // "critical": the ratio the solution found.
      const auto& used = c.a.solutions[k].impulse;
      const std::optional<double> x = ratio_key == "mu_t" ? used.mu_t : ratio_key == "mu_z" ? used.mu_z : used.mu;
      if (x) marks.push_back({fmt::format("{} critical={:.6g}", ratio_key, *x), *x, strategy_marker(k).colour, "dt 1"});
    }
    const auto& imp = c.a.solutions[first].impulse;
    if (imp.gir) marks.push_back({fmt::format("GIR={:.6g}", *imp.gir), *imp.gir, colour::gir, "dt 4"});
    if (imp.cir) marks.push_back({fmt::format("CIR={:.6g}", *imp.cir), *imp.cir, colour::cir, "dt 3"});
    for (const auto& m : marks)
      if (std::isfinite(m.x)) top = std::max(top, 1.15 * m.x);
    std::string names;
    for (const std::size_t k : group) names += (names.empty() ? "" : ", ") + case_format::strategy_label(strategies[k]);
    const std::string span = by_gir ? "0 to 1.5 GIR" : "0 to 1, GIR = 0";
    sweep(c, fmt::format("sweep_mu_{}", first + 1), fmt::format("{} against {} ({}, or past the marks)", names, ratio_key, span),
          ratio_key, top, 60, marks, [&](double x) {
            return analyze(c.scene, {case_format::to_strategy<double>(with_ratio(spec, x))}, c.o.engine).solutions.at(0);
          });
  }
  for (std::size_t k = 0; k < strategies.size(); ++k) {
    const Strategy<double> as_given = case_format::to_strategy<double>(strategies[k]);
    const std::vector<Mark> marks{{"eps=" + c.spec.restitution.text, c.scene.restitution, strategy_marker(k).colour, "dt 1"}};
    sweep(c, fmt::format("sweep_eps_{}", k + 1), case_format::strategy_label(strategies[k]) + " against restitution eps (0 to 1)",
          "restitution eps", 1.0, 40, marks, [&](double x) {
            Scene<double> sc = c.scene;
            sc.restitution = x;
            return analyze(sc, {as_given}, c.o.engine).solutions.at(0);
          });
  }
}

}  // namespace impact3d::cli
