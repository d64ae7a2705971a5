// Reconstruction by weighted least squares (reconstruct.hpp): each regime's model
// (reconstruct_model.hpp) minimized by Eigen's Levenberg-Marquardt from several starts, then the
// statistics of the fit from its standardized Jacobian.
#include "impact3d/studies/reconstruct.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <Eigen/Dense>
#include <boost/math/special_functions/gamma.hpp>
#include <fmt/format.h>
#include <unsupported/Eigen/LevenbergMarquardt>

#include "reconstruct_model.hpp"

namespace impact3d::studies {
using namespace case_format;  // the studies are written in the case format's terms

using namespace reconstruct_model;

namespace {

// The residual of a point where the model has no solution (not approaching, a bad variant): far above
// any feasible point's, so that the minimizer refuses the step and shortens its trust region.
constexpr double kInfeasible = 1e100;

// Eigen's Levenberg-Marquardt on the standardized residuals, padded with zeros to at least as many
// rows as unknowns (MINPACK's requirement; a zero row changes no sum of squares).
struct LeastSquares : Eigen::DenseFunctor<double> {
  LeastSquares(Model& model, const ImposedBranch* imposed)
      : DenseFunctor(static_cast<int>(model.unknowns()), static_cast<int>(std::max(model.components(), model.unknowns()))),
        model_(model), imposed_(imposed) {}

  int operator()(const Vector& x, Vector& fvec) {
    const Eval& e = at(x);
    fvec.setZero(values());
    if (!e.ok) {
      fvec.setConstant(kInfeasible);
      ++infeasible_, problem_ = e.problem, refused_ = x;
    } else {
      fvec.head(e.r.size()) = e.r;
    }
    return 0;
  }
  int df(const Vector& x, Matrix& fjac) {
    const Eval& e = at(x);
    // The Jacobian is asked at accepted points, and every start is one the model solves; a failure
    // here would stop the minimizer (UserAsked: not converged).
    if (!e.ok) return -1;
    fjac.setZero(values(), inputs());
    fjac.topRows(e.J.rows()) = e.J;
    return 0;
  }
  // Trial points the case refused, and the last one and its problem.
  int infeasible() const { return infeasible_; }
  const std::string& problem() const { return problem_; }
  const Vector& refused() const { return refused_; }

