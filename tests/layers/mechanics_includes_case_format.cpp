// Must not compile: impact3d::mechanics sees no header of impact3d::case_format, a layer above it.
#include "impact3d/case_format/case_spec.hpp"
