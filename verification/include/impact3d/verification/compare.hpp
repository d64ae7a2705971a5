// impact3d compare: another tool's results against the reference suite, case by case, field by field.
#pragma once

#include <string>

namespace impact3d::verification {

// The default tolerances: a user's choice for another tool's results, not a rounding bound (those are
// impact3d/mechanics/rounding.hpp's).
inline constexpr double kDefaultRtol = 1e-9;
inline constexpr double kDefaultAtol = 1e-9;

struct CompareOptions {
  double rtol = kDefaultRtol;
  double atol = kDefaultAtol;
  bool all_fields = false;  // also require the reference's keys beyond the contract
  bool subset = false;      // compare only what the other side has, and say so: never a silent partial pass
  // Each case's tolerance from the other side's own rounding bound instead of rtol and atol: rtol = the
  // largest `rounding_bound` of its results (impact3d's result JSON writes one per result), atol = that
  // rtol times the largest magnitude among the case's reference numbers. For impact3d's own results.
  bool rtol_from_bound = false;
};

// Prints the table to stdout; returns 0 when every reference field in scope was compared and passes,
// 1 otherwise (a comparison of nothing fails). Throws case_format::CaseError naming the file on bad input, before
// anything is printed.
int compare(const std::string& reference, const std::string& other, const CompareOptions& o);

}  // namespace impact3d::verification
