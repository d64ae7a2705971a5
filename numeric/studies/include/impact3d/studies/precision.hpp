// A read case solved at a precision named by the user and written as case_format/render.hpp's
// render<Scalar> writes it: a floating scalar of the list (scalar/scalars.hpp) or, with the
// multiprecision scalars, exact (fractions) or certified (Arb's balls).
#pragma once

#include <string>
#include <cstddef>
#include <string_view>
#include <variant>
#include <vector>

#include "impact3d/case_format/render.hpp"

namespace impact3d::studies {

using case_format::CaseSpec;
using case_format::RenderOptions;
using case_format::render;

// A precision as the user names it, parsed once where it is named (parse_precision): a floating scalar
// of the list, by its index there; exact (fractions where the result is rational, beside the 100-digit
// computation); or certified (Arb's balls; bits 0: the default, render_certified.hpp).
struct FloatingPrecision {
  std::size_t index = 0;
  bool operator==(const FloatingPrecision&) const = default;
};
struct ExactPrecision {
  bool operator==(const ExactPrecision&) const = default;
};
struct CertifiedPrecision {
  long bits = 0;
  bool operator==(const CertifiedPrecision&) const = default;
};
using PrecisionChoice = std::variant<FloatingPrecision, ExactPrecision, CertifiedPrecision>;

// The floating precision of `Scalar`, a scalar of the list.
template <typename Scalar>
constexpr FloatingPrecision floating_precision() {
  static_assert(!precision_name<Scalar>.empty(), "not a scalar of the list (scalar_list.hpp)");
  std::size_t index = 0;
  for_each_scalar_index([&]<std::size_t I>(std::integral_constant<std::size_t, I>) {
    if (std::is_same_v<ScalarAt<I>, Scalar>) index = I;
  });
  return {index};
}

// f.template operator()<Scalar>() for the floating scalar `p` names.
template <typename F>
void with_floating_scalar(const FloatingPrecision& p, F&& f) {
  for_each_scalar_index([&]<std::size_t I>(std::integral_constant<std::size_t, I>) {
    if (I == p.index) f.template operator()<ScalarAt<I>>();
  });
}

// The names parse_precision takes without BITS: every scalar of scalars.hpp and, with the
// multiprecision scalars, "exact" ("certified" and "certified:BITS" besides).
std::vector<std::string> precision_names();

// What is wrong with a name parse_precision would refuse; empty for one it takes: those of
// precision_names() and, with the multiprecision scalars, "certified" and "certified:BITS" (ball
// arithmetic, scalar/ball.hpp; BITS from 16 to 8192).
std::string precision_problem(std::string_view name);

// The precision `name` names; throws CaseError("--precision", precision_problem's words) for another.
PrecisionChoice parse_precision(std::string_view name);

// As the user names it: "double", "exact", "certified", "certified:128".
std::string precision_label(const PrecisionChoice& p);

// The case at the precision.
std::string render(const CaseSpec& spec, const PrecisionChoice& precision, const RenderOptions& o);
// The same, the precision named (parse_precision): for tools and tests that hold a name.
inline std::string render(const CaseSpec& spec, std::string_view precision, const RenderOptions& o) {
  return render(spec, parse_precision(precision), o);
}

}  // namespace impact3d::studies
