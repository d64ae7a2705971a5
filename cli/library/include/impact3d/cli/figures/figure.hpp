// What every impulse-space figure shares: the case and its analysis, the output directory, the script's
// head (terminal, title, key), the data blocks drawn as lines or shaded polygons, and the points drawn
// from the file that lists them, coincident ones told apart.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "impact3d/cli/gnuplot.hpp"
#include "impact3d/cli/plot.hpp"
#include "impact3d/case_format/present.hpp"
#include "impact3d/mechanics/analysis.hpp"
#include "impact3d/cli/figures/style.hpp"

namespace impact3d::cli {

struct FigureContext {
  const case_format::CaseSpec& spec;
  const PlotOptions& o;
  const OutputDir& dir;
  const Scene<double>& scene;  // SI
  const Analysis<double>& a;
  const Problem<double>& p;
  const Figures<double>& fig;  // the geometry drawn, from the analysis (impulse_space.hpp)
  Units units;                 // drawn in; the case's own unless asked otherwise
  UnitFactors<double> f;       // of `units`
  std::string imp_unit, vel_unit, energy_unit;
  std::string written, warnings;

  void draw(const std::string& name, const std::string& script) { written += draw_figure(dir, name, script, o.png, warnings); }
};

// Terminal, title (the case's name, the figure's, then one line per further line given), grid and a key
// beside the plot, one entry a line: below it, gnuplot lays wide entries out in columns that can fall
// off the page.
// The title's lines as one gnuplot string expression: the case's name, `title`, then `more`.
std::string title_lines(const FigureContext& c, const std::string& title, const std::vector<std::string>& more = {});

inline constexpr const char* kKeyBeside = "set key outside right top vertical Left reverse noenhanced\n";
std::string figure_head(const FigureContext& c, const std::string& title, int w, int h,
                        const std::vector<std::string>& more = {}, const char* key = kKeyBeside);

// A tick step of 1, 2 or 5 times a power of ten giving about `count` ticks over [lo, hi].
double tick_step(double lo, double hi, int count = 5);

// A range [lo, hi] widened where it is empty, so that gnuplot draws a degenerate figure (a head-on
// collision has no contact-plane impulse) instead of refusing it.
std::pair<double, double> nonempty(double lo, double hi, double scale);

// Two far points of the line a x + b y = r, for drawing (the plot's range clips them); empty for no line.
std::string line_segment(double a, double b, double r, double extent);

// A data set of a figure: lines, or a shaded semi-transparent polygon (a block of vertices) of `colour`.
struct Series {
  std::string style, title, data;
  const char* colour = nullptr;  // set: a polygon
};

// Writes the sets to FILE.dat as gnuplot blocks and returns `verb` drawing each with its style and title.
// A set with no data (a degenerate line) is left out, so that gnuplot is never handed an empty block.
std::string series(const FigureContext& c, const std::string& verb, const std::string& file, const std::vector<Series>& list);

struct Point {
  std::string label;
  Marker marker;
  double x, y, z = 0;
};

// The ranges drawn, to tell on the page whether two points coincide.
struct Frame {
  double x0, x1, y0, y1, z0 = 0, z1 = 1;
};

// The points of a figure: written to NAME.points.csv and drawn from it one plot item each, so that the
// picture shows exactly the numbers in the file. A point within 1.2 % of the frame of earlier ones is
// drawn larger, around them, and its key entry names the first of them: "(= Full Impact)". `columns`
// draws other columns of the file than all of them (2:3 or 2:3:4): one panel of points that coincide in
// three dimensions.
std::string points_items(const FigureContext& c, const std::string& name, const std::string& header, const std::vector<Point>& pts,
                         bool three_d, const Frame& frame, const char* columns = nullptr);

}  // namespace impact3d::cli
