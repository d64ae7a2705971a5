#include "montecarlo.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <cerrno>
#include <optional>

#include <fmt/format.h>

#include "impact3d/case_format/limits.hpp"
#include "impact3d/studies/montecarlo.hpp"
#include "impact3d/case_format/read_case.hpp"
#include "impact3d/case_format/read_uncertainty.hpp"
#include "impact3d/case_format/strategy_kinds.hpp"
#include "impact3d/case_format/strategy_option.hpp"
#include "impact3d/case_format/escape.hpp"
#include "impact3d/cli/output_file.hpp"
#include "impact3d/cli/user_error.hpp"

namespace impact3d::cli {

int montecarlo(const MonteCarloCliOptions& o) {
  studies::MonteCarloOptions mo;
  mo.precision = studies::parse_precision(o.precision);
  mo.engine = o.engine;
  mo.jobs = o.jobs;
  if (o.strategies.size() > case_format::limits::kStrategies)
    throw case_format::CaseError("--strategy", fmt::format("more than {} strategies", case_format::limits::kStrategies));
  for (std::size_t i = 0; i < o.strategies.size(); ++i)
    mo.strategies.push_back(case_format::read_strategy_option(o.strategies[i], static_cast<int>(i)));
  // The case on its own first, so that its problems name it; then the uncertainty file's.
  std::string case_text;
  try {
    case_text = case_format::read_text_file(o.case_path);
    case_format::read_case(case_text);
  } catch (const case_format::CaseError& e) {
    throw in_file(o.case_path, e);
  }
  case_format::UncertaintySpec u;
  try {
    u = case_format::read_uncertainty(case_format::read_text_file(o.uncertainty_path));
  } catch (const case_format::CaseError& e) {
    throw in_file(o.uncertainty_path, e);
  }
  if (o.samples) u.samples = *o.samples;
  if (o.seed) u.seed = *o.seed;
  if (!o.plot.out_dir.empty()) {
    check_plot_options(o.plot);
    mo.keep_samples = true;
  }
  // The samples' file is opened before the run, so that a run is not lost to a path that cannot be written.
  std::optional<OutputFile> samples_file;
  if (!o.samples_out.empty()) {
    mo.keep_samples = true;
    try {
      samples_file.emplace(o.samples_out);
    } catch (const UserError& e) {
      throw UserError(std::string("--samples-out: ") + e.what());
    }
  }
  const bool shown = ::isatty(STDERR_FILENO) == 1;
  const auto start = std::chrono::steady_clock::now();
  if (shown)
    mo.progress = [&](std::uint64_t done) {
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const double rate = seconds > 0 ? static_cast<double>(done) / seconds : 0;
      const double left = rate > 0 ? static_cast<double>(u.samples - done) / rate : 0;
      std::fprintf(stderr, "\rimpact3d: montecarlo: %llu of %llu samples, %.0f/s, %.0f s left   ",
                   static_cast<unsigned long long>(done), static_cast<unsigned long long>(u.samples), rate, left);
    };
  studies::MonteCarloRun run;
  try {
    run = studies::montecarlo(case_text, u, mo);
  } catch (const case_format::CaseError& e) {
    if (shown) std::fputs("\r\033[K", stderr);
    if (o.samples && e.path == "$.samples") throw case_format::CaseError("--samples", e.what());
    throw in_file(o.uncertainty_path, e);
  }
  if (shown) std::fputs("\r\033[K", stderr);
  // A summary of fewer than half the samples describes another population than the one asked for.
  for (const studies::StrategySummary& r : run.results)
    if (2 * r.solved < run.samples) {
      std::uint64_t most = 0;
      std::string why;
      for (const studies::Rejections& x : r.rejected)
        if (x.count > most) most = x.count, why = x.reason;
      std::fprintf(stderr, "impact3d: warning: montecarlo: %s solved %llu of %llu samples (the commonest rejection: %s, %llu): its summary describes only those\n",
                   case_format::printable(case_format::strategy_label(r.strategy)).c_str(), static_cast<unsigned long long>(r.solved),
                   static_cast<unsigned long long>(run.samples), case_format::printable(why).c_str(), static_cast<unsigned long long>(most));
    }
  if (samples_file) {
    int error = 0;
    studies::samples_csv(run, [&](std::string_view piece) {
      if (!error) error = write_all(samples_file->fd(), piece);
    });
    if (error)
      throw OutputLost(fmt::format("--samples-out: {}: cannot write the file ({}){}", o.samples_out, std::strerror(error),
                                   samples_file->replaces() ? "; nothing was replaced" : ""));
    try {
      samples_file->commit();
    } catch (const OutputLost& e) {
      throw OutputLost(std::string("--samples-out: ") + e.what());
    }
  }
  if (!o.plot.out_dir.empty()) montecarlo_plot(run, o.plot);
  const std::string out = o.format == "json" ? studies::montecarlo_json(run) : studies::montecarlo_text(run);
  std::fwrite(out.data(), 1, out.size(), stdout);
  return 0;
}

}  // namespace impact3d::cli
