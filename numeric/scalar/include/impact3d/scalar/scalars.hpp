// The scalar types impact3d is instantiated, dispatched and verified at: the one list (as Drake's
// common/default_scalars.h), written in scalar_list.hpp and given here as types. The instantiation
// sources are compiled once per scalar of it; the program's --precision names, the precision a rounding
// warning suggests and the rows of `verify` all come from here.
//
// X(type, precision name, unit roundoff u): u is what rounding.hpp's bounds are stated in. Binary types
// have u = 2^(1 - p); the decimal types are held to 10^(1 - digits), what their digits promise (Boost
// cpp_bin_float<50> and MPFR at 100 digits carry a few bits more).
#pragma once

#include <cstddef>
#include <string_view>
#include <tuple>
#include <type_traits>

#include "impact3d/scalar/scalar_list.hpp"
#if IMPACT3D_MULTIPRECISION
#include "impact3d/scalar/multiprecision.hpp"
#endif

namespace impact3d {

#define IMPACT3D_SCALAR_TYPE_(type, name, u) type,
// The list as types; `void` closes it.
using ScalarList = std::tuple<IMPACT3D_SCALARS(IMPACT3D_SCALAR_TYPE_) void>;
#undef IMPACT3D_SCALAR_TYPE_
inline constexpr std::size_t kScalarCount = std::tuple_size_v<ScalarList> - 1;
#ifdef IMPACT3D_SCALAR_SLOTS
static_assert(kScalarCount <= IMPACT3D_SCALAR_SLOTS,
              "more scalars than numeric/CMakeLists.txt compiles instantiations for: raise IMPACT3D_SCALAR_SLOTS there");
#endif
template <std::size_t I>
using ScalarAt = std::tuple_element_t<I, ScalarList>;

struct Precision {
  std::string_view name;
  double unit_roundoff;
};

#define IMPACT3D_SCALAR_PRECISION_(type, name, u) Precision{name, u},
// The precisions, narrowest first.
inline constexpr Precision kPrecisions[] = {IMPACT3D_SCALARS(IMPACT3D_SCALAR_PRECISION_)};
#undef IMPACT3D_SCALAR_PRECISION_

template <typename Scalar>
inline constexpr std::string_view precision_name = {};
#define IMPACT3D_SCALAR_NAME_(type, name, u) \
  template <>                                \
  inline constexpr std::string_view precision_name<type> = name;
IMPACT3D_SCALARS(IMPACT3D_SCALAR_NAME_)
#undef IMPACT3D_SCALAR_NAME_

// f(std::integral_constant<std::size_t, I>{}) for each index I of the list, in order.
template <typename F>
constexpr void for_each_scalar_index(F&& f) {
  [&]<std::size_t... I>(std::index_sequence<I...>) { (f(std::integral_constant<std::size_t, I>{}), ...); }(
      std::make_index_sequence<kScalarCount>{});
}

// f(std::type_identity<Scalar>{}) for each scalar of the list, in order.
template <typename F>
void for_each_scalar(F&& f) {
  [&]<std::size_t... I>(std::index_sequence<I...>) { (f(std::type_identity<ScalarAt<I>>{}), ...); }(
      std::make_index_sequence<kScalarCount>{});
}

}  // namespace impact3d
