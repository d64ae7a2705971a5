// The Monte Carlo runner: samples drawn by index (uncertainty/sampler.hpp), so that any split over
// threads gives the same samples; each thread solves chunks of consecutive samples and writes their
// outputs into the run's store at the samples' own places, and the counts are sums, so the result does
// not depend on --jobs. Statistics are then taken over the store in sample order.
#include "impact3d/io/montecarlo.hpp"

#include <algorithm>
#include <atomic>
#include <charconv>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <map>
#include <mutex>
#include <thread>

#include <fmt/format.h>

#include "impact3d/io/case_variants.hpp"
#include "impact3d/io/escape.hpp"
#include "impact3d/io/format_double.hpp"
#include "impact3d/io/json_pick.hpp"
#include "impact3d/io/render.hpp"
#include "impact3d/uncertainty/portable_math.hpp"

namespace impact3d::io {

const std::vector<OutputPath>& monte_carlo_outputs() {
  static const std::vector<OutputPath> outputs = [] {
    std::vector<OutputPath> v;
    auto add = [&](std::string text, bool angle = false, bool from_zero = false) {
      JsonPath path = parse_json_path(text, "monte_carlo_outputs");
      v.push_back({std::move(text), std::move(path), angle, from_zero});
    };
    for (const char* k : {"mu", "mu_t", "mu_z"}) add(fmt::format("impulse_ratio.{}", k));
    for (const char* k : {"gir", "cir", "mu_t_critical", "mu_z_critical"}) add(fmt::format("limits.{}", k));
    add("plane_angle_deg", true);
    for (const char* group : {"impulse.contact", "impulse.world", "relative_velocity.before", "relative_velocity.after"})
      for (int i = 0; i < 3; ++i) add(fmt::format("{}[{}]", group, i));
    add("sliding.before");
    add("sliding.after");
    add("sliding.swerve_angle_deg", true);
    add("sliding.swerve_speed");
    add("impulse_space.restitution_effective");
    for (int veh = 0; veh < 2; ++veh) {
      for (const char* group : {"velocity", "angular_velocity", "delta_v"})
        for (int i = 0; i < 3; ++i) add(fmt::format("vehicles[{}].{}[{}]", veh, group, i));
      add(fmt::format("vehicles[{}].delta_v_magnitude", veh));
      add(fmt::format("vehicles[{}].pdof_deg", veh), true, true);  // [0, 360)
    }
    for (const char* k : {"before", "after", "loss"}) add(fmt::format("energy.{}", k));
    return v;
  }();
  return outputs;
}

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr std::uint64_t kChunk = 64;  // samples a thread takes at once

// What the pick records of each result document: every output, then the regime.
JsonPick make_pick() {
  std::vector<JsonPath> paths;
  auto in_results = [](const JsonPath& path) {
    JsonPath out = {PathStep::of_key("results"), PathStep::any_index()};
    out.insert(out.end(), path.begin(), path.end());
    return out;
  };
  for (const auto& o : monte_carlo_outputs()) paths.push_back(in_results(o.path));
  paths.push_back(in_results({PathStep::of_key("regime")}));
  return JsonPick(paths, true);
}

// A distribution's values reach a field the case bounds only inside its support: each end is tried on
// the case reader (the case's own rules, not a copy of them), an unbounded end as a value far out.
void check_supports(CaseVariants& variants, const UncertaintySpec& u) {
  using Kind = uncertainty::Distribution::Kind;
  constexpr double kFar = 1e11;  // inside the case's magnitude limit, outside any field's bounds
  const std::vector<double> base = variants.values();
  for (std::size_t i = 0; i < u.inputs.size(); ++i) {
    const auto& d = u.inputs[i].distribution;
    struct End {
      double value;
      bool bounded;
      const char* side;
    };
    std::vector<End> ends;
    switch (d.kind) {
      case Kind::normal: ends = {{-kFar, false, "below"}, {kFar, false, "above"}}; break;
      case Kind::lognormal:
        ends = {{d.median * uncertainty::portable_exp(-9 * d.sigma), true, "lower"}, {kFar, false, "above"}};
        break;
      case Kind::discrete: {
        const auto [lo, hi] = std::minmax_element(d.values.begin(), d.values.end());
        ends = {{*lo, true, "lower"}, {*hi, true, "upper"}};
        break;
      }
      default: ends = {{d.min, true, "lower"}, {d.max, true, "upper"}};
    }
    const std::string field = u.inputs[i].path_text;
    for (const End& end : ends) {
      std::vector<double> values = base;
      values[i] = end.value;
      try {
        variants.with(values.data());
      } catch (const CaseError& e) {
        if (e.path != path_text(u.inputs[i].path)) continue;  // a rule of the whole case: the sample's to meet
        const std::string kind(uncertainty::kind_name(d.kind));
        if (end.bounded)
          throw CaseError(fmt::format("$.inputs[{}].distribution", i),
                          fmt::format("the {} reaches {} at its {} end, but the case refuses it: {}", kind,
                                      fmt::format("{}", end.value), end.side, e.line()));
        throw CaseError(fmt::format("$.inputs[{}].distribution", i),
                        fmt::format("a {} is not bounded {}, but the case bounds {} ({}): use a bounded distribution "
                                    "(truncated-normal, uniform, triangular, discrete)",
                                    kind, end.side, field, e.what()));
      }
    }
  }
}

// What a sample's failure is counted as.
std::string reason_of(const CaseError& e) {
  const std::string_view what = e.what();
  if (what.find("not approaching") != std::string_view::npos) return "not approaching";
  if (what.rfind("no solution", 0) == 0) return "no solution";
  return "invalid " + e.path;
}

struct Tally {
  std::uint64_t solved = 0;
  std::array<std::uint64_t, kRegimeNames.size()> regimes{};
  std::array<std::uint64_t, kWarningNames.size()> warnings{};
  std::vector<bool> written;                 // per output: some document wrote it
  std::map<std::string, Rejections> rejected;  // by reason
};

class Worker {
 public:
  Worker(const CaseVariants& variants, const uncertainty::Sampler& sampler, const MonteCarloOptions& o,
         std::size_t results, MonteCarloRun& run, std::vector<double>& store, std::mutex& reasons_lock)
      : variants_(variants), sampler_(sampler), o_(o), pick_(make_pick()), tally_(results), run_(run), store_(store),
        reasons_lock_(reasons_lock), values_(sampler.size()) {
    for (auto& t : tally_) t.written.assign(monte_carlo_outputs().size(), false);
  }

