// One look per meaning across every figure: strategy k of a case has the same glyph and colour in the
// contact-plane view, its solution plane, the impulse space and the sweeps; the reference points (Full
// Impact, the Critical Impulse Line's point, maximum energy loss) have glyphs no strategy uses.
#pragma once

#include <array>
#include <cstddef>
#include <string>

#include <fmt/format.h>

namespace impact3d::cli {

struct Marker {
  int glyph;           // gnuplot point type
  const char* colour;  // '#rrggbb'
  std::string style(double size) const { return fmt::format("pt {} ps {:.2f} lw 2 lc rgb '{}'", glyph, size, colour); }
};

// Open glyphs first, so that concentric markers of coincident points stay visible; then filled ones.
inline Marker strategy_marker(std::size_t k) {
  static constexpr std::array<int, 12> glyphs{4, 6, 8, 12, 10, 14, 5, 7, 9, 13, 11, 15};
  // Okabe and Ito's palette, told apart with colour blindness.
  static constexpr std::array<const char*, 6> colours{"#d55e00", "#0072b2", "#009e73", "#cc79a7", "#e69f00", "#56b4e9"};
  return {glyphs[k % glyphs.size()], colours[k % colours.size()]};
}

inline constexpr Marker kFullImpactMarker{3, "#000000"};  // asterisk
inline constexpr Marker kNoSlidingMarker{2, "#8c564b"};   // cross: the Critical Impulse Line's point
inline constexpr Marker kMaxLossMarker{1, "#000000"};     // plus

// Lines and planes, the same in every figure.
namespace colour {
inline constexpr const char* max_compression = "#000000";
inline constexpr const char* restitution = "#7f7f7f";
inline constexpr const char* t_no_sliding = "#1f77b4";
inline constexpr const char* z_no_sliding = "#ff7f0e";
inline constexpr const char* critical_line = "#8c564b";
inline constexpr const char* pc_crash_plane = "#2ca02c";
inline constexpr const char* wach_plane = "#9467bd";
inline constexpr const char* gir = "#d62728";
inline constexpr const char* cir = "#17becf";
}  // namespace colour

}  // namespace impact3d::cli
