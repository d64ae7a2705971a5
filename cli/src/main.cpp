// impact3d: solve a two-vehicle 3D collision case by the strategies of Marine's paper.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <optional>

#include <fmt/format.h>

#include <CLI/CLI.hpp>

#include "impact3d/case_format/escape.hpp"
#include "impact3d/case_format/read_case.hpp"
#include "impact3d/case_format/read_uncertainty.hpp"
#include "impact3d/studies/precision.hpp"
#include "impact3d/verification/compare.hpp"
#include "impact3d/verification/verify.hpp"
#include "batch.hpp"
#include "montecarlo.hpp"
#include "impact3d/cli/output_file.hpp"
#include "impact3d/cli/plot.hpp"
#include "report.hpp"
#include "reconstruct.hpp"
#include "sensitivity.hpp"
#include "impact3d/cli/user_error.hpp"

namespace {

// One policy for every subcommand: 0 done, 1 bad input (one line naming the file and the JSON path, or
// a strategy with no solution), 2 command-line usage, 3 internal error or an output lost. Every error
// is one line on stderr with the user's text escaped, and nothing on stdout.
constexpr int kBadInput = 1;
constexpr int kUsage = 2;
constexpr int kInternal = 3;

int error_line(const std::string& text, int status) {
  std::fprintf(stderr, "impact3d: error: %s\n", impact3d::case_format::printable(text).c_str());
  return status;
}

// `file`: the input the error is about, named first unless the error names it already.
template <typename F>
int guarded(const std::string& file, F&& body) {
  using namespace impact3d;
  const auto in_file = [&](const std::string& line) {
    return file.empty() || line.rfind(file + ":", 0) == 0 ? line : file + ": " + line;
  };
  try {
    return body();
  } catch (const case_format::CaseError& e) {
    return error_line(in_file(e.line()), kBadInput);
  } catch (const SolveError& e) {
    return error_line(in_file(std::string("no solution: ") + e.what()), kBadInput);
  } catch (const cli::OutputLost& e) {
    return error_line(e.what(), kInternal);
  } catch (const cli::UserError& e) {
    return error_line(e.what(), kBadInput);
  } catch (const std::bad_alloc&) {
    return error_line(in_file("out of memory: the machine gave less than the run needed (docs/limits-and-exit-status.md)"), kInternal);
  } catch (const std::exception& e) {
    return error_line(in_file(e.what()), kInternal);
  }
}

// `body(spec)`, with a strategy that has no solution named by its path in the case ($.strategy[2]).
template <typename F>
auto naming_strategies(const impact3d::case_format::CaseSpec& spec, F&& body) {
  try {
    return body();
  } catch (const impact3d::SolveError& e) {
    throw impact3d::case_format::no_solution(spec, e);
  }
}

// CLI11 converts "-1" to an unsigned 2^64 - 1 and lets a NaN through a range: the options' texts are
// checked as the files' numbers are, before any conversion.
// A seed or a count is read here, in decimal, from the option's text: CLI11 would read "010" as octal.
std::optional<std::uint64_t> seed_of(const std::string& text) {
  std::uint64_t v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return v;
}

std::string seed_problem(const std::string& text) {
  return seed_of(text) ? std::string() : "must be a whole number from 0 to 18446744073709551615, in decimal digits";
}

std::string tolerance_problem(const std::string& text) {
  double v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  const bool whole = !text.empty() && end == text.data() + text.size();
  // A value too small for a double (1e-400) is a tolerance of 0, as it reads.
  const bool underflow = ec == std::errc::result_out_of_range && std::fabs(std::strtod(text.c_str(), nullptr)) < 1;
  if (!whole || (ec != std::errc() && !underflow) || !std::isfinite(v) || v < 0 || v > 1e300)
    return "must be a finite number from 0 to 1e300";
  return {};
}

// The strategies of the case or the command line.
int solve(const std::string& case_path, const std::vector<std::string>& strategies, const impact3d::studies::PrecisionChoice& precision,
          const impact3d::case_format::RenderOptions& options) {
  using namespace impact3d;
  return guarded(case_path, [&] {
    case_format::CaseSpec spec = case_format::read_case(case_format::read_text_file(case_path));
    if (strategies.size() > case_format::limits::kStrategies)
      throw case_format::CaseError("--strategy", fmt::format("more than {} strategies", case_format::limits::kStrategies));
    if (!strategies.empty()) {
      spec.strategies.clear();
      for (std::size_t i = 0; i < strategies.size(); ++i)
        spec.strategies.push_back(case_format::read_strategy_option(strategies[i], static_cast<int>(i)));
    }
    const std::string output = naming_strategies(spec, [&] { return studies::render(spec, precision, options); });
    std::fwrite(output.data(), 1, output.size(), stdout);
    return 0;
  });
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"impact3d: three-dimensional rigid-body impact mechanics for automobile collisions"};
  app.require_subcommand(1);
  auto* solve_cmd = app.add_subcommand("solve", "solve a case file (contract: case-format.md)");
  std::string case_path, format = "text";
  std::vector<std::string> strategies;
  int digits = 0;
  std::string engine = "generated", precision = "double";
  solve_cmd->add_option("case", case_path, "case file (JSON)")->required();
  solve_cmd->add_option("--format", format, "text report or contract JSON")->check(CLI::IsMember({"text", "json"}));
  solve_cmd->add_option("--strategy", strategies,
                        "replace the case's strategies, e.g. pc-crash:mu=0.4  wach:mu=0.4,limit=gir  "
                        "brach:mu_t=critical,mu_z=0 (repeatable)");
  solve_cmd->add_option("--digits", digits,
                        "significant digits in the text report (default 10 at double, else every digit the "
                        "precision holds; JSON always prints them all)")
      ->check(CLI::Range(1, 110));
  std::string precision_list;
  for (const auto& name : impact3d::studies::precision_names()) precision_list += name + ", ";
  solve_cmd->add_option("--precision", precision,
                        "arithmetic: " + precision_list +
                            "certified or certified:BITS (numbers name decimal digits; exact: fractions where the "
                            "result is rational, beside the 100-digit solve; certified: ball arithmetic that encloses "
                            "every result and decides every branch or says it cannot, BITS 16 to 8192, default 256 "
                            "and more while a decision is undecided)")
      ->check([](const std::string& name) { return impact3d::studies::precision_problem(name); });
  solve_cmd->add_option("--engine", engine,
                        "generated: closed forms derived by symbolic/ (default); direct: 3x3 solves of the constraints")
      ->check(CLI::IsMember({"generated", "direct"}));
  std::string units;
  solve_cmd->add_option("--units", units,
                        "units of the output, whatever the case's: SI, US (mph, lb, ft, deg/s) or metric-kmh (SI with "
                        "km/h and deg/s); default the case's. The text report gives yaw rates in deg/s always")
      ->check(CLI::IsMember({"SI", "US", "metric-kmh"}));
  auto* batch_cmd = app.add_subcommand("batch", "solve many cases, one JSON object per line (contract: many-cases.md)");
  impact3d::cli::BatchOptions bopt;
  std::string batch_engine = "generated";
  batch_cmd->add_option("input", bopt.input, "JSON Lines or CSV file of cases (default: standard input, also -)");
  batch_cmd->add_option("-o,--output", bopt.output, "file for the results (default: standard output)");
  batch_cmd->add_option("--jobs", bopt.jobs, "threads (default: every core)")->check(CLI::Range(1, 1024));
  batch_cmd->add_option("--format", bopt.format, "jsonl: one result document per line (default); csv: one row per result")
      ->check(CLI::IsMember({"jsonl", "csv"}));
  batch_cmd->add_option("--input-format", bopt.input_format, "jsonl, csv (a header of case paths), or auto (default: csv for *.csv)")
      ->check(CLI::IsMember({"auto", "jsonl", "csv"}));
  batch_cmd->add_option("--strategy", bopt.strategies, "replace every case's strategies (as solve's --strategy)");
  batch_cmd->add_option("--precision", bopt.precision, "arithmetic, as solve's")
      ->check(CLI::IsMember(impact3d::studies::precision_names()));
  batch_cmd->add_option("--engine", batch_engine, "generated (default) or direct, as solve's")
      ->check(CLI::IsMember({"generated", "direct"}));
  auto* mc_cmd = app.add_subcommand("montecarlo", "solve a case for every sample of its uncertain inputs (contract: many-cases.md)");
  impact3d::cli::MonteCarloCliOptions mopt;
  std::string mc_engine = "generated";
  mc_cmd->add_option("case", mopt.case_path, "case file (JSON)")->required();
  mc_cmd->add_option("--uncertainty", mopt.uncertainty_path, "uncertainty file: the inputs' distributions (docs/montecarlo-and-sensitivity.md)")
      ->required();
  mc_cmd->add_option("--format", mopt.format, "text summary (default) or contract JSON")->check(CLI::IsMember({"text", "json"}));
  std::string mc_samples;
  mc_cmd->add_option("--samples", mc_samples, "replace the file's number of samples")->check([](const std::string& text) {
    const auto n = seed_of(text);
    return n && *n >= 1 && *n <= impact3d::case_format::kMaxSamples
               ? std::string()
               : fmt::format("must be a whole number from 1 to {}, in decimal digits", impact3d::case_format::kMaxSamples);
  });
  std::string mc_seed;
  mc_cmd->add_option("--seed", mc_seed, "replace the file's seed (0 to 2^64 - 1)")->check(seed_problem);
  mc_cmd->add_option("--jobs", mopt.jobs, "threads (default: every core); the output does not depend on it")
      ->check(CLI::Range(1, 1024));
  mc_cmd->add_option("--samples-out", mopt.samples_out, "also write every sample's inputs and outputs to this CSV file");
  mc_cmd->add_option("--plot", mopt.plot.out_dir, "also draw the figures into this directory (gnuplot)");
  mc_cmd->add_flag("--png", mopt.plot.png, "figures as PNG instead of SVG");
  std::vector<std::string> scatter;
  mc_cmd->add_option("--scatter", scatter, "the two outputs of the scatter figure (default: both vehicles' delta_v_magnitude)")
      ->expected(2);
  mc_cmd->add_option("--strategy", mopt.strategies, "replace the case's strategies (as solve's --strategy)");
  std::vector<std::string> mc_precisions = impact3d::studies::precision_names();
  std::erase(mc_precisions, "exact");
  mc_cmd->add_option("--precision", mopt.precision, "arithmetic of each sample, as solve's (not exact)")
      ->check(CLI::IsMember(mc_precisions));
  mc_cmd->add_option("--engine", mc_engine, "generated (default) or direct, as solve's")
      ->check(CLI::IsMember({"generated", "direct"}));
  auto* sens_cmd = app.add_subcommand(
      "sensitivity", "derivatives of every result number by every numeric input, the regime held fixed (many-cases.md)");
  impact3d::cli::SensitivityCliOptions sopt;
  std::string sens_engine = "generated";
  sens_cmd->add_option("case", sopt.case_path, "case file (JSON)")->required();
  sens_cmd->add_option("--format", sopt.format, "text report (default) or contract JSON")->check(CLI::IsMember({"text", "json"}));
  sens_cmd->add_option("--strategy", sopt.strategies, "replace the case's strategies (as solve's --strategy)");
  sens_cmd->add_option("--engine", sens_engine, "generated (default) or direct, as solve's")
      ->check(CLI::IsMember({"generated", "direct"}));
  sens_cmd->add_option("--plot", sopt.plot_dir, "also draw a tornado figure of each vehicle's delta-V into this directory");
  sens_cmd->add_flag("--png", sopt.png, "figures as PNG instead of SVG");
  auto* rec_cmd = app.add_subcommand(
      "reconstruct", "pre-impact speeds and other unknowns from post-impact evidence, by weighted least squares (many-cases.md)");
  impact3d::cli::ReconstructCliOptions recopt;
  std::string rec_engine = "generated";
  rec_cmd->add_option("case", recopt.case_path, "case file (JSON): every input but the unknowns, and one strategy")->required();
  rec_cmd->add_option("--evidence", recopt.evidence_path, "evidence file: the unknowns and the evidence (docs/reconstruction.md)")
      ->required();
  rec_cmd->add_option("--format", recopt.format, "text report (default) or contract JSON")->check(CLI::IsMember({"text", "json"}));
  rec_cmd->add_option("--strategy", recopt.strategy, "the strategy fitted, replacing the case's (as solve's --strategy)");
  rec_cmd->add_option("--engine", rec_engine, "generated (default) or direct, as solve's")
      ->check(CLI::IsMember({"generated", "direct"}));
  rec_cmd->add_option("--plot", recopt.plot_dir, "also draw the plan view and the chi2 surface into this directory (gnuplot)");
  rec_cmd->add_flag("--png", recopt.png, "figures as PNG instead of SVG");
  auto* compare_cmd = app.add_subcommand("compare", "compare another tool's results with reference results");
  std::string reference, other;
  impact3d::verification::CompareOptions copt;
  compare_cmd->add_option("reference", reference, "reference result (JSON file) or directory (verification/reference)")->required();
  compare_cmd->add_option("other", other, "the other tool's results: JSON file, directory of JSON files, or CSV")->required();
  // A tolerance that admits everything (inf) or nothing (< 0) is a usage error, not a verdict.
  auto* rtol_opt =
      compare_cmd->add_option("--rtol", copt.rtol, "relative tolerance (default 1e-9)")->check(tolerance_problem);
  auto* atol_opt = compare_cmd->add_option("--atol", copt.atol, "absolute tolerance in the case's units (default 1e-9)")
                       ->check(tolerance_problem);
  compare_cmd
      ->add_flag("--rtol-from-bound", copt.rtol_from_bound,
                 "each case's tolerance from the other results' own rounding_bound (impact3d's result JSON): rtol = the "
                 "largest of the case's, atol = rtol x the case's largest magnitude")
      ->excludes(rtol_opt)
      ->excludes(atol_opt);
  compare_cmd->add_flag("--all", copt.all_fields, "also require the reference's fields beyond the contract");
  compare_cmd->add_flag("--subset", copt.subset, "compare only what the other results contain (cases, results, fields); reported as a subset");
  auto* verify_cmd = app.add_subcommand("verify", "every engine at every precision against the 100-digit solve");
  impact3d::verification::VerifyOptions vopt;
  verify_cmd->add_option("inputs", vopt.inputs,
                         "case files or directories of them (e.g. examples verification/cases); give these, --random "
                         "N, or both");
  verify_cmd->add_option("--random", vopt.random, "add this many seeded random collisions (at most 100000)")
      ->check(CLI::Range(0, 100000));
  std::string verify_seed;
  verify_cmd->add_option("--seed", verify_seed, "seed of the random collisions (default 1)")->check(seed_problem);
  verify_cmd->add_flag("--certify", vopt.certify,
                       "also enclose each case's exact result in ball arithmetic and prove that every precision's "
                       "results of both engines lie within their stated rounding bounds of it");
  auto* plot_cmd = app.add_subcommand("plot", "draw the impulse-space figures and sweeps of a case (gnuplot)");
  std::string plot_case;
  impact3d::cli::PlotOptions popt;
  plot_cmd->add_option("case", plot_case, "case file (JSON)")->required();
  plot_cmd->add_option("-o,--output", popt.out_dir, "directory for the figures, their scripts and data")->required();
  plot_cmd->add_flag("--png", popt.png, "PNG instead of SVG");
  std::string plot_units;
  plot_cmd->add_option("--units", plot_units, "units drawn: SI, US or metric-kmh (default: the case's)")
      ->check(CLI::IsMember({"SI", "US", "metric-kmh"}));
  auto* report_cmd = app.add_subcommand("report", "the case as one self-contained HTML page: summary, warnings, figures");
  impact3d::cli::ReportOptions ropt;
  std::string report_units, report_engine = "generated";
  report_cmd->add_option("case", ropt.case_path, "case file (JSON)")->required();
  report_cmd->add_option("-o,--output", ropt.out_file, "the HTML file to write")->required();
  report_cmd->add_option("--precision", ropt.precision, "arithmetic (default double)")
      ->check(CLI::IsMember(impact3d::studies::precision_names()));
  report_cmd->add_option("--digits", ropt.digits, "significant digits shown (default 10 at double)")->check(CLI::Range(1, 200));
  report_cmd->add_option("--units", report_units, "units shown: SI, US or metric-kmh (default: the case's)")
      ->check(CLI::IsMember({"SI", "US", "metric-kmh"}));
  report_cmd->add_option("--engine", report_engine, "generated (default) or direct")->check(CLI::IsMember({"generated", "direct"}));
  bool no_figures = false;
  report_cmd->add_flag("--no-figures", no_figures, "leave the figures out (no gnuplot run)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::string what = e.what();
    std::replace(what.begin(), what.end(), '\n', ' ');
    std::fprintf(stderr, "impact3d: usage: %s (impact3d --help)\n", impact3d::case_format::printable(what).c_str());
    return kUsage;
  }
  if (report_cmd->parsed())
    return guarded(ropt.case_path, [&] {
      if (!report_units.empty()) ropt.units = impact3d::units_named(report_units);
      ropt.engine = report_engine == "direct" ? impact3d::Engine::direct : impact3d::Engine::generated;
      ropt.figures = !no_figures;
      const std::string written = impact3d::cli::report(ropt);
      std::fputs(written.c_str(), stdout);
      return 0;
    });
  if (plot_cmd->parsed())
    return guarded(plot_case, [&] {
      if (!plot_units.empty()) popt.units = impact3d::units_named(plot_units);
      const auto spec = impact3d::case_format::read_case(impact3d::case_format::read_text_file(plot_case));
      const std::string written = naming_strategies(spec, [&] { return impact3d::cli::plot(spec, popt); });
      std::fputs(written.c_str(), stdout);
      return 0;
    });
  if (batch_cmd->parsed())
    return guarded("", [&] {
      bopt.engine = batch_engine == "direct" ? impact3d::Engine::direct : impact3d::Engine::generated;
      return impact3d::cli::batch(bopt);
    });
  if (!mc_seed.empty()) mopt.seed = seed_of(mc_seed);
  if (!mc_samples.empty()) mopt.samples = seed_of(mc_samples);
  if (!verify_seed.empty()) vopt.seed = *seed_of(verify_seed);
  if (mc_cmd->parsed())
    return guarded("", [&] {
      mopt.engine = mc_engine == "direct" ? impact3d::Engine::direct : impact3d::Engine::generated;
      if (scatter.size() == 2) mopt.plot.scatter_x = scatter[0], mopt.plot.scatter_y = scatter[1];
      return impact3d::cli::montecarlo(mopt);
    });
  if (sens_cmd->parsed())
    return guarded(sopt.case_path, [&] {
      sopt.engine = sens_engine == "direct" ? impact3d::Engine::direct : impact3d::Engine::generated;
      return impact3d::cli::sensitivity(sopt);
    });
  if (rec_cmd->parsed())
    return guarded("", [&] {
      recopt.engine = rec_engine == "direct" ? impact3d::Engine::direct : impact3d::Engine::generated;
      return impact3d::cli::reconstruct(recopt);
    });
  if (verify_cmd->parsed()) {
    // Nothing to compare is not a pass.
    if (vopt.inputs.empty() && vopt.random == 0) {
      std::fputs("impact3d: usage: verify: nothing to verify: give case files or directories (e.g. examples "
                 "verification/cases), or --random N (impact3d verify --help)\n",
                 stderr);
      return kUsage;
    }
    return guarded("", [&] { return impact3d::verification::verify(vopt); });
  }
  if (compare_cmd->parsed()) return guarded("", [&] { return impact3d::verification::compare(reference, other, copt); });
  if (digits == 0 && precision == "double") digits = 10;
  impact3d::case_format::RenderOptions ro;
  ro.format = *impact3d::case_format::parse_format(format);  // CLI11 took it from the list
  ro.digits = digits;
  ro.engine = engine == "direct" ? impact3d::Engine::direct : impact3d::Engine::generated;
  if (!units.empty()) ro.units = impact3d::units_named(units);
  // --precision was checked against precision_problem: parsed here, once.
  return solve(case_path, strategies, impact3d::studies::parse_precision(precision), ro);
}