  void sample(std::uint64_t i) {
    sampler_.draw(i, values_.data());
    if (o_.keep_samples) std::copy(values_.begin(), values_.end(), run_.inputs_of.begin() + static_cast<std::ptrdiff_t>(i * values_.size()));
    CaseSpec spec;
    try {
      spec = variants_.with(values_.data());
    } catch (const CaseError& e) {
      for (std::size_t k = 0; k < tally_.size(); ++k) reject(i, k, e);
      return;
    }
    if (!o_.strategies.empty()) spec.strategies = o_.strategies;
    try {
      solve(i, spec, 0, tally_.size());
    } catch (const SolveError& e) {
      if (!e.strategy) {
        for (std::size_t k = 0; k < tally_.size(); ++k) reject(i, k, CaseError("$", e.what()));
        return;
      }
      // One strategy has no solution: the others are solved on their own.
      for (std::size_t k = 0; k < tally_.size(); ++k) {
        CaseSpec one = spec;
        one.strategies = {spec.strategies[k]};
        try {
          solve(i, one, k, 1);
        } catch (const SolveError& f) {
          SolveError named = f;
          named.strategy = k;
          reject(i, k, no_solution(spec, named));
        } catch (const CaseError& f) {
          reject(i, k, f);
        }
      }
    } catch (const CaseError& e) {
      for (std::size_t k = 0; k < tally_.size(); ++k) reject(i, k, e);
    }
  }

  std::vector<Tally>& tally() { return tally_; }

