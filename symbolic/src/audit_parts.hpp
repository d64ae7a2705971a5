// The audit's entries, by part of the paper (run_audit puts them together in the paper's order).
#pragma once

#include <string>
#include <vector>

#include "audit.hpp"

namespace impact3d::symbolic {

// The entries, one maker per kind; the status still comes from the comparisons (status_of).
AuditEntry definition(const std::string& id, const std::string& detail);
AuditEntry formula(const std::string& id, const std::string& detail, std::vector<Check> checks,
                   const std::string& printed_latex = "");
AuditEntry ambiguous(const std::string& id, const std::string& detail, const std::string& printed_latex,
                     std::vector<Reading> readings);
AuditEntry claim(const std::string& id, const std::string& words, const std::string& detail, std::vector<Check> checks);
// An expression in the paper's notation.
std::string tex(const ex& e);

void audit_equations(std::vector<AuditEntry>& out, const Derivation& d, const ClosedForms& c);
void audit_appendix_a(std::vector<AuditEntry>& out, const AppendixA& a);
void audit_claims(std::vector<AuditEntry>& out, const ClosedForms& c);

}  // namespace impact3d::symbolic
