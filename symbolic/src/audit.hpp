// The audit of the paper: every printed expression the derivation can decide, compared with it.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "appendix_a.hpp"
#include "closed_forms.hpp"
#include "model.hpp"

namespace impact3d::symbolic {

struct Witness {
  std::vector<std::pair<std::string, std::string>> inputs;  // symbol -> exact value
  std::string printed, derived;                             // exact values of the printed and derived forms
  std::string printed_decimal, derived_decimal;
};

struct AuditEntry {
  std::string id;      // eqN or A.<name>
  std::string status;  // verified | erratum | not-checked
  std::string detail;
  std::string printed_latex;    // the printed expression, where one was checked
  std::string corrected_latex;  // erratum: the corrected expression (verified against the derivation)
  std::optional<Witness> witness;
};

std::vector<AuditEntry> run_audit(const Derivation& d, const AppendixA& a, const ClosedForms& c);

// Symbol name -> LaTeX, for every symbol the program uses.
const std::map<std::string, std::string>& latex_names();

}  // namespace impact3d::symbolic
