// Philox4x32-10, the counter-based generator of Salmon, Moraes, Dror and Shaw ("Parallel random numbers:
// as easy as 1, 2, 3", SC11): a random draw is a pure function of (key, counter), so sample i of a Monte
// Carlo run is the same whichever thread computes it and on whichever platform, with no state to
// share or to split. Integer arithmetic only.
#pragma once

#include <array>
#include <cstdint>

namespace impact3d::uncertainty {

using PhiloxCounter = std::array<std::uint32_t, 4>;
using PhiloxKey = std::array<std::uint32_t, 2>;

// Ten rounds, each two 32x32->64 multiplications and the key bumped by the Weyl constants between
// rounds, as the paper and Random123's philox.h define them.
constexpr PhiloxCounter philox4x32_10(PhiloxCounter c, PhiloxKey k) {
  constexpr std::uint32_t kM0 = 0xD2511F53, kM1 = 0xCD9E8D57, kW0 = 0x9E3779B9, kW1 = 0xBB67AE85;
  for (int round = 0; round < 10; ++round) {
    if (round) k[0] += kW0, k[1] += kW1;
    const std::uint64_t p0 = std::uint64_t{kM0} * c[0], p1 = std::uint64_t{kM1} * c[2];
    c = {static_cast<std::uint32_t>(p1 >> 32) ^ c[1] ^ k[0], static_cast<std::uint32_t>(p1),
         static_cast<std::uint32_t>(p0 >> 32) ^ c[3] ^ k[1], static_cast<std::uint32_t>(p0)};
  }
  return c;
}

// The uniform draw of Monte Carlo sample `sample`, input `input` (its place in the uncertainty file)
// and stream `stream` (a second draw for the same input): counter (sample low, sample high, input,
// stream), key the seed. The top 52 bits of the first two words, k, give (k + 1/2) / 2^52: exact (2k + 1
// has at most 53 bits), inside the open interval (0, 1) by 2^-53 at least, so that a quantile function
// never sees 0 or 1.
constexpr double uniform_open(std::uint64_t seed, std::uint64_t sample, std::uint32_t input, std::uint32_t stream = 0) {
  const PhiloxCounter r = philox4x32_10(
      {static_cast<std::uint32_t>(sample), static_cast<std::uint32_t>(sample >> 32), input, stream},
      {static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32)});
  const std::uint64_t bits = (std::uint64_t{r[0]} << 32 | r[1]) >> 12;
  return (static_cast<double>(bits) + 0.5) * 0x1p-52;
}

}  // namespace impact3d::uncertainty
