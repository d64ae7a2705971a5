// A figure for the HTML report: drawn by the program (gnuplot), placed by the library's page writer.
#pragma once

#include <string>

namespace impact3d::case_format {

struct ReportFigure {
  std::string caption;
  std::string svg;  // a whole SVG document
};

}  // namespace impact3d::case_format
