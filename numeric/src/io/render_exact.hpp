// --precision exact, for render(): the one precision that is not a scalar of the list.
#pragma once

#include <string>

#include "impact3d/io/render.hpp"

namespace impact3d::io {

#if IMPACT3D_MULTIPRECISION
std::string render_exact(const CaseSpec& spec, const RenderOptions& o);
#endif

}  // namespace impact3d::io
