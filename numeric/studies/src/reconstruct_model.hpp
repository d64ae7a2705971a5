// The model a reconstruction fits (reconstruct.hpp): the unknowns written into the case, the case
// solved once on dual numbers, and the evidence's outputs with their derivatives by the unknowns.
// Internal to io's sources.
#pragma once

#include <array>
#include <cstddef>
#include <limits>
#include <string>
#include <variant>
#include <vector>

#include <Eigen/Dense>

#include "impact3d/case_format/case_variants.hpp"
#include "impact3d/case_format/read_evidence.hpp"
#include "impact3d/studies/reconstruct.hpp"
#include "impact3d/mechanics/decisions.hpp"
#include "impact3d/mechanics/strategies/list.hpp"
#include "not_a_number.hpp"

namespace impact3d::studies::reconstruct_model {
using namespace case_format;  // the studies are written in the case format's terms

using Vector = Eigen::VectorXd;
using Matrix = Eigen::MatrixXd;

// The two branches of a strategy's regime, as the mechanics name the decision; none where the strategy
// decides no regime from the inputs.
struct Branches {
  const char* decision = nullptr;
  Regime when_true = Regime::as_given, when_false = Regime::as_given;
};

inline Branches branches_of(const Strategy<double>& st) {
  const auto d = regime_decision(st);
  if (!d) return {};
  return {d->decision, d->when_at_most, d->otherwise};
}

struct Eval {
  bool ok = false;
  std::string problem;
  Vector f, r;  // model value and standardized residual, per evidence component
  Matrix J;     // d r / d unknowns
  Regime regime = Regime::as_given;
  std::vector<std::string> warnings;
  FitStates states;
};

// A vehicle whose velocity the unknowns move: by a speed, a heading, or both.
struct MovedVelocity {
  int vehicle = 0;
  int speed = -1, heading = -1;  // places in the unknowns
  std::size_t slot = 0;          // its three components' first dual slot and variant path
  double base_speed = 0;
  Eigen::Vector3d direction;     // unit, as the case gives it
};

class Model {
 public:
  Model(const std::string& case_text, const EvidenceSpec& e, const ReconstructOptions& o);

  Eval evaluate(const Vector& theta, const ImposedBranch* imposed);
  std::size_t unknowns() const { return evidence_.unknowns.size(); }
  std::size_t components() const { return component_item_.size(); }
  const std::vector<double>& start() const { return start_; }
  const Branches& branches() const { return branches_; }
  const CaseSpec& base() const { return variants_.base(); }
  const StrategySpec& strategy() const { return strategy_; }
  Units units() const { return variants_.base().units; }
  // Every evidence component: its item, its output's place (or none for a speed) and its text.
  std::size_t item(std::size_t c) const { return component_item_[c]; }
  const std::string& output(std::size_t c) const { return component_name_[c]; }
  double value(std::size_t c) const { return y_[c]; }
  double sd(std::size_t c) const { return sd_[c]; }

 private:
  const EvidenceSpec& evidence_;
  Engine engine_;
  StrategySpec strategy_;
  bool replace_strategy_ = false;
  Branches branches_;
  std::vector<MovedVelocity> moved_;
  std::vector<std::size_t> path_slot_;  // per unknown: its slot (path unknowns only)
  std::vector<std::string> slot_path_;  // per slot: the case input it seeds
  std::vector<std::vector<std::size_t>> path_variants_;  // per unknown: its paths' places in the variants
  std::size_t variant_count_ = 0;
  CaseVariants variants_;
  std::vector<double> start_;
  std::vector<std::size_t> component_item_, component_output_;
  std::vector<std::string> component_name_;
  std::vector<char> component_angle_;
  std::vector<double> y_, sd_;
  static constexpr std::size_t kSpeedOutput = ~std::size_t{0};

  static std::vector<JsonPath> variant_paths(const EvidenceSpec& e, std::vector<std::string>& where);
};

}  // namespace impact3d::studies::reconstruct_model
