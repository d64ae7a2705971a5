// A naive scalar implementation of the pc-crash impulse from raw parameters, written for the benchmarks as
// a user would write it from the paper: std::sin/cos, plain arrays, a 3x3 solve by Cramer's rule. It is
// a peer to measure against, not part of impact3d; tests/mechanics/check_naive_peers.cpp holds it to impact3d.
#pragma once

#include <cmath>
#include <numbers>

namespace impact3d::bench {

struct NaiveVehicle {
  double mass;
  double J[3][3];               // inertia tensor, body axes
  double yaw, pitch, roll;      // degrees
  double v[3], w[3], r[3];      // CG velocity (world), angular velocity (body), impulse centre (body)
};

struct NaiveCase {
  NaiveVehicle veh[2];
  double normal_yaw, normal_pitch, tangent_roll;  // degrees
  double restitution, mu;
};

struct NaiveImpulse {
  double P[3];  // on vehicle 1, contact axes
  bool full;    // the Full Impact (mu >= GIR), else the Sliding Impact on the phi_FI plane
};

namespace naive {

using M = double[3][3];

inline void rotation(double yaw, double pitch, double roll, M& R) {
  const double k = std::numbers::pi / 180;
  const double cy = std::cos(yaw * k), sy = std::sin(yaw * k), cp = std::cos(pitch * k), sp = std::sin(pitch * k),
               cr = std::cos(roll * k), sr = std::sin(roll * k);
  // Rz(yaw) Ry(pitch) Rx(roll)
  R[0][0] = cy * cp, R[0][1] = cy * sp * sr - sy * cr, R[0][2] = cy * sp * cr + sy * sr;
  R[1][0] = sy * cp, R[1][1] = sy * sp * sr + cy * cr, R[1][2] = sy * sp * cr - cy * sr;
  R[2][0] = -sp, R[2][1] = cp * sr, R[2][2] = cp * cr;
}

inline double det(const M& A) {
  return A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) - A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
         A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]);
}

inline void inverse(const M& A, M& X) {
  const double d = det(A);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const int i1 = (j + 1) % 3, i2 = (j + 2) % 3, j1 = (i + 1) % 3, j2 = (i + 2) % 3;
      X[i][j] = (A[i1][j1] * A[i2][j2] - A[i1][j2] * A[i2][j1]) / d;
    }
}

inline void solve(const M& A, const double b[3], double x[3]) {
  const double d = det(A);
  for (int k = 0; k < 3; ++k) {
    M Ak;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) Ak[i][j] = j == k ? b[i] : A[i][j];
    x[k] = det(Ak) / d;
  }
}

inline void cross(const double a[3], const double b[3], double c[3]) {
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

}  // namespace naive

inline NaiveImpulse naive_pc_crash(const NaiveCase& c) {
  using namespace naive;
  M RC;
  rotation(c.normal_yaw, c.normal_pitch, c.tangent_roll, RC);
  double K[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const double mp = c.veh[0].mass * c.veh[1].mass / (c.veh[0].mass + c.veh[1].mass);
  double V[3] = {0, 0, 0};  // vehicle 2's impulse-centre velocity minus vehicle 1's, world
  for (int i = 0; i < 2; ++i) {
    const NaiveVehicle& b = c.veh[i];
    M R, Ji, T;
    rotation(b.yaw, b.pitch, b.roll, R);
    inverse(b.J, Ji);
    for (int p = 0; p < 3; ++p)  // T = RC^T R: vehicle axes -> contact axes
      for (int q = 0; q < 3; ++q) T[p][q] = RC[0][p] * R[0][q] + RC[1][p] * R[1][q] + RC[2][p] * R[2][q];
    double wr[3];
    cross(b.w, b.r, wr);
    for (int p = 0; p < 3; ++p) {
      const double v = b.v[p] + R[p][0] * wr[0] + R[p][1] * wr[1] + R[p][2] * wr[2];
      V[p] += i == 0 ? -v : v;
    }
    // K += m' T [r]x^T J^-1 [r]x T^T, column by column: [r]x T^T e_k = r x (T^T e_k).
    for (int k = 0; k < 3; ++k) {
      const double e[3] = {T[k][0], T[k][1], T[k][2]};
      double a[3], Ja[3], s[3];
      cross(b.r, e, a);
      for (int p = 0; p < 3; ++p) Ja[p] = Ji[p][0] * a[0] + Ji[p][1] * a[1] + Ji[p][2] * a[2];
      cross(Ja, b.r, s);  // [r]x^T y = y x r
      for (int p = 0; p < 3; ++p) K[p][k] += mp * (T[p][0] * s[0] + T[p][1] * s[1] + T[p][2] * s[2]);
    }
  }
  double Vc[3];
  for (int p = 0; p < 3; ++p) Vc[p] = RC[0][p] * V[0] + RC[1][p] * V[1] + RC[2][p] * V[2];
  // Full Impact: K P = m' (1 + eps) V_ri.
  const double f = mp * (1 + c.restitution);
  const double rhs[3] = {f * Vc[0], f * Vc[1], f * Vc[2]};
  NaiveImpulse out{};
  solve(K, rhs, out.P);
  const double Pcp = std::hypot(out.P[1], out.P[2]);
  out.full = c.mu >= Pcp / out.P[0];
  if (out.full) return out;
  // Sliding Impact on the phi_FI plane (eqs 15-18).
  const double cphi = out.P[1] / Pcp, sphi = out.P[2] / Pcp;
  const double Pn = f * Vc[0] / (K[0][0] + c.mu * (K[0][1] * cphi + K[0][2] * sphi));
  out.P[0] = Pn;
  out.P[1] = c.mu * cphi * Pn;
  out.P[2] = c.mu * sphi * Pn;
  return out;
}

}  // namespace impact3d::bench
