// The case format's solve-and-write, and its writers, at one scalar of scalars.hpp:
// numeric/CMakeLists.txt compiles this file once per scalar with IMPACT3D_SCALAR_INDEX set.
#include <limits>

#include "impact3d/case_format/read_case.hpp"
#include "impact3d/case_format/render.hpp"
#include "impact3d/case_format/report_html.hpp"
#include "impact3d/case_format/report_text.hpp"
#include "impact3d/case_format/result_csv.hpp"
#include "impact3d/mechanics/analysis.hpp"

namespace impact3d::case_format {

template <typename Scalar>
std::string render(const CaseSpec& spec, const RenderOptions& o) {
  const Scene<Scalar> scene = to_scene<Scalar>(spec);
  const Analysis<Scalar> a = analyze(scene, to_strategies<Scalar>(spec), o.engine);
  const std::string precision(precision_name<Scalar>);
  // The numbers written in the units asked for: the writers present in their spec's units.
  CaseSpec storage;
  const CaseSpec* shown = &shown_in_units(spec, o, storage);
  if (o.format == Format::csv) return result_csv_rows(*shown, a, precision, o.line);
  if (is_json(o.format)) return result_json(*shown, a, precision, 0, false, {}, o.format == Format::jsonl, o.pick);
  const int digits = o.digits > 0 ? o.digits : std::numeric_limits<Scalar>::digits10;
  if (o.format == Format::html) return report_html(*shown, a, precision, digits, o.figures ? *o.figures : std::vector<ReportFigure>{}, o.figures_note);
  return report_text(*shown, a, precision, digits);
}

template std::string render<ScalarAt<IMPACT3D_SCALAR_INDEX>>(const CaseSpec&, const RenderOptions&);
template std::string report_html(const CaseSpec&, const Analysis<ScalarAt<IMPACT3D_SCALAR_INDEX>>&, const std::string&, int,
                                 const std::vector<ReportFigure>&, const std::string&);
template std::string report_text(const CaseSpec&, const Analysis<ScalarAt<IMPACT3D_SCALAR_INDEX>>&, const std::string&, int);
template std::string result_json(const CaseSpec&, const Analysis<ScalarAt<IMPACT3D_SCALAR_INDEX>>&, const std::string&, int, bool,
                                 const std::function<void(JsonWriter&)>&, bool, JsonPick*,
                                 const std::function<void(JsonWriter&, std::size_t)>&);
template std::string result_csv_rows(const CaseSpec&, const Analysis<ScalarAt<IMPACT3D_SCALAR_INDEX>>&, const std::string&, long);
template Scene<ScalarAt<IMPACT3D_SCALAR_INDEX>> to_scene<ScalarAt<IMPACT3D_SCALAR_INDEX>>(const CaseSpec&);
template std::vector<Strategy<ScalarAt<IMPACT3D_SCALAR_INDEX>>> to_strategies<ScalarAt<IMPACT3D_SCALAR_INDEX>>(const CaseSpec&);

}  // namespace impact3d::case_format
