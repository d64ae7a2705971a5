// Must not compile: impact3d::studies sees no header of impact3d::cli, a layer above it.
#include "impact3d/cli/output_file.hpp"
