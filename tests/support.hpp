// Shared by the tests: seeded random collisions with products of inertia, tilted contact frames and
// pitched/rolled vehicles; the bundled examples; and tolerances in units of epsilon.
#pragma once

#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>

#include "impact3d/io/read_case.hpp"
#include "impact3d/numeric/analysis.hpp"

namespace impact3d::test {

using V3 = Vec3<double>;
using M3 = Mat3<double>;
constexpr double eps = std::numeric_limits<double>::epsilon();

inline std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

inline std::string example(const std::string& name) { return std::string(IMPACT3D_EXAMPLES_DIR) + "/" + name; }

inline io::CaseSpec load_spec(const std::string& path) { return io::read_case(read_text(path)); }

// A random rigid body: principal moments obeying the triangle inequality, turned by a random small
// rotation so that every product of inertia is non-zero.
inline RigidBody<double> random_body(std::mt19937_64& g) {
  std::uniform_real_distribution<double> u(0, 1);
  auto in = [&](double a, double b) { return a + (b - a) * u(g); };
  RigidBody<double> b;
  b.mass = in(700, 3500);
  const double ixx = in(300, 1500), iyy = in(1200, 6000), izz = iyy + in(0.5, 1.0) * ixx;
  const M3 Q = rotation_zyx_deg(in(-15, 15), in(-15, 15), in(-15, 15));
  b.J_B = Q * Eigen::Vector3d(ixx, iyy, izz).asDiagonal() * Q.transpose();
  b.J_B = (b.J_B + b.J_B.transpose()).eval() / 2;
  b.R_WB = rotation_zyx_deg(in(-180, 180), in(-12, 12), in(-12, 12));
  b.v_W = V3(in(-25, 25), in(-25, 25), in(-1, 1));
  b.w_B = V3(in(-0.3, 0.3), in(-0.3, 0.3), in(-1.5, 1.5));
  b.p_CgIc_B = V3(in(-2.6, 2.6), in(-1.0, 1.0), in(-0.5, 0.4));
  return b;
}

// A random approaching collision with a tilted, rolled contact frame and restitution in [0, 1].
inline Scene<double> random_scene(std::mt19937_64& g) {
  std::uniform_real_distribution<double> u(0, 1);
  for (;;) {
    Scene<double> s;
    s.body = {random_body(g), random_body(g)};
    s.R_WC = rotation_zyx_deg(-180 + 360 * u(g), -25 + 50 * u(g), -30 + 60 * u(g));
    s.restitution = u(g);
    if (relative_velocity_C(s).x() > 1.0) return s;
  }
}

// Both engines: the closed forms derived by symbolic/ and the direct 3x3 solves of the constraints.
constexpr Engine kEngines[] = {Engine::direct, Engine::generated};

template <typename S>
Solution<double> solve_one(const Scene<double>& s, const S& strategy, Engine engine = Engine::generated) {
  return analyze(s, std::vector<Strategy<double>>{Strategy<double>(strategy)}, engine).solutions.at(0);
}

inline std::vector<Strategy<double>> every_strategy(double mu) {
  return {PcCrash<double>{mu},           PcCrash<double>{0.05},
          PcCrash<double>{10.0},         Wach<double>{mu, WachLimit::cir},
          Wach<double>{mu, WachLimit::gir}, Wach<double>{10.0, WachLimit::cir},
          Brach<double>{mu, -0.1},       Brach<double>{std::nullopt, 0.1},
          Brach<double>{0.2, std::nullopt}, Brach<double>{std::nullopt, std::nullopt}};
}

// Scale of the velocities that enter a post-impact relative velocity (rounding.hpp).
using rounding::velocity_scale;

}  // namespace impact3d::test
