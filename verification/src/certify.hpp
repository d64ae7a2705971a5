// impact3d verify --certify (issue 14): each case's exact result enclosed in ball arithmetic, and every
// precision's results of both engines checked to lie within their own stated rounding bounds of every
// point of the enclosure: a proof of each bound on each case, not agreement with another rounded answer.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "impact3d/case_format/case_spec.hpp"

namespace impact3d::verification {

// Appends its report to `report`; false when a bound fails or nothing was checked. `corrupt_double`
// (for the tests) is added, relative, to every double P_n before it is checked.
bool certify(const std::vector<std::pair<std::string, case_format::CaseSpec>>& cases, std::string& report, double corrupt_double = 0);

}  // namespace impact3d::verification
