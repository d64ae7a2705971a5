// The Monte Carlo runner: samples drawn by index (uncertainty/sampler.hpp), so that any split over
// threads gives the same samples; each thread solves chunks of consecutive samples and writes their
// outputs into the run's store at the samples' own places, and the counts are sums, so the result does
// not depend on --jobs. Statistics are then taken over the store in sample order.
#include "impact3d/studies/montecarlo.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include <fmt/format.h>

#include "impact3d/case_format/case_variants.hpp"
#include "impact3d/case_format/escape.hpp"
#include "impact3d/case_format/format_double.hpp"
#include "impact3d/studies/precision.hpp"
#include "impact3d/case_format/result_outputs.hpp"
#include "impact3d/case_format/strategy_kinds.hpp"
#include "impact3d/case_format/to_scene.hpp"
#include "impact3d/case_format/case_numbers.hpp"
#include "impact3d/studies/montecarlo_linear.hpp"
#include "impact3d/studies/result_numbers.hpp"
#include "impact3d/mechanics/analysis.hpp"
#include "impact3d/scalar/parallel_chunks.hpp"
#include "impact3d/uncertainty/portable_math.hpp"
#include "not_a_number.hpp"

namespace impact3d::studies {
using namespace case_format;  // the studies are written in the case format's terms

namespace {

constexpr std::uint64_t kChunk = 64;  // samples a thread takes at once
// The value an unbounded end of a distribution is probed at: inside the case's magnitude limit (1e12),
// outside any field's bounds.
constexpr double kFar = 1e11;

// Whether `path` is `container` or lies under it.
bool under(const std::string& path, const std::string& container) {
  return path.rfind(container, 0) == 0 &&
         (path.size() == container.size() || path[container.size()] == '.' || path[container.size()] == '[');
}

// A distribution's values reach a field the case bounds only inside its support: each end is tried on
// the case reader (the case's own rules, not a copy of them), an unbounded end as a value far out.
// Returns, per input, whether both ends passed the reader with no error at all: then the reader takes
// every value between them (its rules on one number are ranges), which the direct route relies on.
std::vector<char> check_supports(CaseVariants& variants, const UncertaintySpec& u) {
  std::vector<char> clean(u.inputs.size(), 1);
  using Kind = uncertainty::Distribution::Kind;
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
        clean[i] = 0;
        const std::string kind(uncertainty::kind_name(d.kind));
        if (e.path != path_text(u.inputs[i].path)) {
          // A rule of several numbers (a symmetric tensor): the samples' to meet, unless no other input
          // varies a number under it, when every sample but the case's own values would break it.
          if (std::any_of(u.inputs.begin(), u.inputs.end(), [&](const UncertainInput& other) {
                return &other != &u.inputs[i] && under(path_text(other.path), e.path);
              }))
            continue;
          throw CaseError(fmt::format("$.inputs[{}].distribution", i),
                          fmt::format("the {} reaches {} at its {} end, where the case refuses it, and no other input "
                                      "varies {}: {}",
                                      kind, fmt::format("{}", end.value), end.side, e.path, e.line()));
        }
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
  return clean;
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
  // `direct`: each input writes straight into a copy of the read case (single_numbers) rather than
  // into its text to be read again; empty when some input needs the reader.
  Worker(const CaseVariants& variants, const uncertainty::Sampler& sampler, const MonteCarloOptions& o,
         std::size_t results, MonteCarloRun& run, std::vector<double>& store, std::mutex& reasons_lock,
         const std::vector<std::string>& direct)
      : variants_(variants), sampler_(sampler), o_(o), tally_(results), run_(run), store_(store),
        reasons_lock_(reasons_lock), values_(sampler.size()), spec_(variants.base()) {
    for (auto& t : tally_) t.written.assign(monte_carlo_outputs().size(), false);
    if (direct.empty()) return;
    const auto numbers = single_numbers(spec_);
    for (const std::string& path : direct)
      for (const auto& [p, number] : numbers)
        if (p == path) slots_.push_back(number);
    if (slots_.size() != direct.size()) slots_.clear();
    if (!o_.strategies.empty()) spec_.strategies = o_.strategies;
  }
  Worker(const Worker&) = delete;  // slots_ point into spec_
  Worker& operator=(const Worker&) = delete;

  void sample(std::uint64_t i) {
    sampler_.draw(i, values_.data());
    if (o_.keep_samples) std::copy(values_.begin(), values_.end(), run_.inputs_of.begin() + static_cast<std::ptrdiff_t>(i * values_.size()));
    const bool direct = write_direct();
    std::optional<CaseSpec> read;
    if (!direct) {
      try {
        read = variants_.with(values_.data());
      } catch (const CaseError& e) {
        for (std::size_t k = 0; k < tally_.size(); ++k) reject(i, k, e);
        return;
      }
      if (!o_.strategies.empty()) read->strategies = o_.strategies;
    }
    const CaseSpec& spec = direct ? spec_ : *read;
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
  // The sample written into spec_, as the reader would have read it from its 17-digit text; false
  // where the reader must decide: no slots, or a value beyond the magnitudes the probes covered or
  // below the case's smallest magnitude. At double the text is not written: the double engine reads
  // the value (to_scene.hpp), and nothing on the double route reads a sampled number's text.
  bool write_direct() {
    if (slots_.empty()) return false;
    for (double v : values_)
      if (!std::isfinite(v) || (v != 0 && (std::fabs(v) < 1e-99 || std::fabs(v) > kFar))) return false;
    const bool text = o_.precision != PrecisionChoice(floating_precision<double>());
    char buf[32];
    for (std::size_t j = 0; j < slots_.size(); ++j) {
      slots_[j]->value = values_[j];
      if (text) slots_[j]->text.assign(buf, format_g17(buf, values_[j]));
    }
    return true;
  }

 private:
  // Results first .. first + count of sample i, where `spec`'s strategies are those results: the
  // analysis at the run's precision, its numbers taken as the document writes them
  // (numbers_of_solution) and each rounded once to double, never read back from text;
  // `tests/studies/check_montecarlo.cpp` holds them to the document's numbers.
  void solve(std::uint64_t i, const CaseSpec& spec, std::size_t first, std::size_t count) {
    with_floating_scalar(std::get<FloatingPrecision>(o_.precision),
                         [&]<typename Scalar>() { solve_at<Scalar>(i, spec, first, count); });
  }

  template <typename Scalar>
  void solve_at(std::uint64_t i, const CaseSpec& spec, std::size_t first, std::size_t count) {
    const Scene<Scalar> scene = to_scene<Scalar>(spec);
    const Analysis<Scalar> a = analyze(scene, to_strategies<Scalar>(spec), o_.engine);
    const UnitFactors<Scalar> f = unit_factors<Scalar>(spec.units);
    const std::size_t outputs = monte_carlo_outputs().size(), n = run_.samples;
    thread_local std::vector<Scalar> numbers;  // kept from sample to sample: no allocation once warm
    numbers.resize(outputs);
    for (std::size_t k = first; k < first + count; ++k) {
      const Solution<Scalar>& sol = a.solutions[k - first];
      Tally& t = tally_[k];
      ++t.solved;
      WarningSet codes = 0;
      for (const auto& w : sol.warnings) codes |= warning_bit(w.code);
      for (std::size_t w = 0; w < kWarningNames.size(); ++w)
        if (has_warning(codes, static_cast<WarningCode>(w))) ++t.warnings[w];
      const auto r = static_cast<std::size_t>(
          std::find(kRegimeNames.begin(), kRegimeNames.end(), regime_name(sol.impulse.regime)) - kRegimeNames.begin());
      ++t.regimes[r];
      if (o_.keep_samples) run_.regime_of[k][i] = static_cast<std::int8_t>(r);
      numbers_of_solution(sol, f, numbers.data(), written_.data());
      for (std::size_t c = 0; c < outputs; ++c)
        if (written_[c]) {
          t.written[c] = true;
          store_[(k * outputs + c) * n + i] = to_double(numbers[c]);
        }
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
  std::vector<Tally> tally_;
  MonteCarloRun& run_;
  std::vector<double>& store_;
  std::mutex& reasons_lock_;
  std::vector<double> values_;
  CaseSpec spec_;                // the read case, for the direct route
  std::vector<Number*> slots_;  // the inputs' numbers in spec_
  std::vector<char> written_ = std::vector<char>(monte_carlo_outputs().size());
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

std::uint64_t run_bytes_per_sample(std::size_t results, std::size_t inputs, bool keep_samples) {
  // The store of every output, the samples' inputs, regimes and reasons when kept, and on each of the
  // summaries' threads at most 48 bytes a sample: the output's column (8), and the order statistics'
  // bin of each value (2) and values gathered (8) at each of their three levels at worst, and the last
  // level's copy (8) (statistics.cpp).
  const std::uint64_t store = 8 * results * monte_carlo_outputs().size();
  const std::uint64_t kept = keep_samples ? 8 * inputs + 3 * results : 0;
  return store + kept + 48 * kSummaryThreads;
}

MonteCarloRun montecarlo(const std::string& case_text, const UncertaintySpec& u, const MonteCarloOptions& o) {
  if (std::holds_alternative<ExactPrecision>(o.precision)) throw CaseError("--precision", "Monte Carlo runs at a floating-point precision, not exact");
  if (std::holds_alternative<CertifiedPrecision>(o.precision)) throw CaseError("--precision", "Monte Carlo runs at a floating-point precision, not certified");
  std::vector<JsonPath> paths;
  std::vector<std::string> where;
  for (std::size_t i = 0; i < u.inputs.size(); ++i) {
    paths.push_back(u.inputs[i].path);
    where.push_back(fmt::format("$.inputs[{}].path", i));
  }
  CaseVariants variants(case_text, paths, where);
  const std::vector<char> clean = check_supports(variants, u);
  if (!o.strategies.empty())
    for (std::size_t i = 0; i < u.inputs.size(); ++i)
      if (!u.inputs[i].path.empty() && u.inputs[i].path[0].kind == PathStep::Kind::key && u.inputs[i].path[0].key == "strategy")
        throw CaseError("--strategy", fmt::format("replaces the case's strategies, which $.inputs[{}] varies ({})", i,
                                                  u.inputs[i].path_text));
  // The direct route when every input is a single number the probes passed (the reader's ranges).
  std::vector<std::string> direct;
  {
    CaseSpec probe = variants.base();
    const auto numbers = single_numbers(probe);
    for (std::size_t i = 0; i < u.inputs.size(); ++i) {
      const std::string path = path_text(u.inputs[i].path);
      const bool single = std::any_of(numbers.begin(), numbers.end(), [&](const auto& n) { return n.first == path; });
      if (!single || !clean[i]) {
        direct.clear();
        break;
      }
      direct.push_back(path);
    }
  }
  const uncertainty::Sampler sampler = make_sampler(u);

  MonteCarloRun run;
  run.samples = u.samples;
  run.seed = u.seed;
  run.precision = precision_label(o.precision);
  for (const auto& in : u.inputs) run.inputs.push_back(in.path_text);
  run.direct = !direct.empty();
  run.units = variants.base().units;
  const std::vector<StrategySpec>& strategies = o.strategies.empty() ? variants.base().strategies : o.strategies;
  const std::size_t results = strategies.size(), outputs = monte_carlo_outputs().size();
  const std::uint64_t n = u.samples;
  const std::uint64_t per_sample = run_bytes_per_sample(results, u.inputs.size(), o.keep_samples);
  // Compared by division: n * per_sample may wrap for a caller that does not bound n (the readers do).
  if (n > kMaxRunBytes / per_sample)
    throw CaseError("$.samples",
                    fmt::format("{} samples of {} {} would take {:.0f} MiB ({} bytes a sample), more than the {} MiB a run may "
                                "take: every output of every sample is kept for the percentiles; take at most {} samples, "
                                "or fewer strategies",
                                n, results, results == 1 ? "result" : "results",
                                std::ceil(static_cast<double>(n) * static_cast<double>(per_sample) / (1 << 20)),
                                per_sample, kMaxRunBytes >> 20, kMaxRunBytes / per_sample));
  std::vector<double> store(results * outputs * n, kNaN);
  if (o.keep_samples) {
    run.inputs_of.assign(n * u.inputs.size(), 0.0);
    run.regime_of.assign(results, std::vector<std::int8_t>(n, -1));
    run.reason_of.assign(results, std::vector<std::uint16_t>(n, 0));
  }

  const unsigned jobs = std::max(1u, o.jobs ? o.jobs : std::thread::hardware_concurrency());
  std::mutex reasons_lock;
  std::vector<std::unique_ptr<Worker>> workers;
  for (unsigned j = 0; j < jobs; ++j)
    workers.push_back(std::make_unique<Worker>(variants, sampler, o, results, run, store, reasons_lock, direct));
  {
    ParallelChunks pool(jobs);
    ParallelChunks::Caller caller;
    if (o.progress) caller.report = [&](std::size_t done) { o.progress(done); };  // the calling thread reports
    pool.run(n, kChunk, [&](unsigned t, std::size_t first, std::size_t last) {
      for (std::size_t i = first; i < last; ++i) workers[t]->sample(i);
    }, caller);
  }

  std::vector<Tally> tally(results);
  for (auto& t : tally) t.written.assign(outputs, false);
  for (auto& w : workers) merge(tally, w->tally());
  for (std::size_t k = 0; k < results; ++k) {
    if (tally[k].solved > 0 || n == 0) continue;
    const Rejections* most = nullptr;
    for (const auto& [reason, r] : tally[k].rejected)
      if (!most || r.count > most->count) most = &r;
    if (!most) continue;
    throw CaseError("$", fmt::format("{} solved none of the {} samples: {} of them {}, the first (sample {}): {}",
                                     strategy_label(strategies[k]), n, most->count,
                                     most->reason == "not approaching" ? "do not approach"
                                     : most->reason == "no solution"   ? "have no solution"
                                                                       : "are refused (" + most->reason + ")",
                                     most->first, most->message));
  }

  for (std::size_t k = 0; k < results; ++k) {
    StrategySummary s;
    s.strategy = strategies[k];
    s.solved = tally[k].solved;
    for (auto& [reason, r] : tally[k].rejected) s.rejected.push_back(std::move(r));
    s.regimes = tally[k].regimes;
    s.warnings = tally[k].warnings;
    for (std::size_t c = 0; c < outputs; ++c)
      if (tally[k].written[c]) s.outputs.push_back({&monte_carlo_outputs()[c], 0, {}});
    run.results.push_back(std::move(s));
  }
  // Each output's summary on its own, on the run's threads: sorting dominates, and the summaries do
  // not depend on each other, so the split changes nothing.
  std::vector<std::pair<std::size_t, OutputSummary*>> todo;  // (result, summary)
  for (std::size_t k = 0; k < results; ++k)
    for (auto& summary : run.results[k].outputs) todo.emplace_back(k, &summary);
  ParallelChunks summarizers(std::min(jobs, kSummaryThreads));
  std::vector<std::vector<double>> columns(summarizers.jobs());  // one a thread, reserved once
  summarizers.run(todo.size(), 1, [&](unsigned thread, std::size_t t, std::size_t) {
    std::vector<double>& column = columns[thread];
    if (column.capacity() < n) column.reserve(n);  // grown by push_back, it could take twice the samples
    const auto [k, summary] = todo[t];
    const OutputPath& out = *summary->output;
    const double* at = store.data() + (k * outputs + static_cast<std::size_t>(&out - monte_carlo_outputs().data())) * n;
    column.clear();
    for (std::uint64_t i = 0; i < n; ++i)
      if (std::isfinite(at[i])) column.push_back(at[i]);
    summary->undefined = run.results[k].solved - column.size();
    summary->summary = out.angle ? uncertainty::summarize_angle_deg(column, out.from_zero) : uncertainty::summarize(column);
  });
  if (o.keep_samples) run.outputs_of = std::move(store);
  linearize(run, variants, u, o);
  return run;
}

}  // namespace impact3d::studies
