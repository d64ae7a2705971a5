// The audit of the paper: every printed expression the derivation can decide, and every claim of the
// text it can decide, compared with it. A status is never written by hand: it is a function of the
// comparisons an entry carries (status_of), and only the Auditor (audit_checks.hpp) makes comparisons.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "appendix_a.hpp"
#include "closed_forms.hpp"
#include "model.hpp"

namespace impact3d::symbolic {

// Exact inputs at which two expressions differ, and their two values side by side.
struct Witness {
  std::vector<std::pair<std::string, std::string>> inputs;  // symbol -> exact value
  std::string left_name, right_name;                        // e.g. "printed", "derived"
  std::string left, right;                                  // exact values
  std::string left_decimal, right_decimal;                  // with enough digits to see them differ
};

class Auditor;

// One comparison the generator ran: two expressions decided identical or not by exact algebra.
class Check {
 public:
  const std::string& what() const { return what_; }
  bool expect_equal() const { return expect_equal_; }  // a claim may assert that two things differ
  bool equal() const { return equal_; }
  bool holds() const { return equal_ == expect_equal_; }
  const std::optional<Witness>& witness() const { return witness_; }

 private:
  friend class Auditor;
  Check(std::string what, bool expect_equal, bool equal, std::optional<Witness> w)
      : what_(std::move(what)), expect_equal_(expect_equal), equal_(equal), witness_(std::move(w)) {}
  std::string what_;
  bool expect_equal_, equal_;
  std::optional<Witness> witness_;
};

// How a printed item may be read, and what comparing it under that reading gives.
struct Reading {
  std::string description;
  std::string latex;  // the reading as a formula
  bool used_by_implementation = false;
  std::vector<Check> checks;
};

enum class EntryKind {
  formula,     // a printed expression: verified or erratum
  ambiguous,   // a printed expression with more than one reading, each compared
  definition,  // nothing to compare: a definition, notation, a starting point
  claim,       // a statement of the text or a figure: claim-checked or claim-contradicted
};

struct AuditEntry {
  std::string id;  // eqN, A.<name>, fig8.<name>, conclusion.<name>
  EntryKind kind = EntryKind::definition;
  std::string detail;
  std::string claim;            // kind claim: the paper's words
  std::string printed_latex;    // the printed expression, where one was compared
  std::vector<Check> checks;    // formula and claim
  std::vector<Check> corrections;  // erratum: the corrected expression compared with the derivation
  std::string corrected_latex;
  std::vector<Reading> readings;  // ambiguous
};

// verified | erratum | ambiguous | definition | claim-checked | claim-contradicted, from the entry's
// comparisons alone; throws std::logic_error for an entry whose comparisons cannot earn a status.
std::string status_of(const AuditEntry& e);

std::vector<AuditEntry> run_audit(const Derivation& d, const AppendixA& a, const ClosedForms& c);

// Symbol name -> LaTeX, for every symbol the program uses.
const std::map<std::string, std::string>& latex_names();
// Symbol name -> what it stands for, in words (for witnesses).
std::string symbol_meaning(const std::string& name);

}  // namespace impact3d::symbolic
