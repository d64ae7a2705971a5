// What any input may ask of impact3d: bounded size, depth and number text, so that no file, however
// written, makes a reader hang or exhaust memory. Each limit is far above what a collision needs (a case
// file is about 3 KB, six levels deep, with numbers of a few digits) and is stated in docs/limits-and-exit-status.md.
#pragma once

#include <cstddef>

namespace impact3d::case_format::limits {

inline constexpr std::size_t kCaseFileBytes = 1 << 20;       // a case file: 1 MiB
inline constexpr std::size_t kResultFileBytes = 16 << 20;    // compare's reference and other results, JSON or CSV
inline constexpr int kDepth = 32;                            // nesting of arrays and objects
inline constexpr int kResultDepth = 8;                       // nesting in compare's result files (the contract's is 6)
inline constexpr int kLiteralDepth = 5;                      // the deepest number a case holds: $.vehicles[i].inertia[r][c]
inline constexpr std::size_t kStrategies = 64;               // strategies of one case, or --strategy options
inline constexpr std::size_t kValues = 20000;                // JSON values in one document
inline constexpr std::size_t kLiteralChars = 256;            // characters of one number literal (100 digits fit)
inline constexpr std::size_t kKeyChars = 128;                // characters of one object key
inline constexpr long kExponent = 1000;                      // |exponent| written in a number literal
inline constexpr const char* kMaxMagnitude = "1e12";         // largest magnitude of a case number
inline constexpr const char* kMinMagnitude = "1e-100";       // smallest non-zero magnitude of a case number
inline constexpr std::size_t kCsvColumns = 10000;            // columns of a compare CSV

}  // namespace impact3d::case_format::limits
