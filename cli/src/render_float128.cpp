#include "impact3d/numeric/multiprecision.hpp"
#include "render_impl.hpp"

namespace impact3d::cli {
std::string render_float128(const io::CaseSpec& spec, const RenderOptions& o) { return render<mp::float128>(spec, o, "float128"); }
}  // namespace impact3d::cli
