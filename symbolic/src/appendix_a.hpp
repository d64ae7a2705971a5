// The derivation under the paper's Appendix A assumptions: vehicles symmetric about x-z, I_xz
// neglected (diagonal tensors), horizontal normal (attitude 0), both vehicles level, contact roll phi.
#pragma once

#include <map>
#include <string>

#include "model.hpp"

namespace impact3d::symbolic {

struct AppendixA {
  matrix K;                            // derived K; symbols mp, Ix1.., x1.., cg1, sg1, cp, sp
  std::map<std::string, ex> derived;   // A, B, C, f1..f8 as the derivation defines them, and a1..c3
  GiNaC::exmap angles;                 // Weierstrass substitutions for gamma_1, gamma_2, phi
};

AppendixA specialize(const Derivation& d);

}  // namespace impact3d::symbolic
