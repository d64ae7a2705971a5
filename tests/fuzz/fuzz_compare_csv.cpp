// libFuzzer harness: any bytes as another tool's results CSV for `impact3d compare`.
#include "fuzz_compare.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) { return fuzz_compare(data, size, ".csv"); }
