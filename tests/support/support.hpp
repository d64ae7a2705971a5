// Shared by the tests: seeded random collisions with products of inertia, tilted contact frames and
// pitched/rolled vehicles; the bundled examples' paths; and tolerances in units of epsilon. Mechanics
// only: a test that reads a case file includes case_files.hpp and links the case format.
#pragma once

#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>

#include <Eigen/Eigenvalues>

#include "impact3d/mechanics/analysis.hpp"

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

struct Range {
  double lo, hi;
};
// A number drawn from [lo, hi).
inline double draw(std::mt19937_64& g, Range r) {
  std::uniform_real_distribution<double> u(0, 1);
  return r.lo + (r.hi - r.lo) * u(g);
}
// Three numbers drawn so, the last first: the order GCC gives a call's arguments, so that a seed draws
// the collisions it always drew. The order of a call's arguments is unspecified (clang takes the first
// first); drawn inside one, the same seed gave other collisions under clang. Draw each number of a call
// in a statement of its own.
inline V3 draw3(std::mt19937_64& g, Range x, Range y, Range z) {
  const double c = draw(g, z), b = draw(g, y), a = draw(g, x);
  return V3(a, b, c);
}
// A rotation of yaw, pitch and roll (degrees) drawn so.
inline M3 random_rotation(std::mt19937_64& g, Range yaw, Range pitch, Range roll) {
  const V3 a = draw3(g, yaw, pitch, roll);
  return rotation_zyx_deg(a.x(), a.y(), a.z());
}

// A random rigid body: principal moments obeying the triangle inequality, turned by a random small
// rotation so that every product of inertia is non-zero.
inline RigidBody<double> random_body(std::mt19937_64& g) {
  RigidBody<double> b;
  b.mass = draw(g, {700, 3500});
  const double ixx = draw(g, {300, 1500}), iyy = draw(g, {1200, 6000}), izz = iyy + draw(g, {0.5, 1.0}) * ixx;
  const M3 Q = random_rotation(g, {-15, 15}, {-15, 15}, {-15, 15});
  b.J_B = Q * Eigen::Vector3d(ixx, iyy, izz).asDiagonal() * Q.transpose();
  b.J_B = (b.J_B + b.J_B.transpose()).eval() / 2;
  b.R_WB = random_rotation(g, {-180, 180}, {-12, 12}, {-12, 12});
  b.v_W = draw3(g, {-25, 25}, {-25, 25}, {-1, 1});
  b.w_B = draw3(g, {-0.3, 0.3}, {-0.3, 0.3}, {-1.5, 1.5});
  b.p_CgIc_B = draw3(g, {-2.6, 2.6}, {-1.0, 1.0}, {-0.5, 0.4});
  return b;
}

// A random approaching collision with a tilted, rolled contact frame and restitution in [0, 1].
inline Scene<double> random_scene(std::mt19937_64& g) {
  std::uniform_real_distribution<double> u(0, 1);
  for (;;) {
    Scene<double> s;
    s.body = {random_body(g), random_body(g)};
    s.R_WC = random_rotation(g, {-180, 180}, {-25, 25}, {-30, 30});
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

// Every strategy of every_strategy and Stronge's three laws, which floating precisions alone solve.
inline std::vector<Strategy<double>> every_floating_strategy(double mu) {
  std::vector<Strategy<double>> out = every_strategy(mu);
  for (const auto law : {stronge::RestitutionLaw::energetic, stronge::RestitutionLaw::poisson, stronge::RestitutionLaw::newton})
    out.push_back(Stronge<double>{mu, law});
  return out;
}

// Scale of the velocities that enter a post-impact relative velocity (rounding.hpp).
using rounding::velocity_scale;

// cond(J) of the worse-conditioned vehicle: the engines invert J differently (adjugate over
// determinant, Cholesky), each accurate to about eps cond(J).
inline double inertia_condition(const Scene<double>& s) {
  double c = 1;
  for (const auto& b : s.body) {
    Eigen::SelfAdjointEigenSolver<M3> eig(b.J_B, Eigen::EigenvaluesOnly);
    c = std::max(c, eig.eigenvalues().maxCoeff() / eig.eigenvalues().minCoeff());
  }
  return c;
}

}  // namespace impact3d::test
