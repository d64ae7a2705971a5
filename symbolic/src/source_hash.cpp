#include "source_hash.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace impact3d::symbolic {

namespace {

// FIPS 180-4.
constexpr std::array<std::uint32_t, 64> kRound = {
    0x428a2f98, 0x71374491, 0xb5c0fbcf, 0xe9b5dba5, 0x3956c25b, 0x59f111f1, 0x923f82a4, 0xab1c5ed5,
    0xd807aa98, 0x12835b01, 0x243185be, 0x550c7dc3, 0x72be5d74, 0x80deb1fe, 0x9bdc06a7, 0xc19bf174,
    0xe49b69c1, 0xefbe4786, 0x0fc19dc6, 0x240ca1cc, 0x2de92c6f, 0x4a7484aa, 0x5cb0a9dc, 0x76f988da,
    0x983e5152, 0xa831c66d, 0xb00327c8, 0xbf597fc7, 0xc6e00bf3, 0xd5a79147, 0x06ca6351, 0x14292967,
    0x27b70a85, 0x2e1b2138, 0x4d2c6dfc, 0x53380d13, 0x650a7354, 0x766a0abb, 0x81c2c92e, 0x92722c85,
    0xa2bfe8a1, 0xa81a664b, 0xc24b8b70, 0xc76c51a3, 0xd192e819, 0xd6990624, 0xf40e3585, 0x106aa070,
    0x19a4c116, 0x1e376c08, 0x2748774c, 0x34b0bcb5, 0x391c0cb3, 0x4ed8aa4a, 0x5b9cca4f, 0x682e6ff3,
    0x748f82ee, 0x78a5636f, 0x84c87814, 0x8cc70208, 0x90befffa, 0xa4506ceb, 0xbef9a3f7, 0xc67178f2};

std::uint32_t rotr(std::uint32_t x, int n) { return (x >> n) | (x << (32 - n)); }

void compress(std::array<std::uint32_t, 8>& h, const unsigned char* block) {
  std::array<std::uint32_t, 64> w{};
  for (int i = 0; i < 16; ++i)
    w[i] = std::uint32_t(block[4 * i]) << 24 | std::uint32_t(block[4 * i + 1]) << 16 |
           std::uint32_t(block[4 * i + 2]) << 8 | std::uint32_t(block[4 * i + 3]);
  for (int i = 16; i < 64; ++i) {
    const std::uint32_t s0 = rotr(w[i - 15], 7) ^ rotr(w[i - 15], 18) ^ (w[i - 15] >> 3);
    const std::uint32_t s1 = rotr(w[i - 2], 17) ^ rotr(w[i - 2], 19) ^ (w[i - 2] >> 10);
    w[i] = w[i - 16] + s0 + w[i - 7] + s1;
  }
  std::array<std::uint32_t, 8> v = h;
  for (int i = 0; i < 64; ++i) {
    const std::uint32_t S1 = rotr(v[4], 6) ^ rotr(v[4], 11) ^ rotr(v[4], 25);
    const std::uint32_t ch = (v[4] & v[5]) ^ (~v[4] & v[6]);
    const std::uint32_t t1 = v[7] + S1 + ch + kRound[i] + w[i];
    const std::uint32_t S0 = rotr(v[0], 2) ^ rotr(v[0], 13) ^ rotr(v[0], 22);
    const std::uint32_t maj = (v[0] & v[1]) ^ (v[0] & v[2]) ^ (v[1] & v[2]);
    const std::uint32_t t2 = S0 + maj;
    v = {t1 + t2, v[0], v[1], v[2], v[3] + t1, v[4], v[5], v[6]};
  }
  for (int i = 0; i < 8; ++i) h[i] += v[i];
}

bool blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }
bool ident_start(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool digit(char c) { return c >= '0' && c <= '9'; }
bool ident_char(char c) { return ident_start(c) || digit(c); }

bool cpp_file(const std::filesystem::path& p) {
  const std::string e = p.extension().string();
  return e == ".cpp" || e == ".hpp" || e == ".h" || e == ".cc";
}

}  // namespace

