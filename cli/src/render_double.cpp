#include "render_impl.hpp"

namespace impact3d::cli {
std::string render_double(const io::CaseSpec& spec, const RenderOptions& o) { return render<double>(spec, o, "double"); }
}  // namespace impact3d::cli
