// SI results back into the case's unit system, as text with a chosen number of significant digits.
#pragma once

#include <string>
#include <vector>

#include "impact3d/case_format/case_spec.hpp"
#include "impact3d/case_format/json_writer.hpp"
#include "impact3d/case_format/scalar_text.hpp"
#include "impact3d/scalar/types.hpp"
#include "impact3d/mechanics/units.hpp"

namespace impact3d::case_format {

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
    w.number([&](auto& out) { append_scalar(out, x, digits); });
  }
  void put(JsonWriter& w, const Scalar& x, const Scalar& factor) const { put(w, Scalar(x / factor)); }
  void put_vec(JsonWriter& w, const Vec3<Scalar>& v, const Scalar& factor) const {
    w.number_row(3, [&](auto& out, int i) { append_scalar(out, Scalar(v[i] / factor), digits); });
  }
};

inline const char* unit_label(Units u, const std::string& quantity) {
  const bool us = u == Units::US;
  if (quantity == "mass") return us ? "lb" : "kg";
  if (quantity == "length") return us ? "ft" : "m";
  if (quantity == "velocity") return us ? "mph" : u == Units::metric_kmh ? "km/h" : "m/s";
  if (quantity == "angular_velocity") return u == Units::SI ? "rad/s" : "deg/s";
  if (quantity == "impulse") return us ? "lbf s" : "N s";
  if (quantity == "angular_momentum") return us ? "lbf ft s" : "N m s";
  if (quantity == "energy") return us ? "ft lbf" : "J";
  return "";
}

}  // namespace impact3d::case_format
