// A double in a document the many-cases commands write (montecarlo, sensitivity, reconstruct): the
// shortest decimal that reads back as the same double (fmt's), the same on every platform; null where
// it is not finite (JSON has no NaN).
#pragma once

#include <cmath>

#include <fmt/format.h>

#include "impact3d/case_format/json_writer.hpp"

namespace impact3d::case_format {

inline void put_shortest(JsonWriter& w, double x) {
  if (std::isfinite(x)) w.raw(fmt::format("{}", x));
  else w.null();
}

}  // namespace impact3d::case_format
