// Stronge's impact as it happens (stronge/integrate.hpp), from the path its integration records: the
// hodograph of the sliding velocity, V_n and the normal work against the normal impulse, and the impulse
// path beside the algebraic strategies' points. The events are marked on each.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "impact3d/case_format/strategy_kinds.hpp"
#include "impact3d/cli/figures/figure.hpp"
#include "impact3d/cli/figures/views.hpp"

namespace impact3d::cli {
namespace {

// One filled glyph per kind of event (history.hpp's order), in dark colours no strategy uses.
const Marker& event_marker(stronge::EventKind k) {
  static const Marker markers[] = {{9, "#000000"}, {7, "#006400"}, {5, "#8b0000"}, {13, "#000080"}, {11, "#6a0dad"}};
  return markers[static_cast<int>(k)];
}

// Four significant digits in fixed notation: a figure's reader compares magnitudes, which exponents hide.
std::string four(double v) {
  if (!std::isfinite(v) || v == 0) return fmt::format("{:g}", v);
  const int decimals = std::max(0, 3 - static_cast<int>(std::floor(std::log10(std::fabs(v)))));
  return fmt::format("{:.{}f}", v, decimals);
}

struct Range {
  double lo = INFINITY, hi = -INFINITY;
  void add(double v) {
    if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  }
  // Padded by 8 % of the span, or of `scale` where it is flat.
  std::pair<double, double> padded(double scale) const {
    const auto [a, b] = nonempty(lo, hi, scale);
    const double pad = 0.08 * (b - a);
    return {a - pad, b + pad};
  }
};

std::string event_label(const stronge::Event<double>& e, double p_scale, const std::string& unit) {
  return fmt::format("{} (p = {} {})", stronge::event_name(e.kind), four(e.p / p_scale), unit);
}

// The events as vertical lines across a panel whose abscissa is p, each named along its line.
std::string event_lines(const std::vector<stronge::Event<double>>& events, double p_scale) {
  std::string gp;
  for (std::size_t i = 0; i < events.size(); ++i) {
    const double x = events[i].p / p_scale;
    gp += fmt::format("set arrow {0} from {1:.17g}, graph 0 to {1:.17g}, graph 1 nohead lw 1 dt 2 lc rgb '{2}'\n", i + 1, x,
                      event_marker(events[i].kind).colour);
    gp += fmt::format("set label {} {} at {:.17g}, graph {} rotate by 90 {} offset 1,0 font ',9' tc rgb '{}' noenhanced\n", i + 1,
                      gnuplot_string(std::string(stronge::event_name(events[i].kind))), x, i % 2 ? "0.03" : "0.97",
                      i % 2 ? "left" : "right", event_marker(events[i].kind).colour);
  }
  return gp;
}

std::string unset_event_lines(std::size_t n) {
  std::string gp;
  for (std::size_t i = 0; i < n; ++i) gp += fmt::format("unset arrow {0}\nunset label {0}\n", i + 1);
  return gp;
}

void hodograph(FigureContext& c, std::size_t k, const stronge::History<double>& h, const std::string& label) {
  const double fv = c.f.velocity;
  std::string data;
  Range x, y;
  for (const auto& q : h.path) {
    data += fmt::format("{:.17g},{:.17g}\n", q.V_C.y() / fv, q.V_C.z() / fv);
    x.add(q.V_C.y() / fv), y.add(q.V_C.z() / fv);
  }
  x.add(0), y.add(0);
  std::vector<Point> pts;
  for (const auto& e : h.events) pts.push_back({event_label(e, c.f.impulse, c.imp_unit), event_marker(e.kind), e.V_C.y() / fv, e.V_C.z() / fv});
  const double scale = std::max({x.hi - x.lo, y.hi - y.lo, h.path.front().V_C.norm() / fv});
  const auto [x0, x1] = x.padded(scale);
  const auto [y0, y1] = y.padded(scale);
  const std::string name = fmt::format("stronge_hodograph_{}", k + 1);
  // The same scale on both axes shows the sliding direction's turning as it is, unless one span is
  // too thin to read at that scale.
  const bool same_scale = std::max(x1 - x0, y1 - y0) <= 3 * std::min(x1 - x0, y1 - y0);
  std::vector<std::string> more{fmt::format("swerve {} deg in all{}{}", four(h.swerve_deg),
                                            h.final_direction_deg ? fmt::format(", sliding at {} deg from t towards z at the end", four(*h.final_direction_deg))
                                                                  : std::string(", not sliding at the end"),
                                            same_scale ? "" : "; the axes are not to one scale")};
  std::string gp = figure_head(c, "hodograph of the sliding velocity through the impact: " + label, 1200, 800, more);
  if (same_scale) gp += "set size ratio -1\n";
  gp += fmt::format("set xlabel {}\nset ylabel {} offset -1,0\n", gnuplot_string("V_t [" + c.vel_unit + "]"),
                    gnuplot_string("V_z [" + c.vel_unit + "]"));
  gp += fmt::format("set xrange [{:.17g}:{:.17g}]\nset yrange [{:.17g}:{:.17g}]\n", x0, x1, y0, y1);
  gp += "set xzeroaxis lt -1 lw 1\nset yzeroaxis lt -1 lw 1\n";
  gp += series(c, "plot", name, {{"lw 2 lc rgb '#333333'", "(V_t, V_z) from p = 0 to the end", data}});
  gp += points_items(c, name, "label,V_t,V_z", pts, false, Frame{x0, x1, y0, y1}) + "\n";
  c.draw(name, gp);
}

void normal_history(FigureContext& c, std::size_t k, const stronge::History<double>& h, const std::string& label) {
  const double fi = c.f.impulse, fv = c.f.velocity, fe = c.f.energy;
  std::string vn, work;
  Range p, v, w;
  for (const auto& q : h.path) {
    const double pn = q.P_C.x() / fi;
    vn += fmt::format("{:.17g},{:.17g}\n", pn, q.V_C.x() / fv);
    work += fmt::format("{:.17g},{:.17g}\n", pn, q.normal_work / fe);
    p.add(pn), v.add(q.V_C.x() / fv), w.add(q.normal_work / fe);
  }
  v.add(0), w.add(0);
  const std::string name = fmt::format("stronge_normal_{}", k + 1);
  c.dir.write(name + ".dat", vn + "\n\n" + work);
  std::string events = "label,p,V_n,normal_work\n";
  for (const auto& e : h.events)
    events += fmt::format("{},{:.17g},{:.17g},{:.17g}\n", stronge::event_name(e.kind), e.p / fi, e.V_C.x() / fv, e.normal_work / fe);
  c.dir.write(name + ".events.csv", events);
  const std::string what = "normal velocity and normal work against the normal impulse: " + label;
  std::string gp = figure_head(c, what, 1000, 800);
  gp += fmt::format("set key off\nunset title\nset multiplot layout 2,1 title {} noenhanced\n", title_lines(c, what,
                    {fmt::format("work of compression {} {}, released in restitution {} {}", four(h.work_compression / fe),
                                 c.energy_unit, four(h.work_restitution / fe), c.energy_unit)}));
  const auto [p0, p1] = p.padded(p.hi);
  gp += fmt::format("set xrange [{:.17g}:{:.17g}]\nset xlabel {}\nset xzeroaxis lt -1 lw 1\n", std::min(0.0, p0), p1,
                    gnuplot_string("normal impulse p [" + c.imp_unit + "]"));
  gp += event_lines(h.events, fi);
  const auto [v0, v1] = v.padded(v.hi - v.lo);
  gp += fmt::format("set ylabel {}\nset yrange [{:.17g}:{:.17g}]\nplot '{}.dat' index 0 with lines lw 2 lc rgb '#333333'\n",
                    gnuplot_string("V_n [" + c.vel_unit + "]"), v0, v1, name);
  const auto [w0, w1] = w.padded(w.hi - w.lo);
  gp += fmt::format("set ylabel {}\nset yrange [{:.17g}:{:.17g}]\nplot '{}.dat' index 1 with lines lw 2 lc rgb '#333333'\n",
                    gnuplot_string("normal work [" + c.energy_unit + "]"), w0, w1, name);
  gp += unset_event_lines(h.events.size()) + "unset multiplot\n";
  c.draw(name, gp);
}

void impulse_path(FigureContext& c, std::size_t k, const stronge::History<double>& h, const std::string& label) {
  const double s = c.f.impulse;
  std::string along[2];
  Range p, q[2];
  for (const auto& r : h.path) {
    p.add(r.P_C.x() / s);
    for (int j = 0; j < 2; ++j) {
      along[j] += fmt::format("{:.17g},{:.17g}\n", r.P_C.x() / s, r.P_C(j + 1) / s);
      q[j].add(r.P_C(j + 1) / s);
    }
  }
  // Every strategy's impulse of the case on the same axes, and the Full Impact: one file of points for
  // both panels, told apart where they coincide in impulse space, not in one projection.
  std::vector<Point> pts;
  const auto add = [&](std::string label, const Marker& m, const Vec3<double>& P) {
    pts.push_back({std::move(label), m, P.x() / s, P.y() / s, P.z() / s});
    p.add(P.x() / s), q[0].add(P.y() / s), q[1].add(P.z() / s);
  };
  add("Full Impact", kFullImpactMarker, c.fig.contact.full_impact);
  for (std::size_t m = 0; m < c.a.solutions.size(); ++m)
    add(case_format::strategy_label(c.spec.strategies[m]), strategy_marker(m), c.a.solutions[m].impulse.P_C);
  for (const auto& e : h.events) {
    // The impulse at an event: a point of the path, for each step's last point is its end.
    const auto at = std::lower_bound(h.path.begin(), h.path.end(), e.p, [](const auto& r, double v) { return r.P_C.x() < v; });
    if (at != h.path.end()) add(event_label(e, s, c.imp_unit), event_marker(e.kind), at->P_C);
  }
  p.add(0), q[0].add(0), q[1].add(0);
  const std::string name = fmt::format("stronge_impulse_path_{}", k + 1);
  const std::string what = "impulse path through the impact, beside every strategy's impulse: " + label;
  std::string gp = figure_head(c, what, 1700, 650);
  // Two panels and the key to their right, clear of both.
  gp += fmt::format("unset title\nset multiplot title {} noenhanced\n", title_lines(c, what));
  const auto [p0, p1] = p.padded(p.hi);
  gp += fmt::format("set xrange [{:.17g}:{:.17g}]\nset xlabel {}\nset xzeroaxis lt -1 lw 1\n", std::min(0.0, p0), p1,
                    gnuplot_string("P_n [" + c.imp_unit + "]"));
  const auto [t0, t1] = q[0].padded(p.hi - p.lo);
  const auto [z0, z1] = q[1].padded(p.hi - p.lo);
  const Frame frame{p0, p1, t0, t1, z0, z1};
  const char* axis[2] = {"P_t", "P_z"};
  for (int j = 0; j < 2; ++j) {
    gp += fmt::format("set origin {},0\nset size 0.3,0.9\nset key {}\nset ylabel {}\nset yrange [{:.17g}:{:.17g}]\n", j ? "0.3" : "0",
                      j ? "at screen 0.615, screen 0.86 left top vertical Left reverse noenhanced font ',10'" : "off",
                      gnuplot_string(std::string(axis[j]) + " [" + c.imp_unit + "]"), j ? z0 : t0, j ? z1 : t1);
    gp += series(c, "plot", fmt::format("{}_{}", name, axis[j][2]), {{"lw 2 lc rgb '#333333'", "the integrated path", along[j]}});
    gp += points_items(c, name, "label,P_n,P_t,P_z", pts, true, frame, j ? "2:4" : "2:3") + "\n";
  }
  gp += "unset multiplot\n";
  c.draw(name, gp);
}

}  // namespace

void stronge_views(FigureContext& c, std::size_t k) {
  const auto& h = c.a.solutions[k].impulse.history;
  if (!h || h->path.size() < 2) return;
  const std::string label = case_format::strategy_label(c.spec.strategies[k]);
  hodograph(c, k, *h, label);
  normal_history(c, k, *h, label);
  impulse_path(c, k, *h, label);
}

}  // namespace impact3d::cli
