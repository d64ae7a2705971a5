// A text cell of the CSV files impact3d writes (batch's results, Monte Carlo's samples), quoted as
// RFC 4180 has it where it must be.
#pragma once

#include <algorithm>
#include <string_view>

namespace impact3d::case_format {

// A text cell, quoted (RFC 4180) where it must be: a comma, a quote or a line break inside, or a space
// at either end, which a spreadsheet would drop.
template <typename Out>  // std::string or JsonText
void put_csv_text(Out& out, std::string_view s) {
  // A loop, not find_first_of, which calls memchr for every byte of a name or a warning.
  const bool special = std::any_of(s.begin(), s.end(), [](char c) { return c == ',' || c == '"' || c == '\r' || c == '\n'; });
  if (!special && (s.empty() || (s.front() != ' ' && s.back() != ' '))) {
    out += s;
    return;
  }
  out += '"';
  for (char c : s) {
    if (c == '"') out += '"';
    out += c;
  }
  out += '"';
}

}  // namespace impact3d::case_format
