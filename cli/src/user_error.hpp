// A failure the user can mend that is not a field of an input file: a missing tool, an output directory
// that cannot be written. Exit status 1, as bad input.
#pragma once

#include <stdexcept>

namespace impact3d::cli {

struct UserError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace impact3d::cli
