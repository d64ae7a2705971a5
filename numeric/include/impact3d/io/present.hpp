// SI results back into the case's unit system, as text with a chosen number of significant digits.
#pragma once

#include <string>
#include <vector>

#include "impact3d/io/case_spec.hpp"
#include "impact3d/io/json_writer.hpp"
#include "impact3d/io/scalar_text.hpp"
#include "impact3d/numeric/types.hpp"
#include "impact3d/numeric/units.hpp"

namespace impact3d::io {

template <typename Scalar>
struct Present {
  UnitFactors<Scalar> f;
  int digits;

  Present(Units u, int d) : f(unit_factors<Scalar>(u)), digits(d) {}

  std::string num(const Scalar& x) const { return scalar_to_text(x, digits); }
  std::string num(const Scalar& x, const Scalar& factor) const { return num(Scalar(x / factor)); }
  std::vector<std::string> vec(const Vec3<Scalar>& v, const Scalar& factor) const {
    return {num(v.x(), factor), num(v.y(), factor), num(v.z(), factor)};
  }
  // The same text written straight into a document.
  void put(JsonWriter& w, const Scalar& x) const {
    w.number([&](std::string& out) { append_scalar(out, x, digits); });
  }
  void put(JsonWriter& w, const Scalar& x, const Scalar& factor) const { put(w, Scalar(x / factor)); }
  void put_vec(JsonWriter& w, const Vec3<Scalar>& v, const Scalar& factor) const {
    w.number_row(3, [&](std::string& out, int i) { append_scalar(out, Scalar(v[i] / factor), digits); });
  }
};

inline const char* unit_label(Units u, const std::string& quantity) {
  const bool si = u == Units::SI;
  if (quantity == "mass") return si ? "kg" : "lb";
  if (quantity == "velocity") return si ? "m/s" : "mph";
  if (quantity == "angular_velocity") return si ? "rad/s" : "deg/s";
  if (quantity == "impulse") return si ? "N s" : "lbf s";
  if (quantity == "energy") return si ? "J" : "ft lbf";
  return "";
}

}  // namespace impact3d::io
