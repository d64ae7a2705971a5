// libFuzzer harness: any bytes as a case file, read and, when valid, solved at every precision and
// written as the result document and the HTML page, differentiated (`sensitivity`) and written, and
// certified (ball arithmetic at 64 bits, JSON with its enclosures and decisions, and text);
// the reader must reject or the solve must finish, never crash or hang. Every number's value must be
// its text correctly rounded, since the double engine reads the value (to_scene.hpp) and the others
// the text.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>

#include "impact3d/case_format/case_numbers.hpp"
#include "impact3d/case_format/read_case.hpp"
#include "impact3d/studies/precision.hpp"
#include "impact3d/case_format/report_html.hpp"
#include "impact3d/case_format/scalar_text.hpp"
#include "impact3d/studies/sensitivity.hpp"
#include "impact3d/scalar/ball.hpp"
#include "impact3d/mechanics/exact_analysis.hpp"
#include "impact3d/scalar/multiprecision.hpp"

namespace {

template <typename Scalar>
void solve_at(const impact3d::case_format::CaseSpec& spec, impact3d::Engine engine) {
  using namespace impact3d;
  try {
    const auto a = analyze(case_format::to_scene<Scalar>(spec), case_format::to_strategies<Scalar>(spec), engine);
    (void)case_format::result_json(spec, a, "fuzz");
    (void)case_format::report_html(spec, a, "fuzz", 10, {}, "");
  } catch (const case_format::CaseError&) {
  } catch (const SolveError&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace impact3d;
  case_format::CaseSpec spec;
  try {
    spec = case_format::read_case(std::string(reinterpret_cast<const char*>(data), size));
  } catch (const case_format::CaseError&) {
    return 0;
  }
  for (const auto& input : case_format::case_inputs(spec).inputs)
    for (const case_format::Number* n : input.numbers) {
      const double x = case_format::scalar_from_text<double>(n->text);
      if (std::memcmp(&x, &n->value, sizeof x) != 0 && !(std::isnan(x) && std::isnan(n->value))) std::abort();
    }
  for (Engine engine : {Engine::generated, Engine::direct}) {
    solve_at<double>(spec, engine);
    solve_at<long double>(spec, engine);
  }
  solve_at<mp::float128>(spec, Engine::generated);
  solve_at<mp::float50>(spec, Engine::generated);
  solve_at<mp::float100>(spec, Engine::direct);
  try {
    const std::string text(reinterpret_cast<const char*>(data), size);
    for (Engine engine : {Engine::generated, Engine::direct}) {
      studies::SensitivityOptions o;
      o.engine = engine;
      const studies::SensitivityRun run = studies::sensitivity(text, o);
      (void)studies::sensitivity_json(run);
      (void)studies::sensitivity_text(run);
    }
  } catch (const case_format::CaseError&) {
  } catch (const SolveError&) {
  }
  for (const auto format : {case_format::Format::json, case_format::Format::text}) {
    try {
      case_format::RenderOptions o;
      o.format = format;
      (void)studies::render(spec, "certified:64", o);
    } catch (const case_format::CaseError&) {
    } catch (const SolveError&) {
    }
  }
  flint_cleanup();  // Arb's caches (pi, powers of ten) would otherwise count as this input's leak
  try {
    (void)exact_analyze(case_format::to_scene<rational>(spec), case_format::to_strategies<rational>(spec));
  } catch (const Irrational&) {
  } catch (const case_format::CaseError&) {
  } catch (const SolveError&) {
  }
  return 0;
}
