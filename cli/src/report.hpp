// impact3d report: the case as one self-contained HTML page (case_format/report_html.hpp) with the figures of
// `plot` inlined.
#pragma once

#include <optional>
#include <string>

#include "impact3d/mechanics/problem.hpp"
#include "impact3d/mechanics/units.hpp"

namespace impact3d::cli {

struct ReportOptions {
  std::string case_path, out_file;
  std::string precision = "double";
  int digits = 0;  // 0: 10 at double, else the precision's digits10
  Engine engine = Engine::generated;
  std::optional<Units> units;
  bool figures = true;
};

// Writes the page to out_file (a link there is replaced, not followed) and returns its name and a line
// end. Without gnuplot the page says the figures are left out and why.
std::string report(const ReportOptions& o);

}  // namespace impact3d::cli
