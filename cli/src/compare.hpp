// impact3d compare: another tool's results against the reference suite, case by case, field by field.
#pragma once

#include <string>

namespace impact3d::cli {

struct CompareOptions {
  double rtol = 1e-9;
  double atol = 1e-9;
  bool all_fields = false;  // also require the reference's keys beyond the contract
};

// Prints the table to stdout; returns 0 when every compared field passes, 1 otherwise. Throws
// std::runtime_error (one line) on unreadable input.
int compare(const std::string& reference, const std::string& other, const CompareOptions& o);

}  // namespace impact3d::cli
