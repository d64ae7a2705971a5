// A read case solved at a precision named by the user and written as render<Scalar> writes it: a
// floating scalar of the list (impact3d/case_format/render.hpp) or, with the multiprecision scalars,
// exact (fractions) or certified (Arb's balls).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "impact3d/case_format/render.hpp"

namespace impact3d::studies {

using case_format::CaseSpec;
using case_format::RenderOptions;
using case_format::render;

// The precisions `render` takes by name: every scalar of scalars.hpp and, with the multiprecision
// scalars, "exact" (fractions where the result is rational, beside the 100-digit computation).
std::vector<std::string> precision_names();

// What is wrong with a precision name `render` would refuse; empty for one it takes: those of
// precision_names() and, with the multiprecision scalars, "certified" and "certified:BITS" (ball
// arithmetic, scalar/ball.hpp; BITS from 16 to 8192).
std::string precision_problem(std::string_view precision);

// The case at the named precision; throws std::invalid_argument for a name precision_names() lacks.
std::string render(const CaseSpec& spec, std::string_view precision, const RenderOptions& o);

}  // namespace impact3d::studies
