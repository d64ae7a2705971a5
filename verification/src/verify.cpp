#include "impact3d/verification/verify.hpp"

#include "algebraic_strategies.hpp"
#include "certify.hpp"

#include <cmath>
#include <filesystem>
#include <map>
#include <random>
#include <sstream>

#include <fmt/format.h>

#include "impact3d/case_format/read_case.hpp"
#include "impact3d/mechanics/exact_analysis.hpp"
#include "impact3d/mechanics/strategies/list.hpp"
#include "impact3d/mechanics/rounding.hpp"
#include "impact3d/scalar/scalars.hpp"

namespace impact3d::verification {
namespace {

namespace fs = std::filesystem;
using F = mp::float100;

struct Case {
  std::string name;
  case_format::CaseSpec spec;
  std::string file;  // empty for the random cases
};

// A case's error, with its file named: the reference solve of a case can fail (not approaching, a
// strategy with no impulse) as `solve` would, and says where.
[[noreturn]] void rethrow_naming(const Case& c, const case_format::CaseError& e) {
  throw case_format::CaseError((c.file.empty() ? c.name : c.file) + ": " + e.path, e.what());
}

case_format::Number num(double v) {
  return case_format::Number{fmt::format("{:.6g}", v), std::stod(fmt::format("{:.6g}", v))};
}

// A random collision written as decimal text (six significant digits), so that every precision
// converts the very same decimals; products of inertia, pitched and rolled vehicles, tilted frames.
case_format::CaseSpec random_case(std::mt19937_64& g) {
  std::uniform_real_distribution<double> u(0, 1);
  auto in = [&](double a, double b) { return a + (b - a) * u(g); };
  for (;;) {
    case_format::CaseSpec c;
    c.name = "random";
    for (auto& v : c.vehicles) {
      v.mass = num(in(700, 3500));
      const double ixx = in(300, 1500), iyy = in(1200, 6000), izz = iyy + in(0.5, 1.0) * ixx, ixz = in(-0.1, 0.1) * ixx;
      const double m[3][3] = {{ixx, 0, ixz}, {0, iyy, 0}, {ixz, 0, izz}};
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) v.inertia[i][j] = num(m[std::min(i, j)][std::max(i, j)]);
      v.yaw = num(in(-180, 180));
      v.pitch = num(in(-8, 8));
      v.roll = num(in(-8, 8));
      v.velocity = {num(in(-25, 25)), num(in(-25, 25)), num(in(-1, 1))};
      v.angular_velocity = {num(in(-0.3, 0.3)), num(in(-0.3, 0.3)), num(in(-1, 1))};
      v.impulse_center = {num(in(-2.6, 2.6)), num(in(-1, 1)), num(in(-0.5, 0.4))};
    }
    c.contact.normal_yaw = num(in(-180, 180));
    c.contact.normal_pitch = num(in(-20, 20));
    c.contact.tangent_roll = num(in(-30, 30));
    c.restitution = num(in(0, 1));
    // Each strategy over the values its entry names (strategies/list.hpp), in the list's order, as a case
    // file would give them.
    c.strategies.clear();
    for_each_strategy([&]<std::size_t I, typename Spec>(std::integral_constant<std::size_t, I>, std::type_identity<Spec>) {
      for (const auto& draws : Spec::verified) {
        case_format::StrategySpec st{I, {}, {}, ""};
        for (std::size_t k = 0; k < Spec::parameters.size(); ++k) {
          const Parameter& p = Spec::parameters[k];
          const ParameterDraw& d = draws[k];
          const std::string key(p.key);
          if (p.type == ParameterType::choice && !d.choice.empty()) st.choices[key] = std::string(d.choice);
          else if (p.type == ParameterType::choice)
            st.choices[key] = std::string(p.choices[std::min(p.choices.size() - 1, static_cast<std::size_t>(in(0, static_cast<double>(p.choices.size()))))]);
          else st.numbers[key] = d.critical ? std::optional<case_format::Number>() : num(in(d.lo, d.hi));
        }
        c.strategies.push_back(std::move(st));
      }
    });
    try {
      case_format::to_scene<double>(c);  // approaching?
      return c;
    } catch (const case_format::CaseError&) {
    }
  }
}

std::vector<Case> collect(const VerifyOptions& o) {
  std::vector<Case> cases;
  for (const auto& input : o.inputs) {
    std::vector<fs::path> files;
    std::error_code ec;
    if (fs::is_directory(input, ec)) {
      for (fs::directory_iterator it(input, ec), end; !ec && it != end; it.increment(ec))
        if (it->path().extension() == ".json") files.push_back(it->path());
      if (ec) throw case_format::CaseError(input, "cannot read the directory (" + ec.message() + ")");
      std::sort(files.begin(), files.end());
    } else {
      files.push_back(input);
    }
    for (const auto& f : files) {
      try {
        cases.push_back({f.stem().string(), case_format::read_case(case_format::read_text_file(f.string())), f.string()});
      } catch (const case_format::CaseError& e) {
        throw e.path == f.string() ? e : case_format::CaseError(f.string() + ": " + e.path, e.what());  // name the file too
      }
    }
  }
  std::mt19937_64 g(o.seed);
  for (int i = 0; i < o.random; ++i) cases.push_back({fmt::format("random-{}", i), random_case(g), ""});
  return cases;
}

template <typename T>
F wide(const T& x) {
  if constexpr (std::is_arithmetic_v<T>) return F(x);
  else return F(case_format::scalar_to_text(x, std::numeric_limits<T>::max_digits10 + 3));
}

template <typename T>
F wide_norm(const Vec3<T>& v, const Vec3<F>& r) {
  F s = 0;
  for (int i = 0; i < 3; ++i) {
    const F d = wide(v(i)) - r(i);
    s += d * d;
  }
  using std::sqrt;
  return sqrt(s);
}

struct Stat {
  double max_eps = 0, sum_sq = 0, max_units = 0, min_digits = 1000;
  long n = 0;
  std::string worst;
  void add(double eps_units, double bound_units, double digits, const std::string& where) {
    sum_sq += eps_units * eps_units;
    ++n;
    if (eps_units > max_eps) max_eps = eps_units;
    if (bound_units > max_units) {
      max_units = bound_units;
      worst = where;
    }
    min_digits = std::min(min_digits, digits);
  }
};

struct Quantities {
  std::map<std::string, Stat> stat;
  int decisions_differ = 0;
  int flagged = 0;  // results the precision itself flags as beyond its rounding (rounding.hpp)
  int compared = 0;
  std::vector<std::string> decision_notes;
};

// The physical warnings, without those that say the precision cannot deliver or decide the result.
template <typename T>
std::vector<WarningCode> physical_warnings(const Solution<T>& s) {
  std::vector<WarningCode> out;
  for (const auto& w : s.warnings)
    if (w.code != WarningCode::rounding && w.code != WarningCode::undecided) out.push_back(w.code);
  return out;
}

template <typename T>
bool flagged(const Solution<T>& s) {
  for (const auto& w : s.warnings)
    if (w.code == WarningCode::rounding || w.code == WarningCode::not_finite) return true;
  return false;
}

template <typename T>
void measure(const Case& c, const Analysis<F>& ref, double cond, Engine engine, Quantities& q) {
  const double eps = static_cast<double>(std::numeric_limits<T>::epsilon());
  Analysis<T> a;
  try {
    a = analyze(case_format::to_scene<T>(c.spec), case_format::to_strategies<T>(c.spec), engine);
  } catch (const std::exception& e) {
    ++q.decisions_differ;
    q.decision_notes.push_back(c.name + ": " + e.what());
    return;
  }
  auto rec = [&](const std::string& quantity, const F& err, const F& scale, double bound_scale, const std::string& where) {
    const double rel = scale > 0 ? static_cast<double>(err / scale) : static_cast<double>(err);
    const double digits = rel > 0 ? -std::log10(rel) : 100;
    q.stat[quantity].add(rel / eps, rel / (eps * bound_scale), digits, c.name + where);
  };
  F kerr = 0, knorm = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const F d = wide(a.K(i, j)) - ref.K(i, j);
      kerr += d * d;
      knorm += ref.K(i, j) * ref.K(i, j);
    }
  using std::sqrt;
  rec("K", sqrt(kerr), sqrt(knorm), cond, "");
  for (std::size_t k = 0; k < ref.solutions.size(); ++k) {
    const auto& s = a.solutions[k];
    const auto& r = ref.solutions[k];
    const std::string where = fmt::format(" result {}", k);
    // A result its precision flags is not held to the bound, and an undecided regime may differ: the
    // flag is the promise, and check_precision_flags tests that unflagged results keep it.
    if (flagged(s)) {
      ++q.flagged;
      continue;
    }
    const bool undecided = s.warnings.size() != physical_warnings(s).size();
    if ((s.impulse.regime != r.impulse.regime && !undecided) || physical_warnings(s) != physical_warnings(r)) {
      ++q.decisions_differ;
      q.decision_notes.push_back(c.name + where + ": regime or warnings differ from the 100-digit solve");
      continue;
    }
    ++q.compared;
    if (s.impulse.integration_error) {
      // An integrated impulse (stronge): P and V_rf within the two integrations' stated bounds and the
      // rounding of the others, in the same units (kResultRoundings at the bound). The stated bound is
      // relative to |P|; the velocities' is that times |P| / (m' |V_ri|) (stronge/history.hpp).
      const double stated = static_cast<double>(*s.impulse.integration_error) + static_cast<double>(*r.impulse.integration_error);
      const double units = (stated / rounding::kResultRoundings + eps * cond) / eps;
      const double to_velocity = static_cast<double>(r.impulse.P_C.norm() / (ref.m_prime * r.V_ri.norm()));
      const double units_V = (stated * to_velocity / rounding::kResultRoundings + eps * cond) / eps;
      rec("integrated P", wide_norm(s.impulse.P_C, r.impulse.P_C), r.impulse.P_C.norm(), units, where);
      rec("integrated V", wide_norm(s.V_rf, r.V_rf), r.V_ri.norm(), units_V, where);
      continue;
    }
    rec("impulse P", wide_norm(s.impulse.P_C, r.impulse.P_C), r.impulse.P_C.norm(), cond, where);
    // Post-impact relative velocity: a difference of velocities of the case's size.
    rec("V_rel after", wide_norm(s.V_rf, r.V_rf), r.V_ri.norm(), cond, where);
    rec("energy loss", abs(wide(s.energy_loss) - r.energy_loss), r.energy_before, cond, where);
    // Ratios are quotients; first order, their error grows as (1 + |r|)(1 + |mu|)^2 with r = V_cp / V_n.
    const double quotient = static_cast<double>(rounding::quotient_factor(r.V_ri));
    const std::optional<T>* mine[] = {&s.impulse.mu, &s.impulse.mu_t, &s.impulse.mu_z, &s.impulse.gir, &s.impulse.cir,
                                      &s.impulse.mu_t_critical, &s.impulse.mu_z_critical};
    const std::optional<F>* theirs[] = {&r.impulse.mu, &r.impulse.mu_t, &r.impulse.mu_z, &r.impulse.gir, &r.impulse.cir,
                                        &r.impulse.mu_t_critical, &r.impulse.mu_z_critical};
    for (int i = 0; i < 7; ++i) {
      if (!theirs[i]->has_value() || !mine[i]->has_value()) continue;
      const F mu = **theirs[i];
      const double m = std::fabs(static_cast<double>(mu));
      if (!std::isfinite(m)) continue;
      rec("impulse ratios", abs(wide(**mine[i]) - mu), F(1) + abs(mu), cond * quotient * (1 + m), where);
    }
  }
}

