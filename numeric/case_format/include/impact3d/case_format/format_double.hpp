// A double as printf's "%.17g" prints it (std::to_chars general, precision 17), at a fraction of the cost:
// a result row of `impact3d batch` holds about 160 such numbers, and formatting them was half its time.
#pragma once

namespace impact3d::case_format {

// Writes the text at `out` (at most 24 characters) and returns its end; `out` must have room for 32, as
// the text is stored in pieces of fixed width that may reach past its end. The 17 digits are the exactly
// rounded ones (ties to even): a 192-bit product with a bounded error decides the rounding, and when it
// cannot (a fraction within 2^-63 of one half) the text is std::to_chars's. Tested against std::to_chars
// on random bit patterns and by a differential fuzz harness (tests/fuzz/fuzz_format_double.cpp).
char* format_g17(char* out, double x);

}  // namespace impact3d::case_format
