// The tests' reading of a case file: the case format's own reader, for the tests that start from the
// bundled examples and verification cases (they link impact3d::case_format, the layer they run through).
#pragma once

#include <string>

#include "impact3d/case_format/read_case.hpp"
#include "support.hpp"

namespace impact3d::test {

inline case_format::CaseSpec load_spec(const std::string& path) { return case_format::read_case(read_text(path)); }

}  // namespace impact3d::test
