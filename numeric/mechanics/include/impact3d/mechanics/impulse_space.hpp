// The fundamental planes of impulse space (paper Figure 2) and the Critical Impulse Line.
//
// With V_rf = V_ri - K P / m', the plane on which the post-impact relative velocity along axis k is zero
// is K_k . P = m' V_rk (K_k the k-th row): k = n is the maximum-compression plane, k = t and k = z the
// no-sliding planes. Their common point is the maximum-energy-loss impulse (Full Impact at eps = 0);
// the t and z planes meet in the Critical Impulse Line, whose direction is K_t x K_z.
//
// Below them, the geometry the figures draw (plot only writes it out): computed here, from the same
// Problem and by the same engine as the analysis, so that a figure states what `solve` reports.
#pragma once

#include <cmath>
#include <optional>
#include <vector>

#include <Eigen/LU>

#include "impact3d/mechanics/decisions.hpp"
#include "impact3d/scalar/planar_norm.hpp"
#include "impact3d/mechanics/problem.hpp"

namespace impact3d {

template <typename Scalar>
struct ImpulseSpace {
  Vec3<Scalar> P_max_loss;         // contact axes
  Vec3<Scalar> cil_direction;      // unit; its P_n component is >= 0
  Mat3<Scalar> plane_normal;       // row k: unit normal of the plane of zero post-impact V_r along axis k
  Vec3<Scalar> plane_offset;       // row k: plane_normal.row(k) . P = plane_offset(k)
  Scalar restitution_offset;       // the case's restitution plane: plane_normal.row(0) . P = this
};

template <typename Engine, typename Scalar>
ImpulseSpace<Scalar> impulse_space(const Problem<Scalar>& p) {
  ImpulseSpace<Scalar> s;
  s.P_max_loss = Engine::full_impact(p, Scalar(0));
  for (int k = 0; k < 3; ++k) {
    const Scalar len = p.K.row(k).norm();
    s.plane_normal.row(k) = p.K.row(k) / len;
    s.plane_offset(k) = p.m_prime * p.V_ri(k) / len;
  }
  s.restitution_offset = p.m_prime * (Scalar(1) + p.restitution) * p.V_ri.x() / p.K.row(0).norm();
  Vec3<Scalar> d = p.K.row(1).transpose().cross(p.K.row(2).transpose());
  {
    const DecisionName<Scalar> name(decision_names::cil_direction);
    if (d.x() < Scalar(0)) d = -d;
  }
  s.cil_direction = d.normalized();
  return s;
}

// A point inside each of the paper's volumes A-D (Figure 2), `reach` from the maximum-energy-loss point:
// the volumes are cut by the maximum-compression plane (above it the bodies separate: A, B) and the t
// no-sliding plane (on the origin's side the t sliding continues: A, D; beyond it, it reverses: B, C).
// The point moves along a sum of the dual basis vectors of the three plane normals, so it crosses each
// of those two planes to the side wanted and stays on the z no-sliding plane. Empty without initial t sliding (no volumes then)
// or where the normals are dependent.
template <typename Scalar>
struct VolumePoint {
  char letter;
  Vec3<Scalar> P;  // contact axes
};

template <typename Scalar>
std::vector<VolumePoint<Scalar>> volume_points(const ImpulseSpace<Scalar>& s, const Scalar& reach) {
  std::vector<VolumePoint<Scalar>> out;
  const Scalar t_side = s.plane_offset(1);
  if (t_side == Scalar(0)) return out;
  const Eigen::FullPivLU<Mat3<Scalar>> lu(s.plane_normal);
  if (!lu.isInvertible()) return out;
  const Mat3<Scalar> dual = lu.inverse();  // column k: crosses plane k by 1, the others by 0
  for (const int separating : {1, -1})
    for (const bool continued : {true, false}) {
      // Continued: on the origin's side of the t plane, where n_t . P - offset_t has the sign of -offset_t.
      const Scalar across_t = (continued == (t_side > Scalar(0))) ? Scalar(-1) : Scalar(1);
      Vec3<Scalar> step = Scalar(separating) * dual.col(0) + across_t * dual.col(1);
      step *= reach / step.norm();
      const char letter = separating > 0 ? (continued ? 'A' : 'B') : (continued ? 'D' : 'C');
      out.push_back({letter, s.P_max_loss + step});
    }
  return out;
}

// A line a x + b y = r in a figure's coordinates.
template <typename Scalar>
struct Line2 {
  Scalar a, b, r;
};

// The contact-plane view (Figures 3-4 right): the case's restitution plane K_n . P = R, R = m' (1 + eps)
// V_rn, seen along n with P_n eliminated through it; coordinates (P_t, P_z).
template <typename Scalar>
struct ContactPlaneFigure {
  Vec3<Scalar> full_impact;                  // at the case's eps (eqs 10-12)
  std::optional<Vec3<Scalar>> no_sliding;    // the Critical Impulse Line on it (eq 27); empty where singular
  Scalar gir;                                // |P_cp| / P_n of the Full Impact (eq 14)
  Scalar restitution_rhs;                    // R
  Line2<Scalar> t_trace, z_trace;            // the no-sliding planes where they cross it
  Scalar phi_fi_deg, phi_deg;                // PC-Crash's plane (eq 15) and Wach's (eq 21), through n
};

// The trace on the restitution plane of the plane K_k . P = m' V_rk.
template <typename Scalar>
Line2<Scalar> restitution_trace(const Problem<Scalar>& p, int k, const Scalar& R) {
  const auto& K = p.K;
  return {K(k, 1) - K(k, 0) * K(0, 1) / K(0, 0), K(k, 2) - K(k, 0) * K(0, 2) / K(0, 0),
          p.m_prime * p.V_ri(k) - K(k, 0) * R / K(0, 0)};
}

template <typename Engine, typename Scalar>
ContactPlaneFigure<Scalar> contact_plane_figure(const Problem<Scalar>& p) {
  using std::atan2;
  ContactPlaneFigure<Scalar> f;
  f.full_impact = Engine::full_impact(p, p.restitution);
  try {
    f.no_sliding = Engine::brach_impulse(p, std::optional<Scalar>(), std::optional<Scalar>(), "critical impulse line");
  } catch (const SolveError&) {
  }
  f.gir = planar_norm(f.full_impact.y(), f.full_impact.z()) / f.full_impact.x();
  f.restitution_rhs = p.m_prime * (Scalar(1) + p.restitution) * p.V_ri.x();
  f.t_trace = restitution_trace(p, 1, f.restitution_rhs);
  f.z_trace = restitution_trace(p, 2, f.restitution_rhs);
  f.phi_fi_deg = degrees(Scalar(atan2(f.full_impact.z(), f.full_impact.y())));
  f.phi_deg = degrees(Scalar(atan2(p.V_ri.z(), p.V_ri.y())));
  return f;
}

// Where the GIR cone |P_cp| = GIR P_n meets the restitution plane, at angle theta from t towards z:
// rho = GIR R / (K_nn + GIR (K_nt cos + K_nz sin)); empty where the ray misses the cone.
template <typename Scalar>
std::optional<Scalar> gir_cone_radius(const Problem<Scalar>& p, const ContactPlaneFigure<Scalar>& f, const Scalar& theta) {
  using std::cos;
  using std::sin;
  const Scalar den = p.K(0, 0) + f.gir * (p.K(0, 1) * cos(theta) + p.K(0, 2) * sin(theta));
  if (!(den > Scalar(0))) return std::nullopt;
  return f.gir * f.restitution_rhs / den;
}

// A strategy's solution-plane view (Figures 4 right and 7): the plane through n the strategy used
// (phi_FI, Wach's phi; for Brach, which has none, the direction of its contact-plane impulse), with its
// axis u in the plane and w across it; coordinates (P_u, P_n).
template <typename Scalar>
struct SolutionPlaneFigure {
  PlaneAxes<Scalar> axes;
  Scalar angle_deg;                 // from t towards z
  Scalar cir, gir;                  // the strategy's own, where it reports them; else on this plane
  Scalar P_u, P_n;                  // the solution
  Line2<Scalar> max_compression, restitution, no_sliding_along, no_sliding_across;
};

template <typename Engine, typename Scalar>
SolutionPlaneFigure<Scalar> solution_plane_figure(const Problem<Scalar>& p, const ImpulseSolution<Scalar>& s) {
  using std::atan2;
  SolutionPlaneFigure<Scalar> f;
  const Vec3<Scalar>& P = s.P_C;
  if (s.plane) {
    f.axes = *s.plane;
  } else {
    const Scalar len = planar_norm(P.y(), P.z());
    f.axes = len > Scalar(0) ? PlaneAxes<Scalar>{P.y() / len, P.z() / len} : PlaneAxes<Scalar>{Scalar(1), Scalar(0)};
  }
  f.angle_deg = s.plane_angle_deg ? *s.plane_angle_deg : degrees(Scalar(atan2(f.axes.s, f.axes.c)));
  f.cir = s.cir ? *s.cir : Engine::plane_ratio(p, f.axes, p.restitution, "CIR (eq 19)");
  f.gir = s.gir ? *s.gir : Engine::plane_ratio(p, f.axes, Scalar(0), "GIR (eq 20)");
  const Vec3<Scalar> n = Vec3<Scalar>::UnitX(), u = f.axes.u(), w = f.axes.w();
  f.P_u = u.dot(P);
  f.P_n = P.x();
  // Row k of K . P = m' V_r,k restricted to the plane P = P_u u + P_n n.
  const auto line = [&](const Vec3<Scalar>& row, const Scalar& rhs) { return Line2<Scalar>{row.dot(u), row.dot(n), rhs}; };
  const Vec3<Scalar> Kn = p.K.row(0).transpose(), Ku = p.K.transpose() * u, Kw = p.K.transpose() * w;
  f.max_compression = line(Kn, p.m_prime * p.V_ri.x());
  f.restitution = line(Kn, p.m_prime * (Scalar(1) + p.restitution) * p.V_ri.x());
  f.no_sliding_along = line(Ku, p.m_prime * u.dot(p.V_ri));
  f.no_sliding_across = line(Kw, p.m_prime * w.dot(p.V_ri));
  return f;
}

}  // namespace impact3d
