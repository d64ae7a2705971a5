// The strategy kinds of the case format: the mechanics' list (strategies/list.hpp) seen by name. A kind
// gives the name in the case file, its keys (kind, and for a choice its values, the first the default),
// the key a sweep over friction varies, and the conversion to the mechanics' Strategy<Scalar>. The
// reader, the label of the report, the result's echo, --strategy and `plot` all read it; none names a
// strategy.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <utility>

#include "impact3d/case_format/case_spec.hpp"
#include "impact3d/case_format/scalar_text.hpp"
#include "impact3d/mechanics/strategies/list.hpp"

namespace impact3d::case_format {

using impact3d::Parameter;
using impact3d::ParameterType;

template <typename Scalar>
std::optional<Scalar> optional_scalar(const std::optional<Number>& n) {
  if (!n) return std::nullopt;
  return to_scalar<Scalar>(*n);
}

// A spec's values as a strategy's make reads them: numbers in Scalar, a choice by its index.
template <typename Scalar, typename Spec>
struct SpecValues {
  const StrategySpec& s;
  std::optional<Scalar> number(std::string_view key) const { return optional_scalar<Scalar>(s.number(key)); }
  std::size_t choice_index(std::string_view key) const {
    const std::string& c = s.choice(key);
    for (const Parameter& p : Spec::parameters)
      if (p.key == key)
        for (std::size_t i = 0; i < p.choices.size(); ++i)
          if (p.choices[i] == c) return i;
    return 0;
  }
};

inline constexpr std::size_t kStrategyKinds = Strategies::size;

// f(std::integral_constant<kind>{}) for the kind `kind` (StrategySpec::kind, the index in the list);
// every kind gives f's result type.
template <typename F>
auto with_strategy_kind(std::size_t kind, F&& f) {
  return with_strategy_index(kind, std::forward<F>(f));
}

template <typename Scalar, std::size_t I>
using StrategyAt = std::variant_alternative_t<I, Strategy<Scalar>>;

struct KindRow {
  std::string_view name;
  std::span<const Parameter> parameters;
  std::string_view sweep_key;
};

inline KindRow strategy_kind(std::size_t kind) {
  return with_strategy_kind(kind, []<std::size_t I>(std::integral_constant<std::size_t, I>) {
    using Row = StrategyAt<double, I>;
    return KindRow{Row::name, std::span<const Parameter>(Row::parameters), Row::friction_key};
  });
}

// The row named `name`, if any.
inline std::optional<std::size_t> find_strategy_kind(std::string_view name) {
  for (std::size_t k = 0; k < kStrategyKinds; ++k)
    if (strategy_kind(k).name == name) return k;
  return std::nullopt;
}

// "pc-crash, wach or brach".
inline std::string strategy_kind_names() {
  std::string s;
  for (std::size_t k = 0; k < kStrategyKinds; ++k)
    s += std::string(k == 0 ? "" : k + 1 == kStrategyKinds ? " or " : ", ") + std::string(strategy_kind(k).name);
  return s;
}

// The text of a parameter as the user wrote it ("critical" for an empty ratio, the default choice).
inline std::string parameter_text(const StrategySpec& s, const Parameter& p) {
  if (p.type == ParameterType::choice) return s.choice(p.key);
  const auto& n = s.number(p.key);
  return n ? n->text : std::string("critical");
}

// The strategy as the user wrote it, e.g. "pc-crash mu=0.4" or "brach mu_t=critical mu_z=0".
inline std::string strategy_label(const StrategySpec& s) {
  const KindRow row = strategy_kind(s.kind);
  std::string label(row.name);
  for (const auto& p : row.parameters) {
    // Appended piece by piece: GCC 12 warns (-Wrestrict, falsely) on a chain of operator+ here.
    label += ' ';
    label += p.key;
    label += '=';
    label += parameter_text(s, p);
  }
  return label;
}

template <typename Scalar>
Strategy<Scalar> to_strategy(const StrategySpec& s) {
  return with_strategy_kind(s.kind, [&]<std::size_t I>(std::integral_constant<std::size_t, I>) {
    using Spec = StrategyAt<Scalar, I>;
    return Strategy<Scalar>(Spec::make(SpecValues<Scalar, Spec>{s}));
  });
}

}  // namespace impact3d::case_format