 private:
  // Results first .. first + count of sample i, from the document of `spec` (whose strategies are
  // those results).
  void solve(std::uint64_t i, const CaseSpec& spec, std::size_t first, std::size_t count) {
    pick_.clear();
    RenderOptions ro;
    ro.format = "jsonl";
    ro.engine = o_.engine;
    ro.pick = &pick_;
    ro.warning_codes = &codes_;
    const std::string doc = render(spec, o_.precision, ro);
    const std::size_t outputs = monte_carlo_outputs().size(), n = run_.samples;
    for (std::size_t k = first; k < first + count; ++k) {
      Tally& t = tally_[k];
      ++t.solved;
      for (std::size_t w = 0; w < kWarningNames.size(); ++w)
        if (has_warning(codes_[k - first], static_cast<WarningCode>(w))) ++t.warnings[w];
    }
    for (const auto& s : pick_.spans()) {
      const std::size_t k = first + s.group;
      if (s.group >= count) continue;
      const std::string_view text(doc.data() + s.begin, s.end - s.begin);
      if (s.column == outputs) {  // the regime, a string
        const std::string_view name = pick_.string(s);
        const auto it = std::find(kRegimeNames.begin(), kRegimeNames.end(), name);
        const std::size_t r = static_cast<std::size_t>(it - kRegimeNames.begin());
        if (r < kRegimeNames.size()) {
          ++tally_[k].regimes[r];
          if (o_.keep_samples) run_.regime_of[k][i] = static_cast<std::int8_t>(r);
        }
        continue;
      }
      double v = kNaN;  // null: a quantity the document leaves undefined for this sample
      if (text != "null") {
        const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
        if (ec != std::errc() || end != text.data() + text.size()) throw std::runtime_error("an output does not read back: " + std::string(text));
      }
      tally_[k].written[s.column] = true;
      store_[(k * outputs + s.column) * n + i] = v;
    }
  }

  void reject(std::uint64_t i, std::size_t k, const CaseError& e) {
    const std::string reason = reason_of(e);
    Rejections& r = tally_[k].rejected[reason];
    if (r.count++ == 0 || i < r.first) {
      r.reason = reason;
      r.first = i;
      r.message = e.line();
    }
    if (o_.keep_samples) {
      const std::lock_guard<std::mutex> lock(reasons_lock_);
      auto it = std::find(run_.reasons.begin(), run_.reasons.end(), reason);
      if (it == run_.reasons.end()) it = run_.reasons.insert(it, reason);
      run_.reason_of[k][i] = static_cast<std::uint16_t>(it - run_.reasons.begin() + 1);
    }
  }

  CaseVariants variants_;  // this thread's copy
  const uncertainty::Sampler& sampler_;
  const MonteCarloOptions& o_;
  JsonPick pick_;
  std::vector<Tally> tally_;
  MonteCarloRun& run_;
  std::vector<double>& store_;
  std::mutex& reasons_lock_;
  std::vector<double> values_;
  std::vector<WarningSet> codes_;
};

void merge(std::vector<Tally>& into, const std::vector<Tally>& from) {
  for (std::size_t k = 0; k < into.size(); ++k) {
    Tally& a = into[k];
    const Tally& b = from[k];
    a.solved += b.solved;
    for (std::size_t r = 0; r < a.regimes.size(); ++r) a.regimes[r] += b.regimes[r];
    for (std::size_t w = 0; w < a.warnings.size(); ++w) a.warnings[w] += b.warnings[w];
    for (std::size_t o = 0; o < a.written.size(); ++o) a.written[o] = a.written[o] || b.written[o];
    for (const auto& [reason, r] : b.rejected) {
      Rejections& m = a.rejected[reason];
      if (m.count == 0 || r.first < m.first) m.reason = r.reason, m.first = r.first, m.message = r.message;
      m.count += r.count;
    }
  }
}

}  // namespace

