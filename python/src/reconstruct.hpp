// impact3d.reconstruct: the contract's reconstruction document (many-cases.md) for a case and an
// evidence file.
#pragma once

#include <string>

#include "case.hpp"

namespace impact3d::python {

// `evidence_text`: E.json's text; `evidence_source`: its file, named first in its messages (empty for a
// dict). `strategy`: replaces the case's (solve's --strategy syntax), when not empty.
std::string reconstruct_json(const Case& c, const std::string& evidence_text, const std::string& evidence_source,
                             const std::string& strategy, const std::string& engine);

}  // namespace impact3d::python
