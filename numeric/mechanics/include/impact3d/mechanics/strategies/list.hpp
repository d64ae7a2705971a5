// The strategies, registered once: every consumer (the solve, the case format's reader, echo and
// --strategy, the sweeps, certified decisions, sensitivities, reconstruction, verification) reads this
// list and each entry's own members, and names no strategy itself.
//
// Adding a strategy: its file here (its spec: parameters, make, convert, regime_decision; and its
// strategies::solve overload; see pc_crash.hpp), the engine primitives its closed forms need, and its
// name in the list below. A SIMD kernel for batch columns, if it has one, joins batch/columns.cpp.
#pragma once

#include <cstddef>
#include <optional>
#include <type_traits>
#include <utility>
#include <variant>

#include "impact3d/mechanics/strategies/brach.hpp"
#include "impact3d/mechanics/strategies/pc_crash.hpp"
#include "impact3d/mechanics/strategies/stronge.hpp"
#include "impact3d/mechanics/strategies/wach.hpp"

namespace impact3d {

template <template <typename> class... S>
struct StrategyList {
  template <typename Scalar>
  using variant = std::variant<S<Scalar>...>;
  static constexpr std::size_t size = sizeof...(S);
};

using Strategies = StrategyList<PcCrash, Wach, Brach, Stronge>;

template <typename Scalar>
using Strategy = Strategies::variant<Scalar>;

// f(std::integral_constant<index>{}, std::type_identity<its spec on double>{}) for each strategy in order.
template <typename F>
constexpr void for_each_strategy(F&& f) {
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    (f(std::integral_constant<std::size_t, I>{}, std::type_identity<std::variant_alternative_t<I, Strategy<double>>>{}), ...);
  }(std::make_index_sequence<Strategies::size>{});
}

// f(std::integral_constant<index>{}) for the strategy at `index`; every index gives f's result type,
// and an index past the list its value-initialized one.
template <typename F>
auto with_strategy_index(std::size_t index, F&& f) {
  return [&]<std::size_t... I>(std::index_sequence<I...>) {
    decltype(f(std::integral_constant<std::size_t, 0>{})) out{};
    ((index == I ? (out = f(std::integral_constant<std::size_t, I>{}), 0) : 0), ...);
    return out;
  }(std::make_index_sequence<Strategies::size>{});
}

template <typename Spec>
struct SpecScalar;
template <template <typename> class S, typename T>
struct SpecScalar<S<T>> {
  using type = T;
};

// The index of a spec (on any scalar) in the list.
template <typename Spec>
inline constexpr std::size_t strategy_index = []<std::size_t... I>(std::index_sequence<I...>) {
  using T = typename SpecScalar<Spec>::type;
  std::size_t at = Strategies::size;
  ((std::is_same_v<Spec, std::variant_alternative_t<I, Strategy<T>>> ? (at = I, 0) : 0), ...);
  return at;
}(std::make_index_sequence<Strategies::size>{});

// A strategy's numbers by f (a scalar to its twin and back, lean_twin.hpp).
template <typename To, typename From, typename F>
Strategy<To> convert_strategy(const Strategy<From>& st, F&& f) {
  return std::visit([&](const auto& s) { return Strategy<To>(s.template convert<To>(f)); }, st);
}

// How the strategy decides its regime from the inputs, if it does (strategy.hpp).
template <typename Scalar>
std::optional<RegimeDecision<Scalar>> regime_decision(const Strategy<Scalar>& st) {
  return std::visit([](const auto& s) { return s.regime_decision(); }, st);
}

}  // namespace impact3d
