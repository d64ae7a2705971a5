// --precision certified[:BITS], for render(): the ball arithmetic of scalar/ball.hpp.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "impact3d/studies/precision.hpp"

namespace impact3d::studies {
using namespace case_format;  // the studies are written in the case format's terms

// The bits a user may ask for: fewer than 16 certify no digit of a double; beyond 8192 a solve takes
// seconds and its digits are more than any reconstruction has.
inline constexpr long kMinCertifiedBits = 16, kMaxCertifiedBits = 8192;
// Without BITS: 256 bits, doubled while a decision is undecided (not a tie) or the impulse's relative
// radius exceeds kCertifiedWidth, up to kMaxDefaultCertifiedBits. The text report prints up to
// kCertifiedTextDigits certified digits (--digits changes it).
inline constexpr long kDefaultCertifiedBits = 256, kMaxDefaultCertifiedBits = 4096;
inline constexpr double kCertifiedWidth = 1e-40;
inline constexpr int kCertifiedTextDigits = 17;

// Empty when `precision` does not name certified; 0 for "certified"; the bits of "certified:BITS".
// Throws CaseError("--precision") for a malformed or out-of-range BITS.
std::optional<long> certified_bits(std::string_view precision);

// `bits` 0: the default, as above.
std::string render_certified(const CaseSpec& spec, long bits, const RenderOptions& o);

}  // namespace impact3d::studies
