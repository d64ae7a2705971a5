// impact3d compare: another tool's results against the reference suite, case by case, field by field.
#pragma once

#include <string>

namespace impact3d::verification {

struct CompareOptions {
  double rtol = 1e-9;
  double atol = 1e-9;
  bool all_fields = false;  // also require the reference's keys beyond the contract
  bool subset = false;      // compare only what the other side has, and say so: never a silent partial pass
};

// Prints the table to stdout; returns 0 when every reference field in scope was compared and passes,
// 1 otherwise (a comparison of nothing fails). Throws io::CaseError naming the file on bad input, before
// anything is printed.
int compare(const std::string& reference, const std::string& other, const CompareOptions& o);

}  // namespace impact3d::verification
