// `impact3d batch`: many cases, one per line (../shared/spec/many-cases.md), solved on every core and
// answered line for line in input order.
#pragma once

#include <string>
#include <vector>

#include "impact3d/mechanics/problem.hpp"

namespace impact3d::cli {

struct BatchOptions {
  std::string input = "-";   // JSON Lines file, or standard input
  std::string output = "-";  // or standard output
  unsigned jobs = 0;         // 0: every core
  std::vector<std::string> strategies;  // --strategy, replacing every row's
  std::string precision = "double";
  std::string format = "jsonl";        // of the output: jsonl or csv
  std::string input_format = "auto";   // jsonl, csv, or auto: csv when the file name ends in .csv
  Engine engine = Engine::generated;
};

// Writes one answer per case line (a JSON line, or CSV rows, one per result); returns the exit status: 0 every row solved, 1 any rejected (after
// writing every row), 130 or 143 when interrupted (the rows finished are written whole).
int batch(const BatchOptions& o);

}  // namespace impact3d::cli
