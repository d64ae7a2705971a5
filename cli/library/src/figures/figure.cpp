#include "impact3d/cli/figures/figure.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace impact3d::cli {

namespace {
constexpr double kCoincident = 0.012;  // of the frame: markers of size 2 overlap closer than this
constexpr double kMarkerSize = 1.6, kMarkerGrowth = 0.9;
constexpr double kSvgMarkerScale = 0.7;  // gnuplot's SVG points are larger than cairo's at one size
}  // namespace

std::string title_lines(const FigureContext& c, const std::string& title, const std::vector<std::string>& more) {
  std::string lines = gnuplot_string(c.spec.name) + ".\"\\n\"." + gnuplot_string(title);
  for (const auto& line : more) lines += ".\"\\n\"." + gnuplot_string(line);
  return lines;
}

std::string figure_head(const FigureContext& c, const std::string& title, int w, int h, const std::vector<std::string>& more,
                        const char* key) {
  const std::string lines = title_lines(c, title, more);
  // clip two: a line whose two ends lie beyond the range is still drawn where it crosses it.
  return gnuplot_terminal(c.o.png, w, h) +
         "set datafile separator comma\nset grid\nset clip two\n" + key +
         fmt::format("set title {} noenhanced\n", lines);
}

double tick_step(double lo, double hi, int count) {
  const double raw = (hi - lo) / count;
  if (!(raw > 0) || !std::isfinite(raw)) return 1;
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0})
    if (m * decade >= raw) return m * decade;
  return 10 * decade;
}

std::pair<double, double> nonempty(double lo, double hi, double scale) {
  constexpr double kFlatRange = 1e-9;  // a drawing heuristic, not a rounding bound
  if (hi - lo > kFlatRange * std::max({std::fabs(lo), std::fabs(hi), scale})) return {lo, hi};
  const double half = scale > 0 ? 0.5 * scale : std::max(1.0, 0.5 * std::fabs(lo));
  return {lo - half, hi + half};
}

std::string line_segment(double a, double b, double r, double extent) {
  const double n2 = a * a + b * b;
  if (n2 == 0) return "";
  const double x0 = r * a / n2, y0 = r * b / n2, len = std::sqrt(n2);
  const double dx = -b / len * extent, dy = a / len * extent;
  return fmt::format("{:.17g},{:.17g}\n{:.17g},{:.17g}\n", x0 - dx, y0 - dy, x0 + dx, y0 + dy);
}

std::string series(const FigureContext& c, const std::string& verb, const std::string& file, const std::vector<Series>& list) {
  std::string dat, out = verb + " ";
  int index = 0;
  for (const auto& item : list) {
    std::string block = item.data;
    while (!block.empty() && block.back() == '\n') block.pop_back();
    if (block.empty()) continue;
    dat += block + "\n\n\n";  // a line end, then the two blank lines that end a gnuplot data block
    out += index ? ", \\\n      " : "";
    if (item.colour)  // gnuplot draws no key sample for polygons: a box of their colour stands in
      out += fmt::format("'{0}.dat' index {1} with polygons {2} notitle, \\\n      keyentry with boxes lc rgb '{3}' fs solid 0.4 title {4}",
                         file, index, item.style, item.colour, gnuplot_string(item.title));
    else
      out += fmt::format("'{}.dat' index {} with lines {} title {}", file, index, item.style, gnuplot_string(item.title));
    ++index;
  }
  c.dir.write(file + ".dat", dat);
  return out;
}

std::string points_items(const FigureContext& c, const std::string& name, const std::string& header, const std::vector<Point>& pts,
                         bool three_d, const Frame& frame, const char* columns) {
  std::string csv = header + "\n";
  for (const auto& q : pts)
    csv += three_d ? fmt::format("{},{:.17g},{:.17g},{:.17g}\n", q.label, q.x, q.y, q.z)
                   : fmt::format("{},{:.17g},{:.17g}\n", q.label, q.x, q.y);
  c.dir.write(name + ".points.csv", csv);
  const auto span = [](double lo, double hi) { return hi > lo ? hi - lo : 1.0; };
  const double sx = span(frame.x0, frame.x1), sy = span(frame.y0, frame.y1), sz = span(frame.z0, frame.z1);
  std::string items;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    int under = 0;
    std::string first;
    for (std::size_t j = 0; j < i; ++j) {
      const double d = std::hypot((pts[i].x - pts[j].x) / sx, (pts[i].y - pts[j].y) / sy, three_d ? (pts[i].z - pts[j].z) / sz : 0.0);
      if (d <= kCoincident) {
        if (!under++) first = pts[j].label;
      }
    }
    const std::string title = under ? fmt::format("{} (= {})", pts[i].label, first) : pts[i].label;
    items += fmt::format(", \\\n     '{}.points.csv' every ::{}::{} using {} with points {} title {} noenhanced", name, i + 1, i + 1,
                         columns ? columns : three_d ? "2:3:4" : "2:3", pts[i].marker.style((kMarkerSize + kMarkerGrowth * under) * (c.o.png ? 1 : kSvgMarkerScale)), gnuplot_string(title));
  }
  return items;
}

}  // namespace impact3d::cli
