// Solving a read case at one precision and rendering it: one translation unit per scalar type
// (render_*.cpp), so that the wide types compile in parallel and only where needed.
#pragma once

#include <string>

#include "impact3d/case/case_spec.hpp"
#include "impact3d/numeric/problem.hpp"

namespace impact3d::cli {

struct RenderOptions {
  std::string format;     // "text" | "json"
  int digits;             // text report; 0 = the precision's digits10
  Engine engine;
};

// Throws io::CaseError for inputs that fail the arithmetic checks, SolveError for no solution.
std::string render_double(const io::CaseSpec& spec, const RenderOptions& o);
std::string render_long_double(const io::CaseSpec& spec, const RenderOptions& o);
std::string render_float128(const io::CaseSpec& spec, const RenderOptions& o);
std::string render_float50(const io::CaseSpec& spec, const RenderOptions& o);
std::string render_float100(const io::CaseSpec& spec, const RenderOptions& o);
// Fractions where the result is rational, beside the 100-digit computation.
std::string render_exact(const io::CaseSpec& spec, const RenderOptions& o);

}  // namespace impact3d::cli
