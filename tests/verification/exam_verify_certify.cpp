// impact3d verify --certify (issue 14): on the bundled examples every precision's results of both
// engines lie within their own stated rounding bounds of the certified enclosure, and a double result
// with an injected relative error of 10^-9 (ten million times double's bound on these well-conditioned
// cases, whose amplification is under 10^3: 32 eps 10^3 = 7e-12) is caught.
#include <catch2/catch.hpp>

#include "impact3d/verification/verify.hpp"

namespace exam_verify_certify {

using namespace impact3d;

TEST_CASE("verify --certify proves the stated bounds on the examples and catches an injected error", "[certified]") {
  verification::VerifyOptions o;
  o.inputs = {std::string(IMPACT3D_EXAMPLES_DIR)};
  o.certify = true;
  CHECK(verification::verify(o) == 0);
  o.corrupt_double = 1e-9;
  CHECK(verification::verify(o) == 1);
}

}  // namespace exam_verify_certify
