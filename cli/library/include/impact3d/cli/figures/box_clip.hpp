// Planes and lines cut to the box a 3D figure draws, so that each is a shaded polygon or a segment
// inside it and nothing is left for gnuplot to clip (it drops polygons that cross the range).
#pragma once

#include <array>
#include <optional>
#include <vector>

namespace impact3d::cli {

using P3 = std::array<double, 3>;

struct Box {
  P3 lo, hi;
  bool inside(const P3& p, double slack = 1e-9) const;
};

// The polygon where the plane normal . p = offset meets the box, its vertices in order around it;
// empty where they do not meet (or meet in an edge or a corner).
std::vector<P3> plane_in_box(const P3& normal, double offset, const Box& box);

// The part of the line origin + s direction inside the box, as its two ends; empty where it misses.
std::optional<std::array<P3, 2>> line_in_box(const P3& origin, const P3& direction, const Box& box);

}  // namespace impact3d::cli
