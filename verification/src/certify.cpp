// verify --certify: see certify.hpp.
#include "certify.hpp"

#include "algebraic_strategies.hpp"

#include <map>

#include <boost/multiprecision/cpp_int.hpp>

#include <fmt/format.h>

#include "impact3d/case_format/scalar_text.hpp"
#include "impact3d/case_format/to_scene.hpp"
#include "impact3d/mechanics/certified.hpp"
#include "impact3d/scalar/scalars.hpp"

namespace impact3d::verification {
namespace {

// The enclosures: far narrower than the 100-digit bound (10^-99 kappa), so that a bound that holds on
// every point of a ball holds with room.
constexpr long kCertifyBits = 512;

// x (a finite value of the type under test) as the exact ball it is: its significand, an integer of the
// type's digits, times a power of two (kCertifyBits holds every type's significand).
template <typename T>
Ball exactly(const T& x) {
  if constexpr (std::is_same_v<T, double>) {
    return Ball(x);
  } else {
    using std::frexp;
    using std::ldexp;
    int e = 0;
    const T significand = ldexp(frexp(x, &e), std::numeric_limits<T>::digits);
    Ball b(static_cast<boost::multiprecision::cpp_int>(significand).str());
    arb_mul_2exp_si(b.get(), b.get(), e - std::numeric_limits<T>::digits);
    return b;
  }
}

// The largest |x - e| over the points e of the ball, over `bound`: at most 1 proves the bound.
template <typename T>
double over_bound(const T& x, const Ball& enclosure, const Ball& bound) {
  const Ball far = abs(Ball(exactly(x) - enclosure)).upper();
  if (bound == Ball(0)) return far == Ball(0) ? 0 : std::numeric_limits<double>::infinity();
  return Ball(far / bound).upper_double();
}

struct Tally {
  double worst = 0;
  std::string where;
  long checked = 0;
  void add(double r, const std::string& w) {
    ++checked;
    if (!(r <= worst)) {  // a NaN is the worst
      worst = r;
      where = w;
    }
  }
};

template <typename T>
void check_precision(const std::vector<std::pair<std::string, case_format::CaseSpec>>& cases, const std::vector<std::optional<CertifiedAnalysis>>& refs,
                     const std::vector<std::vector<std::size_t>>& indices, Engine engine, double corrupt, std::map<std::string, Tally>& q,
                     int& skipped) {
  for (std::size_t i = 0; i < cases.size(); ++i) {
    if (!refs[i]) continue;
    const CertifiedAnalysis& ref = *refs[i];
    Analysis<T> a;
    try {
      a = analyze(case_format::to_scene<T>(cases[i].second), case_format::to_strategies<T>(cases[i].second), engine);
    } catch (const std::exception&) {
      ++skipped;
      continue;
    }
    for (std::size_t k = 0; k < ref.analysis.solutions.size(); ++k) {
      auto s = a.solutions[indices[i][k]];
      const auto& r = ref.analysis.solutions[k];
      bool flagged = false;
      for (const auto& w : s.warnings) flagged = flagged || w.code == WarningCode::rounding || w.code == WarningCode::not_finite;
      bool undecided = false;
      for (const auto& d : ref.decisions[k])
        undecided = undecided || (d.status == DecisionStatus::undecided && chooses_impulse(d.name));
      // A result its precision flags promises nothing; an undecided enclosure holds one branch only.
      if (flagged || undecided || s.impulse.regime != r.impulse.regime) {
        ++skipped;
        continue;
      }
      if constexpr (std::is_same_v<T, double>) s.impulse.P_C.x() *= 1 + corrupt;
      const BallBits bits(kCertifyBits);
      const std::string where = fmt::format("{} result {}", cases[i].first, indices[i][k]);
      const Ball bound = exactly(s.rounding_bound);
      const Ball P = r.impulse.P_C.norm(), V = r.V_ri.norm();
      for (int j = 0; j < 3; ++j) {
        q["impulse P"].add(over_bound(s.impulse.P_C[j], r.impulse.P_C[j], Ball(bound * P)), where);
        q["V_rel after"].add(over_bound(s.V_rf[j], r.V_rf[j], Ball(bound * V)), where);
      }
    }
  }
}

}  // namespace

bool certify(const std::vector<std::pair<std::string, case_format::CaseSpec>>& cases, std::string& report, double corrupt_double) {
  std::vector<std::optional<CertifiedAnalysis>> refs;
  std::vector<std::vector<std::size_t>> indices;
  int enclosed = 0;
  std::size_t integrated = 0;
  for (const auto& [name, spec] : cases) {
    const BallBits bits(kCertifyBits);
    try {
      auto algebraic = algebraic_strategies<Ball>(spec);
      indices.push_back(std::move(algebraic.index));
      refs.push_back(certified_analyze(case_format::to_scene<Ball>(spec), algebraic.strategies));
      ++enclosed;
      integrated += spec.strategies.size() - algebraic.strategies.size();
    } catch (const std::exception& e) {
      indices.resize(refs.size() + 1);
      refs.push_back(std::nullopt);
      report += fmt::format("certify: {}: no enclosure ({})\n", name, e.what());
    }
  }
  report += fmt::format(
      "\ncertified: {} of {} cases enclosed in ball arithmetic at {} bits; each precision's impulse and V_rel after\n"
      "against every point of the enclosure. over bound: the largest |x - exact| over the result's own stated\n"
      "rounding bound (rounding_bound x |P|, x |V_ri|); at most 1 proves the bound on that case.\n",
      enclosed, cases.size(), kCertifyBits);
  if (integrated)
    report += fmt::format("{} integrated results (stronge) have no enclosure: verify's table above holds them to the 100-digit solve\n",
                          integrated);
  report += fmt::format("{:<12} {:<10} {:<15} {:>10} {:>12}  {}\n", "precision", "engine", "quantity", "checked", "over bound", "worst");
  bool ok = enclosed > 0;
  for_each_scalar([&]<typename T>(std::type_identity<T>) {
    for (Engine engine : {Engine::generated, Engine::direct}) {
      std::map<std::string, Tally> q;
      int skipped = 0;
      check_precision<T>(cases, refs, indices, engine, corrupt_double, q, skipped);
      const std::string name(precision_name<T>);
      if (q.empty()) {
        ok = false;
        report += fmt::format("{:<12} {:<10} FAILED: nothing was checked\n", name, engine_name(engine));
      }
      for (const auto& [quantity, t] : q) {
        const bool pass = t.worst <= 1;
        ok = ok && pass;
        report += fmt::format("{:<12} {:<10} {:<15} {:>10} {:>12.3g}  {}{}\n", name, engine_name(engine), quantity, t.checked,
                              t.worst, t.where, pass ? "" : "  BOUND NOT PROVEN");
      }
      if (skipped)
        report += fmt::format("{:<12} {:<10} {} results not checked (flagged by their precision, or their impulse undecided)\n", name,
                              engine_name(engine), skipped);
    }
  });
  return ok;
}

}  // namespace impact3d::verification
