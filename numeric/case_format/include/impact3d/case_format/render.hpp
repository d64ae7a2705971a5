// A read case solved at one floating scalar of the list and written as the contract's result (JSON) or the text report.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "impact3d/case_format/case_spec.hpp"
#include "impact3d/case_format/json_pick.hpp"
#include "impact3d/case_format/report_figure.hpp"
#include "impact3d/mechanics/problem.hpp"
#include "impact3d/scalar/scalars.hpp"

namespace impact3d::case_format {

struct RenderOptions {
  std::string format = "text";  // "text" | "json" | "jsonl" (the JSON document on one line) | "html" | "csv"
  int digits = 0;               // text report; 0 = the precision's digits10
  Engine engine = Engine::generated;
  JsonPick* pick = nullptr;  // json, jsonl: where the values it names are written (json_pick.hpp)
  std::vector<WarningSet>* warning_codes = nullptr;  // when given: each result's warnings as codes
  std::optional<Units> units;  // the unit system written; empty: the case's
  const std::vector<ReportFigure>* figures = nullptr;  // html: the figures placed on the page
  std::string figures_note;                            // html: said above them (e.g. why there are none)
  long line = 0;  // csv: the input line each row starts with (result_csv.hpp)
};

// Throws CaseError for inputs that fail the arithmetic checks, SolveError for no solution.
template <typename Scalar>
std::string render(const CaseSpec& spec, const RenderOptions& o);

#define IMPACT3D_EXTERN_RENDER_(type, name, u) \
  extern template std::string render<type>(const CaseSpec&, const RenderOptions&);
IMPACT3D_SCALARS(IMPACT3D_EXTERN_RENDER_)
#undef IMPACT3D_EXTERN_RENDER_

}  // namespace impact3d::case_format
