// "%.17g" of a double. x = f·2^e (f normalized to 64 bits) times 10^q, q chosen so that the product has
// 17 digits before the point, is computed as f × c · 2^(e+s) with c·2^s the 128-bit truncation of 10^q
// (c ≥ 2^127, exact below it or short by less than one unit). The 192-bit product's integer part is the
// digits; its next 64 bits, short of the true fraction by less than two units of their last place, say
// which way to round unless the fraction is within that of one half, where std::to_chars decides. The
// guess of k from the binary exponent is right or one short; one short, the product has 18 digits and the
// last of them rounds the 17. Both roundings are formed and one kept, since which applies is a coin toss
// to the branch predictor. A product of 16 digits or fewer cannot occur (the true product is 10^16
// exactly or at least 1.001 · 10^16, far beyond the truncation's error); if it did, std::to_chars
// would write the text.
#include "impact3d/case_format/format_double.hpp"

#include <array>
#include <bit>
#include <charconv>
#include <cstdint>
#include <cstring>

#include <boost/multiprecision/cpp_int.hpp>

namespace impact3d::case_format {
namespace {

using u64 = std::uint64_t;
using u128 = unsigned __int128;

// 10^q ≈ (hi·2^64 + lo)·2^s with hi ≥ 2^63, rounded down. q spans 16 − floor(log10 x) for every finite
// x > 0 (4.9e-324 … 1.8e308) and one step either side.
struct Power {
  u64 hi, lo;
  int s;
};
constexpr int kQMin = -294, kQMax = 342;
using Powers = std::array<Power, kQMax - kQMin + 1>;

Powers make_powers() {
  using boost::multiprecision::cpp_int;
  Powers table{};
  for (int q = kQMin; q <= kQMax; ++q) {
    cpp_int c;
    int s;
    if (q >= 0) {
      const cpp_int x = boost::multiprecision::pow(cpp_int(10), static_cast<unsigned>(q));
      const int b = static_cast<int>(msb(x));
      c = b >= 127 ? cpp_int(x >> (b - 127)) : cpp_int(x << (127 - b));
      s = b - 127;
    } else {
      // 2^u / 10^-q lies in (2^127, 2^128) for u = msb(10^-q) + 128, as 10^-q is not a power of two.
      const cpp_int d = boost::multiprecision::pow(cpp_int(10), static_cast<unsigned>(-q));
      const int u = static_cast<int>(msb(d)) + 128;
      c = (cpp_int(1) << u) / d;
      s = -u;
    }
    table[static_cast<std::size_t>(q - kQMin)] = {static_cast<u64>(c >> 64), static_cast<u64>(c & ~u64{0}), s};
  }
  return table;
}

const Powers& powers() {
  static const Powers table = make_powers();
  return table;
}

constexpr u64 kTen16 = 10'000'000'000'000'000ULL, kTen17 = 100'000'000'000'000'000ULL;

char* fallback(char* out, double x) { return std::to_chars(out, out + 24, x, std::chars_format::general, 17).ptr; }

// The eight decimal digits of v < 10^8, one a byte, most significant in the lowest byte. v / 10^6 is
// taken in fixed point with 52 bits of fraction, and each product of the fraction by 100 brings the next
// pair of digits above the point (exact for every v < 10^8, checked exhaustively); a table splits each
// pair into its two digits, so each pair waits on one multiplication after the last.
struct DigitPairs {
  std::array<std::uint16_t, 100> split{};
  constexpr DigitPairs() {
    for (unsigned v = 0; v < 100; ++v) split[v] = static_cast<std::uint16_t>(v / 10 | (v % 10) << 8);
  }
};
constexpr DigitPairs kDigitPairs;

u64 eight_digits(std::uint32_t v) {
  constexpr u64 kScale = (u64{1} << 52) / 1'000'000 + 1, kFraction = (u64{1} << 52) - 1;
  u64 t = v * kScale;
  const u64 p0 = kDigitPairs.split[t >> 52];
  t = (t & kFraction) * 100;
  const u64 p1 = kDigitPairs.split[t >> 52];
  t = (t & kFraction) * 100;
  const u64 p2 = kDigitPairs.split[t >> 52];
  t = (t & kFraction) * 100;
  const u64 p3 = kDigitPairs.split[t >> 52];
  return p0 | p1 << 16 | p2 << 32 | p3 << 48;
}

constexpr u64 kAscii = 0x3030303030303030ULL;

// printf's %g at precision 17 of N·10^(k-16), 10^16 ≤ N < 10^17, sign first when negative: fixed
// notation when -4 ≤ k < 17, exponential otherwise; trailing zeros and a bare point dropped. The text is
// stored from registers in pieces of fixed width, later pieces over earlier ones (none is read back, so
// no load waits on a narrower store); with the sign they reach at most 27 bytes from `out`.
char* write_general(char* out, bool negative, u64 n, int k) {
  static_assert(std::endian::native == std::endian::little);
  // first, then digits 1-8 and 9-16, each from n by independent products.
  const u64 first = n / 10'000'000'000'000'000ULL;
  const u64 q8 = n / 100'000'000;
  const u64 a = eight_digits(static_cast<std::uint32_t>(q8 - first * 100'000'000));
  const u64 b = eight_digits(static_cast<std::uint32_t>(n - q8 * 100'000'000));
  // Trailing zero digits are the zero bytes at the top of b, then of a.
  const int zeros = b != 0 ? std::countl_zero(b) / 8 : 8 + (a != 0 ? std::countl_zero(a) / 8 : 8);
  const int len = 17 - zeros;
  const char lead = static_cast<char>('0' + first);
  const u128 rest = (a + kAscii) | static_cast<u128>(b + kAscii) << 64;  // digits 1 to 16
  *out = '-';
  char* p = out + negative;
  if (k < -4 || k >= 17) {
    p[0] = lead;
    p[1] = '.';
    std::memcpy(p + 2, &rest, 16);
    p += len > 1 ? len + 1 : 1;
    const unsigned e = static_cast<unsigned>(k < 0 ? -k : k);
    const u64 exponent = e >= 100 ? (u64{'0' + e % 10} << 32 | u64{'0' + e / 10 % 10} << 24 | u64{'0' + e / 100} << 16)
                                  : (u64{'0' + e % 10} << 24 | u64{'0' + e / 10} << 16);
    const u64 text = exponent | u64{static_cast<unsigned char>(k < 0 ? '-' : '+')} << 8 | 'e';
    std::memcpy(p, &text, 8);
    return p + (e >= 100 ? 5 : 4);
  }
  if (k < 0) {
    std::memcpy(p, "0.000000", 8);
    p += 1 - k;  // "0." and -k-1 zeros
    p[0] = lead;
    std::memcpy(p + 1, &rest, 16);
    return p + len;
  }
  const int whole = k + 1;
  p[0] = lead;
  std::memcpy(p + 1, &rest, 16);
  if (len <= whole) return p + whole;
  p[whole] = '.';
  const u128 fraction = rest >> (8 * (whole - 1));  // digits whole to 16
  if (whole <= 8) {
    std::memcpy(p + whole + 1, &fraction, 16);
  } else {
    const u64 tail = static_cast<u64>(fraction);
    std::memcpy(p + whole + 1, &tail, 8);
  }
  return p + len + 1;
}

}  // namespace

char* format_g17(char* out, double x) {
  const u64 bits = std::bit_cast<u64>(x);
  const int biased = static_cast<int>(bits >> 52 & 0x7ff);
  const u64 fraction = bits & ((u64{1} << 52) - 1);
  if ((bits << 1) == 0) {  // ±0
    *out = '-';
    out += bits >> 63;
    *out = '0';
    return out + 1;
  }
  if (biased == 0x7ff) return fallback(out, x);  // inf, nan
  u64 f = biased == 0 ? fraction : fraction | u64{1} << 52;
  int e = biased == 0 ? -1074 : biased - 1075;
  const int lz = std::countl_zero(f);
  f <<= lz;
  e -= lz;
  // floor((e + 63)·log10 2), exact over this range: the product has 17 digits, or 18 when x is at least
  // the next power of ten.
  int k = ((e + 63) * 315653) >> 20;
  const Powers& table = powers();
  const int q = 16 - k;
  if (q < kQMin || q > kQMax) return fallback(out, x);
  const Power& p = table[static_cast<std::size_t>(q - kQMin)];
  const u128 low = static_cast<u128>(f) * p.lo, high = static_cast<u128>(f) * p.hi;
  const u128 mid = (low >> 64) + static_cast<u64>(high);
  const u64 w1 = static_cast<u64>(mid), w2 = static_cast<u64>(high >> 64) + static_cast<u64>(mid >> 64);
  const int r = -(e + p.s) - 128;  // the point sits r bits into the top word
  if (r < 1 || r > 63) return fallback(out, x);
  const u64 whole = w2 >> r, frac = w2 << (64 - r) | w1 >> r;
  if (whole < kTen16) return fallback(out, x);
  constexpr u64 kHalf = u64{1} << 63;
  // 17 digits, or 18 when the guess of k was one short (whole < 2·10^17): then the last digit and the
  // fraction round the first 17, undecided only where a carry out of the fraction or a fraction of zero
  // could make it a tie. Both are formed and one is kept, without a branch on which.
  const bool eighteen = whole >= kTen17;
  const u64 tenth = whole / 10, last = whole - 10 * tenth;
  const bool undecided = eighteen ? (last == 4 && frac >= ~u64{0} - 1) || (last == 5 && frac == 0)
                                  : frac - (kHalf - 2) <= 2;
  if (undecided) return fallback(out, x);
  u64 n = eighteen ? tenth + (last >= 5) : whole + (frac > kHalf);
  k += eighteen;
  const bool carry = n == kTen17;
  n = carry ? kTen16 : n;
  k += carry;
  return write_general(out, (bits >> 63) != 0, n, k);
}

}  // namespace impact3d::case_format
