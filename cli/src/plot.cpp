#include "plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <fmt/format.h>

#include "gnuplot.hpp"
#include "impact3d/io/escape.hpp"
#include "impact3d/io/read_case.hpp"

namespace impact3d::cli {
namespace {

using V3 = Vec3<double>;

// Drawing heuristics, not rounding bounds (those are rounding.hpp's): a plot range narrower than this
// fraction of its values is drawn widened, and a plane normal within this of the x axis takes the y axis
// to span its drawn patch.
constexpr double kFlatRange = 1e-9;
constexpr double kNearlyParallel = 1e-6;

struct Context {
  const io::CaseSpec& spec;
  const PlotOptions& o;
  const OutputDir& dir;
  const Scene<double>& scene;  // SI
  const Analysis<double>& a;
  const Problem<double>& p;
  const Figures<double>& fig;  // the geometry drawn, from the analysis (impulse_space.hpp)
  UnitFactors<double> f;
  std::string imp_unit, vel_unit, energy_unit;
  std::string written, warnings;
};

// The image goes to gnuplot's standard output, which run_gnuplot points at a file it created itself.
std::string terminal(const Context& c, int w = 800, int h = 600) {
  return fmt::format("set terminal {} size {},{}\n", c.o.png ? "png" : "svg enhanced", w, h);
}

void draw(Context& c, const std::string& name, const std::string& script) {
  c.dir.write(name + ".gp", script);
  const std::string image = name + (c.o.png ? ".png" : ".svg");
  const std::string messages = run_gnuplot(c.dir, name + ".gp", image);
  if (!messages.empty()) c.warnings += fmt::format("impact3d: warning: gnuplot on {}.gp: {}\n", name, messages);
  c.written += image + "\n";
}

// A range [lo, hi] widened where it is empty, so that gnuplot draws a degenerate figure (a head-on
// collision has no contact-plane impulse) instead of refusing it.
std::pair<double, double> nonempty(double lo, double hi, double scale) {
  if (hi - lo > kFlatRange * std::max({std::fabs(lo), std::fabs(hi), scale})) return {lo, hi};
  const double half = scale > 0 ? 0.5 * scale : std::max(1.0, 0.5 * std::fabs(lo));
  return {lo - half, hi + half};
}

// Two far points of the line a x + b y = r, for drawing (the plot's range clips them).
std::string line_segment(double a, double b, double r, double extent) {
  const double n2 = a * a + b * b;
  if (n2 == 0) return "";  // no line: the series is left out
  const double x0 = r * a / n2, y0 = r * b / n2, len = std::sqrt(n2);
  const double dx = -b / len * extent, dy = a / len * extent;
  return fmt::format("{:.17g},{:.17g}\n{:.17g},{:.17g}\n", x0 - dx, y0 - dy, x0 + dx, y0 + dy);
}

struct Point {
  std::string label;
  double x, y, z = 0;
};

// The solution points of a figure: written to NAME.points.csv, and drawn from it one plot item each,
// so that the picture shows exactly the numbers in the file.
std::string points_file(const OutputDir& dir, const std::string& name, const std::string& header, const std::vector<Point>& pts,
                        bool three_d) {
  std::string csv = header + "\n";
  for (const auto& q : pts)
    csv += three_d ? fmt::format("{},{:.17g},{:.17g},{:.17g}\n", q.label, q.x, q.y, q.z)
                   : fmt::format("{},{:.17g},{:.17g}\n", q.label, q.x, q.y);
  dir.write(name + ".points.csv", csv);
  std::string items;
  for (std::size_t i = 0; i < pts.size(); ++i)
    items += fmt::format(", \\\n     '{}.points.csv' every ::{}::{} using {} with points pt {} ps 2 lw 2 title {} noenhanced", name, i + 1,
                         i + 1, three_d ? "2:3:4" : "2:3", 4 + static_cast<int>(i), gnuplot_string(pts[i].label));
  return items;
}

// The title: the case's name, the figure's title, then one line per further line given (warnings).
std::string header_lines(const Context& c, const std::string& title, int w = 900, int h = 700,
                         const std::vector<std::string>& more = {}) {
  std::string lines = gnuplot_string(c.spec.name) + ".\"\\n\"." + gnuplot_string(title);
  for (const auto& line : more) lines += ".\"\\n\"." + gnuplot_string(line);
  // clip two: a line whose two ends lie beyond the range is still drawn where it crosses it.
  return terminal(c, w, h) + "set datafile separator comma\nset grid\nset clip two\nset key below noenhanced\n" +
         fmt::format("set title {} noenhanced\n", lines);
}

std::string label(const io::StrategySpec& s) { return io::strategy_label(s); }

// The data sets of a figure, written to FILE.dat as gnuplot blocks, and the `plot` (or `splot`) command
// drawing each with its line style and title. A set with no data (a degenerate line) is left out, so
// that gnuplot is never handed an empty block.
struct Series {
  std::string style, title, data;
};
std::string series(const Context& c, const std::string& verb, const std::string& file, const std::vector<Series>& list) {
  std::string dat, out = verb + " ";
  int index = 0;
  for (const auto& item : list) {
    std::string block = item.data;
    while (!block.empty() && block.back() == '\n') block.pop_back();
    if (block.empty()) continue;
    dat += block + "\n\n\n";  // a line end, then the two blank lines that end a gnuplot data block
    out += fmt::format("{}'{}.dat' index {} with lines {} title {}", index ? ", \\\n      " : "", file, index, item.style,
                       gnuplot_string(item.title));
    ++index;
  }
  c.dir.write(file + ".dat", dat);
  return out;
}

std::string trace(const Line2<double>& l, double scale, double extent) { return line_segment(l.a, l.b, l.r / scale, extent); }

void contact_plane_view(Context& c) {
  const auto& f = c.fig.contact;
  const double s = c.f.impulse;
  const V3& fi = f.full_impact;
  std::vector<Point> pts{{"Full Impact", fi.y() / s, fi.z() / s}};
  if (f.no_sliding) pts.push_back({"no sliding (Critical Impulse Line)", f.no_sliding->y() / s, f.no_sliding->z() / s});
  for (std::size_t k = 0; k < c.a.solutions.size(); ++k) {
    const V3& P = c.a.solutions[k].impulse.P_C;
    pts.push_back({label(c.spec.strategies[k]), P.y() / s, P.z() / s});
  }
  // Frame the solutions, with room around them, and the origin where it is close.
  double x0 = pts[0].x, x1 = pts[0].x, y0 = pts[0].y, y1 = pts[0].y, extent = 0;
  for (const auto& q : pts) {
    x0 = std::min(x0, q.x), x1 = std::max(x1, q.x), y0 = std::min(y0, q.y), y1 = std::max(y1, q.y);
    extent = std::max({extent, std::fabs(q.x), std::fabs(q.y)});
  }
  double margin = std::max({0.6 * (x1 - x0), 0.6 * (y1 - y0), 0.15 * extent});
  if (!(margin > 0)) margin = 0.15 * fi.x() / s;  // every point at the origin: frame by the normal impulse's size
  if (!(extent > 0)) extent = margin;
  const std::string t_trace = trace(f.t_trace, s, 3 * extent), z_trace = trace(f.z_trace, s, 3 * extent);
  // The solution planes of PC-Crash (phi_FI, eq 15) and Wach (phi, eq 21) through the origin.
  std::string plane_lines[2];
  const double phis[2] = {f.phi_fi_deg * M_PI / 180, f.phi_deg * M_PI / 180};
  for (int j = 0; j < 2; ++j)
    plane_lines[j] = fmt::format("{:.17g},{:.17g}\n{:.17g},{:.17g}\n", -3 * extent * std::cos(phis[j]), -3 * extent * std::sin(phis[j]),
                                 3 * extent * std::cos(phis[j]), 3 * extent * std::sin(phis[j]));
  std::string cone;
  // The GIR cone |P_cp| = GIR P_n cut by the restitution plane.
  for (int i = 0; i <= 360; ++i) {
    const double th = i * M_PI / 180;
    const std::optional<double> rho = gir_cone_radius(c.p, f, th);
    if (!rho) {
      cone += "\n";
      continue;
    }
    cone += fmt::format("{:.17g},{:.17g}\n", *rho / s * std::cos(th), *rho / s * std::sin(th));
  }
  if (cone.find(',') == std::string::npos) cone.clear();
  std::string gp = header_lines(c, "contact-plane view on the restitution plane (eps = " + c.spec.restitution.text + ")");
  gp += fmt::format("set xlabel {}\nset ylabel {}\n", gnuplot_string("P_t [" + c.imp_unit + "]"), gnuplot_string("P_z [" + c.imp_unit + "]"));
  gp += fmt::format("set xrange [{:.17g}:{:.17g}]\nset yrange [{:.17g}:{:.17g}]\n", x0 - margin, x1 + margin, y0 - margin, y1 + margin);
  gp += series(c, "plot", "contact_plane", {{"lw 2 lc rgb '#1f77b4'", "t no-sliding plane", t_trace},
                                            {"lw 2 lc rgb '#ff7f0e'", "z no-sliding plane", z_trace},
                                            {"dt 2 lc rgb '#2ca02c'", "PC-Crash plane (phi_FI)", plane_lines[0]},
                                            {"dt 3 lc rgb '#9467bd'", "Wach plane (phi)", plane_lines[1]},
                                            {"lc rgb '#7f7f7f'", "GIR cone", cone}});
  gp += points_file(c.dir, "contact_plane", "label,P_t,P_z", pts, false) + "\n";
  draw(c, "contact_plane", gp);
}

// P_n against the in-plane impulse on the plane through n and the strategy's contact-plane impulse
// (for pc-crash the phi_FI plane, for Wach the phi plane): Figures 4 right and 7.
void solution_plane_view(Context& c, std::size_t k) {
  const auto& p = c.p;
  const auto& f = c.fig.planes[k];
  const double s = c.f.impulse;
  const Point sol{label(c.spec.strategies[k]), f.P_u / s, f.P_n / s};
  const double cir = f.cir, gir = f.gir;
  const double ymax = 1.6 * std::max(sol.y, c.fig.contact.restitution_rhs / p.K(0, 0) / s);
  const double xs[] = {sol.x, gir * ymax, cir * ymax, 0.0};
  double xmin = 0, xmax = 0;
  for (double x : xs) xmin = std::min(xmin, x), xmax = std::max(xmax, x);
  const double pad = xmax > xmin ? 0.15 * (xmax - xmin) : 0.15 * ymax;  // no in-plane impulse: frame by P_n
  const double extent = 10 * (ymax + xmax - xmin);
  auto ray = [&](double mu) { return fmt::format("0,0\n{:.17g},{:.17g}\n", mu * 10 * ymax, 10 * ymax); };
  const std::string name = fmt::format("solution_plane_{}", k + 1);
  // The title states the plane's angle and every warning of the solution, as `solve` reports them.
  std::vector<std::string> warnings;
  for (const auto& w : c.a.solutions[k].warnings) warnings.push_back("warning: " + w.text);
  std::string gp = header_lines(c, fmt::format("solution plane of {} (angle {:.6g} deg from t towards z)", label(c.spec.strategies[k]),
                                               f.angle_deg), 900, 700, warnings);
  gp += fmt::format("set xlabel {}\nset ylabel {}\n", gnuplot_string("in-plane impulse P_u [" + c.imp_unit + "]"),
                    gnuplot_string("P_n [" + c.imp_unit + "]"));
  gp += fmt::format("set xrange [{:.17g}:{:.17g}]\nset yrange [0:{:.17g}]\n", xmin - pad, xmax + pad, ymax);
  gp += series(c, "plot", name, {{"lw 2 lc rgb '#000000'", "maximum compression", trace(f.max_compression, s, extent)},
                                 {"dt 2 lc rgb '#000000'", "restitution (eps = " + c.spec.restitution.text + ")",
                                  trace(f.restitution, s, extent)},
                                 {"lw 2 lc rgb '#1f77b4'", "no sliding along the plane", trace(f.no_sliding_along, s, extent)},
                                 {"lw 2 lc rgb '#ff7f0e'", "no sliding across the plane", trace(f.no_sliding_across, s, extent)},
                                 {"dt 3 lc rgb '#2ca02c'", fmt::format("CIR = {:.6g}", cir), ray(cir)},
                                 {"dt 4 lc rgb '#d62728'", fmt::format("GIR = {:.6g}", gir), ray(gir)}});
  gp += points_file(c.dir, name, "label,P_u,P_n", {sol}, false) + "\n";
  draw(c, name, gp);
}

// The three fundamental planes, the restitution plane, the Critical Impulse Line and the solutions in
// impulse space (P_t, P_z, P_n): Figures 2-3 left.
void impulse_space_view(Context& c) {
  const double s = c.f.impulse;
  const V3 P0 = c.a.space.P_max_loss, d = c.a.space.cil_direction;
  // The restitution plane is drawn around the Critical Impulse Line's point on it, or the Full Impact.
  const V3 on_restitution = c.fig.contact.no_sliding ? *c.fig.contact.no_sliding : c.fig.contact.full_impact;
  const double L = 0.5 * P0.norm();
  // A square patch of a plane (unit normal nrm) centred at `centre`, as a mesh of lines.
  auto patch = [&](const V3& nrm, const V3& centre) {
    std::string dat;
    V3 e1 = nrm.cross(V3::UnitX());
    if (e1.norm() < kNearlyParallel) e1 = nrm.cross(V3::UnitY());
    e1.normalize();
    const V3 e2 = nrm.cross(e1).normalized();
    for (int i = -2; i <= 2; ++i)
      for (const auto& [a, b] : {std::pair{e1, e2}, std::pair{e2, e1}}) {
        const V3 q0 = centre + L * (0.5 * i * a - b), q1 = centre + L * (0.5 * i * a + b);
        dat += fmt::format("{:.17g},{:.17g},{:.17g}\n{:.17g},{:.17g},{:.17g}\n\n", q0.y() / s, q0.z() / s, q0.x() / s, q1.y() / s,
                           q1.z() / s, q1.x() / s);
      }
    return dat;
  };
  const V3 a0 = P0 - 1.5 * L * d, a1 = P0 + 3 * L * d;
  const std::string cil_line = fmt::format("{:.17g},{:.17g},{:.17g}\n{:.17g},{:.17g},{:.17g}\n", a0.y() / s, a0.z() / s, a0.x() / s,
                                           a1.y() / s, a1.z() / s, a1.x() / s);
  auto plane = [&](int k) { return V3(c.a.space.plane_normal.row(k).transpose()); };
  std::vector<Point> pts{{"maximum energy loss", P0.y() / s, P0.z() / s, P0.x() / s}};
  for (std::size_t k = 0; k < c.a.solutions.size(); ++k) {
    const V3& P = c.a.solutions[k].impulse.P_C;
    pts.push_back({label(c.spec.strategies[k]), P.y() / s, P.z() / s, P.x() / s});
  }
  std::string gp = header_lines(c, "impulse space: fundamental planes, restitution plane, Critical Impulse Line", 1000, 800);
  gp += fmt::format("set xlabel {}\nset ylabel {}\nset zlabel {} rotate\nset view 62, 35\nset xyplane 0\n",
                    gnuplot_string("P_t [" + c.imp_unit + "]"), gnuplot_string("P_z [" + c.imp_unit + "]"),
                    gnuplot_string("P_n [" + c.imp_unit + "]"));
  gp += series(c, "splot", "impulse_space", {{"lc rgb '#000000'", "maximum-compression plane", patch(plane(0), P0)},
                                             {"lc rgb '#1f77b4'", "t no-sliding plane", patch(plane(1), P0)},
                                             {"lc rgb '#ff7f0e'", "z no-sliding plane", patch(plane(2), P0)},
                                             // the case's restitution plane, through the CIL point
                                             {"dt 2 lc rgb '#7f7f7f'", "restitution plane", patch(plane(0), on_restitution)},
                                             {"lw 3 lc rgb '#d62728'", "Critical Impulse Line", cil_line}});
  gp += points_file(c.dir, "impulse_space", "label,P_t,P_z,P_n", pts, true) + "\n";
  draw(c, "impulse_space", gp);
}

// Post-impact sliding along t and z, swerve and energy loss against mu (0 to 1.5 GIR) and against eps.
void sweeps(Context& c, std::size_t k) {
  const io::StrategySpec& spec = c.spec.strategies[k];
  const double gir = c.fig.contact.gir;
  // The strategy with its friction key (strategy_kinds.hpp) set to mu, written as a decimal.
  const std::string sweep_key(io::strategy_kind(spec.kind).sweep_key);
  auto with_mu = [&](double mu) -> Strategy<double> {
    io::StrategySpec swept = spec;
    swept.numbers[sweep_key] = io::Number{fmt::format("{:.17g}", mu), mu};
    return io::to_strategy<double>(swept);
  };
  const Strategy<double> as_given = io::to_strategy<double>(spec);
  const double fv = c.f.velocity, fe = c.f.energy;
  // A case with no contact-plane impulse has GIR = 0: sweep mu over [0, 1] instead of an empty range.
  const bool by_gir = gir > 0 && std::isfinite(gir);
  const double mu_max = by_gir ? 1.5 * gir : 1.0;
  for (const bool over_mu : {true, false}) {
    std::string csv = over_mu ? "mu,V_t_after,V_z_after,swerve_deg,energy_loss\n" : "eps,V_t_after,V_z_after,swerve_deg,energy_loss\n";
    const int n = over_mu ? 60 : 40;
    double lo[4], hi[4];
    std::fill(lo, lo + 4, INFINITY);
    std::fill(hi, hi + 4, -INFINITY);
    for (int i = 0; i <= n; ++i) {
      const double x = over_mu ? mu_max * i / n : static_cast<double>(i) / n;
      Scene<double> sc = c.scene;
      if (!over_mu) sc.restitution = x;
      try {
        const Solution<double> sol = analyze(sc, {over_mu ? with_mu(x) : as_given}, c.o.engine).solutions[0];
        const double y[4] = {sol.V_rf.y() / fv, sol.V_rf.z() / fv, sol.swerve_deg ? *sol.swerve_deg : NAN, sol.energy_loss / fe};
        for (int q = 0; q < 4; ++q)
          if (std::isfinite(y[q])) lo[q] = std::min(lo[q], y[q]), hi[q] = std::max(hi[q], y[q]);
        csv += fmt::format("{:.17g},{:.17g},{:.17g},{},{:.17g}\n", x, y[0], y[1],
                           sol.swerve_deg ? fmt::format("{:.17g}", y[2]) : std::string("NaN"), y[3]);
      } catch (const SolveError&) {
        csv += "\n";  // no impulse at this value: a gap in the curves
      }
    }
    const std::string name = fmt::format("sweep_{}_{}", over_mu ? "mu" : "eps", k + 1);
    c.dir.write(name + ".csv", csv);
    const std::string xl = over_mu ? sweep_key : "restitution eps";
    const std::string span = over_mu ? (by_gir ? "0 to 1.5 GIR" : "0 to 1, GIR = 0") : "0 to 1";
    std::string gp = header_lines(c, fmt::format("{} against {} ({})", label(spec), xl, span), 1000, 800);
    gp += fmt::format("set key off\nunset title\nset multiplot layout 2,2 title {}.\"\\n\".{} noenhanced\n",
                      gnuplot_string(c.spec.name), gnuplot_string(label(spec) + " against " + xl));
    gp += fmt::format("set xrange [0:{:.17g}]\n", over_mu ? mu_max : 1.0);
    const char* titles[] = {"sliding along t after", "sliding along z after (swerve)", "swerve angle", "energy loss"};
    const std::string units[] = {c.vel_unit, c.vel_unit, "deg", c.energy_unit};
    for (int q = 0; q < 4; ++q) {
      if (!(lo[q] <= hi[q])) {  // nothing finite to draw (no sliding after the impact: swerve undefined)
        gp += fmt::format("set title {}\nunset xlabel\nunset ylabel\nset label 1 {} at graph 0.5, 0.5 center\nset yrange [0:1]\n"
                          "unset xtics\nunset ytics\nplot 2 notitle\nunset label 1\nset xtics\nset ytics\n",
                          gnuplot_string(titles[q]),
                          gnuplot_string(q == 2 ? "no sliding after the impact: swerve undefined" : "no value to draw"));
        continue;
      }
      const auto [y0, y1] = nonempty(lo[q], hi[q], 0);
      gp += fmt::format("set title {}\nset xlabel {} noenhanced\nset ylabel {}\nset yrange [{:.17g}:{:.17g}]\n"
                        "plot '{}.csv' using 1:{} skip 1 with linespoints pt 7 ps 0.4\n",
                        gnuplot_string(titles[q]), gnuplot_string(xl), gnuplot_string("[" + units[q] + "]"), y0, y1, name, q + 2);
    }
    gp += "unset multiplot\n";
    draw(c, name, gp);
  }
}

}  // namespace

std::string plot(const io::CaseSpec& spec, const PlotOptions& o) {
  require_gnuplot();
  const Scene<double> scene = io::to_scene<double>(spec);
  const Analysis<double> a = analyze(scene, io::to_strategies<double>(spec), o.engine);
  const OutputDir dir(o.out_dir);
  const Figures<double> fig = figures(a);
  Context c{spec, o, dir, scene, a, a.problem(), fig, unit_factors<double>(spec.units),
            io::unit_label(spec.units, "impulse"), io::unit_label(spec.units, "velocity"), io::unit_label(spec.units, "energy"), "", ""};
  contact_plane_view(c);
  for (std::size_t k = 0; k < a.solutions.size(); ++k) solution_plane_view(c, k);
  impulse_space_view(c);
  for (std::size_t k = 0; k < a.solutions.size(); ++k) sweeps(c, k);
  std::fputs(c.warnings.c_str(), stderr);
  return c.written;
}

}  // namespace impact3d::cli
