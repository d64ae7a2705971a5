// --precision exact, for render(): the one precision that is not a scalar of the list.
#pragma once

#include <string>

#include "impact3d/studies/precision.hpp"

namespace impact3d::studies {
using namespace case_format;  // the studies are written in the case format's terms

#if IMPACT3D_MULTIPRECISION
std::string render_exact(const CaseSpec& spec, const RenderOptions& o);
#endif

}  // namespace impact3d::studies
