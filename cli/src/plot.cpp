#include "plot.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>

#include "impact3d/case/read_case.hpp"

namespace impact3d::cli {
namespace {

namespace fs = std::filesystem;
using V3 = Vec3<double>;

struct Context {
  const io::CaseSpec& spec;
  const PlotOptions& o;
  const Scene<double>& scene;  // SI
  const Analysis<double>& a;
  Problem<double> p;
  UnitFactors<double> f;
  std::string imp_unit, vel_unit, energy_unit;
  std::string written;
};

std::string esc(const std::string& s) {  // a gnuplot double-quoted string
  std::string out;
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out;
}

void write_file(const fs::path& p, const std::string& text) {
  std::ofstream out(p, std::ios::binary);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + p.string());
}

std::string terminal(const Context& c, const std::string& name, int w = 800, int h = 600) {
  const std::string ext = c.o.png ? "png" : "svg";
  return fmt::format("set terminal {} size {},{}\nset output \"{}.{}\"\n", c.o.png ? "png" : "svg enhanced", w, h, name, ext);
}

void run_gnuplot(Context& c, const std::string& name, const std::string& script) {
  const fs::path dir = c.o.out_dir;
  write_file(dir / (name + ".gp"), script);
  const std::string cmd = fmt::format("cd '{}' && gnuplot '{}.gp' 2>&1", dir.string(), name);
  FILE* pipe = popen(cmd.c_str(), "r");
  if (!pipe) throw std::runtime_error("cannot run gnuplot");
  std::string output;
  char buf[512];
  while (fgets(buf, sizeof buf, pipe)) output += buf;
  const int status = pclose(pipe);
  if (status != 0) throw std::runtime_error("gnuplot failed on " + name + ".gp: " + output.substr(0, 300));
  c.written += name + (c.o.png ? ".png" : ".svg") + "\n";
}

// Two far points of the line a x + b y = r, for drawing (the plot's range clips them).
std::string line_segment(double a, double b, double r, double extent) {
  const double n2 = a * a + b * b;
  if (n2 == 0) return "\n\n";
  const double x0 = r * a / n2, y0 = r * b / n2, len = std::sqrt(n2);
  const double dx = -b / len * extent, dy = a / len * extent;
  return fmt::format("{:.17g},{:.17g}\n{:.17g},{:.17g}\n\n\n", x0 - dx, y0 - dy, x0 + dx, y0 + dy);
}

struct Point {
  std::string label;
  double x, y, z = 0;
};

// The solution points of a figure: written to NAME.points.csv, and drawn from it one plot item each,
// so that the picture shows exactly the numbers in the file.
std::string points_file(const fs::path& dir, const std::string& name, const std::string& header, const std::vector<Point>& pts,
                        bool three_d) {
  std::string csv = header + "\n";
  for (const auto& q : pts)
    csv += three_d ? fmt::format("{},{:.17g},{:.17g},{:.17g}\n", q.label, q.x, q.y, q.z)
                   : fmt::format("{},{:.17g},{:.17g}\n", q.label, q.x, q.y);
  write_file(dir / (name + ".points.csv"), csv);
  std::string items;
  for (std::size_t i = 0; i < pts.size(); ++i)
    items += fmt::format(", \\\n     '{}.points.csv' every ::{}::{} using {} with points pt {} ps 2 lw 2 title \"{}\" noenhanced", name, i + 1,
                         i + 1, three_d ? "2:3:4" : "2:3", 4 + static_cast<int>(i), esc(pts[i].label));
  return items;
}

std::string header_lines(const Context& c, const std::string& name, const std::string& title, int w = 900, int h = 700) {
  // clip two: a line whose two ends lie beyond the range is still drawn where it crosses it.
  return terminal(c, name, w, h) + "set datafile separator comma\nset grid\nset clip two\nset key below noenhanced\n" +
         fmt::format("set title \"{}\\n{}\" noenhanced\n", esc(c.spec.name), esc(title));
}

std::string label(const io::StrategySpec& s) { return io::strategy_label(s); }

// `plot` (or `splot`) of the data sets of FILE.dat in order, each with its line style and title.
struct Series {
  std::string style, title;
};
std::string series(const std::string& verb, const std::string& file, const std::vector<Series>& list) {
  std::string out = verb + " ";
  for (std::size_t i = 0; i < list.size(); ++i)
    out += fmt::format("{}'{}.dat' index {} with lines {} title '{}'", i ? ", \\\n      " : "", file, i, list[i].style, list[i].title);
  return out;
}

// The point of the Critical Impulse Line on the case's restitution plane: no sliding at all.
V3 critical_line_point(const Problem<double>& p) {
  return direct::DirectEngine::brach_impulse(p, std::optional<double>(), std::optional<double>(), "critical impulse line");
}

double case_gir(const Problem<double>& p) {
  const V3 P = direct::DirectEngine::full_impact(p, p.restitution);
  return std::hypot(P.y(), P.z()) / P.x();
}

void contact_plane_view(Context& c) {
  const auto& p = c.p;
  const auto& K = p.K;
  const double s = c.f.impulse, R = p.m_prime * (1 + p.restitution) * p.V_ri.x();
  const V3 fi = direct::DirectEngine::full_impact(p, p.restitution), cil = critical_line_point(p);
  std::vector<Point> pts{{"Full Impact", fi.y() / s, fi.z() / s}, {"no sliding (Critical Impulse Line)", cil.y() / s, cil.z() / s}};
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
  const double margin = std::max({0.6 * (x1 - x0), 0.6 * (y1 - y0), 0.15 * extent});
  // Traces on the restitution plane (P_n eliminated through it) of the t and z no-sliding planes.
  std::string dat;
  dat += line_segment(K(1, 1) - K(1, 0) * K(0, 1) / K(0, 0), K(1, 2) - K(1, 0) * K(0, 2) / K(0, 0),
                      (p.m_prime * p.V_ri.y() - K(1, 0) * R / K(0, 0)) / s, 3 * extent);
  dat += line_segment(K(2, 1) - K(2, 0) * K(0, 1) / K(0, 0), K(2, 2) - K(2, 0) * K(0, 2) / K(0, 0),
                      (p.m_prime * p.V_ri.z() - K(2, 0) * R / K(0, 0)) / s, 3 * extent);
  // The solution planes of PC-Crash (phi_FI, eq 15) and Wach (phi, eq 21) through the origin.
  for (double phi : {std::atan2(fi.z(), fi.y()), std::atan2(p.V_ri.z(), p.V_ri.y())})
    dat += fmt::format("{:.17g},{:.17g}\n{:.17g},{:.17g}\n\n\n", -3 * extent * std::cos(phi), -3 * extent * std::sin(phi),
                       3 * extent * std::cos(phi), 3 * extent * std::sin(phi));
  // The GIR cone |P_cp| = GIR P_n cut by the restitution plane: rho = GIR R / (a1 + GIR (b1 cos + c1 sin)).
  const double gir = case_gir(p);
  for (int i = 0; i <= 360; ++i) {
    const double th = i * M_PI / 180, den = K(0, 0) + gir * (K(0, 1) * std::cos(th) + K(0, 2) * std::sin(th));
    if (den <= 0) {
      dat += "\n";
      continue;
    }
    dat += fmt::format("{:.17g},{:.17g}\n", gir * R / den / s * std::cos(th), gir * R / den / s * std::sin(th));
  }
  const fs::path dir = c.o.out_dir;
  write_file(dir / "contact_plane.dat", dat);
  std::string gp = header_lines(c, "contact_plane", "contact-plane view on the restitution plane (eps = " + c.spec.restitution.text + ")");
  gp += fmt::format("set xlabel \"P_t [{}]\"\nset ylabel \"P_z [{}]\"\n", c.imp_unit, c.imp_unit);
  gp += fmt::format("set xrange [{:.6g}:{:.6g}]\nset yrange [{:.6g}:{:.6g}]\n", x0 - margin, x1 + margin, y0 - margin, y1 + margin);
  gp += series("plot", "contact_plane", {{"lw 2 lc rgb '#1f77b4'", "t no-sliding plane"},
                                         {"lw 2 lc rgb '#ff7f0e'", "z no-sliding plane"},
                                         {"dt 2 lc rgb '#2ca02c'", "PC-Crash plane (phi_FI)"},
                                         {"dt 3 lc rgb '#9467bd'", "Wach plane (phi)"},
                                         {"lc rgb '#7f7f7f'", "GIR cone"}});
  gp += points_file(dir, "contact_plane", "label,P_t,P_z", pts, false) + "\n";
  run_gnuplot(c, "contact_plane", gp);
}

// P_n against the in-plane impulse on the plane through n and the strategy's contact-plane impulse
// (for pc-crash the phi_FI plane, for Wach the phi plane): Figures 4 right and 7.
void solution_plane_view(Context& c, std::size_t k) {
  const auto& p = c.p;
  const auto& K = p.K;
  const double s = c.f.impulse;
  const V3& P = c.a.solutions[k].impulse.P_C;
  const double len = std::hypot(P.y(), P.z());
  const PlaneAxes<double> ax = len > 0 ? PlaneAxes<double>{P.y() / len, P.z() / len} : PlaneAxes<double>{1, 0};
  const V3 n = V3::UnitX(), u = ax.u(), w = ax.w();
  const Point sol{label(c.spec.strategies[k]), u.dot(P) / s, P.x() / s};
  const double cir = direct::DirectEngine::plane_ratio(p, ax, p.restitution, "CIR");
  const double gir = direct::DirectEngine::plane_ratio(p, ax, 0.0, "GIR");
  const double ymax = 1.6 * std::max(sol.y, p.m_prime * (1 + p.restitution) * p.V_ri.x() / K(0, 0) / s);
  const double xs[] = {sol.x, gir * ymax, cir * ymax, 0.0};
  double xmin = 0, xmax = 0;
  for (double x : xs) xmin = std::min(xmin, x), xmax = std::max(xmax, x);
  const double pad = 0.15 * (xmax - xmin + 1e-300);
  std::string dat;
  // Lines of the plane, in (x, y) = (P_u, P_n): coefficients (K_row . u, K_row . n).
  auto line = [&](const V3& row, double rhs) { return line_segment(row.dot(u), row.dot(n), rhs / s, 10 * (ymax + xmax - xmin)); };
  const V3 Kn = K.row(0).transpose(), Ku = K.transpose() * u, Kw = K.transpose() * w;
  dat += line(Kn, p.m_prime * p.V_ri.x());                      // maximum compression
  dat += line(Kn, p.m_prime * (1 + p.restitution) * p.V_ri.x());  // restitution
  dat += line(Ku, p.m_prime * u.dot(p.V_ri));                   // no sliding along the plane
  dat += line(Kw, p.m_prime * w.dot(p.V_ri));                   // no sliding across it
  for (double mu : {cir, gir}) dat += fmt::format("0,0\n{:.17g},{:.17g}\n\n\n", mu * 10 * ymax, 10 * ymax);
  const std::string name = fmt::format("solution_plane_{}", k + 1);
  const fs::path dir = c.o.out_dir;
  write_file(dir / (name + ".dat"), dat);
  std::string gp = header_lines(c, name, fmt::format("solution plane of {} (angle {:.4g} deg from t towards z)", label(c.spec.strategies[k]),
                                                     std::atan2(ax.s, ax.c) * 180 / M_PI));
  gp += fmt::format("set xlabel \"in-plane impulse P_u [{}]\"\nset ylabel \"P_n [{}]\"\n", c.imp_unit, c.imp_unit);
  gp += fmt::format("set xrange [{:.6g}:{:.6g}]\nset yrange [0:{:.6g}]\n", xmin - pad, xmax + pad, ymax);
  gp += series("plot", name, {{"lw 2 lc rgb '#000000'", "maximum compression"},
                              {"dt 2 lc rgb '#000000'", "restitution (eps = " + c.spec.restitution.text + ")"},
                              {"lw 2 lc rgb '#1f77b4'", "no sliding along the plane"},
                              {"lw 2 lc rgb '#ff7f0e'", "no sliding across the plane"},
                              {"dt 3 lc rgb '#2ca02c'", fmt::format("CIR = {:.4g}", cir)},
                              {"dt 4 lc rgb '#d62728'", fmt::format("GIR = {:.4g}", gir)}});
  gp += points_file(dir, name, "label,P_u,P_n", {sol}, false) + "\n";
  run_gnuplot(c, name, gp);
}

// The three fundamental planes, the restitution plane, the Critical Impulse Line and the solutions in
// impulse space (P_t, P_z, P_n): Figures 2-3 left.
void impulse_space_view(Context& c) {
  const auto& p = c.p;
  const double s = c.f.impulse;
  const V3 P0 = c.a.space.P_max_loss, cil = critical_line_point(p), d = c.a.space.cil_direction;
  const double L = 0.5 * P0.norm();
  std::string dat;
  // A square patch of a plane (unit normal nrm) centred at `centre`, as a mesh of lines.
  auto patch = [&](const V3& nrm, const V3& centre) {
    V3 e1 = nrm.cross(V3::UnitX());
    if (e1.norm() < 1e-6) e1 = nrm.cross(V3::UnitY());
    e1.normalize();
    const V3 e2 = nrm.cross(e1).normalized();
    for (int i = -2; i <= 2; ++i)
      for (const auto& [a, b] : {std::pair{e1, e2}, std::pair{e2, e1}}) {
        const V3 q0 = centre + L * (0.5 * i * a - b), q1 = centre + L * (0.5 * i * a + b);
        dat += fmt::format("{:.17g},{:.17g},{:.17g}\n{:.17g},{:.17g},{:.17g}\n\n", q0.y() / s, q0.z() / s, q0.x() / s, q1.y() / s,
                           q1.z() / s, q1.x() / s);
      }
    dat += "\n";
  };
  for (int k = 0; k < 3; ++k) patch(c.a.space.plane_normal.row(k).transpose(), P0);
  patch(c.a.space.plane_normal.row(0).transpose(), cil);  // the case's restitution plane, through the CIL point
  const V3 a0 = P0 - 1.5 * L * d, a1 = P0 + 3 * L * d;
  dat += fmt::format("{:.17g},{:.17g},{:.17g}\n{:.17g},{:.17g},{:.17g}\n\n\n", a0.y() / s, a0.z() / s, a0.x() / s, a1.y() / s, a1.z() / s,
                     a1.x() / s);
  std::vector<Point> pts{{"maximum energy loss", P0.y() / s, P0.z() / s, P0.x() / s}};
  for (std::size_t k = 0; k < c.a.solutions.size(); ++k) {
    const V3& P = c.a.solutions[k].impulse.P_C;
    pts.push_back({label(c.spec.strategies[k]), P.y() / s, P.z() / s, P.x() / s});
  }
  const fs::path dir = c.o.out_dir;
  write_file(dir / "impulse_space.dat", dat);
  std::string gp = header_lines(c, "impulse_space", "impulse space: fundamental planes, restitution plane, Critical Impulse Line", 1000, 800);
  gp += fmt::format("set xlabel \"P_t [{0}]\"\nset ylabel \"P_z [{0}]\"\nset zlabel \"P_n [{0}]\" rotate\nset view 62, 35\nset xyplane 0\n", c.imp_unit);
  gp += series("splot", "impulse_space", {{"lc rgb '#000000'", "maximum-compression plane"},
                                          {"lc rgb '#1f77b4'", "t no-sliding plane"},
                                          {"lc rgb '#ff7f0e'", "z no-sliding plane"},
                                          {"dt 2 lc rgb '#7f7f7f'", "restitution plane"},
                                          {"lw 3 lc rgb '#d62728'", "Critical Impulse Line"}});
  gp += points_file(dir, "impulse_space", "label,P_t,P_z,P_n", pts, true) + "\n";
  run_gnuplot(c, "impulse_space", gp);
}

// Post-impact sliding along t and z, swerve and energy loss against mu (0 to 1.5 GIR) and against eps.
void sweeps(Context& c, std::size_t k) {
  const io::StrategySpec& spec = c.spec.strategies[k];
  const double gir = case_gir(c.p);
  auto with_mu = [&](double mu) -> Strategy<double> {
    switch (spec.kind) {
      case io::StrategySpec::Kind::pc_crash: return PcCrash<double>{mu};
      case io::StrategySpec::Kind::wach: return Wach<double>{mu, spec.limit};
      default: {
        Brach<double> b;
        b.mu_t = mu;
        if (spec.mu_z) b.mu_z = io::to_scalar<double>(*spec.mu_z);
        return b;
      }
    }
  };
  const Strategy<double> as_given = io::to_strategy<double>(spec);
  const double fv = c.f.velocity, fe = c.f.energy;
  for (const bool over_mu : {true, false}) {
    std::string csv = over_mu ? "mu,V_t_after,V_z_after,swerve_deg,energy_loss\n" : "eps,V_t_after,V_z_after,swerve_deg,energy_loss\n";
    const int n = over_mu ? 60 : 40;
    bool swerve_defined = false;
    for (int i = 0; i <= n; ++i) {
      const double x = over_mu ? 1.5 * gir * i / n : static_cast<double>(i) / n;
      Scene<double> sc = c.scene;
      if (!over_mu) sc.restitution = x;
      try {
        const Solution<double> sol = analyze(sc, {over_mu ? with_mu(x) : as_given}, c.o.engine).solutions[0];
        swerve_defined = swerve_defined || sol.swerve_deg.has_value();
        csv += fmt::format("{:.17g},{:.17g},{:.17g},{},{:.17g}\n", x, sol.V_rf.y() / fv, sol.V_rf.z() / fv,
                           sol.swerve_deg ? fmt::format("{:.17g}", *sol.swerve_deg) : std::string("NaN"), sol.energy_loss / fe);
      } catch (const SolveError&) {
        csv += "\n";  // no impulse at this value: a gap in the curves
      }
    }
    const std::string name = fmt::format("sweep_{}_{}", over_mu ? "mu" : "eps", k + 1);
    write_file(fs::path(c.o.out_dir) / (name + ".csv"), csv);
    const std::string xl = over_mu ? (spec.kind == io::StrategySpec::Kind::brach ? "mu_t" : "mu") : "restitution eps";
    std::string gp = header_lines(c, name, fmt::format("{} against {} ({})", label(spec), xl, over_mu ? "0 to 1.5 GIR" : "0 to 1"), 1000, 800);
    gp += fmt::format("set key off\nunset title\nset multiplot layout 2,2 title \"{}\\n{} against {}\" noenhanced\n", esc(c.spec.name),
                      esc(label(spec)), xl);
    const char* titles[] = {"sliding along t after", "sliding along z after (swerve)", "swerve angle", "energy loss"};
    const std::string units[] = {c.vel_unit, c.vel_unit, "deg", c.energy_unit};
    for (int q = 0; q < 4; ++q) {
      if (q == 2 && !swerve_defined) {  // no sliding after the impact anywhere: nothing to draw
        gp += "set title \"swerve angle\"\nunset xlabel\nunset ylabel\nset label 1 \"no sliding after the impact: swerve undefined\" "
              "at graph 0.5, 0.5 center\nset xrange [0:1]\nset yrange [0:1]\nunset xtics\nunset ytics\nplot 2 notitle\n"
              "unset label 1\nset xtics\nset ytics\nset autoscale\n";
        continue;
      }
      gp += fmt::format("set title \"{}\"\nset xlabel \"{}\" noenhanced\nset ylabel \"[{}]\"\nplot '{}.csv' using 1:{} skip 1 with linespoints pt 7 ps 0.4\n",
                        titles[q], xl, units[q], name, q + 2);
    }
    gp += "unset multiplot\n";
    run_gnuplot(c, name, gp);
  }
}

}  // namespace

std::string plot(const io::CaseSpec& spec, const PlotOptions& o) {
  if (std::system("gnuplot --version >/dev/null 2>&1") != 0)
    throw std::runtime_error("gnuplot not found: install it (Debian: apt-get install gnuplot-nox) or put it on PATH");
  fs::create_directories(o.out_dir);
  const Scene<double> scene = io::to_scene<double>(spec);
  const Analysis<double> a = analyze(scene, io::to_strategies<double>(spec), o.engine);
  Context c{spec, o, scene, a, problem_of(a, scene.restitution), unit_factors<double>(spec.units),
            io::unit_label(spec.units, "impulse"), io::unit_label(spec.units, "velocity"), io::unit_label(spec.units, "energy"), ""};
  contact_plane_view(c);
  for (std::size_t k = 0; k < a.solutions.size(); ++k) solution_plane_view(c, k);
  impulse_space_view(c);
  for (std::size_t k = 0; k < a.solutions.size(); ++k) sweeps(c, k);
  return c.written;
}

}  // namespace impact3d::cli
