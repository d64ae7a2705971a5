// A read case solved at one precision and written as the contract's result (JSON) or the text report.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "impact3d/io/case_spec.hpp"
#include "impact3d/io/json_pick.hpp"
#include "impact3d/io/report_figure.hpp"
#include "impact3d/numeric/problem.hpp"
#include "impact3d/numeric/scalars.hpp"

namespace impact3d::io {

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

// The precisions `render` takes by name: every scalar of scalars.hpp and, with the multiprecision
// scalars, "exact" (fractions where the result is rational, beside the 100-digit computation).
std::vector<std::string> precision_names();

// What is wrong with a precision name `render` would refuse; empty for one it takes: those of
// precision_names() and, with the multiprecision scalars, "certified" and "certified:BITS" (ball
// arithmetic, numeric/ball.hpp; BITS from 16 to 8192).
std::string precision_problem(std::string_view precision);

// The case at the named precision; throws std::invalid_argument for a name precision_names() lacks.
std::string render(const CaseSpec& spec, std::string_view precision, const RenderOptions& o);

}  // namespace impact3d::io
