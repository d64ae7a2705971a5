// Must not compile: impact3d::case_format sees no header of impact3d::studies, a layer above it.
#include "impact3d/studies/montecarlo.hpp"