template <typename T>
void run_precision(const std::string& name, const std::vector<Case>& cases, const std::vector<Analysis<F>>& refs,
                   const std::vector<double>& conds, std::string& report, bool& ok) {
  for (Engine engine : {Engine::generated, Engine::direct}) {
    Quantities q;
    for (std::size_t i = 0; i < cases.size(); ++i) measure<T>(cases[i], refs[i], conds[i], engine, q);
    for (const auto& [quantity, s] : q.stat) {
      // Bound, in units of eps x the case's amplification (and for ratios the quotient's): rounding.hpp.
      const bool pass = s.max_units <= rounding::kResultRoundings;
      ok = ok && pass;
      report += fmt::format("{:<12} {:<10} {:<15} {:>12.3f} {:>10.3f} {:>10.3f} {:>8.1f}  {}{}\n", name, engine_name(engine),
                            quantity, s.max_eps, std::sqrt(s.sum_sq / s.n), s.max_units, s.min_digits, s.worst,
                            pass ? "" : "  BOUND EXCEEDED");
    }
    if (q.compared == 0) {
      ok = false;
      report += fmt::format("{:<12} {:<10} FAILED: no result was compared (every one was flagged or differed)\n", name,
                            engine_name(engine));
    }
    if (q.flagged)
      report += fmt::format("{:<12} {:<10} {} results flagged by the precision itself as beyond its rounding (not held to the bound)\n",
                            name, engine_name(engine), q.flagged);
    if (q.decisions_differ) {
      ok = false;
      for (const auto& note : q.decision_notes) report += fmt::format("{:<12} {:<10} decision differs: {}\n", name, engine_name(engine), note);
    }
  }
}

}  // namespace

