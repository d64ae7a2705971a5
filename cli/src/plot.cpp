#include "plot.hpp"

#include <cstdio>

#include "figures/views.hpp"
#include "gnuplot.hpp"
#include "impact3d/io/read_case.hpp"
#include "impact3d/io/to_scene.hpp"

namespace impact3d::cli {

std::string plot(const io::CaseSpec& spec, const PlotOptions& o) {
  require_gnuplot();
  const Scene<double> scene = io::to_scene<double>(spec);
  const Analysis<double> a = analyze(scene, io::to_strategies<double>(spec), o.engine);
  const OutputDir dir(o.out_dir);
  const Figures<double> fig = figures(a);
  const Units u = o.units.value_or(spec.units);
  FigureContext c{spec, o, dir, scene, a, a.problem(), fig, u, unit_factors<double>(u),
                  io::unit_label(u, "impulse"), io::unit_label(u, "velocity"), io::unit_label(u, "energy"), "", ""};
  contact_plane_view(c);
  for (std::size_t k = 0; k < a.solutions.size(); ++k) solution_plane_view(c, k);
  impulse_space_view(c);
  sweeps(c);
  for (std::size_t k = 0; k < a.solutions.size(); ++k) collision_view(c, k);
  std::fputs(c.warnings.c_str(), stderr);
  return c.written;
}

}  // namespace impact3d::cli
