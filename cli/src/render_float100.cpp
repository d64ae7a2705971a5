#include "impact3d/numeric/multiprecision.hpp"
#include "render_impl.hpp"

namespace impact3d::cli {
std::string render_float100(const io::CaseSpec& spec, const RenderOptions& o) { return render<mp::float100>(spec, o, "100"); }
}  // namespace impact3d::cli