MonteCarloRun montecarlo(const std::string& case_text, const UncertaintySpec& u, const MonteCarloOptions& o) {
  if (o.precision == "exact") throw CaseError("--precision", "Monte Carlo runs at a floating-point precision, not exact");
  std::vector<JsonPath> paths;
  std::vector<std::string> where;
  for (std::size_t i = 0; i < u.inputs.size(); ++i) {
    paths.push_back(u.inputs[i].path);
    where.push_back(fmt::format("$.inputs[{}].path", i));
  }
  CaseVariants variants(case_text, paths, where);
  check_supports(variants, u);
  const uncertainty::Sampler sampler = make_sampler(u);

  MonteCarloRun run;
  run.samples = u.samples;
  run.seed = u.seed;
  run.precision = o.precision;
  for (const auto& in : u.inputs) run.inputs.push_back(in.path_text);
  const std::vector<StrategySpec>& strategies = o.strategies.empty() ? variants.base().strategies : o.strategies;
  const std::size_t results = strategies.size(), outputs = monte_carlo_outputs().size();
  const std::uint64_t n = u.samples;
  const std::uint64_t kept = n * (results * outputs + (o.keep_samples ? u.inputs.size() : 0));
  if (kept > kMaxKeptValues)
    throw CaseError("$.samples", fmt::format("{} samples of {} results keep {} values, more than a run keeps ({}): take "
                                             "fewer samples or strategies",
                                             n, results, kept, kMaxKeptValues));
  std::vector<double> store(results * outputs * n, kNaN);
  if (o.keep_samples) {
    run.inputs_of.assign(n * u.inputs.size(), 0.0);
    run.regime_of.assign(results, std::vector<std::int8_t>(n, -1));
    run.reason_of.assign(results, std::vector<std::uint16_t>(n, 0));
  }

  const unsigned jobs = std::max(1u, o.jobs ? o.jobs : std::thread::hardware_concurrency());
  std::mutex reasons_lock;
  std::vector<Worker> workers;
  workers.reserve(jobs);
  for (unsigned j = 0; j < jobs; ++j) workers.emplace_back(variants, sampler, o, results, run, store, reasons_lock);
  std::atomic<std::uint64_t> next{0}, done{0};
  std::atomic<bool> failed{false};
  std::exception_ptr error;
  std::mutex error_lock;
  auto work = [&](Worker& w) {
    try {
      for (;;) {
        const std::uint64_t first = next.fetch_add(kChunk);
        if (first >= n || failed) return;
        const std::uint64_t last = std::min(n, first + kChunk);
        for (std::uint64_t i = first; i < last; ++i) w.sample(i);
        done += last - first;
      }
    } catch (...) {
      const std::lock_guard<std::mutex> lock(error_lock);
      if (!error) error = std::current_exception();
      failed = true;
    }
  };
  {
    std::vector<std::jthread> threads;
    for (unsigned j = 1; j < jobs; ++j) threads.emplace_back(work, std::ref(workers[j]));
    if (o.progress) {  // the calling thread reports
      std::jthread own(work, std::ref(workers[0]));
      while (done < n && !failed) {
        o.progress(done);
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
      }
      own.join();
      o.progress(done);
    } else {
      work(workers[0]);
    }
  }
  if (error) std::rethrow_exception(error);

  std::vector<Tally> tally(results);
  for (auto& t : tally) t.written.assign(outputs, false);
  for (auto& w : workers) merge(tally, w.tally());

  for (std::size_t k = 0; k < results; ++k) {
    StrategySummary s;
    s.strategy = strategies[k];
    s.solved = tally[k].solved;
    for (auto& [reason, r] : tally[k].rejected) s.rejected.push_back(std::move(r));
    s.regimes = tally[k].regimes;
    s.warnings = tally[k].warnings;
    std::vector<double> column;
    for (std::size_t c = 0; c < outputs; ++c) {
      if (!tally[k].written[c]) continue;
      const double* at = store.data() + (k * outputs + c) * n;
      column.clear();
      for (std::uint64_t i = 0; i < n; ++i)
        if (std::isfinite(at[i])) column.push_back(at[i]);
      const OutputPath& out = monte_carlo_outputs()[c];
      OutputSummary summary{&out, s.solved - column.size(), {}};
      summary.summary = out.angle ? uncertainty::summarize_angle_deg(column, out.from_zero) : uncertainty::summarize(column);
      s.outputs.push_back(std::move(summary));
    }
    run.results.push_back(std::move(s));
  }
  if (o.keep_samples) run.outputs_of = std::move(store);
  return run;
}

}  // namespace impact3d::io
