// The mechanics at one scalar of scalars.hpp: numeric/CMakeLists.txt compiles this file once per scalar
// with IMPACT3D_SCALAR_INDEX set, so that the wide types compile in parallel.
#include "impact3d/mechanics/analysis.hpp"

namespace impact3d {
using InstantiatedScalar = ScalarAt<IMPACT3D_SCALAR_INDEX>;
template Analysis<InstantiatedScalar> analyze(const Scene<InstantiatedScalar>&,
                                              const std::vector<Strategy<InstantiatedScalar>>&, Engine);
template LeanSolution<InstantiatedScalar> solve_lean(const Scene<InstantiatedScalar>&, const Strategy<InstantiatedScalar>&,
                                                     Want, Engine);
template LeanSolution<InstantiatedScalar> solve_lean(const RawCollision<InstantiatedScalar>&,
                                                     const Strategy<InstantiatedScalar>&, Want, Engine);
}  // namespace impact3d
