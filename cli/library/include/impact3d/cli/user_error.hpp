// A failure the user can mend that is not a field of an input file: a missing tool, an output directory
// that cannot be written. Exit status 1, as bad input.
#pragma once

#include <stdexcept>
#include <string>

#include "impact3d/case_format/case_spec.hpp"

namespace impact3d::cli {

struct UserError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A problem of one input file, named by it ("U.json: $.inputs[2].path: ..."); an option's stays its own.
inline case_format::CaseError in_file(const std::string& file, const case_format::CaseError& e) {
  if (e.path.rfind("--", 0) == 0 || e.path.rfind(file + ":", 0) == 0) return e;
  return case_format::CaseError(file + ": " + e.path, e.what());
}

}  // namespace impact3d::cli
