// A read case solved at one floating scalar of the list and written as the contract's result (JSON) or the text report.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "impact3d/case_format/case_spec.hpp"
#include "impact3d/case_format/json_pick.hpp"
#include "impact3d/case_format/report_figure.hpp"
#include "impact3d/mechanics/problem.hpp"
#include "impact3d/scalar/scalars.hpp"

namespace impact3d::case_format {

// The forms a result is written in: the text report, the contract's JSON (jsonl: on one line), the HTML
// page, batch's CSV rows. Parsed once, where the user names one (the program's options, the binding).
enum class Format { text, json, jsonl, html, csv };
inline constexpr std::pair<Format, std::string_view> kFormatNames[] = {
    {Format::text, "text"}, {Format::json, "json"}, {Format::jsonl, "jsonl"}, {Format::html, "html"}, {Format::csv, "csv"}};
constexpr std::string_view format_name(Format f) {
  for (const auto& [format, name] : kFormatNames)
    if (format == f) return name;
  return {};
}
constexpr std::optional<Format> parse_format(std::string_view name) {
  for (const auto& [format, n] : kFormatNames)
    if (n == name) return format;
  return std::nullopt;
}
constexpr bool is_json(Format f) { return f == Format::json || f == Format::jsonl; }

struct RenderOptions {
  Format format = Format::text;
  int digits = 0;               // text report; 0 = the precision's digits10
  Engine engine = Engine::generated;
  JsonPick* pick = nullptr;  // json, jsonl: where the values it names are written (json_pick.hpp)
  std::optional<Units> units;  // the unit system written; empty: the case's
  const std::vector<ReportFigure>* figures = nullptr;  // html: the figures placed on the page
  std::string figures_note;                            // html: said above them (e.g. why there are none)
  long line = 0;  // csv: the input line each row starts with (result_csv.hpp)
};

// The case as the writers present it, whose numbers they write in its spec's units: `spec` itself, or
// its copy in `storage` in the units o.units asks for.
inline const CaseSpec& shown_in_units(const CaseSpec& spec, const RenderOptions& o, CaseSpec& storage) {
  if (!o.units || *o.units == spec.units) return spec;
  storage = spec;
  storage.units = *o.units;
  return storage;
}

// Throws CaseError for inputs that fail the arithmetic checks, SolveError for no solution.
template <typename Scalar>
std::string render(const CaseSpec& spec, const RenderOptions& o);

#define IMPACT3D_EXTERN_RENDER_(type, name, u) \
  extern template std::string render<type>(const CaseSpec&, const RenderOptions&);
IMPACT3D_SCALARS(IMPACT3D_EXTERN_RENDER_)
#undef IMPACT3D_EXTERN_RENDER_

}  // namespace impact3d::case_format
