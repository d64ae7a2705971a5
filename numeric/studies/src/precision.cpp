// A result rendered at a precision the user named: a scalar of the list, exact or certified.
#include <fmt/format.h>

#include "render_certified.hpp"
#include "render_exact.hpp"

#include "impact3d/studies/precision.hpp"
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

PrecisionChoice parse_precision(std::string_view name) {
  for (std::size_t i = 0; i < kScalarCount; ++i)
    if (kPrecisions[i].name == name) return FloatingPrecision{i};
#if IMPACT3D_MULTIPRECISION
  if (name == "exact") return ExactPrecision{};
  if (const auto bits = certified_bits(name)) return CertifiedPrecision{*bits};
#endif
  std::string list;
  for (const auto& n : precision_names()) list += (list.empty() ? "" : ", ") + n;
#if IMPACT3D_MULTIPRECISION
  list += ", certified, certified:BITS";
#endif
  throw CaseError("--precision", "not a precision (" + list + ")");
}

std::string precision_problem(std::string_view name) {
  try {
    (void)parse_precision(name);
    return "";
  } catch (const CaseError& e) {
    return e.what();
  }
}

std::string precision_label(const PrecisionChoice& p) {
  if (const auto* f = std::get_if<FloatingPrecision>(&p)) return std::string(kPrecisions[f->index].name);
  if (std::holds_alternative<ExactPrecision>(p)) return "exact";
  const long bits = std::get<CertifiedPrecision>(p).bits;
  return bits ? fmt::format("certified:{}", bits) : "certified";
}

std::string render(const CaseSpec& spec, const PrecisionChoice& precision, const RenderOptions& o) {
  const bool exact = std::holds_alternative<ExactPrecision>(precision);
  if (o.units && *o.units != spec.units && exact)
    // Exact results are fractions of the case's own units; deg/s and km/h would make them irrational.
    throw CaseError("--units", fmt::format("exact results are written in the case's units ({})", units_name(spec.units)));
  if (o.format == Format::html && exact)
    throw CaseError("--precision", "the HTML report is written at a floating precision; exact results: impact3d solve --precision exact");
#if IMPACT3D_MULTIPRECISION
  if (o.format == Format::csv && std::holds_alternative<CertifiedPrecision>(precision))
    throw CaseError("--format", "CSV results are written at a floating precision or exact; certified results: impact3d solve --precision certified");
  if (exact) return render_exact(spec, o);
  if (const auto* c = std::get_if<CertifiedPrecision>(&precision)) return render_certified(spec, c->bits, o);
#endif
  std::string out;
  with_floating_scalar(std::get<FloatingPrecision>(precision), [&]<typename Scalar>() { out = render<Scalar>(spec, o); });
  return out;
}

}  // namespace impact3d::studies
