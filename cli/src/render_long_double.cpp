#include "render_impl.hpp"

namespace impact3d::cli {
std::string render_long_double(const io::CaseSpec& spec, const RenderOptions& o) { return render<long double>(spec, o, "long-double"); }
}  // namespace impact3d::cli
