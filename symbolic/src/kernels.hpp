// The generated headers: which kernels go in which file, from which derived expressions.
#pragma once

#include <string>
#include <vector>

#include "appendix_a.hpp"
#include "closed_forms.hpp"
#include "codegen.hpp"
#include "model.hpp"

namespace impact3d::symbolic {

struct GeneratedFile {
  std::string name;     // e.g. "full_impact.hpp"
  std::string summary;  // one line for the banner
  std::vector<Kernel> kernels;
};

std::vector<GeneratedFile> kernel_files(const Derivation& d, const ClosedForms& c);

}  // namespace impact3d::symbolic
