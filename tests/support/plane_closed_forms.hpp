// The paper's closed forms on a solution plane at angle phi (eqs 17-20), written out for the tests from
// the printed equations; the library's direct engine never uses them.
#pragma once

#include <cmath>

#include "support.hpp"

namespace impact3d::test {

struct PlaneCoefficients {
  double a1, a2, b1, b2, r;  // eq 17 coefficients for the plane, and r = V_rCPi / V_rni (eq 19)
};

// Coefficients of eq 17 on the plane through n at angle phi from t towards z: K' = Q K Q^T with
// Q's rows n, u = (0, cos phi, sin phi), w = (0, -sin phi, cos phi).
inline PlaneCoefficients plane_coefficients(const M3& K, const V3& V_ri, double c, double s) {
  M3 Q;
  Q << 1, 0, 0, 0, c, s, 0, -s, c;
  const M3 Kp = Q * K * Q.transpose();
  return {Kp(0, 0), Kp(1, 0), Kp(0, 1), Kp(1, 1), (c * V_ri.y() + s * V_ri.z()) / V_ri.x()};
}

// Contact-plane components of v along and across the direction at angle phi (radians) from t to z.
struct InPlane {
  double along, across;
};
inline InPlane plane_components(double phi, const V3& v) {
  return {std::cos(phi) * v.y() + std::sin(phi) * v.z(), -std::sin(phi) * v.y() + std::cos(phi) * v.z()};
}

// eq 19
inline double eq19_cir(const PlaneCoefficients& k, double e) {
  return (k.r * k.a1 - (1 + e) * k.a2) / ((1 + e) * k.b2 - k.r * k.b1);
}
// eq 20
inline double eq20_gir(const PlaneCoefficients& k) { return (k.r * k.a1 - k.a2) / (k.b2 - k.r * k.b1); }
// eq 18
inline double eq18_Pn(const PlaneCoefficients& k, double m_prime, double e, double V_rni, double mu) {
  return m_prime * (1 + e) * V_rni / (k.a1 + mu * k.b1);
}

// A ratio mu = N / D of differences of O(|K|) coefficients times (1 + eps) or r: to first order its error
// is (dN - mu dD) / D, and each coefficient carries a few eps |K| from the assembly of K. So the error
// is bounded by c eps |K| (1 + |r|) (1 + e) (1 + |mu|) / |D|, which grows as D cancels (a ratio near
// infinity); c = 64 covers the roundings of both evaluations.
inline double quotient_tolerance(double mu, double D, const M3& K, double r, double e) {
  return 4 * rounding::arithmetic_roundoff(K.norm()) * (1 + std::abs(r)) * (1 + e) * (1 + std::abs(mu)) / std::abs(D);
}

inline double ratio_tolerance(const PlaneCoefficients& k, const M3& K, double e, double mu) {
  return quotient_tolerance(mu, (1 + e) * k.b2 - k.r * k.b1, K, k.r, e);
}

}  // namespace impact3d::test
