// impact3d verify: every engine at every precision against the 100-digit solve of the same decimal
// inputs, with errors in units of each type's epsilon, digits of agreement and the worst case.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace impact3d::verification {

struct VerifyOptions {
  std::vector<std::string> inputs;  // case files or directories of them
  int random = 0;                   // seeded random cases to add
  std::uint64_t seed = 1;
  // --certify: also enclose each case in ball arithmetic and prove every precision's stated bound on it.
  bool certify = false;
  double corrupt_double = 0;  // the tests' injected error: relative, added to every double P_n it certifies
};

// Prints the report; returns 0 when every bound holds and every precision takes the reference's
// decisions (regimes, plane fallbacks), 1 otherwise.
int verify(const VerifyOptions& o);

}  // namespace impact3d::verification
