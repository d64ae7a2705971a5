// The collision itself (the paper's Figures 1 and 5): both vehicles as boxes at their orientation, the
// impulse centre where their impulse centres meet, the contact frame, each CG's velocity before and
// after, and the impulse on vehicle 1; seen from above, and from the side when anything is pitched,
// rolled or tilted. One diagram per strategy, since the state after is the strategy's.
#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/format.h>

#include "impact3d/cli/figures/figure.hpp"
#include "impact3d/case_format/strategy_kinds.hpp"
#include "impact3d/cli/figures/views.hpp"

namespace impact3d::cli {
namespace {

using V3 = Vec3<double>;
using Xy = std::array<double, 2>;

// A stand-in box where the case gives no dimensions: a mid-size car's, in metres.
constexpr double kStandInLength = 4.5, kStandInWidth = 1.8, kStandInHeight = 1.4;
constexpr double kLevel = 1e-9;  // |sin| of a tilt drawn as level: a drawing heuristic, not a rounding bound
constexpr const char* kVehicleColour[2] = {"#4a6fa5", "#a5544a"};

struct BoxB {  // the vehicle's box in body axes about the CG (SI)
  double front, rear, half_width, half_height;
  bool stand_in;
};

BoxB box_of(const case_format::VehicleSpec& v, const V3& p_CgIc_B, double metres_per_unit) {
  if (v.dimensions) {
    const auto& d = *v.dimensions;
    const double L = d.length.value * metres_per_unit, W = d.width.value * metres_per_unit;
    const double front = d.cg_to_front ? d.cg_to_front->value * metres_per_unit : L / 2;
    const double H = d.height ? d.height->value * metres_per_unit : kStandInHeight;
    return {front, front - L, W / 2, H / 2, false};
  }
  const double half_length = std::max(kStandInLength / 2, std::fabs(p_CgIc_B.x()));
  return {half_length, -half_length, std::max(kStandInWidth / 2, std::fabs(p_CgIc_B.y())),
          std::max(kStandInHeight / 2, std::fabs(p_CgIc_B.z())), true};
}

std::array<V3, 8> corners(const BoxB& b) {
  std::array<V3, 8> c;
  for (int i = 0; i < 8; ++i) c[i] = V3(i & 1 ? b.front : b.rear, i & 2 ? b.half_width : -b.half_width, i & 4 ? b.half_height : -b.half_height);
  return c;
}

// The convex hull of points in the plane, counter-clockwise (Andrew's monotone chain).
std::vector<Xy> hull(std::vector<Xy> p) {
  std::sort(p.begin(), p.end());
  if (p.size() < 3) return p;
  std::vector<Xy> h(2 * p.size());
  std::size_t k = 0;
  const auto turn = [](const Xy& o, const Xy& a, const Xy& b) { return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]); };
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && turn(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && turn(h[k - 2], h[k - 1], p[i - 1]) <= 0) --k;
    h[k++] = p[i - 1];
  }
  h.resize(k - 1);
  return h;
}

struct View {  // a picture plane: two world directions
  V3 across, up;
  Xy at(const V3& p) const { return {p.dot(across), p.dot(up)}; }
};

struct Arrow {
  std::string label;
  V3 from, value;  // value in the output units (velocity or impulse)
  double scale;    // drawn length per unit of value
  const char* style;
  std::string key;
};

}  // namespace

