// libFuzzer harness, differential: format_g17 (case_format/format_double.hpp) must print every double as
// std::to_chars does at 17 digits. The input's first 8 bytes are the double's bits (zero-padded).
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string_view>

#include "impact3d/case_format/format_double.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::uint64_t bits = 0;
  if (size > 0) std::memcpy(&bits, data, size < sizeof bits ? size : sizeof bits);
  double x;
  std::memcpy(&x, &bits, sizeof x);
  char mine[32], theirs[32];
  const std::string_view a(mine, static_cast<std::size_t>(impact3d::case_format::format_g17(mine, x) - mine));
  const auto end = std::to_chars(theirs, theirs + sizeof theirs, x, std::chars_format::general, 17).ptr;
  if (a != std::string_view(theirs, static_cast<std::size_t>(end - theirs))) std::abort();
  return 0;
}
