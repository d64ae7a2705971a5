// Must not compile: impact3d::scalar sees no header of impact3d::mechanics, a layer above it.
#include "impact3d/mechanics/problem.hpp"
