// Impulse space in perspective (Figures 2-3 left): the fundamental planes, the case's restitution plane
// and the solution planes of PC-Crash and Wach as shaded planes cut to a cube around the solutions, the
// Critical Impulse Line, the GIR cone, the paper's volumes A-D, and the points.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "impact3d/cli/figures/box_clip.hpp"
#include "impact3d/cli/figures/figure.hpp"
#include "impact3d/case_format/strategy_kinds.hpp"
#include "impact3d/cli/figures/views.hpp"

namespace impact3d::cli {
namespace {

using V3 = Vec3<double>;

constexpr int kConeGenerators = 24;
constexpr int kConeRings = 3;

// Drawing coordinates: (P_t, P_z, P_n) in the output units.
P3 drawn(const V3& P_C, double s) { return {P_C.y() / s, P_C.z() / s, P_C.x() / s}; }
P3 drawn_direction(const V3& d) { return {d.y(), d.z(), d.x()}; }

std::string vertices(const std::vector<P3>& poly) {
  std::string out;
  for (const auto& q : poly) out += fmt::format("{:.17g},{:.17g},{:.17g}\n", q[0], q[1], q[2]);
  return out;
}

std::string shaded(const char* colour) {
  return fmt::format("fs transparent solid 0.16 border lc rgb '{}' fc rgb '{}'", colour, colour);
}

// The cube on the left, the key on the right: beside a 3D plot gnuplot would shrink the cube to fit.
constexpr const char* kKeyRight =
    "set key at screen 0.62, 0.9 left top vertical Left reverse noenhanced\nset rmargin at screen 0.6\n";

}  // namespace

void impulse_space_view(FigureContext& c) {
  const double s = c.f.impulse;
  const auto& space = c.a.space;
  const auto& contact = c.fig.contact;
  // The points, and a cube around them with room: equal scales keep the planes' angles true.
  std::vector<Point> pts{{"maximum energy loss (eps = 0)", kMaxLossMarker, 0, 0, 0},
                         {"Full Impact", kFullImpactMarker, 0, 0, 0}};
  std::vector<V3> at{space.P_max_loss, contact.full_impact};
  if (contact.no_sliding) {
    pts.push_back({"no sliding (CIL)", kNoSlidingMarker, 0, 0, 0});
    at.push_back(*contact.no_sliding);
  }
  for (std::size_t k = 0; k < c.a.solutions.size(); ++k) {
    pts.push_back({case_format::strategy_label(c.spec.strategies[k]), strategy_marker(k), 0, 0, 0});
    at.push_back(c.a.solutions[k].impulse.P_C);
  }
  P3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const P3 q = drawn(at[i], s);
    pts[i].x = q[0], pts[i].y = q[1], pts[i].z = q[2];
    for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], q[k]), hi[k] = std::max(hi[k], q[k]);
  }
  double half = 0;
  for (int k = 0; k < 3; ++k) half = std::max(half, 0.5 * (hi[k] - lo[k]));
  half = std::max(1.3 * half, 0.35 * space.P_max_loss.norm() / s);
  if (!(half > 0)) half = 1;
  Box box;
  for (int k = 0; k < 3; ++k) {
    const double mid = 0.5 * (lo[k] + hi[k]);
    box.lo[k] = mid - half, box.hi[k] = mid + half;
  }
  const auto plane = [&](const V3& normal_C, double offset_SI) {
    return vertices(plane_in_box(drawn_direction(normal_C), offset_SI / s, box));
  };
  const auto& N = space.plane_normal;
  const auto through_n = [&](double phi_deg) {  // the plane through n at phi from t towards z
    const double phi = phi_deg * M_PI / 180;
    return plane(V3(0, -std::sin(phi), std::cos(phi)), 0);
  };
  const auto segment = [&](const P3& origin, const P3& direction) {
    const auto seg = line_in_box(origin, direction, box);
    return seg ? vertices({(*seg)[0], (*seg)[1]}) : std::string();
  };
  // The GIR cone |P_cp| = GIR P_n: generators from the origin and rings at heights inside the cube.
  std::string cone;
  const double gir = contact.gir;
  if (gir > 0 && std::isfinite(gir)) {
    for (int i = 0; i < kConeGenerators; ++i) {
      const double th = 2 * M_PI * i / kConeGenerators;
      cone += segment({0, 0, 0}, {gir * std::cos(th), gir * std::sin(th), 1}) + "\n";
    }
    for (int r = 1; r <= kConeRings; ++r) {
      const double h = box.lo[2] + (box.hi[2] - box.lo[2]) * r / (kConeRings + 1);
      if (h <= 0) continue;
      bool open = false;
      for (int i = 0; i <= 120; ++i) {
        const double th = 2 * M_PI * i / 120;
        const P3 q{gir * h * std::cos(th), gir * h * std::sin(th), h};
        if (box.inside(q)) {
          cone += fmt::format("{:.17g},{:.17g},{:.17g}\n", q[0], q[1], q[2]);
          open = true;
        } else if (open) {
          cone += "\n";
          open = false;
        }
      }
      cone += "\n";
    }
  }
  std::string gp = figure_head(c, "impulse space (Figures 2-3): planes, Critical Impulse Line (CIL), GIR cone, volumes A-D", 1300, 850, {},
                               kKeyRight);
  gp += fmt::format("set xlabel {} offset 0,-1\nset ylabel {} offset 1,-1\nset zlabel {} rotate by 90 offset -2,0\n",
                    gnuplot_string("P_t [" + c.imp_unit + "]"), gnuplot_string("P_z [" + c.imp_unit + "]"),
                    gnuplot_string("P_n [" + c.imp_unit + "]"));
  gp += "set view 64, 32\nset view equal xyz\nset xyplane 0\nset border 4095 lc rgb '#bbbbbb'\n";
  gp += fmt::format("set xrange [{:.17g}:{:.17g}]\nset yrange [{:.17g}:{:.17g}]\nset zrange [{:.17g}:{:.17g}]\n", box.lo[0],
                    box.hi[0], box.lo[1], box.hi[1], box.lo[2], box.hi[2]);
  const double step = tick_step(0, 2 * half, 6);
  // Ticks pushed off the axes so that the labels at a shared corner do not run together.
  gp += fmt::format("set xtics {0:.17g} offset -0.5,-0.4\nset ytics {0:.17g} offset 0.5,-0.4\nset ztics {0:.17g}\n", step);
  // The paper's volumes, each letter inside its own (volume_points, checked in exam_figures).
  int tag = 1;
  for (const auto& v : volume_points(space, 0.55 * half * s)) {
    const P3 q = drawn(v.P, s);
    if (!box.inside(q)) continue;
    gp += fmt::format("set label {} '{}' at {:.17g},{:.17g},{:.17g} center front font ',18' tc rgb '#505050'\n", tag++, v.letter, q[0], q[1],
                      q[2]);
  }
  const P3 cil_origin = drawn(space.P_max_loss, s);
  gp += series(c, "splot", "impulse_space",
               {{shaded(colour::max_compression), "maximum-compression plane", plane(V3(N.row(0).transpose()), space.plane_offset(0)), colour::max_compression},
                {shaded(colour::t_no_sliding), "t no-sliding plane", plane(V3(N.row(1).transpose()), space.plane_offset(1)), colour::t_no_sliding},
                {shaded(colour::z_no_sliding), "z no-sliding plane", plane(V3(N.row(2).transpose()), space.plane_offset(2)), colour::z_no_sliding},
                {shaded(colour::restitution), "restitution plane (eps = " + c.spec.restitution.text + ")",
                 plane(V3(N.row(0).transpose()), space.restitution_offset), colour::restitution},
                {shaded(colour::pc_crash_plane), "PC-Crash plane (phi_FI, eq 15)", through_n(contact.phi_fi_deg), colour::pc_crash_plane},
                {shaded(colour::wach_plane), "Wach plane (phi, eq 21)", through_n(contact.phi_deg), colour::wach_plane},
                {fmt::format("lw 3 lc rgb '{}'", colour::critical_line), "Critical Impulse Line",
                 segment(cil_origin, drawn_direction(space.cil_direction))},
                {fmt::format("lw 1 lc rgb '{}'", colour::gir), fmt::format("GIR cone (GIR = {:.6g})", gir), cone}});
  gp += points_items(c, "impulse_space", "label,P_t,P_z,P_n", pts, true,
                     Frame{box.lo[0], box.hi[0], box.lo[1], box.hi[1], box.lo[2], box.hi[2]}) +
        "\n";
  c.draw("impulse_space", gp);
}

}  // namespace impact3d::cli
