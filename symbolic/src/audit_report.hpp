// The audit written out: generated/audit.json (machine-readable) and papers/audit.md (summary first).
#pragma once

#include <string>
#include <vector>

#include "audit.hpp"

namespace impact3d::symbolic {

std::string audit_json(const std::vector<AuditEntry>& entries, const std::string& provenance);
std::string audit_markdown(const std::vector<AuditEntry>& entries, const std::string& banner);

}  // namespace impact3d::symbolic
