// impact3d-reference: the reference outputs. Each case is solved at 100 decimal digits by both engines,
// which must agree to rounding::kEngineAgreementDigits (80) digits, and the contract's result is written at 40 significant digits;
// a post-impact relative velocity within the 100-digit rounding bound is written as 0. Every digit
// written is then proven by the certified result of the same case (reference_proof.hpp), or nothing is
// written.
#include <filesystem>
#include <fstream>
#include <iostream>

#include "impact3d/case_format/read_case.hpp"
#include "impact3d/studies/precision.hpp"
#include "impact3d/case_format/result_json.hpp"
#include "impact3d/scalar/multiprecision.hpp"
#include "impact3d/mechanics/rounding.hpp"
#include "impact3d/verification/reference_proof.hpp"

namespace fs = std::filesystem;
using namespace impact3d;
using F = mp::float100;
constexpr int kDigits = 40;  // significant digits written

namespace {

// Relative difference of the two engines' impulses, the largest over the case's strategies.
F engine_difference(const Analysis<F>& a, const Analysis<F>& b) {
  F worst = 0;
  for (std::size_t k = 0; k < a.solutions.size(); ++k) {
    const F d = (a.solutions[k].impulse.P_C - b.solutions[k].impulse.P_C).norm() / b.solutions[k].impulse.P_C.norm();
    if (d > worst) worst = d;
  }
  return worst;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3 || std::string(argv[1]) != "--out") {
    std::cerr << "usage: impact3d-reference --out DIR CASE.json...\n";
    return 2;
  }
  const fs::path out = argv[2];
  fs::create_directories(out);
  for (int i = 3; i < argc; ++i) {
    const fs::path in = argv[i];
    try {
      const case_format::CaseSpec spec = case_format::read_case(case_format::read_text_file(in.string()));
      const Scene<F> scene = case_format::to_scene<F>(spec);
      const auto strategies = case_format::to_strategies<F>(spec);
      const Analysis<F> a = analyze(scene, strategies, Engine::generated);
      const Analysis<F> b = analyze(scene, strategies, Engine::direct);
      if (engine_difference(a, b) > rounding::engine_agreement_tolerance<F>()) {
        std::cerr << "impact3d-reference: " << in << ": the engines disagree beyond " << rounding::kEngineAgreementDigits
                  << " digits\n";
        return 1;
      }
      // The default certified precision first; where a ball is too wide to prove a digit, more bits.
      case_format::RenderOptions certified;
      certified.format = case_format::Format::json;
      verification::ReferenceProof proof;
      for (const char* precision : {"certified", "certified:512", "certified:1024", "certified:2048", "certified:4096"}) {
        proof = verification::prove_reference(
            [&](const auto& extra, const auto& per_result) {
              return case_format::result_json(spec, a, "100", kDigits, true, extra, false, nullptr, per_result);
            },
            studies::render(spec, precision, certified), kDigits);
        if (proof.failure.empty()) break;
      }
      if (!proof.failure.empty()) {
        std::cerr << "impact3d-reference: " << in << ": a digit is not proven at 4096 bits: " << proof.failure << "\n";
        return 1;
      }
      std::ofstream(out / in.filename(), std::ios::binary) << proof.document;
    } catch (const std::exception& e) {
      std::cerr << "impact3d-reference: " << in << ": " << e.what() << "\n";
      return 1;
    }
  }
  return 0;
}
