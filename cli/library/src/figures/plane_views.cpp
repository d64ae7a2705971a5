// The two flat views of impulse space: the contact plane seen along n on the restitution plane
// (Figures 3-4 right) and each strategy's solution plane (Figures 4 right and 7).
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "impact3d/cli/figures/figure.hpp"
#include "impact3d/case_format/strategy_kinds.hpp"
#include "impact3d/cli/figures/views.hpp"

namespace impact3d::cli {
namespace {

using V3 = Vec3<double>;

std::string trace(const Line2<double>& l, double scale, double extent) { return line_segment(l.a, l.b, l.r / scale, extent); }

std::string lines_style(const char* colour, const char* extra = "lw 2") { return fmt::format("{} lc rgb '{}'", extra, colour); }

}  // namespace

void contact_plane_view(FigureContext& c) {
  const auto& f = c.fig.contact;
  const double s = c.f.impulse;
  const V3& fi = f.full_impact;
  std::vector<Point> pts{{"Full Impact", kFullImpactMarker, fi.y() / s, fi.z() / s}};
  if (f.no_sliding) pts.push_back({"no sliding (CIL)", kNoSlidingMarker, f.no_sliding->y() / s, f.no_sliding->z() / s});
  for (std::size_t k = 0; k < c.a.solutions.size(); ++k) {
    const V3& P = c.a.solutions[k].impulse.P_C;
    pts.push_back({case_format::strategy_label(c.spec.strategies[k]), strategy_marker(k), P.y() / s, P.z() / s});
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
  const Frame frame{x0 - margin, x1 + margin, y0 - margin, y1 + margin};
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
  std::string gp = figure_head(c, "contact-plane view on the restitution plane (eps = " + c.spec.restitution.text + ")", 1100, 700);
  gp += fmt::format("set xlabel {}\nset ylabel {} offset -1,0\n", gnuplot_string("P_t [" + c.imp_unit + "]"),
                    gnuplot_string("P_z [" + c.imp_unit + "]"));
  gp += fmt::format("set xrange [{:.17g}:{:.17g}]\nset yrange [{:.17g}:{:.17g}]\n", frame.x0, frame.x1, frame.y0, frame.y1);
  gp += fmt::format("set xtics {:.17g}\nset ytics {:.17g}\n", tick_step(frame.x0, frame.x1), tick_step(frame.y0, frame.y1));
  gp += series(c, "plot", "contact_plane",
               {{lines_style(colour::t_no_sliding), "t no-sliding plane", trace(f.t_trace, s, 3 * extent)},
                {lines_style(colour::z_no_sliding), "z no-sliding plane", trace(f.z_trace, s, 3 * extent)},
                {lines_style(colour::pc_crash_plane, "lw 1.5 dt 2"), "PC-Crash plane (phi_FI, eq 15)", plane_lines[0]},
                {lines_style(colour::wach_plane, "lw 1.5 dt 3"), "Wach plane (phi, eq 21)", plane_lines[1]},
                {lines_style(colour::gir, "lw 1.5"), fmt::format("GIR cone (GIR = {:.6g})", f.gir), cone}});
  gp += points_items(c, "contact_plane", "label,P_t,P_z", pts, false, frame) + "\n";
  c.draw("contact_plane", gp);
}

void solution_plane_view(FigureContext& c, std::size_t k) {
  const auto& p = c.p;
  const auto& f = c.fig.planes[k];
  const auto& imp = c.a.solutions[k].impulse;
  const double s = c.f.impulse;
  const std::string name_k = case_format::strategy_label(c.spec.strategies[k]);
  const Point sol{name_k, strategy_marker(k), f.P_u / s, f.P_n / s};
  const double cir = f.cir, gir = f.gir;
  const double ymax = 1.6 * std::max(sol.y, c.fig.contact.restitution_rhs / p.K(0, 0) / s);
  const double xs[] = {sol.x, gir * ymax, cir * ymax, 0.0};
  double xmin = 0, xmax = 0;
  for (double x : xs) xmin = std::min(xmin, x), xmax = std::max(xmax, x);
  const double pad = xmax > xmin ? 0.15 * (xmax - xmin) : 0.15 * ymax;  // no in-plane impulse: frame by P_n
  const double extent = 10 * (ymax + xmax - xmin);
  auto ray = [&](double mu) { return fmt::format("0,0\n{:.17g},{:.17g}\n", mu * 10 * ymax, 10 * ymax); };
  // The ratio the strategy used, as `solve` reports it; Brach's, which reports two, is the point's own.
  const double used = imp.mu ? *imp.mu : (sol.y != 0 ? sol.x / sol.y : 0.0);
  const std::string name = fmt::format("solution_plane_{}", k + 1);
  // The title states the plane's angle and every warning of the solution, as `solve` reports them.
  std::vector<std::string> warnings;
  for (const auto& w : c.a.solutions[k].warnings) warnings.push_back("warning: " + w.text);
  std::string gp = figure_head(c, fmt::format("solution plane of {} (angle {:.6g} deg from t towards z)", name_k, f.angle_deg), 1100,
                               700, warnings);
  // The paper's name for the in-plane impulse is P_CP (Figures 4 and 7).
  gp += fmt::format("set xlabel {}\nset ylabel {} offset -1,0\n", gnuplot_string("P_{CP} [" + c.imp_unit + "]"),
                    gnuplot_string("P_n [" + c.imp_unit + "]"));
  gp += fmt::format("set xrange [{:.17g}:{:.17g}]\nset yrange [0:{:.17g}]\n", xmin - pad, xmax + pad, ymax);
  gp += fmt::format("set xtics {:.17g}\nset ytics {:.17g}\n", tick_step(xmin - pad, xmax + pad), tick_step(0, ymax));
  const Marker m = strategy_marker(k);
  gp += series(c, "plot", name,
               {{lines_style(colour::max_compression), "maximum compression", trace(f.max_compression, s, extent)},
                {lines_style(colour::restitution, "lw 2 dt 2"), "restitution (eps = " + c.spec.restitution.text + ")",
                 trace(f.restitution, s, extent)},
                {lines_style(colour::t_no_sliding), "no sliding along the plane", trace(f.no_sliding_along, s, extent)},
                {lines_style(colour::z_no_sliding), "no sliding across the plane", trace(f.no_sliding_across, s, extent)},
                {lines_style(colour::cir, "lw 1.5 dt 3"), fmt::format("CIR = {:.6g}", cir), ray(cir)},
                {lines_style(colour::gir, "lw 1.5 dt 4"), fmt::format("GIR = {:.6g}", gir), ray(gir)},
                {lines_style(m.colour, "lw 2.5 dt 5"), fmt::format("ratio used = {:.6g}", used), ray(used)}});
  gp += points_items(c, name, "label,P_u,P_n", {sol}, false, Frame{xmin - pad, xmax + pad, 0, ymax}) + "\n";
  c.draw(name, gp);
}

}  // namespace impact3d::cli
