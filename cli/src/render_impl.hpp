// The body shared by the render_*.cpp files.
#pragma once

#include <limits>

#include "impact3d/case/read_case.hpp"
#include "render.hpp"
#include "report_text.hpp"

namespace impact3d::cli {

template <typename Scalar>
std::string render(const io::CaseSpec& spec, const RenderOptions& o, const std::string& precision) {
  const Scene<Scalar> scene = io::to_scene<Scalar>(spec);
  const Analysis<Scalar> a = analyze(scene, io::to_strategies<Scalar>(spec), o.engine);
  if (o.format == "json") return io::result_json(spec, a, precision);
  const int digits = o.digits > 0 ? o.digits : std::numeric_limits<Scalar>::digits10;
  return report_text(spec, a, precision, digits);
}

}  // namespace impact3d::cli
