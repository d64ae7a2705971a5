// scalar_to_text prints double and long double through std::to_chars (case_format/scalar_text.hpp) and every
// other type through a classic-locale stream; the two must give the same text, since `solve` and `batch`
// print every result number this way and the contract fixes the digits (%.17g for double). Random bit
// patterns (subnormals, infinities and NaNs among them) and ordinary magnitudes, at every digit count
// the reports use.
#include <catch2/catch.hpp>

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <random>
#include <utility>

#include "impact3d/case_format/json_text.hpp"
#include "impact3d/case_format/json_writer.hpp"
#include "impact3d/case_format/scalar_text.hpp"
#include "impact3d/scalar/ball.hpp"
#include "impact3d/scalar/scalars.hpp"

namespace check_scalar_text {

namespace {

template <typename T>
std::string streamed(const T& x, int digits) {
  std::ostringstream os;
  os.imbue(std::locale::classic());
  os.precision(digits);
  os << x;
  return os.str();
}

}  // namespace

TEST_CASE("scalar_to_text of double and long double is the classic stream's text", "[io]") {
  std::mt19937_64 g(11);
  int compared = 0, mismatched = 0;
  auto check = [&](auto x, int digits) {
    ++compared;
    if (impact3d::case_format::scalar_to_text(x, digits) != streamed(x, digits)) {
      ++mismatched;
      UNSCOPED_INFO(streamed(x, digits));
    }
  };
  for (int i = 0; i < 200000; ++i) {
    const std::uint64_t bits = g();
    double x;
    std::memcpy(&x, &bits, sizeof x);
    if (i % 2) {
      const int e = static_cast<int>(g() % 80) - 40;  // the last first, as GCC took the call's arguments
      x = std::ldexp(static_cast<double>(g() % 1000000) / 7.0, e);
    }
    for (int d : {17, 10, 6, 1}) check(x, d);
    for (int d : {21, 18, 10}) check(static_cast<long double>(x) / 3.0L, d);
  }
  for (double x : {0.0, -0.0, HUGE_VAL, -HUGE_VAL, std::nan(""), 5e-324, 1.0, 1e16, 1e17, 123456789012345678.0})
    for (int d : {17, 10, 1}) check(x, d);
  CHECK(mismatched == 0);
  CHECK(compared == 200000 * 7 + 10 * 3);
}

// format_g17 decides the rounding from a 192-bit product and leaves only near-ties to std::to_chars
// (case_format/format_double.hpp); it must give std::to_chars's text everywhere. Beside random bit patterns: every
// binade's ends, the neighbours of each power of ten (where the digit count changes), exact ties at the
// 18th digit (n + 0.25 and n + 0.75 for 16-digit n below 2^51, where quarters are representable; rounded
// to even; below 2^50 the guess of the decimal exponent is one short, and the 18-digit product decides),
// and scaled random integers.
TEST_CASE("format_g17 is std::to_chars at 17 digits", "[io]") {
  std::mt19937_64 g(17);
  int compared = 0, mismatched = 0;
  auto check = [&](double x) {
    char mine[32], theirs[32];
    const std::string a(mine, impact3d::case_format::format_g17(mine, x));
    const std::string b(theirs, std::to_chars(theirs, theirs + sizeof theirs, x, std::chars_format::general, 17).ptr);
    ++compared;
    if (a != b) {
      ++mismatched;
      UNSCOPED_INFO(a << " != " << b);
    }
  };
  for (int i = 0; i < 1000000; ++i) {
    const std::uint64_t bits = g();
    double x;
    std::memcpy(&x, &bits, sizeof x);
    check(x);
  }
  for (int e = -1074; e <= 1023; ++e) {
    const double lo = std::ldexp(1.0, e);
    check(lo);
    check(std::nextafter(lo, 0.0));
    check(-std::nextafter(lo, HUGE_VAL));
  }
  for (int p = -323; p <= 308; ++p) {
    const double t = std::strtod(("1e" + std::to_string(p)).c_str(), nullptr);  // stod refuses subnormals
    for (double x = t, n = 0; n < 4; ++n) x = std::nextafter(x, 0.0), check(x);
    for (double x = t, n = 0; n < 4; ++n) check(x), x = std::nextafter(x, HUGE_VAL);
  }
  for (int i = 0; i < 100000; ++i) {
    const double n = static_cast<double>(1000000000000000ULL + g() % 1251799813685248ULL);  // [1e15, 2^51)
    check(n + 0.25);
    check(n + 0.75);
    const int e = static_cast<int>(g() % 200) - 100;
    check(std::ldexp(static_cast<double>(g() >> 11), e));
  }
  for (double x : {0.0, -0.0, HUGE_VAL, -HUGE_VAL, std::nan(""), 5e-324, 1.7976931348623157e308, 1e16, 1e17, 975.0})
    check(x);
  CHECK(mismatched == 0);
  CHECK(compared == 1000000 + 3 * 2098 + 8 * 632 + 3 * 100000 + 10);
}

// format_g17 writes the 16 digits after the first as two groups of eight, each from fixed-point
// products (format_double.cpp). The integers 10^8 + w, w < 10^8, print as 1 and then w's eight digits,
// so this passes every group of eight through them; the text to match is std::to_chars's of the integer.
TEST_CASE("format_g17 writes every group of eight digits", "[io]") {
  long compared = 0, mismatched = 0;
  for (std::uint64_t w = 0; w < 100000000; ++w) {
    char mine[32], theirs[32];
    char* a = impact3d::case_format::format_g17(mine, static_cast<double>(100000000 + w));
    char* b = std::to_chars(theirs, theirs + sizeof theirs, 100000000 + w).ptr;
    ++compared;
    if (a - mine != b - theirs || std::memcmp(mine, theirs, static_cast<std::size_t>(b - theirs)) != 0) {
      if (++mismatched <= 10) UNSCOPED_INFO(std::string(mine, a) << " != " << std::string(theirs, b));
    }
  }
  CHECK(mismatched == 0);
  CHECK(compared == 100000000);
}

// The JSON writer writes a non-finite number as null, telling it by the text's first letter (after a
// sign): every scalar type's text of an infinity or a NaN, at every digit count, is null there, and every
// finite text is written as it is.
TEST_CASE("the JSON writer writes non-finite numbers as null and finite ones as their text, at every scalar type", "[io]") {
  using impact3d::case_format::JsonWriter;
  int compared = 0;
  auto written = [](auto x, int digits) {
    JsonWriter w(true);
    w.number([&](auto& out) { impact3d::case_format::append_scalar(out, x, digits); });
    std::string s = std::move(w).str();
    s.pop_back();  // the newline
    return s;
  };
  auto check_type = [&](auto zero) {
    using T = decltype(zero);
    const T inf = std::numeric_limits<T>::infinity(), nan = std::numeric_limits<T>::quiet_NaN();
    for (int digits : {std::numeric_limits<T>::max_digits10, 17, 6, 3}) {
      for (const T& x : {inf, T(-inf), nan, T(-nan)}) {
        CHECK(written(x, digits) == "null");
        ++compared;
      }
      for (const T& x : {T(0), T(-T(0)), T(1) / T(3), T(-2) / T(7), T(1e300), T(-1e-300), std::numeric_limits<T>::denorm_min()}) {
        CHECK(written(x, digits) == impact3d::case_format::scalar_to_text(x, digits));
        ++compared;
      }
    }
  };
  [&]<std::size_t... I>(std::index_sequence<I...>) { (check_type(impact3d::ScalarAt<I>(0)), ...); }(std::make_index_sequence<impact3d::kScalarCount>());
  CHECK(compared == static_cast<int>(impact3d::kScalarCount) * 4 * 11);
  // A ball: NaN when not finite (one not containing a finite real), its enclosure text otherwise.
  CHECK(written(impact3d::Ball(std::numeric_limits<double>::infinity()), 17) == "null");
  CHECK(written(impact3d::Ball(1.0) / impact3d::Ball(3.0), 17) != "null");
}

// JsonWriter finds the bytes a string must escape eight at a time (json_writer.hpp, next_special); here
// against RFC 8259's rule read a byte at a time: a control byte (below 0x20), '"' and '\' are escaped,
// every other byte (UTF-8's high bytes included) is copied. Strings and keys of every length up to 56
// (a key of up to 48 bytes is tested by whole words, plain(), and one longer as a string is), their bytes
// drawn mostly from those at the three tests' edges, so that most words hold one; then each edge byte at
// every place of a key of letters of every length up to 56.
TEST_CASE("the JSON writer escapes exactly the bytes JSON requires, in strings and in keys", "[io]") {
  using impact3d::case_format::JsonWriter;
  auto by_byte = [](const std::string& s) {
    std::string q = "\"";
    for (const char ch : s) {
      const unsigned char c = static_cast<unsigned char>(ch);
      if (c == '"') q += "\\\"";
      else if (c == '\\') q += "\\\\";
      else if (c == '\n') q += "\\n";
      else if (c < 0x20) q += "\\u00" + std::string(1, "0123456789abcdef"[c >> 4]) + "0123456789abcdef"[c & 15];
      else q += ch;
    }
    return q + "\"";
  };
  // As a string and as a key after another; true when the string needed no escape.
  auto written_as_json_says = [&](const std::string& s) {
    const std::string want = by_byte(s);
    CHECK(JsonWriter::quote(s) == want);
    JsonWriter w(true);
    w.begin_object();
    w.key("a").null();
    w.key(s).null();
    w.end_object();
    CHECK(std::move(w).str() == "{\"a\": null, " + want + ": null}\n");
    return want.size() == s.size() + 2;
  };
  const unsigned char edges[] = {0x00, 0x01, 0x0a, 0x1f, 0x20, 0x21, 0x22, 0x23, 0x5b, 0x5c, 0x5d, 0x7f, 0x80, 0xa2, 0xdc, 0xff};
  std::mt19937_64 g(17);
  int compared = 0, escaped = 0;
  for (int n = 0; n < 40000; ++n) {
    std::string s(g() % 57, ' ');
    const bool rare = g() % 4 == 0;  // one edge byte at most, elsewhere letters: the first hit's position
    for (auto& ch : s) ch = static_cast<char>(rare ? 'a' + g() % 26 : edges[g() % std::size(edges)]);
    if (rare && !s.empty()) s[g() % s.size()] = static_cast<char>(edges[g() % std::size(edges)]);
    escaped += !written_as_json_says(s);
    ++compared;
  }
  CHECK(compared == 40000);
  CHECK(escaped > 20000);
  // And every key of letters up to 56 long with one edge byte, at every place.
  int placed = 0;
  for (std::size_t n = 1; n <= 56; ++n)
    for (std::size_t at = 0; at < n; ++at)
      for (const unsigned char edge : edges) {
        std::string s(n, 'k');
        s[at] = static_cast<char>(edge);
        written_as_json_says(s);
        ++placed;
      }
  CHECK(placed == 16 * 56 * 57 / 2);
}

// JsonText copies short pieces by overlapping fixed-width moves (json_text.hpp): here every length up to
// 80 from varied offsets of a source, appended after texts of 41 lengths up to 280 (so that the storage,
// first 256 bytes, grows under some with text in it), against the same appends to a std::string.
TEST_CASE("JsonText holds what std::string holds after the same appends", "[io]") {
  std::string source(128, ' ');
  for (std::size_t i = 0; i < source.size(); ++i) source[i] = static_cast<char>(33 + i % 90);
  int compared = 0;
  for (std::size_t before = 0; before <= 40; ++before)
    for (std::size_t n = 0; n <= 80; ++n) {
      const std::size_t from = (before * 7 + n) % (source.size() - n + 1);
      impact3d::case_format::JsonText text;
      std::string want;
      const std::size_t held = 7 * before;
      text.append(held, 'x');
      want.append(held, 'x');
      text.append(source.data() + from, n);
      want.append(source, from, n);
      text += '|';
      want += '|';
      char* p = text.room(32);
      *p++ = 'y';
      text.commit(p);
      want += 'y';
      CHECK(text.view() == want);
      text.resize(held);
      CHECK(std::move(text).take() == want.substr(0, held));
      ++compared;
    }
  CHECK(compared == 41 * 81);
}

}  // namespace check_scalar_text
