#include "impact3d/cli/reconstruct_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <fmt/format.h>

#include "impact3d/cli/gnuplot.hpp"
#include "impact3d/studies/montecarlo.hpp"
#include "impact3d/case_format/present.hpp"
#include "impact3d/case_format/strategy_kinds.hpp"

namespace impact3d::cli {

namespace {

constexpr int kGrid = 41;           // points a side of the chi2 surface
constexpr double kGridSds = 4;      // its half-width, in standard errors of each unknown
// chi2 above its minimum at the joint 68.3 %, 95.4 % and 99.73 % regions of two unknowns (the
// chi-squared quantiles of 2 degrees of freedom, -2 ln(1 - p)).
constexpr double kLevels[] = {2.2957489288986, 6.1800743062369, 11.829158081900795};

// Vehicle i's post-impact velocity evidence in the plan: its x and y values and sd, when both are given.
struct PlanEvidence {
  bool given = false;
  double x = 0, y = 0, sd_x = 0, sd_y = 0;
};

PlanEvidence plan_evidence(const case_format::EvidenceSpec& e, int vehicle) {
  PlanEvidence p;
  bool has[2] = {false, false};
  const auto& outputs = case_format::monte_carlo_outputs();
  for (const auto& item : e.evidence) {
    if (item.kind != case_format::EvidenceItem::Kind::output) continue;
    for (std::size_t c = 0; c < item.outputs.size(); ++c)
      for (int k = 0; k < 2; ++k)
        if (outputs[item.outputs[c]].text == fmt::format("vehicles[{}].velocity[{}]", vehicle, k)) {
          (k == 0 ? p.x : p.y) = item.value[c];
          (k == 0 ? p.sd_x : p.sd_y) = item.sd[c];
          has[k] = true;
        }
  }
  p.given = has[0] && has[1];
  return p;
}

std::string plan_view(const ReconstructFigures& f, const OutputDir& dir, bool png, std::string& warnings) {
  const studies::FitStates s = studies::fit_states(f.case_text, f.evidence, f.options, f.reconstruction.best);
  // Arrows are the distance covered in `T` seconds: the longest as long as twice the farthest CG from
  // the impulse centre, and at least 3 length units.
  double reach = 0, speed = 0;
  for (int i = 0; i < 2; ++i) {
    reach = std::max(reach, std::hypot(s.cg[i][0], s.cg[i][1]));
    speed = std::max({speed, std::hypot(s.before[i][0], s.before[i][1]), std::hypot(s.after[i][0], s.after[i][1])});
  }
  const double T = speed > 0 ? std::max(2 * reach, 3.0) / speed : 1.0;
  std::string arrows, cgs, evidence;
  for (int i = 0; i < 2; ++i) {
    const auto& cg = s.cg[i];
    cgs += fmt::format("{} {} {}\n", cg[0], cg[1], i + 1);
    arrows += fmt::format("{} {} {} {} 1\n", cg[0] - T * s.before[i][0], cg[1] - T * s.before[i][1], T * s.before[i][0], T * s.before[i][1]);
    arrows += fmt::format("{} {} {} {} 2\n", cg[0], cg[1], T * s.after[i][0], T * s.after[i][1]);
    const PlanEvidence p = plan_evidence(f.evidence, i);
    if (p.given) evidence += fmt::format("{} {} {} {}\n", cg[0] + T * p.x, cg[1] + T * p.y, 2 * T * p.sd_x, 2 * T * p.sd_y);
  }
  dir.write("rec_plan_arrows.dat", arrows);
  dir.write("rec_plan_cg.dat", cgs);
  dir.write("rec_plan_evidence.dat", evidence.empty() ? "NaN NaN NaN NaN\n" : evidence);
  const Units u = f.reconstruction.units;
  std::string script = gnuplot_terminal(png, 800, 700);
  script += fmt::format("set title {} noenhanced\nset xlabel {} noenhanced\nset ylabel {} noenhanced\n",
                        gnuplot_string(fmt::format("plan view ({}, regime {}): velocities as the distance covered in {:.3g} s",
                                                   case_format::strategy_label(f.reconstruction.strategy), f.reconstruction.best.regime, T)),
                        gnuplot_string(fmt::format("world x ({}), the impulse centre at 0", case_format::unit_label(u, "length"))),
                        gnuplot_string(fmt::format("world y ({})", case_format::unit_label(u, "length"))));
  script +=
      "set size ratio -1\nset grid\nset key outside below noenhanced\n"
      "plot 'rec_plan_arrows.dat' using 1:($5 == 1 ? $2 : NaN):3:4 with vectors dt 2 lw 2 lc rgb '#606060' "
      "title 'reconstructed pre-impact velocity', \\\n"
      "     'rec_plan_arrows.dat' using 1:($5 == 2 ? $2 : NaN):3:4 with vectors lw 2 lc rgb '#3060a0' "
      "title 'fitted post-impact velocity', \\\n"
      "     'rec_plan_evidence.dat' using 1:2:3:4 with ellipses lw 1.5 lc rgb '#c06020' title 'evidence: post-impact velocity, 1 sd', \\\n"
      "     'rec_plan_evidence.dat' using 1:2 with points pt 7 ps 0.8 lc rgb '#c06020' notitle, \\\n"
      "     'rec_plan_cg.dat' using 1:2 with points pt 6 ps 1.5 lc rgb 'black' title 'CG (vehicle number)', \\\n"
      "     'rec_plan_cg.dat' using 1:2:3 with labels offset 1.2,1.2 notitle, \\\n"
      "     '+' using (0):(0) every ::0::0 with points pt 2 ps 2 lc rgb 'black' title 'impulse centre'\n";
  return draw_figure(dir, "rec_plan", script, png, warnings);
}

std::string chi2_surface(const ReconstructFigures& f, const OutputDir& dir, bool png, std::string& warnings) {
  const studies::Fit& fit = f.reconstruction.best;
  if (fit.value.size() < 2) return {};
  for (std::size_t j = 0; j < 2; ++j)
    if (!std::isfinite(fit.value[j]) || !(fit.sd[j] > 0)) return {};
  std::vector<double> axis[2];
  for (std::size_t j = 0; j < 2; ++j)
    for (int k = 0; k < kGrid; ++k) axis[j].push_back(fit.value[j] + fit.sd[j] * kGridSds * (2.0 * k / (kGrid - 1) - 1));
  const std::vector<double> chi2 = studies::chi2_grid(f.case_text, f.evidence, f.options, fit, 0, 1, axis[0], axis[1]);
  std::string data;
  for (int r = 0; r < kGrid; ++r) {
    for (int c = 0; c < kGrid; ++c) {
      const double z = chi2[static_cast<std::size_t>(r * kGrid + c)];
      data += fmt::format("{} {} {}\n", axis[0][static_cast<std::size_t>(c)], axis[1][static_cast<std::size_t>(r)],
                          std::isfinite(z) ? fmt::format("{}", z) : std::string("NaN"));
    }
    data += '\n';
  }
  dir.write("rec_chi2.dat", data);
  dir.write("rec_chi2_fit.dat", fmt::format("{} {} {}\n", fit.value[0], fit.value[1], fit.chi2));
  const auto& unknowns = f.reconstruction.unknowns;
  std::string script = gnuplot_terminal(png, 800, 700);
  script += fmt::format(
      "set title {} noenhanced\nset xlabel {} noenhanced\nset ylabel {} noenhanced\nset cblabel 'chi2'\n",
      // With more unknowns the surface is a slice through the fit: its regions are conditional on the
      // others, narrower than the joint ones of the two.
      gnuplot_string(unknowns.size() == 2
                         ? fmt::format("chi2 over {} and {}; contours: their joint 68.3, 95.4, 99.73 % regions", unknowns[0].label(),
                                       unknowns[1].label())
                         : fmt::format("chi2 over {} and {}, the others at the fit; contours: 68.3, 95.4, 99.73 % regions "
                                       "conditional on the others",
                                       unknowns[0].label(), unknowns[1].label())),
      gnuplot_string(unknowns[0].label()), gnuplot_string(unknowns[1].label()));
  script += fmt::format(
      "set view map\nset pm3d at b\nset palette rgbformulae 33,13,10\nset contour base\nset autoscale fix\n"
      "set cntrparam levels discrete {},{},{}\nunset clabel\nset bmargin 7\n"
      "set key at screen 0.5, 0.04 center horizontal noenhanced\n"
      "splot 'rec_chi2.dat' using 1:2:3 with pm3d nocontours notitle, \\\n"
      "      'rec_chi2.dat' using 1:2:3 nosurface with lines lc rgb 'black' title 'chi2 - chi2_min = 2.30, 6.18, 11.8', \\\n"
      "      'rec_chi2_fit.dat' using 1:2:3 nocontours with points pt 2 ps 2 lc rgb 'black' title 'estimate'\n",
      fit.chi2 + kLevels[0], fit.chi2 + kLevels[1], fit.chi2 + kLevels[2]);
  return draw_figure(dir, "rec_chi2", script, png, warnings);
}

}  // namespace

std::string reconstruct_figures(const ReconstructFigures& f, const OutputDir& dir, bool png) {
  std::string warnings;
  std::string written = plan_view(f, dir, png, warnings);
  written += chi2_surface(f, dir, png, warnings);
  std::fputs(warnings.c_str(), stderr);
  return written;
}

}  // namespace impact3d::cli
