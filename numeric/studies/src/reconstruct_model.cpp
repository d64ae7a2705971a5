// The model of a reconstruction (reconstruct_model.hpp). Each evaluation writes the unknowns into the
// case's tree (case_variants.hpp), reads it as `solve` reads a case, and solves it once on dual numbers
// seeded at the numbers the unknowns move, so that the values and the exact Jacobian come from one pass.
#include "reconstruct_model.hpp"

#include <cmath>
#include <numbers>
#include <optional>
#include <utility>

#include <fmt/format.h>

#include "impact3d/studies/angle_difference.hpp"
#include "impact3d/case_format/case_numbers.hpp"
#include "impact3d/case_format/escape.hpp"
#include "impact3d/studies/montecarlo.hpp"
#include "impact3d/studies/result_numbers.hpp"
#include "impact3d/case_format/to_scene.hpp"
#include "impact3d/mechanics/dual_analysis.hpp"

namespace impact3d::studies::reconstruct_model {
using namespace case_format;  // the studies are written in the case format's terms

namespace {

constexpr double kDegree = std::numbers::pi / 180;

// The mirror of an off-diagonal inertia entry ([i][j] for [j][i]), which moves with it so that the
// tensor stays symmetric (case_numbers.hpp); none for any other path.
std::optional<JsonPath> mirror_of(const JsonPath& p) {
  const std::size_t n = p.size();
  if (n < 3 || p[n - 3].kind != PathStep::Kind::key || p[n - 3].key != "inertia" || p[n - 2].kind != PathStep::Kind::index ||
      p[n - 1].kind != PathStep::Kind::index || p[n - 2].index == p[n - 1].index)
    return std::nullopt;
  JsonPath m = p;
  std::swap(m[n - 2].index, m[n - 1].index);
  return m;
}

}  // namespace

std::vector<JsonPath> Model::variant_paths(const EvidenceSpec& e, std::vector<std::string>& where) {
  std::vector<JsonPath> paths;
  for (int v = 0; v < 2; ++v)
    for (std::size_t u = 0; u < e.unknowns.size(); ++u) {
      const Unknown& k = e.unknowns[u];
      if (k.kind == Unknown::Kind::path || k.vehicle != v) continue;
      for (std::size_t c = 0; c < 3; ++c) {
        paths.push_back({PathStep::of_key("vehicles"), PathStep::of_index(static_cast<std::size_t>(v)), PathStep::of_key("velocity"),
                         PathStep::of_index(c)});
        where.push_back(fmt::format("$.unknowns[{}]", u));
      }
      break;  // the speed and the heading of one vehicle move the same three numbers
    }
  for (std::size_t u = 0; u < e.unknowns.size(); ++u)
    if (e.unknowns[u].kind == Unknown::Kind::path) {
      paths.push_back(e.unknowns[u].path);
      where.push_back(fmt::format("$.unknowns[{}].path", u));
      if (const auto mirror = mirror_of(e.unknowns[u].path)) {
        paths.push_back(*mirror);
        where.push_back(fmt::format("$.unknowns[{}].path", u));
      }
    }
  return paths;
}

Model::Model(const std::string& case_text, const EvidenceSpec& e, const ReconstructOptions& o)
    : evidence_(e), engine_(o.engine), variants_([&] {
        std::vector<std::string> where;
        std::vector<JsonPath> paths = variant_paths(e, where);
        return CaseVariants(case_text, paths, where);
      }()) {
  const CaseSpec& spec = variants_.base();
  if (o.strategy) {
    strategy_ = *o.strategy, replace_strategy_ = true;
  } else {
    if (spec.strategies.size() != 1)
      throw CaseError("$.strategy", fmt::format("holds {} strategies: a reconstruction fits one (give it with --strategy)", spec.strategies.size()));
    strategy_ = spec.strategies.front();
  }
  {
    CaseSpec one = spec;
    one.strategies = {strategy_};
    branches_ = branches_of(to_strategies<double>(one).front());
  }
  const std::vector<double> values = variants_.values();
  std::size_t slot = 0;
  path_slot_.assign(e.unknowns.size(), 0);
  path_variants_.assign(e.unknowns.size(), {});
  for (int v = 0; v < 2; ++v) {
    MovedVelocity m;
    m.vehicle = v;
    for (std::size_t u = 0; u < e.unknowns.size(); ++u) {
      const Unknown& k = e.unknowns[u];
      if (k.kind == Unknown::Kind::speed && k.vehicle == v) m.speed = static_cast<int>(u);
      if (k.kind == Unknown::Kind::heading && k.vehicle == v) m.heading = static_cast<int>(u);
    }
    if (m.speed < 0 && m.heading < 0) continue;
    m.slot = slot;
    const Eigen::Vector3d velocity(values[slot], values[slot + 1], values[slot + 2]);
    m.base_speed = velocity.norm();
    const int first = m.speed >= 0 ? m.speed : m.heading;
    if (!(m.base_speed > 0))
      throw CaseError(fmt::format("$.unknowns[{}]", first),
                      fmt::format("vehicle {}'s velocity in the case is zero: its direction, which the reconstruction keeps, is undefined", v));
    m.direction = velocity / m.base_speed;
    if (m.heading >= 0 && !(std::hypot(m.direction.x(), m.direction.y()) > 1e-9))
      throw CaseError(fmt::format("$.unknowns[{}]", m.heading), fmt::format("vehicle {}'s velocity in the case is vertical: it has no heading", v));
    for (int c = 0; c < 3; ++c) slot_path_.push_back(fmt::format("$.vehicles[{}].velocity[{}]", v, c));
    slot += 3;
    moved_.push_back(m);
  }
  std::size_t variant = slot;  // the moved velocities' paths come first, one per slot
  CaseSpec listed = spec;
  const CaseInputs in = case_inputs(listed);
  for (std::size_t u = 0; u < e.unknowns.size(); ++u) {
    const Unknown& k = e.unknowns[u];
    if (k.kind != Unknown::Kind::path) continue;
    const std::string at = fmt::format("$.unknowns[{}].path", u);
    if (replace_strategy_ && k.path_text.rfind("$.strategy", 0) == 0)
      throw CaseError(at, "names an input of the case's strategy, which --strategy replaces");
    for (const MovedVelocity& m : moved_)
      if (k.path_text.rfind(fmt::format("$.vehicles[{}].velocity", m.vehicle), 0) == 0)
        throw CaseError(at, fmt::format("moves vehicle {}'s velocity, which its speed or heading unknown already moves", m.vehicle));
    // The case input it seeds: its own path, or its mirror's, which the inputs list instead ([0][2]
    // for [2][0]).
    std::string seeded;
    const auto mirror = mirror_of(k.path);
    for (const CaseInput& i : in.inputs)
      if (i.path == k.path_text || (mirror && i.path == path_text(*mirror))) seeded = i.path;
    if (seeded.empty()) {
      std::string why = "is not a numeric input of the case";
      for (const auto& [path, reason] : in.fixed)
        if (path == k.path_text) why = "cannot be an unknown: " + reason;
      throw CaseError(at, why);
    }
    for (std::size_t j = 0; j < slot_path_.size(); ++j)
      if (slot_path_[j] == seeded) throw CaseError(at, "moves the same input as another unknown (an inertia entry moves its mirror)");
    path_slot_[u] = slot++;
    slot_path_.push_back(seeded);
    path_variants_[u] = {variant++};
    if (mirror_of(k.path)) path_variants_[u].push_back(variant++);
  }
  variant_count_ = variant;
  start_.resize(e.unknowns.size());
  for (std::size_t u = 0; u < e.unknowns.size(); ++u) {
    const Unknown& k = e.unknowns[u];
    double base = 0;
    if (k.kind == Unknown::Kind::speed) {
      for (const MovedVelocity& m : moved_)
        if (m.vehicle == k.vehicle) base = m.base_speed;
    } else if (k.kind == Unknown::Kind::path) {
      base = values[path_variants_[u].front()];
    }
    start_[u] = k.start.value_or(base);
  }
  for (std::size_t i = 0; i < e.evidence.size(); ++i) {
    const EvidenceItem& item = e.evidence[i];
    for (std::size_t c = 0; c < item.value.size(); ++c) {
      component_item_.push_back(i);
      const bool speed = item.kind == EvidenceItem::Kind::speed;
      component_output_.push_back(speed ? kSpeedOutput : item.outputs[c]);
      component_name_.push_back(speed ? item.output : monte_carlo_outputs()[item.outputs[c]].text);
      component_angle_.push_back(!speed && monte_carlo_outputs()[item.outputs[c]].angle);
      y_.push_back(item.value[c]);
      sd_.push_back(item.sd[c]);
    }
  }
}

Eval Model::evaluate(const Vector& theta, const ImposedBranch* imposed) {
  Eval out;
  const std::size_t p = unknowns(), m = components();
  std::vector<double> values(variant_count_);
  // Per moved velocity: d v / d speed and d v / d heading (per degree).
  std::vector<std::array<Eigen::Vector3d, 2>> d_velocity(moved_.size());
  for (std::size_t i = 0; i < moved_.size(); ++i) {
    const MovedVelocity& mv = moved_[i];
    const double s = mv.speed >= 0 ? theta[mv.speed] : mv.base_speed;
    const double h = mv.heading >= 0 ? theta[mv.heading] * kDegree : 0.0;
    const Eigen::Matrix3d R = Eigen::AngleAxisd(h, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    const Eigen::Vector3d along = R * mv.direction;
    const Eigen::Vector3d v = s * along;
    for (int c = 0; c < 3; ++c) values[mv.slot + static_cast<std::size_t>(c)] = v[c];
    d_velocity[i] = {along, Eigen::Vector3d(-v.y(), v.x(), 0) * kDegree};
  }
  for (std::size_t u = 0; u < p; ++u)
    for (const std::size_t i : path_variants_[u]) values[i] = theta[static_cast<Eigen::Index>(u)];
  CaseSpec spec;
  try {
    spec = variants_.with(values.data());
  } catch (const CaseError& e) {
    out.problem = e.line();
    return out;
  }
  if (replace_strategy_) spec.strategies = {strategy_};
  DualSeeds seeds;
  {
    CaseInputs in = case_inputs(spec);
    for (std::size_t j = 0; j < slot_path_.size(); ++j)
      for (const CaseInput& i : in.inputs)
        if (i.path == slot_path_[j])
          for (const Number* n : i.numbers) seeds.index.emplace_back(n, static_cast<int>(j));
  }
  std::optional<Analysis<Dual>> a;
  Scene<Dual> scene;
  try {
    std::vector<Strategy<Dual>> strategies;
    {
      const DualSeedScope scope(seeds);
      scene = to_scene<Dual>(spec);
      strategies = to_strategies<Dual>(spec);
    }
    const ImposeBranch impose(imposed);
    a = analyze(scene, strategies, engine_);
  } catch (const CaseError& e) {
    out.problem = e.line();
    return out;
  } catch (const SolveError& e) {
    out.problem = std::string("no solution: ") + e.what();
    return out;
  }
  const Solution<Dual>& sol = a->solutions.front();
  const UnitFactors<Dual> f = unit_factors<Dual>(spec.units);
  std::vector<Dual> v(monte_carlo_outputs().size());
  std::vector<char> written(v.size(), 0);
  numbers_of_solution(sol, f, v.data(), written.data());
  out.f.resize(static_cast<Eigen::Index>(m));
  out.r.resize(static_cast<Eigen::Index>(m));
  out.J.setZero(static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(p));
  for (std::size_t c = 0; c < m; ++c) {
    const auto row = static_cast<Eigen::Index>(c);
    Dual x;
    if (component_output_[c] == kSpeedOutput) {
      const auto& b = scene.body[static_cast<std::size_t>(evidence_.evidence[component_item_[c]].vehicle)];
      x = Dual(sqrt(b.v_W.squaredNorm()) / f.velocity);
    } else {
      const std::size_t o = component_output_[c];
      if (!written[o] || !std::isfinite(v[o].value())) {
        out.problem = fmt::format("$.evidence[{}].output: the result has no {} here", component_item_[c], case_format::quoted(component_name_[c]));
        return out;
      }
      x = v[o];
    }
    out.f[row] = x.value();
    const double residual = component_angle_[c] ? angle_difference(x.value(), y_[c]) : x.value() - y_[c];
    out.r[row] = residual / sd_[c];
    const auto d = [&](std::size_t slot) { return x.derivatives()[static_cast<Eigen::Index>(slot)]; };
    for (std::size_t u = 0; u < p; ++u)
      if (evidence_.unknowns[u].kind == Unknown::Kind::path) out.J(row, static_cast<Eigen::Index>(u)) = d(path_slot_[u]) / sd_[c];
    for (std::size_t i = 0; i < moved_.size(); ++i)
      for (int which = 0; which < 2; ++which) {
        const int u = which == 0 ? moved_[i].speed : moved_[i].heading;
        if (u < 0) continue;
        double sum = 0;
        for (int k = 0; k < 3; ++k) sum += d_velocity[i][static_cast<std::size_t>(which)][k] * d(moved_[i].slot + static_cast<std::size_t>(k));
        out.J(row, u) = sum / sd_[c];
      }
  }
  if (!out.r.allFinite() || !out.J.allFinite()) {
    out.problem = "the model is not finite here";
    return out;
  }
  out.regime = sol.impulse.regime;
  for (const auto& w : sol.warnings) out.warnings.push_back(w.text);
  for (std::size_t i = 0; i < 2; ++i) {
    const Vec3<Dual> cg = -(scene.body[i].R_WB * scene.body[i].p_CgIc_B);
    for (int k = 0; k < 3; ++k) {
      out.states.cg[i][static_cast<std::size_t>(k)] = (cg[k] / f.length).value();
      out.states.before[i][static_cast<std::size_t>(k)] = (scene.body[i].v_W[k] / f.velocity).value();
      out.states.after[i][static_cast<std::size_t>(k)] = (sol.after[i].v_W[k] / f.velocity).value();
    }
  }
  out.ok = true;
  return out;
}

}  // namespace impact3d::studies::reconstruct_model