 private:
  Model& model_;
  const ImposedBranch* imposed_;
  Vector last_x_;
  Eval last_;
  int infeasible_ = 0;
  std::string problem_;
  Vector refused_;
  const Eval& at(const Vector& x) {
    if (last_x_.size() != x.size() || last_x_ != x) last_ = model_.evaluate(x, imposed_), last_x_ = x;
    return last_;
  }
};

const char* status_name(Eigen::LevenbergMarquardtSpace::Status s) {
  using namespace Eigen::LevenbergMarquardtSpace;
  switch (s) {
    case RelativeReductionTooSmall: return "the relative reduction of chi2 is at most ftol";
    case RelativeErrorTooSmall: return "the relative change of the unknowns is at most xtol";
    case RelativeErrorAndReductionTooSmall: return "the relative reduction of chi2 and change of the unknowns are at most ftol and xtol";
    case CosinusTooSmall: return "the residuals are orthogonal to the Jacobian's columns";
    case TooManyFunctionEvaluation: return "too many evaluations";
    case FtolTooSmall: return "no further reduction of chi2 is possible";
    case XtolTooSmall: return "no further improvement of the unknowns is possible";
    case GtolTooSmall: return "the residuals are orthogonal to the Jacobian's columns (gtol)";
    case UserAsked: return "the model had no solution at an accepted point";
    default: return "improper input";
  }
}

bool converged(Eigen::LevenbergMarquardtSpace::Status s) {
  using namespace Eigen::LevenbergMarquardtSpace;
  return s == RelativeReductionTooSmall || s == RelativeErrorTooSmall || s == RelativeErrorAndReductionTooSmall ||
         s == CosinusTooSmall || s == FtolTooSmall || s == XtolTooSmall || s == GtolTooSmall;
}

// The Jacobian's columns scaled to unit length, and its singular value decomposition: the rank, the
// covariance of the determined unknowns, and the undetermined combinations.
void statistics(const Eval& e, Fit& fit) {
  const Eigen::Index m = e.J.rows(), p = e.J.cols();
  Vector scale(p);
  Matrix Js = e.J;
  for (Eigen::Index j = 0; j < p; ++j) {
    const double n = e.J.col(j).norm();
    scale[j] = n > 0 ? n : 1.0;
    Js.col(j) /= scale[j];
  }
  Eigen::JacobiSVD<Matrix> svd(Js, Eigen::ComputeFullV);
  const Vector sigma_short = svd.singularValues();
  Vector sigma = Vector::Zero(p);
  sigma.head(sigma_short.size()) = sigma_short;
  const double top = sigma.size() ? sigma[0] : 0.0;
  Eigen::Index rank = 0;
  while (rank < p && top > 0 && sigma[rank] > kUndetermined * top) ++rank;
  const Matrix& V = svd.matrixV();
  std::vector<char> determined(static_cast<std::size_t>(p), 1);
  for (Eigen::Index k = rank; k < p; ++k) {
    Undetermined u;
    Vector c = V.col(k).cwiseQuotient(scale);
    c /= c.norm();
    Eigen::Index big = 0;
    c.cwiseAbs().maxCoeff(&big);
    if (c[big] < 0) c = -c;
    for (Eigen::Index j = 0; j < p; ++j) u.combination.push_back(std::fabs(c[j]) < 1e-12 ? 0.0 : c[j]);
    u.relative_singular_value = top > 0 ? sigma[k] / top : 0.0;
    fit.undetermined.push_back(std::move(u));
  }
  // An unknown is determined when the undetermined directions have no part along it.
  for (Eigen::Index j = 0; j < p; ++j) {
    const double in_null = rank < p ? V.row(j).tail(p - rank).norm() : 0.0;
    determined[static_cast<std::size_t>(j)] = in_null < 1e-6;
  }
  Matrix C = Matrix::Zero(p, p);
  for (Eigen::Index k = 0; k < rank; ++k) C += V.col(k) * V.col(k).transpose() / (sigma[k] * sigma[k]);
  for (Eigen::Index i = 0; i < p; ++i)
    for (Eigen::Index j = 0; j < p; ++j) C(i, j) /= scale[i] * scale[j];
  fit.identifiable = rank == p;
  fit.value = fit.fitted;
  fit.sd.assign(static_cast<std::size_t>(p), kNaN);
  fit.correlation.assign(static_cast<std::size_t>(p), std::vector<double>(static_cast<std::size_t>(p), kNaN));
  for (Eigen::Index i = 0; i < p; ++i) {
    const auto ui = static_cast<std::size_t>(i);
    if (!determined[ui]) {
      fit.value[ui] = kNaN;
      continue;
    }
    fit.sd[ui] = std::sqrt(C(i, i));
    for (Eigen::Index j = 0; j < p; ++j)
      if (determined[static_cast<std::size_t>(j)]) fit.correlation[ui][static_cast<std::size_t>(j)] = C(i, j) / std::sqrt(C(i, i) * C(j, j));
  }
  fit.chi2 = e.r.squaredNorm();
  fit.dof = static_cast<std::size_t>(m - std::min(m, rank));
  fit.p_value = kNaN;
  if (fit.dof > 0) try {
      fit.p_value = boost::math::gamma_q(static_cast<double>(fit.dof) / 2, fit.chi2 / 2);
    } catch (const std::exception&) {  // Boost's policy errors: left NaN, the test untested
    }
}

std::string combination_text(const std::vector<Unknown>& unknowns, const Undetermined& u) {
  std::string s;
  for (std::size_t j = 0; j < unknowns.size(); ++j) {
    if (u.combination[j] == 0) continue;
    s += fmt::format("{}{:.4g} {}", s.empty() ? (u.combination[j] < 0 ? "-" : "") : (u.combination[j] < 0 ? " - " : " + "),
                     std::fabs(u.combination[j]), unknowns[j].label());
  }
  return s;
}

// A fit is stuck at the edge of the inputs the case accepts, not at a minimum, when the last trial
// point the case refused lies within 1e-6 (relative) of where it stopped, in every unknown, and the
// model linearized there still promises chi2 a fall above this: a Gauss-Newton step delta with
// |J delta|^2 above it moves some estimate by more than 1e-3 of its sd (|delta_j| <= sd_j |J delta|).
// A minimum has |J delta|^2 at rounding level; a stationary point where J vanishes is far from the
// refused trials, which were the long steps its flat chi2 invited.
constexpr double kEdgeDecrement = 1e-6;

bool stuck_at_edge(const Eval& e, const Vector& x, const Vector& refused) {
  if (refused.size() != x.size()) return false;
  for (Eigen::Index j = 0; j < x.size(); ++j)
    if (!(std::fabs(refused[j] - x[j]) <= 1e-6 * std::max(std::fabs(x[j]), 1.0))) return false;
  Eigen::CompleteOrthogonalDecomposition<Matrix> cod(e.J);
  cod.setThreshold(kUndetermined);
  return (e.J * cod.solve(e.r)).squaredNorm() > kEdgeDecrement;
}

// One fit from `start`, with `imposed` (or nothing) imposed.
Fit fit_from(Model& model, const Vector& start, const ImposedBranch* imposed, const std::vector<Unknown>& unknowns) {
  LeastSquares functor(model, imposed);
  Eigen::LevenbergMarquardt<LeastSquares> lm(functor);
  // Tolerances at the rounding of the residuals: a fit stops where double arithmetic can no longer
  // tell a better point (MINPACK's "too small" statuses count as converged).
  lm.setFtol(1e-15);
  lm.setXtol(1e-15);
  lm.setMaxfev(static_cast<Eigen::Index>(200 * (unknowns.size() + 1)));
  Vector x = start;
  const auto status = lm.minimize(x);
  Fit fit;
  fit.solver_status = status_name(status);
  fit.converged = converged(status);
  fit.evaluations = static_cast<int>(lm.nfev());
  fit.fitted.assign(x.data(), x.data() + x.size());
  if (imposed) {
    const Branches& b = model.branches();
    fit.imposed = regime_name(imposed->value ? b.when_true : b.when_false);
  }
  const Eval e = model.evaluate(x, imposed);
  if (!e.ok) {  // the start itself had no solution
    fit.converged = fit.admissible = false;
    fit.warnings.push_back("the model has no solution at the fit: " + e.problem);
    fit.value.assign(unknowns.size(), kNaN);
    fit.sd.assign(unknowns.size(), kNaN);
    fit.correlation.assign(unknowns.size(), std::vector<double>(unknowns.size(), kNaN));
    fit.chi2 = kNaN, fit.p_value = kNaN;
    return fit;
  }
  if (fit.converged && functor.infeasible() > 0 && stuck_at_edge(e, x, functor.refused())) {
    fit.converged = false;
    fit.solver_status = fmt::format("stopped at the edge of the inputs the case accepts, not at a minimum: {}", functor.problem());
  }
  fit.regime = regime_name(e.regime);
  statistics(e, fit);
  for (std::size_t c = 0; c < model.components(); ++c) {
    EvidenceResidual r;
    r.item = model.item(c);
    r.output = model.output(c);
    r.value = model.value(c), r.sd = model.sd(c);
    r.fitted = e.f[static_cast<Eigen::Index>(c)];
    r.standardized = e.r[static_cast<Eigen::Index>(c)];
    r.residual = r.standardized * r.sd;
    fit.residuals.push_back(r);
  }
  if (imposed) {
    const Eval natural = model.evaluate(x, nullptr);
    fit.decided = natural.ok ? regime_name(natural.regime) : "";
    fit.admissible = natural.ok && natural.regime == e.regime;
  } else {
    fit.decided = fit.regime;
  }
  if (!fit.converged) fit.warnings.push_back(fmt::format("the minimizer stopped before converging: {}", fit.solver_status));
  for (const Undetermined& u : fit.undetermined)
    fit.warnings.push_back(fmt::format("the evidence does not determine {} (relative singular value {:.3g})",
                                       combination_text(unknowns, u), u.relative_singular_value));
  for (std::size_t j = 0; j < unknowns.size(); ++j)
    if (unknowns[j].kind == Unknown::Kind::speed && fit.value[j] < 0)
      fit.warnings.push_back(fmt::format("{} is negative: the vehicle moved against the direction the case gives it", unknowns[j].label()));
  for (const auto& w : e.warnings) fit.warnings.push_back("the result at the fit: " + w);
  return fit;
}

// The Gauss-Newton step of the model linearized at x (its minimum-norm least-squares step where the
// Jacobian is rank-deficient): exact for a model linear in the unknowns, as a Full Impact's is in the
// speeds when the evidence is post-impact velocities (its impulse is linear in the relative velocity);
// a sliding regime's plane turns with the velocities, so there it is a first step.
Vector linear_start(Model& model, const Vector& x, const ImposedBranch* imposed) {
  const Eval e = model.evaluate(x, imposed);
  if (!e.ok) return x;
  Eigen::CompleteOrthogonalDecomposition<Matrix> cod(e.J);
  cod.setThreshold(kUndetermined);
  const Vector next = x - cod.solve(e.r);
  const Eval e2 = model.evaluate(next, imposed);
  return e2.ok && e2.r.squaredNorm() < e.r.squaredNorm() ? next : x;
}

}  // namespace

Reconstruction reconstruct(const std::string& case_text, const EvidenceSpec& evidence, const ReconstructOptions& o) {
  Model model(case_text, evidence, o);
  Reconstruction out;
  out.units = model.units();
  out.engine = o.engine;
  out.strategy = model.strategy();
  out.unknowns = evidence.unknowns;
  out.start = model.start();
  const Vector x0 = Eigen::Map<const Vector>(out.start.data(), static_cast<Eigen::Index>(out.start.size()));
  {
    const Eval e = model.evaluate(x0, nullptr);
    if (!e.ok) {
      // An evidence item the result never has is the evidence file's fault; anything else the start's.
      if (e.problem.rfind("$.evidence", 0) == 0) {
        const std::size_t colon = e.problem.find(": ");
        throw CaseError(e.problem.substr(0, colon), e.problem.substr(colon + 2));
      }
      std::string starts;
      for (std::size_t j = 0; j < out.start.size(); ++j)
        starts += fmt::format("{}{} = {}", j ? ", " : "", evidence.unknowns[j].label(), out.start[j]);
      throw CaseError("$.unknowns", fmt::format("the case has no solution at the unknowns' starting values ({}): {}", starts, e.problem));
    }
  }
  // Each regime's model from several starts, its best fit kept: the linear step from the start, the
  // start itself (the linear step of a model curved between the start and the fit may overshoot into
  // another basin), and then each other regime's fit.
  const Branches& b = model.branches();
  std::vector<std::optional<ImposedBranch>> regimes;
  if (b.decision) regimes = {ImposedBranch{b.decision, true}, ImposedBranch{b.decision, false}};
  else regimes = {std::nullopt};
  const auto imposed = [&](std::size_t k) { return regimes[k] ? &*regimes[k] : nullptr; };
  std::vector<Fit> fits;
  // A converged fit in its own regime over any other, then the least chi2.
  const auto rank = [](const Fit& f) { return !std::isfinite(f.chi2) ? 3 : f.converged && f.admissible ? 0 : f.converged ? 1 : 2; };
  const auto better = [&](const Fit& a, const Fit& c) { return rank(a) < rank(c) || (rank(a) == rank(c) && a.chi2 < c.chi2); };
  for (std::size_t k = 0; k < regimes.size(); ++k) {
    Fit f = fit_from(model, linear_start(model, x0, imposed(k)), imposed(k), evidence.unknowns);
    Fit g = fit_from(model, x0, imposed(k), evidence.unknowns);
    fits.push_back(better(g, f) ? std::move(g) : std::move(f));
  }
  for (std::size_t k = 0; k < regimes.size(); ++k)
    for (std::size_t other = 0; other < regimes.size(); ++other) {
      if (other == k || !std::isfinite(fits[other].chi2)) continue;
      const Vector from = Eigen::Map<const Vector>(fits[other].fitted.data(), static_cast<Eigen::Index>(fits[other].fitted.size()));
      Fit g = fit_from(model, from, imposed(k), evidence.unknowns);
      if (better(g, fits[k])) fits[k] = std::move(g);
    }
  std::vector<Fit> admissible;
  for (Fit& f : fits) (f.admissible && f.converged && std::isfinite(f.chi2) ? admissible : out.inadmissible).push_back(std::move(f));
  std::stable_sort(admissible.begin(), admissible.end(), [](const Fit& a, const Fit& c) { return a.chi2 < c.chi2; });
  if (!admissible.empty()) {
    out.best = std::move(admissible.front());
    out.alternatives.assign(std::make_move_iterator(admissible.begin() + 1), std::make_move_iterator(admissible.end()));
    return out;
  }
  // No regime's fit lies in its own regime: the minimum of the whole model is on the boundary between
  // them, where it has a kink. That fit is reported, flagged.
  const Fit* closest = nullptr;
  for (const Fit& f : out.inadmissible)
    if (std::isfinite(f.chi2) && (!closest || f.chi2 < closest->chi2)) closest = &f;
  const Vector from = closest ? Eigen::Map<const Vector>(closest->fitted.data(), static_cast<Eigen::Index>(closest->fitted.size())) : x0;
  out.best = fit_from(model, from, nullptr, evidence.unknowns);
  out.best.admissible = false;
  // Why: every regime's converged fit decides another regime (a kink between them), or a fit did not
  // converge.
  bool kink = b.decision != nullptr;
  for (const Fit& f : out.inadmissible) kink = kink && f.converged && !f.decided.empty() && f.decided != f.imposed;
  out.best.warnings.insert(out.best.warnings.begin(),
                           kink ? "no regime's fit lies in its own regime: this fit of the whole model is on or near the boundary between "
                                  "regimes, where the model has a kink; its standard errors are one side's, and its chi2 is not tested"
                                : "no fit both converged and lies in its own regime (see the fits not admitted): this fit of the whole "
                                  "model is reported as the minimizer left it, and its chi2 is not tested");
  return out;
}

FitStates fit_states(const std::string& case_text, const EvidenceSpec& evidence, const ReconstructOptions& o, const Fit& fit) {
  Model model(case_text, evidence, o);
  const Eval e = model.evaluate(Eigen::Map<const Vector>(fit.fitted.data(), static_cast<Eigen::Index>(fit.fitted.size())), nullptr);
  if (!e.ok) throw CaseError("$.unknowns", "the case has no solution at the fit (" + e.problem + ")");
  return e.states;
}

std::vector<double> chi2_grid(const std::string& case_text, const EvidenceSpec& evidence, const ReconstructOptions& o,
                              const Fit& fit, std::size_t a, std::size_t b, const std::vector<double>& xs,
                              const std::vector<double>& ys) {
  Model model(case_text, evidence, o);
  Vector x = Eigen::Map<const Vector>(fit.fitted.data(), static_cast<Eigen::Index>(fit.fitted.size()));
  std::vector<double> out;
  out.reserve(xs.size() * ys.size());
  for (const double y : ys)
    for (const double v : xs) {
      x[static_cast<Eigen::Index>(a)] = v, x[static_cast<Eigen::Index>(b)] = y;
      const Eval e = model.evaluate(x, nullptr);
      out.push_back(e.ok ? e.r.squaredNorm() : kNaN);
    }
  return out;
}

}  // namespace impact3d::studies
