// impact3d: solve a two-vehicle 3D collision case by the strategies of Marine's paper.
#include <cstdio>
#include <iostream>

#include <CLI/CLI.hpp>

#include "impact3d/case/read_case.hpp"
#include "compare.hpp"
#include "plot.hpp"
#include "render.hpp"
#include "impact3d/verification/verify.hpp"

namespace {

// Bad input exits 1, internal failures 3; CLI11 uses its own codes (106 and up) for usage errors.
constexpr int kBadInput = 1;
constexpr int kInternal = 3;

// One line for an error of `verify` or `compare`: a case error names its file and field.
int report(const std::exception& e) {
  if (const auto* c = dynamic_cast<const impact3d::io::CaseError*>(&e))
    std::fprintf(stderr, "impact3d: error: %s\n", c->line().c_str());
  else
    std::fprintf(stderr, "impact3d: error: %s\n", e.what());
  return kBadInput;
}

int solve(const std::string& case_path, const std::vector<std::string>& strategies, const std::string& precision,
          const impact3d::cli::RenderOptions& options) {
  using namespace impact3d;
  std::string output;
  try {
    io::CaseSpec spec = io::read_case(io::read_text_file(case_path));
    if (!strategies.empty()) {
      spec.strategies.clear();
      for (std::size_t i = 0; i < strategies.size(); ++i)
        spec.strategies.push_back(io::read_strategy_option(strategies[i], static_cast<int>(i)));
    }
    if (precision == "double") output = cli::render_double(spec, options);
    else if (precision == "long-double") output = cli::render_long_double(spec, options);
    else if (precision == "float128") output = cli::render_float128(spec, options);
    else if (precision == "50") output = cli::render_float50(spec, options);
    else if (precision == "100") output = cli::render_float100(spec, options);
    else output = cli::render_exact(spec, options);
  } catch (const io::CaseError& e) {
    std::fprintf(stderr, "impact3d: error: %s: %s\n", case_path.c_str(), e.line().c_str());
    return kBadInput;
  } catch (const SolveError& e) {
    std::fprintf(stderr, "impact3d: error: %s: no solution: %s\n", case_path.c_str(), e.what());
    return kBadInput;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "impact3d: error: %s: %s\n", case_path.c_str(), e.what());
    return kInternal;
  }
  std::fwrite(output.data(), 1, output.size(), stdout);
  return 0;
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
  solve_cmd->add_option("--precision", precision,
                        "arithmetic: double, long-double, float128, 50 or 100 decimal digits, or exact (fractions where "
                        "the result is rational, beside the 100-digit solve)")
      ->check(CLI::IsMember({"double", "long-double", "float128", "50", "100", "exact"}));
  solve_cmd->add_option("--engine", engine,
                        "generated: closed forms derived by symbolic/ (default); direct: 3x3 solves of the constraints")
      ->check(CLI::IsMember({"generated", "direct"}));
  auto* compare_cmd = app.add_subcommand("compare", "compare another tool's results with reference results");
  std::string reference, other;
  impact3d::cli::CompareOptions copt;
  compare_cmd->add_option("reference", reference, "reference result (JSON file) or directory (verification/reference)")->required();
  compare_cmd->add_option("other", other, "the other tool's results: JSON file, directory of JSON files, or CSV")->required();
  compare_cmd->add_option("--rtol", copt.rtol, "relative tolerance (default 1e-9)");
  compare_cmd->add_option("--atol", copt.atol, "absolute tolerance in the case's units (default 1e-9)");
  compare_cmd->add_flag("--all", copt.all_fields, "also require the reference's fields beyond the contract");
  auto* verify_cmd = app.add_subcommand("verify", "every engine at every precision against the 100-digit solve");
  impact3d::verification::VerifyOptions vopt;
  verify_cmd->add_option("inputs", vopt.inputs, "case files or directories (e.g. examples verification/cases)");
  verify_cmd->add_option("--random", vopt.random, "add this many seeded random collisions");
  verify_cmd->add_option("--seed", vopt.seed, "seed of the random collisions (default 1)");
  auto* plot_cmd = app.add_subcommand("plot", "draw the impulse-space figures and sweeps of a case (gnuplot)");
  std::string plot_case;
  impact3d::cli::PlotOptions popt;
  plot_cmd->add_option("case", plot_case, "case file (JSON)")->required();
  plot_cmd->add_option("-o,--output", popt.out_dir, "directory for the figures, their scripts and data")->required();
  plot_cmd->add_flag("--png", popt.png, "PNG instead of SVG");
  CLI11_PARSE(app, argc, argv);
  if (plot_cmd->parsed()) {
    try {
      const auto spec = impact3d::io::read_case(impact3d::io::read_text_file(plot_case));
      std::fputs(impact3d::cli::plot(spec, popt).c_str(), stdout);
      return 0;
    } catch (const impact3d::io::CaseError& e) {
      std::fprintf(stderr, "impact3d: error: %s: %s\n", plot_case.c_str(), e.line().c_str());
      return kBadInput;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "impact3d: error: %s: %s\n", plot_case.c_str(), e.what());
      return kBadInput;
    }
  }
  if (verify_cmd->parsed()) {
    try {
      return impact3d::verification::verify(vopt);
    } catch (const std::exception& e) {
      return report(e);
    }
  }
  if (compare_cmd->parsed()) {
    try {
      return impact3d::cli::compare(reference, other, copt);
    } catch (const std::exception& e) {
      return report(e);
    }
  }
  if (digits == 0 && precision == "double") digits = 10;
  return solve(case_path, strategies, precision,
               {format, digits, engine == "direct" ? impact3d::Engine::direct : impact3d::Engine::generated});
}
