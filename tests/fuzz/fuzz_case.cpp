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

#include "impact3d/io/case_numbers.hpp"
#include "impact3d/io/read_case.hpp"
#include "impact3d/io/render.hpp"
#include "impact3d/io/report_html.hpp"
#include "impact3d/io/scalar_text.hpp"
#include "impact3d/io/sensitivity.hpp"
#include "impact3d/numeric/ball.hpp"
#include "impact3d/numeric/exact_analysis.hpp"
#include "impact3d/numeric/multiprecision.hpp"

namespace {

template <typename Scalar>
void solve_at(const impact3d::io::CaseSpec& spec, impact3d::Engine engine) {
  using namespace impact3d;
  try {
    const auto a = analyze(io::to_scene<Scalar>(spec), io::to_strategies<Scalar>(spec), engine);
    (void)io::result_json(spec, a, "fuzz");
    (void)io::report_html(spec, a, "fuzz", 10, {}, "");
  } catch (const io::CaseError&) {
  } catch (const SolveError&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace impact3d;
  io::CaseSpec spec;
  try {
    spec = io::read_case(std::string(reinterpret_cast<const char*>(data), size));
  } catch (const io::CaseError&) {
    return 0;
  }
  for (const auto& input : io::case_inputs(spec).inputs)
    for (const io::Number* n : input.numbers) {
      const double x = io::scalar_from_text<double>(n->text);
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
      io::SensitivityOptions o;
      o.engine = engine;
      const io::SensitivityRun run = io::sensitivity(text, o);
      (void)io::sensitivity_json(run);
      (void)io::sensitivity_text(run);
    }
  } catch (const io::CaseError&) {
  } catch (const SolveError&) {
  }
  for (const char* format : {"json", "text"}) {
    try {
      io::RenderOptions o;
      o.format = format;
      (void)io::render(spec, "certified:64", o);
    } catch (const io::CaseError&) {
    } catch (const SolveError&) {
    }
  }
  flint_cleanup();  // Arb's caches (pi, powers of ten) would otherwise count as this input's leak
  try {
    (void)exact_analyze(io::to_scene<rational>(spec), io::to_strategies<rational>(spec));
  } catch (const Irrational&) {
  } catch (const io::CaseError&) {
  } catch (const SolveError&) {
  }
  return 0;
}