int verify(const VerifyOptions& o) {
  const std::vector<Case> cases = collect(o);
  if (cases.empty()) throw case_format::CaseError("verify", "no cases to verify: name case files or directories holding them, or --random N");
  std::vector<Analysis<F>> refs;
  std::vector<double> conds;
  for (const auto& c : cases) {
    try {
      const Scene<F> s = case_format::to_scene<F>(c.spec);
      refs.push_back(analyze(s, case_format::to_strategies<F>(c.spec), Engine::generated));
      conds.push_back(static_cast<double>(refs.back().amplification));  // rounding.hpp
    } catch (const case_format::CaseError& e) {
      rethrow_naming(c, e);
    } catch (const SolveError& e) {
      rethrow_naming(c, case_format::no_solution(c.spec, e));
    }
  }
  std::string report = fmt::format(
      "{} cases against their 100-digit solve (generated engine). Errors: max and rms in units of the type's eps;\n"
      "bound: max in units of eps x kappa(K) cond(J) (|v_IC1| + |v_IC2|)/V_rn (ratios also x (1 + |V_cp/V_n|)(1 + |mu|)),\n"
      "must be <= {}; integrated P and V (stronge) in units of eps x that cond plus the two integrations' stated\n"
      "bounds over {}, so that the bound is the same;\n"
      "digits: the fewest correct significant digits; worst: the case of the largest bound units.\n\n",
      cases.size(), rounding::kResultRoundings, rounding::kResultRoundings);
  report += fmt::format("{:<12} {:<10} {:<15} {:>12} {:>10} {:>10} {:>8}  {}\n", "precision", "engine", "quantity", "max [eps]",
                        "rms [eps]", "bound", "digits", "worst");
  bool ok = true;
  // The 100-digit reference itself, against exact fractions wherever a case's rotations are rational,
  // to rounding::kExactCheckDigits digits.
  int exact_results = 0;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const auto exact = algebraic_strategies<rational>(cases[i].spec);
    if (exact.strategies.empty()) continue;
    std::optional<ExactAnalysis> x;
    try {
      x = exact_analyze(case_format::to_scene<rational>(cases[i].spec), exact.strategies);
    } catch (const Irrational&) {
      continue;
    } catch (const case_format::CaseError&) {
      continue;  // a rotation orthonormal within rounding::orthonormality_tolerance but not exactly: no exact fractions
    }
    for (std::size_t k = 0; k < x->results.size(); ++k) {
      if (!x->results[k].solution) continue;
      ++exact_results;
      const Vec3<rational>& P = x->results[k].solution->impulse.P_C;
      const auto& R = refs[i].solutions[exact.index[k]].impulse.P_C;
      for (int j = 0; j < 3; ++j) {
        using std::abs;
        if (abs(R(j) - to_floating<F>(P(j))) > rounding::exact_check_tolerance<F>() * R.norm()) {
          ok = false;
          report += fmt::format("exact: {} result {}: the 100-digit impulse differs from the exact one\n", cases[i].name, exact.index[k]);
        }
      }
    }
  }
  report += fmt::format("exact: {} results of cases with rational rotations agree with the 100-digit solve to {} digits\n\n",
                        exact_results, rounding::kExactCheckDigits);
  for_each_scalar([&]<typename T>(std::type_identity<T>) {
    if constexpr (!std::is_same_v<T, F>) run_precision<T>(std::string(precision_name<T>), cases, refs, conds, report, ok);
  });
  if (o.certify) {
    std::vector<std::pair<std::string, case_format::CaseSpec>> named;
    for (const auto& c : cases) named.push_back({c.name, c.spec});
    ok = certify(named, report, o.corrupt_double) && ok;
  }
  report += ok ? "\nall bounds hold\n" : "\nFAILED: a bound is exceeded or a decision differs\n";
  std::fputs(report.c_str(), stdout);
  return ok ? 0 : 1;
}

}  // namespace impact3d::verification
