#include "impact3d/case_format/nearest_key.hpp"

#include <algorithm>
#include <array>
#include <cstddef>

namespace impact3d::case_format {
namespace {

constexpr std::size_t kLongest = 64;

char folded(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }

// Optimal string alignment distance (Levenshtein with adjacent swaps), both at most kLongest.
std::size_t distance(std::string_view a, std::string_view b) {
  std::array<std::array<std::size_t, kLongest + 1>, kLongest + 1> d{};
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i)
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t cost = folded(a[i - 1]) == folded(b[j - 1]) ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && folded(a[i - 1]) == folded(b[j - 2]) && folded(a[i - 2]) == folded(b[j - 1]))
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

bool begins_at_underscore(std::string_view longer, std::string_view shorter) {
  return !shorter.empty() && longer.size() > shorter.size() && longer[shorter.size()] == '_' &&
         std::equal(shorter.begin(), shorter.end(), longer.begin(), [](char a, char b) { return folded(a) == folded(b); });
}

}  // namespace

std::optional<std::string_view> nearest_key(std::string_view unknown, std::span<const std::string_view> known) {
  if (unknown.empty() || unknown.size() > kLongest) return std::nullopt;
  std::optional<std::string_view> best;
  std::size_t best_d = kLongest + 1;
  bool tie = false;
  // The known keys it begins (a suffix left out), and those that begin it (one added), counted.
  std::optional<std::string_view> longer_key, shorter_key;
  int longer_keys = 0, shorter_keys = 0;
  for (std::string_view k : known) {
    if (k.size() > kLongest) continue;
    const std::size_t d = distance(unknown, k);
    if (d < best_d) best = k, best_d = d, tie = false;
    else if (d == best_d) tie = true;
    if (begins_at_underscore(k, unknown)) longer_key = k, ++longer_keys;
    if (begins_at_underscore(unknown, k)) shorter_key = k, ++shorter_keys;
  }
  const std::size_t longer = std::max(unknown.size(), best ? best->size() : 0);
  const std::size_t reach = longer <= 5 ? 1 : std::min<std::size_t>(3, longer / 3);
  if (best && !tie && best_d <= reach) return best;  // 0: a key differing only in case
  if (longer_keys == 1) return longer_key;
  if (longer_keys == 0 && shorter_keys == 1) return shorter_key;
  return std::nullopt;
}

std::string did_you_mean(std::string_view unknown, std::span<const std::string_view> known) {
  const auto k = nearest_key(unknown, known);
  return k ? "; did you mean " + std::string(*k) + "?" : std::string();
}

}  // namespace impact3d::case_format