std::string sha256_hex(const std::string& data) {
  std::array<std::uint32_t, 8> h = {0x6a09e667, 0xbb67ae85, 0x3c6ef372, 0xa54ff53a,
                                    0x510e527f, 0x9b05688c, 0x1f83d9ab, 0x5be0cd19};
  std::string msg = data;
  const std::uint64_t bits = std::uint64_t(data.size()) * 8;
  msg += char(0x80);
  while (msg.size() % 64 != 56) msg += char(0);
  for (int i = 7; i >= 0; --i) msg += char((bits >> (8 * i)) & 0xff);
  for (std::size_t off = 0; off < msg.size(); off += 64)
    compress(h, reinterpret_cast<const unsigned char*>(msg.data() + off));
  static const char* hex = "0123456789abcdef";
  std::string out;
  for (std::uint32_t word : h)
    for (int i = 28; i >= 0; i -= 4) out += hex[(word >> i) & 0xf];
  return out;
}

std::string code_only(const std::string& s) {
  std::vector<std::string> lines;
  std::string line;
  bool space = false;  // blanks or a comment since the last token of this line
  auto emit = [&](const std::string& text) {
    if (space && !line.empty()) line += ' ';
    space = false;
    line += text;
  };
  // A quoted literal from s[i] (the opening quote) to its closing quote, escapes kept; an unterminated
  // one ends before the newline.
  auto quoted = [&](std::size_t i) -> std::size_t {
    const char q = s[i];
    std::size_t j = i + 1;
    while (j < s.size() && s[j] != q && s[j] != '\n') j += s[j] == '\\' && j + 1 < s.size() ? 2 : 1;
    return (j < s.size() && s[j] == q ? j + 1 : j) - i;
  };
  std::size_t i = 0;
  while (i < s.size()) {
    const char c = s[i];
    const char next = i + 1 < s.size() ? s[i + 1] : '\0';
    if (c == '\n') {
      if (!line.empty()) lines.push_back(line);
      line.clear();
      space = false;
      ++i;
    } else if (blank(c)) {
      space = true;
      ++i;
    } else if (c == '/' && next == '/') {
      while (i < s.size() && s[i] != '\n') ++i;
      space = true;
    } else if (c == '/' && next == '*') {
      const std::size_t end = s.find("*/", i + 2);
      i = end == std::string::npos ? s.size() : end + 2;
      space = true;
    } else if (ident_start(c)) {
      std::size_t j = i;
      while (j < s.size() && ident_char(s[j])) ++j;
      const std::string id = s.substr(i, j - i);
      const bool raw = j < s.size() && s[j] == '"' &&
                       (id == "R" || id == "LR" || id == "uR" || id == "UR" || id == "u8R");
      if (raw) {
        const std::size_t open = s.find('(', j);
        if (open == std::string::npos) throw std::runtime_error("code_only: raw string without '('");
        std::string close(1, ')');
        close.append(s, j + 1, open - j - 1).push_back('"');
        const std::size_t end = s.find(close, open);
        j = end == std::string::npos ? s.size() : end + close.size();
      }
      emit(s.substr(i, j - i));
      i = j;
    } else if (digit(c) || (c == '.' && digit(next))) {
      // A preprocessing number: digit separators and exponent signs belong to it.
      std::size_t j = i + 1;
      while (j < s.size()) {
        const char d = s[j];
        if (ident_char(d) || d == '.') ++j;
        else if (d == '\'' && j + 1 < s.size() && ident_char(s[j + 1])) j += 2;
        else if ((d == '+' || d == '-') && std::string("eEpP").find(s[j - 1]) != std::string::npos) ++j;
        else break;
      }
      emit(s.substr(i, j - i));
      i = j;
    } else if (c == '"' || c == '\'') {
      const std::size_t n = quoted(i);
      emit(s.substr(i, n));
      i += n;
    } else {
      emit(std::string(1, c));
      ++i;
    }
  }
  if (!line.empty()) lines.push_back(line);
  std::string out;
  for (const auto& l : lines) out += l + "\n";
  return out;
}

std::string hash_sources(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    if (entry.is_regular_file()) files.push_back(entry.path());
  if (files.empty()) throw std::runtime_error("no sources in " + dir.string());
  std::sort(files.begin(), files.end(),
            [](const auto& a, const auto& b) { return a.filename().string() < b.filename().string(); });
  std::string all;
  for (const auto& f : files) {
    std::ifstream in(f, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in) throw std::runtime_error("cannot read " + f.string());
    all += f.filename().string() + " " + sha256_hex(cpp_file(f) ? code_only(text.str()) : text.str()) + "\n";
  }
  return sha256_hex(all);
}

}  // namespace impact3d::symbolic
