#include "impact3d/cli/figures/box_clip.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace impact3d::cli {
namespace {

double dot(const P3& a, const P3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
P3 sub(const P3& a, const P3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
P3 cross(const P3& a, const P3& b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }

}  // namespace

bool Box::inside(const P3& p, double slack) const {
  for (int k = 0; k < 3; ++k) {
    const double s = slack * (hi[k] - lo[k]);
    if (p[k] < lo[k] - s || p[k] > hi[k] + s) return false;
  }
  return true;
}

std::vector<P3> plane_in_box(const P3& normal, double offset, const Box& box) {
  std::vector<P3> corners;
  for (int i = 0; i < 8; ++i) corners.push_back({i & 1 ? box.hi[0] : box.lo[0], i & 2 ? box.hi[1] : box.lo[1], i & 4 ? box.hi[2] : box.lo[2]});
  std::vector<P3> hits;
  for (int i = 0; i < 8; ++i)
    for (int k = 0; k < 3; ++k) {
      const int j = i | (1 << k);
      if (j == i) continue;  // each edge once, from its lower corner
      const double fi = dot(normal, corners[i]) - offset, fj = dot(normal, corners[j]) - offset;
      if (fi == 0) hits.push_back(corners[i]);
      if ((fi < 0 && fj > 0) || (fi > 0 && fj < 0)) {
        const double t = fi / (fi - fj);
        const P3& a = corners[i];
        const P3& b = corners[j];
        hits.push_back({a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])});
      }
    }
  if (dot(normal, corners[7]) - offset == 0) hits.push_back(corners[7]);
  if (hits.size() < 3) return {};
  P3 centre{0, 0, 0};
  for (const auto& h : hits)
    for (int k = 0; k < 3; ++k) centre[k] += h[k] / static_cast<double>(hits.size());
  // Order by angle about the centre in the plane.
  const P3 e1 = sub(hits[0], centre);
  const P3 e2 = cross(normal, e1);
  std::vector<std::pair<double, P3>> around;
  for (const auto& h : hits) {
    const P3 d = sub(h, centre);
    around.push_back({std::atan2(dot(d, e2), dot(d, e1)), h});
  }
  std::sort(around.begin(), around.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<P3> out;
  const double span = std::max({box.hi[0] - box.lo[0], box.hi[1] - box.lo[1], box.hi[2] - box.lo[2]});
  for (const auto& [angle, q] : around) {
    (void)angle;
    if (out.empty() || std::sqrt(dot(sub(q, out.back()), sub(q, out.back()))) > 1e-12 * span) out.push_back(q);
  }
  if (out.size() >= 2 && std::sqrt(dot(sub(out.front(), out.back()), sub(out.front(), out.back()))) <= 1e-12 * span) out.pop_back();
  if (out.size() < 3) return {};
  return out;
}

std::optional<std::array<P3, 2>> line_in_box(const P3& origin, const P3& direction, const Box& box) {
  double s0 = -std::numeric_limits<double>::infinity(), s1 = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    if (direction[k] == 0) {
      if (origin[k] < box.lo[k] || origin[k] > box.hi[k]) return std::nullopt;
      continue;
    }
    double a = (box.lo[k] - origin[k]) / direction[k], b = (box.hi[k] - origin[k]) / direction[k];
    if (a > b) std::swap(a, b);
    s0 = std::max(s0, a);
    s1 = std::min(s1, b);
  }
  if (!(s0 < s1)) return std::nullopt;
  const auto at = [&](double s) { return P3{origin[0] + s * direction[0], origin[1] + s * direction[1], origin[2] + s * direction[2]}; };
  return std::array<P3, 2>{at(s0), at(s1)};
}

}  // namespace impact3d::cli
