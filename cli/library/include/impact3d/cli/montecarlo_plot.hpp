// The figures of a Monte Carlo run (`montecarlo --plot DIR`), drawn by gnuplot from the run's kept
// samples: per strategy, histograms of each vehicle's ΔV and PDOF and of the energy loss with the
// 2.5, 50 and 97.5 percentiles marked; a scatter of two chosen outputs; ΔV of both vehicles against
// each uncertain input.
#pragma once

#include <string>

#include "impact3d/studies/montecarlo.hpp"

namespace impact3d::cli {

struct MonteCarloPlotOptions {
  std::string out_dir;
  bool png = false;
  std::string scatter_x = "vehicles[0].delta_v_magnitude", scatter_y = "vehicles[1].delta_v_magnitude";
};

// Before the run: the scatter's outputs exist (case_format::CaseError at "--scatter") and gnuplot can be started.
void check_plot_options(const MonteCarloPlotOptions& o);

// Writes NAME.gp, NAME.dat and NAME.svg (or .png) per figure into out_dir, for a run with kept samples;
// returns the images' names, one a line.
std::string montecarlo_plot(const studies::MonteCarloRun& run, const MonteCarloPlotOptions& o);

}  // namespace impact3d::cli
