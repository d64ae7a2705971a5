#include "impact3d/numeric/multiprecision.hpp"
#include "render_impl.hpp"

namespace impact3d::cli {
std::string render_float50(const io::CaseSpec& spec, const RenderOptions& o) { return render<mp::float50>(spec, o, "50"); }
}  // namespace impact3d::cli
