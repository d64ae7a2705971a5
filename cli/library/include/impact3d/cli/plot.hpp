// impact3d plot: the paper's impulse-space figures (contact-plane view as Figures 3-4 right, solution
// plane as Figures 4 right and 7, impulse-space perspective as Figures 2-3 left) and sweeps over mu and
// eps, for any case, from the same computation as `solve`, drawn by gnuplot.
#pragma once

#include <optional>
#include <string>

#include "impact3d/case_format/case_spec.hpp"
#include "impact3d/mechanics/problem.hpp"
#include "impact3d/mechanics/units.hpp"

namespace impact3d::cli {

struct PlotOptions {
  std::string out_dir;
  bool png = false;
  Engine engine = Engine::generated;
  std::optional<Units> units;  // the units drawn; empty: the case's
};

// Writes, per figure, NAME.gp (the script), NAME*.dat (the data drawn), NAME.points.csv (the solution
// points drawn) and NAME.svg (or .png). Returns the names written, one line each. Throws
// std::runtime_error when gnuplot is missing or fails.
std::string plot(const case_format::CaseSpec& spec, const PlotOptions& o);

}  // namespace impact3d::cli
