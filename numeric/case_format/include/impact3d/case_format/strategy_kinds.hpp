// The strategy kinds of the case format, one row each: the only place that lists them. A row gives the
// name in the case file, its keys (kind, and for a choice its values, the first the default), the key a
// sweep over friction varies, and the conversion to the mechanics' Strategy<Scalar>. The reader, the
// label of the report, the result's echo, --strategy and `plot` all read this table.
//
// Adding a strategy: its mechanics (numeric/strategies/, an alternative of Strategy<Scalar> in
// strategy.hpp and its branch in lean.hpp's solve_strategy), and a row here.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>

#include "impact3d/case_format/case_spec.hpp"
#include "impact3d/case_format/scalar_text.hpp"
#include "impact3d/mechanics/strategy.hpp"

namespace impact3d::case_format {

enum class ParameterType {
  non_negative,       // a number >= 0
  ratio_or_critical,  // a number of either sign, or "critical" (stored as an empty number)
  choice,             // one of `choices`; absent means the first
};

struct Parameter {
  std::string_view key;
  ParameterType type;
  std::array<std::string_view, 2> choices{};
};

template <typename Scalar>
std::optional<Scalar> optional_scalar(const std::optional<Number>& n) {
  if (!n) return std::nullopt;
  return to_scalar<Scalar>(*n);
}

struct PcCrashKind {
  static constexpr std::string_view name = "pc-crash";
  static constexpr std::array<Parameter, 1> parameters{{{"mu", ParameterType::non_negative}}};
  static constexpr std::string_view sweep_key = "mu";
  template <typename Scalar>
  static Strategy<Scalar> make(const StrategySpec& s) {
    return PcCrash<Scalar>{to_scalar<Scalar>(*s.number("mu"))};
  }
};

struct WachKind {
  static constexpr std::string_view name = "wach";
  static constexpr std::array<Parameter, 2> parameters{
      {{"mu", ParameterType::non_negative}, {"limit", ParameterType::choice, {"cir", "gir"}}}};
  static constexpr std::string_view sweep_key = "mu";
  template <typename Scalar>
  static Strategy<Scalar> make(const StrategySpec& s) {
    return Wach<Scalar>{to_scalar<Scalar>(*s.number("mu")), s.choice("limit") == "gir" ? WachLimit::gir : WachLimit::cir};
  }
};

struct BrachKind {
  static constexpr std::string_view name = "brach";
  static constexpr std::array<Parameter, 2> parameters{
      {{"mu_t", ParameterType::ratio_or_critical}, {"mu_z", ParameterType::ratio_or_critical}}};
  static constexpr std::string_view sweep_key = "mu_t";
  template <typename Scalar>
  static Strategy<Scalar> make(const StrategySpec& s) {
    return Brach<Scalar>{optional_scalar<Scalar>(s.number("mu_t")), optional_scalar<Scalar>(s.number("mu_z"))};
  }
};

using StrategyKinds = std::tuple<PcCrashKind, WachKind, BrachKind>;
inline constexpr std::size_t kStrategyKinds = std::tuple_size_v<StrategyKinds>;

// f(Row{}) for the row `kind` (StrategySpec::kind); every row gives f's result type.
template <typename F>
auto with_strategy_kind(std::size_t kind, F&& f) {
  return [&]<std::size_t... I>(std::index_sequence<I...>) {
    decltype(f(std::tuple_element_t<0, StrategyKinds>{})) out{};
    ((kind == I ? (out = f(std::tuple_element_t<I, StrategyKinds>{}), 0) : 0), ...);
    return out;
  }(std::make_index_sequence<kStrategyKinds>{});
}

struct KindRow {
  std::string_view name;
  std::span<const Parameter> parameters;
  std::string_view sweep_key;
};

inline KindRow strategy_kind(std::size_t kind) {
  return with_strategy_kind(kind, []<typename Row>(Row) {
    return KindRow{Row::name, std::span<const Parameter>(Row::parameters), Row::sweep_key};
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
  return with_strategy_kind(s.kind, [&]<typename Row>(Row) { return Row::template make<Scalar>(s); });
}

}  // namespace impact3d::case_format
