// A result rendered for a precision named by the user: one of the scalar list, or exact.
#include <stdexcept>

#include <fmt/format.h>

#include "render_certified.hpp"
#include "render_exact.hpp"

#include "impact3d/studies/precision.hpp"
#include "impact3d/case_format/result_csv.hpp"
#include "impact3d/scalar/scalars.hpp"

namespace impact3d::studies {
using namespace case_format;  // the studies are written in the case format's terms

std::vector<std::string> precision_names() {
  std::vector<std::string> names;
  for (const auto& p : kPrecisions) names.emplace_back(p.name);
#if IMPACT3D_MULTIPRECISION
  names.emplace_back("exact");
#endif
  return names;
}

std::string precision_problem(std::string_view precision) {
  for (const auto& name : precision_names())
    if (name == precision) return "";
#if IMPACT3D_MULTIPRECISION
  try {
    if (certified_bits(precision)) return "";
  } catch (const CaseError& e) {
    return e.what();
  }
#endif
  std::string list;
  for (const auto& name : precision_names()) list += (list.empty() ? "" : ", ") + name;
#if IMPACT3D_MULTIPRECISION
  list += ", certified, certified:BITS";
#endif
  return "not a precision (" + list + ")";
}

std::string render(const CaseSpec& spec, std::string_view precision, const RenderOptions& o) {
  if (o.units && *o.units != spec.units && precision == "exact")
    // Exact results are fractions of the case's own units; deg/s and km/h would make them irrational.
    throw CaseError("--units", fmt::format("exact results are written in the case's units ({})", units_name(spec.units)));
  if (o.format == Format::html && precision == "exact")
    throw CaseError("--precision", "the HTML report is written at a floating precision; exact results: impact3d solve --precision exact");
#if IMPACT3D_MULTIPRECISION
  if (o.format == Format::csv && certified_bits(precision))
    throw CaseError("--format", "CSV results are written at a floating precision or exact; certified results: impact3d solve --precision certified");
  if (o.format == Format::csv && precision == "exact") {
    // render_exact writes the document, fractions beside the 100-digit values: the cells are taken from
    // it as it is written.
    thread_local JsonPick pick = result_csv_pick();  // kept from case to case: no allocation once warm
    pick.clear();
    RenderOptions as_json = o;
    as_json.format = Format::jsonl;
    as_json.pick = &pick;
    const std::string document = render(spec, precision, as_json);
    return result_csv_from_document(document, pick, spec, o.line);
  }
  if (precision == "exact") return render_exact(spec, o);
  if (const auto bits = certified_bits(precision)) return render_certified(spec, *bits, o);
#endif
  std::string out;
  bool found = false;
  for_each_scalar([&]<typename Scalar>(std::type_identity<Scalar>) {
    if (precision_name<Scalar> != precision) return;
    out = render<Scalar>(spec, o);
    found = true;
  });
  if (!found) throw std::invalid_argument("no precision named " + std::string(precision));
  return out;
}

}  // namespace impact3d::studies
