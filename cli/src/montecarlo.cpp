#include "montecarlo.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <cerrno>
#include <optional>

#include <fmt/format.h>

#include "impact3d/io/limits.hpp"
#include "impact3d/io/montecarlo.hpp"
#include "impact3d/io/read_case.hpp"
#include "impact3d/io/read_uncertainty.hpp"
#include "impact3d/io/strategy_kinds.hpp"
#include "impact3d/io/strategy_option.hpp"
#include "impact3d/io/escape.hpp"
#include "output_file.hpp"
#include "user_error.hpp"

namespace impact3d::cli {

int montecarlo(const MonteCarloCliOptions& o) {
  io::MonteCarloOptions mo;
  mo.precision = o.precision;
  mo.engine = o.engine;
  mo.jobs = o.jobs;
  if (o.strategies.size() > io::limits::kStrategies)
    throw io::CaseError("--strategy", fmt::format("more than {} strategies", io::limits::kStrategies));
  for (std::size_t i = 0; i < o.strategies.size(); ++i)
    mo.strategies.push_back(io::read_strategy_option(o.strategies[i], static_cast<int>(i)));
  // The case on its own first, so that its problems name it; then the uncertainty file's.
  std::string case_text;
  try {
    case_text = io::read_text_file(o.case_path);
    io::read_case(case_text);
  } catch (const io::CaseError& e) {
    throw in_file(o.case_path, e);
  }
  io::UncertaintySpec u;
  try {
    u = io::read_uncertainty(io::read_text_file(o.uncertainty_path));
  } catch (const io::CaseError& e) {
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
  io::MonteCarloRun run;
  try {
    run = io::montecarlo(case_text, u, mo);
  } catch (const io::CaseError& e) {
    if (shown) std::fputs("\r\033[K", stderr);
    if (o.samples && e.path == "$.samples") throw io::CaseError("--samples", e.what());
    throw in_file(o.uncertainty_path, e);
  }
  if (shown) std::fputs("\r\033[K", stderr);
  // A summary of fewer than half the samples describes another population than the one asked for.
  for (const io::StrategySummary& r : run.results)
    if (2 * r.solved < run.samples) {
      std::uint64_t most = 0;
      std::string why;
      for (const io::Rejections& x : r.rejected)
        if (x.count > most) most = x.count, why = x.reason;
      std::fprintf(stderr, "impact3d: warning: montecarlo: %s solved %llu of %llu samples (the commonest rejection: %s, %llu): its summary describes only those\n",
                   io::printable(io::strategy_label(r.strategy)).c_str(), static_cast<unsigned long long>(r.solved),
                   static_cast<unsigned long long>(run.samples), io::printable(why).c_str(), static_cast<unsigned long long>(most));
    }
  if (samples_file) {
    int error = 0;
    io::samples_csv(run, [&](std::string_view piece) {
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
  const std::string out = o.format == "json" ? io::montecarlo_json(run) : io::montecarlo_text(run);
  std::fwrite(out.data(), 1, out.size(), stdout);
  return 0;
}

}  // namespace impact3d::cli