void collision_view(FigureContext& c, std::size_t k) {
  const auto& sol = c.a.solutions[k];
  const double fl = c.f.length, fv = c.f.velocity, fi = c.f.impulse;
  std::array<BoxB, 2> box;
  std::array<V3, 2> cg;  // drawn units, impulse centre at the origin
  double longest = 0;
  bool stand_in = false, tilted = false;
  for (int i = 0; i < 2; ++i) {
    const auto& b = c.scene.body[i];
    box[i] = box_of(c.spec.vehicles[i], b.p_CgIc_B, unit_factors<double>(c.spec.units).length);  // dimensions: case units
    stand_in = stand_in || box[i].stand_in;
    cg[i] = -(b.R_WB * b.p_CgIc_B) / fl;
    longest = std::max(longest, (box[i].front - box[i].rear) / fl);
    tilted = tilted || std::fabs(b.R_WB(2, 0)) > kLevel || std::fabs(b.R_WB(2, 1)) > kLevel;
  }
  const Mat3<double>& R_WC = c.scene.R_WC;
  tilted = tilted || std::fabs(R_WC(2, 0)) > kLevel || std::fabs(R_WC(2, 1)) > kLevel;
  // Arrows: velocities from each CG at one time scale, the impulse at its own; the longest of each a
  // fixed share of the longest vehicle.
  double vmax = 0;
  for (int i = 0; i < 2; ++i)
    vmax = std::max({vmax, c.scene.body[i].v_W.norm() / fv, sol.after[i].v_W.norm() / fv});
  const double vscale = vmax > 0 ? 0.6 * longest / vmax : 0;
  const double pnorm = sol.P_W.norm() / fi, pscale = pnorm > 0 ? 0.45 * longest / pnorm : 0;
  const std::string strategy = case_format::strategy_label(c.spec.strategies[k]);
  std::vector<Arrow> arrows;
  for (int i = 0; i < 2; ++i) {
    const std::string who = fmt::format("vehicle {}", i + 1);
    arrows.push_back({who + " velocity before", cg[i], c.scene.body[i].v_W / fv, vscale, "lw 2.5 dt 1", "velocity before"});
    arrows.push_back({who + " velocity after", cg[i], sol.after[i].v_W / fv, vscale, "lw 2.5 dt 2", "velocity after (" + strategy + ")"});
  }
  arrows.push_back({"impulse on vehicle 1", V3::Zero(), sol.P_W / fi, pscale, "lw 3.5 lc rgb '#000000'", "impulse on vehicle 1"});
  const double axis = 0.3 * longest;
  const char* frame[3] = {"n", "t", "z"};
  for (int a = 0; a < 3; ++a)
    arrows.push_back({std::string("contact axis ") + frame[a], V3::Zero(), V3(R_WC.col(a)), axis, "lw 1.5 lc rgb '#555555'", ""});

  std::string csv = "label,from_x,from_y,from_z,value_x,value_y,value_z,drawn_per_unit\n";
  for (const auto& a : arrows)
    csv += fmt::format("{},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n", a.label, a.from.x(), a.from.y(), a.from.z(), a.value.x(),
                       a.value.y(), a.value.z(), a.scale);
  const std::string name = fmt::format("collision_{}", k + 1);
  c.dir.write(name + ".arrows.csv", csv);

  const V3 n = R_WC.col(0);
  V3 across(n.x(), n.y(), 0);
  across = across.norm() > kLevel ? across.normalized() : V3::UnitX();
  const std::vector<View> views = tilted ? std::vector<View>{{V3::UnitX(), V3::UnitY()}, {across, V3::UnitZ()}}
                                         : std::vector<View>{{V3::UnitX(), V3::UnitY()}};
  const char* view_title[2] = {"plan (from above; world x right, y up)", "elevation (along the normal's horizontal, z up)"};
  std::string dat;
  int block = 0;
  std::vector<std::vector<std::string>> items(views.size());
  const auto add = [&](std::size_t v, const std::string& data, const std::string& how) {
    dat += data + "\n\n";
    items[v].push_back(fmt::format("'{}.dat' index {} {}", name, block++, how));
  };
  for (std::size_t v = 0; v < views.size(); ++v) {
    const View& view = views[v];
    for (int i = 0; i < 2; ++i) {
      const auto& R = c.scene.body[i].R_WB;
      std::vector<Xy> pts;
      for (const V3& q : corners(box[i])) pts.push_back(view.at(cg[i] + R * q / fl));
      std::string outline;
      for (const auto& q : hull(pts)) outline += fmt::format("{:.17g},{:.17g}\n", q[0], q[1]);
      const std::string who = c.spec.vehicles[i].name.empty() ? fmt::format("vehicle {}", i + 1) : c.spec.vehicles[i].name;
      add(v, outline, fmt::format("with filledcurves closed fs transparent solid 0.18 border lc rgb '{0}' lw 1.5 fc rgb '{0}' {1}",
                                  kVehicleColour[i], v == 0 ? "title " + gnuplot_string(fmt::format("vehicle {}: {}", i + 1, who)) : "notitle"));
      // The front: from the CG to the middle of the front face.
      const Xy a = view.at(cg[i]), b = view.at(cg[i] + R * V3(box[i].front, 0, 0) / fl);
      add(v, fmt::format("{:.17g},{:.17g}\n{:.17g},{:.17g}\n", a[0], a[1], b[0], b[1]),
          fmt::format("with lines lw 1.5 dt 3 lc rgb '{}' {}", kVehicleColour[i], v == 0 && i == 0 ? "title 'CG to the front'" : "notitle"));
      add(v, fmt::format("{:.17g},{:.17g}\n", a[0], a[1]),
          fmt::format("with points pt 6 ps 1.5 lw 2 lc rgb '{}' {}", kVehicleColour[i], v == 0 && i == 0 ? "title 'CG'" : "notitle"));
    }
    add(v, "0,0\n", std::string("with points pt 7 ps 1.2 lc rgb '#000000' ") + (v == 0 ? "title 'impulse centre'" : "notitle"));
    std::vector<std::string> keyed;
    for (std::size_t j = 0; j < arrows.size(); ++j) {
      const auto& ar = arrows[j];
      const Xy from = view.at(ar.from), d = view.at(V3(ar.value * ar.scale));
      if (std::hypot(d[0], d[1]) <= kLevel * longest) continue;  // seen end on
      const int i = ar.label.rfind("vehicle 2", 0) == 0 ? 1 : 0;
      const std::string colour = ar.label.rfind("vehicle", 0) == 0 ? fmt::format(" lc rgb '{}'", kVehicleColour[i]) : "";
      std::string title = "notitle";
      if (v == 0 && !ar.key.empty() && std::find(keyed.begin(), keyed.end(), ar.key) == keyed.end()) {
        keyed.push_back(ar.key);
        title = "title " + gnuplot_string(ar.key);
      }
      add(v, fmt::format("{:.17g},{:.17g},{:.17g},{:.17g}\n", from[0], from[1], d[0], d[1]),
          fmt::format("with vectors head filled size screen 0.012,20 {}{} {}", ar.style, colour, title));
    }
  }
  c.dir.write(name + ".dat", dat);

  const std::string length_unit = case_format::unit_label(c.units, "length");
  std::vector<std::string> notes{fmt::format("arrows to scale: 1 {} of velocity = {:.3g} {}; the impulse on vehicle 1 ({:.6g} {}) = {:.3g} {}",
                                             c.vel_unit, vscale, length_unit, pnorm, c.imp_unit, pnorm * pscale, length_unit)};
  if (stand_in) notes.push_back("stand-in boxes (4.5 m x 1.8 m about the CG, reaching the impulse centre): the case gives no dimensions");
  std::string gp = figure_head(c, "the collision: " + strategy, tilted ? 1400 : 1000, 800, notes);
  gp += "set size ratio -1\nset key outside below Left reverse noenhanced\n";
  // The contact axes' names at their tips.
  for (int a = 0; a < 3; ++a) {
    const Xy tip = views[0].at(V3(R_WC.col(a) * axis * 1.12));
    if (std::hypot(tip[0], tip[1]) > 0.2 * axis) gp += fmt::format("set label {} '{}' at {:.17g},{:.17g} center\n", a + 1, frame[a], tip[0], tip[1]);
  }
  gp += fmt::format("set xlabel {0}\nset ylabel {0}\n", gnuplot_string("[" + length_unit + "]"));
  if (tilted)
    gp += fmt::format("unset title\nset multiplot layout 1,2 title {} noenhanced\n", title_lines(c, "the collision: " + strategy, notes));
  for (std::size_t v = 0; v < views.size(); ++v) {
    if (v == 1) {
      gp += "set key off\nunset label\n";
      for (int a = 0; a < 3; ++a) {
        const Xy tip = views[1].at(V3(R_WC.col(a) * axis * 1.12));
        if (std::hypot(tip[0], tip[1]) > 0.2 * axis) gp += fmt::format("set label {} '{}' at {:.17g},{:.17g} center\n", a + 1, frame[a], tip[0], tip[1]);
      }
    }
    if (tilted) gp += fmt::format("set title {}\n", gnuplot_string(view_title[v]));
    std::string plot = "plot ";
    for (std::size_t j = 0; j < items[v].size(); ++j) plot += (j ? ", \\\n     " : "") + items[v][j];
    gp += plot + "\n";
  }
  if (tilted) gp += "unset multiplot\n";
  c.draw(name, gp);
}

}  // namespace impact3d::cli
