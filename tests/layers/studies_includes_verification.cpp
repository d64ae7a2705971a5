// Must not compile: impact3d::studies sees no header of impact3d::verification, a layer above it.
#include "impact3d/verification/verify.hpp"
