// "%.17g" of a double. x = f·2^e (f normalized to 64 bits) times 10^q, q chosen so that the product has
// 17 digits before the point, is computed as f × c · 2^(e+s) with c·2^s the 128-bit truncation of 10^q
// (c ≥ 2^127, exact below it or short by less than one unit). The 192-bit product's integer part is the
// digits; its next 64 bits, short of the true fraction by less than two units of their last place, say
// which way to round unless the fraction is within that of one half, where std::to_chars decides.
#include "impact3d/io/format_double.hpp"

#include <array>
#include <bit>
#include <charconv>
#include <cstdint>
#include <cstring>

#include <boost/multiprecision/cpp_int.hpp>

namespace impact3d::io {
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

// The eight decimal digits of v < 10^8 as ASCII, most significant first, by arithmetic on lanes of one
// 64-bit word (no loop, no table): two lanes of four digits, four of two, eight of one. Each lane's
// quotient by 100 (by 10) is its product by 10486 / 2^20 (by 103 / 2^10), exact below 10^4 (below 179).
void eight_digits(char* out, std::uint32_t v) {
  const u64 x = v;
  const u64 halves = x / 10000 | (x % 10000) << 32;  // abcd, efgh
  const u64 high = (halves * 10486 >> 20) & 0x0000007f0000007fULL;  // ab, ef
  const u64 pairs = (halves - 100 * high) << 16 | high;  // ab, cd, ef, gh in 16-bit lanes
  const u64 tens = (pairs * 103 >> 10) & 0x000f000f000f000fULL;
  const u64 digits = tens | (pairs - 10 * tens) << 8;  // a, b, ..., h in bytes, least significant first
  const u64 ascii = digits + 0x3030303030303030ULL;
  static_assert(std::endian::native == std::endian::little);
  std::memcpy(out, &ascii, 8);
}

// printf's %g at precision 17 of N·10^(k-16), 10^16 ≤ N < 10^17: fixed notation when -4 ≤ k < 17,
// exponential otherwise; trailing zeros and a bare point dropped.
char* write_general(char* out, u64 n, int k) {
  char digits[17];
  const u64 high = n / 100'000'000;  // nine digits, the first not zero
  digits[0] = static_cast<char>('0' + high / 100'000'000);
  eight_digits(digits + 1, static_cast<std::uint32_t>(high % 100'000'000));
  eight_digits(digits + 9, static_cast<std::uint32_t>(n % 100'000'000));
  int len = 17;
  while (len > 1 && digits[len - 1] == '0') --len;
  if (k < -4 || k >= 17) {
    *out++ = digits[0];
    if (len > 1) {
      *out++ = '.';
      std::memcpy(out, digits + 1, static_cast<std::size_t>(len - 1));
      out += len - 1;
    }
    *out++ = 'e';
    *out++ = k < 0 ? '-' : '+';
    const int a = k < 0 ? -k : k;
    if (a >= 100) *out++ = static_cast<char>('0' + a / 100);
    *out++ = static_cast<char>('0' + a / 10 % 10);
    *out++ = static_cast<char>('0' + a % 10);
  } else if (k < 0) {
    *out++ = '0';
    *out++ = '.';
    for (int i = -1; i > k; --i) *out++ = '0';
    std::memcpy(out, digits, static_cast<std::size_t>(len));
    out += len;
  } else {
    const int whole = k + 1;
    std::memcpy(out, digits, static_cast<std::size_t>(whole));
    out += whole;
    if (len > whole) {
      *out++ = '.';
      std::memcpy(out, digits + whole, static_cast<std::size_t>(len - whole));
      out += len - whole;
    }
  }
  return out;
}

}  // namespace

char* format_g17(char* out, double x) {
  const u64 bits = std::bit_cast<u64>(x);
  const int biased = static_cast<int>(bits >> 52 & 0x7ff);
  const u64 fraction = bits & ((u64{1} << 52) - 1);
  if (biased == 0x7ff || (biased == 0 && fraction == 0)) return fallback(out, x);  // inf, nan, ±0
  u64 f = biased == 0 ? fraction : fraction | u64{1} << 52;
  int e = biased == 0 ? -1074 : biased - 1075;
  const int lz = std::countl_zero(f);
  f <<= lz;
  e -= lz;
  // floor((e + 63)·log10 2), exact over this range; a wrong guess is corrected below all the same.
  int k = ((e + 63) * 315653) >> 20;
  const Powers& table = powers();
  for (int attempt = 0; attempt < 3; ++attempt) {
    const int q = 16 - k;
    if (q < kQMin || q > kQMax) break;
    const Power& p = table[static_cast<std::size_t>(q - kQMin)];
    const u128 low = static_cast<u128>(f) * p.lo, high = static_cast<u128>(f) * p.hi;
    const u128 mid = (low >> 64) + static_cast<u64>(high);
    const u64 w1 = static_cast<u64>(mid), w2 = static_cast<u64>(high >> 64) + static_cast<u64>(mid >> 64);
    const int r = -(e + p.s) - 128;  // the point sits r bits into the top word
    if (r < 1 || r > 63) break;
    const u64 whole = w2 >> r, frac = w2 << (64 - r) | w1 >> r;
    if (whole < kTen16) {
      --k;
      continue;
    }
    if (whole >= kTen17) {
      ++k;
      continue;
    }
    constexpr u64 kHalf = u64{1} << 63;
    if (frac >= kHalf - 2 && frac <= kHalf) break;  // too close to a tie to decide here
    u64 n = whole + (frac > kHalf ? 1 : 0);
    if (n == kTen17) {
      n = kTen16;
      ++k;
    }
    if (bits >> 63) *out++ = '-';
    return write_general(out, n, k);
  }
  return fallback(out, x);
}

}  // namespace impact3d::io
