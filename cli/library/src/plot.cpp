#include "impact3d/cli/plot.hpp"

#include <cstdio>

#include "impact3d/cli/figures/views.hpp"
#include "impact3d/cli/gnuplot.hpp"
#include "impact3d/case_format/read_case.hpp"
#include "impact3d/case_format/to_scene.hpp"

namespace impact3d::cli {

std::string plot(const case_format::CaseSpec& spec, const PlotOptions& o) {
  require_gnuplot();
  const Scene<double> scene = case_format::to_scene<double>(spec);
  const Analysis<double> a = analyze(scene, case_format::to_strategies<double>(spec), o.engine);
  const OutputDir dir(o.out_dir);
  const Figures<double> fig = figures(a);
  const Units u = o.units.value_or(spec.units);
  FigureContext c{spec, o, dir, scene, a, a.problem(), fig, u, unit_factors<double>(u),
                  case_format::unit_label(u, "impulse"), case_format::unit_label(u, "velocity"), case_format::unit_label(u, "energy"), "", ""};
  contact_plane_view(c);
  for (std::size_t k = 0; k < a.solutions.size(); ++k) solution_plane_view(c, k);
  impulse_space_view(c);
  sweeps(c);
  for (std::size_t k = 0; k < a.solutions.size(); ++k) collision_view(c, k);
  for (std::size_t k = 0; k < a.solutions.size(); ++k) stronge_views(c, k);
  std::fputs(c.warnings.c_str(), stderr);
  return c.written;
}

}  // namespace impact3d::cli
