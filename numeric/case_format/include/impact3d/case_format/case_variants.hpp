// Variants of one case, for Monte Carlo and sensitivity: the case file parsed once, and each variant
// read from its tree with new numbers at given paths (an uncertainty file's inputs). Each number is
// written as its exact 17-digit text (format_g17), so that every precision reads the sample's double.
#pragma once

#include <string>
#include <vector>

#include "impact3d/case_format/case_spec.hpp"
#include "impact3d/case_format/json_path.hpp"
#include "impact3d/case_format/json_tree.hpp"

namespace impact3d::case_format {

class CaseVariants {
 public:
  // `where[i]` names path i in messages ("$.inputs[2].path"). Throws CaseError there when a path
  // names nothing in the case, or something that is not a number; and the case's own errors.
  CaseVariants(const std::string& case_text, const std::vector<JsonPath>& paths, const std::vector<std::string>& where);
  CaseVariants(const CaseVariants& other);
  CaseVariants& operator=(const CaseVariants&) = delete;

  // The case with values[i] at path i. Throws CaseError where the variant breaks the case's rules (a
  // mass <= 0, a restitution above 1): the sample is then rejected, with that line as its reason.
  // Not for two threads at once: each thread takes a copy.
  CaseSpec with(const double* values);

  const CaseSpec& base() const { return base_; }
  // The case's own numbers at the paths, as read (each literal correctly rounded).
  std::vector<double> values() const;

 private:
  JsonValue root_;
  std::vector<JsonPath> paths_;
  std::vector<JsonValue*> slots_;
  CaseSpec base_;
  void resolve(const std::vector<std::string>* where);
};

}  // namespace impact3d::case_format
