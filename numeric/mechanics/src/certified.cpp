// The certified solve (mechanics/certified.hpp): analyze at the ball scalar, once per strategy under a
// decision log, and once more per undecided decision with that decision's other branch.
#include "impact3d/mechanics/certified.hpp"

#include <cstring>
#include <utility>

namespace impact3d {
namespace {

struct Run {
  std::optional<Analysis<Ball>> analysis;
  std::vector<Decision> decisions;
  std::string failure;
};

Run run(const Scene<Ball>& s, const Strategy<Ball>& st, Engine engine, const std::string& flip) {
  Run r;
  DecisionLog log;
  log.flip = flip;
  {
    const DecisionRecording recording(log);
    try {
      r.analysis = analyze(s, std::vector<Strategy<Ball>>{st}, engine);
    } catch (const SolveError& e) {
      r.failure = e.what();
    }
  }
  r.decisions = std::move(log.decisions);
  return r;
}

}  // namespace

CertifiedAnalysis certified_analyze(const Scene<Ball>& s, const std::vector<Strategy<Ball>>& strategies, Engine engine) {
  CertifiedAnalysis out;
  out.bits = ball_bits;
  for (std::size_t k = 0; k < strategies.size(); ++k) {
    Run main = run(s, strategies[k], engine, "");
    if (!main.analysis) {
      std::string message = main.failure;
      for (const auto& d : main.decisions)
        if (d.status == DecisionStatus::undecided)
          message += "; undecided at " + std::to_string(ball_bits) + " bits: " + d.name + " (" + d.detail + ")";
      SolveError e(message);
      e.strategy = k;
      throw e;
    }
    if (k == 0) {
      out.analysis = *main.analysis;
      out.analysis.solutions.clear();
    }
    out.analysis.solutions.push_back(main.analysis->solutions.front());
    std::vector<CertifiedAlternative> alternatives;
    for (const auto& d : main.decisions) {
      // An unnamed comparison is never flipped: it has no other branch to show.
      if (d.status != DecisionStatus::undecided || d.name == decision_names::unnamed) continue;
      Run other = run(s, strategies[k], engine, d.name);
      CertifiedAlternative a{d.name, std::nullopt, std::move(other.decisions), std::move(other.failure)};
      if (other.analysis) a.solution = other.analysis->solutions.front();
      alternatives.push_back(std::move(a));
    }
    out.decisions.push_back(std::move(main.decisions));
    out.alternatives.push_back(std::move(alternatives));
  }
  return out;
}

bool same_result_at_tie(const std::string& decision) {
  bool regime = false;
  for_each_strategy([&](auto, auto spec) {
    for (const char* d : decltype(spec)::type::regime_decisions) regime = regime || decision == d;
  });
  return regime;
}

bool chooses_impulse(const std::string& decision) {
  namespace n = decision_names;
  for (const char* d : {n::approach, n::ratio_sign, n::normal_impulse_sign, n::volume, n::z_sliding, n::energy_loss_sign,
                        n::pdof, n::swerve, n::heading_after, n::cil_direction})
    if (decision == d) return false;
  return true;  // the regime, the cap, the plane, and whatever is not named: assume it chose
}

namespace {

// One zero question a decision asked: its ball, and whether the exact value is zero.
struct ZeroQuestion {
  const Ball* ball;
  bool exactly_zero;
};

// A name that merges several zero questions (the volume's, the sliding's, the swerve's) is a tie only
// when its balls left at least one open (a ball holding 0) and each one left open is exactly zero: one
// exactly zero beside another undecided and not zero is no tie.
bool open_questions_zero(const std::vector<ZeroQuestion>& questions) {
  bool any_open = false;
  for (const auto& q : questions) {
    if (!q.ball->contains_zero()) continue;
    if (!q.exactly_zero) return false;
    any_open = true;
  }
  return any_open;
}

}  // namespace

std::vector<std::string> exact_ties(const std::vector<Decision>& decisions, const Strategy<rational>& strategy,
                                    const Solution<rational>& exact, const Solution<Ball>& balls) {
  namespace n = decision_names;
  const rational zero(0);
  // The limit the strategy's regime decision compares its ratio against (the GIR, or the cap a Wach
  // solution used, eqs 19-20), where it decides one.
  const auto decision = regime_decision(strategy);
  auto cap_is_zero = [&]() {
    return decision && exact.impulse.*decision->limit && *(exact.impulse.*decision->limit) == zero;
  };
  auto limit_tie = [&]() {
    return decision && exact.impulse.*decision->limit && *(exact.impulse.*decision->limit) == decision->mu;
  };
  const bool plane_undefined = has_warning(exact.impulse.codes, WarningCode::plane_undefined);
  std::vector<std::string> ties;
  for (const auto& d : decisions) {
    if (d.status != DecisionStatus::undecided) continue;
    const char* name = d.name.c_str();
    bool tie = false;
    if (decision && !std::strcmp(name, decision->decision))
      tie = limit_tie();
    else if (!std::strcmp(name, n::plane_direction))
      tie = plane_undefined;  // exactly, the direction's length is zero
    else if (!std::strcmp(name, n::fallback_direction))
      tie = plane_undefined && cap_is_zero();
    else if (!std::strcmp(name, n::ratio_sign)) {
      // Wach's alone (its cap). A decimal mu's ball is exact or excludes 0, so only a capped ratio is undecided:
      // the tie is the cap's, which, exactly zero, the exact solve also caps at (mu >= 0).
      tie = cap_is_zero();
    } else if (!std::strcmp(name, n::normal_impulse_sign))
      tie = exact.impulse.P_C.x() == zero;
    else if (!std::strcmp(name, n::volume))  // post_impact's axis_change along t, and V_rn after
      tie = open_questions_zero({{&balls.V_ri.y(), exact.V_ri.y() == zero},
                                 {&balls.V_rf.y(), exact.V_rf.y() == zero},
                                 {&balls.V_rf.x(), exact.V_rf.x() == zero}});
    else if (!std::strcmp(name, n::z_sliding))
      tie = open_questions_zero({{&balls.V_ri.z(), exact.V_ri.z() == zero}, {&balls.V_rf.z(), exact.V_rf.z() == zero}});
    else if (!std::strcmp(name, n::swerve)) {
      // post_impact's questions: the initial sliding, then (where it is not zero) the final, then (where
      // that is not zero) the final sliding across and along the initial, V_ri x V_rf and V_ri . V_rf in
      // the contact plane: rational.
      const rational across = exact.V_ri.y() * exact.V_rf.z() - exact.V_ri.z() * exact.V_rf.y();
      const rational along = exact.V_ri.y() * exact.V_rf.y() + exact.V_ri.z() * exact.V_rf.z();
      std::vector<ZeroQuestion> asked{{&balls.sliding_before, exact.V_ri.y() == zero && exact.V_ri.z() == zero}};
      if (!balls.sliding_before.contains_zero()) {
        asked.push_back({&balls.sliding_after, exact.V_rf.y() == zero && exact.V_rf.z() == zero});
        if (!balls.sliding_after.contains_zero() && balls.swerve_speed && balls.sliding_along) {
          asked.push_back({&*balls.swerve_speed, across == zero});
          asked.push_back({&*balls.sliding_along, along == zero});
        }
      }
      tie = open_questions_zero(asked);
    } else if (!std::strcmp(name, n::energy_loss_sign))
      tie = exact.energy_loss == zero;
    if (tie)
      ties.push_back(d.name);
    else if (chooses_impulse(d.name))
      break;  // the balls may have left the exact solve's branch here: what they compared after is not its to judge
  }
  return ties;
}

}  // namespace impact3d
