// impact3d: solve a two-vehicle 3D collision case by the strategies of Marine's paper.
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

#include <CLI/CLI.hpp>

#include "impact3d/case/read_case.hpp"
#include "report_text.hpp"

namespace {

// Bad input exits 1, internal failures 3; CLI11 uses its own codes (106 and up) for usage errors.
constexpr int kBadInput = 1;
constexpr int kInternal = 3;

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw impact3d::io::CaseError(path, "cannot read the file");
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

int solve(const std::string& case_path, const std::string& format, const std::vector<std::string>& strategies,
          int digits, const std::string& engine_name) {
  using namespace impact3d;
  std::string output;
  try {
    io::CaseSpec spec = io::read_case(read_file(case_path));
    if (!strategies.empty()) {
      spec.strategies.clear();
      for (std::size_t i = 0; i < strategies.size(); ++i)
        spec.strategies.push_back(io::read_strategy_option(strategies[i], static_cast<int>(i)));
    }
    const Scene<double> scene = io::to_scene<double>(spec);
    const Engine engine = engine_name == "direct" ? Engine::direct : Engine::generated;
    const Analysis<double> a = analyze(scene, io::to_strategies<double>(spec), engine);
    output = format == "json" ? io::result_json(spec, a, "double") : cli::report_text(spec, a, "double", digits);
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
  int digits = 10;
  std::string engine = "generated";
  solve_cmd->add_option("case", case_path, "case file (JSON)")->required();
  solve_cmd->add_option("--format", format, "text report or contract JSON")->check(CLI::IsMember({"text", "json"}));
  solve_cmd->add_option("--strategy", strategies,
                        "replace the case's strategies, e.g. pc-crash:mu=0.4  wach:mu=0.4,limit=gir  "
                        "brach:mu_t=critical,mu_z=0 (repeatable)");
  solve_cmd->add_option("--digits", digits, "significant digits in the text report (JSON always prints all)")
      ->check(CLI::Range(1, 40));
  solve_cmd->add_option("--engine", engine,
                        "generated: closed forms derived by symbolic/ (default); direct: 3x3 solves of the constraints")
      ->check(CLI::IsMember({"generated", "direct"}));
  CLI11_PARSE(app, argc, argv);
  return solve(case_path, format, strategies, digits, engine);
}
