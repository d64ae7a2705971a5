// The audit's entries, by part of the paper (run_audit puts them together in the paper's order).
#pragma once

#include <vector>

#include "audit.hpp"

namespace impact3d::symbolic {

void audit_equations(std::vector<AuditEntry>& out, const Derivation& d, const ClosedForms& c);
void audit_appendix_a(std::vector<AuditEntry>& out, const AppendixA& a);
void audit_claims(std::vector<AuditEntry>& out, const ClosedForms& c);

}  // namespace impact3d::symbolic
